using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Clips
{
    public static partial class KeyFill
    {
        /// <summary>The Euler curves the Animation window keys a generic rotation on.</summary>
        public const string EulerStem = "localEulerAnglesRaw";

        /// <summary>
        /// The key poses of a transform clip, read off its curves: every key frame of <paramref name="plan"/>, each bone's
        /// rotation from its quaternion or Euler curves and the root bone's position from its position curves, at the
        /// key's time (a curve without a key there is evaluated between its keys); bones and components without
        /// curves keep <paramref name="scenePose"/>'s value, as the clip leaves them in the scene.
        /// </summary>
        /// <param name="plan">From <see cref="Plan"/> on these curves.</param>
        /// <param name="curves">The clip's curves.</param>
        /// <param name="rig">The character.</param>
        /// <param name="bonePaths">Each rig bone's transform path under the animated GameObject, in <see cref="CharacterRig.BoneNames"/> order.</param>
        /// <param name="scenePose">The bones' current local transforms: root position (3) then every bone's rotation (w, x, y, z).</param>
        /// <returns>A track of <c>plan.LastKey + 1</c> frames at the model's rate with the plan's key frames set.</returns>
        /// <exception cref="KeyFillException">Curves the rig cannot map: a pose curve on a transform that is no rig bone, a rotation missing components, quaternion and Euler curves on one bone, a position curve on a bone other than the root, Euler curves other than <c>localEulerAnglesRaw</c>, a weighted segment to evaluate.</exception>
        public static CharacterPoseTrack KeyPoses(KeyFillPlan plan, IReadOnlyList<KeyedCurve> curves, CharacterRig rig, IReadOnlyList<string> bonePaths, ReadOnlySpan<double> scenePose)
        {
            BoneCurves[] bones = Bind(plan, curves, rig, bonePaths);
            int n = rig.BoneNames.Count;
            if (scenePose.Length != 3 + 4 * n) throw new ArgumentException($"expected the root position and {n} rotations, {3 + 4 * n} values; got {scenePose.Length}", nameof(scenePose));
            var track = new CharacterPoseTrack(rig, plan.LastKey + 1, 1.0 / plan.FrameRate);
            var root = new double[3];
            var rotations = new double[4 * n];
            for (int k = 0; k < plan.KeyFrameArray.Length; k++)
            {
                double time = plan.KeyTimeArray[k];
                scenePose.Slice(0, 3).CopyTo(root);
                scenePose.Slice(3).CopyTo(rotations);
                for (int b = 0; b < n; b++)
                {
                    BoneCurves bone = bones[b];
                    if (bone.Quaternion != null)
                    {
                        // Unity's components x, y, z, w → (w, x, y, z).
                        for (int c = 0; c < 4; c++) rotations[4 * b + (c + 1) % 4] = Value(plan, curves[bone.Quaternion[c]], time);
                    }
                    else if (bone.Euler != null)
                    {
                        UnityEuler.ToRotation(Value(plan, curves[bone.Euler[0]], time), Value(plan, curves[bone.Euler[1]], time), Value(plan, curves[bone.Euler[2]], time)).Write(rotations, 4 * b);
                    }

                    if (bone.Position == null) continue;
                    for (int c = 0; c < 3; c++)
                    {
                        if (bone.Position[c] >= 0) root[c] = Value(plan, curves[bone.Position[c]], time);
                    }
                }

                track.SetUnityPose(plan.KeyFrameArray[k], root, rotations);
            }

            return track;
        }

        /// <summary>
        /// The fill of a transform clip: <paramref name="filled"/> (the bake's motion on the rig from the first to the last
        /// key, e.g. <see cref="Workflows.MethodBake.OnRig"/>) written as keys on the clip's pose curves: quaternion curves
        /// kept in the hemisphere of the frame before, Euler curves (<c>localEulerAnglesRaw</c>, degrees) unwrapped to
        /// the frame before so no key flips by 360°, the root bone's position.
        /// </summary>
        /// <exception cref="KeyFillException">As <see cref="KeyPoses"/>.</exception>
        /// <exception cref="ArgumentException"><paramref name="filled"/> does not span the plan's keys.</exception>
        public static KeyFillEdit Edit(KeyFillPlan plan, IReadOnlyList<KeyedCurve> curves, CharacterRig rig, IReadOnlyList<string> bonePaths, MotionClip filled)
        {
            BoneCurves[] bones = Bind(plan, curves, rig, bonePaths);
            if (filled == null) throw new ArgumentNullException(nameof(filled));
            int span = plan.LastKey - plan.FirstKey + 1;
            if (filled.FrameCount != span) throw new ArgumentException($"the filled motion has {filled.FrameCount} frames; expected the plan's {span} (frames {plan.FirstKey}–{plan.LastKey})", nameof(filled));
            int n = rig.BoneNames.Count;
            var root = new double[3];
            var rotations = new double[4 * span * n];
            var positions = new double[3 * span];
            var q = new double[4 * n];
            for (int f = 0; f < span; f++)
            {
                CharacterPoseTrack.ReadUnityPose(rig, filled, f, root, q);
                Array.Copy(q, 0, rotations, 4 * n * f, 4 * n);
                Array.Copy(root, 0, positions, 3 * f, 3);
            }

            var values = new FilledValues(plan, curves);
            for (int b = 0; b < n; b++)
            {
                BoneCurves bone = bones[b];
                if (bone.Quaternion != null) values.Quaternions(bone.Quaternion, f => QuaternionD.Read(rotations, 4 * (n * f + b)));
                if (bone.Euler != null) values.Euler(bone.Euler, f => QuaternionD.Read(rotations, 4 * (n * f + b)));
                if (bone.Position == null) continue;
                for (int c = 0; c < 3; c++)
                {
                    int component = c;
                    if (bone.Position[c] >= 0) values.Scalar(bone.Position[c], f => positions[3 * f + component]);
                }
            }

            return values.ToEdit();
        }

        /// <summary>A curve's value at a key time: its own key's value when it has one on that frame, else evaluated.</summary>
        private static double Value(KeyFillPlan plan, KeyedCurve curve, double time)
        {
            int frame = (int)Math.Round(time * plan.FrameRate, MidpointRounding.AwayFromZero);
            foreach (CurveKey key in curve.Keys)
            {
                if (FrameOf(key.Time, plan.FrameRate) == frame) return key.Value;
            }

            try
            {
                return curve.Evaluate(time);
            }
            catch (InvalidOperationException)
            {
                throw new KeyFillException(plan.Clip, FormattableString.Invariant($"{curve} has no key at {time:0.####} s and a weighted segment there"), "expected unweighted tangents where a pose curve is read between its keys, or a key on every pose curve at each key frame", "curves");
            }
        }

        /// <summary>Which curves animate one rig bone: indices into the clip's curves, −1 for a component without one.</summary>
        private sealed class BoneCurves
        {
            public int[]? Quaternion;
            public int[]? Euler;
            public int[]? Position;
        }

        private static BoneCurves[] Bind(KeyFillPlan plan, IReadOnlyList<KeyedCurve> curves, CharacterRig rig, IReadOnlyList<string> bonePaths)
        {
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            if (curves == null) throw new ArgumentNullException(nameof(curves));
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (bonePaths == null) throw new ArgumentNullException(nameof(bonePaths));
            int n = rig.BoneNames.Count;
            if (bonePaths.Count != n) throw new ArgumentException($"expected one path per bone ({n}), got {bonePaths.Count}", nameof(bonePaths));
            if (plan.Kind != KeyFillClipKind.Transform) throw new ArgumentException($"{plan.Clip} is a humanoid clip; its key poses are sampled by the engine and its fill written from recorded muscles", nameof(plan));
            CheckSameCurves(plan, curves);
            var byPath = new Dictionary<string, int>(StringComparer.Ordinal);
            for (int b = 0; b < n; b++) byPath[bonePaths[b]] = b;
            var bones = new BoneCurves[n];
            for (int b = 0; b < n; b++) bones[b] = new BoneCurves();
            for (int i = 0; i < curves.Count; i++)
            {
                KeyedCurve curve = curves[i];
                if (!plan.PoseCurveArray[i]) continue;
                if (!byPath.TryGetValue(curve.Path, out int b))
                {
                    throw new KeyFillException(plan.Clip, $"{curve} animates a transform that is not one of {rig.Name}'s bones", "expected pose curves on the rig's bones only (the model predicts nothing else; move the curve to another clip)", nameof(curves));
                }

                string stem = curve.Property.Substring(0, curve.Property.Length - 2);
                int c = curve.Property[curve.Property.Length - 1] == 'w' ? 3 : curve.Property[curve.Property.Length - 1] - 'x';
                if (stem == "m_LocalRotation")
                {
                    Set(ref bones[b].Quaternion, 4, c, i);
                }
                else if (stem == EulerStem)
                {
                    Set(ref bones[b].Euler, 3, c, i);
                }
                else if (stem == "m_LocalPosition")
                {
                    if (b != 0)
                    {
                        throw new KeyFillException(plan.Clip, $"{curve} keys the position of {rig.BoneNames[b]}, which is not the root bone", $"expected position curves on the root bone ({bonePaths[0]}) only: the model moves the root and rotates the others", nameof(curves));
                    }

                    Set(ref bones[b].Position, 3, c, i);
                }
                else
                {
                    throw new KeyFillException(plan.Clip, $"{curve} is a {stem} curve", $"expected m_LocalRotation or {EulerStem} rotation curves (as the Animation window keys them)", nameof(curves));
                }
            }

            for (int b = 0; b < n; b++)
            {
                BoneCurves bone = bones[b];
                if (bone.Quaternion != null && bone.Euler != null)
                {
                    throw new KeyFillException(plan.Clip, $"{Path(bonePaths[b])} has both m_LocalRotation and {EulerStem} curves", "expected one kind of rotation curve per bone", nameof(curves));
                }

                Complete(plan, bone.Quaternion, bonePaths[b], "m_LocalRotation.x/y/z/w");
                Complete(plan, bone.Euler, bonePaths[b], EulerStem + ".x/y/z");
            }

            return bones;
        }

        private static void CheckSameCurves(KeyFillPlan plan, IReadOnlyList<KeyedCurve> curves)
        {
            if (curves.Count != plan.PoseCurveArray.Length) throw new ArgumentException($"{curves.Count} curves given; the plan was made on {plan.PoseCurveArray.Length}: plan again on these curves", nameof(curves));
        }

        private static void Set(ref int[]? slots, int count, int component, int curve)
        {
            if (slots == null)
            {
                slots = new int[count];
                for (int c = 0; c < count; c++) slots[c] = -1;
            }

            slots[component] = curve;
        }

        // A rotation needs every component: one keyed alone would be filled from a rotation the others do not share.
        private static void Complete(KeyFillPlan plan, int[]? slots, string path, string what)
        {
            if (slots == null) return;
            foreach (int s in slots)
            {
                if (s < 0) throw new KeyFillException(plan.Clip, $"{Path(path)} has some of its {what} curves but not all", "expected every component of a rotation keyed (key the rotation, not one axis)", "curves");
            }
        }

        private static string Path(string path) => path.Length == 0 ? "<root>" : path;

        /// <summary>Unity's Euler angles (degrees; Z, then X, then Y about the parent's axes: <c>Quaternion.Euler</c>) and back.</summary>
        internal static class UnityEuler
        {
            private const double Degrees = 180 / Math.PI;

            /// <summary>The rotation (w, x, y, z) of Euler angles in degrees, q = q_y ⊗ q_x ⊗ q_z.</summary>
            public static QuaternionD ToRotation(double x, double y, double z) => Quaternions.FromEulerDegrees(y, x, z, EulerOrder.Yxz);

            /// <summary>
            /// The Euler angles (degrees) of <paramref name="q"/> nearest <paramref name="previous"/>: of the two solutions
            /// (x, y, z) and (180 − x, y + 180, z + 180), each component moved by whole turns to lie within 180° of the
            /// previous value, the one that moved least.
            /// </summary>
            public static void Nearest(QuaternionD q, ReadOnlySpan<double> previous, Span<double> result)
            {
                Vector3D e = Quaternions.ToEuler(q, EulerOrder.Yxz); // (y, x, z), radians
                double x = e.Y * Degrees, y = e.X * Degrees, z = e.Z * Degrees;
                Span<double> a = stackalloc double[] { Unwrap(x, previous[0]), Unwrap(y, previous[1]), Unwrap(z, previous[2]) };
                Span<double> b = stackalloc double[] { Unwrap(180 - x, previous[0]), Unwrap(y + 180, previous[1]), Unwrap(z + 180, previous[2]) };
                double da = 0, db = 0;
                for (int c = 0; c < 3; c++)
                {
                    da += Math.Abs(a[c] - previous[c]);
                    db += Math.Abs(b[c] - previous[c]);
                }

                (db < da ? b : a).CopyTo(result);
            }

            private static double Unwrap(double angle, double previous) => angle + 360 * Math.Round((previous - angle) / 360);
        }
    }
}
