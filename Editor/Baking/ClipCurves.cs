#nullable enable
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Editor.Baking
{
    /// <summary>
    /// A clip's pose-capable float curves (those on a Transform or the Animator) as Core's <see cref="KeyedCurve"/>s,
    /// each key with its tangent modes, and a <see cref="KeyFillEdit"/> written back: the animator's keys as the very
    /// <see cref="Keyframe"/>s read (every field, the editor's tangent mode included), the filled keys as new ones.
    /// </summary>
    internal sealed class ClipCurves
    {
        private readonly EditorCurveBinding[] _bindings;
        private readonly Keyframe[][] _keyframes;

        private ClipCurves(EditorCurveBinding[] bindings, Keyframe[][] keyframes, List<KeyedCurve> curves)
        {
            _bindings = bindings;
            _keyframes = keyframes;
            Curves = curves;
        }

        /// <summary>The curves, in the clip's binding order.</summary>
        public List<KeyedCurve> Curves { get; }

        /// <summary>Reads every float curve of <paramref name="clip"/> bound to a Transform or the Animator.</summary>
        public static ClipCurves Read(AnimationClip clip)
        {
            var bindings = new List<EditorCurveBinding>();
            var keyframes = new List<Keyframe[]>();
            var curves = new List<KeyedCurve>();
            foreach (EditorCurveBinding binding in AnimationUtility.GetCurveBindings(clip))
            {
                if (binding.type != typeof(Transform) && binding.type != typeof(Animator)) continue;
                AnimationCurve curve = AnimationUtility.GetEditorCurve(clip, binding);
                if (curve == null) continue;
                Keyframe[] keys = curve.keys;
                var plain = new CurveKey[keys.Length];
                for (int i = 0; i < keys.Length; i++)
                {
                    Keyframe k = keys[i];
                    // Unity's packing of the editor's tangent mode: bit 0 broken, bits 1–4 left, bits 5–8 right.
                    int mode = (AnimationUtility.GetKeyBroken(curve, i) ? 1 : 0) | ((int)AnimationUtility.GetKeyLeftTangentMode(curve, i) << 1) | ((int)AnimationUtility.GetKeyRightTangentMode(curve, i) << 5);
                    plain[i] = new CurveKey(k.time, k.value, k.inTangent, k.outTangent, k.inWeight, k.outWeight, (int)k.weightedMode, mode);
                }

                bindings.Add(binding);
                keyframes.Add(keys);
                curves.Add(new KeyedCurve(binding.path, binding.propertyName, plain));
            }

            return new ClipCurves(bindings.ToArray(), keyframes.ToArray(), curves);
        }

        /// <summary>
        /// Writes <paramref name="edit"/>'s after-curves into <paramref name="clip"/> in one call: each kept key is the
        /// <see cref="Keyframe"/> read, each filled key a new one (tangent mode Free, its slope the neighbours').
        /// </summary>
        public void Write(AnimationClip clip, KeyFillEdit edit)
        {
            var bindings = new EditorCurveBinding[edit.Changes.Count];
            var curves = new AnimationCurve[edit.Changes.Count];
            for (int c = 0; c < edit.Changes.Count; c++)
            {
                KeyFillEdit.CurveChange change = edit.Changes[c];
                int index = IndexOf(change.Before);
                bindings[c] = _bindings[index];
                curves[c] = Build(change.After, _keyframes[index], Curves[index]);
            }

            AnimationUtility.SetEditorCurves(clip, bindings, curves);
        }

        /// <summary>
        /// A temporary copy of <paramref name="clip"/> with <paramref name="edit"/> applied, for the preview: every
        /// curve of the clip's, the changed ones replaced. Destroy it when the preview ends.
        /// </summary>
        public AnimationClip Preview(AnimationClip clip, KeyFillEdit edit)
        {
            var preview = new AnimationClip { frameRate = clip.frameRate, name = clip.name + " (fill preview)" };
            foreach (EditorCurveBinding binding in AnimationUtility.GetCurveBindings(clip))
            {
                AnimationUtility.SetEditorCurve(preview, binding, AnimationUtility.GetEditorCurve(clip, binding));
            }

            Write(preview, edit);
            return preview;
        }

        private int IndexOf(KeyedCurve before)
        {
            for (int i = 0; i < Curves.Count; i++)
            {
                if (Curves[i].Path == before.Path && Curves[i].Property == before.Property) return i;
            }

            throw new System.ArgumentException($"{before} is not a curve of the clip that was read", nameof(before));
        }

        private static AnimationCurve Build(KeyedCurve after, Keyframe[] original, KeyedCurve read)
        {
            var keys = new Keyframe[after.Keys.Count];
            int o = 0;
            for (int i = 0; i < keys.Length; i++)
            {
                CurveKey k = after.Keys[i];
                if (o < original.Length && k.Equals(read.Keys[o]))
                {
                    keys[i] = original[o++];
                    continue;
                }

                keys[i] = new Keyframe(k.Time, k.Value, k.InTangent, k.OutTangent);
            }

            return new AnimationCurve(keys);
        }
    }
}
