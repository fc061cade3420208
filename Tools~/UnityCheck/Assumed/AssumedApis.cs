using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using UnityEngine;

// Declarations of what other branches build, as Editor/ and Samples~/ call them. Not package code.

namespace DeltaInterpolator.Core.Baking
{
    /// <summary>Assumed: Runtime/Core/Baking/ClipBaker (keys at frame indices → dense motion via any IInbetweener).</summary>
    public static class ClipBaker
    {
        /// <summary>Fills every gap between consecutive key frames of <paramref name="keys"/>, using up to <paramref name="maxPastFrames"/> frames before each gap as past context.</summary>
        public static MotionClip Bake(MotionClip keys, IReadOnlyList<int> keyFrames, IInbetweener inbetweener, int maxPastFrames) => throw new NotImplementedException();
    }
}

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>Assumed: the severity of one contract check result.</summary>
    public enum ContractCheckSeverity
    {
        Info,
        Warning,
        Error,
    }

    /// <summary>Assumed: one contract check result (what, how bad, what to do).</summary>
    public sealed class ContractCheck
    {
        public ContractCheckSeverity Severity => throw new NotImplementedException();
        public string Message => throw new NotImplementedException();
        public string Remedy => throw new NotImplementedException();
    }
}

namespace DeltaInterpolator.Unity
{
    /// <summary>Assumed: Runtime/Unity's model asset (contract JSON + graph references).</summary>
    public class InbetweeningModel : ScriptableObject
    {
        /// <summary>Loads the graphs (Sentis CPU in the editor) into a Core inbetweener; the caller disposes it.</summary>
        public Inbetweener CreateInbetweener() => throw new NotImplementedException();

        /// <summary>Every contract check of the asset, in order.</summary>
        public IReadOnlyList<ContractCheck> CheckContract() => throw new NotImplementedException();
    }

    /// <summary>Assumed: Runtime/Unity's component.</summary>
    public class InbetweeningAnimator : MonoBehaviour
    {
        public void RequestTransition(AnimationClip clip, float time, float seconds) => throw new NotImplementedException();

        public event Action TransitionCompleted
        {
            add => throw new NotImplementedException();
            remove => throw new NotImplementedException();
        }
    }
}
