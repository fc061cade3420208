using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>Where the ground is under each foot joint, from the keys (the class remarks say how).</summary>
    public sealed partial class FootLocker
    {
        /// <summary>
        /// Where the ground is at each key: the lowest foot joint's height and horizontal position (a key whose lowest
        /// joint is above its neighbours' mean, in a jump or a run's flight, takes that mean); each frame's gap.
        /// </summary>
        private void EstimateGround(IReadOnlyList<int> keys)
        {
            int n = keys.Count;
            for (int i = 0; i < n; i++) Support(i, LowestFoot(keys[i], 0, 0, 0), keys[i]);

            // On a slope a foot swinging behind may be lower than the one planted ahead: pick again the lowest
            // foot joint relative to the slope the first guess shows around each key (the previous values are in _scratch).
            double[] first = _scratch;
            Array.Copy(_support, first, 3 * n);
            for (int i = 0; i < n; i++)
            {
                int p = Math.Max(0, i - 1), q = Math.Min(n - 1, i + 1);
                double dx = first[3 * q] - first[3 * p], dz = first[3 * q + 1] - first[3 * p + 1];
                double d = Math.Sqrt(dx * dx + dz * dz);
                if (d < 0.25 * _rig.LegLength) continue;
                double slope = Math.Max(-0.5, Math.Min(0.5, (first[3 * q + 2] - first[3 * p + 2]) / d));
                Support(i, LowestFoot(keys[i], slope, dx / d, dz / d), keys[i]);
            }

            double previous = _support[2];
            for (int i = 0; i < n; i++)
            {
                double here = _support[3 * i + 2];
                double around = n == 1 ? here : i == 0 ? _support[3 * 1 + 2] : i == n - 1 ? previous : 0.5 * (previous + _support[3 * (i + 1) + 2]);
                previous = here;
                _support[3 * i + 2] = Math.Min(here, around);
            }

            int gap = 0;
            for (int f = 0; f < _frames; f++)
            {
                while (gap + 2 < n && f > keys[gap + 1]) gap++;
                _gap[f] = gap;
            }
        }

        /// <summary>
        /// The ground height at horizontal position (x, z) on frame f: on the line through the two keys' ground points
        /// around the frame (so a slope is followed under each foot), or, when those points are close together, their
        /// heights interpolated in time.
        /// </summary>
        private double GroundAt(double x, double z, int f, IReadOnlyList<int> keys)
        {
            int n = keys.Count;
            if (n == 1) return _support[2];
            int i = _gap[f];
            int a = keys[i], b = keys[i + 1];
            double ax = _support[3 * i], az = _support[3 * i + 1], ga = _support[3 * i + 2];
            double dx = _support[3 * (i + 1)] - ax, dz = _support[3 * (i + 1) + 1] - az, gb = _support[3 * (i + 1) + 2];
            double d = Math.Sqrt(dx * dx + dz * dz);
            if (d < 0.25 * _rig.LegLength)
            {
                double t = Math.Max(0, Math.Min(1, (f - a) / (double)(b - a)));
                return ga + t * (gb - ga);
            }

            double slope = Math.Max(-0.5, Math.Min(0.5, (gb - ga) / d));
            double u = Math.Max(-d, Math.Min(2 * d, ((x - ax) * dx + (z - az) * dz) / d));
            return ga + slope * u;
        }

        /// <summary>The channel of the lowest foot joint on a frame, heights measured from a plane rising by <paramref name="slope"/> along (dx, dz).</summary>
        private int LowestFoot(int frame, double slope, double dx, double dz)
        {
            int lowest = -1;
            double best = double.PositiveInfinity;
            for (int c = 0; c < ChannelCount; c++)
            {
                if (_channelJoint[c] < 0) continue;
                int i = (c * _capacity + frame) * 3;
                double height = _feet[i + 1] - slope * (_feet[i] * dx + _feet[i + 2] * dz);
                if (height < best)
                {
                    best = height;
                    lowest = c;
                }
            }

            return lowest;
        }

        private void Support(int key, int channel, int frame)
        {
            int at = (channel * _capacity + frame) * 3;
            _support[3 * key] = _feet[at];
            _support[3 * key + 1] = _feet[at + 2];
            _support[3 * key + 2] = _feet[at + 1];
        }

        /// <summary>The 10th percentile of the joint's height above the ground at the keys, between 1 % of a leg below the ground and its standing height.</summary>
        private double PlantedHeightOf(int c, double leg, IReadOnlyList<int> keys)
        {
            // From the keys only: they are real poses, while filled motion may sink a foot into the floor.
            double[] h = _scratch;
            int n = keys.Count;
            for (int i = 0; i < n; i++) h[i] = _feet[(c * _capacity + keys[i]) * 3 + 1] - _ground[c * _capacity + keys[i]];
            Array.Sort(h, 0, n);
            double low = h[(int)(0.1 * (n - 1))];
            return Math.Max(-0.01 * leg, Math.Min(low, _maxPlantedHeight[c] * leg));
        }
    }
}
