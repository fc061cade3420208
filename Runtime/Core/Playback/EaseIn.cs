using DeltaInterpolator.Core.Scheduling;
using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// The pose a transition shows at model time (a + f) in model space: its SLERP pose S while the
    /// network's frames are missing, the network's pose M when they are there, and in between
    /// slerp(S, M, c) with a correction weight c that moves toward 1 (frames there) or 0 (frames missing
    /// again) as fast as keeps every joint's turn between two shown frames within
    /// <see cref="TurnFactor"/> × the larger of what S and M turn there, plus <see cref="TurnSlack"/>:
    /// never a hold, never a pop. While frames are missing after some arrived, M is S carried by the
    /// newest decoded frame's correction, so c can fall back smoothly.
    /// </summary>
    /// <remarks>One per player, main thread; allocation-free.</remarks>
    internal sealed class EaseIn
    {
        /// <summary>How much faster than S or M a joint may turn while the correction eases in or out.</summary>
        public const double TurnFactor = 1.2;

        /// <summary>Turn allowed on top, radians (0.45°).</summary>
        public const double TurnSlack = 0.45 * Math.PI / 180;

        private const int Bisections = 12;

        private readonly int _joints;
        private readonly double[] _sRoot = new double[3];
        private readonly double[] _s;
        private readonly double[] _mRoot = new double[3];
        private readonly double[] _m;
        private readonly double[] _prev;
        private readonly double[] _scratch;
        private readonly double[] _allow;
        private int _prevA;
        private double _prevF;

        public EaseIn(int joints)
        {
            _joints = joints;
            _s = new double[4 * joints];
            _m = new double[4 * joints];
            _prev = new double[4 * joints];
            _scratch = new double[4 * joints];
            _allow = new double[joints];
            Rotations = new double[4 * joints];
        }

        /// <summary>The correction weight c of the last frame shown.</summary>
        public double Weight { get; private set; }

        /// <summary>The root position to show (model space).</summary>
        public double[] Root { get; } = new double[3];

        /// <summary>The local rotations to show (model space, J × 4).</summary>
        public double[] Rotations { get; }

        /// <summary>A new request: it starts at its frame 0 (the pose shown), with no correction.</summary>
        public void Begin(Transition t)
        {
            Weight = 0;
            _prevA = 0;
            _prevF = 0;
            int key = t.PastFrames - 1;
            Array.Copy(t.KeyLocalRotations, key * _joints * 4, _prev, 0, _joints * 4);
        }

        /// <summary>
        /// Computes the pose at model time a + f into <see cref="Root"/> and <see cref="Rotations"/>.
        /// </summary>
        /// <param name="request">The request (SLERP frames, network frames below <see cref="TransitionRequest.Decoded"/>).</param>
        /// <param name="a">Model frame (0: last past key … G − 1).</param>
        /// <param name="f">Fraction toward frame a + 1.</param>
        /// <param name="available">True when the network's frames a and a + 1 are decoded.</param>
        /// <returns>True when the pose equals the last one shown although the model time moved (a frozen frame).</returns>
        public bool Show(TransitionRequest request, int a, double f, bool available)
        {
            int decoded = request.Decoded;
            Interpolate(request, a, f, false, _sRoot, _s);
            bool haveModel = available || (Weight > 0 && decoded > 0);
            if (!haveModel)
            {
                Weight = 0;
                Copy(_sRoot, _s);
            }
            else
            {
                if (available)
                {
                    Interpolate(request, a, f, true, _mRoot, _m);
                }
                else
                {
                    CarryCorrection(request, decoded);
                }

                double target = available ? 1 : 0;
                if (Weight == target)
                {
                    if (target == 1) Copy(_mRoot, _m);
                    else Copy(_sRoot, _s);
                }
                else
                {
                    Allowances(request, decoded, available);
                    Weight = Choose(target);
                    Compose(Weight, Rotations);
                    for (int c = 0; c < 3; c++) Root[c] = _sRoot[c] + Weight * (_mRoot[c] - _sRoot[c]);
                }
            }

            bool moved = a != _prevA || f != _prevF;
            bool held = moved && SameAsPrevious();
            Array.Copy(Rotations, _prev, Rotations.Length);
            _prevA = a;
            _prevF = f;
            return held;
        }

        private bool SameAsPrevious()
        {
            for (int i = 0; i < Rotations.Length; i++)
            {
                if (Rotations[i] != _prev[i]) return false;
            }

            return true;
        }

        private void Copy(double[] root, double[] rotations)
        {
            Array.Copy(root, Root, 3);
            Array.Copy(rotations, Rotations, rotations.Length);
        }

        /// <summary>
        /// Each joint's allowed turn from the last pose shown: TurnFactor × the larger of S's turn and (when
        /// the network's frames are there) M's turn since the last frame, plus TurnSlack.
        /// </summary>
        private void Allowances(TransitionRequest request, int decoded, bool available)
        {
            Interpolate(request, _prevA, _prevF, false, null, _scratch);
            for (int j = 0; j < _joints; j++) _allow[j] = Angle(_scratch, _s, j);
            if (available)
            {
                Interpolate(request, _prevA, _prevF, true, null, _scratch);
                for (int j = 0; j < _joints; j++) _allow[j] = Math.Max(_allow[j], Angle(_scratch, _m, j));
            }

            for (int j = 0; j < _joints; j++) _allow[j] = TurnFactor * _allow[j] + TurnSlack;
        }

        private double Choose(double target)
        {
            if (Fits(target)) return target;
            double current = Weight;
            // Bisection between the weight shown last (assumed to fit) and the target.
            double good = current, bad = target;
            for (int i = 0; i < Bisections; i++)
            {
                double mid = 0.5 * (good + bad);
                if (Fits(mid)) good = mid;
                else bad = mid;
            }

            return good;
        }

        private bool Fits(double c)
        {
            Compose(c, _scratch);
            for (int j = 0; j < _joints; j++)
            {
                if (Angle(_prev, _scratch, j) > _allow[j]) return false;
            }

            return true;
        }

        private void Compose(double c, double[] into)
        {
            for (int j = 0; j < _joints; j++)
            {
                QuaternionD s = QuaternionD.Read(_s, 4 * j);
                QuaternionD q = c <= 0 ? s : c >= 1 ? QuaternionD.Read(_m, 4 * j) : Quaternions.Normalize(new SlerpPair(s, QuaternionD.Read(_m, 4 * j)).At(c));
                q.Write(into, 4 * j);
            }
        }

        /// <summary>M while the frames are missing: S carried by the correction of the newest decoded frame (d = decoded).</summary>
        private void CarryCorrection(TransitionRequest request, int decoded)
        {
            Transition t = request.Transition;
            int k = decoded - 1;
            int jr = 4 * _joints;
            for (int c = 0; c < 3; c++) _mRoot[c] = _sRoot[c] + (t.RootPositions[3 * k + c] - request.SlerpRoots[3 * k + c]);
            for (int j = 0; j < _joints; j++)
            {
                QuaternionD m = QuaternionD.Read(t.LocalRotations, jr * k + 4 * j);
                QuaternionD s = QuaternionD.Read(request.SlerpRotations, jr * k + 4 * j);
                QuaternionD correction = Quaternions.Multiply(m, Quaternions.Conjugate(s));
                Quaternions.Normalize(Quaternions.Multiply(correction, QuaternionD.Read(_s, 4 * j))).Write(_m, 4 * j);
            }
        }

        /// <summary>The pose between model frames a and a + 1 (0: last past key, G: target) at fraction f: SLERP frames or the network's.</summary>
        private void Interpolate(TransitionRequest request, int a, double f, bool model, double[]? root, double[] rotations)
        {
            Frame(request, a, model, out double[] rootsA, out int rootA, out double[] rotsA, out int rotA);
            Frame(request, a + 1, model, out double[] rootsB, out int rootB, out double[] rotsB, out int rotB);
            if (root != null)
            {
                for (int c = 0; c < 3; c++) root[c] = rootsA[rootA + c] + f * (rootsB[rootB + c] - rootsA[rootA + c]);
            }

            for (int j = 0; j < _joints; j++)
            {
                QuaternionD qa = QuaternionD.Read(rotsA, rotA + 4 * j);
                QuaternionD qb = QuaternionD.Read(rotsB, rotB + 4 * j);
                QuaternionD q = f == 0 ? qa : Quaternions.Normalize(new SlerpPair(qa, qb).At(f));
                q.Write(rotations, 4 * j);
            }
        }

        private void Frame(TransitionRequest request, int i, bool model, out double[] roots, out int rootOffset, out double[] rotations, out int rotationOffset)
        {
            Transition t = request.Transition;
            int jr = 4 * _joints;
            int gap = t.MissingFrames + 1;
            if (i == 0 || i == gap)
            {
                int key = i == 0 ? t.PastFrames - 1 : t.PastFrames;
                roots = t.KeyRootPositions;
                rootOffset = 3 * key;
                rotations = t.KeyLocalRotations;
                rotationOffset = jr * key;
                return;
            }

            roots = model ? t.RootPositions : request.SlerpRoots;
            rootOffset = 3 * (i - 1);
            rotations = model ? t.LocalRotations : request.SlerpRotations;
            rotationOffset = jr * (i - 1);
        }

        /// <summary>The angle (radians) between joint j's rotations in two pose buffers.</summary>
        internal static double Angle(double[] p, double[] q, int j)
        {
            QuaternionD a = QuaternionD.Read(p, 4 * j);
            QuaternionD b = QuaternionD.Read(q, 4 * j);
            QuaternionD d = Quaternions.Multiply(Quaternions.Conjugate(a), b);
            double v = Math.Sqrt(d.X * d.X + d.Y * d.Y + d.Z * d.Z);
            return 2 * Math.Atan2(v, Math.Abs(d.W));
        }
    }
}
