using System.Collections.Generic;
using Spectre.Console;
using Spectre.Console.Rendering;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// The terminal-safe rule for standard output as a whole: every text segment a verb prints through
    /// <see cref="AnsiConsole"/> (tables, markup lines) passes <see cref="TerminalText"/>, so a joint name,
    /// a model name or a file name holding <c>ESC]0;…</c> or <c>\r\n</c> is shown escaped and can neither
    /// retitle the terminal nor forge a line. Spectre's own styles and cursor codes are not text segments
    /// and pass unchanged. Attached once to the console by <see cref="Program"/>.
    /// </summary>
    internal sealed class TerminalSafeHook : IRenderHook
    {
        /// <inheritdoc />
        public IEnumerable<IRenderable> Process(RenderOptions options, IEnumerable<IRenderable> renderables)
        {
            foreach (IRenderable renderable in renderables) yield return new SafeRenderable(renderable);
        }

        /// <summary>Attaches the hook to <paramref name="console"/>.</summary>
        public static void AttachTo(IAnsiConsole console) => console.Pipeline.Attach(new TerminalSafeHook());

        private sealed class SafeRenderable : IRenderable
        {
            private readonly IRenderable _inner;

            public SafeRenderable(IRenderable inner) => _inner = inner;

            public Measurement Measure(RenderOptions options, int maxWidth) => _inner.Measure(options, maxWidth);

            public IEnumerable<Segment> Render(RenderOptions options, int maxWidth)
            {
                foreach (Segment segment in _inner.Render(options, maxWidth))
                {
                    if (segment.IsControlCode || segment.IsLineBreak || !HasUnsafe(segment.Text))
                    {
                        yield return segment;
                        continue;
                    }

                    // Line breaks inside a text segment stay line breaks; everything else unsafe is escaped.
                    string[] lines = segment.Text.Split('\n');
                    for (int i = 0; i < lines.Length; i++)
                    {
                        if (i > 0) yield return Segment.LineBreak;
                        if (lines[i].Length > 0) yield return new Segment(TerminalText.Safe(lines[i], int.MaxValue), segment.Style);
                    }
                }
            }

            private static bool HasUnsafe(string text)
            {
                foreach (char c in text)
                {
                    if (c != '\n' && TerminalText.IsUnsafe(c)) return true;
                }

                return false;
            }
        }
    }
}
