using System;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Cli.Packaging;
using DeltaInterpolator.Core.IO;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween pack</c>: the release archives of the package — the UPM <c>.tgz</c> (what a registry or
    /// a tarball install imports: every importable file with its <c>.meta</c>, plus <c>Samples~</c> and
    /// <c>Documentation~</c>) and the <c>.unitypackage</c> (importable assets under
    /// <c>Packages/NAME/</c>) — from the repository's committed and uncommitted-but-not-ignored files.
    /// </summary>
    public sealed class PackVerb : ICliVerb
    {
        private readonly Option<string> _root = new Option<string>("--root")
        {
            Description = "The package root (the folder with package.json).",
            DefaultValueFactory = _ => ".",
        };

        private readonly Option<string> _out = new Option<string>("--out")
        {
            Description = "Folder for both archives, named NAME-VERSION.tgz and NAME-VERSION.unitypackage (created when missing).",
            DefaultValueFactory = _ => "out",
        };

        private readonly Option<string?> _tgz = new Option<string?>("--tgz")
        {
            Description = "Path of the UPM tarball instead of --out/NAME-VERSION.tgz.",
        };

        private readonly Option<string?> _unityPackage = new Option<string?>("--unitypackage")
        {
            Description = "Path of the .unitypackage instead of --out/NAME-VERSION.unitypackage.",
        };

        private readonly OutputOptions _output = new OutputOptions();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "pack",
                "Build the release archives: the UPM .tgz (package/ + every importable file with its .meta, Samples~ and Documentation~; " +
                "Tools~, UnityPackage/HostProject~ and other hidden folders left out) and the .unitypackage (one GUID folder per asset " +
                "with asset, asset.meta and pathname = Packages/NAME/PATH). Prints both sizes.\n" +
                "An importable file without a .meta, or two metas sharing a GUID, is refused (exit status 2).\n" +
                "Example:\n  inbetween pack --out out/release --force");
            command.Options.Add(_root);
            command.Options.Add(_out);
            command.Options.Add(_tgz);
            command.Options.Add(_unityPackage);
            _output.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            string root = parse.GetValue(_root)!;
            bool force = parse.GetValue(_output.Force);
            if (!Directory.Exists(root))
            {
                throw new CliErrors.UsageException($"{root}: no such folder; expected the package root (the folder with package.json)");
            }

            PackageContents contents = PackageContents.Read(root);
            string baseName = contents.Name + "-" + contents.Version;
            string outDir = parse.GetValue(_out)!;
            string tgzPath = parse.GetValue(_tgz) ?? Path.Combine(outDir, baseName + ".tgz");
            string unityPackagePath = parse.GetValue(_unityPackage) ?? Path.Combine(outDir, baseName + ".unitypackage");
            if (string.Equals(Path.GetFullPath(tgzPath), Path.GetFullPath(unityPackagePath), StringComparison.Ordinal))
            {
                throw new CliErrors.UsageException($"{tgzPath}: given for both archives; expected two different paths");
            }

            // An archive never replaces a file it packs (e.g. --tgz package.json).
            var inputs = new string[contents.Files.Count];
            for (int i = 0; i < inputs.Length; i++) inputs[i] = Path.Combine(contents.Root, contents.Files[i]);
            string tgzFull = OutputFile.Check(tgzPath, force, inputs);
            string unityFull = OutputFile.Check(unityPackagePath, force, inputs);

            IAnsiConsole progressConsole = AnsiConsole.Create(new AnsiConsoleSettings
            {
                Out = new AnsiConsoleOutput(Console.Error),
                Interactive = Console.IsErrorRedirected ? InteractionSupport.No : InteractionSupport.Detect,
            });
            var clock = Stopwatch.StartNew();
            progressConsole.Progress()
                .AutoClear(true)
                .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn())
                .Start(ctx =>
                {
                    ProgressTask tgzTask = ctx.AddTask("UPM .tgz", true, Math.Max(1, contents.Files.Count));
                    OutputFile.Write(tgzFull, s => PackageArchives.WriteUpmTarball(contents, s, n => tgzTask.Value = n));
                    ProgressTask unityTask = ctx.AddTask(".unitypackage", true, Math.Max(1, contents.Assets.Count));
                    OutputFile.Write(unityFull, s => PackageArchives.WriteUnityPackage(contents, s, n => unityTask.Value = n));
                });

            var table = new Table().Border(TableBorder.Rounded).Title($"[bold]{Markup.Escape(baseName)}[/]");
            table.AddColumn("Archive");
            table.AddColumn(new TableColumn("Entries").RightAligned());
            table.AddColumn(new TableColumn("Size").RightAligned());
            table.AddRow(Markup.Escape(tgzPath), contents.Files.Count.ToString("N0", CultureInfo.InvariantCulture) + " files", Size(tgzFull));
            table.AddRow(Markup.Escape(unityPackagePath), contents.Assets.Count.ToString("N0", CultureInfo.InvariantCulture) + " assets", Size(unityFull));
            AnsiConsole.Write(table);
            AnsiConsole.WriteLine(string.Format(CultureInfo.InvariantCulture, "Packed in {0:0.0} s.", clock.Elapsed.TotalSeconds));
            return 0;
        }

        private static string Size(string path)
        {
            long bytes = new FileInfo(path).Length;
            return string.Format(CultureInfo.InvariantCulture, "{0:N0} bytes ({1:0.00} MB)", bytes, bytes / 1e6);
        }
    }
}
