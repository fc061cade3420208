using System;
using DeltaInterpolator.Core.Clips;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The character's part of the Editor previews (<see cref="IAnimationWindowPreview"/>, implemented by
    /// <see cref="MotionInbetweener"/>): over what the Animation window or Timeline previews, the key fill's filled copy of
    /// the clip being keyed, at that clip's own time, while the fill publishes one for this character
    /// (<see cref="Publish"/>) and the preview plays that clip; the animator's own keys otherwise. Nothing is written to
    /// the clip and Play mode is untouched.
    /// </summary>
    /// <remarks>
    /// <para>How the engine calls it (UnityCsReference 6000.0, <c>AnimationWindowControl</c>; Timeline 1.8.10,
    /// <c>AnimationTrack.CreateMixerPlayableGraph</c> and <c>AnimationPreviewUpdateCallback</c>): <c>StartPreview</c> when
    /// the preview starts; <c>BuildPreviewGraph</c> each time the preview graph is built, given the graph's pose so far
    /// (the Animation window's layer mixer of default pose, clip and candidate keys; a Timeline track's mixer);
    /// <c>UpdatePreviewGraph</c> before each evaluation (the Animation window: every resample; Timeline: after it set its
    /// clips' times); <c>StopPreview</c> after the graph was destroyed.</para>
    /// <para>The graph: a two-layer mixer, the input at weight 1 and the filled copy's clip playable as an override layer
    /// at w (curves the copy has replace the input's; the rest keep the input's, as under the keyed clip). w is Core's
    /// (<see cref="FillPreviewBoard{TClip}.Weight"/>): 1 where the input plays the keyed clip
    /// (<see cref="PreviewGraphSearch"/>), else 0. The copy plays at the keyed clip playable's time, so the Animation
    /// window's playhead and a Timeline clip's clip-in, speed and offsets apply to it as to the clip. A new publish or a
    /// clear swaps the copy's playable once (the board's version), in the graph already built: the window need not
    /// rebuild it.</para>
    /// </remarks>
    public sealed class FillPreviewLayer
    {
        private readonly GameObject _character;
        private Playable _input;
        private AnimationLayerMixerPlayable _mixer;
        private AnimationClipPlayable _filled;
        private int _version = -1;

        /// <summary>The layer of <paramref name="character"/> (the GameObject holding its Animator and the component).</summary>
        public FillPreviewLayer(GameObject character)
        {
            _character = character != null ? character : throw new ArgumentNullException(nameof(character));
        }

        /// <summary>The key fill's previews, per character: what <see cref="Publish"/> and <see cref="Clear"/> change.</summary>
        public static FillPreviewBoard<AnimationClip> Board { get; } = new FillPreviewBoard<AnimationClip>();

        /// <summary>
        /// Shows <paramref name="filled"/> (a filled copy of <paramref name="keyedClip"/>) on <paramref name="character"/>'s
        /// previews wherever they play <paramref name="keyedClip"/>, until <see cref="Clear"/> or another publish. Keep
        /// <paramref name="filled"/> alive until then.
        /// </summary>
        /// <exception cref="ArgumentNullException">An argument is null (or a destroyed object).</exception>
        /// <exception cref="ArgumentException"><paramref name="filled"/> is <paramref name="keyedClip"/> itself.</exception>
        public static void Publish(GameObject character, AnimationClip keyedClip, AnimationClip filled)
        {
            if (character == null) throw new ArgumentNullException(nameof(character), "character: none; expected the GameObject with the character's Animator");
            if (keyedClip == null) throw new ArgumentNullException(nameof(keyedClip), "keyedClip: none; expected the clip being keyed");
            if (filled == null) throw new ArgumentNullException(nameof(filled), "filled: none; expected the filled copy of the keyed clip");
            if (filled == keyedClip) throw new ArgumentException($"filled: the keyed clip {keyedClip.name} itself; expected a copy, so that nothing is written before the fill", nameof(filled));
            Board.Publish(character.GetInstanceID(), keyedClip.GetInstanceID(), filled);
        }

        /// <summary>Shows <paramref name="character"/>'s own keys again; false when nothing was published for it.</summary>
        public static bool Clear(GameObject character) => character != null && Board.Clear(character.GetInstanceID());

        /// <summary>The preview starts: nothing is held from an earlier one.</summary>
        public void Start() => Release();

        /// <summary>The preview stopped (the engine destroyed its graph first): let go of its playables.</summary>
        public void Stop() => Release();

        /// <summary>
        /// The preview's graph is built: a mixer over <paramref name="input"/> where the filled copy will join. In Play mode,
        /// or when <paramref name="active"/> is false (the component disabled), <paramref name="input"/> goes on unchanged.
        /// </summary>
        public Playable Build(PlayableGraph graph, Playable input, bool active)
        {
            Release();
            if (!active || Application.isPlaying || !graph.IsValid() || !input.IsValid()) return input;
            _input = input;
            // A layer mixer, the copy an override layer: bones and properties the copy does not key keep the input's
            // values (the Animation window's default-pose layer, a track's other curves), as they do under the clip.
            _mixer = AnimationLayerMixerPlayable.Create(graph, 2);
            graph.Connect(input, 0, _mixer, 0);
            _mixer.SetInputWeight(0, 1f);
            _mixer.SetInputWeight(1, 0f);
            return _mixer;
        }

        /// <summary>Before an evaluation of the preview: the filled copy swapped in when the board changed, its weight and time.</summary>
        public void Update(PlayableGraph graph)
        {
            if (!graph.IsValid() || !_mixer.IsValid()) return;
            int id = _character.GetInstanceID();
            int version = Board.Version(id);
            if (version != _version)
            {
                Swap(graph, id);
                _version = version;
            }

            float weight = 0f;
            if (_filled.IsValid() && Board.TryGet(id, out int keyed, out _))
            {
                PreviewGraphSearch.Shown shown = PreviewGraphSearch.Find(_input, keyed, new PlayableTree(), out Playable at);
                weight = Board.Weight(id, shown);
                if (weight > 0f) _filled.SetTime(at.GetTime());
            }

            _mixer.SetInputWeight(1, weight);
        }

        private void Swap(PlayableGraph graph, int id)
        {
            if (_filled.IsValid())
            {
                graph.Disconnect(_mixer, 1);
                graph.DestroyPlayable(_filled);
            }

            _filled = default;
            if (!Board.TryGet(id, out _, out AnimationClip? filled) || filled == null) return;
            _filled = AnimationClipPlayable.Create(graph, filled);
            // As the Animation window plays the keyed clip: no foot IK, so the copy shows the keys' own feet.
            _filled.SetApplyFootIK(false);
            graph.Connect(_filled, 0, _mixer, 1);
        }

        private void Release()
        {
            _input = Playable.Null;
            _mixer = default;
            _filled = default;
            _version = -1;
        }

        /// <summary>Unity's playables as Core's search walks them (a struct: searching allocates nothing).</summary>
        private struct PlayableTree : PreviewGraphSearch.IGraph<Playable>
        {
            public bool IsValid(Playable node) => node.IsValid();

            public int InputCount(Playable node) => node.GetInputCount();

            public Playable Input(Playable node, int port) => node.GetInput(port);

            public float InputWeight(Playable node, int port) => node.GetInputWeight(port);

            public int ClipOf(Playable node)
            {
                if (node.GetPlayableType() != typeof(AnimationClipPlayable)) return 0;
                AnimationClip clip = ((AnimationClipPlayable)node).GetAnimationClip();
                return clip != null ? clip.GetInstanceID() : 0;
            }
        }
    }
}
