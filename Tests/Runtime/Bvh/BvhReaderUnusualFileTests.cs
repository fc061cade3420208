using System;
using System.Text;
using DeltaInterpolator.Core.Bvh;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Bvh
{
    /// <summary>Unusual files the reader must read or refuse well (issue 8): deep nesting beyond the call stack, an unclosed deep chain, CR-only line endings, huge names.</summary>
    public class BvhReaderUnusualFileTests
    {
        private static string DeepChain(int depth)
        {
            var sb = new StringBuilder(depth * 80);
            sb.Append("HIERARCHY\nROOT J0\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n");
            for (int i = 1; i < depth; i++) sb.Append("JOINT J").Append(i).Append("\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Yrotation Xrotation\n");
            sb.Append("End Site\n{\nOFFSET 0 1 0\n}\n");
            for (int i = 0; i < depth; i++) sb.Append("}\n");
            sb.Append("MOTION\nFrames: 1\nFrame Time: 0.033333\n");
            for (int i = 0; i < 3 + 3 * depth; i++) sb.Append("0 ");
            return sb.Append('\n').ToString();
        }

        [Test]
        public void NestingDepthIsNotLimitedByTheCallStack()
        {
            // 80,000 levels (6 MB) overflowed the stack of the recursive parser (exit 134).
            BvhAnimation a = BvhReader.Parse(DeepChain(80000), "deep.bvh");
            Assert.That(a.Skeleton.JointCount, Is.EqualTo(80000));
            Assert.That(a.Skeleton.Parents[79999], Is.EqualTo(79998));
            Assert.That(a.EndSites[79999], Has.Length.EqualTo(1));
        }

        [Test]
        public void AnUnclosedDeepChainNamesTheInnermostJoint()
        {
            string text = DeepChain(3000);
            text = text.Replace("}\n}\nMOTION", "}\nMOTION");
            var e = Assert.Throws<BvhFormatException>(() => BvhReader.Parse(text, "deep.bvh"))!;
            Assert.That(e.Message, Does.Contain("MOTION while joint 'J0' is still open"));
        }

        [Test]
        public void CrOnlyLineEndingsReadLikeLf()
        {
            BvhAnimation lf = BvhReader.Parse(BvhSamples.TwoJoints, "lf.bvh");
            BvhAnimation cr = BvhReader.Parse(BvhSamples.TwoJoints.Replace("\n", "\r"), "cr.bvh");
            Assert.That(cr.Skeleton.Names, Is.EqualTo(lf.Skeleton.Names));
            Assert.That(cr.Motion.LocalPositions, Is.EqualTo(lf.Motion.LocalPositions));
            Assert.That(cr.Motion.LocalRotations, Is.EqualTo(lf.Motion.LocalRotations));

            // Before, a CR-only file was one long line: "found ... in joint" on line 1.
            var e = Assert.Throws<BvhFormatException>(() => BvhReader.Parse(BvhSamples.TwoJoints.Replace("OFFSET 0 10 0", "OFFSET 0 ten 0").Replace("\n", "\r"), "cr.bvh"))!;
            Assert.That(e.Line, Is.EqualTo(8));
            var mixed = Assert.Throws<BvhFormatException>(() => BvhReader.Parse(BvhSamples.TwoJoints.Replace("11 21 31 0 90", "11 21 31 0 x90").Replace("\t{\n", "\t{\r").Replace("}\n", "}\r\n"), "mixed.bvh"))!;
            Assert.That(mixed.Line, Is.EqualTo(20));
        }

        [Test]
        public void HugeNamesMakeShortMessages()
        {
            string name = new string('N', 1_000_000);
            string text = BvhSamples.TwoJoints.Replace("ROOT Hips", "ROOT " + name).Replace("JOINT Spine", "JOINT " + name);
            var e = Assert.Throws<BvhFormatException>(() => BvhReader.Parse(text, "names.bvh"))!;
            Assert.That(e.Message, Does.Contain("is used twice (first on line 2)"));
            Assert.That(e.Message.Length, Is.LessThan(300));

            string unknown = BvhSamples.TwoJoints.Replace("JOINT Spine", "JOINT " + name).Replace("\t\tOFFSET 0 10 0", "\t\tOFSET 0 10 0");
            var e2 = Assert.Throws<BvhFormatException>(() => BvhReader.Parse(unknown, "names.bvh"))!;
            Assert.That(e2.Message.Length, Is.LessThan(300));
        }
    }
}
