using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// One fill as an edit of a clip's curves: for every curve it changes, the curve before and after. Applying it
    /// to the curves it was made from gives the filled clip; its <see cref="Inverse"/> applied to that gives the
    /// original back, key for key and bit for bit. The editor writes <see cref="Changes"/>' after-curves under one
    /// Undo step; Core tests apply and invert it.
    /// </summary>
    public sealed class KeyFillEdit
    {
        private readonly CurveChange[] _changes;

        internal KeyFillEdit(string clip, CurveChange[] changes, int filledKeys)
        {
            Clip = clip;
            _changes = changes;
            FilledKeys = filledKeys;
        }

        /// <summary>The clip's name.</summary>
        public string Clip { get; }

        /// <summary>Every curve the edit changes, in the clip's curve order.</summary>
        public IReadOnlyList<CurveChange> Changes => _changes;

        /// <summary>Keys the edit adds (over every curve).</summary>
        public int FilledKeys { get; }

        /// <summary>The edit that takes the filled clip back to the original.</summary>
        public KeyFillEdit Inverse()
        {
            var inverse = new CurveChange[_changes.Length];
            for (int i = 0; i < inverse.Length; i++) inverse[i] = new CurveChange(_changes[i].After, _changes[i].Before);
            return new KeyFillEdit(Clip, inverse, -FilledKeys);
        }

        /// <summary>
        /// <paramref name="curves"/> with the edit applied: each changed curve replaced by its after-curve, every other
        /// curve the same object. Refused when a curve the edit changes is not in <paramref name="curves"/> as it was
        /// before (the clip changed since the fill was planned).
        /// </summary>
        /// <exception cref="KeyFillException">A changed curve is missing or differs from the edit's before-curve (<c>curves</c>).</exception>
        public IReadOnlyList<KeyedCurve> Apply(IReadOnlyList<KeyedCurve> curves)
        {
            if (curves == null) throw new ArgumentNullException(nameof(curves));
            var result = new KeyedCurve[curves.Count];
            var used = new bool[_changes.Length];
            for (int i = 0; i < curves.Count; i++)
            {
                KeyedCurve curve = curves[i] ?? throw new ArgumentNullException(nameof(curves), "a curve of the list is null");
                result[i] = curve;
                for (int c = 0; c < _changes.Length; c++)
                {
                    CurveChange change = _changes[c];
                    if (used[c] || change.Before.Path != curve.Path || change.Before.Property != curve.Property) continue;
                    if (!change.Before.SameAs(curve))
                    {
                        throw new KeyFillException(Clip, $"{curve} changed since the fill was planned", "expected the clip as it was when the fill was made (fill again)", nameof(curves));
                    }

                    result[i] = change.After;
                    used[c] = true;
                    break;
                }
            }

            for (int c = 0; c < _changes.Length; c++)
            {
                if (!used[c]) throw new KeyFillException(Clip, $"{_changes[c].Before} is not in the clip", "expected the clip the fill was made on (fill again)", nameof(curves));
            }

            return result;
        }

        /// <summary>One curve's change: the same binding, its keys before and after.</summary>
        public sealed class CurveChange
        {
            internal CurveChange(KeyedCurve before, KeyedCurve after)
            {
                Before = before;
                After = after;
            }

            /// <summary>The curve as it was.</summary>
            public KeyedCurve Before { get; }

            /// <summary>The curve as the edit leaves it.</summary>
            public KeyedCurve After { get; }
        }
    }
}
