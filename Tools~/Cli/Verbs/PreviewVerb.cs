using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Linq;
using DeltaInterpolator.Cli.Presenters;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Preview;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween preview</c>: BVH files of one skeleton as a self-contained HTML player (side by side in
    /// 3D, in sync, keys marked, per-frame error against a ground truth) and, with <c>--png</c>, a contact
    /// sheet rasterised by headless Chromium.
    /// </summary>
    public sealed class PreviewVerb : ICliVerb
    {
        private readonly Argument<string[]> _files = new Argument<string[]>("FILE")
        {
            Description = "BVH files to play side by side, each labelled by its file name (same skeleton: same joints in the same order).",
            Arity = ArgumentArity.ZeroOrMore,
        };

        private readonly Option<string?> _truth = new Option<string?>("--truth")
        {
            Description = "The ground truth ([NAME=]FILE.bvh): shown first, and every other track's per-frame mean joint position error against it is plotted.",
            HelpName = "[NAME=]FILE",
        };

        private readonly Option<string[]> _tracks = new Option<string[]>("--track")
        {
            Description = "A named track, NAME=FILE.bvh (repeatable), e.g. --track SLERP=out/slerp.bvh --track Model=out/model.bvh.",
            HelpName = "NAME=FILE",
            Arity = ArgumentArity.ZeroOrMore,
            AllowMultipleArgumentsPerToken = false,
        };

        private readonly Option<string?> _keys = new Option<string?>("--keys")
        {
            Description = "Key frame indices of the files, comma-separated and increasing: marked on the timeline and highlighted on the skeletons.",
            HelpName = "K,K,...",
        };

        private readonly Option<string?> _frames = new Option<string?>("--frames")
        {
            Description = "Show only frames START-END of the files (inclusive, frame indices of the files); frames are labelled with the files' numbers, like --keys.",
            HelpName = "START-END",
        };

        private readonly Option<string?> _map = new Option<string?>("--map")
        {
            Description = "A JSON joint map of the files' rig, the format 'inbetween retarget --map' reads ({\"LeftHand\": \"l_wrist\", ...}): the trails follow the joints it gives the model's LeftHand, RightHand, LeftFoot and RightFoot (others by built-in names).",
            HelpName = "MAP.json",
        };

        private readonly Option<string> _up = UpAxisArgument.Create();

        private readonly Option<string> _out = new Option<string>("--out")
        {
            Description = "The HTML file to write (self-contained: opens offline in any browser).",
            HelpName = "OUT.html",
            Required = true,
        };

        private readonly Option<string?> _png = new Option<string?>("--png")
        {
            Description = "Also write a PNG contact sheet (side and top views, joint trails, one row per track), rasterised by headless Chromium; without Chromium, an SVG beside it instead.",
            HelpName = "OUT.png",
        };

        private readonly OutputOptions _output = new OutputOptions();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "preview",
                "Show BVH motion of one skeleton as pictures: a self-contained HTML page that plays the tracks side by side in 3D\n" +
                "(play/pause, frame scrubber, key frames marked, orbit camera, per-frame error plot against --truth), and with --png a\n" +
                "contact sheet (side and top views, trails of root, hands and feet). Frame rate from the files.\n" +
                "Examples:\n" +
                "  inbetween preview ../shared/data/lafan1/walk4_subject1.bvh ../shared/data/lafan1/dance1_subject1.bvh --frames 0-299 --out out/preview.html\n" +
                "  inbetween preview --truth ../shared/data/lafan1/obstacles1_subject5.bvh --track Other=../shared/data/lafan1/ground1_subject5.bvh \\\n" +
                "      --keys 1000,1030,1060,1090,1120 --frames 1000-1120 --out out/compare.html --png out/compare.png --force");
            command.Arguments.Add(_files);
            command.Options.Add(_truth);
            command.Options.Add(_tracks);
            command.Options.Add(_keys);
            command.Options.Add(_frames);
            command.Options.Add(_map);
            command.Options.Add(_up);
            command.Options.Add(_out);
            command.Options.Add(_png);
            _output.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            var requests = new List<(string Name, string Path)>();
            string? truth = parse.GetValue(_truth);
            if (truth != null) requests.Add(TrackArgument.Parse(truth, "Ground truth", "--truth"));
            foreach (string file in parse.GetValue(_files) ?? Array.Empty<string>())
            {
                requests.Add((Path.GetFileNameWithoutExtension(file), file));
            }

            foreach (string track in parse.GetValue(_tracks) ?? Array.Empty<string>())
            {
                if (track.IndexOf('=') <= 0)
                {
                    throw new CliErrors.UsageException($"--track {track}: no NAME=; expected NAME=FILE.bvh, e.g. --track SLERP=out/slerp.bvh");
                }

                requests.Add(TrackArgument.Parse(track, "", "--track"));
            }

            if (requests.Count == 0)
            {
                throw new CliErrors.UsageException("inbetween preview: no BVH file given; expected FILE.bvh arguments, --truth or --track (see 'inbetween preview --help')");
            }

            var seen = new HashSet<string>(StringComparer.Ordinal);
            foreach ((string name, string path) in requests)
            {
                if (!seen.Add(name))
                {
                    throw new CliErrors.UsageException($"{path}: the track name '{name}' is used twice; expected unique names (give one with --track NAME=FILE)");
                }

                InputFile.Check(path, "a .bvh file");
            }

            (int Start, int End)? range = FrameRangeArgument.Parse(parse.GetValue(_frames));
            int[] keys = ParseKeys(parse.GetValue(_keys));
            UpAxis up = UpAxisArgument.Parse(parse.GetValue(_up), "preview");
            bool force = parse.GetValue(_output.Force);
            string? mapPath = parse.GetValue(_map);
            if (mapPath != null) InputFile.Check(mapPath, "a JSON joint map");
            // A key list file (--keys @FILE) and a joint map are inputs too: no output replaces them, --force or not.
            string? keyFile = parse.GetValue(_keys) is string keysText ? KeyListArgument.FilePath(keysText) : null;
            string[] inputs = requests.Select(r => r.Path).Append(mapPath).Append(keyFile).Where(p => p != null).Select(p => p!).ToArray();
            string htmlPath = parse.GetValue(_out)!;
            OutputFile.Check(htmlPath, force, inputs);
            string? pngPath = parse.GetValue(_png);
            if (pngPath != null)
            {
                // The PNG and the SVG written instead when Chromium fails: both checked now, not after the work.
                ContactSheet.CheckOutputs(pngPath, force, new[] { htmlPath }, inputs);
            }

            JointMap? map = mapPath == null ? null : JointMap.Load(mapPath);
            PreviewScene scene = BvhPreview.Build(requests, range, keys, truth != null, map, up);
            PreviewWriter.WriteHtml(scene, htmlPath);
            PreviewSummary.Page(scene, htmlPath);
            if (pngPath != null)
            {
                string? fallback = null;
                string written = pngPath;
                if (ContactSheet.FindChromium() != null)
                {
                    AnsiConsole.Status().Start("Rasterising the contact sheet with headless Chromium...", _ => written = ContactSheet.Write(scene, pngPath, force, out fallback));
                }
                else
                {
                    written = ContactSheet.Write(scene, pngPath, force, out fallback);
                }

                PreviewSummary.Sheet(written, fallback);
            }

            return 0;
        }

        private static int[] ParseKeys(string? text)
        {
            if (text == null) return Array.Empty<int>();
            string[] parts = KeyListArgument.Text(text).Split(',');
            var keys = new int[parts.Length];
            for (int i = 0; i < parts.Length; i++)
            {
                if (!int.TryParse(parts[i].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out keys[i]))
                {
                    throw new CliErrors.UsageException($"--keys: '{parts[i].Trim()}' is not a frame index; expected comma-separated whole numbers, e.g. 0,15,30");
                }

                if (i > 0 && keys[i] <= keys[i - 1])
                {
                    string what = keys[i] == keys[i - 1] ? "repeats" : "comes after";
                    throw new CliErrors.UsageException($"--keys: {keys[i]} {what} {keys[i - 1]}; expected strictly increasing frame indices");
                }
            }

            return keys;
        }
    }
}
