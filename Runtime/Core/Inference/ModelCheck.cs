using System;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// One result of checking a model against this runtime, a skeleton or a request: what was found and
    /// what to do about it. The command line prints these (<c>inbetween check</c>) and the editor's model
    /// inspector shows them as help boxes; errors are also what loading throws as
    /// <see cref="ModelContractException"/>.
    /// </summary>
    public sealed class ModelCheck
    {
        /// <summary>Creates a result.</summary>
        /// <param name="severity">How much it matters.</param>
        /// <param name="source">The model file or asset the result is about (used in messages).</param>
        /// <param name="message">What was found, e.g. <c>"the model has contract version 2"</c>.</param>
        /// <param name="remedy">What was expected and what to do, e.g. <c>"expected a version from 1 to 1; update the package"</c>.</param>
        public ModelCheck(CheckSeverity severity, string source, string message, string remedy)
        {
            Severity = severity;
            Source = source ?? "<model>";
            Message = message ?? throw new ArgumentNullException(nameof(message));
            Remedy = remedy ?? "";
        }

        /// <summary>How much it matters.</summary>
        public CheckSeverity Severity { get; }

        /// <summary>The model file or asset the result is about.</summary>
        public string Source { get; }

        /// <summary>What was found.</summary>
        public string Message { get; }

        /// <summary>What was expected and what to do (starts with "expected" for errors and warnings).</summary>
        public string Remedy { get; }

        /// <summary>The exception loading throws for this result (the one-line <c>FILE:0: what; expected</c> form).</summary>
        public ModelContractException ToException() => new ModelContractException(Source, Message, Remedy);

        /// <summary><c>Error: FILE: what; remedy</c>.</summary>
        public override string ToString() => Severity + ": " + Source + ": " + Message + (Remedy.Length > 0 ? "; " + Remedy : "");
    }
}
