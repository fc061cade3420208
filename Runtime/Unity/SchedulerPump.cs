using System.Collections.Generic;
using DeltaInterpolator.Core.Scheduling;
using Unity.Profiling;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The one point of a rendered frame where the schedulers' network work runs: before every script's
    /// <c>Update</c> (its execution order), once per frame, for every scheduler in use — never from inside one
    /// character's frame. A hidden object that lives across scenes, created with the first scheduler. Characters
    /// on the Animator's Fixed clock tick in <c>FixedUpdate</c>, which Unity runs before <c>Update</c>: they see the
    /// work of the previous rendered frame's pump.
    /// </summary>
    [DefaultExecutionOrder(-1000)]
    [AddComponentMenu("")]
    internal sealed class SchedulerPump : MonoBehaviour
    {
        private static readonly ProfilerMarker s_Pump = new ProfilerMarker("DeltaInterpolator.Scheduler.Pump");
        private static readonly List<TransitionScheduler> s_schedulers = new List<TransitionScheduler>();
        private static SchedulerPump? s_pump;
        private static int s_pumpedFrame = -1;
        private static bool s_warnedOrder;

        /// <summary>Pumps <paramref name="scheduler"/> once per rendered frame from now on (the pump object is created when missing).</summary>
        public static void Add(TransitionScheduler scheduler)
        {
            s_schedulers.Add(scheduler);
            if (s_pump != null) return;
            var host = new GameObject("Δ-Interpolator scheduler pump");
            DontDestroyOnLoad(host);
            s_pump = host.AddComponent<SchedulerPump>();
        }

        /// <summary>Stops pumping <paramref name="scheduler"/> (it is being disposed).</summary>
        public static void Remove(TransitionScheduler scheduler) => s_schedulers.Remove(scheduler);

        /// <summary>
        /// The run-time check of the execution order this relies on (Documentation~/unity-verification.md): called
        /// from a character's <c>Update</c>, it says once in the Console when the pump has run before but not yet in
        /// this frame, i.e. a script ordered before -1000 drives a character, which then sees last frame's work.
        /// </summary>
        public static void CheckPumpedThisFrame(Object character)
        {
            if (s_warnedOrder || s_pumpedFrame < 0 || s_pumpedFrame == Time.frameCount) return;
            s_warnedOrder = true;
            Debug.LogWarning($"{character.name}: the Δ-Interpolator scheduler pump ([DefaultExecutionOrder(-1000)]) had not run yet this frame when this character's Update did; a script ordered before it drives the character, whose transitions then start one frame late", character);
        }

        // Play ends (or the application quits): the preloads let their models go, as the characters do in their OnDisable.
        private void OnDestroy() => ModelPreloads.ReleaseAll();

        private void Update()
        {
            s_pumpedFrame = Time.frameCount;
            using (s_Pump.Auto())
            {
                for (int i = 0; i < s_schedulers.Count; i++) s_schedulers[i].Pump();
            }
        }
    }

    /// <summary>The schedulers' stage timings as Profiler markers (Window → Analysis → Profiler, CPU timeline).</summary>
    internal sealed class ProfilerScheduleTimer : IScheduleTimer
    {
        private static readonly ProfilerMarker s_Collect = new ProfilerMarker("DeltaInterpolator.Scheduler.Collect");
        private static readonly ProfilerMarker s_Keys = new ProfilerMarker("DeltaInterpolator.Scheduler.Keys");
        private static readonly ProfilerMarker s_Frames = new ProfilerMarker("DeltaInterpolator.Scheduler.Frames");
        private static readonly ProfilerMarker s_Whole = new ProfilerMarker("DeltaInterpolator.Scheduler.Whole");

        public static readonly ProfilerScheduleTimer Instance = new ProfilerScheduleTimer();

        public void Begin(ScheduleStage stage) => Marker(stage).Begin();

        public void End(ScheduleStage stage) => Marker(stage).End();

        private static ProfilerMarker Marker(ScheduleStage stage) => stage switch
        {
            ScheduleStage.Collect => s_Collect,
            ScheduleStage.Keys => s_Keys,
            ScheduleStage.Frames => s_Frames,
            _ => s_Whole,
        };
    }
}
