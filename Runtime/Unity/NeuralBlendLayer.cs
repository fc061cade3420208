using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Rotations;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Playables;
using CoreJointMap = DeltaInterpolator.Core.Retargeting.JointMap;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The neural blends of one track of clips on one character: what a Timeline track (the optional
    /// <c>DeltaInterpolator.Timeline</c> assembly) builds when its graph is built. <see cref="Build"/> lays the clips out
    /// (Core's <see cref="TrackLayout"/>) and gets every blend and gap from the shared <see cref="BlendCache"/> — baked
    /// once, through the editor baker's Core path, with the model and rig the settings give the component —
    /// and <see cref="Evaluate"/> shows, each frame, the cached pose at the playhead (no network run, no allocation).
    /// </summary>
    /// <remarks>
    /// The cache is shared by every track in the process, so a graph rebuilt without a change (Timeline rebuilds on
    /// every edit, on entering Play mode, on scrubbing after one) finds its blends again; the loaded models are shared the
    /// same way and live as long as the domain (released when it unloads).
    /// </remarks>
    public sealed class NeuralBlendLayer : IDisposable
    {
        private static readonly BlendCache s_cache = new BlendCache(256);
        private static readonly Dictionary<(InbetweeningModel, string), Inbetweener> s_models = new Dictionary<(InbetweeningModel, string), Inbetweener>();

        static NeuralBlendLayer()
        {
            // The engines' workers hold native memory: release them when the Editor reloads scripts or the player quits.
            AppDomain.CurrentDomain.DomainUnload += (sender, e) =>
            {
                foreach (Inbetweener network in s_models.Values) network.Dispose();
                s_models.Clear();
                s_cache.Clear();
            };
        }

        private readonly Animator _animator;
        private readonly CharacterRig _rig;
        private readonly Transform[] _bones;
        private readonly BlendModel _model;
        private readonly PoseBlendBuffers _buffers;
        private readonly double[] _sample;
        // The root motion the job puts on the stream this frame (one element).
        private NativeArray<TrackRootDrive> _root = new NativeArray<TrackRootDrive>(1, Allocator.Persistent);
        private TrackLayout _layout = TrackLayout.Create(Array.Empty<TrackClipTiming>());
        private BlendFrames?[] _blends = Array.Empty<BlendFrames?>();
        private SpanRootTravel?[] _travel = Array.Empty<SpanRootTravel?>();
        // With transform offsets: where the character stands at any time (null otherwise: the clips' root motion plays relatively).
        private TrackRootPath? _path;
        private static readonly HashSet<string> s_said = new HashSet<string>();

        private NeuralBlendLayer(Animator animator, CharacterRig rig, Transform[] bones, BlendModel model)
        {
            _animator = animator;
            _rig = rig;
            _bones = bones;
            _model = model;
            _buffers = new PoseBlendBuffers(animator, bones);
            _sample = new double[3 + 4 * bones.Length];
        }

        /// <summary>
        /// The layer of <paramref name="animator"/>'s character as <paramref name="settings"/> describe it (model, engine,
        /// rig kind, joint map: what <see cref="MotionInbetweener"/> uses).
        /// </summary>
        /// <exception cref="ArgumentNullException">No animator or settings.</exception>
        /// <exception cref="InvalidOperationException">The settings have no model, the engine is not installed, or the rig cannot be collected (what to do said).</exception>
        /// <exception cref="Core.Retargeting.JointMapException">The rig cannot be mapped onto the model (bones named).</exception>
        public static NeuralBlendLayer Create(Animator animator, InbetweenerSettings settings)
        {
            if (animator == null) throw new ArgumentNullException(nameof(animator));
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            InbetweeningModel model = settings.Model != null ? settings.Model : throw new InvalidOperationException($"the settings {settings.name} have no model; assign an imported in-betweening model");
            IInferenceBackendFactory factory = InferenceBackends.Find(settings.Backend)
                ?? throw new InvalidOperationException($"the inference engine '{settings.Backend}' is not installed; install its package (Sentis: com.unity.ai.inference 2.4.0 or later) or choose another in {settings.name}");
            if (!s_models.TryGetValue((model, factory.Name), out Inbetweener? network))
            {
                network = ModelAssetGraphs.Load(model, factory, LazyGraphs.None);
                s_models[(model, factory.Name)] = network;
            }

            CharacterRig rig = RigCollector.Collect(animator, settings, network.Contract.Skeleton, out CoreJointMap jointMap, out Transform[] bones);
            // Refuses a rig the model cannot take now, with the bones named, rather than at the first blend.
            rig.CreatePoseConverter(network.Contract.Skeleton, jointMap);
            return new NeuralBlendLayer(animator, rig, bones, new BlendModel(network.Contract, network, jointMap));
        }

        /// <summary>The clips' layout of the last <see cref="Build"/>.</summary>
        public TrackLayout Layout => _layout;

        /// <summary>Each span's frames from the last <see cref="Build"/> (null where the track has a clip without animation).</summary>
        public IReadOnlyList<BlendFrames?> Blends => _blends;

        /// <summary>
        /// Lays out <paramref name="timings"/> and gets each blend and gap between <paramref name="clips"/> (same order) from
        /// the cache, baking the ones it lacks; a span the model cannot fill, or an extrapolation a gap overrides, is said
        /// once in the Console. With <paramref name="rootTravel"/> a blend or gap carries root motion (<see cref="SpanRootPlan"/>):
        /// a blend's target is placed where Timeline's mix of its clips' root motion leaves the character, the clips weighted
        /// by the second clip's mix-in curve (<paramref name="mixIn"/>, Timeline's <c>TimelineClip.mixInCurve</c>; null or a
        /// null entry: Timeline's default ease). With <see cref="RootTravelMode.TransformOffset"/> the track places the
        /// character itself, every frame, where <see cref="TrackRootPath"/> has it: under <paramref name="trackOffset"/>, each clip
        /// as <paramref name="placements"/> says (null: every clip moving the root, at no offset, from its first frame); each
        /// span lands on its second clip's placement. The bones and the character's own transform are put back as they were.
        /// </summary>
        /// <exception cref="ArgumentException">Not one clip (or mix-in curve, or placement) per timing (<c>clips</c>, <c>mixIn</c> or <c>placements</c> named), or two clips at one start.</exception>
        public void Build(IReadOnlyList<TrackClipTiming> timings, IReadOnlyList<AnimationClip?> clips, RootTravelMode rootTravel = RootTravelMode.None,
            IReadOnlyList<AnimationCurve?>? mixIn = null, RootPlacement trackOffset = default, IReadOnlyList<ClipPlacement>? placements = null)
        {
            if (timings == null) throw new ArgumentNullException(nameof(timings));
            if (clips == null) throw new ArgumentNullException(nameof(clips));
            if (clips.Count != timings.Count) throw new ArgumentException($"{clips.Count} clips for {timings.Count} timings; expected one clip per timing", nameof(clips));
            if (mixIn != null && mixIn.Count != timings.Count) throw new ArgumentException($"{mixIn.Count} mix-in curves for {timings.Count} timings; expected one per timing", nameof(mixIn));
            if (placements != null && placements.Count != timings.Count) throw new ArgumentException($"{placements.Count} placements for {timings.Count} timings; expected one per timing", nameof(placements));
            _layout = TrackLayout.Create(timings);
            _blends = new BlendFrames?[_layout.Spans.Count];
            _travel = new SpanRootTravel?[_layout.Spans.Count];
            _path = null;
            double[] saved = UnityPoses.Read(_bones, 0);
            // Sampling a clip that keys the character's own transform moves it: put back with the bones.
            Transform character = _animator.transform;
            Vector3 savedPosition = character.localPosition;
            Quaternion savedRotation = character.localRotation;
            try
            {
                if (rootTravel == RootTravelMode.TransformOffset) _path = Path(timings, clips, trackOffset, placements);
                for (int s = 0; s < _blends.Length; s++)
                {
                    TrackSpan span = _layout.Spans[s];
                    AnimationClip? from = clips[span.From], to = clips[span.To];
                    if (from == null || to == null) continue;
                    if (span.ExtrapolationOverridden != null && s_said.Add($"{_animator.GetInstanceID()}|{from.name}|{to.name}|{span.Start}|{span.ExtrapolationOverridden}"))
                    {
                        Debug.LogWarning($"{_animator.name}: gap {from.name} → {to.name} at {span.Start:0.###}–{span.End:0.###} s: {span.ExtrapolationOverridden}", _animator);
                    }

                    var fromPoses = new AnimationClipPoses(from, _animator.gameObject, _bones);
                    var toPoses = new AnimationClipPoses(to, _animator.gameObject, _bones);
                    Action<string> warn = warning => Debug.LogWarning($"{_animator.name}: {warning}", _animator);
                    if (rootTravel != RootTravelMode.None)
                    {
                        // Timeline weighs the second clip by its mix-in curve at the fraction of the overlap, clamped to 0..1 (TimelineClip.EvaluateMixIn).
                        AnimationCurve? curve = mixIn?[span.To];
                        Func<double, double>? weight = curve == null ? null : u => Math.Clamp((double)curve.Evaluate((float)u), 0.0, 1.0);
                        // Transform offsets: the span lands where the second clip places the character (relative to where the first leaves it).
                        RootPlacement arrival = _path != null ? _path.Arrival(s) : RootPlacement.Identity;
                        _travel[s] = SpanRootPlan.Bake(s_cache, _model, _rig, span, fromPoses, toPoses, rootTravel, arrival, out BlendFrames frames, warn, weight);
                        _path?.Travel(s, _travel[s]!, weight);
                        _blends[s] = frames;
                    }
                    else
                    {
                        _blends[s] = s_cache.Get(_model, _rig, span, fromPoses, toPoses, warn);
                    }
                }
            }
            finally
            {
                character.localPosition = savedPosition;
                character.localRotation = savedRotation;
                UnityPoses.Apply(_bones, 0, saved.AsSpan(0, 3), saved.AsSpan(3));
            }
        }

        /// <summary>
        /// Where the character stands at any time with transform offsets: each clip's root motion sampled once (as the spans'
        /// keys are) and placed by its offset; a clip that does not move the root, or has no animation, stands at the track's offset.
        /// </summary>
        private TrackRootPath Path(IReadOnlyList<TrackClipTiming> timings, IReadOnlyList<AnimationClip?> clips, RootPlacement trackOffset, IReadOnlyList<ClipPlacement>? placements)
        {
            var paths = new ClipRootPath[timings.Count];
            for (int i = 0; i < paths.Length; i++)
            {
                ClipPlacement placement = placements != null ? placements[i] : new ClipPlacement(RootPlacement.Identity, true, true);
                AnimationClip? clip = clips[i];
                paths[i] = clip != null && placement.MovesRoot
                    ? ClipRootPath.Sample(new AnimationClipPoses(clip, _animator.gameObject, _bones), _rig, timings[i].AnimationLength, timings[i].Loops, placement.Offset, placement.RemoveStartOffset)
                    : ClipRootPath.Still(RootPlacement.Identity);
            }

            return new TrackRootPath(_layout, trackOffset, paths);
        }

        /// <summary>The mixer: an animation job with <paramref name="inputCount"/> inputs, mixed by their weights (Timeline sets them) before the blend pose is laid over.</summary>
        public AnimationScriptPlayable CreatePlayable(PlayableGraph graph, int inputCount)
        {
            var job = new TrackBlendJob { Bones = _buffers.Bones, Pose = _buffers.Pose, Shown = _buffers.Shown, Weight = _buffers.Weight, Root = _root };
            AnimationScriptPlayable playable = AnimationScriptPlayable.Create(graph, job, inputCount);
            playable.SetProcessInputs(true);
            return playable;
        }

        /// <summary>
        /// What the mixer shows at track time <paramref name="time"/>: inside a blend or gap the model fills, its cached
        /// pose (read between model frames as a bake is read back) — in a blend or gap with root travel, the pose over the root
        /// placed there and the root's velocity for the job to hand the Animator; elsewhere the clips as Timeline mixes them.
        /// </summary>
        public void Evaluate(double time)
        {
            TrackMoment moment = _layout.Locate(time);
            BlendFrames? frames = moment.Kind == TrackMomentKind.Span ? _blends[moment.Span] : null;
            _root[0] = default;
            if (_path != null) Place(moment, time);
            if (frames == null || !frames.Sample(moment.Fraction, _sample.AsSpan(0, 3), _sample.AsSpan(3)))
            {
                _buffers.Weight[0] = 0;
                return;
            }

            SpanRootTravel? travel = _travel[moment.Span];
            if (travel != null && travel.Mode != RootTravelMode.None)
            {
                travel.InPlace(_rig, moment.Fraction, _sample.AsSpan(0, 3), _sample.AsSpan(3, 4));
                // Scene offsets: the travel's own velocity (with transform offsets Place has put the character on the path).
                if (_path == null)
                {
                    travel.Velocity(moment.Fraction, _layout.Spans[moment.Span].Duration, out double x, out double z, out double yawRate);
                    _root[0] = new TrackRootDrive { Kind = TrackRootDrive.Source.SpanTravel, VelocityX = x, VelocityZ = z, YawRate = yawRate };
                }
            }

            _sample.AsSpan().CopyTo(_buffers.Pose.AsSpan());
            _buffers.Weight[0] = 1;
        }

        /// <summary>
        /// Transform offsets: where the character stands now — the Animator's transform in its parent's space, the track's
        /// space (Timeline's offsets are in the parent's) — and where the track has it at <paramref name="time"/>, for the job
        /// to move it there in this frame whatever happened before (<see cref="RootVelocity"/>, with the frame's delta time);
        /// outside Play mode the character is put there at once.
        /// </summary>
        private void Place(TrackMoment moment, double time)
        {
            Transform character = _animator.transform;
            Vector3 p = character.localPosition;
            Quaternion q = character.localRotation;
            var rotation = new QuaternionD(q.w, q.x, q.y, q.z);
            var current = RootPlacement.OfTransform(p.x, p.z, rotation);
            RootPlacement target = _path!.At(moment, time);
            if (!current.IsFinite) return;
            if (!Application.isPlaying)
            {
                // An Editor preview may evaluate with no delta time (a paused scrub), and Timeline previews an Animation Track in
                // absolute motion: put the character there directly, its height, pitch and roll kept (the track registers the
                // transform with the preview, which gives it back when the preview ends), and leave the job nothing to move.
                QuaternionD turned = RootPlacement.TurnedTo(rotation, target.Yaw);
                character.localPosition = new Vector3((float)target.X, p.y, (float)target.Z);
                character.localRotation = new Quaternion((float)turned.X, (float)turned.Y, (float)turned.Z, (float)turned.W);
                current = target;
            }

            _root[0] = new TrackRootDrive { Kind = TrackRootDrive.Source.Placement, Current = current, Target = target };
        }

        /// <summary>Frees the job's buffers (the graph owns the playable).</summary>
        public void Dispose()
        {
            _buffers.Dispose();
            if (_root.IsCreated) _root.Dispose();
        }
    }
}
