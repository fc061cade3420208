using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The same motion on two differently built rigs bakes to the same world motion (issue 15): the bundled CMU
    /// clip, and a copy with other joint names (reached through a JSON map), other local bone frames (every joint's
    /// frame turned by its own rotation, offsets and rotations re-expressed), in metres instead of centimetres and
    /// written with XYZ instead of ZYX Euler channels. Baked through Core's workflow (what <c>bake --map</c> and the
    /// editor baker call) with the shipped model and with SLERP, every joint's world position agrees to 1e-3 of a
    /// leg length.
    /// </summary>
    [TestFixture]
    public sealed class TwoRigBakeTests
    {
        private const string Sample = "Samples~/Demo/cmu_09_12_walk_navigate.bvh";
        private const double Metres = 0.01;

        [Test]
        public void TheSameMotionOnTwoRigsBakesToTheSameWorldMotion()
        {
            MotionClip original = DemoWalk();
            using Inbetweener model = ShippedModel();

            IRigRetargeting rigA = RigRetargeting.For(model.Contract, original, "cmu.bvh", referenceFrame: 0);
            (MotionClip rebuilt, string json) = Rebuild(original, ((MappedRig)rigA).Map);
            // Through a BVH file with other Euler channels, as a user's export would arrive.
            MotionClip other = WriteAndRead(rebuilt);
            JointMap map = JointMap.FromJson(json, "rig-b-map.json");
            IRigRetargeting rigB = RigRetargeting.For(model.Contract, other, "rig-b.bvh", referenceFrame: 0, map: map);

            int[] keys = BakeKeys.Every(60, original, 1, model.Contract);
            BakeRun a = InbetweenBake.Run(original, keys, rigA, new[] { BakeMethod.Model(model), BakeMethod.Slerp() });
            BakeRun b = InbetweenBake.Run(other, keys, rigB, new[] { BakeMethod.Model(model), BakeMethod.Slerp() });
            double leg = rigA.LegLength;
            Assert.That(rigB.LegLength / Metres, Is.EqualTo(leg).Within(1e-6 * leg), "leg length in the rig's own units");
            foreach (string method in new[] { "Model", "SLERP" })
            {
                double[] pa = World(a[method].OnRig);
                double[] pb = World(b[method].OnRig);
                double worst = 0;
                for (int i = 0; i < pa.Length; i++) worst = Math.Max(worst, Math.Abs(pa[i] - pb[i] / Metres));
                Assert.That(worst / leg, Is.LessThan(1e-3), $"{method}: largest world position difference {worst / leg:E2} leg lengths");
                TestContext.WriteLine($"{method}: largest world position difference between the rigs {worst / leg:E2} leg lengths");
            }
        }

        /// <summary>The demo clip's T-pose and first 4 s of walking (the test is skipped, saying why, without it).</summary>
        internal static MotionClip DemoWalk()
        {
            string samplePath = ShippedModels.Find(Sample);
            if (!File.Exists(samplePath)) Assert.Ignore($"{Sample} not found above {AppContext.BaseDirectory}");
            return BvhReader.Read(samplePath).Motion.Excerpt(0, 481);
        }

        /// <summary>The shipped default model, whole graph only (the test is skipped, saying why, without it).</summary>
        internal static Inbetweener ShippedModel()
        {
            string modelPath = ShippedModels.Find(ShippedModels.Default);
            if (!File.Exists(modelPath)) Assert.Ignore($"{ShippedModels.Default} not found above {AppContext.BaseDirectory}");
            return InbetweenerLoader.Load(new OnnxModelFiles(modelPath), LazyGraphs.None);
        }

        /// <summary>Joints renamed, each joint's local frame turned by its own rotation, units in metres; and the JSON map that names the model's joints on it.</summary>
        internal static (MotionClip Clip, string Json) Rebuild(MotionClip clip, SkeletonMap mapA)
        {
            Skeleton s = clip.Skeleton;
            int j = s.JointCount;
            var random = new Random(15);
            var turn = new QuaternionD[j];
            for (int i = 0; i < j; i++)
            {
                var axis = new Vector3D(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                turn[i] = Quaternions.FromAxisAngle((1 / axis.Length) * axis, 0.3 + 2 * random.NextDouble());
            }

            var names = new string[j];
            var offsets = new double[3 * j];
            for (int i = 0; i < j; i++)
            {
                names[i] = "rigB_" + s.Names[i];
                int p = s.Parents[i];
                Vector3D offset = Vector3D.Read(s.OffsetSpan, 3 * i);
                // An offset is in the parent's frame: the parent's turned frame sees it turned back.
                Vector3D turned = p < 0 ? offset : Quaternions.Apply(Quaternions.Conjugate(turn[p]), offset);
                (Metres * turned).Write(offsets, 3 * i);
            }

            var skeleton = new Skeleton(names, s.Parents, offsets);
            var positions = new double[clip.FrameCount * j * 3];
            var rotations = new double[clip.FrameCount * j * 4];
            for (int f = 0; f < clip.FrameCount; f++)
            {
                for (int i = 0; i < j; i++)
                {
                    int p = s.Parents[i];
                    QuaternionD q = QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(f, i));
                    // Local rotation in turned frames: world(i) · turn(i) = world(parent) · turn(parent) · q'.
                    QuaternionD local = Quaternions.Multiply(p < 0 ? q : Quaternions.Multiply(Quaternions.Conjugate(turn[p]), q), turn[i]);
                    local.Write(rotations, (f * j + i) * 4);
                    Vector3D lp = Vector3D.Read(clip.LocalPositions, clip.PositionIndex(f, i));
                    (i == 0 ? Metres * lp : Vector3D.Read(offsets, 3 * i)).Write(positions, (f * j + i) * 3);
                }
            }

            var json = new StringBuilder("{");
            bool first = true;
            foreach (string target in mapA.Map.TargetJoints)
            {
                IReadOnlyList<string>? chain = mapA.Map.SourceChain(target);
                if (chain == null) continue;
                var renamed = new List<string>();
                foreach (string link in chain)
                {
                    // Built-in tables list alternatives ("Neck|Neck1"): the one this rig has.
                    foreach (string alternative in link.Split('|'))
                    {
                        if (s.IndexOf(alternative) >= 0)
                        {
                            renamed.Add("\"rigB_" + alternative + "\"");
                            break;
                        }
                    }
                }

                if (renamed.Count == 0) continue;
                json.Append(first ? "" : ", ").Append('"').Append(target).Append("\": ").Append(renamed.Count == 1 ? renamed[0] : "[" + string.Join(", ", renamed) + "]");
                first = false;
            }

            return (new MotionClip(skeleton, clip.FrameCount, clip.FrameTime, positions, rotations), json.Append('}').ToString());
        }

        private static MotionClip WriteAndRead(MotionClip clip)
        {
            int j = clip.Skeleton.JointCount;
            var channels = new BvhChannel[j][];
            for (int i = 0; i < j; i++)
            {
                channels[i] = i == 0
                    ? new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Xrotation, BvhChannel.Yrotation, BvhChannel.Zrotation }
                    : new[] { BvhChannel.Xrotation, BvhChannel.Yrotation, BvhChannel.Zrotation };
            }

            var writer = new StringWriter();
            BvhWriter.Write(new BvhAnimation(clip, channels, null, "rig-b.bvh"), writer);
            return BvhReader.Parse(writer.ToString(), "rig-b.bvh").Motion;
        }

        internal static double[] World(MotionClip clip)
        {
            int j = clip.Skeleton.JointCount;
            var positions = new double[clip.FrameCount * j * 3];
            var rotations = new double[clip.FrameCount * j * 4];
            ForwardKinematics.ComputeWithLocalPositions(clip.Skeleton, clip.FrameCount, clip.LocalPositions, clip.LocalRotations, positions, rotations);
            return positions;
        }
    }
}
