using System;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Bvh
{
    public class BvhReaderTests
    {
        private const double Deg = Math.PI / 180.0;

        [Test]
        public void ReadsHierarchyChannelsAndMotion()
        {
            BvhAnimation a = BvhReader.Parse(BvhSamples.TwoJoints, "two.bvh");
            Assert.That(a.Skeleton.Names, Is.EqualTo(new[] { "Hips", "Spine" }));
            Assert.That(a.Skeleton.Parents, Is.EqualTo(new[] { -1, 0 }));
            Assert.That(a.Skeleton.Offsets, Is.EqualTo(new double[] { 1, 2, 3, 0, 10, 0 }));
            Assert.That(a.EndSites[1], Has.Length.EqualTo(1), "End Site kept for writing, but not a joint");
            Assert.That(a.Motion.FrameCount, Is.EqualTo(2));
            Assert.That(a.Motion.FrameTime, Is.EqualTo(0.033333));
            Assert.That(a.ChannelCount, Is.EqualTo(9));
            Assert.That(a.RotationOrder(0), Is.EqualTo(EulerOrder.Zyx));
            // Frame 1: root at (11, 21, 31); Spine at its offset.
            Assert.That(a.Motion.LocalPositions[6], Is.EqualTo(11));
            Assert.That(a.Motion.LocalPositions[9 + 1], Is.EqualTo(10), "non-root joints sit at their offsets");
            // Frame 0: Spine Zrotation 90°.
            RotationAssert.SameRotation(QuaternionD.Read(a.Motion.LocalRotations, 4), Quaternions.FromAxisAngle(Vector3D.UnitZ, 90 * Deg), 1e-15);
            // Frame 1: root Yrotation 90°.
            RotationAssert.SameRotation(QuaternionD.Read(a.Motion.LocalRotations, 8), Quaternions.FromAxisAngle(Vector3D.UnitY, 90 * Deg), 1e-15);
        }

        [Test]
        public void AcceptsCrlfTabsSpacesAndExponents()
        {
            string text = BvhSamples.TwoJoints.Replace("\n", "\r\n")
                .Replace("10 20 30 0 0 0 90 0 0", "1.0E1\t2e+1   3.0e1 0 0 0 9.0e1 -0.0 +0 ");
            BvhAnimation a = BvhReader.Parse(text, "crlf.bvh");
            Assert.That(a.Motion.LocalPositions[0], Is.EqualTo(10.0));
            Assert.That(a.Motion.LocalPositions[1], Is.EqualTo(20.0));
            Assert.That(a.Motion.LocalPositions[2], Is.EqualTo(30.0));
            RotationAssert.SameRotation(QuaternionD.Read(a.Motion.LocalRotations, 4), Quaternions.FromAxisAngle(Vector3D.UnitZ, 90 * Deg), 1e-15);
        }

        [Test]
        public void ParsesDecimalsExactlyLikeTheFramework()
        {
            var random = new TestRandom(11);
            string[] samples = { "-287.536011", "0.000001", "123456789012345678901234", "1.7976931348623157e308", "4.9e-324", "0.1", "-0.030654", "92.468430", "1e-30",
                "0.12345678901234567890123", "1234567890123456789012.5", "0.000000000000000000001234", ".5", "5." };
            foreach (string s in samples) CheckValue(s);
            for (int i = 0; i < 2000; i++)
            {
                double v = random.Uniform(-1000, 1000);
                CheckValue(v.ToString("F6", System.Globalization.CultureInfo.InvariantCulture));
                CheckValue(v.ToString("R", System.Globalization.CultureInfo.InvariantCulture));
            }
        }

        private static void CheckValue(string text)
        {
            string bvh = BvhSamples.TwoJoints.Replace("10 20 30 0 0 0 90 0 0", text + " 20 30 0 0 0 90 0 0");
            double expected = double.Parse(text, System.Globalization.CultureInfo.InvariantCulture);
            Assert.That(BvhReader.Parse(bvh, "n.bvh").Motion.LocalPositions[0], Is.EqualTo(expected), text);
        }

        [Test]
        public void SupportsSixChannelsOnAnyJointAndPositionOnlyJoints()
        {
            string text = BvhSamples.TwoJoints
                .Replace("\t\tCHANNELS 3 Zrotation Yrotation Xrotation", "\t\tCHANNELS 6 Yrotation Xposition Xrotation Yposition Zrotation Zposition")
                .Replace("10 20 30 0 0 0 90 0 0", "10 20 30 0 0 0 90 1 0 2 0 3")
                .Replace("11 21 31 0 90 0 0 0 0", "11 21 31 0 90 0 0 1 0 2 0 3");
            BvhAnimation a = BvhReader.Parse(text, "six.bvh");
            Assert.That(a.ChannelCount, Is.EqualTo(12));
            Assert.That(a.RotationOrder(1), Is.EqualTo(EulerOrder.Yxz));
            Assert.That(new[] { a.Motion.LocalPositions[3], a.Motion.LocalPositions[4], a.Motion.LocalPositions[5] }, Is.EqualTo(new double[] { 1, 2, 3 }));
            RotationAssert.SameRotation(QuaternionD.Read(a.Motion.LocalRotations, 4), Quaternions.FromAxisAngle(Vector3D.UnitY, 90 * Deg), 1e-15);

            string positionsOnly = BvhSamples.TwoJoints
                .Replace("\t\tCHANNELS 3 Zrotation Yrotation Xrotation", "\t\tCHANNELS 3 Xposition Yposition Zposition");
            BvhAnimation p = BvhReader.Parse(positionsOnly, "pos.bvh");
            Assert.That(p.RotationOrder(1), Is.Null);
            Assert.That(p.Motion.LocalPositions[3 + 1], Is.EqualTo(0), "Yposition read from the motion line");
            Assert.That(QuaternionD.Read(p.Motion.LocalRotations, 4), Is.EqualTo(QuaternionD.Identity));
        }

        [Test]
        public void AcceptsJointNamesWithSpacesAndBracesOnTheNameLine()
        {
            string text = BvhSamples.TwoJoints.Replace("\tJOINT Spine\n\t{\n", "\tJOINT Left Spine {\n");
            BvhAnimation a = BvhReader.Parse(text, "names.bvh");
            Assert.That(a.Skeleton.Names[1], Is.EqualTo("Left Spine"));
        }

        [Test]
        public void EveryNumberOnAMotionLineMustBeFinite()
        {
            foreach (string bad in new[] { "nan", "NaN", "inf", "-Infinity", "1e400" })
            {
                string text = BvhSamples.TwoJoints.Replace("11 21 31", "11 " + bad + " 31");
                var e = Assert.Throws<BvhFormatException>(() => BvhReader.Parse(text, "f.bvh"))!;
                Assert.That(e.Line, Is.EqualTo(20), bad);
                Assert.That(e.Message, Does.Contain("not a finite number"), bad);
            }
        }

        /// <summary>Each malformed input: where it fails (line) and a phrase the message must contain.</summary>
        private static readonly object[] MalformedCases =
        {
            new object[] { "empty file", "", 1, "the file is empty" },
            new object[] { "whitespace only", "  \r\n\r\n", 1, "the file is empty" },
            new object[] { "missing HIERARCHY", BvhSamples.TwoJoints.Replace("HIERARCHY\n", ""), 1, "expected HIERARCHY" },
            new object[] { "missing MOTION", BvhSamples.TwoJoints.Replace("MOTION\n", ""), 16, "expected MOTION" },
            new object[] { "hierarchy only", BvhSamples.TwoJoints.Substring(0, BvhSamples.TwoJoints.IndexOf("MOTION", StringComparison.Ordinal)), 15, "expected a MOTION section" },
            new object[] { "truncated inside the hierarchy", BvhSamples.TwoJoints.Substring(0, BvhSamples.TwoJoints.IndexOf("\t\tEnd Site", StringComparison.Ordinal)), 9, "the file ends inside joint 'Spine'" },
            new object[] { "truncated after End", BvhSamples.TwoJoints.Substring(0, BvhSamples.TwoJoints.IndexOf("End Site", StringComparison.Ordinal) + 3), 10, "the file ends too early (truncated file?); expected 'Site' after 'End'" },
            new object[] { "truncated after MOTION", BvhSamples.TwoJoints.Substring(0, BvhSamples.TwoJoints.IndexOf("Frames:", StringComparison.Ordinal)), 16, "the file ends too early (truncated file?); expected 'Frames: N' after MOTION" },
            new object[] { "truncated after a joint name", BvhSamples.TwoJoints.Substring(0, BvhSamples.TwoJoints.IndexOf("\t{", StringComparison.Ordinal)), 6, "the file ends too early (truncated file?); expected '{' opening joint 'Spine'" },
            new object[] { "truncated motion (missing frame)", BvhSamples.TwoJoints.Replace("11 21 31 0 90 0 0 0 0\n", ""), 19, "the file ends after 1 of the 2 frames" },
            new object[] { "truncated mid-line", BvhSamples.TwoJoints.Replace("11 21 31 0 90 0 0 0 0\n", "11 21 31 0 9"), 20, "has 5 values" },
            new object[] { "Frames: larger than the motion lines", BvhSamples.TwoJoints.Replace("Frames: 2", "Frames: 3"), 20, "the file ends after 2 of the 3 frames" },
            new object[] { "Frames: smaller than the motion lines", BvhSamples.TwoJoints.Replace("Frames: 2", "Frames: 1"), 20, "more motion lines than the 1" },
            new object[] { "Frames: not a number", BvhSamples.TwoJoints.Replace("Frames: 2", "Frames: two"), 17, "expected a whole number of frames" },
            new object[] { "missing Frame Time", BvhSamples.TwoJoints.Replace("Frame Time: 0.033333\n", ""), 18, "expected 'Frame Time: seconds'" },
            new object[] { "zero Frame Time", BvhSamples.TwoJoints.Replace("Frame Time: 0.033333", "Frame Time: 0"), 18, "expected a positive number of seconds" },
            new object[] { "too few values on a line", BvhSamples.TwoJoints.Replace("10 20 30 0 0 0 90 0 0", "10 20 30 0 0 0 90 0"), 19, "frame 1 of 2 has 8 values; expected 9" },
            new object[] { "too many values on a line", BvhSamples.TwoJoints.Replace("10 20 30 0 0 0 90 0 0", "10 20 30 0 0 0 90 0 0 7 8"), 19, "frame 1 of 2 has 11 values; expected 9" },
            new object[] { "non-numeric token", BvhSamples.TwoJoints.Replace("11 21 31 0 90", "11 21 31 0 x90"), 20, "'x90' is not a number" },
            new object[] { "comma decimal", BvhSamples.TwoJoints.Replace("11 21 31 0 90", "11 21 31 0 9,5"), 20, "'9,5' is not a number" },
            new object[] { "NaN in the motion", BvhSamples.TwoJoints.Replace("11 21 31 0 90", "11 21 31 0 NaN"), 20, "not a finite number" },
            new object[] { "Inf in an offset", BvhSamples.TwoJoints.Replace("OFFSET 0 10 0", "OFFSET 0 Inf 0"), 8, "not a finite number" },
            new object[] { "non-numeric offset", BvhSamples.TwoJoints.Replace("OFFSET 0 10 0", "OFFSET 0 ten 0"), 8, "'ten' is not a number" },
            new object[] { "short offset", BvhSamples.TwoJoints.Replace("OFFSET 0 10 0", "OFFSET 0 10"), 8, "has too few values" },
            new object[] { "unknown channel name", BvhSamples.TwoJoints.Replace("CHANNELS 3 Zrotation Yrotation Xrotation", "CHANNELS 3 Zrotation Yrot Xrotation"), 9, "unknown channel 'Yrot'" },
            new object[] { "wrong channel count", BvhSamples.TwoJoints.Replace("CHANNELS 3 Zrotation", "CHANNELS 4 Zrotation"), 9, "expected 3 or 6 channels" },
            new object[] { "channel listed twice", BvhSamples.TwoJoints.Replace("CHANNELS 3 Zrotation Yrotation Xrotation", "CHANNELS 3 Zrotation Zrotation Xrotation"), 9, "listed twice" },
            new object[] { "two rotations and a position", BvhSamples.TwoJoints.Replace("CHANNELS 3 Zrotation Yrotation Xrotation", "CHANNELS 3 Zrotation Yrotation Xposition"), 9, "2 rotation channels" },
            new object[] { "CHANNELS with too few names", BvhSamples.TwoJoints.Replace("CHANNELS 3 Zrotation Yrotation Xrotation", "CHANNELS 3 Zrotation Yrotation"), 9, "names only 2 channels" },
            new object[] { "duplicate joint names", BvhSamples.TwoJoints.Replace("JOINT Spine", "JOINT Hips"), 6, "joint name 'Hips' is used twice (first on line 2)" },
            new object[] { "unbalanced: missing closing brace", BvhSamples.TwoJoints.Replace("\t}\n}\nMOTION", "}\nMOTION"), 15, "MOTION while joint 'Hips' is still open" },
            new object[] { "unbalanced: extra closing brace", BvhSamples.TwoJoints.Replace("}\nMOTION", "}\n}\nMOTION"), 16, "without a matching '{'" },
            new object[] { "missing opening brace", BvhSamples.TwoJoints.Replace("\tJOINT Spine\n\t{\n", "\tJOINT Spine\n"), 7, "expected '{'" },
            new object[] { "joint without CHANNELS", BvhSamples.TwoJoints.Replace("\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n", ""), 9, "joint 'Spine' has no CHANNELS line" },
            new object[] { "joint without OFFSET", BvhSamples.TwoJoints.Replace("\t\tOFFSET 0 10 0\n", ""), 9, "joint 'Spine' has no OFFSET" },
            new object[] { "unknown keyword", BvhSamples.TwoJoints.Replace("\t\tOFFSET 0 10 0\n", "\t\tOFSET 0 10 0\n"), 8, "found 'OFSET' in joint 'Spine'" },
            new object[] { "second ROOT", BvhSamples.TwoJoints.Replace("}\nMOTION", "}\nROOT Other\n{\n}\nMOTION"), 16, "a second ROOT" },
            new object[] { "not a BVH file", "{\"json\": true}\n", 1, "expected HIERARCHY" },
        };

        [TestCaseSource(nameof(MalformedCases))]
        public void MalformedInputThrowsOneExceptionTypeWithFileLineAndExpectation(string what, string text, int line, string phrase)
        {
            var e = Assert.Throws<BvhFormatException>(() => BvhReader.Parse(text, "bad.bvh"), what)!;
            Assert.That(e.Source, Is.EqualTo("bad.bvh"));
            Assert.That(e.Line, Is.EqualTo(line), $"{what}: {e.Message}");
            Assert.That(e.Message, Does.StartWith($"bad.bvh:{line}: "), what);
            Assert.That(e.Message, Does.Contain(phrase), what);
            Assert.That(e.Message, Does.Contain("; expected "), what);
            Assert.That(e.Expected, Is.Not.Empty, what);
        }

        [Test]
        public void EveryPrefixOfAValidFileFailsCleanly()
        {
            // Truncation anywhere must give a BvhFormatException (or, at a line end after the last
            // frame, a valid file) — never an index, format or null-reference error.
            string text = BvhSamples.TwoJoints;
            for (int length = 0; length < text.Length; length++)
            {
                string prefix = text.Substring(0, length);
                try
                {
                    BvhReader.Parse(prefix, "prefix.bvh");
                }
                catch (BvhFormatException)
                {
                }
            }

            Assert.Pass("every prefix either parsed or raised BvhFormatException");
        }

        [Test]
        public void ReadReportsThePathOfTheFile()
        {
            string path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "deltainterp-bad-" + Guid.NewGuid().ToString("N") + ".bvh");
            System.IO.File.WriteAllText(path, "HIERARCHY\nROOT\n");
            try
            {
                var e = Assert.Throws<BvhFormatException>(() => BvhReader.Read(path))!;
                Assert.That(e.Message, Does.StartWith(path + ":2: ROOT without a name"));
            }
            finally
            {
                System.IO.File.Delete(path);
            }
        }
    }
}
