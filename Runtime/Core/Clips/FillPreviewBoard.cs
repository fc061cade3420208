using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// The key fill's previews, published per character: the fill's window posts "on this character, show this filled
    /// copy over this keyed clip" here, and the character's preview layer (an <c>IAnimationWindowPreview</c>) reads it
    /// when the Animation window or Timeline previews the character. It decides which clip, which character and
    /// whether a preview shows; the engine's side only asks.
    /// </summary>
    /// <remarks>
    /// <para>Engine-free: characters and clips are the engine's instance ids, <typeparamref name="TClip"/> is the
    /// preview (Unity's <c>AnimationClip</c>). A preview shows only while the preview graph plays the very clip it was
    /// computed from (an Animation window on another clip, or Timeline between that clip's uses, shows the animator's
    /// own keys), and each publish or clear moves the character's <see cref="Version"/> on, so a layer swaps what it
    /// plays once per change rather than comparing clips at every evaluation.</para>
    /// </remarks>
    public sealed class FillPreviewBoard<TClip> where TClip : class
    {
        // Per character: the keyed clip a preview was computed from, and the preview.
        private readonly Dictionary<int, (int KeyedClip, TClip Preview)> _byCharacter = new Dictionary<int, (int KeyedClip, TClip Preview)>();
        private readonly Dictionary<int, int> _versions = new Dictionary<int, int>();

        /// <summary>
        /// Shows <paramref name="preview"/> on <paramref name="character"/> wherever its preview plays
        /// <paramref name="keyedClip"/>, in place of any preview published for it before.
        /// </summary>
        /// <exception cref="ArgumentException">An id is 0 (no engine object has it).</exception>
        /// <exception cref="ArgumentNullException"><paramref name="preview"/> is null.</exception>
        public void Publish(int character, int keyedClip, TClip preview)
        {
            if (character == 0) throw new ArgumentException("character: 0 is no object's id; expected the character's instance id", nameof(character));
            if (keyedClip == 0) throw new ArgumentException("keyedClip: 0 is no object's id; expected the keyed clip's instance id", nameof(keyedClip));
            if (preview == null) throw new ArgumentNullException(nameof(preview), "preview: null; expected the filled copy of the keyed clip");
            _byCharacter[character] = (keyedClip, preview);
            Bump(character);
        }

        /// <summary>Shows the animator's own keys on <paramref name="character"/> again; false when nothing was published.</summary>
        public bool Clear(int character)
        {
            if (!_byCharacter.Remove(character)) return false;
            Bump(character);
            return true;
        }

        /// <summary>Moves on at every publish and clear for <paramref name="character"/>; 0 before the first.</summary>
        public int Version(int character) => _versions.TryGetValue(character, out int v) ? v : 0;

        /// <summary>The preview published for <paramref name="character"/> and the clip it was computed from.</summary>
        public bool TryGet(int character, out int keyedClip, out TClip? preview)
        {
            if (_byCharacter.TryGetValue(character, out (int KeyedClip, TClip Preview) p))
            {
                keyedClip = p.KeyedClip;
                preview = p.Preview;
                return true;
            }

            keyedClip = 0;
            preview = null;
            return false;
        }

        /// <summary>
        /// The preview's weight over what the graph plays: 1 where a preview is published for
        /// <paramref name="character"/> and the graph plays its keyed clip (<paramref name="shown"/> is that clip's
        /// playable, <see cref="PreviewGraphSearch.Find"/>), else 0: the animator's own keys.
        /// </summary>
        public float Weight(int character, PreviewGraphSearch.Shown shown) =>
            shown.Found && _byCharacter.TryGetValue(character, out (int KeyedClip, TClip Preview) p) && p.KeyedClip == shown.Clip ? 1f : 0f;

        private void Bump(int character) => _versions[character] = Version(character) + 1;
    }
}
