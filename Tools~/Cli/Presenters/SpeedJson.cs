using System;
using System.Globalization;
using System.Text.Json.Nodes;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Evaluation.Speed;
using DeltaInterpolator.OnnxRuntime;

namespace DeltaInterpolator.Cli.Presenters
{
    /// <summary>
    /// The JSON document of <c>inbetween speed</c> (the keys its <c>--json</c> help lists, in a fixed order),
    /// built from Evaluation's <see cref="SpeedResults"/>, the trainer's PyTorch timings and the crowd's.
    /// <see cref="SpeedTable"/> prints from this document, so the table and the file never disagree.
    /// </summary>
    internal static class SpeedJson
    {
        /// <summary>The whole document.</summary>
        /// <param name="modelPath">The model file timed, as given.</param>
        /// <param name="contract">Its contract (name).</param>
        /// <param name="threads">Intra-op threads it ran on.</param>
        /// <param name="repeats">The most timed runs per measurement.</param>
        /// <param name="speed">Evaluation's measurements.</param>
        /// <param name="pytorch">The trainer's JSON (<see cref="Speed.PyTorchSpeed"/>), or null without <c>--pytorch</c>.</param>
        /// <param name="crowd">The crowd object (<see cref="Crowd"/>), or null when the crowd did not run.</param>
        public static JsonObject Results(string modelPath, ModelContract contract, int threads, int repeats, SpeedResults speed, JsonObject? pytorch, JsonObject? crowd)
        {
            var results = new JsonObject
            {
                ["model"] = modelPath,
                ["name"] = contract.Name,
                ["threads"] = threads,
                ["past_frames"] = RuntimeSpeed.PastFrames,
                ["onnxruntime"] = OnnxRuntimeBackend.RuntimeVersion,
                ["processors"] = Environment.ProcessorCount,
                ["repeats"] = repeats,
            };

            var transition = new JsonObject();
            var network = new JsonObject();
            for (int i = 0; i < RuntimeSpeed.Lengths.Count; i++)
            {
                transition[Key(RuntimeSpeed.Lengths[i])] = Timing(speed.Transition[i]);
                network[Key(RuntimeSpeed.Lengths[i])] = Timing(speed.Network[i]);
            }

            results["transition_ms"] = transition;
            results["network_ms"] = network;
            if (speed.LazyFrame is Timing frame && speed.LazyKeys is Timing keys)
            {
                results["lazy_keys_ms"] = Timing(keys);
                results["lazy_frame_ms"] = Timing(frame);
                results["lazy_frame_fraction_of_transition_30"] = speed.LazyFrameFraction!.Value;
            }
            else
            {
                results["lazy_frame_ms"] = null;
            }

            results["slerp_fk_us"] = Timing(speed.SlerpFk);
            results["alloc_bytes_per_transition"] = speed.AllocatedBytesPerTransition;
            if (pytorch != null)
            {
                results["pytorch"] = new JsonObject { ["torch"] = pytorch["torch"]?.DeepClone(), ["parameters"] = pytorch["parameters"]?.DeepClone(), ["paper_parameters"] = pytorch["paper_parameters"]?.DeepClone() };
                results["pytorch_transition_ms"] = pytorch["transition_ms"]!.DeepClone();
                var speedup = new JsonObject();
                foreach (int n in RuntimeSpeed.Lengths)
                {
                    double torchMs = pytorch["transition_ms"]![Key(n)]!["median"]!.GetValue<double>();
                    speedup[Key(n)] = speed.SpeedupOver(torchMs, n);
                }

                results["speedup_vs_pytorch"] = speedup;
                results["paper_pytorch_transition_ms"] = pytorch["paper_transition_ms"]?.DeepClone();
            }
            else
            {
                results["pytorch_transition_ms"] = null;
                results["speedup_vs_pytorch"] = null;
                results["paper_pytorch_transition_ms"] = null;
            }

            if (crowd != null) results["crowd"] = crowd;
            return results;
        }

        /// <summary>The "crowd" object of the document.</summary>
        public static JsonObject Crowd(CrowdTimings crowd) => new JsonObject
        {
            ["characters"] = crowd.Characters,
            ["frozen_frames"] = crowd.FrozenFrames,
            ["frames_late"] = crowd.FramesLate,
            ["request_main_thread_ms"] = crowd.RequestMainThreadMs,
            ["all_first_frames_ms"] = crowd.AllFirstFramesMs,
            ["all_frames_ms"] = crowd.AllFramesMs,
            ["frame_ms_batched"] = crowd.FrameMsBatched,
            ["frame_ms_unbatched"] = crowd.FrameMsUnbatched,
            ["step_ms_batched"] = crowd.StepMsBatched,
            ["step_ms_unbatched"] = crowd.StepMsUnbatched,
        };

        /// <summary>A length as a JSON key ("5", "15", "30").</summary>
        public static string Key(int n) => n.ToString(CultureInfo.InvariantCulture);

        private static JsonObject Timing(Timing t) => new JsonObject { ["median"] = Math.Round(t.Median, 6), ["p95"] = Math.Round(t.P95, 6), ["samples"] = t.Samples };
    }
}
