#nullable enable
using System;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.BvhImport;
using DeltaInterpolator.Core.IO;
using UnityEditor.AssetImporters;
using UnityEngine;

namespace DeltaInterpolator.Editor.Importers
{
    /// <summary>
    /// Imports <c>.bvh</c> motion capture files: each becomes a skeleton prefab (a visible stick figure with an
    /// Animator), an <c>AnimationClip</c> at the file's frame rate in Unity's space and metres, and an avatar —
    /// humanoid, built from the file's T-pose, when the joint names follow a known convention (CMU/MotionBuilder,
    /// LaFAN1, Mixamo, Unity, Poser), else generic. Drag the prefab into a scene and the clip onto it to play.
    /// </summary>
    /// <remarks>
    /// All conversion is Core's (<see cref="BvhClipImport"/>, tested without Unity); this class only builds
    /// the objects and reports a file that cannot be read as an import error naming the file and line.
    /// </remarks>
    [ScriptedImporter(1, "bvh")]
    public sealed class BvhImporter : ScriptedImporter
    {
        /// <summary>Metres per unit of the file; 0 tells the unit from the skeleton's size (centimetres, metres, inches, CMU units, …).</summary>
        [Tooltip("Metres per unit of the file. 0: tell it from the skeleton's leg length (centimetres, metres, millimetres, inches, CMU units).")]
        public float metresPerUnit;

        /// <inheritdoc />
        public override void OnImportAsset(AssetImportContext ctx)
        {
            BvhImportResult import;
            try
            {
                import = BvhClipImport.ImportFile(ctx.assetPath, metresPerUnit);
            }
            catch (Exception e) when (e is DataFormatException || e is InputPathException || e is IOException || e is UnauthorizedAccessException)
            {
                // The messages read FILE:LINE: what; expected — the import log shows them as they are.
                ctx.LogImportError(e.Message);
                return;
            }

            GameObject figure = BvhFigure.Build(import, out Transform[] joints);
            Avatar? human = BvhFigure.BuildHumanoid(import, figure, out string? problem);
            if (problem != null) ctx.LogImportWarning(problem);
            bool humanoid = !(human is null);
            // Otherwise a generic avatar without a root motion node: the clip moves the root joint itself.
            Avatar avatar = human is null ? AvatarBuilder.BuildGenericAvatar(figure, "") : human;
            avatar.name = import.Name + "Avatar";
            figure.AddComponent<Animator>().avatar = avatar;
            AnimationClip clip = BvhFigure.Clip(import, figure, joints, avatar, humanoid);

            ctx.AddObjectToAsset(BvhSubAssets.FigureId, figure);
            ctx.AddObjectToAsset(BvhSubAssets.ClipId, clip);
            ctx.AddObjectToAsset(BvhSubAssets.AvatarId, avatar);
            ctx.SetMainObject(figure);
        }
    }
}
