#if UNITY_EDITOR
#nullable enable
using System;
using System.Collections;
using System.Collections.Generic;
using DeltaInterpolator.Editor.Importers;
using DeltaInterpolator.Tests.Blends;
using DeltaInterpolator.Timeline;
using static DeltaInterpolator.Tests.Blends.TrackMotionChecks;
using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.Playables;
using UnityEngine.TestTools;
using UnityEngine.Timeline;
using Object = UnityEngine.Object;

namespace DeltaInterpolator.Tests.PlayMode.Timeline
{
    /// <summary>
    /// What the engine does with the Neural Animation Track's root motion, checked in the real engine (Test Runner →
    /// PlayMode; steps in <c>Documentation~/unity-verification.md</c>). The package's BVH importer turns the Demo sample's
    /// walk and jumps into clips with root motion; one Timeline, built in memory, holds a Neural Animation Track with
    /// Walk, a 0.6 s gap, Walk again, a 0.3 s blend into Jump — bound to a figure (turned 90°) whose Animator applies root
    /// motion — and two tracks with one clip each (Walk where the second Walk starts, Jump where it starts), bound to two
    /// twins, which play the clips' own root motion with no span. Every frame records where the figures and their hips
    /// stand (<see cref="TrackRecorder"/>), and the test asserts:
    /// (a) through the gap the character keeps walking: no stop (the Animator applying the job's velocity) and no jump;
    /// (b) where the gap and the blend start and end the hips' world position does not jump against the clips' own steps;
    /// (c) after each span the character moves exactly as its twin does, from where the span left it (scene offsets);
    /// (d) nothing is logged. The track's times, the checks and their bounds are <see cref="TrackMotionChecks"/>'s (engine-free,
    /// shown there to fail on recordings of the faults they are for). Those tracks are set to Apply Scene Offsets; a third test
    /// checks Apply Transform Offsets, the track's default (<see cref="TransformOffsetChecks"/>).
    /// </summary>
    /// <remarks>
    /// Editor only (it imports the sample's <c>.bvh</c> files into a temporary folder under Assets, removed afterwards) and
    /// only with Timeline installed (its assembly is constrained as <c>DeltaInterpolator.Timeline</c> is). The Unity check
    /// compiles it against stubs proven against Unity 6000.0, com.unity.timeline 1.8.10 and com.unity.test-framework
    /// 1.4.6, but cannot run it.
    /// </remarks>
    public sealed class NeuralTrackRootMotionVerification
    {
        private const string WalkFile = "cmu_09_12_walk_navigate.bvh"; // frame 0 is a T-pose: the reference pose
        private const string JumpsFile = "cmu_01_01_jumps_turn.bvh";
        private const string RootBone = "Hips";                         // the CMU skeleton's root joint

        private const double Timeout = 10.0;   // seconds of play past the track's end before the test gives up

        /// <summary>The figure with a generic avatar whose root motion node is the hips, and clips of transform curves only.</summary>
        [UnityTest]
        public IEnumerator AGenericFigureWalksThroughAGapAndABlendWithoutStoppingOrPoppingAndPlaysOnFromWhereTheyLeftIt() => Run(humanoid: false);

        /// <summary>The same with the humanoid avatar and clips the importer makes (the engine extracts the body's centre of mass).</summary>
        [UnityTest]
        public IEnumerator AHumanoidFigureWalksThroughAGapAndABlendWithoutStoppingOrPoppingAndPlaysOnFromWhereTheyLeftIt() => Run(humanoid: true);

