using System;
using System.IO;
using DeltaInterpolator.Core.IO;
using Microsoft.Playwright;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// A still picture of a scene, in the spirit of Figure 4 of the Δ-Interpolator paper: one row per
    /// track, each with a side view and a top view of poses at and between the key frames, and trails of
    /// the root, hands and feet. Drawn as SVG; rasterised to PNG by headless Chromium when it is
    /// installed (<see cref="FindChromium"/>), otherwise written as SVG (<see cref="Write"/>).
    /// </summary>
    public static class ContactSheet
    {
        /// <summary>
        /// The Chromium executable used for PNG output (Debian's <c>/usr/bin/chromium</c>, or the file
        /// named by the environment variable <c>INBETWEEN_CHROMIUM</c>), or null when none is installed.
        /// </summary>
        public static string? FindChromium() => Chromium.Find();

        /// <summary>
        /// Where <see cref="Write"/> will put a sheet asked for at <paramref name="pngPath"/>: the path
        /// itself when Chromium is installed, else the same path with the extension <c>.svg</c>. Check
        /// this path with <see cref="OutputFile.Check(string, bool, string[])"/> before the work.
        /// </summary>
        public static string OutputPathFor(string pngPath)
        {
            if (pngPath == null) throw new ArgumentNullException(nameof(pngPath));
            return FindChromium() != null ? pngPath : Path.ChangeExtension(pngPath, ".svg");
        }

        /// <summary>
        /// Before any work, both places a sheet asked for at <paramref name="pngPath"/> may land — the PNG
        /// and the SVG written instead when Chromium is missing or fails — must be writable (an existing
        /// one only with <paramref name="force"/>), neither may be one of the command's
        /// <paramref name="inputs"/>, nor one of its <paramref name="otherOutputs"/> (e.g. the HTML page).
        /// </summary>
        /// <exception cref="OutputPathException">Either path must not be written.</exception>
        public static void CheckOutputs(string pngPath, bool force, System.Collections.Generic.IEnumerable<string> otherOutputs, System.Collections.Generic.IEnumerable<string?> inputs)
        {
            if (pngPath == null) throw new ArgumentNullException(nameof(pngPath));
            string svgPath = Path.ChangeExtension(pngPath, ".svg");
            var others = new System.Collections.Generic.List<string>();
            foreach (string o in otherOutputs) others.Add(Path.GetFullPath(o));
            var paths = new System.Collections.Generic.List<string>(2) { OutputPathFor(pngPath) };
            if (!string.Equals(Path.GetFullPath(pngPath), Path.GetFullPath(svgPath), StringComparison.Ordinal))
            {
                paths.Add(string.Equals(paths[0], pngPath, StringComparison.Ordinal) ? svgPath : pngPath);
            }

            foreach (string path in paths)
            {
                string role = string.Equals(path, svgPath, StringComparison.Ordinal) && !string.Equals(path, pngPath, StringComparison.Ordinal)
                    ? $"the SVG written instead of {pngPath} when Chromium is missing or fails" : "the contact sheet";
                foreach (string other in others)
                {
                    if (string.Equals(Path.GetFullPath(path), other, OperatingSystem.IsWindows() || OperatingSystem.IsMacOS() ? StringComparison.OrdinalIgnoreCase : StringComparison.Ordinal))
                    {
                        throw new OutputPathException(path, $"is {role} and also another output of this command", "expected a --png path whose .png and .svg differ from the other outputs");
                    }
                }

                try
                {
                    OutputFile.Check(path, force, inputs);
                }
                catch (OutputPathException e) when (!string.Equals(path, paths[0], StringComparison.Ordinal))
                {
                    throw new OutputPathException(path, $"{e.Problem} ({role})", e.Expected);
                }
            }
        }

        /// <summary>
        /// Writes the sheet as PNG when Chromium is installed and starts, else as SVG beside it (same
        /// name, extension <c>.svg</c>), through <see cref="OutputFile"/>. Check
        /// <see cref="OutputPathFor"/> before the work; an SVG written because Chromium failed to start
        /// is checked here, with <paramref name="force"/>.
        /// </summary>
        /// <param name="scene">What to draw.</param>
        /// <param name="pngPath">The PNG file asked for.</param>
        /// <param name="force">Whether an existing SVG may be replaced when falling back.</param>
        /// <param name="fallback">Null when the PNG was written; else one line saying why an SVG was written instead.</param>
        /// <returns>The path written.</returns>
        public static string Write(PreviewScene scene, string pngPath, bool force, out string? fallback)
        {
            string svgPath = Path.ChangeExtension(pngPath, ".svg");
            string? chromium = FindChromium();
            if (chromium == null)
            {
                fallback = $"no Chromium found (install Debian's chromium for PNG): wrote {svgPath} instead of {pngPath}";
                WriteSvg(scene, svgPath);
                return svgPath;
            }

            byte[] png;
            try
            {
                png = RenderPng(scene, chromium);
            }
            catch (Exception e) when (e is PlaywrightException || e is TimeoutException)
            {
                string reason = e.Message.Split('\n')[0].Trim();
                fallback = $"Chromium ({chromium}) failed: {reason}; wrote {svgPath} instead of {pngPath}";
                OutputFile.Check(svgPath, force);
                WriteSvg(scene, svgPath);
                return svgPath;
            }

            OutputFile.WriteAllBytes(pngPath, png);
            fallback = null;
            return pngPath;
        }

        /// <summary>
        /// Rasterises the sheet with headless Chromium and writes the PNG through <see cref="OutputFile"/>.
        /// </summary>
        /// <param name="scene">What to draw.</param>
        /// <param name="path">The PNG file.</param>
        /// <param name="chromium">The browser executable; null finds it (<see cref="FindChromium"/>).</param>
        /// <exception cref="InvalidOperationException">No Chromium is installed.</exception>
        public static void WritePng(PreviewScene scene, string path, string? chromium = null)
        {
            OutputFile.WriteAllBytes(path, RenderPng(scene, chromium));
        }

        /// <summary>Writes the sheet's SVG through <see cref="OutputFile"/>.</summary>
        public static void WriteSvg(PreviewScene scene, string path)
        {
            OutputFile.WriteAllText(path, BuildSvg(scene));
        }

        /// <summary>The sheet as an SVG document.</summary>
        public static string BuildSvg(PreviewScene scene)
        {
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            return ContactSheetDrawing.Of(scene).ToSvg();
        }

        /// <summary>The sheet as PNG bytes, rasterised by headless Chromium.</summary>
        public static byte[] RenderPng(PreviewScene scene, string? chromium = null)
        {
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            string executable = chromium ?? FindChromium()
                ?? throw new InvalidOperationException("no Chromium found (install Debian's chromium, or set INBETWEEN_CHROMIUM); write the SVG instead");
            ContactSheetDrawing drawing = ContactSheetDrawing.Of(scene);
            string svg = drawing.ToSvg();
            int width = (int)Math.Ceiling(ContactSheetDrawing.SheetWidth);
            int height = (int)Math.Ceiling(drawing.Height);
            return Chromium.RasteriseSvgAsync(executable, svg, width, height, 1f).GetAwaiter().GetResult();
        }
    }
}
