using System.Runtime.CompilerServices;

// Only the API users call is public; the tests, the tools and the package's other assemblies (backends,
// Unity glue, editor, evaluation) also see Core's internals. Assembly names as in their .asmdef / .csproj.
[assembly: InternalsVisibleTo("DeltaInterpolator.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.OnnxRuntime.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation.OnnxRuntime.Tests")]
[assembly: InternalsVisibleTo("inbetween")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Benchmarks")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation")]
[assembly: InternalsVisibleTo("DeltaInterpolator.OnnxRuntime")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Sentis")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Unity")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Editor")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Preview")]
