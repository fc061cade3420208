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
    /// mode shows what plays. Clips that move the root are placed as on an Animation Track: by default at the track's and each
    /// clip's offsets (Apply Transform Offsets, the track putting the character there itself: <see cref="TrackRootPath"/>), or
    /// each from where the character stands (Apply Scene Offsets).
    /// </summary>
    [Serializable]
    [TrackClipType(typeof(AnimationPlayableAsset), false)]
    [TrackBindingType(typeof(Animator))]
    public sealed class NeuralAnimationTrack : TrackAsset
    {
        [SerializeField]
        [Tooltip("The model, engine and rig, as the Motion Inbetweener component takes them.")]
        private InbetweenerSettings? settings;

        [SerializeField]
        [Tooltip("What places the character when its clips move the root, as on an Animation Track: Apply Transform Offsets (each clip's root motion from its clip offset, after the track's offset; the default), Apply Scene Offsets (each clip from where the character stands), or Auto (scene offsets when the Animator has a controller, else transform offsets).")]
        private TrackOffset trackOffset = TrackOffset.ApplyTransformOffsets;

        [SerializeField]
        [Tooltip("The track's position offset (in the character's parent's space), with Apply Transform Offsets. Its height is not used.")]
        private Vector3 position;

        [SerializeField]
        [Tooltip("The track's rotation offset (Euler angles, degrees), with Apply Transform Offsets. Only its turn about the up axis is used.")]
        private Vector3 eulerAngles;

        // The tracks that were told once that an offset's height, pitch or roll is not used.
        private static readonly HashSet<int> s_flattenedSaid = new HashSet<int>();

        /// <summary>The model, engine and rig the blends are baked with.</summary>
        public InbetweenerSettings? Settings
        {
            get => settings;
            set => settings = value;
        }

        /// <summary>What places the character when the clips move the root (Timeline's <c>AnimationTrack.trackOffset</c>; the same default).</summary>
        public TrackOffset TrackOffset
        {
            get => trackOffset;
            set => trackOffset = value;
        }

        /// <summary>The track's position offset, with transform offsets (Timeline's <c>AnimationTrack.position</c>); x and z are used.</summary>
        public Vector3 Position
        {
            get => position;
            set => position = value;
        }

        /// <summary>The track's rotation offset in Euler angles, with transform offsets (Timeline's <c>AnimationTrack.eulerAngles</c>); the yaw is used.</summary>
        public Vector3 EulerAngles
        {
            get => eulerAngles;
            set => eulerAngles = value;
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
                    var placements = new List<ClipPlacement>();
                    bool rootTransforms = false, flattened = false;
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
                        bool movesRoot = animation != null && !animation.empty && (animation.hasGenericRootTransform || animation.hasMotionCurves || animation.hasRootCurves);
                        rootTransforms |= movesRoot;
                        RootPlacement offset = playable != null ? Offset(playable.position, playable.eulerAngles, ref flattened) : RootPlacement.Identity;
                        placements.Add(new ClipPlacement(offset, playable == null || playable.removeStartOffset, movesRoot));
                    }

                    // Clips that move the root, played by an Animator that applies root motion: placed as an Animation Track places
                    // them (its offset playables are internal, so the track puts the character there itself: timeline.md).
                    RootTravelMode mode = !(rootTransforms && animator!.applyRootMotion) ? RootTravelMode.None
                        : PlacesClips(trackOffset, animator.runtimeAnimatorController != null) ? RootTravelMode.TransformOffset : RootTravelMode.SceneOffset;
                    RootPlacement track = Offset(position, eulerAngles, ref flattened);
                    if (mode == RootTravelMode.TransformOffset && flattened && s_flattenedSaid.Add(GetInstanceID()))
                    {
                        Debug.LogWarning($"{name}: a track or clip offset has a height, pitch or roll; the track places the character on the ground by x, z and the turn about the up axis only (timeline.md, Known limitations)", this);
                    }

                    layer.Build(timings, clips, mode, mixIn, track, placements);
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

        /// <summary>
        /// Whether the clips are placed at their offsets (transform offsets) rather than played from where the character stands
        /// (scene offsets): as Timeline 1.8.10 decides it for an Animation Track (<c>AnimationTrack.GetOffsetMode</c>,
        /// <c>Runtime/Animation/AnimationTrack.cs:969-988</c>) — Auto, a legacy mode, is scene offsets when the bound Animator has
        /// a controller and transform offsets when it has none.
        /// </summary>
        private static bool PlacesClips(TrackOffset mode, bool hasController) => mode switch
        {
            TrackOffset.ApplyTransformOffsets => true,
            TrackOffset.ApplySceneOffsets => false,
            _ => !hasController,
        };

        /// <summary>A Timeline offset (position, Euler angles in degrees) as a placement on the ground; <paramref name="flattened"/> set where it had a height, pitch or roll.</summary>
        private static RootPlacement Offset(Vector3 position, Vector3 euler, ref bool flattened)
        {
            RootPlacement placement = RootPlacement.OfOffset(position.x, position.y, position.z, euler.x, euler.y, euler.z, out bool lost);
            flattened |= lost;
            return placement;
        }

        // The character's own transform, which the Editor preview of a transform-offset track sets (NeuralBlendLayer.Place).
        private static readonly string[] s_placedProperties =
        {
            "m_LocalPosition.x", "m_LocalPosition.y", "m_LocalPosition.z",
            "m_LocalRotation.x", "m_LocalRotation.y", "m_LocalRotation.z", "m_LocalRotation.w",
        };

        /// <inheritdoc />
        /// <remarks>
        /// Besides the clips' properties, the bound character's own position and rotation: outside Play mode a track that places
        /// its clips puts the character where it stands at the playhead, and the preview gives the transform back when it ends
        /// (as it does for the bones the clips animate).
        /// </remarks>
        public override void GatherProperties(PlayableDirector director, IPropertyCollector driver)
        {
            base.GatherProperties(director, driver);
            Animator? animator = director != null ? director.GetGenericBinding(this) as Animator : null;
            if (animator == null) return;
            foreach (string property in s_placedProperties) driver.AddFromName<Transform>(animator.gameObject, property);
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
