using System.Text;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.BvhImport;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.BvhImport
{
    /// <summary>
    /// The importer's Core refuses, in one line naming the file and the joint, a rest offset or a root position that
    /// no float holds (Unity's transforms and curves are float): an OFFSET of 1e306 or a root at 1e300 came back as
    /// Infinity clip keys and rest positions without an error.
    /// </summary>
    public sealed class ImportRefusesPositionsBeyondFloatRangeTests
    {
        [TestCase("1e306", "0", 0.01, "OFFSET")]
        [TestCase("1e39", "0", 1.0, "OFFSET")]
        [TestCase("10", "1e300", 0.01, "frame 1")]
        [TestCase("10", "-4e38", 1.0, "frame 1")]
        public void BeyondFloatRangeIsRefusedInOneLine(string offset, string rootAtFrameOne, double metresPerUnit, string names)
        {
            var e = Assert.Throws<DataFormatException>(() => BvhClipImport.Import(Clip(offset, rootAtFrameOne), "far.bvh", metresPerUnit))!;
            Assert.That(e.Message, Does.StartWith("far.bvh: "));
            Assert.That(e.Message, Does.Contain(names).And.Contain("beyond float range").And.Contain("; expected"));
            Assert.That(e.Message, Does.Not.Contain("\n"));
        }

        [Test]
        public void LargeButFloatSizedValuesImport()
        {
            BvhImportResult result = BvhClipImport.Import(Clip("1e30", "1e30"), "big.bvh", 1.0);
            foreach (ImportedJoint j in result.Joints) Assert.That(System.Math.Abs(j.RestPosition.Y), Is.LessThanOrEqualTo(float.MaxValue), j.Name);
            foreach (float v in result.LocalPositions) Assert.That(float.IsInfinity(v) || float.IsNaN(v), Is.False);
        }

        // A root and one child at `offset` above it, two frames; the root's X on frame 1 is `rootAtFrameOne`.
        private static byte[] Clip(string offset, string rootAtFrameOne)
        {
            var sb = new StringBuilder();
            sb.Append("HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n");
            sb.Append("JOINT Spine\n{\nOFFSET 0 ").Append(offset).Append(" 0\nCHANNELS 3 Zrotation Yrotation Xrotation\nEnd Site\n{\nOFFSET 0 1 0\n}\n}\n}\n");
            sb.Append("MOTION\nFrames: 2\nFrame Time: 0.033333\n");
            sb.Append("0 0 0 0 0 0 0 0 0\n");
            sb.Append(rootAtFrameOne).Append(" 0 0 0 0 0 0 0 0\n");
            return Encoding.ASCII.GetBytes(sb.ToString());
        }
    }
}
