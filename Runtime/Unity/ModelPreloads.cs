using System.Collections.Generic;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Scheduling;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Models loaded before a character needs them (<see cref="InbetweenerSettings.Preload"/>, and every loaded settings asset
    /// with <see cref="InbetweenerSettings.LoadOnAwake"/> when a scene has loaded), so the first character to start finds its
    /// model in <see cref="SharedSchedulers"/> instead of loading ~20 MB of graphs synchronously in the frame it is enabled.
    /// A preload holds the model like one more character; <see cref="InbetweenerSettings.ReleasePreload"/>, the settings being
    /// unloaded, or the end of play lets it go (the last holder disposes it).
    /// </summary>
    internal static class ModelPreloads
    {
        private static readonly Dictionary<InbetweenerSettings, TransitionScheduler> s_held = new Dictionary<InbetweenerSettings, TransitionScheduler>();
        // Settings assets in memory (their OnEnable to OnDisable): a scene loads those its objects and prefabs reference.
        private static readonly HashSet<InbetweenerSettings> s_loaded = new HashSet<InbetweenerSettings>();
        private static readonly List<InbetweenerSettings> s_scratch = new List<InbetweenerSettings>();

        public static bool IsPreloaded(InbetweenerSettings settings) => s_held.ContainsKey(settings);

        /// <exception cref="System.InvalidOperationException">No model, or its engine is not installed.</exception>
        /// <exception cref="Core.Inference.ModelContractException">The model does not load or fit its contract.</exception>
        public static void Preload(InbetweenerSettings settings)
        {
            if (s_held.ContainsKey(settings)) return;
            IInferenceBackendFactory factory = CharacterBuild.Engine(settings, out InbetweeningModel model);
            s_held.Add(settings, SharedSchedulers.Acquire(model, factory));
        }

        public static void Release(InbetweenerSettings settings)
        {
            if (!s_held.TryGetValue(settings, out TransitionScheduler? scheduler)) return;
            s_held.Remove(settings);
            SharedSchedulers.Release(scheduler);
        }

        /// <summary>Lets every preload go (the scheduler pump is destroyed: play ends or the application quits).</summary>
        public static void ReleaseAll()
        {
            s_scratch.Clear();
            s_scratch.AddRange(s_held.Keys);
            foreach (InbetweenerSettings settings in s_scratch) Release(settings);
        }

        public static void Loaded(InbetweenerSettings settings) => s_loaded.Add(settings);

        public static void Unloaded(InbetweenerSettings settings)
        {
            s_loaded.Remove(settings);
            Release(settings);
        }

        // After the first scene has loaded, and after every scene loaded later: after its objects' Awake and OnEnable (characters
        // enabled with the scene load their model there anyway), before any frame, so a character spawned or enabled later does not.
        [RuntimeInitializeOnLoadMethod(RuntimeInitializeLoadType.AfterSceneLoad)]
        private static void Install()
        {
            SceneManager.sceneLoaded -= OnSceneLoaded;
            SceneManager.sceneLoaded += OnSceneLoaded;
            PreloadLoadedSettings();
        }

        private static void OnSceneLoaded(Scene scene, LoadSceneMode mode) => PreloadLoadedSettings();

        private static void PreloadLoadedSettings()
        {
            s_scratch.Clear();
            s_scratch.AddRange(s_loaded);
            foreach (InbetweenerSettings settings in s_scratch)
            {
                if (!settings.LoadOnAwake || settings.Model == null || s_held.ContainsKey(settings)) continue;
                try
                {
                    Preload(settings);
                }
                catch (System.Exception e) when (!PlaybackStatus.IsFatal(e))
                {
                    // One message per settings asset and scene load; a character using them reports its own failure when it starts.
                    Debug.LogError($"{settings.name}: Load On Awake could not load the in-betweening model: {PlaybackStatus.StartFailure(settings.Model.name, e)}", settings);
                }
            }
        }
    }
}
