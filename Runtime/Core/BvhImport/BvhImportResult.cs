using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// What a BVH file becomes in Unity, engine-free (<see cref="BvhClipImport"/>): the skeleton prefab's
    /// transforms and visible pieces, the clip's curves and frames, and the humanoid mapping when the
    /// joint names have one — all in Unity's space (left-handed, Y up) and metres. The editor's importer
    /// only turns these into GameObjects, an <c>AnimationClip</c> and an <c>Avatar</c>.
    /// </summary>
    public sealed class BvhImportResult
    {
        /// <summary>What the file's up axis was taken to be (<see cref="Retargeting.UpAxisDecision.Description"/>), or null when the file has no humanoid joints to judge by.</summary>
        public string? UpAxis { get; internal set; }

        /// <summary>True when the file was turned onto Y up (a Z-up rest skeleton or world).</summary>
        public bool Turned { get; internal set; }

        internal BvhImportResult(
            string sourceName,
            string name,
            string rootName,
            double frameRate,
            int frameCount,
            double metresPerUnit,
            double legLength,
            ImportedJoint[] joints,
            FigureBone[] figure,
            HumanoidMapping? humanoid,
            float[] localPositions,
            float[] localRotations,
            IReadOnlyList<ClipCurve> curves)
        {
            SourceName = sourceName;
            Name = name;
            RootName = rootName;
            FrameRate = frameRate;
            FrameCount = frameCount;
            MetresPerUnit = metresPerUnit;
            LegLength = legLength;
            Joints = joints;
            Figure = figure;
            Humanoid = humanoid;
            LocalPositions = localPositions;
            LocalRotations = localRotations;
            Curves = curves;
        }

        /// <summary>The file path or name the data came from.</summary>
        public string SourceName { get; }

        /// <summary>The clip's name: the file's name without folder and extension.</summary>
        public string Name { get; }

        /// <summary>The prefab's root object's name (the clip's name, unless a joint is called so too), parent of the root joint.</summary>
        public string RootName { get; }

        /// <summary>
        /// Frames per second: 1 / Frame Time, rounded to a whole number when within 0.01 of one (BVH writers
        /// print <c>.0083333</c> for 120 fps), so that keys land on the clip's frames.
        /// </summary>
        public double FrameRate { get; }

        /// <summary>Number of frames (one key per frame on every curve).</summary>
        public int FrameCount { get; }

        /// <summary>Metres per unit of the file (given, or <see cref="BvhUnitScale.Detect"/>).</summary>
        public double MetresPerUnit { get; }

        /// <summary>The rest pose's leg length (root height above the lowest joint), metres.</summary>
        public double LegLength { get; }

        /// <summary>The skeleton's joints in file order (parents first).</summary>
        public IReadOnlyList<ImportedJoint> Joints { get; }

        /// <summary>The visible pieces of the skeleton prefab.</summary>
        public IReadOnlyList<FigureBone> Figure { get; }

        /// <summary>Which joint plays each humanoid bone, or null when the names follow no built-in map (a generic avatar).</summary>
        public HumanoidMapping? Humanoid { get; }

        /// <summary>Frames × joints × 3 local positions, metres, Unity space (what the position curves hold, and each joint's offset otherwise).</summary>
        public float[] LocalPositions { get; }

        /// <summary>Frames × joints × 4 local rotations in Unity's component order (x, y, z, w), each joint kept in one hemisphere from frame to frame.</summary>
        public float[] LocalRotations { get; }

        /// <summary>
        /// The clip's curves (paths relative to the prefab's root object): every joint's <c>m_LocalRotation</c>,
        /// then the <c>m_LocalPosition</c> of the joints with <see cref="ImportedJoint.HasPositionCurves"/>.
        /// </summary>
        public IReadOnlyList<ClipCurve> Curves { get; }

        /// <summary>The time of frame <paramref name="frame"/>'s keys, seconds.</summary>
        public float KeyTime(int frame) => (float)(frame / FrameRate);

        /// <summary>The identifiers of the sub-assets, in the order the importer adds them (<see cref="BvhSubAssets"/>).</summary>
        public IReadOnlyList<string> SubAssetIds { get; } = new[] { BvhSubAssets.FigureId, BvhSubAssets.ClipId, BvhSubAssets.AvatarId };
    }
}
