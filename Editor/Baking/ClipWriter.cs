#nullable enable
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Editor.Baking
{
    /// <summary>
    /// Writes Core's <see cref="ClipCurve"/>s into a new <see cref="AnimationClip"/> asset. An existing asset is never
    /// replaced: the user is asked, and the clip is saved beside it under a new name or not at all.
    /// </summary>
    /// <remarks>
    /// The bake is an asset operation, not an edit: like Unity's own <i>Assets → Create</i>, it is not on the Undo stack
    /// (delete the <c>.anim</c> in the Project window to take it back). Registering the new clip with
    /// <c>Undo.RegisterCreatedObjectUndo</c>, as before, made Undo destroy the clip in memory and leave its <c>.anim</c> on
    /// disk: half undone.
    /// </remarks>
    internal static class ClipWriter
    {
        /// <summary>
        /// Asks where to save, then creates the clip. Returns the clip, or null when the user cancelled.
        /// </summary>
        /// <param name="curves">The curves to write (paths relative to the animated GameObject).</param>
        /// <param name="frameRate">The clip's sample rate (the model's rate).</param>
        /// <param name="defaultName">File name offered in the save panel, without extension.</param>
        /// <param name="boundTo">The component type the curves animate: <c>Transform</c> for a generic clip, <c>Animator</c> for a humanoid clip's body and muscles.</param>
        public static AnimationClip? Save(IReadOnlyList<ClipCurve> curves, double frameRate, string defaultName, System.Type boundTo)
        {
            string path = EditorUtility.SaveFilePanelInProject("Save baked clip", defaultName, "anim", "Where to save the clip with the in-betweens");
            if (string.IsNullOrEmpty(path)) return null;
            if (AssetDatabase.LoadAssetAtPath<Object>(path) != null)
            {
                string unique = AssetDatabase.GenerateUniqueAssetPath(path);
                bool keep = EditorUtility.DisplayDialog(
                    "Clip already exists",
                    $"{path} already exists and will not be replaced. Save the baked clip as {unique} instead?",
                    "Save as new clip",
                    "Cancel");
                if (!keep) return null;
                path = unique;
            }

            var clip = new AnimationClip { frameRate = (float)frameRate };
            foreach (ClipCurve c in curves)
            {
                var keys = new Keyframe[c.KeyCount];
                for (int i = 0; i < keys.Length; i++) keys[i] = new Keyframe(c.Times[i], c.Values[i], c.InTangents[i], c.OutTangents[i]);
                AnimationUtility.SetEditorCurve(clip, EditorCurveBinding.FloatCurve(c.Path, boundTo, c.Property), new AnimationCurve(keys));
            }

            AssetDatabase.CreateAsset(clip, path);
            AssetDatabase.SaveAssets();
            EditorGUIUtility.PingObject(clip);
            return clip;
        }
    }
}