        /// <summary>
        /// Transform offsets (the track's default): a generic figure started elsewhere stands where the track's and each clip's
        /// offsets place it when each Walk starts (e), and after the playhead is set back it stands where it stood at the same
        /// times before (f); nothing is logged. Checks and bounds: <see cref="TransformOffsetChecks"/>.
        /// </summary>
        [UnityTest]
        public IEnumerator AGenericFigureOnATransformOffsetTrackStandsWhereTheOffsetsPlaceItEvenAfterAJumpBack()
        {
            var rig = Rig.Import(humanoid: false);
            try
            {
                GameObject figure = rig.Figure(new Vector3(5f, 0f, 5f), 200f); // anywhere: the track places it
                var timeline = ScriptableObject.CreateInstance<TimelineAsset>();
                rig.Keep(timeline);
                NeuralAnimationTrack track = rig.Track(timeline, "Transform offsets", TrackOffset.ApplyTransformOffsets);
                track.Position = new Vector3((float)TransformOffsetChecks.Track.X, 0f, (float)TransformOffsetChecks.Track.Z);
                track.EulerAngles = new Vector3(0f, (float)TransformOffsetChecks.Track.YawDegrees, 0f);
                Offset(rig.Place(track, rig.Walk, 0.0, TransformOffsetChecks.FirstEnd), TransformOffsetChecks.FirstWalk);
                Offset(rig.Place(track, rig.Walk, TransformOffsetChecks.SecondStart, TransformOffsetChecks.SecondEnd - TransformOffsetChecks.SecondStart), TransformOffsetChecks.SecondWalk);

                var directorObject = new GameObject("Director");
                rig.Keep(directorObject);
                var director = directorObject.AddComponent<PlayableDirector>();
                director.playableAsset = timeline;
                director.SetGenericBinding(track, figure.GetComponent<Animator>());
                var recorder = directorObject.AddComponent<TrackRecorder>();
                recorder.Figures = new[] { figure.transform };
                recorder.Hips = new[] { rig.Hips(figure) };
                recorder.Director = director;
                director.Play();

                double started = Time.timeAsDouble;
                bool jumped = false;
                while (true)
                {
                    Assert.That(Time.timeAsDouble - started, Is.LessThan(2 * TransformOffsetChecks.SecondEnd + Timeout), "the timeline plays past the jump and to the first Walk's end again");
                    if (!jumped && director.time >= TransformOffsetChecks.JumpAt)
                    {
                        director.time = TransformOffsetChecks.JumpBackTo;
                        jumped = true;
                    }
                    else if (jumped && director.time >= TransformOffsetChecks.FirstEnd + 0.1) break;
                    yield return null;
                }

                // The walk's own speed, from the first pass (the character's ground speed where the first Walk plays).
                List<TrackMotionFrame> frames = recorder.Frames;
                double fastest = 0;
                for (int i = 1; i < frames.Count && frames[i].Time >= frames[i - 1].Time && frames[i].Time <= TransformOffsetChecks.FirstEnd; i++)
                {
                    double dt = frames[i].Time - frames[i - 1].Time;
                    if (frames[i - 1].Time < WalkFrom || dt <= 1e-6) continue;
                    FigurePlace a = frames[i - 1].Figures[0], b = frames[i].Figures[0];
                    fastest = Math.Max(fastest, Math.Sqrt((b.X - a.X) * (b.X - a.X) + (b.Z - a.Z) * (b.Z - a.Z)) / dt);
                }

                var failures = new List<string>();
                TransformOffsetChecks.StartsAtTheOffset(frames, 0.0, TransformOffsetChecks.Placed(TransformOffsetChecks.FirstWalk), StepMargin * fastest, "the first Walk", failures, TestContext.Out);
                TransformOffsetChecks.StartsAtTheOffset(frames, TransformOffsetChecks.SecondStart, TransformOffsetChecks.Placed(TransformOffsetChecks.SecondWalk), StepMargin * fastest, "the second Walk", failures, TestContext.Out);
                TransformOffsetChecks.StandsWhereItStoodAtTheSameTime(frames, failures, TestContext.Out);
                foreach (string failure in failures) TestContext.Out.WriteLine(failure);
                LogAssert.NoUnexpectedReceived();
                Assert.That(fastest, Is.GreaterThan(0.1), "the walk moves the character (the track sees root motion and the Animator applies the job's velocity)");
                Assert.That(failures, Is.Empty, $"transform offsets: {failures.Count} comparisons of (e)-(f) failed (all in the test's output); the first: {(failures.Count > 0 ? failures[0] : "")}");
            }
            finally
            {
                rig.Dispose();
            }
        }

        private static void Offset(TimelineClip clip, (double X, double Z, double YawDegrees) offset)
        {
            var asset = (AnimationPlayableAsset)clip.asset;
            asset.position = new Vector3((float)offset.X, 0f, (float)offset.Z);
            asset.eulerAngles = new Vector3(0f, (float)offset.YawDegrees, 0f);
        }

