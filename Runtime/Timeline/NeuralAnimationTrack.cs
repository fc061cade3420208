using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Unity;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Playables;
using UnityEngine.Timeline;

namespace DeltaInterpolator.Timeline
{
    /// <summary>
    /// A Timeline track like an Animation Track — bound to a character's <see cref="Animator"/>, its clips AnimationClips
    /// placed in time — whose blends are neural: where two clips overlap the model goes from the first clip's pose where
    /// the blend starts (its past frames as history) to the second's where it ends, and where time lies between two clips
    /// from the first one's last frame to the second one's first, instead of a crossfade. Each blend is baked once when the
    /// graph is built and read from a cache as the playhead moves (<see cref="NeuralBlendLayer"/>), so scrubbing in edit
    /// mode shows what plays.
    /// </summary>
    [Serializable]
    [TrackClipType(typeof(AnimationPlayableAsset), false)]
    [TrackBindingType(typeof(Animator))]
    public sealed class NeuralAnimationTrack : TrackAsset
    {
        [SerializeField]
        [Tooltip("The model, engine and rig, as the Motion Inbetweener component takes them.")]
        private InbetweenerSettings? settings;

        /// <summary>The model, engine and rig the blends are baked with.</summary>
        public InbetweenerSettings? Settings
        {
            get => settings;
            set => settings = value;
        }

        // The character's IAnimationWindowPreview components, let into the Editor preview after this track's mix.
        [NonSerialized]
        private TrackPreviewComponents? _preview;

        /// <inheritdoc />
        /// <remarks>
        /// Timeline reads the outputs right after it connected the track's mixer to the timeline: in an Editor preview the
        /// bound character's preview components are inserted after the mix then (<see cref="TrackPreviewComponents"/>).
        /// </remarks>
        public override IEnumerable<PlayableBinding> outputs
        {
            get
            {
                _preview?.Insert(this);
                yield return AnimationPlayableBinding.Create(name, this);
            }
        }

        /// <summary>
        /// The mixer: the clips mixed by Timeline's weights with each blend's cached in-between laid over it. Without a
        /// bound Animator or settings, or when the model cannot take the character, the clips crossfade as on an Animation
        /// Track and the reason is logged.
        /// </summary>
        public override Playable CreateTrackMixer(PlayableGraph graph, GameObject go, int inputCount)
        {
            PlayableDirector? director = go != null ? go.GetComponent<PlayableDirector>() : null;
            Animator? animator = director != null ? director.GetGenericBinding(this) as Animator : null;
            string? problem = animator == null ? "no Animator is bound to it" : settings == null ? "it has no Inbetweener Settings" : null;
            NeuralBlendLayer? layer = null;
            if (problem == null)
            {
                try
                {
                    layer = NeuralBlendLayer.Create(animator!, settings!);
                    var timings = new List<TrackClipTiming>();
                    var clips = new List<AnimationClip?>();
                    var mixIn = new List<AnimationCurve?>();
                    bool rootTransforms = false;
                    foreach (TimelineClip clip in GetClips())
                    {
                        var playable = clip.asset as AnimationPlayableAsset;
                        AnimationClip? animation = playable != null ? playable.clip : null;
                        // As Timeline plays the clip: at its speed, wrapped where its playable loops (AnimationPlayableAsset
                        // overrides the source clip's Loop Time unless set to UseSourceAsset).
                        bool loops = playable != null && animation != null && (playable.loop == AnimationPlayableAsset.LoopMode.On
                            || (playable.loop == AnimationPlayableAsset.LoopMode.UseSourceAsset && animation.isLooping));
                        timings.Add(new TrackClipTiming(clip.start, clip.duration, clip.clipIn, animation != null && animation.length > 0 ? animation.length : clip.duration, clip.timeScale, loops,
                            Extrapolation(clip.preExtrapolationMode), Extrapolation(clip.postExtrapolationMode)));
                        clips.Add(animation);
                        // A blend's root travel weighs the clips as Timeline does: the second clip by its mix-in curve (timeline.md).
                        mixIn.Add(clip.mixInCurve);
                        // Timeline's own test for a clip that moves the root (AnimationPlayableAsset.HasRootTransforms, less the internal hasRootMotion).
                        rootTransforms |= animation != null && !animation.empty && (animation.hasGenericRootTransform || animation.hasMotionCurves || animation.hasRootCurves);
                    }

                    // A custom track's clips play their root motion as the clip playables make it, each from where the character
                    // stands (Timeline's scene offsets; the offset playables an Animation Track adds are internal): timeline.md.
                    layer.Build(timings, clips, rootTransforms && animator!.applyRootMotion ? RootTravelMode.SceneOffset : RootTravelMode.None, mixIn);
                }
                catch (Exception e) when (e is InvalidOperationException || e is JointMapException || e is ModelContractException || e is ArgumentException)
                {
                    layer?.Dispose();
                    layer = null;
                    problem = e.Message;
                }
            }

            if (layer == null) Debug.LogWarning($"{name}: {problem}; its clips crossfade as on an Animation Track", this);
            Playable mixer = layer != null ? layer.CreatePlayable(graph, inputCount) : AnimationMixerPlayable.Create(graph, inputCount);
            _preview ??= new TrackPreviewComponents();
            var previewComponents = _preview.Built(mixer, animator != null ? animator.gameObject : null);
            // The playhead reaches the layer through a script output of its own: its PrepareFrame runs before the animation jobs.
            ScriptPlayable<NeuralTrackDriver> driver = ScriptPlayable<NeuralTrackDriver>.Create(graph);
            driver.GetBehaviour().Bind(layer, director, previewComponents);
            ScriptPlayableOutput.Create(graph, name + " (neural blends)").SetSourcePlayable(driver);
            return mixer;
        }

        /// <summary>Timeline's clip extrapolation as Core's (the same five modes).</summary>
        private static TrackExtrapolation Extrapolation(TimelineClip.ClipExtrapolation mode) => mode switch
        {
            TimelineClip.ClipExtrapolation.Hold => TrackExtrapolation.Hold,
            TimelineClip.ClipExtrapolation.Loop => TrackExtrapolation.Loop,
            TimelineClip.ClipExtrapolation.PingPong => TrackExtrapolation.PingPong,
            TimelineClip.ClipExtrapolation.Continue => TrackExtrapolation.Continue,
            _ => TrackExtrapolation.None,
        };
    }
}
