using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>Which frames each foot joint is planted on: contacts the keys vouch for, those the filled motion shows, or those given.</summary>
    public sealed partial class FootLocker
    {
        /// <summary>
        /// Contacts that the keys vouch for: a foot joint planted on a key (at most <see cref="FootLockSettings.EnterHeight"/>
        /// above its planted height there) stays planted into the gaps beside it while the filled motion keeps it
        /// low and near that spot; two planted keys at the same spot with the foot kept low between them make one
        /// contact across the gap.
        /// </summary>
        private void LabelFromKeys(int c, double leg, IReadOnlyList<int> keys, int ease, double dt, ref int next)
        {
            double fast = _settings.HoldSpeed * leg;
            int cap = _capacity, row = c * cap;
            double enter = _settings.EnterHeight * leg, exit = _settings.ExitHeight * leg;
            double hold = _settings.HoldDistance * leg, step = _settings.StepHeight * leg;
            int first = keys[0];
            if (_rise[first] <= enter) _segment[row + first] = next++;
            // A key's contact carries on into the gap after it only as far as the next key (never over it).
            for (int i = 0; i + 1 < keys.Count; i++)
            {
                int a = keys[i], b = keys[i + 1];
                bool plantedA = _rise[a] <= enter, plantedB = _rise[b] <= enter;
                if (plantedA && plantedB && (Vector3D.Read(_feet, (row + a) * 3) - Vector3D.Read(_feet, (row + b) * 3)).Length <= _settings.BridgeDistance * leg && MaxRise(a, b) <= step)
                {
                    // One contact across the gap (a foot standing through it).
                    for (int f = a + 1; f <= b; f++) _segment[row + f] = _segment[row + a];
                    continue;
                }

                int backStart = b;
                if (plantedB)
                {
                    int id = next++;
                    _segment[row + b] = id;
                    for (int f = b - 1; f > a && _rise[f] <= exit && Horizontal(c, f, b) <= hold && HorizontalSpeed(c, f, dt) <= fast; f--)
                    {
                        _segment[row + f] = id;
                        backStart = f;
                    }
                }

                if (!plantedA) continue;
                int forwardEnd = a;
                for (int f = a + 1; f < backStart && _rise[f] <= exit && Horizontal(c, f, a) <= hold && HorizontalSpeed(c, f, dt) <= fast; f++)
                {
                    _segment[row + f] = _segment[row + a];
                    forwardEnd = f;
                }

                // Two different contacts in one gap: leave room to ease from one to the other.
                while (plantedB && backStart - forwardEnd - 1 < ease && (forwardEnd > a || backStart < b))
                {
                    if (forwardEnd - a >= b - backStart && forwardEnd > a) _segment[row + forwardEnd--] = 0;
                    else if (backStart < b) _segment[row + backStart++] = 0;
                    else break;
                }
            }
        }

        /// <summary>
        /// Contacts the filled motion shows by itself (between keys that are not planted there): with hysteresis
        /// on height and speed (<see cref="NextPlanted"/>), at least <paramref name="minFrames"/> long; one that
        /// touches a key's contact joins it.
        /// </summary>
        private void LabelFree(int c, double leg, double dt, int minFrames, ref int next)
        {
            int cap = _capacity, row = c * cap, n = _frames;
            bool planted = false;
            int start = 0;
            for (int f = 0; f <= n; f++)
            {
                // A key joins a free contact only if it is planted by its own height (keys are where contacts are anchored).
                bool free = f < n && _segment[row + f] == 0 && (!_isKey[f] || _rise[f] <= _settings.EnterHeight * leg);
                bool now = free && NextPlanted(planted, _rise[f] / leg, HorizontalSpeed(c, f, dt) / leg, _settings);
                if (now && !planted) start = f;
                if (planted && !now)
                {
                    // A contact start..f-1 ends: it joins a key's contact it touches, else stands alone if long enough.
                    int id = start > 0 && _segment[row + start - 1] != 0 ? _segment[row + start - 1]
                        : f < n && _segment[row + f] != 0 ? _segment[row + f]
                        : f - start >= minFrames ? next++ : 0;
                    for (int g = start; g < f; g++) _segment[row + g] = id;
                }

                planted = now;
            }
        }

        /// <summary>Channel c's contacts from <paramref name="contacts"/> (frames × channels) instead of the labels: one contact per run of set flags.</summary>
        private void Given(int c, bool[] contacts, ref int next)
        {
            int row = c * _capacity;
            for (int f = 0; f < _frames; f++)
            {
                _segment[row + f] = !contacts[f * ChannelCount + c] ? 0
                    : f > 0 && _segment[row + f - 1] != 0 ? _segment[row + f - 1]
                    : next++;
            }
        }

        /// <summary>
        /// Channel c's contacts where the network predicted them (<see cref="FootContacts.IsPredicted"/>), the labels
        /// elsewhere (keys, frames it did not fill): one contact per run of planted frames, so a predicted stance that
        /// reaches a planted key is held through the key.
        /// </summary>
        private void Predicted(int c, FootContacts contacts, ref int next)
        {
            int row = c * _capacity;
            for (int f = 0; f < _frames; f++)
            {
                bool planted = contacts.IsPredicted(f) ? contacts.IsPlanted(f, c) : _segment[row + f] != 0;
                _segment[row + f] = !planted ? 0
                    : f > 0 && _segment[row + f - 1] != 0 ? _segment[row + f - 1]
                    : next++;
            }
        }

        /// <summary>
        /// The contact state machine with hysteresis: a joint <paramref name="rise"/> leg lengths above its planted
        /// height moving at <paramref name="speed"/> leg lengths per second becomes planted below the entry
        /// thresholds and stays planted until it passes an exit threshold.
        /// </summary>
        internal static bool NextPlanted(bool planted, double rise, double speed, FootLockSettings settings) => planted
            ? rise <= settings.ExitHeight && speed <= settings.ExitSpeed
            : rise <= settings.EnterHeight && speed <= settings.EnterSpeed;

        private double MaxRise(int a, int b)
        {
            double most = double.NegativeInfinity;
            for (int f = a; f <= b; f++) most = Math.Max(most, _rise[f]);
            return most;
        }

        private double Horizontal(int c, int f, int g)
        {
            int i = (c * _capacity + f) * 3, j = (c * _capacity + g) * 3;
            double dx = _feet[i] - _feet[j], dz = _feet[i + 2] - _feet[j + 2];
            return Math.Sqrt(dx * dx + dz * dz);
        }

        private double HorizontalSpeed(int c, int f, double dt)
        {
            int n = _frames;
            if (n < 2) return 0;
            int a = Math.Max(0, f - 1), b = Math.Min(n - 1, f + 1);
            return Horizontal(c, a, b) / ((b - a) * dt);
        }

        /// <summary>
        /// Leaves at least <paramref name="ease"/> frames between two different contacts of channel c (trimming filled
        /// frames off the longer one), so that the joint eases from one spot to the next instead of jumping.
        /// </summary>
        private void Separate(int c, int ease)
        {
            int row = c * _capacity, n = _frames;
            for (int e = 0; e + 1 < n; e++)
            {
                int id = _segment[row + e];
                if (id == 0 || _segment[row + e + 1] == id) continue;
                int s = e + 1;
                while (s < n && _segment[row + s] == 0 && s - e - 1 < ease) s++;
                if (s >= n || _segment[row + s] == 0 || _segment[row + s] == id) continue;
                // Contact `id` ends at e, another starts at s, fewer than `ease` free frames between them.
                int other = _segment[row + s];
                while (s - e - 1 < ease)
                {
                    bool trimEnd = !_isKey[e] && _segment[row + e] == id && (RunLength(row, e, -1) >= RunLength(row, s, +1) || _isKey[s] || _segment[row + s] != other);
                    if (trimEnd) _segment[row + e--] = 0;
                    else if (!_isKey[s] && _segment[row + s] == other) _segment[row + s++] = 0;
                    else break;
                }
            }
        }

        /// <summary>Frames of the run containing frame f, counted from f in direction <paramref name="step"/>.</summary>
        private int RunLength(int row, int f, int step)
        {
            int id = _segment[row + f], count = 0;
            while (f >= 0 && f < _frames && _segment[row + f] == id)
            {
                count++;
                f += step;
            }

            return count;
        }

        /// <summary>The next contact of a channel's row at or after frame <paramref name="s"/>: its first (s) and last (e) frame; false when none is left.</summary>
        private bool NextContact(int row, ref int s, out int e)
        {
            int n = _frames;
            while (s < n && _segment[row + s] == 0) s++;
            e = s;
            if (s >= n) return false;
            int id = _segment[row + s];
            while (e + 1 < n && _segment[row + e + 1] == id) e++;
            return true;
        }
    }
}
