using System;
using System.IO;
using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Running;

namespace DeltaInterpolator.Benchmarks
{
    /// <summary>
    /// Core micro-benchmarks (BenchmarkDotNet). From the repository root:
    /// <code>dotnet run -c Release --project Tools~/Benchmarks -- --filter '*'</code>
    /// (<c>--job short</c> for a quick look). Reports go to Tools~/.build/BenchmarkDotNet.Artifacts, never
    /// beside the package sources.
    /// </summary>
    public static class Program
    {
        public static void Main(string[] args)
        {
            // bin/Release/net10.0 → Tools~/.build
            string artifacts = Path.GetFullPath(Path.Combine(AppContext.BaseDirectory, "..", "..", "..", "..", "BenchmarkDotNet.Artifacts"));
            BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args, DefaultConfig.Instance.WithArtifactsPath(artifacts));
        }
    }
}
