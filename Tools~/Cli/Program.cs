using System;
using System.CommandLine;
using System.IO;
using System.Linq;
using DeltaInterpolator.Cli.Verbs;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// Entry point of <c>inbetween</c>. Each verb is one <see cref="ICliVerb"/>; adding a verb means adding
    /// a class to <see cref="Verbs"/>. Exit codes: 0 success, 2 bad input (one line on stderr:
    /// <c>FILE:LINE: what was wrong; what was expected</c>), 1 an unexpected failure.
    /// </summary>
    public static class Program
    {
        /// <summary>The verbs, in the order <c>--help</c> lists them.</summary>
        private static ICliVerb[] Verbs => new ICliVerb[]
        {
            new BakeVerb(),
            new BenchmarkVerb(),
            new CheckVerb(),
            new DemoVerb(),
            new InfoVerb(),
            new RetargetVerb(),
            new PreviewVerb(),
            new PackVerb(),
            new ScoreVerb(),
            new SpeedVerb(),
        };

        /// <summary>The longest command line accepted (all arguments and the spaces between them).</summary>
        public const int MaxCommandLineCharacters = 16_000;

        public static int Main(string[] args)
        {
            InterruptCleanup.Install();
            TerminalSafeHook.AttachTo(Spectre.Console.AnsiConsole.Console);
            long characters = 0;
            foreach (string arg in args) characters += arg.Length + 1;
            if (characters > MaxCommandLineCharacters)
            {
                // Past ~40 KB, starting ONNX Runtime aborted the process (exit 134); no verb needs that much.
                CliErrors.WriteLine(string.Format(System.Globalization.CultureInfo.InvariantCulture,
                    "inbetween: the command line is {0:N0} characters long; expected at most {1:N0} (give a long key list from a file: --keys @FILE)",
                    characters, MaxCommandLineCharacters));
                return CliErrors.BadInput;
            }

            // Tables written to a file or a pipe stay plain text (no colour escape codes).
            if (Console.IsOutputRedirected)
            {
                Spectre.Console.AnsiConsole.Profile.Capabilities.Ansi = false;
            }

            var root = new RootCommand(
                "inbetween: headless tools of the Δ-Interpolator motion in-betweening package.\n" +
                "Reads BVH motion capture, runs the official LaFAN1 in-betweening benchmark and (later) neural models.\n\n" +
                "Examples:\n" +
                "  inbetween benchmark --data ../shared/data/lafan1 --stats ../shared/data/lafan1/train_stats_official.json\n" +
                "  inbetween check Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx --past 10 --gap 60\n" +
                "  inbetween info ../shared/data/lafan1/walk4_subject1.bvh\n" +
                "  inbetween bake ../shared/data/lafan1/obstacles1_subject5.bvh --every 15 --out out/obstacles1-every15.bvh --force\n" +
                "  inbetween pack --out out/release\n\n" +
                "Run 'inbetween VERB --help' for a verb's options.");
            foreach (ICliVerb verb in Verbs) root.Subcommands.Add(verb.CreateCommand());

            // No response files: System.CommandLine would expand any "@FILE" argument by reading the file (a named
            // pipe blocks forever, /dev/zero never ends); --keys @FILE is read by the verb through the safe input path.
            ParseResult parse = root.Parse(args, new ParserConfiguration { ResponseFileTokenReplacer = null });
            if (parse.Errors.Count > 0)
            {
                string verb = parse.CommandResult.Command is RootCommand ? "inbetween" : "inbetween " + parse.CommandResult.Command.Name;
                // An unknown word explains more than the "required command" error it also causes.
                System.CommandLine.Parsing.ParseError first = parse.Errors.FirstOrDefault(e => e.Message.StartsWith("Unrecognized", StringComparison.Ordinal)) ?? parse.Errors[0];
                string message = FriendlyTypeNames(first.Message).TrimEnd('.');
                CliErrors.WriteLine($"{verb}: {message}; expected valid arguments (see '{verb} --help')");
                return CliErrors.BadInput;
            }

            var invocation = new InvocationConfiguration { EnableDefaultExceptionHandler = false };
            return CliErrors.Guard(() => parse.Invoke(invocation));
        }

        /// <summary>
        /// A parser message with .NET type names (<c>System.Nullable`1[System.Int32]</c>) said in words
        /// ("a whole number"), as a user reads the option's help.
        /// </summary>
        internal static string FriendlyTypeNames(string message)
        {
            return System.Text.RegularExpressions.Regex.Replace(message.Replace("as expected type ", "as "), @"'?System\.Nullable`1\[(System\.[A-Za-z0-9]+)\]'?|'?(System\.[A-Za-z0-9]+(\[\])?)'?", m =>
            {
                string type = m.Groups[1].Success ? m.Groups[1].Value : m.Groups[2].Value;
                switch (type)
                {
                    case "System.Int32":
                    case "System.Int64": return "a whole number";
                    case "System.Double":
                    case "System.Single": return "a number";
                    case "System.Boolean": return "true or false";
                    case "System.String":
                    case "System.String[]": return "text";
                    default: return m.Value;
                }
            });
        }

        /// <summary>
        /// Runs the tool in this process with its standard output and error going to the given writers,
        /// as the shell would see them (plain text, no colours): the entry point of the CLI tests. The
        /// console is process-wide, so calls must not overlap.
        /// </summary>
        public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
        {
            TextWriter oldOut = Console.Out, oldError = Console.Error;
            Spectre.Console.IAnsiConsole oldConsole = Spectre.Console.AnsiConsole.Console;
            Console.SetOut(stdout);
            Console.SetError(stderr);
            Spectre.Console.AnsiConsole.Console = Spectre.Console.AnsiConsole.Create(new Spectre.Console.AnsiConsoleSettings
            {
                Out = new Spectre.Console.AnsiConsoleOutput(stdout),
                Ansi = Spectre.Console.AnsiSupport.No,
                ColorSystem = Spectre.Console.ColorSystemSupport.NoColors,
                Interactive = Spectre.Console.InteractionSupport.No,
            });
            try
            {
                return Main(args);
            }
            finally
            {
                Console.SetOut(oldOut);
                Console.SetError(oldError);
                Spectre.Console.AnsiConsole.Console = oldConsole;
            }
        }
    }
}
