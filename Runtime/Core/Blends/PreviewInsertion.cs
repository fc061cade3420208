using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// When and how a neural track lets the character's preview components into its editor preview, as Timeline's
    /// Animation Track does (<c>AnimationTrack.CreateMixerPlayableGraph</c>: outside Play mode, each
    /// <c>IAnimationWindowPreview</c> on the bound GameObject, in component order, gets the track's mix and returns what
    /// follows it). In Play mode those components run their own graphs after the track's output (Animation Rigging's
    /// rig at sort order 1000), so the preview inserts them where play mode applies them: after the track's mix, neural
    /// blends included.
    /// </summary>
    /// <remarks>
    /// <para>Engine-free: <typeparamref name="TNode"/> is the graph's node type (Unity's <c>Playable</c>) and the caller
    /// says which node is valid. A custom track cannot insert anything between its mixer and Timeline's parent while
    /// the graph is being compiled (its mixer is what Timeline connects clips into and its parent into), so the
    /// insertion waits: <see cref="Built"/> records the mixer when the graph is built for a preview, and
    /// <see cref="TryTake"/> hands it over once, when Timeline has connected it.</para>
    /// <para>A component that returns an invalid node is left out of the chain (the track's mix carries on) and said
    /// once per build: the Animation Track would hand the invalid node on and break the preview.</para>
    /// </remarks>
    public sealed class PreviewInsertion<TNode>
    {
        private readonly Func<TNode, bool> _isValid;
        private TNode _mixer = default!;

        /// <summary>An insertion whose nodes are valid where <paramref name="isValid"/> says so.</summary>
        public PreviewInsertion(Func<TNode, bool> isValid)
        {
            _isValid = isValid ?? throw new ArgumentNullException(nameof(isValid));
        }

        /// <summary>Whether a built mixer waits for its preview components.</summary>
        public bool Pending { get; private set; }

        /// <summary>
        /// The track's mixer was built: in an editor preview (not Play mode, not a player) its preview components are
        /// inserted after it once Timeline has connected it (<see cref="TryTake"/>); otherwise nothing is. A rebuilt
        /// graph replaces a mixer still waiting.
        /// </summary>
        public void Built(TNode mixer, bool editorPreview)
        {
            Pending = editorPreview && _isValid(mixer);
            _mixer = Pending ? mixer : default!;
        }

        /// <summary>
        /// The mixer waiting for its preview components, once, when <paramref name="connected"/> says Timeline has
        /// connected it to its parent; false (and still waiting) before that, and false after it was taken.
        /// </summary>
        public bool TryTake(Func<TNode, bool> connected, out TNode mixer)
        {
            if (connected == null) throw new ArgumentNullException(nameof(connected));
            mixer = default!;
            if (!Pending || !_isValid(_mixer) || !connected(_mixer)) return false;
            mixer = _mixer;
            Pending = false;
            _mixer = default!;
            return true;
        }

        /// <summary>
        /// Chains <paramref name="stages"/> after <paramref name="mixer"/> in their order, each given the end of the chain so
        /// far (<paramref name="insert"/>: a component's <c>BuildPreviewGraph</c>); a stage that returns an invalid node is
        /// left out and <paramref name="warn"/> told its name. Returns the chain's end (the mixer when no stage inserted anything).
        /// </summary>
        public TNode Chain<TStage>(TNode mixer, IReadOnlyList<TStage> stages, Func<TStage, TNode, TNode> insert, Func<TStage, string> name, Action<string>? warn)
        {
            if (stages == null) throw new ArgumentNullException(nameof(stages));
            if (insert == null) throw new ArgumentNullException(nameof(insert));
            if (name == null) throw new ArgumentNullException(nameof(name));
            if (!_isValid(mixer)) throw new ArgumentException("expected the track's built mixer, a valid node", nameof(mixer));
            TNode end = mixer;
            for (int i = 0; i < stages.Count; i++)
            {
                TNode next = insert(stages[i], end);
                if (_isValid(next))
                {
                    end = next;
                    continue;
                }

                warn?.Invoke($"{name(stages[i])} returned no playable from BuildPreviewGraph; the preview shows the track without it");
            }

            return end;
        }
    }
}
