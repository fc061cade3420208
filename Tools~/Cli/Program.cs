using System;
using System.CommandLine;
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
            new BenchmarkVerb(),
            new InfoVerb(),
            new RetargetVerb(),
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
                "  inbetween info ../shared/data/lafan1/walk4_subject1.bvh\n\n" +
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
    }
}
