#nullable enable
using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Unity;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Editor.Baking
{
    /// <summary>
    /// Window → Animation → In-between Baker: fills the gaps between key poses with the model and saves
    /// the result as a new clip. The keys come from a clip's own keyframes, or from two clips and a
    /// transition point. Every decision (which frames are keys, how poses become model space and back,
    /// which curves a clip gets) is Core code (<see cref="ClipKeyReader"/>, <see cref="TransitionKeyPlan"/>,
    /// <see cref="KeyPoseTrack"/>, <see cref="CurveBuilder"/>); this window binds the fields to it.
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
        }

        [SerializeField] private GameObject? _character;
        [SerializeField] private InbetweeningModel? _model;
        [SerializeField] private KeySource _source = KeySource.ClipKeyframes;
        [SerializeField] private AnimationClip? _keyClip;
        [SerializeField] private AnimationClip? _fromClip;
        [SerializeField] private float _fromTime = 1f;
        [SerializeField] private AnimationClip? _toClip;
        [SerializeField] private float _toTime;
        [SerializeField] private int _gapFrames = 15;
        [SerializeField] private int _pastFrames = 10;
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

        private void OnGUI()
        {
            _character = (GameObject?)EditorGUILayout.ObjectField("Character", _character, typeof(GameObject), true);
            _model = (InbetweeningModel?)EditorGUILayout.ObjectField("Model", _model, typeof(InbetweeningModel), false);
            _source = (KeySource)EditorGUILayout.EnumPopup("Keys from", _source);
            if (_source == KeySource.ClipKeyframes)
            {
                _keyClip = (AnimationClip?)EditorGUILayout.ObjectField("Key clip", _keyClip, typeof(AnimationClip), false);
                if (_keyClip != null)
                {
                    // Reading every curve is slow for big clips: once per clip, not per repaint.
                    if (_ratedModel != _model) _modelRate = FrameRateOf(_model); // parsed once per model, not per repaint
                    _ratedModel = _model;
                    double rate = _modelRate;
                    if (_describedClip != _keyClip || _describedRate != rate) _description = DescribeKeys(_keyClip, rate);
                    _describedClip = _keyClip;
                    _describedRate = rate;
                    EditorGUILayout.HelpBox(_description, MessageType.Info);
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
            string? problem = Problem();
            if (problem != null) EditorGUILayout.HelpBox(problem, MessageType.Warning);
            if (GUILayout.Button("Bake…") && problem == null)
            {
                Bake();
            }
        }

        // The whole graph only: a bake decodes every gap at once. Sentis on the CPU when installed,
        // otherwise the first engine registered with InferenceBackends.
        private static Inbetweener Load(InbetweeningModel model)
        {
            IInferenceBackendFactory? factory = InferenceBackends.Find("Sentis");
            if (factory == null && InferenceBackends.All.Count > 0) factory = InferenceBackends.All[0];
            if (factory == null)
            {
                throw new ModelContractException(model.name, "no inference engine is installed", "install com.unity.ai.inference 2.4.0 or later (Sentis)");
            }

            return ModelAssetGraphs.Load(model, factory, LazyGraphs.None);
        }

        private string? Problem()
        {
            if (_character == null) return "Assign the character (the GameObject the clips animate).";
            if (_model == null) return "Assign a model asset (Create → Delta Interpolator → Model).";
            if (_pastFrames < 1) return "Past keys must be at least 1.";
            if (_source == KeySource.ClipKeyframes) return _keyClip == null ? "Assign the clip whose keyframes are the key poses." : null;
            if (_fromClip == null || _toClip == null) return "Assign both clips.";
            if (_gapFrames < 1) return "The gap must be at least one frame.";
            if (_fromTime < 0 || _fromTime > _fromClip.length) return $"'Leave at' must lie in the first clip (0 – {_fromClip.length:0.###} s).";
            if (_toTime < 0 || _toTime > _toClip.length) return $"'Arrive at' must lie in the second clip (0 – {_toClip.length:0.###} s).";
            return null;
        }

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
            try
            {
                using (Inbetweener inbetweener = Load(_model!))
                {
                    ModelContract contract = inbetweener.Contract;
                    Skeleton skeleton = contract.Skeleton;
                    double rate = contract.FramesPerSecond;
                    string?[] paths = BonePaths.Resolve(skeleton.Names, ClipSampler.TransformPaths(character.transform), out List<string> missing);
                    if (missing.Count > 0)
                    {
                        EditorUtility.DisplayDialog("Bones missing", $"{character.name} has no bone named {string.Join(", ", missing)}. The model needs every joint of its skeleton ({contract.Source}); use a character with the model's skeleton.", "OK");
                        return;
                    }

                    var bones = new Transform[paths.Length];
                    for (int j = 0; j < bones.Length; j++) bones[j] = paths[j]!.Length == 0 ? character.transform : character.transform.Find(paths[j]!);

                    KeyPoseTrack track;
                    string name;
                    if (_source == KeySource.ClipKeyframes)
                    {
                        AnimationClip clip = _keyClip!;
                        ClipKeyFrames keys = ClipKeyReader.Read(ClipSampler.PoseKeyTimes(clip), rate, clip.length);
                        if (keys.GapCount == 0)
                        {
                            EditorUtility.DisplayDialog("Nothing to fill", $"{clip.name} has no gap between its keys at {rate:0.##} fps.", "OK");
                            return;
                        }

                        (int min, int max) = contract.TrainingMissingFrames;
                        IReadOnlyList<int> outside = keys.GapsOutside(min, max);
                        if (outside.Count > 0 && !EditorUtility.DisplayDialog(
                                "Gaps outside the trained range",
                                $"{contract.Source} was trained on gaps of {min}–{max} frames; {clip.name} has gaps of {string.Join(", ", outside)} frames. The model will fill them, but it never saw such gaps: check the result, or move keys.",
                                "Bake anyway",
                                "Cancel"))
                        {
                            return;
                        }

                        track = new KeyPoseTrack(skeleton, keys.FrameCount, rate, contract.UnitScale);
                        ClipSampler.SampleInto(track, character, bones, clip, keys.Frames, keys.Frames.Select(f => f / rate).ToList());
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

                        track = new KeyPoseTrack(skeleton, plan.FrameCount, rate, contract.UnitScale);
                        ClipSampler.SampleInto(track, character, bones, _fromClip!, Enumerable.Range(0, plan.PastFrames).ToList(), plan.FromTimes);
                        ClipSampler.SampleInto(track, character, bones, _toClip!, new[] { plan.TargetFrame }, new[] { plan.ToTime });
                        name = _fromClip!.name + " to " + _toClip!.name;
                    }

                    EditorUtility.DisplayProgressBar("In-between Baker", "Running the model…", 0.5f);
                    BakeSettings settings = BakeSettings.ForModel(contract);
                    settings.PastFrames = _pastFrames;
                    var baker = new ClipBaker(inbetweener, settings);
                    BakePlan bakePlan = baker.Plan(track.Motion.FrameCount, track.KeyFrames.ToArray());
                    if (bakePlan.Warnings.Count > 0 && !EditorUtility.DisplayDialog("Check the keys", string.Join("\n", bakePlan.Warnings), "Bake anyway", "Cancel"))
                    {
                        return;
                    }

                    MotionClip baked = baker.Bake(track.Motion, bakePlan);
                    EditorUtility.ClearProgressBar();
                    ClipWriter.Save(CurveBuilder.Build(baked, paths, contract.UnitScale), rate, name);
                }
            }
            catch (ModelContractException e)
            {
                EditorUtility.DisplayDialog("The model cannot be used", e.Message, "OK");
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
    }
}
