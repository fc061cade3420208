using System.Runtime.CompilerServices;

// Only test assemblies see Core's internals. Everything else (the backends, the Unity glue, the Editor-only
// assemblies Evaluation and Editor, and the .NET tools that compile Core in place: the CLI, benchmarks and
// previews) uses Core's public API, so what they need is public and documented. Tools~/UnityCheck's friends
// rule holds this on the compiled assemblies.
[assembly: InternalsVisibleTo("DeltaInterpolator.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.OnnxRuntime.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation.OnnxRuntime.Tests")]
