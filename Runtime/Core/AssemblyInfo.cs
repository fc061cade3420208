using System.Runtime.CompilerServices;

// Only the API users call is public. In Unity, Core's internals are visible to the test assemblies and to
// the package's Editor-only assemblies (Evaluation, Editor) and to nothing a player build contains: the
// backends and the Unity glue use public API only (Tools~/UnityCheck's rules hold this on the compiled
// assemblies). The .NET tools that compile Core in place (the CLI, benchmarks, previews) see them too, but
// only outside Unity (UNITY_5_3_OR_NEWER is defined in every Unity compilation).
[assembly: InternalsVisibleTo("DeltaInterpolator.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.OnnxRuntime.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation.OnnxRuntime.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation.OnnxRuntime.Tests")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Evaluation")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Editor")]
#if !UNITY_5_3_OR_NEWER
[assembly: InternalsVisibleTo("inbetween")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Benchmarks")]
[assembly: InternalsVisibleTo("DeltaInterpolator.Preview")]
#endif
