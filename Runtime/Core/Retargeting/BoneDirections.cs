using System;
using System.Collections.Generic;
using System.Globalization;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// How far a source's reference pose is from the pose the target declares (for the model: its T-pose),
    /// bone by bone. <see cref="SkeletonMap"/> aligns any reference pose, so a character in an A-pose or
    /// with a bent arm still maps; but every frame is then read relative to that pose, and a reference that
    /// is not the T-pose the user believes it is (the bind pose of a rig modelled with arms down, a clip
    /// frame mid-step) bends every transition the same wrong way. A clear refusal at start is kinder.
    /// </summary>
    public static class BoneDirections
    {
        /// <summary>
        /// Per target joint: the angle (radians) between its bone (to its only child) in the source's
        /// reference pose and in <paramref name="declared"/> turned by the root's yaw alignment; NaN for
        /// joints whose bone is not compared (<see cref="SkeletonMap.AlignedBones"/> false).
        /// </summary>
        /// <param name="map">The map (its aligned target reference carries the source's bone directions).</param>
        /// <param name="declared">The target's declared reference pose the map was created with.</param>
        public static double[] Deviations(SkeletonMap map, ReferencePose declared)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (declared == null) throw new ArgumentNullException(nameof(declared));
            ReferencePose aligned = map.TargetReference;
            int count = map.Target.JointCount;
            var deviation = new double[count];
            // The root's alignment is a yaw only (SkeletonMap aligns the facing first); bones are compared after it.
            QuaternionD yaw = Quaternions.Multiply(aligned.GlobalRotation(0), Quaternions.Conjugate(declared.GlobalRotation(0)));
            var onlyChild = new int[count];
            var children = new int[count];
            for (int j = 1; j < count; j++)
            {
                int p = map.Target.Parents[j];
                children[p]++;
                onlyChild[p] = j;
            }

            for (int j = 0; j < count; j++)
            {
                deviation[j] = double.NaN;
                if (!map.AlignedBones[j] || children[j] != 1) continue;
                int c = onlyChild[j];
                Vector3D want = Quaternions.Apply(yaw, declared.GlobalPosition(c) - declared.GlobalPosition(j));
                Vector3D have = aligned.GlobalPosition(c) - aligned.GlobalPosition(j);
                deviation[j] = Math.Atan2(Vector3D.Cross(want, have).Length, Vector3D.Dot(want, have));
            }

            return deviation;
        }

        /// <summary>
        /// Refuses a source reference pose in which a mapped bone points more than
        /// <paramref name="maxDegrees"/> away from <paramref name="declared"/>, naming every such bone
        /// (the source's name, the target's in parentheses, and the angle).
        /// </summary>
        /// <param name="map">The map.</param>
        /// <param name="declared">The target's declared reference pose the map was created with.</param>
        /// <param name="maxDegrees">The largest angle allowed.</param>
        /// <param name="sourceName">The source's name or file, for the message.</param>
        /// <exception cref="JointMapException">One or more bones point too far away.</exception>
        public static void RequireTPose(SkeletonMap map, ReferencePose declared, double maxDegrees, string sourceName)
        {
            if (!(maxDegrees > 0) || double.IsInfinity(maxDegrees)) throw new ArgumentOutOfRangeException(nameof(maxDegrees), maxDegrees, "expected a positive number of degrees");
            double[] deviation = Deviations(map, declared);
            var off = new List<string>();
            for (int j = 0; j < deviation.Length; j++)
            {
                double degrees = deviation[j] * 180.0 / Math.PI;
                if (!(degrees > maxDegrees)) continue;
                string source = map.Source.Names[map.SourceJointOf(j)];
                off.Add(string.Format(CultureInfo.InvariantCulture, "{0} ({1}) {2:0}°", source, map.Target.Names[j], degrees));
            }

            if (off.Count == 0) return;
            throw new JointMapException(sourceName ?? "<source>",
                $"in the reference pose {off.Count} bone(s) point more than {maxDegrees.ToString("0.#", CultureInfo.InvariantCulture)}° from the model's T-pose: {string.Join(", ", off)}",
                "expected a T-pose reference (legs straight down, arms straight out sideways, spine and head up); choose the avatar's T-pose, a bind pose in T-pose or a T-pose frame of a clip");
        }
    }
}