        private static IEnumerator Run(bool humanoid)
        {
            var rig = Rig.Import(humanoid);
            try
            {
                var figures = new[]
                {
                    rig.Figure(new Vector3(0f, 0f, 0f), 90f),   // facing +X: the stream's velocity is in the character's frame
                    rig.Figure(new Vector3(0f, 0f, -4f), 0f),
                    rig.Figure(new Vector3(0f, 0f, 4f), 180f),
                };
                foreach (AnimationClip clip in new[] { rig.Walk, rig.Jump })
                {
                    // Timeline's own test (AnimationPlayableAsset.HasRootTransforms, less the internal hasRootMotion), as the track reads it.
                    Assert.That(!clip.empty && (clip.hasGenericRootTransform || clip.hasMotionCurves || clip.hasRootCurves), Is.True,
                        $"{clip.name}: the track sees root motion in the clip (else its spans carry no root travel: timeline.md, 'Which one the track uses')");
                }

                var timeline = ScriptableObject.CreateInstance<TimelineAsset>();
                rig.Keep(timeline);
                // Scene offsets: each clip plays on from where the character stands, so (c) compares the character's moves with its twins'.
                var neural = rig.Track(timeline, "Neural blends", TrackOffset.ApplySceneOffsets);
                rig.Place(neural, rig.Walk, 0.0, GapStart);
                rig.Place(neural, rig.Walk, GapEnd, BlendEnd - GapEnd);
                rig.Place(neural, rig.Jump, BlendStart, End - BlendStart);
                var walkAlone = rig.Track(timeline, "Walk alone", TrackOffset.ApplySceneOffsets);
                rig.Place(walkAlone, rig.Walk, GapEnd, BlendEnd - GapEnd);
                var jumpAlone = rig.Track(timeline, "Jump alone", TrackOffset.ApplySceneOffsets);
                rig.Place(jumpAlone, rig.Jump, BlendStart, End - BlendStart);

                var directorObject = new GameObject("Director");
                rig.Keep(directorObject);
                var director = directorObject.AddComponent<PlayableDirector>();
                director.playableAsset = timeline;
                director.SetGenericBinding(neural, figures[Character].GetComponent<Animator>());
                director.SetGenericBinding(walkAlone, figures[WalkTwin].GetComponent<Animator>());
                director.SetGenericBinding(jumpAlone, figures[JumpTwin].GetComponent<Animator>());
                var recorder = directorObject.AddComponent<TrackRecorder>();
                recorder.Figures = new[] { figures[0].transform, figures[1].transform, figures[2].transform };
                recorder.Hips = new[] { rig.Hips(figures[0]), rig.Hips(figures[1]), rig.Hips(figures[2]) };
                recorder.Director = director;
                director.Play();

                double started = Time.timeAsDouble;
                while (!TrackMotionChecks.PlayedToTheEnd(recorder.Frames))
                {
                    Assert.That(Time.timeAsDouble - started, Is.LessThan(End + Timeout), "the timeline plays to its end");
                    yield return null;
                }

                foreach (GameObject figure in figures)
                {
                    Assert.That(figure.GetComponent<Animator>().hasRootMotion, Is.True, $"{figure.name}'s rig has root motion (a generic avatar's root motion node is {RootBone})");
                }

                List<TrackMotionFrame> frames = TrackMotionChecks.Played(recorder.Frames);
                var failures = new List<string>();
                TrackMotionChecks.KeepsMovingThroughTheGap(frames, failures, TestContext.Out);
                TrackMotionChecks.HipsDoNotJumpWhereSpansStartOrEnd(frames, failures, TestContext.Out);
                TrackMotionChecks.PlaysOnFromWhereTheSpanLeftIt(frames, WalkTwin, GapEnd + Settle, BlendStart, "the second Walk, after the gap", failures, TestContext.Out);
                TrackMotionChecks.PlaysOnFromWhereTheSpanLeftIt(frames, JumpTwin, BlendEnd + Settle, End, "Jump, after the blend", failures, TestContext.Out);
                foreach (string failure in failures) TestContext.Out.WriteLine(failure);
                // (d) first: a warning from the track (a crossfade fallback, an out-of-range span) says why (a)-(c) would fail.
                LogAssert.NoUnexpectedReceived();
                Assert.That(failures, Is.Empty, $"{(humanoid ? "humanoid" : "generic")}: {failures.Count} comparisons of (a)-(c) failed (all in the test's output); the first: {(failures.Count > 0 ? failures[0] : "")}");
            }
            finally
            {
                rig.Dispose();
            }
        }

        /// <summary>The imported figure, its avatar and clips, the settings and everything made, in a temporary folder.</summary>
        private sealed class Rig : DemoFigureImport
        {
            private InbetweenerSettings _settings = null!;

            private Rig()
                : base("DeltaInterpolator Track Verification")
            {
            }

            public AnimationClip Walk { get; private set; } = null!;

            public AnimationClip Jump { get; private set; } = null!;

