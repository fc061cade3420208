using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// Tells a Z-up file from a Y-up one, separately for its reference pose and for its motion: a Y-up
    /// skeleton can move in a Z-up world (its root turned on every frame) and a Z-up rest skeleton lies down
    /// at zero rotations. Only Y and Z are told apart; anything else is left to the leg-length and
    /// bone-direction refusals.
    /// </summary>
    /// <remarks>
    /// <para><b>Reference pose.</b> A reference pose stands by definition: its up is the world axis (Y or Z)
    /// nearer to the direction from the middle of the feet to the head.</para>
    /// <para><b>Motion.</b> Hips height alone would misjudge people who crawl, lie or fall, so the motion's up
    /// is where its floor is: for each candidate axis, per sampled frame, the body's lowest point along it
    /// (over every joint) and the hips' and the lower foot's heights above that point. Along the true up the
    /// lowest points stay on one plane (the floor), a foot is mostly on it and the hips stand above it; along
    /// a horizontal axis the lowest point is the rearmost joint, which travels with the body and sits close
    /// to the hips; upside down the lowest point is the head, far from the feet. The score of an axis is the
    /// median hips height minus the median foot height minus the spread (10th to 90th percentile) of the
    /// lowest points, in leg lengths; Z is chosen only when it scores more than <see cref="Margin"/> and
    /// <see cref="Margin"/> more than Y, so a Y-up file is never turned on weak evidence (a clip that neither
    /// stands nor travels, or climbs so that no floor holds, keeps Y).</para>
    /// </remarks>
    public static class UpAxisDetection
    {
        /// <summary>How many leg lengths Z must score above Y for a motion to be called Z-up.</summary>
        public const double Margin = 0.3;

        /// <summary>Frames read at most (evenly spaced) to judge a motion.</summary>
        public const int MaxSampledFrames = 600;

        /// <summary>The rotation that turns a world with <paramref name="up"/> up into the model's Y-up one.</summary>
        public static QuaternionD ToYUp(UpAxis up)
        {
            if (up == UpAxis.Z)
            {
                // −90° about X: (x, y, z) → (x, z, −y), so +Z becomes +Y.
                double h = Math.Sqrt(0.5);
                return new QuaternionD(h, -h, 0, 0);
            }

            return QuaternionD.Identity;
        }

        /// <summary>The first built-in joint map that finds hips, head and feet in <paramref name="skeleton"/> (for tools without a model skeleton), or null.</summary>
        public static JointMap? BodyMap(Skeleton skeleton)
        {
            foreach (JointMap map in JointMap.BuiltIn) if (FindBody(skeleton, map) != null) return map;
            return null;
        }

        /// <summary>The up axis of a reference pose (Y or Z), or null when the map finds no hips, head or feet in it.</summary>
        public static UpAxis? OfPose(ReferencePose pose, JointMap map)
        {
            if (!(FindBody(pose.Skeleton, map) is { } body)) return null;
            Vector3D feet = Vector3D.Zero;
            foreach (int f in body.Feet) feet = feet + pose.GlobalPosition(f);
            Vector3D v = pose.GlobalPosition(body.Head) - (1.0 / body.Feet.Length) * feet;
            return v.Z > Math.Abs(v.Y) ? UpAxis.Z : UpAxis.Y;
        }

        /// <summary>
        /// The up axis of a motion (Y or Z) by where its floor is (see the remarks), with the two axes'
        /// scores; null when the map finds no hips, head or feet, or the legs have no length.
        /// </summary>
        public static (UpAxis Up, double ScoreY, double ScoreZ)? OfMotion(MotionClip motion, JointMap map)
        {
            if (motion == null) throw new ArgumentNullException(nameof(motion));
            double[]? score = Scores(motion, map, new[] { Vector3D.UnitY, Vector3D.UnitZ });
            if (score == null) return null;
            return (IsFloor(score[1], score[0]) ? UpAxis.Z : UpAxis.Y, score[0], score[1]);
        }

        /// <summary>
        /// Refuses motion on the model's skeleton that does not stand on +Y: when another of the six axis
        /// directions (±X, ±Y, ±Z) scores <see cref="Margin"/> more than +Y, the figure lies (or hangs) on that
        /// side; <paramref name="decided"/> says what was done, for the message.
        /// </summary>
        /// <exception cref="Workflows.MotionRequestException">The motion lies down.</exception>
        public static void RequireStanding(MotionClip onModel, string sourceName, string decided)
        {
            if (onModel == null) throw new ArgumentNullException(nameof(onModel));
            string[] names = { "+Y", "-Y", "+X", "-X", "+Z", "-Z" };
            var axes = new[] { Vector3D.UnitY, -1.0 * Vector3D.UnitY, Vector3D.UnitX, -1.0 * Vector3D.UnitX, Vector3D.UnitZ, -1.0 * Vector3D.UnitZ };
            double[]? score = Scores(onModel, JointMap.Lafan1, axes);
            if (score == null) return;
            int best = 0;
            for (int a = 1; a < axes.Length; a++) if (score[a] > score[best]) best = a;
            if (best == 0 || !IsFloor(score[best], score[0])) return;
            throw new Workflows.MotionRequestException(sourceName ?? "<source>",
                string.Format(System.Globalization.CultureInfo.InvariantCulture,
                    "after retargeting the motion lies down: its floor is on the {0} side (floor score {1:0.00} leg lengths against {2:0.00} for +Y) with {3}",
                    names[best], score[best], score[0], decided),
                "expected it standing on Y; the file's up axis was likely misjudged: pass --up z for a Z-up file or --up y for a Y-up one (the importer's Up Axis setting in Unity), or name a standing frame with --reference-frame");
        }

        private static double[]? Scores(MotionClip motion, JointMap map, Vector3D[] axes)
        {
            Skeleton skeleton = motion.Skeleton;
            if (!(FindBody(skeleton, map) is { } body) || !(body.LegLength > 0) || motion.FrameCount == 0) return null;
            int joints = skeleton.JointCount;
            int samples = Math.Min(motion.FrameCount, MaxSampledFrames);
            var globalPositions = new double[3 * joints];
            var globalRotations = new double[4 * joints];
            var lowest = new double[axes.Length][];
            var hipsHeight = new double[axes.Length][];
            var feetHeight = new double[axes.Length][];
            for (int a = 0; a < axes.Length; a++)
            {
                lowest[a] = new double[samples];
                hipsHeight[a] = new double[samples];
                feetHeight[a] = new double[samples];
            }

            for (int i = 0; i < samples; i++)
            {
                int f = samples == 1 ? 0 : (int)((long)i * (motion.FrameCount - 1) / (samples - 1));
                ReadOnlySpan<double> lp = motion.LocalPositions.AsSpan(motion.PositionIndex(f, 0), 3 * joints);
                ForwardKinematics.ComputeFrame(skeleton.ParentSpan, lp, Vector3D.Read(lp, 0), motion.LocalRotations.AsSpan(motion.RotationIndex(f, 0), 4 * joints), globalPositions, globalRotations);
                for (int a = 0; a < axes.Length; a++)
                {
                    double low = double.PositiveInfinity;
                    for (int j = 0; j < joints; j++) low = Math.Min(low, Vector3D.Dot(Vector3D.Read(globalPositions, 3 * j), axes[a]));
                    lowest[a][i] = low;
                    hipsHeight[a][i] = Vector3D.Dot(Vector3D.Read(globalPositions, 3 * body.Hips), axes[a]) - low;
                    double feet = double.PositiveInfinity;
                    foreach (int foot in body.Feet) feet = Math.Min(feet, Vector3D.Dot(Vector3D.Read(globalPositions, 3 * foot), axes[a]));
                    feetHeight[a][i] = feet - low;
                }
            }

            var score = new double[axes.Length];
            for (int a = 0; a < axes.Length; a++)
            {
                Array.Sort(lowest[a]);
                Array.Sort(hipsHeight[a]);
                Array.Sort(feetHeight[a]);
                double spread = Percentile(lowest[a], 0.9) - Percentile(lowest[a], 0.1);
                score[a] = (Percentile(hipsHeight[a], 0.5) - Percentile(feetHeight[a], 0.5) - spread) / body.LegLength;
            }

            return score;
        }

        /// <summary>
        /// True when an axis that scores <paramref name="other"/> is the floor rather than +Y: it must look like
        /// a floor on its own (above <see cref="Margin"/>: hips well above a resting foot) and beat Y by the
        /// margin; a clip whose floor moves on every axis (climbing, jumping down) keeps Y.
        /// </summary>
        private static bool IsFloor(double other, double y) => other > Margin && other > y + Margin;

        private static double Percentile(double[] sorted, double p) => sorted[(int)Math.Round(p * (sorted.Length - 1))];

        /// <summary>
        /// The joints detection reads, found through a joint map's chains, and the rest skeleton's bone lengths summed
        /// from the hips down to the first foot (pose-free); null when the map finds no hips, head or foot.
        /// </summary>
        private static (int Hips, int Head, int[] Feet, double LegLength)? FindBody(Skeleton skeleton, JointMap map)
        {
            int hips = Last(skeleton, map, "Hips"), head = Last(skeleton, map, "Head");
            var feet = new List<int>();
            foreach (string name in new[] { "LeftFoot", "RightFoot", "LeftToe", "RightToe" })
            {
                int f = Last(skeleton, map, name);
                if (f >= 0) feet.Add(f);
            }

            if (hips < 0 || head < 0 || feet.Count == 0) return null;
            double length = 0;
            ReadOnlySpan<double> offsets = skeleton.OffsetSpan;
            for (int j = feet[0]; j != hips; j = skeleton.Parents[j])
            {
                if (j < 0) return null;
                length += Vector3D.Read(offsets, 3 * j).Length;
            }

            return (hips, head, feet.ToArray(), length);
        }

        private static int Last(Skeleton skeleton, JointMap map, string target)
        {
            IReadOnlyList<string>? chain = map.SourceChain(target);
            int[]? found = chain == null ? null : JointMap.FindChain(skeleton, chain);
            return found == null ? -1 : found[found.Length - 1];
        }
    }
}
