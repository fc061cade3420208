using DeltaInterpolator.Core.Scheduling;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// One loaded model per (model asset, engine) for every character using it: characters share a
    /// <see cref="TransitionScheduler"/> and the last one to leave disposes it.
    /// </summary>
    internal static class SharedSchedulers
    {
        private static readonly Dictionary<(InbetweeningModel, string), Entry> s_entries = new Dictionary<(InbetweeningModel, string), Entry>();
        private static readonly List<Entry> s_discarded = new List<Entry>();

        /// <exception cref="ModelContractException">The model does not load or fit the contract.</exception>
        public static TransitionScheduler Acquire(InbetweeningModel model, IInferenceBackendFactory factory)
        {
            var key = (model, factory.Name);
            if (!s_entries.TryGetValue(key, out Entry? entry))
            {
                entry = new Entry(Load(model, factory));
                s_entries.Add(key, entry);
            }

            entry.Users++;
            return entry.Scheduler;
        }

        public static void Release(TransitionScheduler scheduler)
        {
            foreach (KeyValuePair<(InbetweeningModel, string), Entry> e in s_entries)
            {
                if (e.Value.Scheduler != scheduler) continue;
                if (--e.Value.Users == 0)
                {
                    s_entries.Remove(e.Key);
                    SchedulerPump.Remove(scheduler);
                    scheduler.Dispose();
                }

                return;
            }

            for (int i = 0; i < s_discarded.Count; i++)
            {
                Entry entry = s_discarded[i];
                if (entry.Scheduler != scheduler) continue;
                if (--entry.Users == 0)
                {
                    s_discarded.RemoveAt(i);
                    SchedulerPump.Remove(scheduler);
                    scheduler.Dispose();
                }

                return;
            }
        }

        /// <summary>
        /// The scheduler's engine failed: the next <see cref="Acquire"/> of its model loads a fresh one, while the
        /// characters still holding this one release it as usual (the last disposes it).
        /// </summary>
        public static void Discard(TransitionScheduler scheduler)
        {
            foreach (KeyValuePair<(InbetweeningModel, string), Entry> e in s_entries)
            {
                if (e.Value.Scheduler != scheduler) continue;
                s_entries.Remove(e.Key);
                s_discarded.Add(e.Value);
                return;
            }
        }

        private static TransitionScheduler Load(InbetweeningModel model, IInferenceBackendFactory factory)
        {
            Inbetweener inbetweener = ModelAssetGraphs.Load(model, factory);
            TransitionScheduler scheduler = factory.RunsOffMainThread ? new WorkerThreadScheduler(inbetweener) : (TransitionScheduler)new MainThreadScheduler(inbetweener);
            scheduler.Timer = ProfilerScheduleTimer.Instance;
            SchedulerPump.Add(scheduler);
            return scheduler;
        }

        private sealed class Entry
        {
            public Entry(TransitionScheduler scheduler)
            {
                Scheduler = scheduler;
            }

            public TransitionScheduler Scheduler { get; }

            public int Users { get; set; }
        }
    }
}
