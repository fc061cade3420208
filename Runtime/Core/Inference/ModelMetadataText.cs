using System;
using System.Collections.Generic;
using System.Text;
using DeltaInterpolator.Core.Json;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// A model's ONNX <c>metadata_props</c> (string keys to string values) as one JSON object of strings,
    /// and back. Sentis shows <c>metadata_props</c> only to an editor callback during import; the editor
    /// stores them with this text inside the imported asset so that a player build, whose Sentis model
    /// has no metadata, still gets the contract.
    /// </summary>
    public static class ModelMetadataText
    {
        /// <summary>The metadata as a JSON object, keys in ordinal order (the same map always gives the same text).</summary>
        public static string Write(IReadOnlyDictionary<string, string> metadata)
        {
            if (metadata == null) throw new ArgumentNullException(nameof(metadata));
            var keys = new List<string>(metadata.Keys);
            keys.Sort(StringComparer.Ordinal);
            var text = new StringBuilder("{");
            for (int i = 0; i < keys.Count; i++)
            {
                if (i > 0) text.Append(", ");
                Quote(text, keys[i]);
                text.Append(": ");
                Quote(text, metadata[keys[i]] ?? "");
            }

            return text.Append('}').ToString();
        }

        /// <summary>Reads text written by <see cref="Write"/>.</summary>
        /// <param name="json">The JSON object.</param>
        /// <param name="source">Where it came from, for messages.</param>
        /// <exception cref="DataFormatException">Not a JSON object of strings.</exception>
        public static Dictionary<string, string> Read(string json, string source)
        {
            IReadOnlyDictionary<string, JsonValue> members = JsonValue.Parse(json, source).ExpectObject("the model metadata");
            var result = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (KeyValuePair<string, JsonValue> m in members)
            {
                result[m.Key] = m.Value.ExpectString("metadata value \"" + m.Key + "\"");
            }

            return result;
        }

        private static void Quote(StringBuilder text, string value) => JsonText.AppendString(text, value);
    }
}
