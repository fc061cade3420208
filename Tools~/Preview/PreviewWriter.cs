using System;
using System.IO;
using System.Net;
using System.Reflection;
using System.Text;
using DeltaInterpolator.Core.IO;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// Writes a scene as one self-contained HTML page: the tracks play side by side in 3D and in sync,
    /// with play/pause, a frame scrubber with the key frames marked, an orbit camera and, when the scene
    /// has a ground truth, a per-frame error plot. Nothing is fetched when it opens: the player's script,
    /// style and data are inside the file, and it draws on a 2D canvas (no WebGL needed).
    /// The page exposes <c>window.preview</c> (<c>frame</c>, <c>frameCount</c>, <c>playing</c>,
    /// <c>setFrame(k)</c>, <c>play()</c>, <c>pause()</c>) for scripts and tests.
    /// </summary>
    public static class PreviewWriter
    {
        /// <summary>
        /// Writes the page to <paramref name="path"/> through <see cref="OutputFile.Write"/> (a temporary
        /// file beside it, then a rename). Call <see cref="OutputFile.Check(string, bool, string[])"/> on
        /// the path before the work that builds the scene, so a refused target costs nothing.
        /// </summary>
        public static void WriteHtml(PreviewScene scene, string path)
        {
            OutputFile.WriteAllText(path, BuildHtml(scene));
        }

        /// <summary>The page's text (UTF-8 HTML).</summary>
        public static string BuildHtml(PreviewScene scene)
        {
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            SceneLayout layout = SceneLayout.Of(scene);
            string title = string.IsNullOrWhiteSpace(scene.Title) ? "Motion preview" : scene.Title;
            string template = Resource("player.html");
            var builder = new StringBuilder(template.Length + 64 * 1024);
            int at = 0;
            while (true)
            {
                int open = template.IndexOf("{{", at, StringComparison.Ordinal);
                if (open < 0) break;
                int close = template.IndexOf("}}", open, StringComparison.Ordinal);
                builder.Append(template, at, open - at);
                string name = template.Substring(open + 2, close - open - 2);
                builder.Append(name switch
                {
                    "TITLE" => WebUtility.HtmlEncode(title),
                    "STYLE" => Resource("player.css"),
                    "SCRIPT" => Resource("player.js"),
                    "DATA" => PlayerData.Build(scene, layout),
                    _ => throw new InvalidOperationException($"player.html names an unknown slot {{{{{name}}}}}"),
                });
                at = close + 2;
            }

            builder.Append(template, at, template.Length - at);
            return builder.ToString();
        }

        internal static string Resource(string name)
        {
            Assembly assembly = typeof(PreviewWriter).Assembly;
            using Stream stream = assembly.GetManifestResourceStream("DeltaInterpolator.Preview." + name)
                ?? throw new InvalidOperationException($"the preview assembly lacks its resource {name}; rebuild Tools~/Preview");
            using var reader = new StreamReader(stream, Encoding.UTF8);
            return reader.ReadToEnd();
        }
    }
}
