using System;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Inbetweening
{
    /// <summary>
    /// One in-betweening problem and its answer buffers: P past key frames (window frames 0..P−1), a gap
    /// of n missing frames (P..P+n−1) and one target key frame (P+n). Key frames give the root's global
    /// position and every joint's local rotation (w, x, y, z); an <see cref="IInbetweener"/> fills the
    /// missing frames in place. Buffers are allocated once per shape and reused, so evaluating many
    /// windows allocates nothing per window.
    /// </summary>
    public sealed class Transition
    {
        /// <summary>Creates buffers for a transition of the given shape.</summary>
        /// <param name="skeleton">Hierarchy and offsets the frames refer to.</param>
        /// <param name="pastFrames">Number of past key frames P (≥ 1).</param>
        /// <param name="missingFrames">Number of missing frames n (≥ 1).</param>
        public Transition(Skeleton skeleton, int pastFrames, int missingFrames)
        {
            Skeleton = skeleton ?? throw new ArgumentNullException(nameof(skeleton));
            if (pastFrames < 1) throw new ArgumentOutOfRangeException(nameof(pastFrames), "at least one past key frame is needed");
            if (missingFrames < 1) throw new ArgumentOutOfRangeException(nameof(missingFrames), "at least one missing frame is needed");
            PastFrames = pastFrames;
            MissingFrames = missingFrames;
            int j = skeleton.JointCount;
            KeyRootPositions = new double[(pastFrames + 1) * 3];
            KeyLocalRotations = new double[(pastFrames + 1) * j * 4];
            RootPositions = new double[missingFrames * 3];
            LocalRotations = new double[missingFrames * j * 4];
            FootContacts = new float[missingFrames * ContactChannels];
        }

        /// <summary>Foot joints a model may predict contacts for: left ankle, left toe, right ankle, right toe.</summary>
        public const int ContactChannels = 4;

        /// <summary>Hierarchy and offsets the frames refer to.</summary>
        public Skeleton Skeleton { get; }

        /// <summary>Number of past key frames P.</summary>
        public int PastFrames { get; }

        /// <summary>Number of missing frames n.</summary>
        public int MissingFrames { get; }

        /// <summary>Number of key frames, P + 1 (past keys, then the target).</summary>
        public int KeyFrameCount => PastFrames + 1;

        /// <summary>Index of the target key in the key arrays (= P).</summary>
        public int TargetKey => PastFrames;

        /// <summary>Key root positions, (P + 1) × 3: past frames in order, then the target.</summary>
        public double[] KeyRootPositions { get; }

        /// <summary>Key local rotations, (P + 1) × joints × 4: past frames in order, then the target.</summary>
        public double[] KeyLocalRotations { get; }

        /// <summary>Output: root positions of the missing frames, n × 3.</summary>
        public double[] RootPositions { get; }

        /// <summary>Output: local rotations of the missing frames, n × joints × 4.</summary>
        public double[] LocalRotations { get; }

        /// <summary>
        /// Output of an in-betweener that predicts foot contacts (<see cref="HasFootContacts"/>): n × 4 probabilities
        /// that the left ankle, left toe, right ankle and right toe are planted on each missing frame.
        /// </summary>
        public float[] FootContacts { get; }

        /// <summary>True when the in-betweener that filled the frames wrote <see cref="FootContacts"/> (a model with a contact output; never SLERP).</summary>
        public bool HasFootContacts { get; set; }

        /// <summary>With <see cref="HasFootContacts"/>: the probability at or above which a foot joint is planted (the model's, chosen on validation).</summary>
        public double ContactThreshold { get; set; }
    }
}
