using System.Collections.Generic;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    public sealed class JointMapTests
    {
        private static Skeleton Chain(params string[] names)
        {
            var parents = new int[names.Length];
            var offsets = new double[3 * names.Length];
            for (int i = 0; i < names.Length; i++)
            {
                parents[i] = i - 1;
                offsets[3 * i + 1] = i == 0 ? 0 : 1;
            }

            return new Skeleton(names, parents, offsets);
        }

        private static Skeleton Renamed(System.Func<string, string> rename)
        {
            Skeleton model = RetargetFixtures.Lafan1();
            var names = new List<string>();
            foreach (string n in model.Names) names.Add(rename(n));
            return new Skeleton(names, model.Parents, model.Offsets);
        }

        [Test]
        public void EveryBuiltInMapNamesEveryModelJoint()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            foreach (JointMap map in JointMap.BuiltIn)
            {
                foreach (string joint in model.Names) Assert.That(map.SourceChain(joint) != null || map.IsSynthesized(joint), Is.True, $"{map.Name} lacks {joint}");
            }
        }

        [Test]
        public void DetectFindsMixamoWithItsPrefixAndUnityNames()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            Skeleton mixamo = Renamed(n => "mixamorig:" + (n.EndsWith("Toe") ? n + "Base" : n));
            Assert.That(JointMap.Detect(mixamo, model), Is.SameAs(JointMap.Mixamo));
            Assert.That(JointMap.FindJoint(mixamo, "LeftToeBase"), Is.EqualTo(4));

            var unityNames = new Dictionary<string, string>
            {
                ["LeftUpLeg"] = "LeftUpperLeg", ["LeftLeg"] = "LeftLowerLeg", ["LeftToe"] = "LeftToes",
                ["RightUpLeg"] = "RightUpperLeg", ["RightLeg"] = "RightLowerLeg", ["RightToe"] = "RightToes",
                ["Spine1"] = "Chest", ["Spine2"] = "UpperChest", ["LeftArm"] = "LeftUpperArm", ["LeftForeArm"] = "LeftLowerArm",
                ["RightArm"] = "RightUpperArm", ["RightForeArm"] = "RightLowerArm",
            };
            Skeleton unity = Renamed(n => unityNames.TryGetValue(n, out string? u) ? u : n);
            Assert.That(JointMap.Detect(unity, model), Is.SameAs(JointMap.UnityHumanoid));
            Assert.That(JointMap.Detect(model, model), Is.SameAs(JointMap.Lafan1));
        }

        [Test]
        public void CmuNeckAndNeck1BecomeOneChain()
        {
            Assert.That(JointMap.Cmu.SourceChain("Neck"), Is.EqualTo(new[] { "Neck", "Neck1" }));
            Assert.That(JointMap.Cmu.SourceChain("Spine"), Is.EqualTo(new[] { "LowerBack" }));
            Assert.That(JointMap.FindChain(Chain("Spine1", "Neck", "Neck1", "Head"), JointMap.Cmu.SourceChain("Neck")!), Is.EqualTo(new[] { 1, 2 }));
        }

        [Test]
        public void AUserMapOverridesTheFallbackAndReadsChains()
        {
            JointMap map = JointMap.FromJson("{\n  \"Hips\": \"pelvis\",\n  \"Neck\": [\"neck_01\", \"neck_02\"]\n}", "user.json", JointMap.Lafan1);
            Assert.That(map.SourceChain("Hips"), Is.EqualTo(new[] { "pelvis" }));
            Assert.That(map.SourceChain("Neck"), Is.EqualTo(new[] { "neck_01", "neck_02" }));
            Assert.That(map.SourceChain("LeftHand"), Is.EqualTo(new[] { "LeftHand" }));
            Assert.That(map.TargetJoints.Count, Is.EqualTo(22));
        }

        [Test]
        public void ABadUserMapNamesFileAndLine()
        {
            var e = Assert.Throws<DataFormatException>(() => JointMap.FromJson("{\n  \"Hips\": \"pelvis\",\n  \"Neck\": 3\n}", "user.json"));
            Assert.That(e!.Message, Does.StartWith("user.json:3: "));
            e = Assert.Throws<DataFormatException>(() => JointMap.FromJson("{\n  \"Hips\": []\n}", "user.json"));
            Assert.That(e!.Message, Does.StartWith("user.json:2: "));
            Assert.Throws<DataFormatException>(() => JointMap.FromJson("{ \"Hips\": ", "user.json"));
        }
    }
}
