using System;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary><c>inbetween info FILE.bvh</c>: what a BVH file holds, and how fast it reads.</summary>
    public sealed class InfoVerb : ICliVerb
    {
        private readonly Argument<string> _file = new Argument<string>("FILE")
        {
            Description = "A BVH file, e.g. ../shared/data/lafan1/walk4_subject1.bvh",
        };

        private readonly Option<string> _up = UpAxisArgument.Create();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "info",
                "Show a BVH file's joints (parent, channels, offset), frame count, frame time, duration, size and read speed,\n" +
                "and the up axis retarget and bake would take it to have (--up; the offsets are listed as the file has them).\n" +
                "A malformed file is reported as FILE:LINE: what was wrong; what was expected (exit status 2). Names are shown with\n" +
                "control characters escaped and clipped to " + TerminalText.NameLength + " characters; a table lists at most " + MaxJointRows + " joints.\n" +
                "Example:\n  inbetween info ../shared/data/lafan1/walk4_subject1.bvh");
            command.Arguments.Add(_file);
            command.Options.Add(_up);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse.GetValue(_file)!, UpAxisArgument.Parse(parse.GetValue(_up), "info"))));
            return command;
        }

        private static int Run(string path, UpAxis up)
        {
            InputFile.Check(path, "a .bvh file");

            long bytes = new FileInfo(path).Length;
            var first = Stopwatch.StartNew();
            BvhAnimation animation = BvhReader.Read(path);
            double firstSeconds = first.Elapsed.TotalSeconds;

            // The first read includes JIT compilation; a few more reads (up to ~1 s) give the steady speed.
            double best = firstSeconds;
            var budget = Stopwatch.StartNew();
            for (int i = 0; i < 5 && budget.Elapsed.TotalSeconds < 1.0; i++)
            {
                var sw = Stopwatch.StartNew();
                BvhReader.Read(path);
                best = Math.Min(best, sw.Elapsed.TotalSeconds);
            }

            Skeleton skeleton = animation.Skeleton;
            MotionClip motion = animation.Motion;
            var joints = new Table().Border(TableBorder.Rounded).Title($"[bold]{Markup.Escape(TerminalText.Safe(Path.GetFileName(path), TerminalText.NameLength))}[/]: {skeleton.JointCount} joints");
            // One line a joint at 80 columns (a Mixamo rig is 65 joints): the tree by indentation instead of
            // a parent column, channels as axis orders ("pos XYZ rot ZYX"), the offset as three short numbers.
            joints.AddColumn(new TableColumn("#").RightAligned());
            joints.AddColumn("Joint (+: End Site)");
            joints.AddColumn(new TableColumn("Channels").NoWrap());
            joints.AddColumn(new TableColumn("Offset").RightAligned().NoWrap());
            // Depths in one pass (parents come before children), so a deep file costs time in proportion to it.
            var depths = new int[skeleton.JointCount];
            for (int j = 1; j < skeleton.JointCount; j++) depths[j] = depths[skeleton.Parents[j]] + 1;
            int shown = Math.Min(skeleton.JointCount, MaxJointRows);
            for (int j = 0; j < shown; j++)
            {
                // Indentation (one space a level) shows the tree up to a few levels; deeper joints say their
                // depth instead of widening the table (a file nested 5,000 deep once made a 10,000-column table).
                string depth = depths[j] <= MaxIndentedDepth ? new string(' ', depths[j]) : new string(' ', MaxIndentedDepth) + "(depth " + depths[j].ToString(CultureInfo.InvariantCulture) + ") ";
                string offset = string.Format(CultureInfo.InvariantCulture, "{0:0.###} {1:0.###} {2:0.###}", skeleton.Offsets[3 * j], skeleton.Offsets[3 * j + 1], skeleton.Offsets[3 * j + 2]);
                string endSites = animation.EndSites[j].Length > 0 ? " +" : "";
                joints.AddRow(
                    j.ToString(CultureInfo.InvariantCulture),
                    Markup.Escape(depth + TerminalText.Safe(skeleton.Names[j], TerminalText.NameLength) + endSites),
                    Markup.Escape(CompactChannels(animation.JointChannels[j])),
                    offset);
            }

            AnsiConsole.Write(joints);
            if (shown < skeleton.JointCount)
            {
                AnsiConsole.MarkupLine(Markup.Escape($"(the first {shown:N0} of {skeleton.JointCount:N0} joints are listed)"));
            }

            var summary = new Table().Border(TableBorder.Rounded).HideHeaders();
            summary.AddColumn("");
            summary.AddColumn("");
            summary.AddRow("Frames", motion.FrameCount.ToString("N0", CultureInfo.InvariantCulture));
            summary.AddRow("Frame time", string.Format(CultureInfo.InvariantCulture, "{0:0.######} s ({1:0.##} fps)", motion.FrameTime, 1.0 / motion.FrameTime));
            summary.AddRow("Duration", string.Format(CultureInfo.InvariantCulture, "{0:0.00} s", motion.Duration));
            summary.AddRow("Channels per frame", animation.ChannelCount.ToString(CultureInfo.InvariantCulture));
            summary.AddRow("File size", string.Format(CultureInfo.InvariantCulture, "{0:N0} bytes ({1:0.00} MB)", bytes, bytes / 1e6));
            summary.AddRow("Up axis", Markup.Escape(UpAxisRow(animation, up)));
            summary.AddRow("Read speed", string.Format(CultureInfo.InvariantCulture, "{0:0} MB/s ({1:0.0} ms; first read with JIT start-up {2:0.0} ms)", bytes / 1e6 / best, best * 1e3, firstSeconds * 1e3));
            AnsiConsole.Write(summary);
            return 0;
        }

        /// <summary>
        /// What <c>retarget</c> and <c>bake</c> would decide about the file's up axis with the same <c>--up</c> and the
        /// built-in joint names (a JSON map there may find the body where the built-in names do not).
        /// </summary>
        private static string UpAxisRow(BvhAnimation animation, UpAxis up)
        {
            JointMap? body = UpAxisDetection.BodyMap(animation.Skeleton);
            if (body == null) return $"up axis {UpAxes.Name(up)}: not judged, no hips, head or feet by the built-in names (retarget and bake judge by --map)";
            return UpAxisDecision.Decide(up, ReferencePose.Zero(animation.Skeleton), false, animation.Motion, body).Description.Replace("turned to the model's Y up", "retarget and bake turn it to Y up", StringComparison.Ordinal);
        }

        /// <summary>
        /// Channels in a few characters: "pos XYZ rot ZYX" for the usual six (each group in file order), the
        /// full names when positions and rotations interleave, "-" for none.
        /// </summary>
        internal static string CompactChannels(BvhChannel[] channels)
        {
            if (channels.Length == 0) return "-";
            var text = new System.Text.StringBuilder();
            bool? rotation = null;
            foreach (BvhChannel c in channels)
            {
                if (rotation != c.IsRotation())
                {
                    if (rotation == true) return BvhChannels.Describe(channels); // rotations then positions again: say it in full
                    if (text.Length > 0) text.Append(' ');
                    text.Append(c.IsRotation() ? "rot " : "pos ");
                    rotation = c.IsRotation();
                }

                text.Append("XYZ"[c.Axis()]);
            }

            return text.ToString();
        }

        /// <summary>Joints listed in the table; a file with more says how many were left out.</summary>
        private const int MaxJointRows = 1000;

        /// <summary>Nesting levels shown by indentation.</summary>
        private const int MaxIndentedDepth = 12;
    }
}
