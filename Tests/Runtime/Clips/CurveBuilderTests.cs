using System;
using System.Collections.Generic;
using System.Linq;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    public class CurveBuilderTests
    {
        private static Skeleton Chain() => new Skeleton(new[] { "Hips", "Spine", "Head" }, new[] { -1, 0, 1 }, new double[] { 0, 90, 0, 0, 10, 0, 0, 20, 0 });

        private static readonly string[] Paths = { "Hips", "Hips/Spine", "Hips/Spine/Head" };

        // The chain as a character: its armature holds the bones in metres under a centimetre skeleton (scale 100), no
        // turn, so a root position in Unity metres lands in the skeleton's centimetres; the reference pose is identity.
        private static CharacterRig Rig()
        {
            Skeleton chain = Chain();
            var rotations = new double[12];
            for (int b = 0; b < 3; b++) rotations[4 * b] = 1;
            return new CharacterRig("chain", chain.Names, chain.Parents, new double[] { 0, 0.9, 0, 0, 0.1, 0, 0, 0.2, 0 }, rotations,
                new RootFrame(Vector3D.Zero, QuaternionD.Identity, 100));
        }

        private static CharacterPoseTrack Track(int frameCount) => new CharacterPoseTrack(Rig(), frameCount, 1.0 / 30);

        // A pose as Unity's transforms give it: rotations in Unity's (x, y, z, w) order, turned into the track's (w, x, y, z).
        private static void SetUnityPose(CharacterPoseTrack track, int frame, float[] localRotationsXyzw, float rootX, float rootY, float rootZ)
        {
            var wxyz = new double[localRotationsXyzw.Length];
            for (int b = 0; b < wxyz.Length / 4; b++)
            {
                wxyz[4 * b] = localRotationsXyzw[4 * b + 3];
                for (int c = 0; c < 3; c++) wxyz[4 * b + 1 + c] = localRotationsXyzw[4 * b + c];
            }

            track.SetUnityPose(frame, new double[] { rootX, rootY, rootZ }, wxyz);
        }

        [Test]
        public void AUnityYawBecomesTheMirroredModelRotation()
        {
            // Mirroring X: a point rotated in Unity and then mirrored lands where the mirrored point lands
            // under the model-space rotation.
            CharacterPoseTrack track = Track(1);
            double half = 0.3;
            float[] unity = { 0, (float)Math.Sin(half), 0, (float)Math.Cos(half), 0.2f, 0.1f, -0.3f, 0.927f, 0, 0, 0, 1 };
            SetUnityPose(track, 0, unity, 1f, 2f, 3f);

            QuaternionD model = QuaternionD.Read(track.Motion.LocalRotations, 0);
            RotationAssert.SameRotation(model, new QuaternionD(Math.Cos(half), 0, -Math.Sin(half), 0), 1e-6);
            var unityQ = Quaternions.Normalize(new QuaternionD(unity[7], unity[4], unity[5], unity[6]));
            var modelQ = QuaternionD.Read(track.Motion.LocalRotations, 4);
            var v = new Vector3D(0.3, -1.2, 0.7);
            Vector3D rotatedThenMirrored = Mirror(Quaternions.Apply(unityQ, v));
            Vector3D mirroredThenRotated = Quaternions.Apply(modelQ, Mirror(v));
            RotationAssert.SameVector(mirroredThenRotated, rotatedThenMirrored, 1e-6);
            // Metres → centimetres, X mirrored.
            RotationAssert.SameVector(Vector3D.Read(track.Motion.LocalPositions, 0), new Vector3D(-100, 200, 300), 1e-4);
        }

        [Test]
        public void KeysSampledFromUnityComeBackAsTheSameCurveValues()
        {
            var random = new TestRandom(11);
            CharacterPoseTrack track = Track(4);
            var poses = new List<float[]>();
            for (int f = 0; f < 4; f++)
            {
                var pose = new float[12];
                for (int j = 0; j < 3; j++)
                {
                    QuaternionD q = random.Rotation();
                    pose[4 * j] = (float)q.X;
                    pose[4 * j + 1] = (float)q.Y;
                    pose[4 * j + 2] = (float)q.Z;
                    pose[4 * j + 3] = (float)q.W;
                }

                poses.Add(pose);
                SetUnityPose(track, f, pose, 0.1f * f, 0.9f, -0.2f * f);
            }

            IReadOnlyList<ClipCurve> curves = CurveBuilder.BuildCharacter(track.Rig, track.Motion, Paths);

            Assert.That(curves.Count, Is.EqualTo(3 * 4 + 3));
            for (int j = 0; j < 3; j++)
            {
                ClipCurve[] rot = curves.Where(c => c.Path == Paths[j] && c.Property.StartsWith("m_LocalRotation", StringComparison.Ordinal)).ToArray();
                Assert.That(rot.Select(c => c.Property), Is.EqualTo(CurveBuilder.RotationProperties));
                for (int f = 0; f < 4; f++)
                {
                    var got = new QuaternionD(rot[3].Values[f], rot[0].Values[f], rot[1].Values[f], rot[2].Values[f]);
                    float[] p = poses[f];
                    RotationAssert.SameRotation(got, Quaternions.Normalize(new QuaternionD(p[4 * j + 3], p[4 * j], p[4 * j + 1], p[4 * j + 2])), 1e-6, $"joint {j} frame {f}");
                    Assert.That(rot[0].Times[f], Is.EqualTo(f / 30f).Within(1e-7));
                }
            }

            ClipCurve[] pos = curves.Where(c => c.Property.StartsWith("m_LocalPosition", StringComparison.Ordinal)).ToArray();
            Assert.That(pos.Select(c => c.Path), Is.All.EqualTo("Hips"));
            for (int f = 0; f < 4; f++)
            {
                Assert.That(pos[0].Values[f], Is.EqualTo(0.1f * f).Within(1e-6));
                Assert.That(pos[1].Values[f], Is.EqualTo(0.9f).Within(1e-6));
                Assert.That(pos[2].Values[f], Is.EqualTo(-0.2f * f).Within(1e-6));
            }
        }

        [Test]
        public void RotationKeysStayInOneHemisphereAndTangentsAreLinear()
        {
            // A bone turning a full 360° about Y over 36 frames: raw quaternions change sign half way,
            // the curves must not.
            Skeleton skeleton = Chain();
            var motion = MotionClip.CreateRestPose(skeleton, 37, 1.0 / 30);
            for (int f = 0; f < 37; f++)
            {
                QuaternionD q = Quaternions.FromAxisAngle(Vector3D.UnitY, 2 * Math.PI * f / 36);
                if (f % 2 == 1) q = q.Negated; // the same rotations with alternating signs
                q.Write(motion.LocalRotations, motion.RotationIndex(f, 1));
            }

            IReadOnlyList<ClipCurve> curves = CurveBuilder.BuildCharacter(Rig(), motion, Paths);
            ClipCurve[] spine = curves.Where(c => c.Path == "Hips/Spine").ToArray();
            for (int f = 1; f < 37; f++)
            {
                double dot = 0;
                for (int c = 0; c < 4; c++) dot += spine[c].Values[f] * spine[c].Values[f - 1];
                Assert.That(dot, Is.GreaterThan(0.9), $"frame {f}");
            }

            ClipCurve w = spine[3];
            for (int f = 1; f < 36; f++)
            {
                float dt = 1f / 30f;
                Assert.That(w.InTangents[f], Is.EqualTo((w.Values[f] - w.Values[f - 1]) / dt).Within(1e-3), $"in {f}");
                Assert.That(w.OutTangents[f], Is.EqualTo((w.Values[f + 1] - w.Values[f]) / dt).Within(1e-3), $"out {f}");
            }

            // After a full turn the last key is −identity: same rotation, opposite sign to the first.
            Assert.That(w.Values[36], Is.EqualTo(-1f).Within(1e-6));
        }

        [Test]
        public void BakedSlerpInbetweensBecomeCurvesBetweenTheKeys()
        {
            // The window's path end to end with the SLERP baseline: two keys, the gap filled, curves built.
            Skeleton skeleton = Chain();
            CharacterPoseTrack track = Track(11);
            float s = (float)Math.Sin(0.5), c = (float)Math.Cos(0.5);
            SetUnityPose(track, 0, new float[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 }, 0, 1, 0);
            SetUnityPose(track, 10, new float[] { 0, s, 0, c, 0, 0, 0, 1, 0, 0, 0, 1 }, 1, 1, 0);
            var transition = new Transition(skeleton, 1, 9);
            MotionClip m = track.Motion;
            Array.Copy(m.LocalRotations, 0, transition.KeyLocalRotations, 0, 12);
            Array.Copy(m.LocalRotations, m.RotationIndex(10, 0), transition.KeyLocalRotations, 12, 12);
            Array.Copy(m.LocalPositions, 0, transition.KeyRootPositions, 0, 3);
            Array.Copy(m.LocalPositions, m.PositionIndex(10, 0), transition.KeyRootPositions, 3, 3);
            new SlerpBaseline().Inbetween(transition);
            for (int k = 0; k < 9; k++)
            {
                Array.Copy(transition.LocalRotations, k * 12, m.LocalRotations, m.RotationIndex(k + 1, 0), 12);
                Array.Copy(transition.RootPositions, k * 3, m.LocalPositions, m.PositionIndex(k + 1, 0), 3);
            }

            IReadOnlyList<ClipCurve> curves = CurveBuilder.BuildCharacter(track.Rig, m, Paths);
            ClipCurve hipsY = curves.Single(cv => cv.Path == "Hips" && cv.Property == "m_LocalRotation.y");
            ClipCurve hipsX = curves.Single(cv => cv.Path == "Hips" && cv.Property == "m_LocalPosition.x");
            for (int f = 0; f <= 10; f++)
            {
                Assert.That(hipsY.Values[f], Is.EqualTo((float)Math.Sin(0.5 * f / 10)).Within(1e-5), $"frame {f}");
                Assert.That(hipsX.Values[f], Is.EqualTo(f / 10f).Within(1e-5), $"frame {f}");
            }
        }

        private static Vector3D Mirror(Vector3D v) => new Vector3D(-v.X, v.Y, v.Z);
    }
}
