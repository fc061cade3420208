using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Linq;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Skeletons;
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
            Description = "Show only frames START-END of the files (inclusive, frame indices of the files); the preview counts from START as 0.",
            HelpName = "START-END",
        };

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
            if (truth != null) requests.Add(SplitTrack(truth, "Ground truth", "--truth"));
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

                requests.Add(SplitTrack(track, "", "--track"));
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

            (int Start, int End)? range = ParseFrames(parse.GetValue(_frames));
            int[] keys = ParseKeys(parse.GetValue(_keys));
            bool force = parse.GetValue(_output.Force);
            string[] inputs = requests.Select(r => r.Path).ToArray();
            string htmlPath = parse.GetValue(_out)!;
            OutputFile.Check(htmlPath, force, inputs);
            string? pngPath = parse.GetValue(_png);
            if (pngPath != null)
            {
                // The PNG and the SVG written instead when Chromium fails: both checked now, not after the work.
                ContactSheet.CheckOutputs(pngPath, force, new[] { htmlPath }, inputs);
            }

            var clips = new List<(string Name, MotionClip Clip)>();
            BvhAnimation? first = null;
            foreach ((string name, string path) in requests)
            {
                BvhAnimation animation = BvhReader.Read(path);
                if (animation.Motion.FrameCount == 0) throw new CliErrors.UsageException($"{path}: has no frames (Frames: 0); expected at least one frame to show");
                MotionChecks.RequireFinitePositions(animation.Motion, path, "the motion");
                if (first == null)
                {
                    first = animation;
                }
                else
                {
                    string? difference = PreviewScene.SkeletonDifference(first.Skeleton, animation.Skeleton);
                    if (difference != null)
                    {
                        throw new CliErrors.UsageException($"{path}: {difference} ({first.SourceName}); expected the same skeleton in every file (retarget first)");
                    }

                    double a = first.Motion.FrameTime, b = animation.Motion.FrameTime;
                    if (Math.Abs(a - b) > 1e-6 * a)
                    {
                        throw new CliErrors.UsageException(string.Format(CultureInfo.InvariantCulture, "{0}: {1:0.###} fps where {2} has {3:0.###} fps; expected one frame rate in every file", path, 1 / b, first.SourceName, 1 / a));
                    }
                }

                clips.Add((name, Slice(animation.Motion, range, path)));
            }

            int frames = clips.Max(c => c.Clip.FrameCount);
            int offset = range?.Start ?? 0;
            int[] sceneKeys = keys.Select(k => k - offset).ToArray();
            foreach (int key in keys)
            {
                if (key - offset < 0 || key - offset >= frames)
                {
                    string where = range == null ? $"frames 0..{frames - 1} of the files" : $"the shown frames {offset}..{offset + frames - 1} (--frames)";
                    throw new CliErrors.UsageException($"--keys: key frame {key} is outside {where}; expected key frames inside them");
                }
            }

            string title = Path.GetFileName(requests[0].Path) + (range == null ? "" : $", frames {offset}–{offset + frames - 1}");
            PreviewScene scene = PreviewScene.FromClips(title, clips, sceneKeys, truth != null ? 0 : -1);
            PreviewWriter.WriteHtml(scene, htmlPath);
            SafeLine(string.Format(
                CultureInfo.InvariantCulture,
                "wrote {0} ({1:0} KB): {2} track{6}, {3} frames at {4:0.##} fps, {5} key frames",
                htmlPath,
                new FileInfo(htmlPath).Length / 1024.0,
                scene.Tracks.Count,
                scene.FrameCount,
                1 / scene.FrameTime,
                scene.KeyFrames.Count,
                scene.Tracks.Count == 1 ? "" : "s"));
            if (scene.GroundTruthTrack >= 0)
            {
                for (int t = 0; t < scene.Tracks.Count; t++)
                {
                    if (t == scene.GroundTruthTrack) continue;
                    SafeLine(string.Format(
                        CultureInfo.InvariantCulture,
                        "  {0}: mean joint position error {1:0.###} (data units) {2}",
                        scene.Tracks[t].Name,
                        scene.MeanErrorBetweenKeys(t),
                        scene.KeyFrames.Count > 0 ? "on frames between keys" : "over all frames"));
                }
            }

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

                SafeLine(fallback ?? string.Format(CultureInfo.InvariantCulture, "wrote {0} ({1:0} KB)", written, new FileInfo(written).Length / 1024.0));
            }

            return 0;
        }

        /// <summary>One line on stdout with file and track names made terminal-safe (no raw escapes, no forged lines).</summary>
        private static void SafeLine(string line) => Console.WriteLine(TerminalText.Safe(line, TerminalText.LineLength));

        private static (string Name, string Path) SplitTrack(string value, string defaultName, string option)
        {
            int equals = value.IndexOf('=');
            if (equals < 0)
            {
                return (defaultName.Length > 0 ? defaultName : Path.GetFileNameWithoutExtension(value), value);
            }

            string name = value.Substring(0, equals).Trim();
            string path = value.Substring(equals + 1);
            if (name.Length == 0 || path.Length == 0)
            {
                throw new CliErrors.UsageException($"{option} {value}: empty name or file; expected NAME=FILE.bvh");
            }

            return (name, path);
        }

        private static MotionClip Slice(MotionClip clip, (int Start, int End)? range, string path)
        {
            if (range == null) return clip;
            (int start, int end) = range.Value;
            if (start >= clip.FrameCount)
            {
                throw new CliErrors.UsageException($"{path}: --frames starts at {start} but the file has {clip.FrameCount} frames; expected a start below {clip.FrameCount}");
            }

            int last = Math.Min(end, clip.FrameCount - 1);
            int count = last - start + 1;
            int j = clip.Skeleton.JointCount;
            var positions = new double[count * j * 3];
            var rotations = new double[count * j * 4];
            Array.Copy(clip.LocalPositions, start * j * 3, positions, 0, positions.Length);
            Array.Copy(clip.LocalRotations, start * j * 4, rotations, 0, rotations.Length);
            return new MotionClip(clip.Skeleton, count, clip.FrameTime, positions, rotations);
        }

        private static (int Start, int End)? ParseFrames(string? text)
        {
            if (text == null) return null;
            string[] parts = text.Split('-');
            if (parts.Length != 2
                || !int.TryParse(parts[0].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out int start)
                || !int.TryParse(parts[1].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out int end)
                || end < start)
            {
                throw new CliErrors.UsageException($"--frames {text}: not a frame range; expected START-END with 0 ≤ START ≤ END, e.g. 0-299");
            }

            return (start, end);
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
