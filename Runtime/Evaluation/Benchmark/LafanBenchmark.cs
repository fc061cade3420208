using System;
using System.Collections.Generic;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Evaluation.Metrics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>
    /// The official LaFAN1 in-betweening benchmark (Harvey et al. 2020; method-spec §1) for any
    /// <see cref="IInbetweener"/>. Per test file: quaternion continuity fix over the whole file; windows
    /// of <see cref="BenchmarkOptions.Window"/> frames every <see cref="BenchmarkOptions.Offset"/> while
    /// start + window &lt; frames; root XZ centred on the window mean; facing +X at the last past frame.
    /// Per window and transition length n: P past frames, n missing frames, the target at P + n (with
    /// <see cref="BenchmarkOptions.FedPastFrames"/>, only the last of the P are given). Ground
    /// truth and predictions both go through FK with the statistics' offsets; L2Q, L2P and NPSS are
    /// computed on the missing frames only.
    /// </summary>
    public static class LafanBenchmark
    {
        /// <summary>The start frames of the windows of a clip of <paramref name="frameCount"/> frames.</summary>
        public static IEnumerable<int> WindowStarts(int frameCount, int window, int offset)
        {
            // Strict inequality as in the official get_lafan1_set: a window that ends exactly on the last
            // frame is not used.
            for (int start = 0; start + window < frameCount; start += offset) yield return start;
        }

        /// <summary>Number of windows over all clips.</summary>
        public static int CountWindows(IReadOnlyList<BvhAnimation> clips, BenchmarkOptions options)
        {
            int total = 0;
            foreach (BvhAnimation clip in clips)
            {
                int frames = clip.Motion.FrameCount;
                if (frames > options.Window) total += (frames - options.Window - 1) / options.Offset + 1;
            }

            return total;
        }

        /// <summary>Runs the benchmark.</summary>
        /// <param name="testClips">The test files (subject 5), already read.</param>
        /// <param name="statistics">Normalisation statistics and benchmark offsets.</param>
        /// <param name="methods">The in-betweeners to evaluate, e.g. zero-velocity and SLERP.</param>
        /// <param name="options">Window layout; <see cref="BenchmarkOptions.Validate"/> is called.</param>
        /// <param name="progress">Receives one report per window.</param>
        /// <exception cref="ArgumentException">Bad options or no windows.</exception>
        /// <exception cref="DataFormatException">Statistics and test files disagree on the skeleton, or a
        /// test file's values make a metric that is not a finite number (the message names file and window).</exception>
        public static BenchmarkReport Run(
            IReadOnlyList<BvhAnimation> testClips,
            BenchmarkStatistics statistics,
            IReadOnlyList<IInbetweener> methods,
            BenchmarkOptions options,
            IProgress<StageProgress>? progress = null)
        {
            if (testClips == null || testClips.Count == 0) throw new ArgumentException("no test files; expected the LaFAN1 files of subject 5", nameof(testClips));
            if (methods == null || methods.Count == 0) throw new ArgumentException("no methods to evaluate", nameof(methods));
            options.Validate();

            Skeleton skeleton = statistics.SkeletonFor(testClips[0].Skeleton, testClips[0].SourceName);
            int jointCount = skeleton.JointCount;
            int window = options.Window;
            int past = options.PastFrames;
            int fed = options.EffectivePastFrames;
            int keyPast = options.TransitionPastFrames;
            IReadOnlyList<int> lengths = options.Lengths;
            int totalWindows = CountWindows(testClips, options);
            if (totalWindows == 0) throw new ArgumentException($"the test files are shorter than one window of {window} frames");

            var totals = new MetricTotals[methods.Count][];
            var ids = new string[methods.Count];
            var names = new string[methods.Count];
            for (int m = 0; m < methods.Count; m++)
            {
                ids[m] = methods[m].Id;
                names[m] = methods[m].DisplayName;
                totals[m] = new MetricTotals[lengths.Count];
                for (int l = 0; l < lengths.Count; l++) totals[m][l] = new MetricTotals();
            }

            // All buffers are allocated once; the window loop allocates nothing.
            var transitions = new Transition[lengths.Count];
            var npss = new Npss[lengths.Count];
            int maxMissing = 0;
            for (int l = 0; l < lengths.Count; l++)
            {
                transitions[l] = new Transition(skeleton, keyPast, lengths[l]);
                npss[l] = new Npss(lengths[l], jointCount * 4);
                maxMissing = Math.Max(maxMissing, lengths[l]);
            }

            var truthTotals = new MetricTotals[lengths.Count];
            for (int l = 0; l < lengths.Count; l++) truthTotals[l] = new MetricTotals();

            // Foot skating (an extra table): the skeleton's feet, and foot-joint positions of the last past key, the
            // filled frames and the target, for the truth and the result.
            // A skeleton without the model's legs (synthetic tests) gets no foot skating (NaN), the rest as usual.
            FootRig? feet = FootRig.HasModelLegs(skeleton) ? FootRig.ForModel(skeleton) : null;
            IReadOnlyList<int> footJoints = feet != null ? feet.FootJoints : Array.Empty<int>();
            int footCount = footJoints.Count;
            var truthFeet = new double[(maxMissing + 2) * footCount * 3];
            var resultFeet = new double[(maxMissing + 2) * footCount * 3];
            var keyPositions = new double[jointCount * 3];
            var keyRotations = new double[jointCount * 4];
            var root = new double[window * 3];
            var rotations = new double[window * jointCount * 4];
            var truthPositions = new double[maxMissing * jointCount * 3];
            var truthRotations = new double[maxMissing * jointCount * 4];
            var predictedPositions = new double[maxMissing * jointCount * 3];
            var predictedRotations = new double[maxMissing * jointCount * 4];
            double[] std = statistics.StandardDeviation;

            int done = 0;
            progress?.Report(new StageProgress("Evaluating windows", 0, totalWindows));
            foreach (BvhAnimation animation in testClips)
            {
                if (!animation.Skeleton.HasSameHierarchy(skeleton))
                {
                    throw new DataFormatException(animation.SourceName, $"the skeleton differs from {testClips[0].SourceName}'s", "expected every test file to have the same joints and parents");
                }

                MotionClip clip = animation.Motion;
                // The file's ground level, as bakes take it from their clip (window normalization moves X and Z only).
                double ground = feet != null ? FootSkating.GroundLevel(FootSkating.FootPositions(clip, 0, clip.FrameCount, footJoints), footCount) : 0;
                // The official pipeline fixes quaternion signs once per file, before windowing; L2Q and
                // NPSS compare raw components, so the sign convention is part of the metric.
                var fixedRotations = (double[])clip.LocalRotations.Clone();
                Quaternions.FixContinuity(fixedRotations, clip.FrameCount, jointCount);

                foreach (int start in WindowStarts(clip.FrameCount, window, options.Offset))
                {
                    for (int f = 0; f < window; f++) Array.Copy(clip.LocalPositions, (start + f) * jointCount * 3, root, f * 3, 3);
                    Array.Copy(fixedRotations, start * jointCount * 4, rotations, 0, rotations.Length);
                    WindowNormalization.CenterXZ(root, window);
                    WindowNormalization.FaceAxis(root, rotations, window, jointCount, past - 1, options.LocalForwardAxis, options.TargetAxis);

                    // The last past key is the same frame for every length: its foot joints once per window.
                    if (feet != null) KeyFeet(skeleton, root, rotations, past - 1, jointCount, footJoints, keyPositions, keyRotations, truthFeet, 0);
                    for (int l = 0; l < lengths.Count; l++)
                    {
                        int n = lengths[l];
                        Transition transition = transitions[l];
                        int posLen = n * jointCount * 3, rotLen = n * jointCount * 4;
                        Span<double> tp = truthPositions.AsSpan(0, posLen);
                        Span<double> tr = truthRotations.AsSpan(0, rotLen);
                        ForwardKinematics.Compute(skeleton, n, root.AsSpan(past * 3, n * 3), rotations.AsSpan(past * jointCount * 4, rotLen), tp, tr);
                        npss[l].SetTruth(tr);
                        int feetLength = (n + 2) * footCount * 3;
                        if (feet != null)
                        {
                            // The keys around the gap are the truth's in every method's result too.
                            KeyFeet(skeleton, root, rotations, past + n, jointCount, footJoints, keyPositions, keyRotations, truthFeet, n + 1);
                            CopyFeet(tp, n, jointCount, footJoints, truthFeet);
                            truthFeet.AsSpan(0, footCount * 3).CopyTo(resultFeet);
                            truthFeet.AsSpan((n + 1) * footCount * 3, footCount * 3).CopyTo(resultFeet.AsSpan((n + 1) * footCount * 3));
                            MetricTotals gt = truthTotals[l];
                            int truthSamples = 0;
                            FootSkating.Accumulate(truthFeet.AsSpan(0, feetLength), truthFeet.AsSpan(0, feetLength), footCount, clip.FrameTime, clip.FrameTime, ground, feet.LegLength, ref gt.FootSkatingSum, ref truthSamples);
                            gt.FootContactSamples += truthSamples;
                        }

                        for (int m = 0; m < methods.Count; m++)
                        {
                            // The last `fed` of the past frames (padded under the short-context policy) and the target.
                            PastContext.FillPast(transition, root, rotations, past - 1, fed);
                            PastContext.FillTarget(transition, root, rotations, past + n);
                            methods[m].Inbetween(transition);
                            Span<double> pp = predictedPositions.AsSpan(0, posLen);
                            Span<double> pr = predictedRotations.AsSpan(0, rotLen);
                            ForwardKinematics.Compute(skeleton, n, transition.RootPositions, transition.LocalRotations, pp, pr);
                            MetricTotals t = totals[m][l];
                            double l2q = TransitionMetrics.SumL2Q(pr, tr, n, jointCount);
                            double l2p = TransitionMetrics.SumL2P(pp, tp, n, jointCount, std);
                            t.L2QSum += l2q;
                            t.L2PSum += l2p;
                            t.FrameCount += n;
                            if (feet != null)
                            {
                                CopyFeet(pp, n, jointCount, footJoints, resultFeet);
                                int samples = 0;
                                FootSkating.Accumulate(truthFeet.AsSpan(0, feetLength), resultFeet.AsSpan(0, feetLength), footCount, clip.FrameTime, clip.FrameTime, ground, feet.LegLength, ref t.FootSkatingSum, ref samples);
                                t.FootContactSamples += samples;
                            }
                            npss[l].Accumulate(pr, ref t.NpssWeightedSum, ref t.NpssWeightSum);
                            if (!double.IsFinite(l2q) || !double.IsFinite(l2p) || !double.IsFinite(t.NpssWeightedSum) || !double.IsFinite(t.NpssWeightSum))
                            {
                                // Finite but huge motion values (1e308) overflow in forward kinematics;
                                // a NaN must never reach a table or a file.
                                string metric = !double.IsFinite(l2q) ? "L2Q" : !double.IsFinite(l2p) ? "L2P" : "NPSS";
                                throw new DataFormatException(animation.SourceName,
                                    $"{names[m]} {metric} of the window at frame {start} (length {n}) is not a finite number",
                                    "expected motion values small enough for forward kinematics and the metrics (e.g. |value| < 1e100)");
                            }
                        }
                    }

                    done++;
                    progress?.Report(new StageProgress("Evaluating windows", done, totalWindows));
                }
            }

            return new BenchmarkReport(totalWindows, options, statistics.Source, ids, names, totals, truthTotals);
        }

        // Foot-joint positions of window frame `frame` (a key) into slot `slot` of `feetBuffer`.
        private static void KeyFeet(Skeleton skeleton, double[] root, double[] rotations, int frame, int jointCount, IReadOnlyList<int> footJoints,
            double[] positions, double[] globalRotations, double[] feetBuffer, int slot)
        {
            ForwardKinematics.Compute(skeleton, 1, root.AsSpan(frame * 3, 3), rotations.AsSpan(frame * jointCount * 4, jointCount * 4), positions, globalRotations);
            for (int k = 0; k < footJoints.Count; k++) Array.Copy(positions, footJoints[k] * 3, feetBuffer, (slot * footJoints.Count + k) * 3, 3);
        }

        // Foot-joint positions of n filled frames (global positions, frames × joints × 3) into slots 1..n.
        private static void CopyFeet(ReadOnlySpan<double> globalPositions, int n, int jointCount, IReadOnlyList<int> footJoints, double[] feetBuffer)
        {
            int c = footJoints.Count;
            for (int f = 0; f < n; f++)
            {
                for (int k = 0; k < c; k++) globalPositions.Slice((f * jointCount + footJoints[k]) * 3, 3).CopyTo(feetBuffer.AsSpan(((f + 1) * c + k) * 3, 3));
            }
        }
    }
}
