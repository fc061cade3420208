using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Skeletons
{
    /// <summary>
    /// A joint hierarchy: names, parent indices and rest offsets (local translation of each joint from
    /// its parent, in data units). Immutable and validated on construction: exactly one root at index 0,
    /// every parent listed before its children, unique non-empty names.
    /// </summary>
    public sealed class Skeleton
    {
        private readonly string[] _names;
        private readonly int[] _parents;
        private readonly double[] _offsets;
        private readonly Dictionary<string, int> _indexByName;

        /// <summary>Creates a validated skeleton.</summary>
        /// <param name="names">Joint names, unique and non-empty.</param>
        /// <param name="parents">Parent index per joint: −1 for the root (index 0 only), otherwise a smaller index.</param>
        /// <param name="offsets">Flat joints × 3 rest offsets (x, y, z) per joint; the root's is its rest position.</param>
        /// <exception cref="ArgumentException">The hierarchy is not valid; the message names the joint.</exception>
        public Skeleton(IReadOnlyList<string> names, IReadOnlyList<int> parents, IReadOnlyList<double> offsets)
        {
            if (names == null) throw new ArgumentNullException(nameof(names));
            if (parents == null) throw new ArgumentNullException(nameof(parents));
            if (offsets == null) throw new ArgumentNullException(nameof(offsets));
            int count = names.Count;
            if (count == 0)
            {
                throw new ArgumentException("a skeleton needs at least one joint (the root)", nameof(names));
            }

            if (parents.Count != count)
            {
                throw new ArgumentException($"{parents.Count} parents for {count} joints; expected one parent per joint", nameof(parents));
            }

            if (offsets.Count != 3 * count)
            {
                throw new ArgumentException($"{offsets.Count} offset values for {count} joints; expected 3 per joint", nameof(offsets));
            }

            _names = new string[count];
            _parents = new int[count];
            _offsets = new double[3 * count];
            _indexByName = new Dictionary<string, int>(count, StringComparer.Ordinal);
            for (int j = 0; j < count; j++)
            {
                string name = names[j];
                if (string.IsNullOrWhiteSpace(name))
                {
                    throw new ArgumentException($"joint {j} has an empty name", nameof(names));
                }

                if (_indexByName.ContainsKey(name))
                {
                    throw new ArgumentException($"joint name '{name}' is used by joints {_indexByName[name]} and {j}; names must be unique", nameof(names));
                }

                int parent = parents[j];
                if (j == 0 && parent != -1)
                {
                    throw new ArgumentException($"joint 0 ('{name}') has parent {parent}; the root must come first with parent -1", nameof(parents));
                }

                if (j > 0 && parent == -1)
                {
                    throw new ArgumentException($"joint {j} ('{name}') is a second root; a skeleton has exactly one root, at index 0", nameof(parents));
                }

                if (j > 0 && (parent < 0 || parent >= j))
                {
                    throw new ArgumentException($"joint {j} ('{name}') has parent {parent}; a parent must be listed before its children", nameof(parents));
                }

                _names[j] = name;
                _parents[j] = parent;
                _indexByName.Add(name, j);
            }

            for (int i = 0; i < _offsets.Length; i++)
            {
                double v = offsets[i];
                if (double.IsNaN(v) || double.IsInfinity(v))
                {
                    throw new ArgumentException($"offset of joint {i / 3} ('{_names[i / 3]}') is not finite", nameof(offsets));
                }

                _offsets[i] = v;
            }
        }

        /// <summary>Number of joints.</summary>
        public int JointCount => _names.Length;

        /// <summary>Joint names in hierarchy order.</summary>
        public IReadOnlyList<string> Names => _names;

        /// <summary>Parent index per joint (−1 for the root).</summary>
        public IReadOnlyList<int> Parents => _parents;

        /// <summary>Flat joints × 3 rest offsets.</summary>
        public IReadOnlyList<double> Offsets => _offsets;

        /// <summary>Direct read-only access to the parents for hot loops.</summary>
        public ReadOnlySpan<int> ParentSpan => _parents;

        /// <summary>Direct read-only access to the offsets for hot loops.</summary>
        public ReadOnlySpan<double> OffsetSpan => _offsets;

        /// <summary>Index of the joint called <paramref name="name"/>, or −1.</summary>
        public int IndexOf(string name) => _indexByName.TryGetValue(name, out int index) ? index : -1;

        /// <summary>A skeleton with the same joints and hierarchy but other offsets (joints × 3 values).</summary>
        public Skeleton WithOffsets(IReadOnlyList<double> offsets) => new Skeleton(_names, _parents, offsets);

        /// <summary>True when both have the same joint names in the same order and the same parents.</summary>
        public bool HasSameHierarchy(Skeleton other)
        {
            if (other == null || other.JointCount != JointCount) return false;
            for (int j = 0; j < JointCount; j++)
            {
                if (other._parents[j] != _parents[j] || !string.Equals(other._names[j], _names[j], StringComparison.Ordinal))
                {
                    return false;
                }
            }

            return true;
        }
    }
}
