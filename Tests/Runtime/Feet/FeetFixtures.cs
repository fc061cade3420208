using System;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Tests.Feet
{
    /// <summary>
    /// Lower bodies with LaFAN1's leg joints (offsets along each bone's local +X, as in LaFAN1, so that the
    /// model T-pose stands them up) and generated walks whose stance feet are exactly planted: the ground
    /// truth that foot locking and the foot-skating measure are tested against.
    /// </summary>
    public static class FeetFixtures
    {
        /// <summary>Thigh, shin and foot lengths (cm) as LaFAN1's.</summary>
        public const double Thigh = 43.5, Shin = 42.37, Foot = 17.3;

        /// <summary>Hips, Spine and both legs (LeftUpLeg, LeftLeg, LeftFoot, LeftToe, …), lengths × <paramref name="scale"/>.</summary>
        public static Skeleton LowerBody(double scale = 1)
        {
            string[] names = { "Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToe", "RightUpLeg", "RightLeg", "RightFoot", "RightToe", "Spine" };
            int[] parents = { -1, 0, 1, 2, 3, 0, 5, 6, 7, 0 };
            double[] offsets =
            {
                0, 0, 0,
                0, 0, 10, Thigh, 0, 0, Shin, 0, 0, Foot, 0, 0,
                0, 0, -10, Thigh, 0, 0, Shin, 0, 0, Foot, 0, 0,
                12, 0, 0,
            };
            for (int i = 0; i < offsets.Length; i++) offsets[i] *= scale;
            return new Skeleton(names, parents, offsets);
        }

        /// <summary><paramref name="frames"/> frames of the model T-pose, the root moving by <paramref name="velocity"/> per second from where the T-pose stands it.</summary>
        public static MotionClip Standing(Skeleton skeleton, int frames, double frameTime, Vector3D velocity = default)
        {
            ReferencePose pose = ReferencePose.ModelTPose(skeleton);
            int j = skeleton.JointCount;
            var positions = new double[frames * j * 3];
            var rotations = new double[frames * j * 4];
            for (int f = 0; f < frames; f++)
            {
                skeleton.OffsetSpan.CopyTo(positions.AsSpan(f * j * 3, j * 3));
                (pose.RootPosition + (f * frameTime) * velocity).Write(positions, f * j * 3);
                for (int k = 0; k < 4 * j; k++) rotations[f * j * 4 + k] = pose.LocalRotations[k];
            }

            return new MotionClip(skeleton, frames, frameTime, positions, rotations);
        }

        /// <summary>
        /// A walk along +Z at <paramref name="speed"/> (skeleton units per second) on ground of height
        /// <c>slope · z</c>: each foot stands flat (toe on the ground, the foot as in the T-pose) for 60 % of a
        /// cycle of <paramref name="cycleSeconds"/> and swings in a low arc for the rest, the legs solved with
        /// analytic IK, the toes rigid (their T-pose rotation, as a synthesized toe). Left foot's cycle starts at
        /// <paramref name="phase"/> (0..1), the right half a cycle later. With <paramref name="rollDegrees"/> the heel
        /// lifts over the last 40 % of each stance, the foot pitching about its planted toe up to that angle (a rolling
        /// foot), and levels again during the swing.
        /// </summary>
        public static MotionClip Walk(Skeleton skeleton, int frames, double frameTime, double speed, double cycleSeconds = 1.0, double slope = 0, double phase = 0, double rollDegrees = 0)
        {
            ReferencePose pose = ReferencePose.ModelTPose(skeleton);
            int j = skeleton.JointCount;
            FootRig rig = FootRig.ForModel(skeleton);
            double stride = speed * cycleSeconds, stance = 0.6;
            double hipDrop = 0.08 * rig.LegLength;
            var positions = new double[frames * j * 3];
            var rotations = new double[frames * j * 4];
            var gp = new double[3 * j];
            var gr = new double[4 * j];
            for (int f = 0; f < frames; f++)
            {
                double t = f * frameTime;
                double z = speed * t;
                Span<double> lp = positions.AsSpan(f * j * 3, j * 3);
                Span<double> lr = rotations.AsSpan(f * j * 4, j * 4);
                skeleton.OffsetSpan.CopyTo(lp);
                for (int k = 0; k < 4 * j; k++) lr[k] = pose.LocalRotations[k];
                Vector3D root = pose.RootPosition;
                new Vector3D(root.X, root.Y - hipDrop + slope * z, z).Write(lp, 0);
                ForwardKinematics.ComputeFrame(skeleton.ParentSpan, lp, Vector3D.Read(lp, 0), lr, gp, gr);
                for (int side = 0; side < 2; side++)
                {
                    Leg leg = rig[side];
                    // The planted toe: where it stands in the T-pose, carried to the stance's spot.
                    Vector3D toeRest = pose.GlobalPosition(leg.Toe), ankleRest = pose.GlobalPosition(leg.Ankle);
                    double cycle = t / cycleSeconds + phase + 0.5 * side;
                    double n = Math.Floor(cycle), u = cycle - n;
                    // Planted at stance n where the T-pose puts the toe when the root is at its mid-stance position.
                    double midStance = (n + 0.5 * stance - phase - 0.5 * side) * cycleSeconds;
                    double toeZ = speed * midStance + (toeRest.Z - pose.RootPosition.Z), lift = 0, roll;
                    if (u >= stance)
                    {
                        double s = (u - stance) / (1 - stance);
                        toeZ += s * s * (3 - 2 * s) * stride;
                        lift = 0.08 * rig.LegLength * Math.Sin(Math.PI * s);
                        roll = 1 - s * s * (3 - 2 * s);
                    }
                    else
                    {
                        double r = Math.Max(0, (u - 0.6 * stance) / (0.4 * stance));
                        roll = r * r;
                    }

                    // Heel up about the toe: a turn about the lateral axis (+X) pitches the foot's toe down.
                    QuaternionD pitch = Quaternions.FromAxisAngle(Vector3D.UnitX, roll * rollDegrees * Math.PI / 180);

                    var toe = new Vector3D(toeRest.X, toeRest.Y + slope * toeZ + lift, toeZ);
                    Vector3D ankleTarget = toe + Quaternions.Apply(pitch, ankleRest - toeRest);
                    Vector3D hip = Vector3D.Read(gp, 3 * leg.Hip), knee = Vector3D.Read(gp, 3 * leg.Knee), ankle = Vector3D.Read(gp, 3 * leg.Ankle);
                    TwoBoneIk.Solve(hip, knee, ankle, QuaternionD.Read(gr, 4 * leg.Hip), QuaternionD.Read(gr, 4 * leg.Knee), ankleTarget, Vector3D.UnitZ,
                        out QuaternionD newHip, out QuaternionD newKnee);
                    QuaternionD parent = QuaternionD.Read(gr, 4 * skeleton.Parents[leg.Hip]);
                    Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(parent), newHip)).Write(lr, 4 * leg.Hip);
                    Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(newHip), newKnee)).Write(lr, 4 * leg.Knee);
                    QuaternionD foot = Quaternions.Multiply(pitch, pose.GlobalRotation(leg.Ankle));
                    Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(newKnee), foot)).Write(lr, 4 * leg.Ankle);
                }
            }

            Quaternions.FixContinuity(rotations, frames, j);
            return new MotionClip(skeleton, frames, frameTime, positions, rotations);
        }

        /// <summary>Solves one leg of one frame of <paramref name="clip"/> (in place) so that its ankle reaches <paramref name="ankle"/>, the foot's global orientation kept.</summary>
        public static void Reach(MotionClip clip, int frame, Leg leg, Vector3D ankle)
        {
            Skeleton s = clip.Skeleton;
            int j = s.JointCount;
            var gp = new double[3 * j];
            var gr = new double[4 * j];
            Span<double> lr = clip.LocalRotations.AsSpan(frame * j * 4, j * 4);
            ReadOnlySpan<double> lp = clip.LocalPositions.AsSpan(frame * j * 3, j * 3);
            ForwardKinematics.ComputeFrame(s.ParentSpan, lp, Vector3D.Read(lp, 0), lr, gp, gr);
            QuaternionD foot = QuaternionD.Read(gr, 4 * leg.Ankle);
            TwoBoneIk.Solve(Vector3D.Read(gp, 3 * leg.Hip), Vector3D.Read(gp, 3 * leg.Knee), Vector3D.Read(gp, 3 * leg.Ankle),
                QuaternionD.Read(gr, 4 * leg.Hip), QuaternionD.Read(gr, 4 * leg.Knee), ankle, Vector3D.UnitZ, out QuaternionD hip, out QuaternionD knee);
            Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(QuaternionD.Read(gr, 4 * s.Parents[leg.Hip])), hip)).Write(lr, 4 * leg.Hip);
            Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(hip), knee)).Write(lr, 4 * leg.Knee);
            Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(knee), foot)).Write(lr, 4 * leg.Ankle);
        }

        /// <summary>Global positions of every joint on every frame (frames × joints × 3).</summary>
        public static double[] GlobalPositions(MotionClip clip)
        {
            int j = clip.Skeleton.JointCount, n = clip.FrameCount;
            var positions = new double[n * j * 3];
            var rotations = new double[n * j * 4];
            ForwardKinematics.ComputeWithLocalPositions(clip.Skeleton, n, clip.LocalPositions, clip.LocalRotations, positions, rotations);
            return positions;
        }

        /// <summary>A deep copy of a clip.</summary>
        public static MotionClip Copy(MotionClip clip) =>
            new MotionClip(clip.Skeleton, clip.FrameCount, clip.FrameTime, (double[])clip.LocalPositions.Clone(), (double[])clip.LocalRotations.Clone());
    }
}
