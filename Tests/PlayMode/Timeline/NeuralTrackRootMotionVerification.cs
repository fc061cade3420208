#if UNITY_EDITOR
#nullable enable
using System;
using System.Collections;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Editor.Importers;
using DeltaInterpolator.Editor.Models;
using DeltaInterpolator.Timeline;
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
    /// (d) nothing is logged.
    /// </summary>
    /// <remarks>
    /// Editor only (it imports the sample's <c>.bvh</c> files into a temporary folder under Assets, removed afterwards) and
    /// only with Timeline installed (its assembly is constrained as <c>DeltaInterpolator.Timeline</c> is). The Unity check
    /// compiles it against stubs proven against Unity 6000.0, com.unity.timeline 1.8.10 and com.unity.test-framework
    /// 1.4.6, but cannot run it.
    /// </remarks>
    public sealed class NeuralTrackRootMotionVerification
    {
        private const string Package = "com.deltainterpolator.inbetweening";
        private const string WalkFile = "cmu_09_12_walk_navigate.bvh"; // frame 0 is a T-pose: the reference pose
        private const string JumpsFile = "cmu_01_01_jumps_turn.bvh";
        private const string RootBone = "Hips";                         // the CMU skeleton's root joint

        // The track, in seconds: the Demo's cuts (one 1.11 s gait cycle of Walk, 1.6 s of Jump) placed within their length.
        private const double GapStart = 1.1;   // Walk plays 0–1.1 s
        private const double GapEnd = 1.7;     // a 0.6 s gap (17 missing frames at the model's 30 fps); Walk again 1.7–2.8 s
        private const double BlendStart = 2.5; // Jump 2.5–4.1 s: a 0.3 s blend (8 missing frames) over the second Walk's end
        private const double BlendEnd = 2.8;
        private const double End = 4.1;
        private const double Settle = 0.05;    // seconds after a clip starts before its frames count as the clip's own
        private const double Timeout = 10.0;   // seconds of play past the track's end before the test gives up
        // The clips' own speeds are read from WalkFrom on: the first frame after Play can be long (the spans are baked
        // inside Play, and Unity caps that frame's delta time at 1/3 s), and a step over it is no walk frame.
        private const double WalkFrom = 0.35;

        // (a), (b): no step across or inside a span is more than 1.5 × the largest the clips make at the same frame length.
        // The model's first step in this gap continues the walk at 0.612 against its 0.580 per frame (GapRootTravelTests)
        // and a blend's step changes by at most 0.148 of 0.62 per model frame inside (BlendRootTravelTests): a quarter at
        // most; the rest is for game frames falling unevenly on the model's 30 fps frames. A pop (the travel applied twice,
        // a placement snapping back, the travel left in the hips) is a whole offset — tens of centimetres — in one frame.
        private const double StepMargin = 1.5;

        // (a): no frame inside the gap moves the character slower than 0.3 × the walk's mean speed. A gap with no root travel
        // (the track seeing no root motion in the clips, or the Animator ignoring the stream's velocity) stands still: 0.
        // 0.3, not nearer 1: the model's path between two walk frames may slow where its feet change over.
        private const double KeepsMoving = 0.3;

        // (b): 1 cm on top of the hips' bound: a span is read at the model's 30 fps between two frames and the clips at their
        // 120 fps keys, so the hips' first step into or out of a span may differ from the clips' by a sub-frame's motion
        // (about 1 cm at a walk's 1.4 m/s); a visible pop is larger.
        private const double HipsSlack = 0.01;

        // (c): after a span the character and its twin play the same clip at the same times, so their moves from a common
        // frame are the same up to float rounding at their different places: 1 cm and 1 % of the distance moved, 1° of turn.
        // Not continuing from where the span left it (snapping to the clip's or the timeline's origin) or carrying the
        // span's velocity on is off by the whole travel.
        private const double FollowSlack = 0.01;
        private const double FollowShare = 0.01;
        private const double FollowDegrees = 1.0;

        private const int Character = 0, WalkTwin = 1, JumpTwin = 2;

        /// <summary>The figure with a generic avatar whose root motion node is the hips, and clips of transform curves only.</summary>
        [UnityTest]
        public IEnumerator AGenericFigureWalksThroughAGapAndABlendWithoutStoppingOrPoppingAndPlaysOnFromWhereTheyLeftIt() => Run(humanoid: false);

        /// <summary>The same with the humanoid avatar and clips the importer makes (the engine extracts the body's centre of mass).</summary>
        [UnityTest]
        public IEnumerator AHumanoidFigureWalksThroughAGapAndABlendWithoutStoppingOrPoppingAndPlaysOnFromWhereTheyLeftIt() => Run(humanoid: true);

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
                var neural = rig.Track(timeline, "Neural blends");
                rig.Place(neural, rig.Walk, 0.0, GapStart);
                rig.Place(neural, rig.Walk, GapEnd, BlendEnd - GapEnd);
                rig.Place(neural, rig.Jump, BlendStart, End - BlendStart);
                var walkAlone = rig.Track(timeline, "Walk alone");
                rig.Place(walkAlone, rig.Walk, GapEnd, BlendEnd - GapEnd);
                var jumpAlone = rig.Track(timeline, "Jump alone");
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
                while (!PlayedToTheEnd(recorder.Frames))
                {
                    Assert.That(Time.timeAsDouble - started, Is.LessThan(End + Timeout), "the timeline plays to its end");
                    yield return null;
                }

                foreach (GameObject figure in figures)
                {
                    Assert.That(figure.GetComponent<Animator>().hasRootMotion, Is.True, $"{figure.name}'s rig has root motion (a generic avatar's root motion node is {RootBone})");
                }

                List<TrackRecorder.Frame> frames = Played(recorder.Frames);
                KeepsWalkingThroughTheGap(frames);
                HipsDoNotJumpWhereSpansStartOrEnd(frames);
                PlaysOnFromWhereTheSpanLeftIt(frames, WalkTwin, GapEnd + Settle, BlendStart, "the second Walk, after the gap");
                PlaysOnFromWhereTheSpanLeftIt(frames, JumpTwin, BlendEnd + Settle, End, "Jump, after the blend");
                LogAssert.NoUnexpectedReceived();
            }
            finally
            {
                rig.Dispose();
            }
        }

        // (a) Per frame touching the gap the character moves at most StepMargin × the walk's fastest frame, and per frame
        // inside it at least KeepsMoving × the walk's mean; the blend's frames at most StepMargin × the clips' fastest.
        private static void KeepsWalkingThroughTheGap(List<TrackRecorder.Frame> frames)
        {
            List<double> walk = Speeds(frames, Character, hips: false, (WalkFrom, GapStart), (GapEnd + Settle, BlendStart));
            List<double> jump = Speeds(frames, Character, hips: false, (BlendEnd + Settle, End));
            double walkMax = Max(walk), walkMean = Mean(walk), clipsMax = Math.Max(walkMax, Max(jump));
            TestContext.Out.WriteLine($"character's ground speed: walk mean {walkMean:F3} m/s, max {walkMax:F3}; jump max {Max(jump):F3}");
            double slowest = double.MaxValue, fastest = 0, fastestInBlend = 0;
            for (int i = 1; i < frames.Count; i++)
            {
                double t0 = frames[i - 1].Time, t1 = frames[i].Time;
                if (t1 - t0 <= 1e-6) continue;
                double speed = Step(frames, i, Character, hips: false) / (t1 - t0);
                if (t1 > GapStart && t0 < GapEnd)
                {
                    fastest = Math.Max(fastest, speed);
                    Assert.That(speed, Is.LessThanOrEqualTo(StepMargin * walkMax), $"(a) the character's step at {t1:F3} s in the gap: no jump (walk's fastest {walkMax:F3} m/s)");
                    if (t0 >= GapStart && t1 <= GapEnd)
                    {
                        slowest = Math.Min(slowest, speed);
                        Assert.That(speed, Is.GreaterThanOrEqualTo(KeepsMoving * walkMean), $"(a) the character keeps moving at {t1:F3} s in the gap (walk's mean {walkMean:F3} m/s): the Animator applies the track's root velocity");
                    }
                }

                if (t1 > BlendStart && t0 < BlendEnd)
                {
                    fastestInBlend = Math.Max(fastestInBlend, speed);
                    Assert.That(speed, Is.LessThanOrEqualTo(StepMargin * clipsMax), $"(a) the character's step at {t1:F3} s in the blend: no jump (the clips' fastest {clipsMax:F3} m/s)");
                }
            }

            Assert.That(slowest, Is.LessThan(double.MaxValue), "frames inside the gap were recorded");
            TestContext.Out.WriteLine($"(a) in the gap: slowest {slowest:F3} m/s, fastest {fastest:F3}; in the blend: fastest {fastestInBlend:F3}");
        }

        // (b) The frames that cross a span's start or end (and the next) move the hips at most StepMargin × the clips' fastest
        // hips at that frame's length, plus HipsSlack.
        private static void HipsDoNotJumpWhereSpansStartOrEnd(List<TrackRecorder.Frame> frames)
        {
            double walk = Max(Speeds(frames, Character, hips: true, (WalkFrom, GapStart), (GapEnd + Settle, BlendStart)));
            double both = Math.Max(walk, Max(Speeds(frames, Character, hips: true, (BlendEnd + Settle, End))));
            foreach ((double at, double fastest, string what) in new[] { (GapStart, walk, "the gap's start"), (GapEnd, walk, "the gap's end"), (BlendStart, both, "the blend's start"), (BlendEnd, both, "the blend's end") })
            {
                for (int i = 1; i < frames.Count; i++)
                {
                    if (!(frames[i - 1].Time < at && frames[i].Time >= at)) continue;
                    for (int k = i; k <= i + 1 && k < frames.Count; k++)
                    {
                        double dt = frames[k].Time - frames[k - 1].Time;
                        double step = Step(frames, k, Character, hips: true);
                        double bound = StepMargin * fastest * dt + HipsSlack;
                        TestContext.Out.WriteLine($"(b) {what}: the hips moved {step:F4} m in the frame to {frames[k].Time:F3} s (bound {bound:F4})");
                        Assert.That(step, Is.LessThanOrEqualTo(bound), $"(b) the hips do not jump at {what} (frame to {frames[k].Time:F3} s; the clips' hips at most {fastest:F3} m/s)");
                    }
                }
            }
        }

        // (c) From the first frame Settle after the span, the character's move in its own frame then is its twin's, frame by frame.
        private static void PlaysOnFromWhereTheSpanLeftIt(List<TrackRecorder.Frame> frames, int twin, double from, double to, string what)
        {
            int r = frames.FindIndex(f => f.Time >= from);
            Assert.That(r, Is.GreaterThanOrEqualTo(0), $"(c) frames of {what} were recorded");
            double worst = 0, worstTurn = 0;
            for (int i = r + 1; i < frames.Count && frames[i].Time <= to; i++)
            {
                Vector3 mine = Moved(frames, r, i, Character), theirs = Moved(frames, r, i, twin);
                double off = Math.Sqrt((mine.x - theirs.x) * (mine.x - theirs.x) + (mine.z - theirs.z) * (mine.z - theirs.z));
                double distance = Math.Sqrt(theirs.x * theirs.x + theirs.z * theirs.z);
                double turn = Math.Abs(Wrap(mine.y - theirs.y)) * 180.0 / Math.PI;
                worst = Math.Max(worst, off);
                worstTurn = Math.Max(worstTurn, turn);
                Assert.That(off, Is.LessThanOrEqualTo(FollowSlack + FollowShare * distance), $"(c) {what}: at {frames[i].Time:F3} s the character has moved as the clip alone moves its twin (twin moved {distance:F3} m)");
                Assert.That(turn, Is.LessThanOrEqualTo(FollowDegrees), $"(c) {what}: at {frames[i].Time:F3} s the character has turned as its twin");
            }

            TestContext.Out.WriteLine($"(c) {what}: at most {worst:F4} m and {worstTurn:F3}° from the twin's own move");
        }

        // Near the track's end, or past it: the director holding its last time, or stopped or wrapped (its time going back).
        private static bool PlayedToTheEnd(List<TrackRecorder.Frame> recorded)
        {
            int n = recorded.Count;
            return n > 0 && (recorded[n - 1].Time >= End - 0.1 || (n > 1 && recorded[n - 1].Time < recorded[n - 2].Time));
        }

        // The frames until the director stopped or wrapped (its time going back).
        private static List<TrackRecorder.Frame> Played(List<TrackRecorder.Frame> recorded)
        {
            var played = new List<TrackRecorder.Frame>();
            foreach (TrackRecorder.Frame f in recorded)
            {
                if (played.Count > 0 && f.Time < played[played.Count - 1].Time) break;
                played.Add(f);
            }

            return played;
        }

        // Ground speeds (m/s) of a figure (or its hips, in 3-D) over the frames wholly inside the given stretches of track time.
        private static List<double> Speeds(List<TrackRecorder.Frame> frames, int figure, bool hips, params (double From, double To)[] stretches)
        {
            var speeds = new List<double>();
            for (int i = 1; i < frames.Count; i++)
            {
                double t0 = frames[i - 1].Time, t1 = frames[i].Time;
                if (t1 - t0 <= 1e-6) continue;
                foreach ((double from, double to) in stretches)
                {
                    if (t0 >= from && t1 <= to) speeds.Add(Step(frames, i, figure, hips) / (t1 - t0));
                }
            }

            Assert.That(speeds.Count, Is.GreaterThanOrEqualTo(5), "enough frames of the clips alone were recorded to measure their speed");
            return speeds;
        }

        // How far a figure's object moved over the ground, or its hips in space, from frame i - 1 to frame i.
        private static double Step(List<TrackRecorder.Frame> frames, int i, int figure, bool hips)
        {
            Vector3 a = hips ? frames[i - 1].HipsPosition[figure] : frames[i - 1].Position[figure];
            Vector3 b = hips ? frames[i].HipsPosition[figure] : frames[i].Position[figure];
            double dy = hips ? b.y - a.y : 0.0;
            return Math.Sqrt((b.x - a.x) * (b.x - a.x) + dy * dy + (b.z - a.z) * (b.z - a.z));
        }

        // A figure's move from frame r to frame i in its own frame at r: (sideways, turn in radians, forward).
        private static Vector3 Moved(List<TrackRecorder.Frame> frames, int r, int i, int figure)
        {
            double yaw = Yaw(frames[r].Rotation[figure]);
            Vector3 d = frames[i].Position[figure] - frames[r].Position[figure];
            double cos = Math.Cos(yaw), sin = Math.Sin(yaw);
            return new Vector3((float)(cos * d.x - sin * d.z), (float)Wrap(Yaw(frames[i].Rotation[figure]) - yaw), (float)(sin * d.x + cos * d.z));
        }

        // The facing about +Y: the angle of the rotated +Z from +Z toward +X.
        private static double Yaw(Quaternion q)
        {
            Vector3 forward = q * new Vector3(0f, 0f, 1f);
            return Math.Atan2(forward.x, forward.z);
        }

        private static double Wrap(double angle)
        {
            while (angle > Math.PI) angle -= 2 * Math.PI;
            while (angle <= -Math.PI) angle += 2 * Math.PI;
            return angle;
        }

        private static double Max(List<double> values)
        {
            double max = 0;
            foreach (double v in values) max = Math.Max(max, v);
            return max;
        }

        private static double Mean(List<double> values)
        {
            double sum = 0;
            foreach (double v in values) sum += v;
            return sum / values.Count;
        }

        /// <summary>The imported figure, its avatar and clips, the settings and everything made, in a temporary folder.</summary>
        private sealed class Rig : IDisposable
        {
            private readonly List<Object> _created = new List<Object>();
            private string _folder = "";
            private GameObject _figure = null!;
            private Avatar _avatar = null!;
            private InbetweenerSettings _settings = null!;

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
                rig._folder = AssetDatabase.GUIDToAssetPath(AssetDatabase.CreateFolder("Assets", "DeltaInterpolator Track Verification"));
                Dictionary<string, AnimationClip> walk = rig.ImportBvh(WalkFile, out GameObject figure, out Avatar avatar, Cut("Walk", 172, 304, true), Cut("TPose", 0, 1, false));
                Dictionary<string, AnimationClip> jumps = rig.ImportBvh(JumpsFile, out _, out _, Cut("Jump", 156, 348, false));
                Assert.That(avatar.isHuman, Is.True, "the CMU figure imports as a humanoid");
                rig._figure = figure;
                AnimationClip tPose = walk["TPose"];
                if (humanoid)
                {
                    rig._avatar = avatar;
                    rig.Walk = walk["Walk"];
                    rig.Jump = jumps["Jump"];
                }
                else
                {
                    // The avatar built from the figure in its rest pose, with the hips as its root motion node.
                    GameObject rest = Object.Instantiate(figure);
                    rig._avatar = AvatarBuilder.BuildGenericAvatar(rest, RootBone);
                    Object.DestroyImmediate(rest);
                    rig.Keep(rig._avatar);
                    Assert.That(rig._avatar.isValid && !rig._avatar.isHuman, Is.True, "a generic avatar is built from the figure");
                    rig.Walk = rig.Keep(TransformCurves(walk["Walk"]));
                    rig.Jump = rig.Keep(TransformCurves(jumps["Jump"]));
                    tPose = rig.Keep(TransformCurves(tPose));
                }

                rig._settings = rig.Keep(Settings(rig._folder, humanoid, tPose));
                return rig;
            }

            /// <summary>An instance of the figure at <paramref name="position"/>, turned <paramref name="yaw"/>° about +Y, its Animator applying root motion.</summary>
            public GameObject Figure(Vector3 position, float yaw)
            {
                GameObject go = Keep(Object.Instantiate(_figure));
                go.transform.SetPositionAndRotation(position, Quaternion.Euler(0f, yaw, 0f));
                Animator animator = go.GetComponent<Animator>();
                if (animator == null) animator = go.AddComponent<Animator>();
                animator.avatar = _avatar;
                animator.runtimeAnimatorController = null!;
                animator.applyRootMotion = true;
                return go;
            }

            public Transform Hips(GameObject figure)
            {
                Transform hips = figure.transform.Find(RootBone);
                Assert.That(hips != null, Is.True, $"{figure.name} has its root joint {RootBone}");
                return hips!;
            }

            /// <summary>A Neural Animation Track on <paramref name="timeline"/> with this rig's settings.</summary>
            public NeuralAnimationTrack Track(TimelineAsset timeline, string name)
            {
                NeuralAnimationTrack track = Keep(timeline.CreateTrack<NeuralAnimationTrack>(null!, name));
                track.Settings = _settings;
                return track;
            }

            /// <summary><paramref name="clip"/> on <paramref name="track"/> from <paramref name="start"/> for <paramref name="duration"/> seconds, from its first frame.</summary>
            public void Place(TrackAsset track, AnimationClip clip, double start, double duration)
            {
                TimelineClip placed = track.CreateClip<AnimationPlayableAsset>();
                Keep(placed.asset);
                ((AnimationPlayableAsset)placed.asset).clip = clip;
                placed.start = start;
                placed.duration = duration;
                placed.clipIn = 0.0;
                placed.displayName = clip.name;
            }

            public T Keep<T>(T made) where T : Object
            {
                _created.Add(made);
                return made;
            }

            public void Dispose()
            {
                foreach (Object o in _created) if (o != null) Object.DestroyImmediate(o);
                if (_folder.Length > 0) AssetDatabase.DeleteAsset(_folder);
            }

            private Dictionary<string, AnimationClip> ImportBvh(string file, out GameObject figure, out Avatar avatar, params BvhClipSettings[] cuts)
            {
                string path = _folder + "/" + file;
                File.Copy(Path.GetFullPath("Packages/" + Package + "/Samples~/Demo/" + file), Path.GetFullPath(path));
                AssetDatabase.ImportAsset(path);
                var importer = AssetImporter.GetAtPath(path) as BvhImporter;
                Assert.That(importer != null, Is.True, path + " is imported by the package's BVH importer");
                importer!.clips = cuts;
                importer.SaveAndReimport();
                GameObject? found = AssetDatabase.LoadAssetAtPath<GameObject>(path);
                Assert.That(found != null, Is.True, path + " is imported as a figure");
                figure = found!;
                avatar = null!;
                var clips = new Dictionary<string, AnimationClip>();
                foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(path))
                {
                    if (o is AnimationClip c) clips[c.name] = c;
                    if (o is Avatar a) avatar = a;
                }

                foreach (BvhClipSettings cut in cuts) Assert.That(clips.ContainsKey(cut.name), Is.True, $"{path} has the clip {cut.name}");
                Assert.That(avatar != null, Is.True, path + " has an avatar");
                return clips;
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

            // The Demo's settings: the shipped model, the rig kind, CMU joint names, the walk's T-pose frame as reference.
            private static InbetweenerSettings Settings(string folder, bool humanoid, AnimationClip tPose)
            {
                var settings = ScriptableObject.CreateInstance<InbetweenerSettings>();
                var s = new SerializedObject(settings);
                s.FindProperty("model").objectReferenceValue = ShippedModelAssets.Create(folder + "/Model.asset");
                s.FindProperty("rig").enumValueIndex = (int)(humanoid ? CharacterRigKind.Humanoid : CharacterRigKind.Generic);
                s.FindProperty("jointMap").enumValueIndex = (int)BuiltInJointMap.Cmu;
                s.FindProperty("referencePose").enumValueIndex = (int)ReferencePoseSource.ClipFrame;
                s.FindProperty("referenceClip").objectReferenceValue = tPose;
                s.FindProperty("referenceClipTime").floatValue = 0f;
                s.ApplyModifiedPropertiesWithoutUndo();
                return settings;
            }
        }
    }
}
#endif
