using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Feet;

namespace DeltaInterpolator.Cli.Baking
{
    /// <summary><c>bake</c>'s command line, parsed and checked (inputs readable, outputs writable and distinct) before any work.</summary>
    internal sealed class BakeRequest
    {
        public string Input { get; set; } = "";
        public int[]? Keys { get; set; }
        public Core.Baking.KeySpacing? Every { get; set; }
        public string Method { get; set; } = "model";
        public string ModelPath { get; set; } = "";
        public ShortContextPolicy? Policy { get; set; }
        public bool FilledContext { get; set; } = true;
        public string OutPath { get; set; } = "";
        public string OutFull { get; set; } = "";
        public bool Force { get; set; }
        public int? ReferenceFrame { get; set; }
        public Core.Retargeting.UpAxis Up { get; set; }
        /// <summary>--accept-reference-pose: keep a reference pose the humanoid rule refuses (then named in the rig's description: console and JSON).</summary>
        public bool AcceptReferencePose { get; set; }
        public string? MapPath { get; set; }
        public double? InputFps { get; set; }
        public int FromFrame { get; set; }
        public FootLockSettings? Feet { get; set; }
        public string? JsonPath { get; set; }
        public string? JsonFull { get; set; }
        public string? PreviewPath { get; set; }
        public string? PngPath { get; set; }
        public string? StatsPath { get; set; }
        public bool StatsGiven { get; set; }
        public int Threads { get; set; } = 1;
    }
}
