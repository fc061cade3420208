using System;
using System.Collections.Generic;
using System.Diagnostics;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// The bake use case of every front end (the CLI's <c>bake</c>, <c>demo</c> and <c>score</c>, the editor's
    /// baker): a rig's clip and key frames → onto the model's skeleton and rate → every method's
    /// <see cref="ClipBaker"/> fills the gaps → back onto the rig. Every method's plan is checked before any
    /// gap is filled, so a bad layout is refused before a network runs.
    /// </summary>
    public static class InbetweenBake
    {
        /// <summary>Bakes <paramref name="rigKeys"/> of <paramref name="rigClip"/> with each of <paramref name="methods"/>.</summary>
        /// <param name="rigClip">The rig's motion: the keys' source (and the ground truth of the other frames).</param>
        /// <param name="rigKeys">Key frame indices of <paramref name="rigClip"/>, increasing, at least two.</param>
        /// <param name="rig">How the rig reaches the model (<see cref="RigRetargeting.For"/>).</param>
        /// <param name="methods">What fills the gaps, in order; at least one.</param>
        /// <param name="progress">Gaps filled over every method, or null.</param>
        /// <exception cref="KeyLayoutException">The keys do not work (too few, out of range, a gap the graph cannot take).</exception>
        public static BakeRun Run(MotionClip rigClip, int[] rigKeys, IRigRetargeting rig, IReadOnlyList<BakeMethod> methods, IProgress<BakeProgress>? progress = null)
        {
            if (rigClip == null) throw new ArgumentNullException(nameof(rigClip));
            if (rigKeys == null) throw new ArgumentNullException(nameof(rigKeys));
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (methods == null || methods.Count == 0) throw new ArgumentException("expected at least one method", nameof(methods));

            MotionClip onModel = rig.ToModel(rigClip, rigKeys);
            int[] modelKeys = rig.KeysToModel(rigKeys);
            var bakers = new ClipBaker[methods.Count];
            var plans = new BakePlan[methods.Count];
            int total = 0;
            for (int i = 0; i < methods.Count; i++)
            {
                bakers[i] = new ClipBaker(methods[i].Inbetweener, methods[i].Settings);
                plans[i] = bakers[i].Plan(onModel.FrameCount, modelKeys);
                total += plans[i].Gaps.Count;
            }

            var results = new MethodBake[methods.Count];
            int done = 0;
            for (int i = 0; i < methods.Count; i++)
            {
                var clock = Stopwatch.StartNew();
                IProgress<int>? gaps = progress == null ? null : new GapCounter(progress, methods[i].Name, done, total);
                MotionClip baked = bakers[i].Bake(onModel, plans[i], gaps);
                double seconds = clock.Elapsed.TotalSeconds;
                done += plans[i].Gaps.Count;
                results[i] = new MethodBake(methods[i], plans[i], baked, rig.FromModel(baked, rigClip, rigKeys), seconds);
            }

            return new BakeRun(rig, onModel, (int[])rigKeys.Clone(), modelKeys, results);
        }

        /// <summary>One method's gap count → progress over every method.</summary>
        private sealed class GapCounter : IProgress<int>
        {
            private readonly IProgress<BakeProgress> _progress;
            private readonly string _method;
            private readonly int _before;
            private readonly int _total;

            public GapCounter(IProgress<BakeProgress> progress, string method, int before, int total)
            {
                _progress = progress;
                _method = method;
                _before = before;
                _total = total;
            }

            public void Report(int value) => _progress.Report(new BakeProgress(_method, _before + value, _total));
        }
    }
}
