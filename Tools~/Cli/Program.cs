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

        public static int Main(string[] args)
        {
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
                "  inbetween check Runtime/Models/DeltaInterpolator-LaFAN1.onnx --past 10 --gap 60\n" +
                "  inbetween info ../shared/data/lafan1/walk4_subject1.bvh\n" +
                "  inbetween bake ../shared/data/lafan1/obstacles1_subject5.bvh --every 15 --out out/obstacles1-every15.bvh --force\n" +
                "  inbetween pack --out out/release\n\n" +
                "Run 'inbetween VERB --help' for a verb's options.");
            foreach (ICliVerb verb in Verbs) root.Subcommands.Add(verb.CreateCommand());

            ParseResult parse = root.Parse(args);
            if (parse.Errors.Count > 0)
            {
                string verb = parse.CommandResult.Command is RootCommand ? "inbetween" : "inbetween " + parse.CommandResult.Command.Name;
                // An unknown word explains more than the "required command" error it also causes.
                System.CommandLine.Parsing.ParseError first = parse.Errors.FirstOrDefault(e => e.Message.StartsWith("Unrecognized", StringComparison.Ordinal)) ?? parse.Errors[0];
                string message = first.Message.TrimEnd('.');
                CliErrors.WriteLine($"{verb}: {message}; expected valid arguments (see '{verb} --help')");
                return CliErrors.BadInput;
            }

            var invocation = new InvocationConfiguration { EnableDefaultExceptionHandler = false };
            return CliErrors.Guard(() => parse.Invoke(invocation));
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
