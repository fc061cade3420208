using System;
using System.Globalization;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// A bake on any humanoid rig: its motion is moved onto the model's skeleton with a
    /// <see cref="SkeletonMap"/> (source reference: its default pose or a given frame; target: the model's
    /// T-pose), brought to the model's frame rate, baked there, and mapped back onto the rig's skeleton
    /// and rate.
    /// </summary>
    /// <remarks>
    /// Time: model frame 0 is the first input key. Each input key k maps to the nearest model frame of its
    /// time, and between two keys time is stretched linearly so that keys land on keys in both directions
    /// (a key between two model frames moves by at most half a model frame on the model's timeline only;
    /// on the way back every input frame between keys reads the baked motion at its stretched time).
    /// Only the input's key frames are read on the way back (unmapped joints are interpolated between
    /// keys), so the non-key frames stay an honest ground truth. The output's key frames are the input's,
    /// copied exactly; <see cref="KeyRoundTripDegrees"/> says how far the map's round trip was from them.
    /// </remarks>
    public sealed class MappedRig : IRigRetargeting
    {
        private readonly SkeletonMap _map;
        private readonly double _modelFrameTime;
        private readonly double _inputFrameTime;
        private readonly string _inputPath;

        private MappedRig(SkeletonMap map, double modelFrameTime, double inputFrameTime, string inputPath, string reference, string? acceptedReference = null)
        {
            AcceptedReference = acceptedReference;
            _map = map;
            _inputFrameTime = inputFrameTime;
            _modelFrameTime = modelFrameTime;
            _inputPath = inputPath;
            Description = string.Format(CultureInfo.InvariantCulture,
                "retargeted with map '{0}' ({1} joints → the model's {2}{6}; reference: {3}; root × {4:0.#####}{7}) at {5:0.##} fps, baked results mapped back onto the input's skeleton and rate",
                map.Map.Name, map.Source.JointCount, map.Target.JointCount, reference, map.RootScale, 1 / modelFrameTime,
                map.SynthesizedJoints.Count == 0 ? "" : "; made up (the input lacks them): " + string.Join(", ", map.SynthesizedJoints),
                map.Up == null ? "" : "; " + map.Up.Description);
        }

        /// <inheritdoc />
        public string Description { get; }

        /// <summary>What the humanoid rule would have refused in a reference pose kept with --accept-reference-pose (also in <see cref="Description"/>), or null.</summary>
        public string? AcceptedReference { get; }

        /// <summary>The map between the input's skeleton and the model's.</summary>
        public SkeletonMap Map => _map;

        SkeletonMap? IRigRetargeting.Map => _map;

        /// <inheritdoc />
        public double LegLength => _map.SourceLegLength;

        /// <summary>The largest angle (degrees) between a mapped-back key rotation and the input's, before the input's were copied in (round-off: ~1e-13 on the CMU demo clip).</summary>
        public double KeyRoundTripDegrees { get; private set; }

        /// <summary>
        /// The seam of a rig whose map is already built (a character's, <see cref="Characters.CharacterRig.CreatePoseConverter"/>:
        /// the component's map, so that the editor baker sees the character as the component does).
        /// </summary>
        /// <param name="contract">The model's contract (frame rate).</param>
        /// <param name="map">Source: the rig's skeleton; target: the model's.</param>
        /// <param name="inputFrameTime">Seconds per frame of the rig's clips.</param>
        /// <param name="inputName">The rig's name, for messages.</param>
        /// <param name="reference">What the map's source reference pose is, for <see cref="Description"/>.</param>
        internal static MappedRig FromMap(ModelContract contract, SkeletonMap map, double inputFrameTime, string inputName, string reference) =>
            new MappedRig(map, 1.0 / contract.FramesPerSecond, inputFrameTime, inputName, reference);

        /// <summary>Builds the map for <paramref name="input"/> onto <paramref name="contract"/>'s skeleton.</summary>
        /// <param name="contract">The model's contract (skeleton, frame rate).</param>
        /// <param name="input">The rig's clip.</param>
        /// <param name="referenceFrame">The input frame that is its reference pose, or null for <see cref="ReferencePose.Default"/>.</param>
        /// <param name="inputPath">The input's path, for messages.</param>
        /// <param name="jointMap">A user joint map, or null for the best built-in one.</param>
        /// <exception cref="JointMapException">Joints missing.</exception>
        /// <param name="up">The file's up axis (auto: detected; see <see cref="UpAxisDecision"/>).</param>
        /// <param name="acceptReferencePose">Keep a reference pose the humanoid rule refuses (the CLI's --accept-reference-pose); what it would have refused is then part of <see cref="Description"/>.</param>
        /// <exception cref="MotionRequestException">The reference frame is not a frame of the clip.</exception>
        public static MappedRig Create(ModelContract contract, MotionClip input, int? referenceFrame, string inputPath, JointMap? jointMap = null, UpAxis up = UpAxis.Auto, bool acceptReferencePose = false)
        {
            ReferencePose source = MotionRetargeting.Reference(input, referenceFrame, "reference frame", inputPath);
            jointMap ??= JointMap.Detect(input.Skeleton, contract.Skeleton);
            UpAxisDecision decided = UpAxisDecision.Decide(up, source, referenceFrame != null, input, jointMap);
            SkeletonMap map = SkeletonMap.Create(source, ReferencePose.ModelTPose(contract.Skeleton), jointMap, inputPath, null, decided);
            // The one humanoid rule of the component (BoneDirections), without the arms: a file's reference pose is not declared a T-pose.
            string? accepted = null;
            if (acceptReferencePose) accepted = BoneDirections.AcceptedDeviation(map, ReferencePose.ModelTPose(contract.Skeleton), BoneDirections.DefaultMaxDegrees, BoneDirections.UprightBones);
            else BoneDirections.RequireTPose(map, ReferencePose.ModelTPose(contract.Skeleton), BoneDirections.DefaultMaxDegrees, inputPath, BoneDirections.UprightBones);
            return new MappedRig(map, 1.0 / contract.FramesPerSecond, input.FrameTime, inputPath,
                (referenceFrame == null ? "the input's default pose" : "input frame " + referenceFrame.Value.ToString(CultureInfo.InvariantCulture)) + (accepted == null ? "" : ", " + accepted), accepted);
        }

        /// <inheritdoc />
        public int[] KeysToModel(int[] rigKeys) => ModelKeys(rigKeys, _inputFrameTime);

        /// <inheritdoc />
        public MotionClip ToModel(MotionClip motion, int[] inputKeys)
        {
            CheckKeys(inputKeys, motion.FrameCount);
            int[] modelKeys = ModelKeys(inputKeys, motion.FrameTime);
            MotionClip onModel = _map.ToTarget(motion);
            if (_map.Up != null) UpAxisDetection.RequireStanding(onModel, _inputPath, _map.Up.Description);
            int frames = modelKeys[modelKeys.Length - 1] + 1;
            int j = _map.Target.JointCount;
            var positions = new double[frames * j * 3];
            var rotations = new double[frames * j * 4];
            for (int m = 0; m < frames; m++)
            {
                MotionResampler.Sample(onModel, InputFrameOf(m, inputKeys, modelKeys), positions.AsSpan(m * j * 3, j * 3), rotations.AsSpan(m * j * 4, j * 4));
            }

            Quaternions.FixContinuity(rotations, frames, j);
            return new MotionClip(_map.Target, frames, _modelFrameTime, positions, rotations);
        }

        /// <inheritdoc />
        public MotionClip FromModel(MotionClip baked, MotionClip source, int[] inputKeys)
        {
            int[] modelKeys = ModelKeys(inputKeys, source.FrameTime);
            int first = inputKeys[0], count = inputKeys[inputKeys.Length - 1] - first + 1;
            int js = _map.Source.JointCount, jt = _map.Target.JointCount;
            var positions = new double[count * js * 3];
            var rotations = new double[count * js * 4];
            var targetPositions = new double[jt * 3];
            var targetRotations = new double[jt * 4];
            double worst = 0;
            int segment = 0;
            for (int i = 0; i < count; i++)
            {
                int frame = first + i;
                while (segment < inputKeys.Length - 2 && frame > inputKeys[segment + 1]) segment++;
                int k0 = inputKeys[segment], k1 = inputKeys[segment + 1];
                double t = (frame - k0) / (double)(k1 - k0);
                Span<double> lp = positions.AsSpan(i * js * 3, js * 3);
                Span<double> lr = rotations.AsSpan(i * js * 4, js * 4);
                // Unmapped values from the keys around the frame only: the other input frames are the ground truth.
                MotionResampler.Blend(source, k0, k1, t, lp, lr);
                double modelFrame = modelKeys[segment] + t * (modelKeys[segment + 1] - modelKeys[segment]);
                MotionResampler.Sample(baked, modelFrame, targetPositions, targetRotations);
                _map.ToSourceFrame(Vector3D.Read(targetPositions, 0), targetRotations, lp, lr);
                if (frame == k0 || frame == k1)
                {
                    worst = Math.Max(worst, MaxAngle(lr, source.LocalRotations.AsSpan(source.RotationIndex(frame, 0), js * 4)));
                    // The output keeps the input's key frames exactly (what a user keyed is never moved).
                    source.LocalPositions.AsSpan(source.PositionIndex(frame, 0), js * 3).CopyTo(lp);
                    source.LocalRotations.AsSpan(source.RotationIndex(frame, 0), js * 4).CopyTo(lr);
                }
            }

            KeyRoundTripDegrees = worst;
            return new MotionClip(_map.Source, count, source.FrameTime, positions, rotations);
        }

        /// <summary>Input key frames → model frames: nearest model frame of each key's time after the first key.</summary>
        private int[] ModelKeys(int[] inputKeys, double inputFrameTime)
        {
            var keys = new int[inputKeys.Length];
            for (int i = 0; i < inputKeys.Length; i++)
            {
                double key = Math.Round((inputKeys[i] - inputKeys[0]) * inputFrameTime / _modelFrameTime, MidpointRounding.AwayFromZero);
                if (i == inputKeys.Length - 1 || !(key < int.MaxValue))
                {
                    // Before anything is allocated: a huge Frame Time would ask for gigabytes of model frames.
                    MotionResampler.CheckLength(key + 1, _map.Target.JointCount, inputKeys[inputKeys.Length - 1] - inputKeys[0] + 1, inputFrameTime, _modelFrameTime, _inputPath);
                }

                keys[i] = (int)key;
                if (i > 0 && keys[i] <= keys[i - 1])
                {
                    // BVH files round their frame time (CMU: 0.008333 s), so 4.0002 input frames per model frame means 4.
                    int apart = (int)Math.Ceiling(_modelFrameTime / inputFrameTime - 1e-3);
                    throw new KeyLayoutException(string.Format(CultureInfo.InvariantCulture,
                        "keys {0} and {1} fall on the same frame at the model's {2:0.##} fps", inputKeys[i - 1], inputKeys[i], 1 / _modelFrameTime),
                        string.Format(CultureInfo.InvariantCulture, "expected keys at least {0} frames apart", apart));
                }
            }

            return keys;
        }

        private void CheckKeys(int[] keys, int frameCount)
        {
            if (keys.Length < 2) throw new KeyLayoutException($"{keys.Length} key", "expected at least two keys");
            for (int i = 0; i < keys.Length; i++)
            {
                if (keys[i] < 0 || keys[i] >= frameCount)
                {
                    throw new KeyLayoutException($"key frame {keys[i]} is outside the file's frames 0..{frameCount - 1}", "expected key frames inside them");
                }

                if (i > 0 && keys[i] <= keys[i - 1])
                {
                    throw new KeyLayoutException($"key {keys[i]} after {keys[i - 1]}", "expected strictly increasing key frames");
                }
            }
        }

        /// <summary>Model frame m → fractional input frame: linear between the keys around it, so keys meet keys.</summary>
        private static double InputFrameOf(int m, int[] inputKeys, int[] modelKeys)
        {
            int s = 0;
            while (s < modelKeys.Length - 2 && m > modelKeys[s + 1]) s++;
            double t = (m - modelKeys[s]) / (double)(modelKeys[s + 1] - modelKeys[s]);
            return inputKeys[s] + t * (inputKeys[s + 1] - inputKeys[s]);
        }

        private static double MaxAngle(ReadOnlySpan<double> a, ReadOnlySpan<double> b)
        {
            double worst = 0;
            for (int q = 0; q < a.Length; q += 4)
            {
                double dot = a[q] * b[q] + a[q + 1] * b[q + 1] + a[q + 2] * b[q + 2] + a[q + 3] * b[q + 3];
                double sign = dot < 0 ? -1 : 1, chord = 0;
                for (int c = 0; c < 4; c++) chord += (a[q + c] - sign * b[q + c]) * (a[q + c] - sign * b[q + c]);
                // From the chord, not acos of the dot product: acos cannot resolve angles below ~1e-6° near 1.
                worst = Math.Max(worst, 4 * Math.Asin(Math.Min(1, Math.Sqrt(chord) / 2)) * 180 / Math.PI);
            }

            return worst;
        }
    }
}
