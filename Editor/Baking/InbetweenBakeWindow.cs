#nullable enable
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Unity;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Editor.Baking
{
    /// <summary>
    /// Window → Animation → In-between Baker: fills the gaps between key poses with the model and saves
    /// the result as a new clip (the In-between Fill's "write to a new clip": the same key plan, <see cref="KeyFill.Plan"/>).
    /// the result as a new clip. The keys come from a clip's own keyframes, or from two clips and a
    /// transition point. The baker takes what the component takes: the character's rig as the settings
    /// describe it (<see cref="RigCollector"/>: a humanoid avatar, or a generic rig with a joint map and its
    /// renames), sampled in animation mode (the scene is never written), baked through Core's workflow
    /// (<see cref="CharacterBake"/> → <see cref="InbetweenBake"/>, the component's map), and saved as
    /// muscle curves for a humanoid Animator or transform curves for a generic one. Every decision (which
    /// frames are keys, how poses reach the model and back, which curves a clip gets) is Core code; this
    /// window binds the fields to it.
    /// </summary>
    internal sealed class InbetweenBakeWindow : EditorWindow
    {
        /// <summary>Where the key poses come from.</summary>
        internal enum KeySource
        {
            /// <summary>Every frame on which the clip has a rotation or position key is a key pose.</summary>
            ClipKeyframes,
            /// <summary>The end of one clip and a time in another, with a gap between.</summary>
            TwoClips,
            /// <summary>A key every N (clip frames, model frames or seconds) of a clip keyed on every frame (mocap), by Core's <see cref="KeyPlanner"/> as the CLI's --every.</summary>
            EveryN,
        }

        [SerializeField] private GameObject? _character;
        [SerializeField] private InbetweenerSettings? _settings;
        [SerializeField] private InbetweeningModel? _model;
        [SerializeField] private bool _alsoSlerp;
        [SerializeField] private bool _lockFeet = true;
        [SerializeField] private KeySource _source = KeySource.ClipKeyframes;
        [SerializeField] private AnimationClip? _keyClip;
        [SerializeField] private AnimationClip? _fromClip;
        [SerializeField] private float _fromTime = 1f;
        [SerializeField] private AnimationClip? _toClip;
        [SerializeField] private float _toTime;
        [SerializeField] private int _gapFrames = 15;
        [SerializeField] private int _pastFrames = 10;
        [SerializeField] private float _every = 0.5f;
        [SerializeField] private KeySpacingUnit _everyUnit = KeySpacingUnit.Seconds;
        [NonSerialized] private AnimationClip? _describedClip;
        [NonSerialized] private double _describedRate;
        [NonSerialized] private InbetweeningModel? _ratedModel;
        [NonSerialized] private double _modelRate = ModelContract.DefaultFramesPerSecond;
        [NonSerialized] private string _description = "";

        [MenuItem("Window/Animation/In-between Baker")]
        private static void Open()
        {
            GetWindow<InbetweenBakeWindow>("In-between Baker");
        }

        /// <summary>
        /// The In-between Fill's "write to a new clip": this window, set to <paramref name="clip"/>'s keys (or keys
        /// every N of it) for the same character, settings and model.
        /// </summary>
        internal static void Show(GameObject? character, InbetweenerSettings? settings, InbetweeningModel? model, AnimationClip clip, KeySource keys)
        {
            InbetweenBakeWindow window = GetWindow<InbetweenBakeWindow>("In-between Baker");
            window._character = character;
            window._settings = settings;
            window._model = model;
            window._keyClip = clip;
            window._source = keys;
        }

        private void OnGUI()
        {
            _character = (GameObject?)EditorGUILayout.ObjectField("Character", _character, typeof(GameObject), true);
            _settings = (InbetweenerSettings?)EditorGUILayout.ObjectField("Settings", _settings, typeof(InbetweenerSettings), false);
            _model = (InbetweeningModel?)EditorGUILayout.ObjectField("Model (else the settings')", _model, typeof(InbetweeningModel), false);
            _source = (KeySource)EditorGUILayout.EnumPopup("Keys from", _source);
            if (_source == KeySource.ClipKeyframes)
            {
                _keyClip = (AnimationClip?)EditorGUILayout.ObjectField("Key clip", _keyClip, typeof(AnimationClip), false);
                if (_keyClip != null)
                {
                    // Reading every curve is slow for big clips: once per clip, not per repaint.
                    InbetweeningModel? model = ModelAsset();
                    if (_ratedModel != model) _modelRate = FrameRateOf(model); // parsed once per model, not per repaint
                    _ratedModel = model;
                    double rate = _modelRate;
                    if (_describedClip != _keyClip || _describedRate != rate) _description = DescribeKeys(_keyClip, rate);
                    _describedClip = _keyClip;
                    _describedRate = rate;
                    EditorGUILayout.HelpBox(_description, MessageType.Info);
                }
            }
            else if (_source == KeySource.EveryN)
            {
                _keyClip = (AnimationClip?)EditorGUILayout.ObjectField("Motion clip", _keyClip, typeof(AnimationClip), false);
                _every = EditorGUILayout.FloatField("Key every", _every);
                _everyUnit = (KeySpacingUnit)EditorGUILayout.EnumPopup("Counted in", _everyUnit);
                if (_keyClip != null && EverySpacing() is KeySpacing spacing)
                {
                    InbetweeningModel? model = ModelAsset();
                    if (_ratedModel != model) _modelRate = FrameRateOf(model); // parsed once per model, not per repaint
                    _ratedModel = model;
                    EditorGUILayout.HelpBox(spacing.Describe(1.0 / _keyClip.frameRate, _modelRate), MessageType.Info);
                }
            }
            else
            {
                _fromClip = (AnimationClip?)EditorGUILayout.ObjectField("From clip", _fromClip, typeof(AnimationClip), false);
                _fromTime = EditorGUILayout.FloatField("Leave at (s)", _fromTime);
                _toClip = (AnimationClip?)EditorGUILayout.ObjectField("To clip", _toClip, typeof(AnimationClip), false);
                _toTime = EditorGUILayout.FloatField("Arrive at (s)", _toTime);
                _gapFrames = EditorGUILayout.IntField("Gap (frames)", _gapFrames);
            }

            _pastFrames = EditorGUILayout.IntField("Past keys (frames)", _pastFrames);
            _alsoSlerp = EditorGUILayout.Toggle("Also bake SLERP", _alsoSlerp);
            // As `bake --feet lock` (the CLI's default): planted feet held still on the filled frames, keys untouched.
            _lockFeet = EditorGUILayout.Toggle("Lock planted feet", _lockFeet);
            string? problem = Problem();
            if (problem != null) EditorGUILayout.HelpBox(problem, MessageType.Warning);
            if (GUILayout.Button("Bake…") && problem == null)
            {
                Bake();
            }
        }

        // The whole graph only: a bake decodes every gap at once. The settings' engine, else Sentis,
        // else the first engine registered with InferenceBackends.
        internal static Inbetweener Load(InbetweeningModel model, string backend)
        {
            IInferenceBackendFactory? factory = InferenceBackends.Find(backend) ?? InferenceBackends.Find("Sentis");
            if (factory == null && InferenceBackends.All.Count > 0) factory = InferenceBackends.All[0];
            if (factory == null)
            {
                throw new ModelContractException(model.name, "no inference engine is installed", "install com.unity.ai.inference 2.4.0 or later (Sentis)");
            }

            return ModelAssetGraphs.Load(model, factory, LazyGraphs.None);
        }

        private string? Problem()
        {
            if (_character == null) return "Assign the character (the GameObject with the Animator the clips animate).";
            if (_character.transform.GetComponent<Animator>() == null) return $"{_character.name} has no Animator; assign the GameObject that holds it.";
            if (_settings == null) return "Assign the in-betweener settings (the rig, joint map and renames the component uses).";
            if (ModelAsset() == null) return "Assign a model asset here or in the settings (Assets → Create → Δ-Interpolator → In-betweening Model (shipped default), or In-betweening Model for your own graphs).";
            if (_pastFrames < 1) return "Past keys must be at least 1.";
            if (_source == KeySource.ClipKeyframes) return _keyClip == null ? "Assign the clip whose keyframes are the key poses." : null;
            if (_source == KeySource.EveryN)
            {
                if (_keyClip == null) return "Assign the clip to take key poses from.";
                return EverySpacing() == null ? "'Key every' must be a positive number (whole for frames)." : null;
            }

            if (_fromClip == null || _toClip == null) return "Assign both clips.";
            if (_gapFrames < 1) return "The gap must be at least one frame.";
            if (_fromTime < 0 || _fromTime > _fromClip.length) return $"'Leave at' must lie in the first clip (0 – {_fromClip.length:0.###} s).";
            if (_toTime < 0 || _toTime > _toClip.length) return $"'Arrive at' must lie in the second clip (0 – {_toClip.length:0.###} s).";
            return null;
        }

        private KeySpacing? EverySpacing()
        {
            try
            {
                return new KeySpacing(_every, _everyUnit);
            }
            catch (ArgumentOutOfRangeException)
            {
                return null;
            }
        }

        private InbetweeningModel? ModelAsset() => _model != null ? _model : _settings != null ? _settings.Model : null;

        // Keys are counted at the model's frame rate, which its contract owns (30 when it does not say).
        private static double FrameRateOf(InbetweeningModel? model)
        {
            if (model == null) return ModelContract.DefaultFramesPerSecond;
            try
            {
                return ModelContract.FromJson(model.ContractJson, model.name).FramesPerSecond;
            }
            catch (ModelContractException)
            {
                return ModelContract.DefaultFramesPerSecond; // the bake itself reports the broken contract
            }
        }

        private static string DescribeKeys(AnimationClip clip, double rate)
        {
            ClipKeyFrames keys = ClipKeyReader.Read(ClipSampler.PoseKeyTimes(clip), rate, clip.length);
            var gaps = new List<string>();
            for (int g = 0; g < keys.GapCount; g++) gaps.Add(keys.GapLength(g).ToString(CultureInfo.InvariantCulture));
            string text = $"{keys.Frames.Count} key frames at {rate:0.##} fps; gaps of {(gaps.Count == 0 ? "none" : string.Join(", ", gaps))} frames.";
            if (keys.SnappedKeys > 0) text += $" {keys.SnappedKeys} keys lie between frames and are rounded (up to {keys.LargestSnapFrames:0.##} frame).";
            if (keys.IgnoredKeys > 0) text += $" {keys.IgnoredKeys} keys outside the clip are ignored.";
            return text;
        }

        private void Bake()
        {
            GameObject character = _character!;
            InbetweenerSettings settings = _settings!;
            Animator animator = character.transform.GetComponent<Animator>();
            var progress = new ProgressBar();
            try
            {
                using (Inbetweener inbetweener = Load(ModelAsset()!, settings.Backend))
                {
                    ModelContract contract = inbetweener.Contract;
                    double rate = contract.FramesPerSecond;
                    // The character as the component sees it: the same bones, joint map and renames.
                    CharacterRig rig = RigCollector.Collect(animator, settings, contract.Skeleton, out JointMap jointMap, out Transform[] bones);
                    bool humanoid = settings.RigOf(animator) == CharacterRigKind.Humanoid;

                    CharacterPoseTrack track;
                    string name;
                    if (_source == KeySource.ClipKeyframes)
                    {
                        AnimationClip clip = _keyClip!;
                        // The key frames as the In-between Fill reads them (one Core plan): it refuses a clip without a gap.
                        KeyFillPlan keys = KeyFill.Plan(clip.name, ClipCurves.Read(clip).Curves, clip.length, rate, null, ClipSampler.MuscleProperties());
                        (int min, int max) = contract.TrainingMissingFrames;
                        var outside = new List<int>();
                        for (int i = 1; i < keys.KeyFrames.Count; i++)
                        {
                            int missing = keys.KeyFrames[i] - keys.KeyFrames[i - 1] - 1;
                            if (missing > 0 && max > 0 && (missing < min || missing > max)) outside.Add(missing);
                        }

                        if (outside.Count > 0 && !EditorUtility.DisplayDialog(
                                "Gaps outside the trained range",
                                $"{contract.Source} was trained on gaps of {min}–{max} frames; {clip.name} has gaps of {string.Join(", ", outside)} frames. The model will fill them, but it never saw such gaps: check the result, or move keys.",
                                "Bake anyway",
                                "Cancel"))
                        {
                            return;
                        }

                        track = new CharacterPoseTrack(rig, keys.LastKey + 1, 1.0 / rate);
                        progress.Show("Sampling the key poses…", 0f);
                        using (new AnimationModeScope())
                        {
                            ClipSampler.SampleInto(track, character, bones, clip, keys.KeyFrames, keys.KeyTimes);
                        }

                        name = clip.name + " (in-betweened)";
                    }
                    else if (_source == KeySource.EveryN)
                    {
                        AnimationClip clip = _keyClip!;
                        (int[] frames, double[] times) = KeyPlanner.PlanClip(EverySpacing()!.Value, clip.length, clip.frameRate, rate, contract.TrainingMissingFrames.Min);
                        track = new CharacterPoseTrack(rig, frames[frames.Length - 1] + 1, 1.0 / rate);
                        progress.Show("Sampling the key poses…", 0f);
                        using (new AnimationModeScope())
                        {
                            ClipSampler.SampleInto(track, character, bones, clip, frames, times);
                        }

                        name = clip.name + " (in-betweened)";
                    }
                    else
                    {
                        TransitionKeyPlan plan = TransitionKeyPlan.Create(_fromTime, _toTime, _pastFrames, _gapFrames, rate);
                        (int min, int max) = contract.TrainingMissingFrames;
                        if (max > 0 && (_gapFrames < min || _gapFrames > max) && !EditorUtility.DisplayDialog(
                                "Gap outside the trained range",
                                $"{contract.Source} was trained on gaps of {min}–{max} frames; this gap has {_gapFrames}. The model will fill it, but it never saw such a gap.",
                                "Bake anyway",
                                "Cancel"))
                        {
                            return;
                        }

                        track = new CharacterPoseTrack(rig, plan.FrameCount, 1.0 / rate);
                        progress.Show("Sampling the key poses…", 0f);
                        using (new AnimationModeScope())
                        {
                            ClipSampler.SampleInto(track, character, bones, _fromClip!, Enumerable.Range(0, plan.PastFrames).ToList(), plan.FromTimes);
                            ClipSampler.SampleInto(track, character, bones, _toClip!, new[] { plan.TargetFrame }, new[] { plan.ToTime });
                        }

                        name = _fromClip!.name + " to " + _toClip!.name;
                    }

                    BakeMethod model = BakeMethod.Model(inbetweener, feet: _lockFeet ? new FootLockSettings() : null);
                    model.Settings.PastFrames = _pastFrames;
                    var methods = new List<BakeMethod> { model };
                    if (_alsoSlerp) methods.Add(BakeMethod.Slerp(_lockFeet));
                    BakeRun run = CharacterBake.Run(contract, track, jointMap, methods, progress);
                    // The plan's warnings (keys) and the run's (e.g. foot locking skipped on a rig whose legs cannot be bent).
                    var warnings = new List<string>(run.Methods[0].Plan.Warnings);
                    warnings.AddRange(run.Warnings);
                    if (warnings.Count > 0 && !EditorUtility.DisplayDialog("Check the bake", string.Join("\n", warnings), "Save anyway", "Cancel"))
                    {
                        return;
                    }

                    foreach (MethodBake result in run.Methods)
                    {
                        progress.Show($"Writing the {result.Method.Name} clip…", 0.95f);
                        IReadOnlyList<ClipCurve> curves;
                        if (humanoid)
                        {
                            // The poses go onto the bones to be read as human poses: in animation mode, and put back.
                            using (new AnimationModeScope())
                            {
                                curves = ClipSampler.HumanoidClipCurves(animator, rig, bones, result.OnRig);
                            }
                        }
                        else
                        {
                            curves = CurveBuilder.BuildCharacter(rig, result.OnRig, ClipSampler.Paths(character.transform, bones));
                        }

                        EditorUtility.ClearProgressBar();
                        string clipName = result.Method.Name == "Model" ? name : $"{name} ({result.Method.Name})";
                        ClipWriter.Save(curves, rate, clipName, humanoid ? typeof(Animator) : typeof(Transform));
                    }
                }
            }
            catch (ModelContractException e)
            {
                EditorUtility.DisplayDialog("The model cannot be used", e.Message, "OK");
            }
            catch (JointMapException e)
            {
                EditorUtility.DisplayDialog("The character does not fit the model", e.Message, "OK");
            }
            catch (InvalidOperationException e)
            {
                EditorUtility.DisplayDialog("Cannot bake", e.Message, "OK");
            }
            catch (ArgumentException e)
            {
                EditorUtility.DisplayDialog("Cannot bake", e.Message, "OK");
            }
            finally
            {
                EditorUtility.ClearProgressBar();
            }
        }

        /// <summary>One bar over the whole bake: sampling, then every method's gaps (<see cref="InbetweenBake"/>'s reports, on this thread), then writing.</summary>
        private sealed class ProgressBar : IProgress<StageProgress>
        {
            public void Show(string info, float progress) => EditorUtility.DisplayProgressBar("In-between Baker", info, progress);

            public void Report(StageProgress value) =>
                Show($"{value.Stage}: {value.Completed} of {value.Total} gaps filled", 0.1f + 0.8f * value.Completed / Math.Max(1, value.Total));
        }
    }
}
