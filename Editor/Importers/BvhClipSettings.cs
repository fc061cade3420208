#nullable enable
using System;
using DeltaInterpolator.Core.BvhImport;
using UnityEngine;

namespace DeltaInterpolator.Editor.Importers
{
    /// <summary>One clip the <c>.bvh</c> importer cuts from the file (its <i>Clips</i> list): Core's <see cref="BvhClipRange"/> as inspector fields.</summary>
    [Serializable]
    public sealed class BvhClipSettings
    {
        /// <summary>The clip's name.</summary>
        [Tooltip("The clip's name (its sub-asset; references to it follow the name).")]
        public string name = "Clip";

        /// <summary>The file's frame the clip starts on (0-based).</summary>
        [Tooltip("The file's frame the clip starts on (0 is the first frame of the MOTION section).")]
        public int firstFrame = 0;

        /// <summary>The file's frame the clip ends on, inclusive.</summary>
        [Tooltip("The file's frame the clip ends on (inclusive).")]
        public int lastFrame = 0;

        /// <summary>Whether the clip loops (Loop Time and Loop Pose).</summary>
        [Tooltip("Loop the clip (Loop Time and Loop Pose). Cut it so that its first frame is what would follow its last in the file (LoopSeam measures this).")]
        public bool loop = false;

        /// <summary>Whether the clip plays the range forward, then back (a seamless loop on motion that does not come back to its start, such as a standing sway).</summary>
        [Tooltip("Play the range forward, then back: with Loop, a loop without a seam on motion that never returns to its start (a standing idle's sway).")]
        public bool pingPong = false;

        /// <summary>The range as Core takes it.</summary>
        public BvhClipRange ToRange() => new BvhClipRange(name ?? "", firstFrame, lastFrame, loop, pingPong);
    }
}
