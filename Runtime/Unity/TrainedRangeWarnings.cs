using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// A request outside the ranges the model was trained on runs, with one Console warning per distinct length
    /// (requests repeat every frame in some games: one warning is enough).
    /// </summary>
    internal sealed class TrainedRangeWarnings
    {
        private readonly HashSet<int> _warnedLengths = new HashSet<int>();

        public void Warn(TransitionPlayer player, float seconds, UnityEngine.Object context)
        {
            int key = (int)Math.Round(seconds * player.FrameRate);
            if (_warnedLengths.Contains(key)) return;
            foreach (ModelCheck check in player.CheckRequest(seconds))
            {
                if (check.Severity != CheckSeverity.Warning) continue;
                _warnedLengths.Add(key);
                Debug.LogWarning($"{context.name}: {check.Message}; {check.Remedy}", context);
            }
        }
    }
}
