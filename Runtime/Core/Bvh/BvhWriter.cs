using System;
using System.Globalization;
using System.IO;
using System.Text;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// Writes BVH files in the layout of a <see cref="BvhAnimation"/>: each joint's channels in their own
    /// order, End Sites, tab indentation. Rotations are converted back to Euler angles in each joint's
    /// channel order (middle angle in [−90°, 90°]), so read → write → read gives the same rotations and
    /// positions (to the 6 decimals written), though not necessarily the same angle triples.
    /// </summary>
    public static class BvhWriter
    {
        private const double RadiansToDegrees = 180.0 / Math.PI;

        /// <summary>
        /// Writes <paramref name="animation"/> to the file at <paramref name="path"/> through
        /// <see cref="OutputFile.Write"/>: a temporary file beside it, renamed into place when complete, so a
        /// failure leaves an existing file byte-identical. Call <see cref="OutputFile.Check(string, bool, string[])"/>
        /// first to refuse an existing file without the user's consent or a path that is also an input.
        /// </summary>
        /// <param name="animation">What to write.</param>
        /// <param name="path">Destination file; replaced when complete.</param>
        /// <param name="newLine">Line ending, "\n" (default) or "\r\n" (as LaFAN1 files have).</param>
        public static void Write(BvhAnimation animation, string path, string newLine = "\n")
        {
            OutputFile.Write(path, stream =>
            {
                using (var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, true))
                {
                    Write(animation, writer, newLine);
                }
            });
        }

        /// <summary>Writes <paramref name="animation"/> as BVH text to <paramref name="writer"/>.</summary>
        public static void Write(BvhAnimation animation, TextWriter writer, string newLine = "\n")
        {
            if (animation == null) throw new ArgumentNullException(nameof(animation));
            if (writer == null) throw new ArgumentNullException(nameof(writer));
            if (newLine != "\n" && newLine != "\r\n") throw new ArgumentException("newLine must be \"\\n\" or \"\\r\\n\"", nameof(newLine));

            Skeleton skeleton = animation.Skeleton;
            RequireDepthFirstOrder(skeleton);
            RequireFinite(animation);
            var sb = new StringBuilder(4096);
            sb.Append("HIERARCHY").Append(newLine);
            WriteJoint(animation, 0, 0, sb, newLine);
            sb.Append("MOTION").Append(newLine);
            MotionClip motion = animation.Motion;
            sb.Append("Frames: ").Append(motion.FrameCount.ToString(CultureInfo.InvariantCulture)).Append(newLine);
            sb.Append("Frame Time: ").Append(motion.FrameTime.ToString("0.0#######", CultureInfo.InvariantCulture)).Append(newLine);
            writer.Write(sb.ToString());

            int jointCount = skeleton.JointCount;
            var orders = new EulerOrder?[jointCount];
            for (int j = 0; j < jointCount; j++) orders[j] = animation.RotationOrder(j);

            Span<double> euler = stackalloc double[3];
            for (int f = 0; f < motion.FrameCount; f++)
            {
                sb.Clear();
                bool first = true;
                for (int j = 0; j < jointCount; j++)
                {
                    int p = motion.PositionIndex(f, j);
                    if (orders[j] is EulerOrder order)
                    {
                        Vector3D e = Quaternions.ToEuler(QuaternionD.Read(motion.LocalRotations, motion.RotationIndex(f, j)), order);
                        euler[0] = e.X * RadiansToDegrees;
                        euler[1] = e.Y * RadiansToDegrees;
                        euler[2] = e.Z * RadiansToDegrees;
                    }

                    int r = 0;
                    foreach (BvhChannel c in animation.JointChannels[j])
                    {
                        double value = c.IsRotation() ? euler[r++] : motion.LocalPositions[p + c.Axis()];
                        if (!first) sb.Append(' ');
                        first = false;
                        AppendNumber(sb, value);
                    }
                }

                sb.Append(newLine);
                writer.Write(sb.ToString());
            }

            writer.Flush();
        }

        /// <summary>
        /// A NaN or an infinity never reaches a file (a reader refuses it, and it would replace good motion):
        /// refused with <see cref="DataFormatException"/> naming the frame and joint, before a byte is written.
        /// </summary>
        private static void RequireFinite(BvhAnimation animation)
        {
            MotionClip motion = animation.Motion;
            Skeleton skeleton = animation.Skeleton;
            const string expected = "expected finite motion (an input value too large to compute with, e.g. 1e308, or a --scale or frame time that overflows); nothing was written";
            if (!IsFinite(motion.FrameTime) || !(motion.FrameTime > 0))
            {
                throw new DataFormatException(animation.SourceName, $"the frame time is {motion.FrameTime.ToString(CultureInfo.InvariantCulture)}", expected);
            }

            for (int i = 0; i < skeleton.Offsets.Count; i++)
            {
                if (!IsFinite(skeleton.Offsets[i])) throw new DataFormatException(animation.SourceName, $"joint '{skeleton.Names[i / 3]}' has a non-finite offset", expected);
            }

            int j = skeleton.JointCount;
            double[] positions = motion.LocalPositions, rotations = motion.LocalRotations;
            for (int f = 0; f < motion.FrameCount; f++)
            {
                for (int k = 0; k < j; k++)
                {
                    int p = motion.PositionIndex(f, k), r = motion.RotationIndex(f, k);
                    bool finite = IsFinite(positions[p]) && IsFinite(positions[p + 1]) && IsFinite(positions[p + 2])
                        && IsFinite(rotations[r]) && IsFinite(rotations[r + 1]) && IsFinite(rotations[r + 2]) && IsFinite(rotations[r + 3]);
                    if (!finite)
                    {
                        throw new DataFormatException(animation.SourceName,
                            string.Format(CultureInfo.InvariantCulture, "frame {0}, joint '{1}' is not a finite number (NaN or infinity) in the result", f, skeleton.Names[k]),
                            expected);
                    }
                }
            }
        }

        private static bool IsFinite(double value) => !double.IsNaN(value) && !double.IsInfinity(value);

        /// <summary>
        /// BVH lists joints depth-first; a reader numbers them in that order. A skeleton whose indices are
        /// another topological order would come back renumbered, so it is refused.
        /// </summary>
        private static void RequireDepthFirstOrder(Skeleton skeleton)
        {
            // In depth-first preorder the parent of joint j is j−1 or one of j−1's ancestors.
            for (int j = 1; j < skeleton.JointCount; j++)
            {
                int ancestor = j - 1;
                while (ancestor >= 0 && ancestor != skeleton.Parents[j]) ancestor = skeleton.Parents[ancestor];
                if (ancestor < 0)
                {
                    throw new ArgumentException(
                        $"joint {j} ('{skeleton.Names[j]}') is not in depth-first order; BVH lists each joint's subtree before its next sibling, so reorder the joints first");
                }
            }
        }

        private static void WriteJoint(BvhAnimation animation, int joint, int depth, StringBuilder sb, string newLine)
        {
            Skeleton skeleton = animation.Skeleton;
            string indent = new string('\t', depth);
            sb.Append(indent).Append(joint == 0 ? "ROOT " : "JOINT ").Append(skeleton.Names[joint]).Append(newLine);
            sb.Append(indent).Append('{').Append(newLine);
            sb.Append(indent).Append("\tOFFSET ");
            AppendVector(sb, new Vector3D(skeleton.Offsets[3 * joint], skeleton.Offsets[3 * joint + 1], skeleton.Offsets[3 * joint + 2]));
            sb.Append(newLine);
            sb.Append(indent).Append("\tCHANNELS ").Append(BvhChannels.Describe(animation.JointChannels[joint])).Append(newLine);
            for (int child = joint + 1; child < skeleton.JointCount; child++)
            {
                if (skeleton.Parents[child] == joint) WriteJoint(animation, child, depth + 1, sb, newLine);
            }

            foreach (Vector3D site in animation.EndSites[joint])
            {
                sb.Append(indent).Append("\tEnd Site").Append(newLine);
                sb.Append(indent).Append("\t{").Append(newLine);
                sb.Append(indent).Append("\t\tOFFSET ");
                AppendVector(sb, site);
                sb.Append(newLine);
                sb.Append(indent).Append("\t}").Append(newLine);
            }

            sb.Append(indent).Append('}').Append(newLine);
        }

        private static void AppendVector(StringBuilder sb, Vector3D v)
        {
            AppendNumber(sb, v.X);
            sb.Append(' ');
            AppendNumber(sb, v.Y);
            sb.Append(' ');
            AppendNumber(sb, v.Z);
        }

        private static void AppendNumber(StringBuilder sb, double value)
        {
            // Six decimals, like LaFAN1 and most exporters: 1e-6 degrees or data units, far below
            // anything visible; avoids "-0.000000" so files diff cleanly.
            string text = value.ToString("F6", CultureInfo.InvariantCulture);
            if (text == "-0.000000") text = "0.000000";
            sb.Append(text);
        }
    }
}
