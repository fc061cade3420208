using System.CommandLine;
using DeltaInterpolator.Core.Retargeting;

namespace DeltaInterpolator.Cli
{
    /// <summary><c>--up y|z|auto</c>, the same on every verb that reads BVH (and the manifests' <c>"up"</c> key).</summary>
    internal static class UpAxisArgument
    {
        /// <summary>The option's help, shared so that every verb says the same.</summary>
        public const string Help = "Which axis is up in the file's world: 'auto' (default) decides from the file — the reference pose (feet to head) and the motion's floor (where the feet rest and the hips stand, not hips height alone) — and says what it decided; 'z' turns a Z-up file (Blender, 3ds Max) −90° about X onto the model's Y up; 'y' takes it as it is. A motion still lying down after retargeting is refused. Taken by every verb that reads a user's BVH motion: retarget, bake, score, preview (draws the files standing) and info (says what the others would decide); check --skeleton compares only joint names and parents, which no up axis changes.";

        /// <summary>A new <c>--up</c> option (default auto).</summary>
        public static Option<string> Create() => new Option<string>("--up")
        {
            Description = Help,
            HelpName = "auto|y|z",
            DefaultValueFactory = _ => "auto",
        };

        /// <summary>The axis <paramref name="text"/> names.</summary>
        /// <exception cref="CliErrors.UsageException">Anything but auto, y or z (one line; exit 2).</exception>
        public static UpAxis Parse(string? text, string verb) =>
            UpAxes.Parse(text) ?? throw new CliErrors.UsageException($"inbetween {verb}: --up '{TerminalText.Safe(text, 40)}'; expected {UpAxes.Values}");
    }
}
