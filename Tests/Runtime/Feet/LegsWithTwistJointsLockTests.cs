using System;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Feet
{
    /// <summary>
    /// Foot locking bends legs whose knee is not the thigh's direct child: a twist joint in the thigh (as many game
    /// rigs have) rides along, so the locked motion is the plain rig's locked motion, joint for joint. Such a leg
    /// was refused ("not a chain of parent and child joints"), which `bake` reported as a bug.
    /// </summary>
    public sealed class LegsWithTwistJointsLockTests
    {
        private const double FrameTime = 1.0 / 30;

        [Test]
        public void ARigWithTwistJointsInItsThighsLocksAsThePlainRigDoes()
        {
            Skeleton plain = FeetFixtures.LowerBody();
            MotionClip plainClip = Sliding(plain);
            MotionClip twistedClip = WithThighTwists(plainClip, 35.0);
            Skeleton twisted = twistedClip.Skeleton;

            new FootLocker(FootRig.ForModel(plain)).Lock(plainClip, new[] { 0, 20 });
            new FootLocker(FootRig.ForModel(twisted)).Lock(twistedClip, new[] { 0, 20 });

            double[] a = FeetFixtures.GlobalPositions(plainClip), b = FeetFixtures.GlobalPositions(twistedClip);
            int pj = plain.JointCount, tj = twisted.JointCount;
            double worst = 0;
            for (int f = 0; f < plainClip.FrameCount; f++)
            {
                for (int j = 0; j < pj; j++)
                {
                    int k = twisted.IndexOf(plain.Names[j]);
                    worst = Math.Max(worst, (Vector3D.Read(a, (f * pj + j) * 3) - Vector3D.Read(b, (f * tj + k) * 3)).Length);
                }
            }

            Assert.That(worst, Is.LessThan(1e-6), "every joint where the plain rig's locking puts it (cm)");
            // And the locking did hold the feet: the plain rig's ankles stay on their key positions.
            FootRig rig = FootRig.ForModel(plain);
            for (int f = 1; f < 20; f++)
            {
                Assert.That((Vector3D.Read(a, (f * pj + rig.Left.Ankle) * 3) - Vector3D.Read(a, rig.Left.Ankle * 3)).Length, Is.LessThan(0.01 * rig.LegLength), $"frame {f}");
            }

            Assert.That(FootRig.ChainProblem(twisted, FootRig.ForModel(twisted).Left, 0), Is.Null);
        }

        [Test]
        public void ALegThatIsNoChainIsNamedNotCrashed()
        {
            // The "knee" hangs off the hips beside the thigh: no two-bone IK can bend it.
            var s = new Skeleton(
                new[] { "Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightUpLeg", "RightLeg", "RightFoot" },
                new[] { -1, 0, 0, 2, 0, 4, 5 },
                new double[] { 0, 0, 0, 0, 0, 10, 0, 0, 10, 42.37, 0, 0, 0, 0, -10, 43.5, 0, 0, 42.37, 0, 0 });
            var e = Assert.Throws<ArgumentException>(() => new FootLocker(FootRig.ForModel(s)))!;
            Assert.That(e.Message, Does.Contain("knee LeftLeg is not below its thigh LeftUpLeg"));
        }

        // Knees bent (hips 8 down, ankles where they stand); between the keys the body slides 5 sideways with the feet.
        private static MotionClip Sliding(Skeleton s)
        {
            FootRig rig = FootRig.ForModel(s);
            MotionClip clip = FeetFixtures.Standing(s, 21, FrameTime);
            int j = s.JointCount;
            double[] rest = FeetFixtures.GlobalPositions(clip);
            for (int f = 0; f < 21; f++)
            {
                double slide = 5 * Math.Sin(Math.PI * f / 20);
                clip.LocalPositions[f * j * 3] += slide;
                clip.LocalPositions[f * j * 3 + 1] -= 8;
                FeetFixtures.Reach(clip, f, rig.Left, Vector3D.Read(rest, rig.Left.Ankle * 3) + new Vector3D(slide, 0, 0));
                FeetFixtures.Reach(clip, f, rig.Right, Vector3D.Read(rest, rig.Right.Ankle * 3) + new Vector3D(slide, 0, 0));
            }

            return clip;
        }

        /// <summary>
        /// The same motion on a rig with a twist joint halfway down each thigh, turned <paramref name="degrees"/> about
        /// the bone (local +X, along which the thigh's offset lies), the knee's rotation compensating: every shared joint
        /// lands where it did.
        /// </summary>
        private static MotionClip WithThighTwists(MotionClip clip, double degrees)
        {
            Skeleton s = clip.Skeleton;
            int j = s.JointCount;
            var names = new System.Collections.Generic.List<string>();
            var parents = new System.Collections.Generic.List<int>();
            var offsets = new System.Collections.Generic.List<double>();
            var source = new System.Collections.Generic.List<int>(); // old joint, or −1 for a twist joint
            var newIndex = new int[j];
            for (int k = 0; k < j; k++)
            {
                int parent = s.Parents[k] < 0 ? -1 : newIndex[s.Parents[k]];
                Vector3D offset = Vector3D.Read(s.OffsetSpan, 3 * k);
                bool knee = s.Names[k] == "LeftLeg" || s.Names[k] == "RightLeg";
                if (knee)
                {
                    names.Add(s.Names[s.Parents[k]] + "Twist");
                    parents.Add(parent);
                    offsets.AddRange(new[] { 0.5 * offset.X, 0.5 * offset.Y, 0.5 * offset.Z });
                    source.Add(-1);
                    parent = names.Count - 1;
                    offset = 0.5 * offset;
                }

                newIndex[k] = names.Count;
                names.Add(s.Names[k]);
                parents.Add(parent);
                offsets.AddRange(new[] { offset.X, offset.Y, offset.Z });
                source.Add(k);
            }

            var twisted = new Skeleton(names, parents, offsets);
            int n = names.Count;
            QuaternionD twist = Quaternions.FromAxisAngle(Vector3D.UnitX, degrees * Math.PI / 180);
            var positions = new double[clip.FrameCount * n * 3];
            var rotations = new double[clip.FrameCount * n * 4];
            for (int f = 0; f < clip.FrameCount; f++)
            {
                for (int k = 0; k < n; k++)
                {
                    int old = source[k];
                    Vector3D p = old >= 0 ? Vector3D.Read(clip.LocalPositions, (f * j + old) * 3) : Vector3D.Read(offsets.ToArray(), 3 * k);
                    if (old >= 0 && (names[k] == "LeftLeg" || names[k] == "RightLeg")) p = Vector3D.Read(offsets.ToArray(), 3 * k);
                    p.Write(positions, (f * n + k) * 3);
                    QuaternionD q = old >= 0 ? QuaternionD.Read(clip.LocalRotations, (f * j + old) * 4) : twist;
                    if (old >= 0 && (names[k] == "LeftLeg" || names[k] == "RightLeg")) q = Quaternions.Multiply(Quaternions.Conjugate(twist), q);
                    q.Write(rotations, (f * n + k) * 4);
                }
            }

            return new MotionClip(twisted, clip.FrameCount, clip.FrameTime, positions, rotations);
        }
    }
}
