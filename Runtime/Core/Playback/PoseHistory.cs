using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// The character's recent poses (character space), recorded once per rendered frame with the game's
    /// frame times, and resampled at the model's frame rate when a transition is requested: the model was
    /// trained on poses 1/30 s apart, while a game renders every 3 to 33 ms.
    /// </summary>
    /// <remarks>
    /// A ring buffer of flat arrays, allocated once. So that it covers the model's past window at any
    /// frame rate with a fixed size, kept samples are at least <see cref="MinimumSpacing"/> apart (an
    /// eighth of a model frame): a frame that comes sooner replaces the newest sample instead of adding
    /// one, so the newest sample is always the last pose recorded. Resampling interpolates linearly
    /// (roots) and spherically (rotations) between the two samples around each model frame time, and holds
    /// the oldest sample before it. Not thread-safe; <see cref="Record"/> allocates nothing.
    /// </remarks>
    public sealed class PoseHistory
    {
        private readonly double[] _times;
        private readonly double[] _roots;
        private readonly double[] _rotations;
        private readonly int _capacity;
        private int _newest = -1;
        private int _count;

        /// <summary>Creates a history that can resample <paramref name="pastFrames"/> poses at <paramref name="frameRate"/>.</summary>
        /// <param name="boneCount">Bones per pose.</param>
        /// <param name="frameRate">The model's frame rate (frames per second; the contract's training fps).</param>
        /// <param name="pastFrames">How many model frames back a request reaches (the model's P).</param>
        public PoseHistory(int boneCount, double frameRate, int pastFrames)
        {
            if (boneCount < 1) throw new ArgumentOutOfRangeException(nameof(boneCount), boneCount, "expected at least one bone");
            if (!(frameRate > 0) || double.IsInfinity(frameRate)) throw new ArgumentOutOfRangeException(nameof(frameRate), frameRate, "expected a positive frame rate");
            if (pastFrames < 1) throw new ArgumentOutOfRangeException(nameof(pastFrames), pastFrames, "expected at least one past frame");
            BoneCount = boneCount;
            FrameRate = frameRate;
            PastFrames = pastFrames;
            MinimumSpacing = 1.0 / (8 * frameRate);
            // (P - 1) model frames of span at 8 samples per frame, plus the newest, plus margin.
            _capacity = 8 * (pastFrames - 1) + 4;
            _times = new double[_capacity];
            _roots = new double[_capacity * 3];
            _rotations = new double[_capacity * boneCount * 4];
        }

        /// <summary>Bones per pose.</summary>
        public int BoneCount { get; }

        /// <summary>The model's frame rate the history resamples to.</summary>
        public double FrameRate { get; }

        /// <summary>The model frames a request reaches back (P).</summary>
        public int PastFrames { get; }

        /// <summary>Kept samples are at least this far apart (seconds).</summary>
        public double MinimumSpacing { get; }

        /// <summary>Number of samples held.</summary>
        public int Count => _count;

        /// <summary>Time of the newest sample (seconds); NaN when empty.</summary>
        public double NewestTime => _count == 0 ? double.NaN : _times[_newest];

        /// <summary>Time of the oldest sample held (seconds); NaN when empty.</summary>
        public double OldestTime => _count == 0 ? double.NaN : _times[Slot(_count - 1)];

        /// <summary>Forgets every sample (e.g. after a teleport or when time restarts).</summary>
        public void Clear()
        {
            _count = 0;
            _newest = -1;
        }

        /// <summary>
        /// Records the pose shown at <paramref name="time"/>. A time equal to the newest replaces it; an
        /// earlier time (time restarted) clears the history first.
        /// </summary>
        /// <param name="time">The rendered frame's time, seconds.</param>
        /// <param name="root">Root position, 3 values.</param>
        /// <param name="rotations">Local rotations, <see cref="BoneCount"/> × 4 values (w, x, y, z).</param>
        public void Record(double time, ReadOnlySpan<double> root, ReadOnlySpan<double> rotations)
        {
            if (double.IsNaN(time) || double.IsInfinity(time)) throw new ArgumentOutOfRangeException(nameof(time), time, "expected a finite time");
            if (root.Length < 3 || rotations.Length < BoneCount * 4) throw new ArgumentException($"a pose needs 3 root values and {BoneCount * 4} rotation values");
            if (_count > 0 && time < _times[_newest]) Clear();
            int slot;
            if (_count > 0 && time == _times[_newest])
            {
                slot = _newest;
            }
            else if (_count >= 2 && _times[_newest] - _times[Slot(1)] < MinimumSpacing)
            {
                // The newest is still too close to the sample before it to be kept: it moves forward in
                // time instead, so kept samples stay at least MinimumSpacing apart.
                slot = _newest;
            }
            else
            {
                _newest = (_newest + 1) % _capacity;
                if (_count < _capacity) _count++;
                slot = _newest;
            }

            _times[slot] = time;
            root.Slice(0, 3).CopyTo(new Span<double>(_roots, slot * 3, 3));
            int r = BoneCount * 4;
            rotations.Slice(0, r).CopyTo(new Span<double>(_rotations, slot * r, r));
        }

        /// <summary>
        /// The pose at <paramref name="time"/>: interpolated between the samples around it, the newest
        /// after the newest, the oldest before the oldest.
        /// </summary>
        /// <exception cref="InvalidOperationException">Nothing was recorded yet.</exception>
        public void Sample(double time, Span<double> root, Span<double> rotations)
        {
            if (_count == 0) throw new InvalidOperationException("the pose history is empty: record at least one frame before requesting a transition");
            int later = 0;
            // Walk from the newest back to the first sample at or before the time (P model frames hold
            // at most ~8 P samples, so a linear walk is as fast as a search).
            while (later < _count - 1 && _times[Slot(later + 1)] > time) later++;
            int newer = Slot(later);
            if (later == _count - 1 || time >= _times[newer])
            {
                Copy(newer, root, rotations);
                return;
            }

            int older = Slot(later + 1);
            double t0 = _times[older];
            double t1 = _times[newer];
            double a = (time - t0) / (t1 - t0);
            for (int c = 0; c < 3; c++) root[c] = _roots[older * 3 + c] + a * (_roots[newer * 3 + c] - _roots[older * 3 + c]);
            int r = BoneCount * 4;
            for (int b = 0; b < BoneCount; b++)
            {
                QuaternionD q0 = QuaternionD.Read(_rotations, older * r + 4 * b);
                QuaternionD q1 = QuaternionD.Read(_rotations, newer * r + 4 * b);
                Quaternions.Normalize(new SlerpPair(q0, q1).At(a)).Write(rotations, 4 * b);
            }
        }

        /// <summary>
        /// The last <paramref name="count"/> poses at the model's frame rate, ending at <paramref name="endTime"/>:
        /// pose i is at endTime − (count − 1 − i) / <see cref="FrameRate"/>, oldest first.
        /// </summary>
        /// <param name="endTime">Time of the last pose (usually <see cref="NewestTime"/>).</param>
        /// <param name="count">Number of poses.</param>
        /// <param name="roots">count × 3 root positions.</param>
        /// <param name="rotations">count × <see cref="BoneCount"/> × 4 local rotations.</param>
        public void Resample(double endTime, int count, Span<double> roots, Span<double> rotations)
        {
            int r = BoneCount * 4;
            for (int i = 0; i < count; i++)
            {
                double t = endTime - (count - 1 - i) / FrameRate;
                Sample(t, roots.Slice(3 * i, 3), rotations.Slice(r * i, r));
            }
        }

        /// <summary>Slot of the sample <paramref name="age"/> places older than the newest.</summary>
        private int Slot(int age) => (_newest - age + _capacity) % _capacity;

        private void Copy(int slot, Span<double> root, Span<double> rotations)
        {
            new ReadOnlySpan<double>(_roots, slot * 3, 3).CopyTo(root);
            int r = BoneCount * 4;
            new ReadOnlySpan<double>(_rotations, slot * r, r).CopyTo(rotations);
        }
    }
}
