using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// Reads the key poses of a clip whose keyframes are an animator's keys: the set of key times over
    /// every rotation and position curve, turned into frame indices at the model's rate. The editor
    /// window passes plain arrays of key times (one per curve), so this runs and is tested without Unity.
    /// </summary>
    public static class ClipKeyReader
    {
        /// <summary>A key closer than this to a frame (in frames) counts as on the frame, not rounded.</summary>
        public const double OnFrameTolerance = 1e-3;

        /// <summary>
        /// True for the Transform properties that make up a pose: local rotation (quaternion
        /// <c>m_LocalRotation.*</c> or Euler <c>localEulerAngles*.*</c>) and local position
        /// (<c>m_LocalPosition.*</c>). Scale, blend shapes and script properties are not poses.
        /// </summary>
        /// <param name="propertyName">A curve's property name as Unity stores it.</param>
        public static bool IsPoseProperty(string propertyName)
        {
            if (string.IsNullOrEmpty(propertyName)) return false;
            int dot = propertyName.LastIndexOf('.');
            if (dot <= 0 || dot != propertyName.Length - 2) return false;
            char c = propertyName[propertyName.Length - 1];
            string stem = propertyName.Substring(0, dot);
            switch (stem)
            {
                case "m_LocalRotation":
                    return c == 'x' || c == 'y' || c == 'z' || c == 'w';
                case "localEulerAngles":
                case "localEulerAnglesRaw":
                case "localEulerAnglesBaked":
                case "m_LocalEulerAngles":
                case "m_LocalPosition":
                    return c == 'x' || c == 'y' || c == 'z';
                default:
                    return false;
            }
        }

        /// <summary>
        /// The distinct key frames of a clip: every key time of every curve, multiplied by
        /// <paramref name="frameRate"/> and rounded to the nearest frame. Keys outside
        /// [0, <paramref name="clipLength"/>] are left out and counted.
        /// </summary>
        /// <param name="keyTimesPerCurve">The key times (seconds) of each pose curve.</param>
        /// <param name="frameRate">The model's frame rate (frames per second, e.g. 30).</param>
        /// <param name="clipLength">The clip's length in seconds.</param>
        /// <exception cref="ArgumentOutOfRangeException">The rate or length is not a positive finite number.</exception>
        public static ClipKeyFrames Read(IEnumerable<IReadOnlyList<float>> keyTimesPerCurve, double frameRate, double clipLength)
        {
            if (keyTimesPerCurve == null) throw new ArgumentNullException(nameof(keyTimesPerCurve));
            if (!(frameRate > 0) || double.IsInfinity(frameRate)) throw new ArgumentOutOfRangeException(nameof(frameRate), "the frame rate must be a positive number of frames per second");
            if (!(clipLength >= 0) || double.IsInfinity(clipLength)) throw new ArgumentOutOfRangeException(nameof(clipLength), "the clip length must be a finite number of seconds ≥ 0");

            // Times a hair past the end (float rounding of the last key) still belong to the clip.
            double end = clipLength + OnFrameTolerance / frameRate;
            var frames = new SortedSet<int>();
            int snapped = 0;
            int ignored = 0;
            double largest = 0;
            foreach (IReadOnlyList<float> times in keyTimesPerCurve)
            {
                if (times == null) continue;
                for (int i = 0; i < times.Count; i++)
                {
                    double t = times[i];
                    if (double.IsNaN(t) || t < -OnFrameTolerance / frameRate || t > end)
                    {
                        ignored++;
                        continue;
                    }

                    double exact = t * frameRate;
                    int frame = (int)Math.Round(exact, MidpointRounding.AwayFromZero);
                    if (frame < 0) frame = 0;
                    double snap = Math.Abs(exact - frame);
                    if (snap > OnFrameTolerance)
                    {
                        snapped++;
                        largest = Math.Max(largest, snap);
                    }

                    frames.Add(frame);
                }
            }

            var list = new int[frames.Count];
            frames.CopyTo(list);
            return new ClipKeyFrames(list, frameRate, snapped, largest, ignored);
        }
    }
}