            /// <summary>
            /// Imports the Demo's walk and jumps with the package's BVH importer into Assets/DeltaInterpolator Track Verification,
            /// cut as the Demo cuts them (Walk: frames 172–304, looping; Jump: 156–348) plus the walk's T-pose frame. Generic:
            /// an avatar whose root motion node is the hips and the clips' transform curves alone; humanoid: as imported.
            /// </summary>
            public static Rig Import(bool humanoid)
            {
                var rig = new Rig();
                Dictionary<string, AnimationClip> walk = rig.ImportBvh(WalkFile, out GameObject figure, out Avatar avatar, Cut("Walk", 172, 304, true), Cut("TPose", 0, 1, false));
                Dictionary<string, AnimationClip> jumps = rig.ImportBvh(JumpsFile, out _, out _, Cut("Jump", 156, 348, false));
                Assert.That(avatar.isHuman, Is.True, "the CMU figure imports as a humanoid");
                rig.FigureAsset = figure;
                AnimationClip tPose = walk["TPose"];
                if (humanoid)
                {
                    rig.FigureAvatar = avatar;
                    rig.Walk = walk["Walk"];
                    rig.Jump = jumps["Jump"];
                }
                else
                {
                    // The avatar built from the figure in its rest pose, with the hips as its root motion node.
                    GameObject rest = Object.Instantiate(figure);
                    rig.FigureAvatar = AvatarBuilder.BuildGenericAvatar(rest, RootBone);
                    Object.DestroyImmediate(rest);
                    rig.Keep(rig.FigureAvatar);
                    Assert.That(rig.FigureAvatar.isValid && !rig.FigureAvatar.isHuman, Is.True, "a generic avatar is built from the figure");
                    rig.Walk = rig.Keep(TransformCurves(walk["Walk"]));
                    rig.Jump = rig.Keep(TransformCurves(jumps["Jump"]));
                    tPose = rig.Keep(TransformCurves(tPose));
                }

                rig._settings = rig.DemoSettings(humanoid ? CharacterRigKind.Humanoid : CharacterRigKind.Generic, tPose);
                return rig;
            }

            /// <summary>An instance of the figure at <paramref name="position"/>, turned <paramref name="yaw"/>° about +Y, its Animator applying root motion.</summary>
            public GameObject Figure(Vector3 position, float yaw) => Figure(position, yaw, null, applyRootMotion: true);

            public Transform Hips(GameObject figure)
            {
                Transform hips = figure.transform.Find(RootBone);
                Assert.That(hips != null, Is.True, $"{figure.name} has its root joint {RootBone}");
                return hips!;
            }

            /// <summary>A Neural Animation Track on <paramref name="timeline"/> with this rig's settings, placing the clips by <paramref name="offsets"/>.</summary>
            public NeuralAnimationTrack Track(TimelineAsset timeline, string name, TrackOffset offsets)
            {
                NeuralAnimationTrack track = Keep(timeline.CreateTrack<NeuralAnimationTrack>(null!, name));
                track.Settings = _settings;
                track.TrackOffset = offsets;
                return track;
            }

            /// <summary><paramref name="clip"/> on <paramref name="track"/> from <paramref name="start"/> for <paramref name="duration"/> seconds, from its first frame.</summary>
            public TimelineClip Place(TrackAsset track, AnimationClip clip, double start, double duration)
            {
                TimelineClip placed = track.CreateClip<AnimationPlayableAsset>();
                Keep(placed.asset);
                ((AnimationPlayableAsset)placed.asset).clip = clip;
                placed.start = start;
                placed.duration = duration;
                placed.clipIn = 0.0;
                placed.displayName = clip.name;
                return placed;
            }

            private static BvhClipSettings Cut(string name, int first, int last, bool loop) => new BvhClipSettings { name = name, firstFrame = first, lastFrame = last, loop = loop };

            // A generic clip: the imported clip's transform curves (the joints' own), without the humanoid body and muscle curves.
            private static AnimationClip TransformCurves(AnimationClip source)
            {
                var clip = new AnimationClip { name = source.name, frameRate = source.frameRate };
                foreach (EditorCurveBinding binding in AnimationUtility.GetCurveBindings(source))
                {
                    if (binding.type == typeof(Transform)) AnimationUtility.SetEditorCurve(clip, binding, AnimationUtility.GetEditorCurve(source, binding));
                }

                AnimationUtility.SetAnimationClipSettings(clip, AnimationUtility.GetAnimationClipSettings(source));
                return clip;
            }
        }
    }
}
#endif
