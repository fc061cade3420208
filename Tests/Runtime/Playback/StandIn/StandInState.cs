using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// A state of the stand-in controller: one clip, or a 1D blend tree of two clips blended by the controller's parameter (0: the
    /// first clip, 1: the second), both at the same normalized time, as Unity's blend trees synchronise their motions.
    /// </summary>
    public sealed class StandInState
    {
        private readonly StandInClip _first;
        private readonly StandInClip? _second;
        private readonly double[] _secondRotations;

        /// <summary>A single-clip state.</summary>
        public StandInState(string name, StandInClip clip, int tagHash = 0)
            : this(name, clip, null, tagHash)
        {
        }

        /// <summary>A 1D blend tree of <paramref name="first"/> (parameter 0) and <paramref name="second"/> (parameter 1).</summary>
        public StandInState(string name, StandInClip first, StandInClip? second, int tagHash = 0)
        {
            Name = name;
            Hash = name.GetHashCode();
            TagHash = tagHash;
            _first = first;
            _second = second;
            _secondRotations = new double[4 * first.BoneCount];
        }

        /// <summary>The state's name.</summary>
        public string Name { get; }

        /// <summary>Its hash (a stand-in for <c>Animator.StringToHash</c>).</summary>
        public int Hash { get; }

        /// <summary>Its tag's hash.</summary>
        public int TagHash { get; }

        /// <summary>Bones per pose.</summary>
        public int BoneCount => _first.BoneCount;

        /// <summary>True for a blend tree.</summary>
        public bool IsBlendTree => _second != null;

        /// <summary>Seconds the state lasts at the parameter value (a blend tree's length blends its clips' lengths).</summary>
        public double Length(double parameter) => _second == null ? _first.Length : _first.Length + parameter * (_second.Length - _first.Length);

        /// <summary>
        /// The state <paramref name="seconds"/> after its start at the parameter value: the root's height, every bone's rotation, and the
        /// root's place on the ground (x, z; a blend tree blends its clips' places as it blends their motion).
        /// </summary>
        public void Sample(double seconds, double parameter, out double height, Span<double> rotations, out double travelX, out double travelZ)
        {
            if (_second == null)
            {
                _first.Sample(seconds, out height, rotations, out travelX, out travelZ);
                return;
            }

            double u = seconds / Length(parameter);
            _first.Sample(u * _first.Length, out double h1, rotations, out double x1, out double z1);
            Span<double> other = new Span<double>(_secondRotations, 0, rotations.Length);
            _second.Sample(u * _second.Length, out double h2, other, out double x2, out double z2);
            height = h1 + parameter * (h2 - h1);
            travelX = x1 + parameter * (x2 - x1);
            travelZ = z1 + parameter * (z2 - z1);
            for (int b = 0; b < rotations.Length; b += 4)
            {
                Quaternions.Normalize(Quaternions.Slerp(QuaternionD.Read(rotations, b), QuaternionD.Read(other, b), parameter)).Write(rotations, b);
            }
        }
    }
}
