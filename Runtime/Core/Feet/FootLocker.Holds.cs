using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>Where a planted joint is held on each frame, within the leg's reach, and how strongly (easing in and out).</summary>
    public sealed partial class FootLocker
    {
        /// <summary>Where channel c is held on each of its contact frames (per contact: through its keys, or its mean).</summary>
        private void Anchor(int c, double leg)
        {
            int cap = _capacity, row = c * cap, n = _frames;
            for (int s = 0; NextContact(row, ref s, out int e); s = e + 1)
            {
                int firstKey = -1, lastKey = -1;
                for (int f = s; f <= e; f++)
                {
                    if (!_isKey[f]) continue;
                    if (firstKey < 0) firstKey = f;
                    lastKey = f;
                }

                if (firstKey >= 0)
                {
                    // Through the keys: held where they have it, linearly from key to key.
                    int previousKey = firstKey;
                    for (int f = s; f <= e; f++)
                    {
                        int at = (row + f) * 3;
                        if (f <= firstKey || f >= lastKey)
                        {
                            Copy(_feet, (row + (f <= firstKey ? firstKey : lastKey)) * 3, _anchor, at);
                            continue;
                        }

                        if (_isKey[f])
                        {
                            previousKey = f;
                            Copy(_feet, at, _anchor, at);
                            continue;
                        }

                        int nextKey = f + 1;
                        while (!_isKey[nextKey]) nextKey++;
                        double t = (f - previousKey) / (double)(nextKey - previousKey);
                        Lerp(Vector3D.Read(_feet, (row + previousKey) * 3), Vector3D.Read(_feet, (row + nextKey) * 3), t).Write(_anchor, at);
                    }
                }
                else
                {
                    // Between keys: its mean position, at a height near its planted height.
                    double x = 0, rise = 0, z = 0;
                    for (int f = s; f <= e; f++)
                    {
                        int i = (row + f) * 3;
                        x += _feet[i];
                        rise += _rise[f];
                        z += _feet[i + 2];
                    }

                    int count = e - s + 1;
                    rise = Math.Max(-0.01 * leg, Math.Min(0.01 * leg, rise / count));
                    var held = new Vector3D(x / count, GroundAt(x / count, z / count, s, _keys!) + _plantedHeight[c] + rise, z / count);
                    for (int f = s; f <= e; f++) held.Write(_anchor, (row + f) * 3);
                }

            }
        }

        /// <summary>
        /// Moves each contact frame's target that the leg cannot reach towards where the filled motion has the joint,
        /// just as far as the leg reaches. Dropping the frame instead would split the contact, and the rest of it would be
        /// held at a spot of its own: the foot would jump there and back. Pulled, it slides only as much as the hips
        /// outrun it, and stays on its spot wherever the leg reaches.
        /// </summary>
        private void PullIntoReach(int c)
        {
            int cap = _capacity, side = c / 2;
            bool toe = (c & 1) == 1;
            double full = TwoBoneIk.MaxExtension * (_thigh[side] + _shin[side]);
            double reach = _settings.MaxReach * (_thigh[side] + _shin[side]);
            for (int f = 0; f < _frames; f++)
            {
                if (_segment[c * cap + f] == 0 || _isKey[f]) continue;
                int at = (c * cap + f) * 3;
                Vector3D anchor = Vector3D.Read(_anchor, at);
                Vector3D hip = Vector3D.Read(_hips, (side * cap + f) * 3);
                // The ankle's target (a toe's less the foot), relative to the hip.
                Vector3D fromHip = toe ? anchor - Vector3D.Read(_toeVector, (side * cap + f) * 3) - hip : anchor - hip;
                // A leg already that straight in the motion may stay so (a standing leg); only a longer reach is refused.
                double now = (Vector3D.Read(_feet, ((2 * side) * cap + f) * 3) - hip).Length;
                double limit = Math.Max(reach, Math.Min(now + 1e-3 * _rig.LegLength, full));
                if (fromHip.Length <= limit) continue;
                // The first point on the way from the target to the filled joint that is within the limit:
                // |fromHip + t·towards| = limit, smallest t in [0, 1] (t = 1, the filled joint, is within it).
                Vector3D towards = Vector3D.Read(_feet, at) - anchor;
                double a = Vector3D.Dot(towards, towards), b = Vector3D.Dot(fromHip, towards), cc = Vector3D.Dot(fromHip, fromHip) - limit * limit;
                double disc = b * b - a * cc;
                double t = a <= 0 || disc < 0 ? 1 : Math.Max(0, Math.Min(1, (-b - Math.Sqrt(disc)) / a));
                (anchor + t * towards).Write(_anchor, at);
                _beyondReach[c * cap + f] = true;
            }
        }

        /// <summary>Weights of channel c: 1 on contact frames, easing to 0 over <paramref name="ease"/> frames before and after, never across a key or into another contact.</summary>
        private void Ease(int c, int ease)
        {
            int cap = _capacity, row = c * cap, n = _frames;
            for (int f = 0; f < n; f++) _weight[row + f] = _segment[row + f] != 0 ? 1 : 0;
            for (int s = 0; NextContact(row, ref s, out int e); s = e + 1)
            {
                for (int d = 1; d <= ease; d++)
                {
                    int f = s - d;
                    if (f < 0 || _isKey[f] || _segment[row + f] != 0) break;
                    Blend(row, f, s, d, ease);
                }

                for (int d = 1; d <= ease; d++)
                {
                    int f = e + d;
                    if (f >= n || _isKey[f] || _segment[row + f] != 0) break;
                    Blend(row, f, e, d, ease);
                }

            }
        }

        /// <summary>Frame f, d frames outside the contact frame <paramref name="edge"/>, eases towards that frame's target (the nearer contact wins).</summary>
        private void Blend(int row, int f, int edge, int d, int ease)
        {
            double x = 1 - d / (double)(ease + 1);
            double w = x * x * (3 - 2 * x);
            if (_settings.EaseReach > 0)
            {
                // A joint the filled motion has carried far from the target is pulled less (a swinging foot is not dragged back).
                double far = (Vector3D.Read(_anchor, (row + edge) * 3) - Vector3D.Read(_feet, (row + f) * 3)).Length;
                w *= Math.Max(0, 1 - far / (_settings.EaseReach * _rig.LegLength));
            }

            if (w <= _weight[row + f]) return;
            _weight[row + f] = w;
            Copy(_anchor, (row + edge) * 3, _anchor, (row + f) * 3);
        }
    }
}
