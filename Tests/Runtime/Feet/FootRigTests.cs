using System;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Feet
{
    public class FootRigTests
    {
        [Test]
        public void TheModelsLegLengthIsTheOneRetargetingMeasures()
        {
            Skeleton s = FeetFixtures.LowerBody();
            FootRig rig = FootRig.ForModel(s);
            Assert.That(rig.Left.Hip, Is.EqualTo(s.IndexOf("LeftUpLeg")));
            Assert.That(rig.Right.Toe, Is.EqualTo(s.IndexOf("RightToe")));
            Assert.That(rig.FootJoints, Is.EqualTo(new[] { 3, 4, 7, 8 }));
            // Standing straight, feet 30° below forward: thigh + shin + foot · sin 30°.
            Assert.That(rig.LegLength, Is.EqualTo(FeetFixtures.Thigh + FeetFixtures.Shin + 0.5 * FeetFixtures.Foot).Within(1e-9));
            SkeletonMap map = SkeletonMap.Create(ReferencePose.ModelTPose(s), ReferencePose.ModelTPose(s), JointMap.Lafan1, "self");
            Assert.That(rig.LegLength, Is.EqualTo(map.TargetLegLength).Within(1e-9));
            FootRig source = FootRig.ForSource(map);
            Assert.That(source.LegLength, Is.EqualTo(map.SourceLegLength));
            Assert.That(source.FootJoints, Is.EqualTo(rig.FootJoints));
        }

        [Test]
        public void ASkeletonWithoutLegsIsRefusedByName()
        {
            var s = new Skeleton(new[] { "Hips", "Spine" }, new[] { -1, 0 }, new double[] { 0, 0, 0, 10, 0, 0 });
            var e = Assert.Throws<ArgumentException>(() => FootRig.ForModel(s));
            Assert.That(e!.Message, Does.Contain("LeftUpLeg"));
        }
    }
}
