#if UNITY_EDITOR
#nullable enable
using System.Collections.Generic;
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

        /// <summary>One entry per frame since the director started.</summary>
        public readonly List<Frame> Frames = new List<Frame>();

        private void LateUpdate()
        {
            if (Director == null) return;
            var frame = new Frame(Director.time, Figures.Length);
            for (int f = 0; f < Figures.Length; f++)
            {
                frame.Position[f] = Figures[f].position;
                frame.Rotation[f] = Figures[f].rotation;
                frame.HipsPosition[f] = Hips[f].position;
            }

            Frames.Add(frame);
        }

        /// <summary>The director's time and, per figure, its object's world position and rotation and its hips' world position.</summary>
        public sealed class Frame
        {
            public Frame(double time, int figures)
            {
                Time = time;
                Position = new Vector3[figures];
                Rotation = new Quaternion[figures];
                HipsPosition = new Vector3[figures];
            }

            public double Time { get; }

            public Vector3[] Position { get; }

            public Quaternion[] Rotation { get; }

            public Vector3[] HipsPosition { get; }
        }
    }
}
#endif
