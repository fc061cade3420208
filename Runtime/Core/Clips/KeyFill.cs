using System;
using System.Collections.Generic;
using System.Globalization;
using static System.FormattableString;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// In-betweens written into the clip an animator is keying, engine-free: <see cref="Plan"/> reads the animator's
    /// key frames off the clip's pose curves (inside an optional <see cref="FillRange"/>) and refuses what cannot be
    /// filled; the key poses go through the one Core bake (<see cref="Workflows.CharacterBake"/>); <c>Edit</c> turns
    /// the baked frames into ordinary keys on the curves the clip has, one <see cref="KeyFillEdit"/> (curves before →
    /// after) that leaves every one of the animator's keys as it was. Transform clips: <see cref="KeyPoses"/> reads
    /// the key poses off the curves and <see cref="Edit(KeyFillPlan, IReadOnlyList{KeyedCurve}, Characters.CharacterRig, IReadOnlyList{string}, Skeletons.MotionClip)"/>
    /// writes quaternion, Euler and root position keys; humanoid clips: the engine samples the key poses and
    /// records the baked frames as muscles (the humanoid recording path), and
    /// <see cref="Edit(KeyFillPlan, IReadOnlyList{KeyedCurve}, IReadOnlyList{ClipCurve})"/> writes them.
    /// </summary>
    /// <remarks>
    /// Filled keys lie on the model's frames (the bake runs at its rate), on every pose curve, at every model frame
    /// from the first to the last key that the curve has no key on — also at another curve's key frame, where the
    /// value is the key pose the bake kept. Their tangents are the slope through their neighbours (tangent mode
    /// Free, unweighted), so the clip plays the baked frames and the animator's keys as they are.
    /// </remarks>
    public static partial class KeyFill
    {
        /// <summary>A key within this many frames of a model frame is on it (as <see cref="ClipKeyReader.OnFrameTolerance"/>).</summary>
        private const double OnFrame = ClipKeyReader.OnFrameTolerance;

        /// <summary>The most key frames a plan takes (a day of keys at 1000 fps would not fit an edit anyway).</summary>
        public const int MaxFrames = 1_000_000;

        /// <summary>
        /// Reads the animator's key frames of <paramref name="curves"/> on the model's timeline and checks that there
        /// is something to fill.
        /// </summary>
        /// <param name="clip">The clip's name, for messages.</param>
        /// <param name="curves">Every float curve of the clip (pose curves are picked out; others are never touched).</param>
        /// <param name="clipLength">The clip's length (seconds); keys after it are not keys of the fill.</param>
        /// <param name="frameRate">The model's frame rate.</param>
        /// <param name="range">Only the keys inside this range, or null for every key.</param>
        /// <param name="muscleProperties">Every muscle's curve property (<see cref="HumanoidCurves.MuscleProperty"/>), or null when no humanoid clip is expected.</param>
        /// <exception cref="KeyFillException">An empty clip, one key, no gap, two keys on one model frame, a non-finite key, transform and humanoid curves mixed (<c>curves</c>); a range outside the clip or with fewer than two keys (<c>range</c>).</exception>
        public static KeyFillPlan Plan(string clip, IReadOnlyList<KeyedCurve> curves, double clipLength, double frameRate, FillRange? range = null, ICollection<string>? muscleProperties = null)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (curves == null) throw new ArgumentNullException(nameof(curves));
            if (!(frameRate > 0) || double.IsInfinity(frameRate)) throw new ArgumentOutOfRangeException(nameof(frameRate), frameRate, "expected the model's frame rate, a positive number");
            if (!(clipLength >= 0) || double.IsInfinity(clipLength)) throw new ArgumentOutOfRangeException(nameof(clipLength), clipLength, "expected the clip's length in seconds, a finite number ≥ 0");
            if (clipLength * frameRate > MaxFrames) throw new KeyFillException(clip, Invariant($"a clip of {clipLength:0.###} s is {clipLength * frameRate:0} frames at {frameRate:0.##} fps"), Invariant($"expected at most {MaxFrames} frames"), nameof(clipLength));

            KeyFillClipKind? kind = null;
            double tolerance = OnFrame / frameRate;
            var frameTimes = new SortedDictionary<int, double>();
            int snapped = 0;
            var pose = new bool[curves.Count];
            for (int i = 0; i < curves.Count; i++)
            {
                KeyedCurve curve = curves[i];
                if (curve == null) throw new ArgumentNullException(nameof(curves), "a curve of the list is null");
                KeyFillClipKind? curveKind = KindOf(curve.Property, muscleProperties);
                if (curveKind == null) continue;
                pose[i] = true;
                if (kind != null && kind != curveKind)
                {
                    throw new KeyFillException(clip, $"the clip has both transform curves and humanoid body or muscle curves ({curve})", "expected the curves of one kind of rig: a generic clip's transform curves or a humanoid clip's body and muscles", nameof(curves));
                }

                kind = curveKind;
                foreach (CurveKey key in curve.Keys)
                {
                    if (!float.IsFinite(key.Time) || !float.IsFinite(key.Value))
                    {
                        throw new KeyFillException(clip, $"{curve} has a key of time {Number(key.Time)} and value {Number(key.Value)}", "expected finite key times and values", nameof(curves));
                    }

                    if (key.Time < -tolerance || key.Time > clipLength + tolerance) continue;
                    double exact = key.Time * frameRate;
                    int frame = Math.Max(0, (int)Math.Round(exact, MidpointRounding.AwayFromZero));
                    if (frameTimes.TryGetValue(frame, out double other))
                    {
                        if (Math.Abs(other - key.Time) * frameRate > OnFrame)
                        {
                            throw new KeyFillException(clip, Invariant($"keys at {Seconds(Math.Min(other, key.Time))} s and {Seconds(Math.Max(other, key.Time))} s fall on one frame ({frame}) at the model's {frameRate:0.##} fps"),
                                "expected at most one key time per model frame (the model fills whole frames of its rate)", nameof(curves));
                        }

                        continue;
                    }

                    if (Math.Abs(exact - frame) > OnFrame) snapped++;
                    frameTimes.Add(frame, key.Time);
                }
            }

            if (kind == null || frameTimes.Count == 0)
            {
                throw new KeyFillException(clip, "the clip has no keyed rotation, position or muscle curve", "expected a clip with the animator's key poses (keys on m_LocalRotation, localEulerAnglesRaw, m_LocalPosition or muscle curves)", nameof(curves));
            }

            if (frameTimes.Count < 2)
            {
                throw new KeyFillException(clip, "the clip has keys on one frame only", "expected at least two key frames (a gap lies between two keys)", nameof(curves));
            }

            var frames = new List<int>();
            var times = new List<double>();
            if (range is { } r)
            {
                if (!double.IsFinite(r.Start) || !double.IsFinite(r.End) || r.Start < -tolerance || r.End > clipLength + tolerance || !(r.End > r.Start))
                {
                    throw new KeyFillException(clip, $"the range {Seconds(r.Start)}–{Seconds(r.End)} s is not inside the clip's 0–{Seconds(clipLength)} s",
                        "expected a start before the end, both inside the clip", nameof(range));
                }
            }

            foreach (KeyValuePair<int, double> pair in frameTimes)
            {
                if (range is { } inside && (pair.Value < inside.Start - tolerance || pair.Value > inside.End + tolerance)) continue;
                frames.Add(pair.Key);
                times.Add(pair.Value);
            }

            if (range is { } few && frames.Count < 2)
            {
                throw new KeyFillException(clip, $"the range {few.Describe(frameRate)} holds {frames.Count} key frame{(frames.Count == 1 ? "" : "s")}",
                    "expected a range with at least two of the animator's key frames", nameof(range));
            }

            int[] keyFrames = frames.ToArray();
            if (ClipKeyFrames.CountGaps(keyFrames) == 0)
            {
                throw new KeyFillException(clip, Invariant($"no frame lies between the keys{(range == null ? "" : " of the range")} at the model's {frameRate:0.##} fps"),
                    "expected two keys at least two model frames apart (a gap to fill)", range == null ? nameof(curves) : nameof(range));
            }

            var warnings = new List<string>();
            if (snapped > 0)
            {
                warnings.Add(Invariant($"{snapped} key time{(snapped == 1 ? " lies" : "s lie")} between the model's frames at {frameRate:0.##} fps; the bake rounds {(snapped == 1 ? "it" : "them")} to the nearest frame (the keys themselves stay as they are)."));
            }

            return new KeyFillPlan(clip, kind.Value, frameRate, keyFrames, times.ToArray(), snapped, range, warnings.ToArray(), pose);
        }

        /// <summary>The kind of rig a pose curve belongs to, or null for a curve that is no pose (scale, blend shapes, script values).</summary>
        private static KeyFillClipKind? KindOf(string property, ICollection<string>? muscleProperties)
        {
            if (ClipKeyReader.IsPoseProperty(property)) return KeyFillClipKind.Transform;
            if (HumanoidCurves.IsPoseProperty(property, muscleProperties ?? Array.Empty<string>())) return KeyFillClipKind.Humanoid;
            return null;
        }

        /// <summary>The frame a key time falls on (rounded as <see cref="Plan"/> rounds it).</summary>
        private static int FrameOf(float time, double frameRate) => Math.Max(0, (int)Math.Round(time * frameRate, MidpointRounding.AwayFromZero));

        private static string Seconds(double t) => t.ToString("0.####", CultureInfo.InvariantCulture);

        private static string Number(float v) => v.ToString(CultureInfo.InvariantCulture);
    }
}
