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
            return entry.Decoder;
        }

        public static void Release(TransitionScheduler decoder)
        {
            foreach (KeyValuePair<(InbetweeningModel, string), Entry> e in s_entries)
            {
                if (e.Value.Decoder != decoder) continue;
                if (--e.Value.Users == 0)
                {
                    s_entries.Remove(e.Key);
                    SchedulerPump.Remove(decoder);
                    decoder.Dispose();
                }

                return;
            }

            for (int i = 0; i < s_discarded.Count; i++)
            {
                Entry entry = s_discarded[i];
                if (entry.Decoder != decoder) continue;
                if (--entry.Users == 0)
                {
                    s_discarded.RemoveAt(i);
                    SchedulerPump.Remove(decoder);
                    decoder.Dispose();
                }

                return;
            }
        }

        /// <summary>
        /// The decoder's engine failed: the next <see cref="Acquire"/> of its model loads a fresh one, while the
        /// characters still holding this one release it as usual (the last disposes it).
        /// </summary>
        public static void Discard(TransitionScheduler decoder)
        {
            foreach (KeyValuePair<(InbetweeningModel, string), Entry> e in s_entries)
            {
                if (e.Value.Decoder != decoder) continue;
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
            public Entry(TransitionScheduler decoder)
            {
                Decoder = decoder;
            }

            public TransitionScheduler Decoder { get; }

            public int Users { get; set; }
        }
    }
}
