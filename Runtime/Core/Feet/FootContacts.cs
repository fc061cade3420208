using System;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>
    /// The one source of foot contacts every locker reads (<see cref="FootLocker"/> for bakes, <see cref="LiveFootLocker"/>
    /// as a transition plays): per frame and foot joint (left ankle, left toe, right ankle, right toe), the network's
    /// predicted probability that the joint is planted where a model with a contact output filled the frame, or nothing,
    /// where the locker labels the contact itself from the keys and the filled motion (key frames, SLERP's frames, a model
    /// without the output, frames not decoded yet).
    /// </summary>
    /// <remarks>
    /// A frame is planted where p ≥ <see cref="Threshold"/> (the model's <c>contact_threshold</c>, chosen on validation).
    /// The buffer grows to the longest clip seen and is reused; nothing else allocates. Not thread-safe.
    /// </remarks>
    public sealed class FootContacts
    {
        /// <summary>Foot joints per frame, in <see cref="FootLocker"/>'s channel order.</summary>
        public const int ChannelCount = FootLocker.ChannelCount;

        private float[] _probabilities = Array.Empty<float>(); // frames × channels; NaN: no prediction (the locker labels)
        private int _frames;

        /// <summary>Frames of the clip the contacts are for (<see cref="Clear"/>).</summary>
        public int FrameCount => _frames;

        /// <summary>The probability at or above which a predicted foot joint is planted.</summary>
        public double Threshold { get; private set; } = 0.5;

        /// <summary>True when at least one frame has a prediction.</summary>
        public bool AnyPredicted { get; private set; }

        /// <summary>Starts over for a clip of <paramref name="frames"/> frames with no predictions (every contact labelled).</summary>
        public void Clear(int frames)
        {
            if (frames < 0) throw new ArgumentOutOfRangeException(nameof(frames), frames, "expected a frame count ≥ 0");
            if (_probabilities.Length < frames * ChannelCount) _probabilities = new float[Math.Max(frames * ChannelCount, 2 * _probabilities.Length)];
            _frames = frames;
            AnyPredicted = false;
            _probabilities.AsSpan(0, frames * ChannelCount).Fill(float.NaN);
        }

        /// <summary>
        /// Takes the predictions of <paramref name="count"/> consecutive frames starting at <paramref name="frame"/>
        /// (<paramref name="probabilities"/>: count × 4, as a model's <c>foot_contacts</c> rows), planted at or above
        /// <paramref name="threshold"/>.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">The frames run past the clip, or the threshold is not in (0, 1).</exception>
        public void SetPredicted(int frame, int count, ReadOnlySpan<float> probabilities, double threshold)
        {
            if (frame < 0 || count < 0 || frame + count > _frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frames {frame}..{frame + count - 1}; expected within 0..{_frames - 1}");
            if (probabilities.Length < count * ChannelCount) throw new ArgumentException($"{probabilities.Length} probabilities; expected {count} frames × {ChannelCount}", nameof(probabilities));
            if (!(threshold > 0 && threshold < 1)) throw new ArgumentOutOfRangeException(nameof(threshold), threshold, "expected a probability strictly between 0 and 1");
            Threshold = threshold;
            probabilities.Slice(0, count * ChannelCount).CopyTo(_probabilities.AsSpan(frame * ChannelCount, count * ChannelCount));
            AnyPredicted |= count > 0;
        }

        /// <summary>Whether frame <paramref name="frame"/> has a prediction (else its contacts are labelled by the locker).</summary>
        public bool IsPredicted(int frame)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            return !float.IsNaN(_probabilities[frame * ChannelCount]);
        }

        /// <summary>The predicted probability that foot joint <paramref name="channel"/> is planted on <paramref name="frame"/> (NaN where none).</summary>
        public float Probability(int frame, int channel)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            if ((uint)channel >= ChannelCount) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            return _probabilities[frame * ChannelCount + channel];
        }

        /// <summary>Whether the prediction plants foot joint <paramref name="channel"/> on <paramref name="frame"/> (false where there is none).</summary>
        public bool IsPlanted(int frame, int channel) => Probability(frame, channel) >= Threshold;

        /// <summary>
        /// These contacts on another frame rate (a retargeted rig's clip): frame f of <paramref name="target"/>
        /// (<paramref name="frames"/> frames of <paramref name="frameTime"/> seconds, starting
        /// <paramref name="startSeconds"/> after this clip's first frame) takes the frame of this clip nearest in time,
        /// of <paramref name="sourceFrameTime"/> seconds each.
        /// </summary>
        public void ResampleInto(FootContacts target, int frames, double frameTime, double sourceFrameTime, double startSeconds)
        {
            if (target == null) throw new ArgumentNullException(nameof(target));
            if (!(frameTime > 0) || !(sourceFrameTime > 0)) throw new ArgumentOutOfRangeException(nameof(frameTime), "expected positive frame times");
            target.Clear(frames);
            target.Threshold = Threshold;
            target.AnyPredicted = AnyPredicted;
            for (int f = 0; f < frames; f++)
            {
                int s = (int)Math.Round((startSeconds + f * frameTime) / sourceFrameTime);
                if (s < 0 || s >= _frames) continue;
                Array.Copy(_probabilities, s * ChannelCount, target._probabilities, f * ChannelCount, ChannelCount);
            }
        }
    }
}
