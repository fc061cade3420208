using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// A game loop of one character whose Animator Controller is a <see cref="StandInController"/> of real CMU clips, run on the
    /// shipped default model (DeltaInterpolator-CMU) on the real ONNX Runtime, the frame driven through <see cref="PlayingCharacter"/>.
    /// It does the glue's part each frame: reads the controller's layers before the frame, puts the controller in a state when the
    /// frame says so (a hand-off's arrival), and samples off-scene the state pose the frame asks for, handed back next frame.
    /// Skips without the model or the CMU data.
    /// </summary>
    public sealed class StandInLoop : IDisposable
    {
        private readonly double _fps;
        private readonly MainThreadScheduler _scheduler;
        private readonly AnimatorLayerState[] _layers = new AnimatorLayerState[4];
        private readonly double[] _sampledRoot = new double[3];
        private readonly double[] _sampledRotations;
        private int _frame;

        /// <summary>Loads the model and clips and builds the controller with <paramref name="build"/> (its first pose is shown before the first frame).</summary>
        public StandInLoop(double fps, Func<StandInClips, StandInController> build, bool lockFeet = false)
        {
            _fps = fps;
            Inbetweener model = OnnxRuntimeInbetweener.Load(DefaultModel(), requireLazy: true);
            _scheduler = new MainThreadScheduler(model);
            ModelContract c = model.Contract;
            Converter = new NamePoseConverter(c.Skeleton, c.UnitScale, c.Skeleton.Names);
            Clips = new StandInClips(c.Skeleton, Converter);
            Controller = build(Clips);
            _sampledRotations = new double[4 * Converter.BoneCount];
            var settings = new PlaybackSettings { BlendInSeconds = 0.1, BlendOutSeconds = 0.2, LockFeet = lockFeet };
            Character = new PlayingCharacter(Converter, _scheduler, settings, Controller.Evaluate);
            Character.Layers = _layers;
            Character.BeforeController = Instructions;
            Player.TransitionCompleted += e => Completions.Add(e);
        }

        /// <summary>
        /// Root motion on from the next frame: the controller keeps the root bone in place and its travel moves the character (standing
        /// at the world's origin, unrotated), by the velocity of each evaluation, applied in the character's frame.
        /// </summary>
        public void PlayWithRootMotion()
        {
            Controller.RootMotion = true;
            Character.PlayWithRootMotion(RootFrame.Identity, Vector3D.Zero, RootVelocityFrame.Local);
            Character.ControllerVelocity = () => new Vector3D(Controller.VelocityX, 0, Controller.VelocityZ);
        }

        /// <summary>The root bone's position in the world (where the character stands, plus the shown root bone in it).</summary>
        public Vector3D RootWorld => Character.Place.PointToParent(new Vector3D(Shown.Root[0], Shown.Root[1], Shown.Root[2]));

        /// <summary>The character's bones ↔ the model's joints (the model's skeleton in Unity's space, metres).</summary>
        public NamePoseConverter Converter { get; }

        /// <summary>The clips the controller's states play.</summary>
        public StandInClips Clips { get; }

        /// <summary>The stand-in Animator Controller.</summary>
        public StandInController Controller { get; }

        /// <summary>The character.</summary>
        public PlayingCharacter Character { get; }

        /// <summary>Its transitions.</summary>
        public TransitionPlayer Player => Character.Player;

        /// <summary>Its neural Animator transitions.</summary>
        public AnimatorTransitions Transitions => Character.Character.Transitions;

        /// <summary>Every completion reported.</summary>
        public List<TransitionCompletion> Completions { get; } = new List<TransitionCompletion>();

        /// <summary>The time of the last frame.</summary>
        public double Time => Character.Time;

        /// <summary>The interval of every frame.</summary>
        public double Step => 1.0 / _fps;

        /// <summary>What the last frame showed.</summary>
        public ArrayPoseStream Shown => Character.Shown;

        /// <summary>The last frame's output.</summary>
        public CharacterFrameOutput Last => Character.LastFrame;

        /// <summary>Changes what the glue read of the layers before a frame (a controller whose report lags), or null.</summary>
        public Action<AnimatorLayerState[]>? AfterRead { get; set; }

        /// <summary>Play states seen in frame outputs, with the frame time they came in.</summary>
        public List<(double Time, StateTarget State)> Plays { get; } = new List<(double, StateTarget)>();

        /// <summary>
        /// One rendered frame at exactly n / fps: the scheduler pumped, the controller's layers read (its last evaluation), the
        /// character's frame, the controller told to play a state when the frame says so, its pose evaluated and blended, and a
        /// state's pose sampled off-scene when the frame asks for one.
        /// </summary>
        public void Frame()
        {
            _scheduler.Pump();
            Character.LayerCount = Controller.Read(_layers);
            AfterRead?.Invoke(_layers);
            _frame++;
            CharacterFrameOutput output = Character.Frame(_frame / _fps - Time);
            if (!output.SampleState) return;
            Controller.SampleOffScene(output.Sample, Math.Max(0, Player.DeferredArrivalTime - Time), _sampledRoot, _sampledRotations);
            Character.Sampled(_sampledRoot, _sampledRotations);
        }

        /// <summary>Frames until <paramref name="time"/>.</summary>
        public void PlayUntil(double time)
        {
            while ((_frame + 1) / _fps <= time + 1e-9) Frame();
        }

        /// <summary>Frames until the decoded network frames are in (the main-thread scheduler decodes when pumped): makes the tests deterministic.</summary>
        public void Decode() => Assert.That(Player.WaitUntilDecoded(20000), Is.True);

        /// <summary>A hand-off into a controller state, from the pose shown.</summary>
        public int RequestState(in StateTarget state, double seconds) => Character.RequestState(state, seconds, Controller);

        public void Dispose() => _scheduler.Dispose();

        /// <summary>The shipped default model, Runtime/Models/DeltaInterpolator-CMU.onnx; skips when absent.</summary>
        public static string DefaultModel()
        {
            string? dir = AppContext.BaseDirectory;
            while (dir != null)
            {
                string candidate = Path.Combine(dir, "Runtime", "Models", "DeltaInterpolator-CMU.onnx");
                if (File.Exists(candidate)) return candidate;
                dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
            }

            Assert.Ignore("Runtime/Models/DeltaInterpolator-CMU.onnx not found; skipping the stand-in controller's frame loops.");
            return "";
        }

        // The glue's part between the character's frame and the controller's evaluation: a hand-off's arrival puts the controller in its state.
        private void Instructions(CharacterFrameOutput output)
        {
            if (!output.PlayState) return;
            Controller.AdvanceTo(Time);
            Controller.Play(output.Play);
            Plays.Add((Time, output.Play));
        }
    }

    /// <summary>The CMU takes the stand-in controller's states play (none of the held-out subjects 02, 09, 13, 38), loaded once per loop.</summary>
    public sealed class StandInClips
    {
        private readonly Core.Skeletons.Skeleton _model;
        private readonly IPoseConverter _converter;
        private readonly Dictionary<string, StandInClip> _loaded = new Dictionary<string, StandInClip>();

        public StandInClips(Core.Skeletons.Skeleton model, IPoseConverter converter)
        {
            _model = model;
            _converter = converter;
        }

        /// <summary>The character's bone names (the model's joints).</summary>
        public IReadOnlyList<string> BoneNames => _model.Names;

        /// <summary>07_01: walk.</summary>
        public StandInClip Walk => Get("07_01.bvh");

        /// <summary>07_04: slow walk.</summary>
        public StandInClip SlowWalk => Get("07_04.bvh");

        /// <summary>07_12: brisk walk.</summary>
        public StandInClip BriskWalk => Get("07_12.bvh");

        /// <summary>06_02: basketball, forward dribble.</summary>
        public StandInClip Dribble => Get("06_02.bvh");

        /// <summary>05_02: dance, expressive arms, pirouette.</summary>
        public StandInClip Dance => Get("05_02.bvh");

        private StandInClip Get(string file)
        {
            if (!_loaded.TryGetValue(file, out StandInClip? clip)) _loaded[file] = clip = new StandInClip(file, _model, _converter);
            return clip;
        }
    }
}
