using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Core.IO;
using System.Text;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>
    /// The benchmark's normalisation statistics: per-coordinate mean and population standard deviation
    /// of global joint positions (index 3·joint + axis, data units) over the training windows, and the
    /// bone offsets the benchmark uses for FK of both ground truth and predictions. L2P divides
    /// position errors by the standard deviations; the offsets define the skeleton that is scored.
    /// </summary>
    public sealed class BenchmarkStatistics
    {
        /// <summary>Creates statistics from their parts (arrays are copied).</summary>
        /// <param name="jointNames">Joint names in order, or null when unknown.</param>
        /// <param name="mean">joints × 3 means.</param>
        /// <param name="standardDeviation">joints × 3 standard deviations, all &gt; 0.</param>
        /// <param name="offsets">joints × 3 bone offsets (the root's are unused).</param>
        /// <param name="source">Where they came from, for reports.</param>
        public BenchmarkStatistics(IReadOnlyList<string>? jointNames, double[] mean, double[] standardDeviation, double[] offsets, string source)
        {
            if (mean == null || standardDeviation == null || offsets == null) throw new ArgumentNullException(mean == null ? nameof(mean) : standardDeviation == null ? nameof(standardDeviation) : nameof(offsets));
            if (mean.Length % 3 != 0 || standardDeviation.Length != mean.Length || offsets.Length != mean.Length)
            {
                throw new ArgumentException("mean, standard deviation and offsets must each hold joints × 3 values");
            }

            if (jointNames != null && jointNames.Count * 3 != mean.Length)
            {
                throw new ArgumentException("one joint name per 3 statistics values is required", nameof(jointNames));
            }

            JointNames = jointNames == null ? null : new List<string>(jointNames).ToArray();
            Mean = (double[])mean.Clone();
            StandardDeviation = (double[])standardDeviation.Clone();
            Offsets = (double[])offsets.Clone();
            Source = source ?? "";
        }

        /// <summary>Joint names the statistics were computed for, or null when the file does not say.</summary>
        public IReadOnlyList<string>? JointNames { get; }

        /// <summary>Number of joints.</summary>
        public int JointCount => Mean.Length / 3;

        /// <summary>joints × 3 means of global positions.</summary>
        public double[] Mean { get; }

        /// <summary>joints × 3 population standard deviations of global positions.</summary>
        public double[] StandardDeviation { get; }

        /// <summary>joints × 3 bone offsets (root entry unused, zero when loaded from the official file).</summary>
        public double[] Offsets { get; }

        /// <summary>Where the statistics came from (file path or a description).</summary>
        public string Source { get; }

        /// <summary>
        /// The benchmark skeleton: <paramref name="hierarchy"/>'s joints and parents with these offsets.
        /// </summary>
        /// <exception cref="DataFormatException">The statistics are for other joints.</exception>
        public Skeleton SkeletonFor(Skeleton hierarchy, string hierarchySource)
        {
            if (hierarchy.JointCount != JointCount)
            {
                throw new DataFormatException(Source, $"the statistics are for {JointCount} joints but {hierarchySource} has {hierarchy.JointCount}", "expected statistics computed for the same skeleton");
            }

            if (JointNames != null)
            {
                for (int j = 0; j < JointCount; j++)
                {
                    if (!string.Equals(JointNames[j], hierarchy.Names[j], StringComparison.Ordinal))
                    {
                        throw new DataFormatException(Source, $"joint {j} is '{JointNames[j]}' in the statistics but '{hierarchy.Names[j]}' in {hierarchySource}", "expected the same joints in the same order");
                    }
                }
            }

            return hierarchy.WithOffsets(Offsets);
        }

        /// <summary>
        /// Loads statistics from JSON: <c>x_mean</c> and <c>x_std</c> (joints × 3 numbers each),
        /// <c>offsets</c> (joints − 1 arrays of 3: the non-root joints) and optionally <c>joints</c>
        /// (names), as in <c>train_stats_official.json</c>.
        /// </summary>
        /// <exception cref="DataFormatException">The file does not have that shape.</exception>
        /// <exception cref="InputPathException">The path is missing or not a regular file.</exception>
        public static BenchmarkStatistics Load(string path)
        {
            InputFile.Check(path, "a statistics JSON such as train_stats_official.json");
            string text = File.ReadAllText(path);
            JsonValue root = JsonValue.Parse(text, path);
            root.ExpectObject("the statistics file");
            double[] mean = root.ExpectMember("x_mean").ExpectNumbers("x_mean", -1);
            int jointCount = mean.Length / 3;
            if (mean.Length == 0 || mean.Length % 3 != 0)
            {
                throw new DataFormatException(path, root.ExpectMember("x_mean").Line, $"x_mean has {mean.Length} values", "expected 3 per joint (index 3·joint + axis)");
            }

            JsonValue stdValue = root.ExpectMember("x_std");
            double[] std = stdValue.ExpectNumbers("x_std", mean.Length);
            for (int i = 0; i < std.Length; i++)
            {
                if (!(std[i] > 0))
                {
                    throw new DataFormatException(path, stdValue.Line, $"x_std[{i}] is {std[i].ToString(CultureInfo.InvariantCulture)}", "expected positive standard deviations (L2P divides by them)");
                }
            }

            JsonValue offsetsValue = root.ExpectMember("offsets");
            IReadOnlyList<JsonValue> rows = offsetsValue.ExpectArray("offsets");
            if (rows.Count != jointCount - 1)
            {
                throw new DataFormatException(path, offsetsValue.Line, $"offsets has {rows.Count} rows for {jointCount} joints", $"expected {jointCount - 1} rows of 3 (every joint but the root)");
            }

            var offsets = new double[mean.Length];
            for (int j = 1; j < jointCount; j++)
            {
                double[] o = rows[j - 1].ExpectNumbers($"offsets[{j - 1}]", 3);
                offsets[3 * j] = o[0];
                offsets[3 * j + 1] = o[1];
                offsets[3 * j + 2] = o[2];
            }

            string[]? names = null;
            IReadOnlyDictionary<string, JsonValue> members = root.ExpectObject("the statistics file");
            if (members.TryGetValue("joints", out JsonValue? jointsValue))
            {
                IReadOnlyList<JsonValue> items = jointsValue.ExpectArray("joints");
                if (items.Count != jointCount)
                {
                    throw new DataFormatException(path, jointsValue.Line, $"joints has {items.Count} names for {jointCount} joints of statistics", "expected one name per joint");
                }

                names = new string[jointCount];
                for (int j = 0; j < jointCount; j++) names[j] = items[j].ExpectString($"joints[{j}]");
            }

            return new BenchmarkStatistics(names, mean, std, offsets, path);
        }

        /// <summary>
        /// Computes the statistics from training clips as the official <c>get_train_stats</c> does:
        /// windows of <paramref name="window"/> frames every <paramref name="offset"/> (while
        /// start + window &lt; frames), XZ-centred, facing normalised at the last past frame, FK with
        /// each clip's own local positions; mean and population standard deviation per coordinate over
        /// all windows and frames. Offsets are the first clip's (the official code takes the first
        /// training window's, in directory order; with <see cref="LafanDataset.FindFiles"/> that order
        /// is by name).
        /// </summary>
        public static BenchmarkStatistics ComputeFromTraining(
            IReadOnlyList<BvhAnimation> clips,
            BenchmarkOptions facing,
            int window = 50,
            int offset = 20,
            string source = "computed from training files",
            IProgress<StageProgress>? progress = null)
        {
            if (clips == null || clips.Count == 0) throw new ArgumentException("no training clips; expected the LaFAN1 files of subjects 1-4", nameof(clips));
            if (window < facing.PastFrames || offset < 1) throw new ArgumentException($"window {window} / offset {offset}; expected window ≥ {facing.PastFrames} past frames and offset ≥ 1");
            Skeleton first = clips[0].Skeleton;
            int jointCount = first.JointCount;
            int features = jointCount * 3;
            var mean = new double[features];
            var m2 = new double[features];
            long count = 0;

            var root = new double[window * 3];
            var localPositions = new double[window * jointCount * 3];
            var localRotations = new double[window * jointCount * 4];
            var globalPositions = new double[window * jointCount * 3];
            var globalRotations = new double[window * jointCount * 4];
            var windowMean = new double[features];
            var windowM2 = new double[features];

            for (int c = 0; c < clips.Count; c++)
            {
                MotionClip clip = clips[c].Motion;
                if (!clip.Skeleton.HasSameHierarchy(first))
                {
                    throw new DataFormatException(clips[c].SourceName, $"the skeleton differs from {clips[0].SourceName}'s", "expected every training file to have the same joints and parents");
                }

                for (int start = 0; start + window < clip.FrameCount; start += offset)
                {
                    Array.Copy(clip.LocalPositions, start * jointCount * 3, localPositions, 0, localPositions.Length);
                    Array.Copy(clip.LocalRotations, start * jointCount * 4, localRotations, 0, localRotations.Length);
                    for (int f = 0; f < window; f++) Array.Copy(localPositions, f * jointCount * 3, root, f * 3, 3);
                    WindowNormalization.CenterXZ(root, window);
                    WindowNormalization.FaceAxis(root, localRotations, window, jointCount, facing.PastFrames - 1, facing.LocalForwardAxis, facing.TargetAxis);
                    for (int f = 0; f < window; f++) Array.Copy(root, f * 3, localPositions, f * jointCount * 3, 3);
                    ForwardKinematics.ComputeWithLocalPositions(clip.Skeleton, window, localPositions, localRotations, globalPositions, globalRotations);

                    // Two-pass moments per window, merged with Chan et al.'s formula: stable in double
                    // even though positions are ~100 cm and deviations ~30 cm.
                    Array.Clear(windowMean, 0, features);
                    Array.Clear(windowM2, 0, features);
                    for (int f = 0; f < window; f++)
                    {
                        for (int k = 0; k < features; k++) windowMean[k] += globalPositions[f * features + k];
                    }

                    for (int k = 0; k < features; k++) windowMean[k] /= window;
                    for (int f = 0; f < window; f++)
                    {
                        for (int k = 0; k < features; k++)
                        {
                            double d = globalPositions[f * features + k] - windowMean[k];
                            windowM2[k] += d * d;
                        }
                    }

                    long total = count + window;
                    for (int k = 0; k < features; k++)
                    {
                        double delta = windowMean[k] - mean[k];
                        mean[k] += delta * window / total;
                        m2[k] += windowM2[k] + delta * delta * ((double)count * window / total);
                    }

                    count = total;
                }

                progress?.Report(new StageProgress("Computing statistics", c + 1, clips.Count));
            }

            if (count == 0) throw new ArgumentException($"the training clips are shorter than one window of {window} frames");
            var std = new double[features];
            for (int k = 0; k < features; k++) std[k] = Math.Sqrt(m2[k] / count);
            var offsets = new double[features];
            Array.Copy(first.OffsetSpan.ToArray(), 3, offsets, 3, features - 3);
            var names = new string[jointCount];
            for (int j = 0; j < jointCount; j++) names[j] = first.Names[j];
            return new BenchmarkStatistics(names, mean, std, offsets, source);
        }

        /// <summary>Writes the statistics as JSON in the shape <see cref="Load"/> reads.</summary>
        public string ToJson()
        {
            var sb = new StringBuilder();
            sb.Append("{\n  \"description\": \"").Append(Escape("LaFAN1 benchmark statistics: per-coordinate mean and population std of global joint positions (index 3*joint + axis) and the bone offsets of joints 1..; " + Source)).Append("\",\n");
            if (JointNames != null)
            {
                sb.Append("  \"joints\": [");
                for (int j = 0; j < JointNames.Count; j++) sb.Append(j == 0 ? "" : ", ").Append('"').Append(Escape(JointNames[j])).Append('"');
                sb.Append("],\n");
            }

            AppendArray(sb, "x_mean", Mean, 0, Mean.Length);
            sb.Append(",\n");
            AppendArray(sb, "x_std", StandardDeviation, 0, StandardDeviation.Length);
            sb.Append(",\n  \"offsets\": [");
            for (int j = 1; j < JointCount; j++)
            {
                sb.Append(j == 1 ? "\n    [" : ",\n    [");
                for (int a = 0; a < 3; a++) sb.Append(a == 0 ? "" : ", ").Append(Offsets[3 * j + a].ToString("R", CultureInfo.InvariantCulture));
                sb.Append(']');
            }

            sb.Append("\n  ]\n}\n");
            return sb.ToString();
        }

        private static void AppendArray(StringBuilder sb, string name, double[] values, int start, int count)
        {
            sb.Append("  \"").Append(name).Append("\": [");
            for (int i = 0; i < count; i++) sb.Append(i == 0 ? "" : ", ").Append(values[start + i].ToString("R", CultureInfo.InvariantCulture));
            sb.Append(']');
        }

        private static string Escape(string s) => s.Replace("\\", "\\\\").Replace("\"", "\\\"");
    }
}
