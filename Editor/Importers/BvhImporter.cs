#nullable enable
using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.BvhImport;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using UnityEditor.AssetImporters;
using UnityEngine;

namespace DeltaInterpolator.Editor.Importers
{
    /// <summary>
    /// Imports <c>.bvh</c> motion capture files: each becomes a skeleton prefab (a visible stick figure with an
    /// Animator), an <c>AnimationClip</c> at the file's frame rate in Unity's space and metres, and an avatar —
    /// humanoid, built from the file's T-pose, when the joint names follow a known convention (CMU/MotionBuilder,
    /// LaFAN1, Mixamo, Unity, Poser), else generic. Drag the prefab into a scene and the clip onto it to play.
    /// <see cref="clips"/> cuts named clips from the file instead (frame ranges, each looping or not).
    /// </summary>
    /// <remarks>
    /// All conversion is Core's (<see cref="BvhClipImport"/>, tested without Unity); this class only builds
    /// the objects and reports a file that cannot be read as an import error naming the file and line.
    /// </remarks>
    // Version 3: clip ranges with loops (Clips); version 2: Z-up files are stood on Y (Up Axis). A new version imports every file again.
    [ScriptedImporter(3, "bvh")]
    public sealed class BvhImporter : ScriptedImporter
    {
        /// <summary>Metres per unit of the file; 0 tells the unit from the skeleton's size (centimetres, metres, inches, CMU units, …).</summary>
        [Tooltip("Metres per unit of the file. 0: tell it from the skeleton's leg length (centimetres, metres, millimetres, inches, CMU units).")]
        public float metresPerUnit;

        /// <summary>The file's up axis, as <c>inbetween --up</c>: Auto decides from the file; a Z-up file is stood on Unity's Y up.</summary>
        [Tooltip("Which axis is up in the file. Auto: decided from the rest pose (feet to head) and the motion's floor; Z: a Z-up file (Blender, 3ds Max) is turned onto Y up; Y: taken as it is. The import log says what was decided when the file was turned.")]
        public UpAxis upAxis = UpAxis.Auto;

        /// <summary>Clips cut from the file, one per range (name, first and last frame, loop); empty: one clip of the whole file.</summary>
        [Tooltip("Clips to cut from the file, one per range: a name, the first and last frame (inclusive) and whether it loops. Empty: one clip of the whole file.")]
        public BvhClipSettings[] clips = new BvhClipSettings[0];

        /// <inheritdoc />
        public override void OnImportAsset(AssetImportContext ctx)
        {
            BvhImportResult import;
            var ranges = new List<BvhClipRange>();
            try
            {
                import = BvhClipImport.ImportFile(ctx.assetPath, metresPerUnit, upAxis);
                foreach (BvhClipSettings c in clips ?? new BvhClipSettings[0]) if (c != null) ranges.Add(c.ToRange());
                BvhClipRange.Check(ranges, import);
            }
            catch (Exception e) when (e is DataFormatException || e is InputPathException || e is IOException || e is UnauthorizedAccessException)
            {
                // The messages read FILE:LINE: what; expected — the import log shows them as they are.
                ctx.LogImportError(e.Message);
                return;
            }

            // The console says what was decided whenever the file was turned (a Y-up file is imported as before, silently).
            if (import.Turned && import.UpAxis != null) ctx.LogImportWarning(ctx.assetPath + ": " + import.UpAxis);
            GameObject figure = BvhFigure.Build(import, out Transform[] joints);
            Avatar? human = BvhFigure.BuildHumanoid(import, figure, out string? problem);
            if (problem != null) ctx.LogImportWarning(problem);
            bool humanoid = !(human is null);
            // Otherwise a generic avatar without a root motion node: the clip moves the root joint itself.
            Avatar avatar = human is null ? AvatarBuilder.BuildGenericAvatar(figure, "") : human;
            avatar.name = import.Name + "Avatar";
            figure.AddComponent<Animator>().avatar = avatar;
            ctx.AddObjectToAsset(BvhSubAssets.FigureId, figure);
            if (ranges.Count == 0)
            {
                ctx.AddObjectToAsset(BvhSubAssets.ClipId, BvhFigure.Clip(import, figure, joints, avatar, humanoid, new BvhClipRange(import.Name, 0, import.FrameCount - 1, false)));
            }
            else
            {
                // One clip per range; each sub-asset's identifier follows its name, so references survive edits of the other ranges.
                foreach (BvhClipRange range in ranges) ctx.AddObjectToAsset(range.SubAssetId, BvhFigure.Clip(import, figure, joints, avatar, humanoid, range));
            }

            ctx.AddObjectToAsset(BvhSubAssets.AvatarId, avatar);
            ctx.SetMainObject(figure);
        }
    }
}
