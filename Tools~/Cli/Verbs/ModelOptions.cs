using System;
using System.CommandLine;
using DeltaInterpolator.OnnxRuntime;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// The <c>--model FILE.onnx</c> and <c>--threads N</c> pair of the verbs that run an exported model
    /// through the ONNX Runtime backend (<c>benchmark</c>, <c>speed</c>): one declaration of the two
    /// options and one place where the thread count becomes <see cref="OnnxRuntimeOptions"/>. What the
    /// model is for and which thread counts make sense differ per verb, so each verb passes its own help
    /// texts and lower bound.
    /// </summary>
    internal sealed class ModelOptions
    {
        private readonly string _verb;
        private readonly int _minimumThreads;
        private readonly string _threadsExpected;

        /// <summary>Declares the two options.</summary>
        /// <param name="verb">The verb, for error messages (<c>inbetween VERB: …</c>).</param>
        /// <param name="modelHelp">Help text of <c>--model</c>.</param>
        /// <param name="threadsHelp">Help text of <c>--threads</c> (default 1).</param>
        /// <param name="minimumThreads">The smallest thread count accepted.</param>
        /// <param name="threadsExpected">What to say when the count is below it, after "expected".</param>
        public ModelOptions(string verb, string modelHelp, string threadsHelp, int minimumThreads, string threadsExpected)
        {
            _verb = verb;
            _minimumThreads = minimumThreads;
            _threadsExpected = threadsExpected;
            Model = new Option<string?>("--model") { Description = modelHelp, HelpName = "FILE.onnx" };
            Threads = new Option<int>("--threads") { Description = threadsHelp + " At most the processors of this machine (" + MaximumThreads + ").", HelpName = "N", DefaultValueFactory = _ => 1 };
        }

        /// <summary><c>--model FILE.onnx</c>; null when not given.</summary>
        public Option<string?> Model { get; }

        /// <summary><c>--threads N</c>, ONNX Runtime intra-op threads.</summary>
        public Option<int> Threads { get; }

        /// <summary>
        /// The most threads accepted: the processors of this machine. More only oversubscribe the cores
        /// (1000 threads made a 0.7 s benchmark take 80 s).
        /// </summary>
        public static int MaximumThreads => Math.Max(1, Environment.ProcessorCount);

        /// <summary>
        /// The ONNX Runtime options for <c>--threads</c>, refusing a count below the verb's minimum or above
        /// <see cref="MaximumThreads"/>.
        /// </summary>
        public OnnxRuntimeOptions RuntimeOptions(ParseResult parse)
        {
            int threads = parse.GetValue(Threads);
            if (threads < _minimumThreads)
            {
                throw new CliErrors.UsageException($"inbetween {_verb}: --threads {threads}; expected {_threadsExpected}");
            }

            if (threads > MaximumThreads)
            {
                throw new CliErrors.UsageException($"inbetween {_verb}: --threads {threads} is more than the {MaximumThreads} processors of this machine; expected at most {MaximumThreads} (more threads only compete for the same cores)");
            }

            return new OnnxRuntimeOptions { IntraOpThreads = threads };
        }
    }
}
