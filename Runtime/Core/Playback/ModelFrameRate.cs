using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Json;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>The frame rate a model was trained at: <c>training.fps</c> in its contract metadata.</summary>
    internal static class ModelFrameRate
    {
        /// <exception cref="ModelContractException">The metadata has no positive <c>training.fps</c>.</exception>
        public static double Of(ModelContract contract)
        {
            JsonValue root = JsonValue.Parse(contract.DescriptionJson, contract.Source + " metadata 'deltainterp'");
            IReadOnlyDictionary<string, JsonValue> members = root.ExpectObject("the 'deltainterp' metadata");
            if (members.TryGetValue("training", out JsonValue? training) &&
                training.ExpectObject("training").TryGetValue("fps", out JsonValue? fps) &&
                fps.Kind == JsonKind.Number && fps.ExpectNumber("training.fps") > 0)
            {
                return fps.ExpectNumber("training.fps");
            }

            throw new ModelContractException(contract.Source, "metadata 'deltainterp' has no positive training.fps",
                "expected the frame rate the model was trained at (python3 -m deltainterp export writes it); export the checkpoint again");
        }
    }
}
