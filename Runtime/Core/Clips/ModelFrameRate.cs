using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Json;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// The frame rate a model was trained at (<c>training.fps</c> of the contract's metadata): key frames
    /// are counted and baked clips are sampled at this rate, whatever the source clip's rate.
    /// </summary>
    public static class ModelFrameRate
    {
        /// <summary>The rate assumed when the metadata does not say (LaFAN1 and the shipped model: 30).</summary>
        public const double Default = 30;

        /// <summary>The model's training frame rate, or <see cref="Default"/> when its metadata has none.</summary>
        public static double Of(ModelContract contract) => FromContractJson(contract.DescriptionJson, contract.Source);

        /// <summary>Reads <c>training.fps</c> from the contract's JSON object.</summary>
        /// <exception cref="DataFormatException">The JSON is malformed or <c>training.fps</c> is not a positive number.</exception>
        public static double FromContractJson(string json, string source)
        {
            if (string.IsNullOrWhiteSpace(json)) return Default;
            IReadOnlyDictionary<string, JsonValue> root = JsonValue.Parse(json, source).ExpectObject("the 'deltainterp' metadata");
            if (!root.TryGetValue("training", out JsonValue? training)) return Default;
            if (!training.ExpectObject("training").TryGetValue("fps", out JsonValue? fps)) return Default;
            double value = fps.ExpectNumber("training.fps");
            if (!(value > 0) || double.IsInfinity(value))
            {
                throw new DataFormatException(source, fps.Line, $"training.fps is {value}", "expected a positive number of frames per second");
            }

            return value;
        }
    }
}
