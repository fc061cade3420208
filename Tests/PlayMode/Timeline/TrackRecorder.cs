#if UNITY_EDITOR
#nullable enable
using System;
using System.Collections.Generic;
using DeltaInterpolator.Tests.Blends;
using UnityEngine;
using UnityEngine.Playables;

namespace DeltaInterpolator.Tests.PlayMode.Timeline
{
    /// <summary>
    /// Records, once per frame after the frame's animation (<c>LateUpdate</c> runs after the directors' animation
    /// evaluation and the Animators' root motion), the director's time and where each figure and its hips stand, so
    /// that every recorded position belongs to the recorded time (a coroutine's <c>yield return null</c> resumes before
    /// the frame's animation and would pair this frame's time with the last frame's pose).
    /// </summary>
    public sealed class TrackRecorder : MonoBehaviour
    {
        /// <summary>The director whose time is recorded.</summary>
        public PlayableDirector? Director;

        /// <summary>The figures' objects (the Animators' transforms: where root motion puts them).</summary>
        public Transform[] Figures = new Transform[0];

        /// <summary>Each figure's hips (its root bone), in the same order.</summary>
        public Transform[] Hips = new Transform[0];

        /// <summary>One entry per frame since <see cref="Director"/> was set.</summary>
        public readonly List<TrackMotionFrame> Frames = new List<TrackMotionFrame>();

        private void LateUpdate()
        {
            if (Director == null) return;
            var places = new FigurePlace[Figures.Length];
            for (int f = 0; f < Figures.Length; f++)
            {
                Vector3 at = Figures[f].position, hips = Hips[f].position;
                // The facing about +Y: the angle of the rotated +Z from +Z toward +X.
                Vector3 forward = Figures[f].rotation * new Vector3(0f, 0f, 1f);
                places[f] = new FigurePlace(at.x, at.z, Math.Atan2(forward.x, forward.z), hips.x, hips.y, hips.z);
            }

            Frames.Add(new TrackMotionFrame(Director.time, places));
        }
    }
}
#endif
