using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    public class BonePathsTests
    {
        [Test]
        public void JointsFindTheirShallowestBoneByName()
        {
            var transforms = new[] { "", "Rig", "Rig/Hips", "Rig/Hips/Spine", "Rig/Hips/Spine/Prop/Spine", "Mesh" };

            string?[] paths = BonePaths.Resolve(new[] { "Hips", "Spine", "Head" }, transforms, out List<string> missing);

            Assert.That(paths, Is.EqualTo(new[] { "Rig/Hips", "Rig/Hips/Spine", null }));
            Assert.That(missing, Is.EqualTo(new[] { "Head" }));
        }
    }
}
