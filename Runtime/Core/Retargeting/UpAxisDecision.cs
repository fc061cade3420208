using System;
using System.Globalization;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// What a file's up axis was taken to be, for its reference pose and for its motion, and the rotations
    /// that stand both on the model's Y up (<see cref="SkeletonMap.Create"/> applies them).
    /// </summary>
    /// <remarks>
    /// <c>--up y|z</c> names the up axis of the motion's world. A reference pose taken from a frame lies in
    /// that world too; the skeleton's default pose (its rest pose) is judged on its own (<see cref="UpAxisDetection.OfPose"/>),
    /// since a Y-up skeleton can move in a Z-up world. With <see cref="UpAxis.Auto"/> both are detected.
    /// </remarks>
    public sealed class UpAxisDecision
    {
        private UpAxisDecision(UpAxis requested, UpAxis referenceUp, UpAxis motionUp, string description)
        {
            Requested = requested;
            ReferenceUp = referenceUp;
            MotionUp = motionUp;
            Description = description;
        }

        /// <summary>What was asked for (<see cref="UpAxis.Auto"/> by default).</summary>
        public UpAxis Requested { get; }

        /// <summary>The reference pose's up axis (Y or Z).</summary>
        public UpAxis ReferenceUp { get; }

        /// <summary>The motion's up axis (Y or Z).</summary>
        public UpAxis MotionUp { get; }

        /// <summary>One line for the console, e.g. "up axis auto: motion Z-up (floor score Y 0.02, Z 0.95 leg lengths), reference pose Y-up; turned to the model's Y up".</summary>
        public string Description { get; }

        /// <summary>The rotation that stands the motion on Y.</summary>
        public QuaternionD MotionToYUp => UpAxisDetection.ToYUp(MotionUp);

        /// <summary>Nothing is turned.</summary>
        public bool IsIdentity => ReferenceUp == UpAxis.Y && MotionUp == UpAxis.Y;

        /// <summary>
        /// Decides the up axes of <paramref name="motion"/> and of its reference pose.
        /// </summary>
        /// <param name="requested">The user's choice (auto, y, z).</param>
        /// <param name="reference">The reference pose as read from the file.</param>
        /// <param name="referenceIsFrame">True when the reference is a frame of the motion (it lies in the motion's world).</param>
        /// <param name="motion">The motion (read for <see cref="UpAxis.Auto"/> only).</param>
        /// <param name="map">The joint map that finds hips, head and feet.</param>
        public static UpAxisDecision Decide(UpAxis requested, ReferencePose reference, bool referenceIsFrame, MotionClip motion, JointMap map)
        {
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            if (motion == null) throw new ArgumentNullException(nameof(motion));
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (requested != UpAxis.Auto && requested != UpAxis.Y && requested != UpAxis.Z) throw new ArgumentOutOfRangeException(nameof(requested), requested, "expected auto, y or z");
            UpAxis motionUp;
            string evidence = "";
            if (requested == UpAxis.Auto)
            {
                var judged = UpAxisDetection.OfMotion(motion, map);
                motionUp = judged?.Up ?? UpAxis.Y;
                evidence = judged == null
                    ? " (no hips, head or feet to judge by: Y kept)"
                    : string.Format(CultureInfo.InvariantCulture, " (floor score Y {0:0.00}, Z {1:0.00} leg lengths)", judged.Value.ScoreY, judged.Value.ScoreZ);
            }
            else
            {
                motionUp = requested;
            }

            UpAxis referenceUp = referenceIsFrame && requested != UpAxis.Auto ? requested : UpAxisDetection.OfPose(reference, map) ?? UpAxis.Y;
            string description = string.Format(CultureInfo.InvariantCulture, "up axis {0}: motion {1}-up{2}, reference pose {3}-up{4}; {5}",
                UpAxes.Name(requested), motionUp, evidence, referenceUp, referenceIsFrame ? " (a frame)" : " (the rest pose)",
                motionUp == UpAxis.Y && referenceUp == UpAxis.Y ? "nothing turned" : "turned to the model's Y up");
            return new UpAxisDecision(requested, referenceUp, motionUp, description);
        }

        /// <summary>
        /// The clip itself stood on Y, for tools that keep the file's skeleton (the Unity importer): rest offsets
        /// turned by the rest pose's rotation R (so the rest pose stands), non-root local rotations conjugated by
        /// it (R q R⁻¹), the root's rotation W q R⁻¹ and position W p with W the motion's rotation, so every
        /// joint's world position is W times the file's.
        /// </summary>
        public MotionClip Apply(MotionClip clip)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (IsIdentity) return clip;
            QuaternionD r = UpAxisDetection.ToYUp(ReferenceUp), w = MotionToYUp, rBack = Quaternions.Conjugate(r);
            Skeleton s = clip.Skeleton;
            int n = s.JointCount;
            var offsets = new double[3 * n];
            for (int j = 0; j < n; j++) Quaternions.Apply(r, Vector3D.Read(s.OffsetSpan, 3 * j)).Write(offsets, 3 * j);
            var turned = new Skeleton(s.Names, s.Parents, offsets);
            var positions = new double[clip.LocalPositions.Length];
            var rotations = new double[clip.LocalRotations.Length];
            for (int f = 0; f < clip.FrameCount; f++)
            {
                for (int j = 0; j < n; j++)
                {
                    int p = clip.PositionIndex(f, j), q = clip.RotationIndex(f, j);
                    Quaternions.Apply(j == 0 ? w : r, Vector3D.Read(clip.LocalPositions, p)).Write(positions, p);
                    QuaternionD local = Quaternions.Multiply(j == 0 ? w : r, Quaternions.Multiply(QuaternionD.Read(clip.LocalRotations, q), rBack));
                    Quaternions.Normalize(local).Write(rotations, q);
                }
            }

            return new MotionClip(turned, clip.FrameCount, clip.FrameTime, positions, rotations);
        }

        /// <summary>The reference pose stood on Y: its root turned by the reference's rotation to Y up.</summary>
        public ReferencePose Turn(ReferencePose reference)
        {
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            if (ReferenceUp == UpAxis.Y) return reference;
            QuaternionD w = UpAxisDetection.ToYUp(ReferenceUp);
            var local = new double[reference.LocalRotations.Count];
            for (int i = 0; i < local.Length; i++) local[i] = reference.LocalRotations[i];
            Quaternions.Normalize(Quaternions.Multiply(w, QuaternionD.Read(local, 0))).Write(local, 0);
            return new ReferencePose(reference.Skeleton, local, Quaternions.Apply(w, reference.RootPosition));
        }
    }
}
