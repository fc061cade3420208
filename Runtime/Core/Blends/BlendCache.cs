using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// Every blend of a track computed once and served from memory: <see cref="Get"/> bakes a blend or gap the first
    /// time it is asked for — one bake of that gap through the editor baker's Core path (<see cref="CharacterBake.Run"/>:
    /// the first clip's <see cref="BlendModel.PastFrames"/> frames up to the span's start as history, read where the
    /// track plays them (the clip's speed, its loop wrapped), the second clip's
    /// pose at its end as the target, the same model) — and returns the same <see cref="BlendFrames"/> whenever nothing
    /// the bake reads has changed, so moving the playhead, evaluating out of order and rebuilding an unchanged graph run
    /// no network.
    /// </summary>
    /// <remarks>
    /// <para>The key is what the bake reads, not what the caller calls it: the model (its network object and joint map),
    /// the rig (bones, parents, positions, reference pose, armature), the span's kind and model-frame count, and the
    /// key poses themselves, sampled from the clips at the span's timing on every <see cref="Get"/> (a handful of clip
    /// samples, no network). So a change to a clip where its keys are read, to the timing, the model or the rig is a new
    /// key and a new bake, and a change that leaves all of that as it was cannot leave a stale blend behind, since there is
    /// no version number to forget to bump.</para>
    /// <para>The least recently used blends beyond <see cref="Capacity"/> are dropped. Not thread-safe (the Unity layer
    /// calls it on the main thread, when the track's graph is built).</para>
    /// </remarks>
    public sealed class BlendCache
    {
        private readonly List<Entry> _entries = new List<Entry>();
        private double[] _poses = Array.Empty<double>();

        /// <summary>A cache of at most <paramref name="capacity"/> blends.</summary>
        /// <exception cref="ArgumentOutOfRangeException">Capacity below 1.</exception>
        public BlendCache(int capacity = 64)
        {
            if (capacity < 1) throw new ArgumentOutOfRangeException(nameof(capacity), capacity, "expected room for at least 1 blend");
            Capacity = capacity;
        }

        /// <summary>Most blends kept.</summary>
        public int Capacity { get; }

        /// <summary>Blends held now.</summary>
        public int Count => _entries.Count;

        /// <summary>Blends computed since the cache was made (each a bake: the network runs only there).</summary>
        public int Computed { get; private set; }

        /// <summary>
        /// The frames of <paramref name="span"/> between <paramref name="from"/> and <paramref name="to"/> for
        /// <paramref name="rig"/>: from memory when the same blend was computed before, else baked now (and
        /// <paramref name="warn"/> told, once, when the model's in-between is not what plays).
        /// </summary>
        /// <param name="model">The model and map.</param>
        /// <param name="rig">The character.</param>
        /// <param name="span">A blend or gap of the track's <see cref="TrackLayout"/>.</param>
        /// <param name="from">The clip the span leaves.</param>
        /// <param name="to">The clip the span arrives in.</param>
        /// <param name="warn">Told the fallback's reason when this call computes a blend the model cannot fill.</param>
        /// <exception cref="Retargeting.JointMapException">The rig cannot be mapped onto the model.</exception>
        public BlendFrames Get(BlendModel model, CharacterRig rig, TrackSpan span, IClipPoses from, IClipPoses to, Action<string>? warn = null)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (from == null) throw new ArgumentNullException(nameof(from));
            if (to == null) throw new ArgumentNullException(nameof(to));
            if (!(span.Duration > 0)) throw new ArgumentException($"a span of {span.Duration} s; expected a blend or gap of a track layout", nameof(span));

            double fps = model.Contract.FramesPerSecond;
            int missing = model.MissingFrames(span.Duration);
            string? reason = span.CrossfadeReason ?? model.OutsideTrainedRange(missing);
            BlendMode mode = reason == null ? BlendMode.Model : span.Kind == TrackSpanKind.Blend ? BlendMode.Crossfade : BlendMode.Slerp;

            // The keys the bake reads: past frames of the first clip up to the span's start, one per model frame of track
            // time and read where the track plays the clip then (its speed, its loop wrapped), then the second clip's pose.
            // The history reaches back as far as the clip has played animation, in track seconds.
            TrackClipTiming leaving = span.FromClip;
            double played = Math.Max(0, leaving.Unwrapped(span.Start)) / leaving.Speed;
            TransitionKeyPlan plan = TransitionKeyPlan.Create(played, span.ToTime, mode == BlendMode.Model ? model.PastFrames : 1, Math.Max(1, missing), fps);
            int bones = rig.Skeleton.JointCount, stride = 3 + 4 * bones;
            int poses = mode == BlendMode.Crossfade ? 0 : plan.PastFrames + 1;
            if (_poses.Length < poses * stride) _poses = new double[poses * stride];
            for (int k = 0; k < poses; k++)
            {
                Span<double> pose = _poses.AsSpan(k * stride, stride);
                if (k < plan.PastFrames) from.Sample(leaving.LocalTime(span.Start - (plan.PastFrames - 1 - k) / fps), pose.Slice(0, 3), pose.Slice(3));
                else to.Sample(plan.ToTime, pose.Slice(0, 3), pose.Slice(3));
            }

            // A crossfade reads no pose: its clips and times are its key, so that each one is said once.
            string crossfade = mode == BlendMode.Crossfade
                ? string.Format(CultureInfo.InvariantCulture, "{0}→{1}@{2:R}–{3:R}", from.Name, to.Name, span.Start, span.End)
                : "";
            var key = new Key(model, rig, span.Kind, mode, missing, crossfade, _poses.AsSpan(0, poses * stride));
            for (int i = 0; i < _entries.Count; i++)
            {
                if (!_entries[i].Key.Equals(key)) continue;
                Entry hit = _entries[i];
                _entries.RemoveAt(i);
                _entries.Add(hit);
                return hit.Frames;
            }

            BlendFrames frames = Compute(model, rig, span, from, to, plan, mode, reason, missing, stride);
            Computed++;
            if (frames.Warning != null) warn?.Invoke(frames.Warning);
            if (_entries.Count == Capacity) _entries.RemoveAt(0);
            _entries.Add(new Entry(key, frames));
            return frames;
        }

        /// <summary>Forgets every blend (e.g. when the model asset is unloaded).</summary>
        public void Clear() => _entries.Clear();

        private BlendFrames Compute(BlendModel model, CharacterRig rig, TrackSpan span, IClipPoses from, IClipPoses to, TransitionKeyPlan plan, BlendMode mode, string? reason, int missing, int stride)
        {
            string where = string.Format(CultureInfo.InvariantCulture, "{0} {1} → {2} at {3:0.###}–{4:0.###} s", span.Kind == TrackSpanKind.Blend ? "blend" : "gap",
                from.Name, to.Name, span.Start, span.End);
            if (mode == BlendMode.Crossfade) return new BlendFrames(mode, rig, null, $"{where}: {reason}; Timeline's crossfade plays instead of the model's in-between");

            double frameTime = 1.0 / model.Contract.FramesPerSecond;
            if (missing < 1)
            {
                // No frame between the two keys: the span plays the SLERP of the two poses itself.
                var direct = new CharacterPoseTrack(rig, 2, frameTime);
                direct.SetUnityPose(0, _poses.AsSpan(0, 3), _poses.AsSpan(3, stride - 3));
                direct.SetUnityPose(1, _poses.AsSpan(stride, 3), _poses.AsSpan(stride + 3, stride - 3));
                return new BlendFrames(BlendMode.Slerp, rig, direct.Motion, $"{where}: {reason}; the SLERP of the two poses plays instead of the model's in-between");
            }

            var track = new CharacterPoseTrack(rig, plan.FrameCount, frameTime);
            for (int k = 0; k < plan.PastFrames; k++) track.SetUnityPose(k, _poses.AsSpan(k * stride, 3), _poses.AsSpan(k * stride + 3, stride - 3));
            int target = plan.PastFrames * stride;
            track.SetUnityPose(plan.TargetFrame, _poses.AsSpan(target, 3), _poses.AsSpan(target + 3, stride - 3));
            BakeMethod method = mode == BlendMode.Model ? new BakeMethod("Model", model.Network, model.Settings) : BakeMethod.Slerp();
            BakeRun run = CharacterBake.Run(model.Contract, track, model.JointMap, new[] { method }, null, model.MaxBoneDeviationDegrees);
            MotionClip frames = run.Methods[0].OnRig.Excerpt(plan.PastFrames - 1, missing + 2);
            string? warning = mode == BlendMode.Slerp ? $"{where}: {reason}; SLERP fills it instead of the model" : null;
            if (mode == BlendMode.Model && run.Methods[0].Plan.Warnings.Count > 0) warning = $"{where}: {string.Join(" ", run.Methods[0].Plan.Warnings)}";
            return new BlendFrames(mode, rig, frames, warning);
        }

        /// <summary>A cached blend and the key it was baked for.</summary>
        private sealed record Entry(Key Key, BlendFrames Frames);

        /// <summary>Everything a blend's bake reads, compared exactly.</summary>
        private sealed class Key : IEquatable<Key>
        {
            private readonly object _network;
            private readonly string _text;
            private readonly double[] _values;
            private readonly int _hash;

            public Key(BlendModel model, CharacterRig rig, TrackSpanKind kind, BlendMode mode, int missing, string crossfade, ReadOnlySpan<double> poses)
            {
                _network = model.Network;
                var text = new StringBuilder();
                text.Append(kind).Append('|').Append(crossfade).Append('|').Append(mode).Append('|').Append(missing).Append('|').Append(model.PastFrames).Append('|');
                if (model.JointMap == null) text.Append("<detected map>");
                else
                {
                    text.Append(model.JointMap.Name);
                    foreach (string joint in model.JointMap.TargetJoints)
                    {
                        text.Append('|').Append(joint).Append('=');
                        IReadOnlyList<string>? chain = model.JointMap.SourceChain(joint);
                        if (chain != null) text.Append(string.Join(",", chain));
                    }
                }

                for (int b = 0; b < rig.BoneNames.Count; b++) text.Append('|').Append(rig.BoneNames[b]).Append('<').Append(rig.Parents[b]);
                _text = text.ToString();
                var values = new List<double>(rig.LocalPositions.Count + rig.ReferenceRotations.Count + 9 + poses.Length);
                values.AddRange(rig.LocalPositions);
                values.AddRange(rig.ReferenceRotations);
                RootFrame a = rig.Armature;
                values.Add(a.Position.X);
                values.Add(a.Position.Y);
                values.Add(a.Position.Z);
                values.Add(a.Rotation.W);
                values.Add(a.Rotation.X);
                values.Add(a.Rotation.Y);
                values.Add(a.Rotation.Z);
                values.Add(a.Scale);
                values.Add(model.MaxBoneDeviationDegrees);
                foreach (double v in poses) values.Add(v);
                _values = values.ToArray();
                int hash = _text.GetHashCode() ^ model.Network.GetHashCode();
                foreach (double v in _values) hash = hash * 31 + v.GetHashCode();
                _hash = hash;
            }

            public bool Equals(Key? other)
            {
                if (other == null || other._hash != _hash || !ReferenceEquals(other._network, _network) || other._text != _text || other._values.Length != _values.Length) return false;
                for (int i = 0; i < _values.Length; i++)
                {
                    if (!_values[i].Equals(other._values[i])) return false;
                }

                return true;
            }

            public override bool Equals(object? obj) => Equals(obj as Key);

            public override int GetHashCode() => _hash;
        }
    }
}
