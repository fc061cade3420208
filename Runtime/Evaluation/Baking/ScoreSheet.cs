using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>
    /// <c>score</c>'s use case after the bakes: one <see cref="ScoreRow"/> per file and the frame-weighted
    /// totals per subject and over every file (every non-key frame counts once), with each method's ratio to
    /// the last method (SLERP, the baseline).
    /// </summary>
    public sealed class ScoreSheet
    {
        private readonly List<ScoreRow> _rows = new List<ScoreRow>();

        /// <summary>An empty sheet for <paramref name="methods"/>, the baseline last.</summary>
        public ScoreSheet(IReadOnlyList<string> methods)
        {
            if (methods == null || methods.Count < 1) throw new ArgumentException("expected at least one method", nameof(methods));
            Methods = methods;
        }

        /// <summary>The methods' names, the baseline last.</summary>
        public IReadOnlyList<string> Methods { get; }

        /// <summary>The files' rows in the order they were added.</summary>
        public IReadOnlyList<ScoreRow> Rows => _rows;

        /// <summary>Adds a file's row.</summary>
        /// <exception cref="ArgumentException">Its method count differs from the sheet's.</exception>
        public void Add(ScoreRow row)
        {
            if (row.Errors.L2Q.Count != Methods.Count) throw new ArgumentException($"{row.File}: {row.Errors.L2Q.Count} methods; expected {Methods.Count}", nameof(row));
            _rows.Add(row);
        }

        /// <summary>The rows by subject (sorted by name; files without one under "").</summary>
        public SortedDictionary<string, List<ScoreRow>> Groups()
        {
            var groups = new SortedDictionary<string, List<ScoreRow>>(StringComparer.Ordinal);
            foreach (ScoreRow r in _rows)
            {
                if (!groups.TryGetValue(r.Group, out List<ScoreRow>? list)) groups[r.Group] = list = new List<ScoreRow>();
                list.Add(r);
            }

            return groups;
        }

        /// <summary>Frame-weighted means of <paramref name="rows"/> per method.</summary>
        public ScoreTotal Total(IEnumerable<ScoreRow> rows)
        {
            int methods = Methods.Count;
            var p = new double[methods];
            var q = new double[methods];
            var skate = new double[methods];
            double truthSkate = 0;
            int frames = 0, files = 0, contacts = 0;
            foreach (ScoreRow r in rows)
            {
                files++;
                frames += r.Frames;
                for (int i = 0; i < methods; i++)
                {
                    p[i] += r.Errors.PositionPerLeg[i] * r.Frames;
                    q[i] += r.Errors.L2Q[i] * r.Frames;
                    if (r.Errors.ContactSamples > 0) skate[i] += r.Errors.FootSkating[i] * r.Errors.ContactSamples;
                }

                if (r.Errors.ContactSamples > 0) truthSkate += r.Errors.TruthFootSkating * r.Errors.ContactSamples;
                contacts += r.Errors.ContactSamples;
            }

            for (int i = 0; i < methods; i++)
            {
                p[i] /= Math.Max(1, frames);
                q[i] /= Math.Max(1, frames);
                skate[i] = contacts > 0 ? skate[i] / contacts : double.NaN;
            }

            // Foot skating is a mean over planted (frame, joint) pairs, so it is weighted by them, not by frames.
            return new ScoreTotal(files, frames, new MethodErrors(p, q, skate, contacts, contacts > 0 ? truthSkate / contacts : double.NaN));
        }

        /// <summary>Every file's total.</summary>
        public ScoreTotal Total() => Total(_rows);
    }
}
