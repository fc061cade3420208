using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>Reads members of one JSON object, reporting a missing or mistyped member as an error and returning a fallback.</summary>
    internal sealed class MetadataFields
    {
        private readonly string _source;
        private readonly IReadOnlyDictionary<string, JsonValue> _obj;
        private readonly ModelCheckReport _report;
        private readonly string _prefix;

        public MetadataFields(string source, IReadOnlyDictionary<string, JsonValue> obj, ModelCheckReport report, string prefix = "")
        {
            _source = source;
            _obj = obj;
            _report = report;
            _prefix = prefix;
        }

        public void Missing(string key)
        {
            _report.Error(_source, $"metadata 'deltainterp' has no \"{_prefix}{key}\"",
                $"expected every field of contract version {ModelContract.Version} (Documentation~/model-contract.md); export the checkpoint again");
        }

        public T Guard<T>(Func<T> read, T fallback)
        {
            try
            {
                return read();
            }
            catch (DataFormatException e)
            {
                _report.Error(_source, "metadata 'deltainterp': " + e.Problem, e.Expected);
                return fallback;
            }
        }

        public JsonValue? Member(string key)
        {
            if (_obj.TryGetValue(key, out JsonValue? v)) return v;
            Missing(key);
            return null;
        }

        public double Number(string key, string what, double fallback)
        {
            JsonValue? v = Member(key);
            return v == null ? fallback : Guard(() => v.ExpectNumber(what), fallback);
        }

        public int Int(string key, string what, int fallback) => (int)Number(key, what, fallback);

        public string String(string key, string what, string fallback)
        {
            JsonValue? v = Member(key);
            return v == null ? fallback : Guard(() => v.ExpectString(what), fallback);
        }

        public IReadOnlyDictionary<string, JsonValue>? Object(string key)
        {
            JsonValue? v = Member(key);
            return v == null ? null : Guard(() => v.ExpectObject(_prefix + key), null);
        }

        public IReadOnlyList<JsonValue>? Array(string key)
        {
            JsonValue? v = Member(key);
            return v == null ? null : Guard(() => v.ExpectArray(_prefix + key), null);
        }

        public Vector3D Axis(string key, Vector3D fallback)
        {
            JsonValue? v = Member(key);
            if (v == null) return fallback;
            double[]? a = Guard(() => v.ExpectNumbers(_prefix + key, 3), null);
            return a == null ? fallback : new Vector3D(a[0], a[1], a[2]);
        }

        public string Convention(string key, string value, string why)
        {
            string actual = String(key, key, value);
            if (!string.Equals(actual, value, StringComparison.Ordinal))
            {
                _report.Error(_source, $"metadata {key} is '{actual}'", $"expected \"{value}\": {why}");
            }

            return actual;
        }

        public (int, int) Range(string key)
        {
            if (!_obj.TryGetValue(key, out JsonValue? v)) return (0, 0);
            double[]? r = Guard(() => v.ExpectNumbers(_prefix + key, 2), null);
            return r == null ? (0, 0) : ((int)r[0], (int)r[1]);
        }
    }
}
