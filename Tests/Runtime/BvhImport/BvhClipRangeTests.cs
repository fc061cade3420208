using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.BvhImport;
using DeltaInterpolator.Core.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.BvhImport
{
    /// <summary>
    /// The <c>.bvh</c> importer's clip ranges (<see cref="BvhClipRange"/>: one clip per range, keyed from 0, looping or not) and
    /// the measure that places a loop's seam (<see cref="LoopSeam"/>), on a synthetic periodic motion and on the Demo sample's
    /// ranges, which its <c>.bvh.meta</c> files hold: each looping range must end where the measure puts it.
    /// </summary>
    public sealed class BvhClipRangeTests
    {
        // Where the Demo's walk loop was searched (its README says the same): one gait cycle at 120 fps (0.83–1.33 s long). The
        // idle is the standing end of the jumps take played forward and back: a standing sway never comes back to where it started
        // (no cut of frames 840 to 900 has a seam under 2.4°, eight times its largest step), so it loops by ping-pong.
        private static readonly Dictionary<string, (int FirstFrom, int FirstTo, int MinFrames, int MaxFrames)> DemoLoopWindows = new Dictionary<string, (int, int, int, int)>
        {
            // Starting anywhere in the walk forward after its first steps (frames 100 to 330: 0.8 to 2.75 s).
            ["Walk"] = (100, 330, 100, 160),
        };

        [Test]
        public void ARangesCurvesAreTheFilesFramesKeyedFromZero()
        {
            BvhImportResult import = Demo("cmu_01_01_jumps_turn.bvh");
            var range = new BvhClipRange("Jump", 156, 348, false);
            IReadOnlyList<ClipCurve> cut = range.Curves(import);
            Assert.That(cut.Count, Is.EqualTo(import.Curves.Count));
            for (int c = 0; c < cut.Count; c++)
            {
                Assert.That(cut[c].Path, Is.EqualTo(import.Curves[c].Path));
                Assert.That(cut[c].Property, Is.EqualTo(import.Curves[c].Property));
                Assert.That(cut[c].KeyCount, Is.EqualTo(193));
                for (int k = 0; k < cut[c].KeyCount; k++)
                {
                    Assert.That(cut[c].Values[k], Is.EqualTo(import.Curves[c].Values[156 + k]), $"{cut[c].Path} {cut[c].Property} key {k}");
                    Assert.That(cut[c].Times[k], Is.EqualTo((float)(k / import.FrameRate)));
                }
            }

            Assert.That(range.SubAssetId, Is.EqualTo("clip:Jump"));
        }

        [TestCase("", 0, 10, "has no name")]
        [TestCase("Walk", -1, 10, "spans frames -1 to 10")]
        [TestCase("Walk", 10, 9, "spans frames 10 to 9")]
        [TestCase("Walk", 0, 901, "spans frames 0 to 901")]
        public void RangesThatDoNotFitTheFileAreRefusedNamingIt(string name, int first, int last, string problem)
        {
            BvhImportResult import = Demo("cmu_01_01_jumps_turn.bvh");
            var e = Assert.Throws<DataFormatException>(() => BvhClipRange.Check(new[] { new BvhClipRange(name, first, last, false) }, import));
            Assert.That(e!.Message, Does.StartWith(import.SourceName + ":").And.Contain(problem).And.Contain("expected"));
        }

        [Test]
        public void TwoRangesOfOneNameAreRefused()
        {
            BvhImportResult import = Demo("cmu_01_01_jumps_turn.bvh");
            var ranges = new[] { new BvhClipRange("Idle", 0, 10, true), new BvhClipRange("Idle", 20, 30, true) };
            var e = Assert.Throws<DataFormatException>(() => BvhClipRange.Check(ranges, import));
            Assert.That(e!.Message, Does.Contain("repeats the name 'Idle'"));
        }

        [Test]
        public void APingPongRangePlaysForwardThenBackToTheFrameAfterItsFirst()
        {
            Assert.That(new BvhClipRange("Idle", 10, 14, true, pingPong: true).ClipFrames(), Is.EqualTo(new[] { 10, 11, 12, 13, 14, 13, 12, 11 }));
            Assert.That(new BvhClipRange("Walk", 10, 14, true).ClipFrames(), Is.EqualTo(new[] { 10, 11, 12, 13, 14 }));
            BvhImportResult import = Demo("cmu_01_01_jumps_turn.bvh");
            IReadOnlyList<ClipCurve> curves = new BvhClipRange("Idle", 840, 898, true, pingPong: true).Curves(import);
            Assert.That(curves[0].KeyCount, Is.EqualTo(116));
            Assert.That(curves[0].Values[60], Is.EqualTo(import.Curves[0].Values[896]), "key 60 is frame 898 - 2 on the way back");
        }

        [Test]
        public void TheSeamOfAPeriodicMotionIsFoundAtItsPeriod()
        {
            // A chest swinging with a 40-frame period: a loop from frame 5 ends on frame 44, and its seam costs nothing.
            BvhImportResult import = BvhClipImport.Import(Encoding.UTF8.GetBytes(Periodic(40, 160)), "periodic.bvh", 0.01);
            int last = LoopSeam.BestLast(import, 5, 20, 70);
            Assert.That(last, Is.EqualTo(44));
            Assert.That(LoopSeam.Cost(import, 5, last), Is.LessThan(0.05), "float32 keys: acos near 1 reads their rounding as hundredths of a degree");
            Assert.That(LoopSeam.Cost(import, 5, 34), Is.GreaterThan(1.0), "a quarter period off is a visible jump");
            Assert.That(LoopSeam.LargestStep(import, 5, last), Is.GreaterThan(LoopSeam.Cost(import, 5, last)));
        }

        [Test]
        public void TheDemosLoopsEndWhereTheirSeamIsSmallest()
        {
            foreach ((string file, BvhClipRange range) in DemoRanges())
            {
                if (!range.Loop) continue;
                BvhImportResult import = Demo(file);
                if (range.PingPong)
                {
                    // Forward then back: the wrap, from the frame after the first back to the first, is one of the clip's own steps.
                    int[] frames = range.ClipFrames();
                    double wrap = LoopSeam.PoseDistance(import, frames[frames.Length - 1], frames[0]);
                    double largest = LoopSeam.LargestStep(import, range.FirstFrame, range.LastFrame);
                    TestContext.Out.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0} ({1}): frames {2}..{3} forward and back ({4:0.000} s); wrap {5:0.000}°, the clip's largest one-frame step {6:0.000}°",
                        range.Name, file, range.FirstFrame, range.LastFrame, frames.Length / import.FrameRate, wrap, largest));
                    Assert.That(wrap, Is.LessThanOrEqualTo(largest), $"{range.Name}: the ping-pong wrap is larger than a step of the clip");
                    continue;
                }

                (int from, int to, int min, int max) = DemoLoopWindows[range.Name];
                (int bestFirst, int best) = LoopSeam.Best(import, from, to, min, max);
                double seam = LoopSeam.Cost(import, range.FirstFrame, range.LastFrame);
                double step = LoopSeam.LargestStep(import, range.FirstFrame, range.LastFrame);
                var costs = new List<double>();
                for (int last = range.FirstFrame + min - 1; last <= range.FirstFrame + max - 1; last++) costs.Add(LoopSeam.Cost(import, range.FirstFrame, last));
                double median = costs.OrderBy(c => c).ElementAt(costs.Count / 2);
                TestContext.Out.WriteLine(string.Format(CultureInfo.InvariantCulture,
                    "{0} ({1}): frames {2}..{3} ({4:0.000} s); seam {5:0.000}° (window's median {6:0.000}°, worst {7:0.000}°); the clip's largest one-frame step {8:0.000}°",
                    range.Name, file, range.FirstFrame, range.LastFrame, range.FrameCount / import.FrameRate, seam, median, costs.Max(), step));
                Assert.That((range.FirstFrame, range.LastFrame), Is.EqualTo((bestFirst, best)), $"{range.Name}: the .meta's range is not the measured best (first {from}..{to}, {min}..{max} frames)");
                // No pop: the wrap moves the pose less than two of the clip's fastest frames (Loop Pose then spreads what is left).
                Assert.That(seam, Is.LessThan(2 * step), $"{range.Name}: the seam is a pop");
            }
        }

        // The Demo sample's clip ranges, as the .bvh importer reads them from each file's .meta (ScriptedImporter fields).
        private static IEnumerable<(string File, BvhClipRange Range)> DemoRanges()
        {
            var found = new List<(string, BvhClipRange)>();
            foreach (string file in new[] { "cmu_01_01_jumps_turn.bvh", "cmu_09_12_walk_navigate.bvh" })
            {
                string[] lines = File.ReadAllLines(DemoPath(file) + ".meta");
                for (int i = 0; i < lines.Length; i++)
                {
                    string line = lines[i].Trim();
                    if (!line.StartsWith("- name: ", StringComparison.Ordinal)) continue;
                    string name = line.Substring("- name: ".Length);
                    int first = int.Parse(Field(lines[i + 1], "firstFrame"), CultureInfo.InvariantCulture);
                    int last = int.Parse(Field(lines[i + 2], "lastFrame"), CultureInfo.InvariantCulture);
                    bool loop = Field(lines[i + 3], "loop") == "1";
                    bool pingPong = Field(lines[i + 4], "pingPong") == "1";
                    found.Add((file, new BvhClipRange(name, first, last, loop, pingPong)));
                }
            }

            Assert.That(found.Select(r => r.Item2.Name), Is.EquivalentTo(new[] { "Idle", "Jump", "Walk" }), "the Demo's clips");
            return found;
        }

        private static string Field(string line, string name)
        {
            string trimmed = line.Trim();
            Assert.That(trimmed, Does.StartWith(name + ": "));
            return trimmed.Substring(name.Length + 2);
        }

        private static string DemoPath(string file)
        {
            string path = Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", file);
            if (!File.Exists(path)) Assert.Ignore($"{path} absent (Samples~ not in this copy); skipping.");
            return path;
        }

        private static BvhImportResult Demo(string file) => BvhClipImport.ImportFile(DemoPath(file));

        private static string Periodic(int period, int frames)
        {
            var sb = new StringBuilder();
            sb.Append("HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 100 0\n\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n");
            sb.Append("\tJOINT Chest\n\t{\n\t\tOFFSET 0 20 0\n\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 20 0\n\t\t}\n\t}\n");
            sb.Append("\tJOINT Leg\n\t{\n\t\tOFFSET 0 -50 0\n\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 -50 0\n\t\t}\n\t}\n}\n");
            sb.Append("MOTION\nFrames: ").Append(frames).Append("\nFrame Time: 0.0083333\n");
            for (int f = 0; f < frames; f++)
            {
                double swing = 30.0 * Math.Sin(2.0 * Math.PI * f / period);
                double leg = 20.0 * Math.Cos(2.0 * Math.PI * f / period);
                sb.Append(string.Format(CultureInfo.InvariantCulture, "{0:R} 100 0 0 0 0 {1:R} 0 0 {2:R} 0 0\n", 0.5 * f, swing, leg));
            }

            return sb.ToString();
        }
    }
}
