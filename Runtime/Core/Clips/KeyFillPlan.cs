using System.Collections.Generic;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>What a clip's curves animate: a generic rig's transforms, or a humanoid Animator's body and muscles.</summary>
    public enum KeyFillClipKind
    {
        /// <summary>Transform curves (<c>m_LocalRotation</c>, <c>localEulerAnglesRaw</c>, <c>m_LocalPosition</c>) on the rig's bones.</summary>
        Transform,

        /// <summary>A humanoid clip's body (<c>RootT</c>, <c>RootQ</c>) and muscle curves on the Animator.</summary>
        Humanoid,
    }

    /// <summary>
    /// What <see cref="KeyFill.Plan"/> found in a clip: its kind, the animator's key frames inside the range on the
    /// model's timeline (the bake's keys), the gaps between them and what had to be rounded. Checked before any
    /// model runs.
    /// </summary>
    public sealed class KeyFillPlan
    {
        internal KeyFillPlan(string clip, KeyFillClipKind kind, double frameRate, int[] keyFrames, double[] keyTimes, int snappedKeys, FillRange? range, string[] warnings, bool[] poseCurves)
        {
            Clip = clip;
            Kind = kind;
            FrameRate = frameRate;
            KeyFrameArray = keyFrames;
            KeyTimeArray = keyTimes;
            SnappedKeys = snappedKeys;
            Range = range;
            Warnings = warnings;
            PoseCurveArray = poseCurves;
        }

        /// <summary>The clip's name, for messages.</summary>
        public string Clip { get; }

        /// <summary>What the clip's pose curves animate.</summary>
        public KeyFillClipKind Kind { get; }

        /// <summary>The model's frame rate: key frames count in it and filled keys lie on it.</summary>
        public double FrameRate { get; }

        /// <summary>The animator's key frames inside the range, ascending, at <see cref="FrameRate"/>: the bake's keys.</summary>
        public IReadOnlyList<int> KeyFrames => KeyFrameArray;

        /// <summary>The clip time (seconds) of each of <see cref="KeyFrames"/>: where the key poses are read.</summary>
        public IReadOnlyList<double> KeyTimes => KeyTimeArray;

        /// <summary>The first key: filled keys start after it.</summary>
        public int FirstKey => KeyFrameArray[0];

        /// <summary>The last key: filled keys end before it.</summary>
        public int LastKey => KeyFrameArray[KeyFrameArray.Length - 1];

        /// <summary>Gaps (consecutive keys with frames between them).</summary>
        public int GapCount => ClipKeyFrames.CountGaps(KeyFrameArray);

        /// <summary>Model frames between the keys (what the model fills).</summary>
        public int MissingFrames => LastKey - FirstKey + 1 - KeyFrameArray.Length;

        /// <summary>Keys whose time was not on a model frame and was rounded to the nearest one for the bake (their values are kept).</summary>
        public int SnappedKeys { get; }

        /// <summary>The range asked for, or null for the whole clip.</summary>
        public FillRange? Range { get; }

        /// <summary>One line per concern the window shows before filling (e.g. rounded keys).</summary>
        public IReadOnlyList<string> Warnings { get; }

        internal int[] KeyFrameArray { get; }

        internal double[] KeyTimeArray { get; }

        /// <summary>For each curve the plan was made on, whether it is a pose curve (the fill writes only those).</summary>
        internal bool[] PoseCurveArray { get; }
    }
}
