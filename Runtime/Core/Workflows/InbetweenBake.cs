using System;
using System.Collections.Generic;
using System.Diagnostics;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// The bake use case of every front end (the CLI's <c>bake</c>, <c>demo</c> and <c>score</c>, the editor's
    /// baker): a rig's clip and key frames → onto the model's skeleton and rate → every method's
    /// <see cref="ClipBaker"/> fills the gaps → back onto the rig. Every method's plan is checked before any
    /// gap is filled, so a bad layout is refused before a network runs.
    /// </summary>
    /// <remarks>
    /// Foot locking (<see cref="BakeSettings.FootLocking"/>) holds planted feet on the skeleton the motion is
    /// delivered on. For a retargeted rig that is the rig's own: the filled frames are mapped back unlocked and
    /// locked there (<see cref="FootRig.ForSource"/>), because rotations that hold a foot still on the model's legs
    /// make it slide on legs of other proportions (measured on CMU files of training subjects, keys every 60 of
    /// 120 frames: locked on the model's skeleton and mapped back, foot skating 0.191 / 0.140 / 0.152 / 0.275 leg
    /// lengths per second on 05_01 / 06_01 / 35_03 / 07_01 against 0.159 / 0.147 / 0.192 / 0.204 unlocked; locked
    /// on the rig 0.031 / 0.017 / 0.003 / 0.063). The bake on the model's skeleton (<see cref="MethodBake.OnModel"/>)
    /// is locked on that skeleton.
    /// </remarks>
    public static class InbetweenBake
    {
        /// <summary>Bakes <paramref name="rigKeys"/> of <paramref name="rigClip"/> with each of <paramref name="methods"/>.</summary>
        /// <param name="rigClip">The rig's motion: the keys' source (and the ground truth of the other frames).</param>
        /// <param name="rigKeys">Key frame indices of <paramref name="rigClip"/>, increasing, at least two.</param>
        /// <param name="rig">How the rig reaches the model (<see cref="RigRetargeting.For"/>).</param>
        /// <param name="methods">What fills the gaps, in order; at least one.</param>
        /// <param name="progress">Gaps filled over every method, or null.</param>
        /// <exception cref="KeyLayoutException">The keys do not work (too few, out of range, a gap the graph cannot take).</exception>
        public static BakeRun Run(MotionClip rigClip, int[] rigKeys, IRigRetargeting rig, IReadOnlyList<BakeMethod> methods, IProgress<StageProgress>? progress = null)
        {
            if (rigClip == null) throw new ArgumentNullException(nameof(rigClip));
            if (rigKeys == null) throw new ArgumentNullException(nameof(rigKeys));
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (methods == null || methods.Count == 0) throw new ArgumentException("expected at least one method", nameof(methods));

            MotionClip onModel = rig.ToModel(rigClip, rigKeys);
            int[] modelKeys = rig.KeysToModel(rigKeys);
            var bakers = new ClipBaker[methods.Count];
            var plans = new BakePlan[methods.Count];
            // A retargeted rig's feet are locked on the rig after mapping back, the model's on the model (see remarks).
            var rigLockers = new FootLocker?[methods.Count];
            var modelLockers = new FootLocker?[methods.Count];
            SkeletonMap? map = rig.Map;
            var warnings = new List<string>();
            int total = 0;
            for (int i = 0; i < methods.Count; i++)
            {
                BakeSettings settings = methods[i].Settings;
                if (map != null && settings.FootLocking != null)
                {
                    // A rig whose legs cannot be bent (a knee the map synthesizes, a leg that is no chain) is baked
                    // unlocked with one warning: the bake itself does not need its feet held.
                    FootRig? legs = FootRig.TryForSource(map, out string? problem);
                    if (legs != null) rigLockers[i] = FootLocker.ForBake(() => legs, settings.FootLocking, "the rig");
                    else if (warnings.Count == 0) warnings.Add($"foot locking skipped on the rig: {problem}; its filled frames keep the feet as each method placed them");
                    modelLockers[i] = FootLocker.ForBake(() => FootRig.ForModel(onModel.Skeleton), settings.FootLocking, "the model's skeleton");
                    settings = settings.WithFootLocking(null);
                }

                bakers[i] = new ClipBaker(methods[i].Inbetweener, settings);
                plans[i] = bakers[i].Plan(onModel.FrameCount, modelKeys);
                total += plans[i].Gaps.Count;
            }

            var results = new MethodBake[methods.Count];
            var rigContacts = new FootContacts();
            int done = 0;
            for (int i = 0; i < methods.Count; i++)
            {
                var clock = Stopwatch.StartNew();
                IProgress<int>? gaps = progress == null ? null : new GapCounter(progress, methods[i].Name, done, total);
                MotionClip baked = bakers[i].Bake(onModel, plans[i], gaps);
                double seconds = clock.Elapsed.TotalSeconds;
                done += plans[i].Gaps.Count;
                MotionClip onRig = rig.FromModel(baked, rigClip, rigKeys);
                if (rigLockers[i] != null)
                {
                    // The model's predicted contacts, on the rig's frames (nearest in time; the rig may run at another rate).
                    double start = rigKeys[0] * rigClip.FrameTime - modelKeys[0] * baked.FrameTime;
                    bakers[i].Contacts.ResampleInto(rigContacts, onRig.FrameCount, onRig.FrameTime, baked.FrameTime, start);
                    rigLockers[i]!.Lock(onRig, Relative(rigKeys), rigContacts);
                }

                modelLockers[i]?.Lock(baked, Relative(modelKeys), bakers[i].Contacts);
                results[i] = new MethodBake(methods[i], plans[i], baked, onRig, seconds, bakers[i].Contacts);
            }

            return new BakeRun(rig, onModel, (int[])rigKeys.Clone(), modelKeys, results, warnings.ToArray());
        }

        /// <summary>Key frames relative to the first (the baked clips span the first to the last key).</summary>
        private static int[] Relative(IReadOnlyList<int> keys)
        {
            var relative = new int[keys.Count];
            for (int i = 0; i < relative.Length; i++) relative[i] = keys[i] - keys[0];
            return relative;
        }

        /// <summary>One method's gap count → progress over every method.</summary>
        private sealed class GapCounter : IProgress<int>
        {
            private readonly IProgress<StageProgress> _progress;
            private readonly string _method;
            private readonly int _before;
            private readonly int _total;

            public GapCounter(IProgress<StageProgress> progress, string method, int before, int total)
            {
                _progress = progress;
                _method = method;
                _before = before;
                _total = total;
            }

            public void Report(int value) => _progress.Report(new StageProgress(_method, _before + value, _total));
        }
    }
}
