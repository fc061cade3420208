using System;
using BenchmarkDotNet.Attributes;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Benchmarks
{
    /// <summary>
    /// The per-frame cost of foot locking for 1, 16 and 64 characters of LaFAN1's 22 joints, every character with
    /// both feet planted on every frame (the costliest case: FK of the frame and two-bone IK of both legs, toe and
    /// heel held): <see cref="Frame"/> is a bake's (<see cref="FootLocker.LockFrame"/>; planning, once per bake, not
    /// part of it), <see cref="PlaybackFrame"/> the component's pose by pose (<see cref="LiveFootLocker.LockPose(double, ReadOnlySpan{double}, Span{double})"/>: contact
    /// labels, FK and IK of the pose shown; a new transition every 58 frames included). Divide by Characters for the
    /// per-character cost; both must allocate 0 B.
    /// <code>dotnet run -c Release --project Tools~/Benchmarks -- --filter '*FootLockBenchmarks*'</code>
    /// </summary>
    [MemoryDiagnoser]
    public class FootLockBenchmarks
    {
        private const int Frames = 60;
        private FootLocker[] _lockers = null!;
        private LiveFootLocker[] _live = null!;
        private MotionClip[] _clips = null!;
        private double[][] _rotations = null!;
        private int _frame;
        private readonly float[] _planted = { 0.9f, 0.9f, 0.9f, 0.9f };
        private static readonly int[] SpanKeys = { 0, Frames - 1 };

        /// <summary>Characters locked per rendered frame.</summary>
        [Params(1, 16, 64)]
        public int Characters { get; set; }

        [GlobalSetup]
        public void Setup()
        {
            string[] names =
            {
                "Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToe", "RightUpLeg", "RightLeg", "RightFoot", "RightToe",
                "Spine", "Spine1", "Spine2", "Neck", "Head", "LeftShoulder", "LeftArm", "LeftForeArm", "LeftHand",
                "RightShoulder", "RightArm", "RightForeArm", "RightHand",
            };
            int[] parents = { -1, 0, 1, 2, 3, 0, 5, 6, 7, 0, 9, 10, 11, 12, 11, 14, 15, 16, 11, 18, 19, 20 };
            double[] offsets =
            {
                0, 0, 0, 0.1, 1.86, 10.55, 43.5, 0, 0, 42.37, 0, 0, 17.3, 0, 0, 0.1, 1.86, -10.55, 43.5, 0, 0, 42.37, 0, 0, 17.3, 0, 0,
                6.9, -2.6, 0, 12.59, 0, 0, 12.34, 0, 0, 25.83, 0, 0, 11.77, 0, 0, 19.75, -1.48, 6.0, 11.28, 0, 0, 33.0, 0, 0, 25.2, 0, 0,
                19.75, -1.48, -6.0, 11.28, 0, 0, 33.0, 0, 0, 25.2, 0, 0,
            };
            var skeleton = new Skeleton(names, parents, offsets);
            FootRig rig = FootRig.ForModel(skeleton);
            ReferencePose pose = ReferencePose.ModelTPose(skeleton);
            int j = skeleton.JointCount;
            var gp = new double[3 * j];
            var gr = new double[4 * j];
            _lockers = new FootLocker[Characters];
            _live = new LiveFootLocker[Characters];
            _clips = new MotionClip[Characters];
            _rotations = new double[Characters][];
            for (int c = 0; c < Characters; c++)
            {
                // Standing, hips 6 cm down and swaying a few centimetres, the feet drifting half as far between the two
                // keys: every filled frame holds both feet (heel and toe) and solves both legs.
                var positions = new double[Frames * j * 3];
                var rotations = new double[Frames * j * 4];
                for (int f = 0; f < Frames; f++)
                {
                    skeleton.OffsetSpan.CopyTo(positions.AsSpan(f * j * 3, j * 3));
                    double sway = 3 * Math.Sin(Math.PI * f / (Frames - 1)) * (1 + 0.01 * c);
                    new Vector3D(pose.RootPosition.X + sway, pose.RootPosition.Y - 6, pose.RootPosition.Z).Write(positions, f * j * 3);
                    for (int k = 0; k < 4 * j; k++) rotations[f * j * 4 + k] = pose.LocalRotations[k];
                    // Knees bent so that the ankles stand where the T-pose has them, carried half the sway along.
                    Span<double> lp = positions.AsSpan(f * j * 3, j * 3), lr = rotations.AsSpan(f * j * 4, j * 4);
                    ForwardKinematics.ComputeFrame(skeleton.ParentSpan, lp, Vector3D.Read(lp, 0), lr, gp, gr);
                    for (int side = 0; side < 2; side++)
                    {
                        Leg leg = rig[side];
                        Vector3D ankle = pose.GlobalPosition(leg.Ankle) + new Vector3D(0.5 * sway, 0, 0);
                        TwoBoneIk.Solve(Vector3D.Read(gp, 3 * leg.Hip), Vector3D.Read(gp, 3 * leg.Knee), Vector3D.Read(gp, 3 * leg.Ankle),
                            QuaternionD.Read(gr, 4 * leg.Hip), QuaternionD.Read(gr, 4 * leg.Knee), ankle, Vector3D.UnitZ, out QuaternionD hip, out QuaternionD knee);
                        Quaternions.Multiply(Quaternions.Conjugate(QuaternionD.Read(gr, 0)), hip).Write(lr, 4 * leg.Hip);
                        Quaternions.Multiply(Quaternions.Conjugate(hip), knee).Write(lr, 4 * leg.Knee);
                        Quaternions.Multiply(Quaternions.Conjugate(knee), QuaternionD.Read(gr, 4 * leg.Ankle)).Write(lr, 4 * leg.Ankle);
                    }
                }

                _clips[c] = new MotionClip(skeleton, Frames, 1.0 / 30, positions, rotations);
                _lockers[c] = new FootLocker(rig);
                _lockers[c].Plan(_clips[c], new[] { 0, Frames - 1 });
                _rotations[c] = new double[4 * j];
                _live[c] = new LiveFootLocker(rig);
            }

            RequireEveryFootHeld(j, planned: false);
            RequireEveryFootHeld(j, planned: true);

            BeginTransitions();

            for (int f = 1; f < Frames - 1; f++)
            {
                for (int channel = 0; channel < FootLocker.ChannelCount; channel++)
                {
                    if (_lockers[0].LockWeight(f, channel) <= 0) throw new InvalidOperationException($"frame {f}: foot joint {channel} is not held; the benchmark would measure less than it says");
                }
            }
        }

        // The first character's transition, played through once pose by pose or planned: every foot joint must be held on
        // every frame, or the benchmark would measure less than it says.
        private void RequireEveryFootHeld(int joints, bool planned)
        {
            BeginTransitions(planned);
            MotionClip clip = _clips[0];
            for (int f = 1; f < Frames - 1; f++)
            {
                Array.Copy(clip.LocalRotations, f * joints * 4, _rotations[0], 0, 4 * joints);
                _live[0].LockPose(f / 30.0, clip.LocalPositions.AsSpan(f * joints * 3, 3), _rotations[0]);
                for (int channel = 0; channel < FootLocker.ChannelCount; channel++)
                {
                    if (_live[0].LockWeight(channel) <= 0) throw new InvalidOperationException($"{(planned ? "planned " : "")}playback frame {f}: foot joint {channel} is not held; the benchmark would measure less than it says");
                }
            }
        }

        /// <summary>One rendered frame of every character playing a transition: the pose shown locked as it is shown (the clip's own pose copied in first).</summary>
        [Benchmark]
        public void PlaybackFrame() => PlayFrame(planned: false, default, 0);

        /// <summary>
        /// <see cref="PlaybackFrame"/> with the model's predicted contacts deciding touch-down and lift-off (issue 29: every
        /// foot joint predicted planted, so both legs are solved on every frame, as in <see cref="PlaybackFrame"/>).
        /// </summary>
        [Benchmark]
        public void PlaybackFramePredicted() => PlayFrame(planned: false, _planted, 0.5);

        /// <summary>
        /// <see cref="PlaybackFrame"/> with each transition's span planned as a bake plans it (<see cref="LiveFootLocker.PlanSpan"/>,
        /// as the component does once the network's frames are decoded): the planning, once per transition, included.
        /// </summary>
        [Benchmark]
        public void PlaybackFramePlanned() => PlayFrame(planned: true, default, 0);

        // One rendered frame of every character (the clip's own pose copied in, then locked as it is shown); the
        // transitions begin again, pose by pose or planned, when the clip wraps. No contacts (default): labelled as it is shown.
        private void PlayFrame(bool planned, ReadOnlySpan<float> contacts, double threshold)
        {
            _frame = _frame % (Frames - 2) + 1;
            if (_frame == 1) BeginTransitions(planned);
            for (int c = 0; c < _live.Length; c++)
            {
                MotionClip clip = _clips[c];
                int j = clip.Skeleton.JointCount;
                double[] pose = _rotations[c];
                Array.Copy(clip.LocalRotations, _frame * j * 4, pose, 0, pose.Length);
                _live[c].LockPose(_frame / 30.0, clip.LocalPositions.AsSpan(_frame * j * 3, 3), pose, contacts, threshold);
            }
        }

        private void BeginTransitions(bool planned = false)
        {
            for (int c = 0; c < _live.Length; c++)
            {
                MotionClip clip = _clips[c];
                int j = clip.Skeleton.JointCount, last = Frames - 1;
                _live[c].Begin(clip.LocalPositions.AsSpan(0, 3), clip.LocalRotations.AsSpan(0, 4 * j), clip.LocalPositions.AsSpan(last * j * 3, 3), clip.LocalRotations.AsSpan(last * j * 4, 4 * j), 0, last / 30.0);
                // The clip is the span: its first frame the start pose, its last the target.
                if (planned) _live[c].PlanSpan(clip, SpanKeys, 0, null);
            }
        }

        /// <summary>One rendered frame of every character: its planned frame's legs solved (the clip's own pose copied in first).</summary>
        [Benchmark]
        public void Frame()
        {
            _frame = _frame % (Frames - 2) + 1;
            for (int c = 0; c < _lockers.Length; c++)
            {
                MotionClip clip = _clips[c];
                int j = clip.Skeleton.JointCount;
                double[] pose = _rotations[c];
                Array.Copy(clip.LocalRotations, _frame * j * 4, pose, 0, pose.Length);
                _lockers[c].LockFrame(_frame, clip.LocalPositions.AsSpan(_frame * j * 3, j * 3), pose);
            }
        }
    }
}
