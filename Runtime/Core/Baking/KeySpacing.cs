using System;
using System.Globalization;

namespace DeltaInterpolator.Core.Baking
{
    /// <summary>What a key spacing is counted in.</summary>
    public enum KeySpacingUnit
    {
        /// <summary>Frames of the clip as it is (a bare number on the CLI: <c>--every 60</c>).</summary>
        InputFrames,

        /// <summary>Frames at the model's rate (<c>--every 15mf</c>): the unit the model's trained gap range is in.</summary>
        ModelFrames,

        /// <summary>Seconds (<c>--every 0.5s</c>): the same keys at any frame rate.</summary>
        Seconds,
    }

    /// <summary>
    /// A spacing between keys in one of three units (<see cref="KeySpacingUnit"/>), the one value the CLI's
    /// <c>--every</c> and the editor baker's "every N" hold; <see cref="KeyPlanner"/> places the keys.
    /// </summary>
    public readonly struct KeySpacing
    {
        /// <summary>The largest value accepted in any unit (a day of frames at 1000 fps).</summary>
        public const double MaxValue = 86_400_000;

        /// <summary>Creates a spacing; refused unless <paramref name="value"/> is positive and finite (whole for frames).</summary>
        /// <exception cref="ArgumentOutOfRangeException">Not positive, not finite, too large, or a fraction of a frame.</exception>
        public KeySpacing(double value, KeySpacingUnit unit)
        {
            if (!(value > 0) || !(value <= MaxValue)) throw new ArgumentOutOfRangeException(nameof(value), value, "expected a positive spacing");
            if (unit != KeySpacingUnit.Seconds && value != Math.Floor(value)) throw new ArgumentOutOfRangeException(nameof(value), value, "expected a whole number of frames");
            if (unit != KeySpacingUnit.InputFrames && unit != KeySpacingUnit.ModelFrames && unit != KeySpacingUnit.Seconds) throw new ArgumentOutOfRangeException(nameof(unit), unit, "expected input frames, model frames or seconds");
            Value = value;
            Unit = unit;
        }

        /// <summary>The number.</summary>
        public double Value { get; }

        /// <summary>Its unit.</summary>
        public KeySpacingUnit Unit { get; }

        /// <summary>How the CLI writes the three units: <c>60</c> (input frames, the default), <c>15mf</c> (model frames), <c>0.5s</c> (seconds).</summary>
        public const string Syntax = "a whole number of input frames (60, the default), of model frames (15mf), or seconds (0.5s)";

        /// <summary>
        /// Reads <paramref name="text"/>: a whole number of input frames (<c>60</c>, or <c>60f</c>), of model frames
        /// (<c>15mf</c>) or a number of seconds (<c>0.5s</c>); null for anything else.
        /// </summary>
        public static KeySpacing? Parse(string? text)
        {
            if (text == null) return null;
            string t = text.Trim();
            KeySpacingUnit unit = KeySpacingUnit.InputFrames;
            if (t.EndsWith("mf", StringComparison.OrdinalIgnoreCase))
            {
                unit = KeySpacingUnit.ModelFrames;
                t = t.Substring(0, t.Length - 2);
            }
            else if (t.EndsWith("s", StringComparison.OrdinalIgnoreCase))
            {
                unit = KeySpacingUnit.Seconds;
                t = t.Substring(0, t.Length - 1);
            }
            else if (t.EndsWith("f", StringComparison.OrdinalIgnoreCase))
            {
                t = t.Substring(0, t.Length - 1);
            }

            NumberStyles style = unit == KeySpacingUnit.Seconds ? NumberStyles.AllowDecimalPoint : NumberStyles.None;
            if (t.Length == 0 || t.Length > 16 || !double.TryParse(t, style, CultureInfo.InvariantCulture, out double v)) return null;
            if (!(v > 0) || !(v <= MaxValue) || (unit != KeySpacingUnit.Seconds && v != Math.Floor(v))) return null;
            return new KeySpacing(v, unit);
        }

        /// <summary>The spacing in seconds for a clip of <paramref name="inputFrameTime"/> seconds per frame and a model at <paramref name="modelFps"/>.</summary>
        public double Seconds(double inputFrameTime, double modelFps) => Unit switch
        {
            KeySpacingUnit.InputFrames => Value * inputFrameTime,
            KeySpacingUnit.ModelFrames => Value / modelFps,
            _ => Value,
        };

        /// <summary>The spacing in all three units, e.g. "every 0.5 s = 15 model frames = 60 input frames (at 120 fps)".</summary>
        public string Describe(double inputFrameTime, double modelFps)
        {
            double s = Seconds(inputFrameTime, modelFps);
            return string.Format(CultureInfo.InvariantCulture, "every {0:0.###} s = {1:0.##} model frames (at {2:0.##} fps) = {3:0.##} input frames (at {4:0.##} fps)",
                s, s * modelFps, modelFps, s / inputFrameTime, 1 / inputFrameTime);
        }

        /// <inheritdoc />
        public override string ToString() => Unit switch
        {
            KeySpacingUnit.InputFrames => Value.ToString("0", CultureInfo.InvariantCulture),
            KeySpacingUnit.ModelFrames => Value.ToString("0", CultureInfo.InvariantCulture) + "mf",
            _ => Value.ToString("0.###", CultureInfo.InvariantCulture) + "s",
        };
    }
}
