using System;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// Which world axis points up in a motion file. The model and every built-in rig are Y-up; files from
    /// Blender, 3ds Max and some mocap pipelines are Z-up (the skeleton's rest pose, its world, or both).
    /// </summary>
    public enum UpAxis
    {
        /// <summary>Decided from the file (<see cref="UpAxisDetection"/>): the reference pose and the feet's contact plane.</summary>
        Auto,

        /// <summary>Y up (the model's convention): nothing is turned.</summary>
        Y,

        /// <summary>Z up: the motion is turned −90° about X so that Z becomes Y.</summary>
        Z,
    }

    /// <summary>Parsing and naming of <see cref="UpAxis"/> values as the CLI, manifests and the importer write them.</summary>
    public static class UpAxes
    {
        /// <summary>The values as written (<c>auto</c>, <c>y</c>, <c>z</c>).</summary>
        public const string Values = "auto, y or z";

        /// <summary>The axis written <paramref name="text"/> (auto, y, z; any case), or null when it is none of them.</summary>
        public static UpAxis? Parse(string? text)
        {
            switch (text?.Trim().ToLowerInvariant())
            {
                case "auto": return UpAxis.Auto;
                case "y": return UpAxis.Y;
                case "z": return UpAxis.Z;
                default: return null;
            }
        }

        /// <summary>The name as written (auto, y, z).</summary>
        public static string Name(UpAxis axis) => axis switch
        {
            UpAxis.Auto => "auto",
            UpAxis.Y => "y",
            UpAxis.Z => "z",
            _ => throw new ArgumentOutOfRangeException(nameof(axis), axis, "expected auto, y or z"),
        };
    }
}
