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

        /// <summary>The largest angle (degrees) a mapped bone may point from the model's T-pose: one number for the CLI and the component.</summary>
        public const double DefaultMaxDegrees = 25.0;

        /// <summary>
        /// The bones compared in a reference pose that is not declared a T-pose (any rig file the CLI reads):
        /// spine, neck and legs. Arms are left out because retargeting aligns any arm pose (arms-down rest poses
        /// retarget well), and feet and toes because rigs model them at any angle.
        /// </summary>
        public static IReadOnlyList<string> UprightBones { get; } = new[] { "Spine", "Spine1", "Spine2", "Neck", "LeftUpLeg", "LeftLeg", "RightUpLeg", "RightLeg" };

        /// <summary>
        /// Refuses a source reference pose in which a mapped bone points more than
        /// <paramref name="maxDegrees"/> away from <paramref name="declared"/>, naming every such bone
        /// (the source's name, the target's in parentheses, and the angle).
        /// </summary>
        /// <param name="map">The map.</param>
        /// <param name="declared">The target's declared reference pose the map was created with.</param>
        /// <param name="maxDegrees">The largest angle allowed.</param>
        /// <param name="sourceName">The source's name or file, for the message.</param>
        /// <param name="only">The target joints whose bones are compared (<see cref="UprightBones"/> for a reference
        /// not declared a T-pose), or null for every bone (a reference declared a T-pose: the component's avatar).</param>
        /// <exception cref="JointMapException">One or more bones point too far away.</exception>
        public static void RequireTPose(SkeletonMap map, ReferencePose declared, double maxDegrees, string sourceName, IReadOnlyList<string>? only = null)
        {
            List<string> off = OffBones(map, declared, maxDegrees, only);
            if (off.Count == 0) return;
            if (only != null)
            {
                throw new JointMapException(sourceName ?? "<source>",
                    $"in the reference pose {off.Count} spine, neck or leg bone(s) point more than {maxDegrees.ToString("0.#", CultureInfo.InvariantCulture)}° from the model's standing pose: {string.Join(", ", off)}",
                    "expected a standing humanoid (legs down, spine and neck up); a rig that is not humanoid cannot be mapped, a wrong bone in the joint map is fixed with --map, a reference pose that does not stand is replaced with --reference-frame naming a standing frame (or --up for a file lying along Z), and a reference pose meant as it is is kept with " + AcceptOption + " (reported in every output)");
            }

            throw new JointMapException(sourceName ?? "<source>",
                $"in the reference pose {off.Count} bone(s) point more than {maxDegrees.ToString("0.#", CultureInfo.InvariantCulture)}° from the model's T-pose: {string.Join(", ", off)}",
                "expected a T-pose reference (legs straight down, arms straight out sideways, spine and head up); choose the avatar's T-pose, a bind pose in T-pose or a T-pose frame of a clip");
        }

        /// <summary>The CLI's explicit override of the humanoid rule (named in the refusal and in what an accepted pose reports).</summary>
        public const string AcceptOption = "--accept-reference-pose";

        /// <summary>
        /// What <see cref="RequireTPose"/> would refuse, as one clause for every output of a run that accepted the
        /// reference pose anyway (<see cref="AcceptOption"/>), or null when nothing is off.
        /// </summary>
        public static string? AcceptedDeviation(SkeletonMap map, ReferencePose declared, double maxDegrees, IReadOnlyList<string>? only = null)
        {
            if (!(maxDegrees > 0) || double.IsInfinity(maxDegrees)) throw new ArgumentOutOfRangeException(nameof(maxDegrees), maxDegrees, "expected a positive number of degrees");
            List<string> off = OffBones(map, declared, maxDegrees, only);
            if (off.Count == 0) return null;
            return $"reference pose accepted by {AcceptOption} although {off.Count} bone(s) point more than {maxDegrees.ToString("0.#", CultureInfo.InvariantCulture)}° from the model's {(only != null ? "standing pose" : "T-pose")}: {string.Join(", ", off)}";
        }

        private static List<string> OffBones(SkeletonMap map, ReferencePose declared, double maxDegrees, IReadOnlyList<string>? only)
        {
            if (!(maxDegrees > 0) || double.IsInfinity(maxDegrees)) throw new ArgumentOutOfRangeException(nameof(maxDegrees), maxDegrees, "expected a positive number of degrees");
            double[] deviation = Deviations(map, declared);
            var off = new List<string>();
            for (int j = 0; j < deviation.Length; j++)
            {
                double degrees = deviation[j] * 180.0 / Math.PI;
                if (!(degrees > maxDegrees)) continue;
                if (only != null && !Contains(only, map.Target.Names[j])) continue;
                string source = map.Source.Names[map.SourceJointOf(j)];
                off.Add(string.Format(CultureInfo.InvariantCulture, "{0} ({1}) {2:0}°", source, map.Target.Names[j], degrees));
            }

            return off;
        }

        private static bool Contains(IReadOnlyList<string> names, string name)
        {
            foreach (string n in names) if (string.Equals(n, name, StringComparison.Ordinal)) return true;
            return false;
        }
    }
}
