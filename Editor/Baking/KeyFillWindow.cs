#nullable enable
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Unity;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Editor.Baking
{
    /// <summary>
    /// Window → Animation → In-between Fill: fills the gaps between the animator's keys in the clip being keyed (the
    /// Animation window's clip), or only those inside a frame range, with the model. <b>Preview</b> computes the fill
    /// and scrubs it on the character in animation mode before anything is written; <b>Fill</b> records one Undo step
    /// (<see cref="Undo.RegisterCompleteObjectUndo(UnityEngine.Object, string)"/>) and writes the filled keys with
    /// <see cref="AnimationUtility.SetEditorCurves"/>. "A new clip" hands the same clip to the In-between Baker, which
    /// writes the in-betweens to a new clip (and plans keys every N frames). Every decision is Core's
    /// (<see cref="KeyFill"/>, <see cref="KeyFillBake"/>, <see cref="CharacterBake"/>); this window binds fields to it.
    /// </summary>
    internal sealed class KeyFillWindow : EditorWindow
    {
        /// <summary>Where the in-betweens go.</summary>
        internal enum Destination
        {
            /// <summary>Into the clip's own curves, as keys between the animator's (one Undo step).</summary>
            ThisClip,
            /// <summary>A new clip, written by the In-between Baker from this clip's keys or keys every N.</summary>
            NewClip,
        }

        /// <summary>The keys the In-between Baker takes for a new clip.</summary>
        internal enum NewClipKeys
        {
            /// <summary>The clip's own keys: the same key plan as the fill.</summary>
            ClipKeys,
            /// <summary>A key every N (clip frames, model frames or seconds) of a clip keyed on every frame, by the one key planner.</summary>
            EveryN,
        }

        [SerializeField] private GameObject? _character;
        [SerializeField] private InbetweenerSettings? _settings;
        [SerializeField] private InbetweeningModel? _model;
        [SerializeField] private AnimationClip? _clip;
        [SerializeField] private bool _lockFeet = true;
        [SerializeField] private bool _useRange;
        [SerializeField] private int _rangeStart;
        [SerializeField] private int _rangeEnd = 30;
        [SerializeField] private Destination _destination = Destination.ThisClip;
        [SerializeField] private NewClipKeys _newClipKeys = NewClipKeys.ClipKeys;
        [NonSerialized] private KeyFillEdit? _edit;
        [NonSerialized] private ClipCurves? _read;
        [NonSerialized] private AnimationClip? _previewClip;
        [NonSerialized] private float _previewTime;
        // Where the preview shows: the character it was published on (its Motion Inbetweener's preview layer), and
        // whether the Animation window shows it (else this window samples it in animation mode at its own slider).
        [NonSerialized] private GameObject? _publishedOn;
        [NonSerialized] private bool _inAnimationWindow;
        [NonSerialized] private string _report = "";
        [NonSerialized] private (UnityEngine.Object? Clip, UnityEngine.Object? Character, UnityEngine.Object? Settings, UnityEngine.Object? Model, bool UseRange, int Start, int End, bool LockFeet) _computedFor;

        [MenuItem("Window/Animation/In-between Fill")]
        private static void Open()
        {
            GetWindow<KeyFillWindow>("In-between Fill");
        }

        private void OnDisable() => StopPreview();

        private void OnGUI()
        {
            _character = (GameObject?)EditorGUILayout.ObjectField("Character", _character, typeof(GameObject), true);
            _settings = (InbetweenerSettings?)EditorGUILayout.ObjectField("Settings", _settings, typeof(InbetweenerSettings), false);
            _model = (InbetweeningModel?)EditorGUILayout.ObjectField("Model (else the settings')", _model, typeof(InbetweeningModel), false);
            _clip = (AnimationClip?)EditorGUILayout.ObjectField("Clip", _clip, typeof(AnimationClip), false);
            if (GUILayout.Button("Take the Animation window's clip and the selection"))
            {
                TakeAnimationWindow();
            }

            _destination = (Destination)EditorGUILayout.EnumPopup("Write to", _destination);
            if (_destination == Destination.NewClip)
            {
                _newClipKeys = (NewClipKeys)EditorGUILayout.EnumPopup("Keys from", _newClipKeys);
                if (GUILayout.Button("Open in the In-between Baker") && _clip != null)
                {
                    InbetweenBakeWindow.Show(_character, _settings, _model, _clip, _newClipKeys == NewClipKeys.EveryN ? InbetweenBakeWindow.KeySource.EveryN : InbetweenBakeWindow.KeySource.ClipKeyframes);
                }

                return;
            }

            // The Animation window's key selection is not public API: the range is asked for here, in the clip's frames.
            _useRange = EditorGUILayout.Toggle("Only a frame range", _useRange);
            if (_useRange)
            {
                _rangeStart = EditorGUILayout.IntField("First frame", _rangeStart);
                _rangeEnd = EditorGUILayout.IntField("Last frame", _rangeEnd);
            }

            _lockFeet = EditorGUILayout.Toggle("Lock planted feet", _lockFeet);
            // A fill computed for other inputs is neither previewed nor written: computed again on the next button.
            if (_edit != null && !_computedFor.Equals(Inputs())) Forget();
            string? problem = Problem();
            if (problem != null)
            {
                EditorGUILayout.HelpBox(problem, MessageType.Warning);
                return;
            }

            if (_report.Length > 0) EditorGUILayout.HelpBox(_report, MessageType.Info);
            if (_previewClip == null)
            {
                if (GUILayout.Button("Preview")) StartPreview();
            }
            else if (_inAnimationWindow)
            {
                EditorGUILayout.HelpBox("The Animation window shows the fill over the clip (and Timeline, where it plays this clip on the character): scrub its playhead. Nothing is written yet.", MessageType.None);
                if (GUILayout.Button("Stop preview")) StopPreview();
            }
            else
            {
                float end = _previewClip.length;
                float time = EditorGUILayout.Slider("Preview time (s)", _previewTime, 0f, end);
                if (time != _previewTime) Sample(time);
                if (GUILayout.Button("Stop preview")) StopPreview();
            }

            if (GUILayout.Button("Fill")) Fill();
        }

        private void TakeAnimationWindow()
        {
            // Only an open Animation window: GetWindow would open one, with no clip in it.
            if (!HasOpenInstances<AnimationWindow>())
            {
                EditorUtility.DisplayDialog("No Animation window", "Open Window → Animation → Animation and select the character whose clip you are keying.", "OK");
                return;
            }

            AnimationWindow window = GetWindow<AnimationWindow>(false, null, false);
            if (window.animationClip != null) _clip = window.animationClip;
            // The character is the selection's nearest Animator above it (the Animation window animates that one).
            GameObject? selected = Selection.activeGameObject;
            for (Transform? t = selected != null ? selected.transform : null; t != null; t = t.parent)
            {
                if (t.GetComponent<Animator>() == null) continue;
                _character = t.gameObject;
                break;
            }

            Forget();
        }

        private string? Problem()
        {
            if (_clip == null) return "Assign the clip to fill (or take the Animation window's).";
            if (_character == null) return "Assign the character (the GameObject with the Animator the clip animates).";
            if (_character.transform.GetComponent<Animator>() == null) return $"{_character.name} has no Animator; assign the GameObject that holds it.";
            if (_settings == null) return "Assign the in-betweener settings (the rig, joint map and renames the component uses).";
            if (ModelAsset() == null) return "Assign a model asset here or in the settings (Assets → Create → Δ-Interpolator → In-betweening Model (shipped default)).";
            return null;
        }

        private (UnityEngine.Object?, UnityEngine.Object?, UnityEngine.Object?, UnityEngine.Object?, bool, int, int, bool) Inputs() =>
            (_clip, _character, _settings, ModelAsset(), _useRange, _rangeStart, _rangeEnd, _lockFeet);

        private InbetweeningModel? ModelAsset() => _model != null ? _model : _settings != null ? _settings.Model : null;

        /// <summary>The clip read and the fill computed (Core's), or null after a dialog said why not.</summary>
        private KeyFillEdit? Compute()
        {
            AnimationClip clip = _clip!;
            GameObject character = _character!;
            InbetweenerSettings settings = _settings!;
            Animator animator = character.transform.GetComponent<Animator>();
            try
            {
                EditorUtility.DisplayProgressBar("In-between Fill", "Filling the gaps…", 0.2f);
                using (Inbetweener inbetweener = InbetweenBakeWindow.Load(ModelAsset()!, settings.Backend))
                {
                    ModelContract contract = inbetweener.Contract;
                    double rate = contract.FramesPerSecond;
                    ClipCurves read = ClipCurves.Read(clip);
                    FillRange? range = _useRange ? new FillRange(_rangeStart / (double)clip.frameRate, _rangeEnd / (double)clip.frameRate) : (FillRange?)null;
                    KeyFillPlan plan = KeyFill.Plan(clip.name, read.Curves, clip.length, rate, range, ClipSampler.MuscleProperties());
                    CharacterRig rig = RigCollector.Collect(animator, settings, contract.Skeleton, out JointMap jointMap, out Transform[] bones);
                    BakeMethod method = BakeMethod.Model(inbetweener, feet: _lockFeet ? new FootLockSettings() : null);
                    KeyFillEdit edit;
                    BakeRun run;
                    if (plan.Kind == KeyFillClipKind.Transform)
                    {
                        (edit, run) = KeyFillBake.Run(contract, plan, read.Curves, rig, jointMap, ClipSampler.Paths(character.transform, bones), ScenePose(bones), method);
                    }
                    else
                    {
                        // A humanoid clip: the engine turns muscles into bones and back (the baker's humanoid path).
                        var track = new CharacterPoseTrack(rig, plan.LastKey + 1, 1.0 / rate);
                        using (new AnimationModeScope())
                        {
                            ClipSampler.SampleInto(track, character, bones, clip, plan.KeyFrames, plan.KeyTimes);
                        }

                        run = CharacterBake.Run(contract, track, jointMap, new[] { method });
                        IReadOnlyList<ClipCurve> recorded;
                        using (new AnimationModeScope())
                        {
                            recorded = ClipSampler.HumanoidClipCurves(animator, rig, bones, run.Methods[0].OnRig);
                        }

                        edit = KeyFill.Edit(plan, read.Curves, recorded);
                    }

                    var warnings = new List<string>(plan.Warnings);
                    warnings.AddRange(run.Methods[0].Plan.Warnings);
                    warnings.AddRange(run.Warnings);
                    _report = $"{plan.GapCount} gap{(plan.GapCount == 1 ? "" : "s")}, {plan.MissingFrames} frames at {rate:0.##} fps; {edit.FilledKeys} keys on {edit.Changes.Count} curves."
                              + (warnings.Count > 0 ? "\n" + string.Join("\n", warnings) : "");
                    _read = read;
                    _computedFor = Inputs();
                    return edit;
                }
            }
            catch (Exception e) when (e is ArgumentException || e is InvalidOperationException || e is DataFormatException || e is JointMapException)
            {
                EditorUtility.DisplayDialog("Cannot fill", e.Message, "OK");
                return null;
            }
            finally
            {
                EditorUtility.ClearProgressBar();
            }
        }

        private void StartPreview()
        {
            // With a Motion Inbetweener on the character, its preview layer (IAnimationWindowPreview) shows the fill in the
            // Animation window's own preview of this clip and in Timeline's; otherwise this window samples it itself.
            bool layer = _character!.GetComponent<MotionInbetweener>() != null;
            AnimationWindow? window = layer ? WindowOn(_clip!) : null;
            if (window == null && AnimationMode.InAnimationMode())
            {
                EditorUtility.DisplayDialog("Cannot preview", "The editor is in animation mode (the Animation window previews or records another clip or character, or Timeline previews); leave preview and record mode, then preview the fill. With a Motion Inbetweener on the character, the Animation window's own preview of this clip shows the fill.", "OK");
                return;
            }

            _edit = Compute();
            if (_edit == null) return;
            _previewClip = _read!.Preview(_clip!, _edit);
            if (layer)
            {
                FillPreviewLayer.Publish(_character, _clip!, _previewClip);
                _publishedOn = _character;
            }

            _inAnimationWindow = window != null;
            if (window != null)
            {
                Resample(window);
                return;
            }

            AnimationMode.StartAnimationMode();
            Sample(_previewTime);
        }

        /// <summary>The open Animation window when it is on <paramref name="clip"/>, else null (GetWindow would open one).</summary>
        private static AnimationWindow? WindowOn(AnimationClip clip)
        {
            if (!HasOpenInstances<AnimationWindow>()) return null;
            AnimationWindow window = GetWindow<AnimationWindow>(false, null, false);
            return window.animationClip == clip ? window : null;
        }

        /// <summary>
        /// Has the Animation window sample its preview again. Its resample (the only call that updates the preview layer
        /// and evaluates) is internal; turning its preview off and on is public and rebuilds the graph, calling the
        /// layer's StopPreview, StartPreview, BuildPreviewGraph and UpdatePreviewGraph (AnimationWindowControl).
        /// </summary>
        private static void Resample(AnimationWindow window)
        {
            if (window.previewing) window.previewing = false;
            window.previewing = true;
            UnityEditorInternal.InternalEditorUtility.RepaintAllViews();
        }

        private void Sample(float time)
        {
            _previewTime = time;
            if (_previewClip == null || _character == null) return;
            AnimationMode.BeginSampling();
            AnimationMode.SampleAnimationClip(_character, _previewClip, time);
            AnimationMode.EndSampling();
            // The scene views show the sampled pose only when they repaint.
            UnityEditorInternal.InternalEditorUtility.RepaintAllViews();
        }

        private void StopPreview()
        {
            if (_previewClip == null) return;
            // Cleared before the copy is destroyed: the layer swaps the copy out at its next update.
            if (_publishedOn != null) FillPreviewLayer.Clear(_publishedOn);
            _publishedOn = null;
            if (_inAnimationWindow)
            {
                AnimationWindow? window = _clip != null ? WindowOn(_clip) : null;
                if (window != null && window.previewing) Resample(window);
            }
            else
            {
                AnimationMode.StopAnimationMode();
            }

            _inAnimationWindow = false;
            DestroyImmediate(_previewClip);
            _previewClip = null;
        }

        private void Fill()
        {
            StopPreview();
            // What was previewed is written, unless the clip changed since (then Apply below refuses and it is computed again).
            KeyFillEdit? edit = _edit ?? Compute();
            if (edit == null) return;
            ClipCurves now = ClipCurves.Read(_clip!);
            try
            {
                edit.Apply(now.Curves);
            }
            catch (KeyFillException)
            {
                edit = Compute();
                if (edit == null) return;
                now = _read!;
            }

            if (_report.Contains("\n") && !EditorUtility.DisplayDialog("Check the fill", _report, "Fill anyway", "Cancel")) return;
            // One Undo step takes the whole fill back: the clip is recorded complete before any curve is written.
            Undo.RegisterCompleteObjectUndo(_clip!, "Fill in-betweens");
            now.Write(_clip!, edit);
            Forget();
        }

        private void Forget()
        {
            StopPreview();
            _edit = null;
            _read = null;
            _report = "";
        }

        /// <summary>The bones' local transforms as they stand: what the clip's missing curves leave them at.</summary>
        private static double[] ScenePose(Transform[] bones)
        {
            var pose = new double[3 + 4 * bones.Length];
            UnityPoses.Read(bones, 0, pose.AsSpan(0, 3), pose.AsSpan(3));
            return pose;
        }
    }
}
