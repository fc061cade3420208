using System;
using System.Linq;
using System.Text.Json;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Preview;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Preview
{
    public sealed class PreviewSceneTests
    {
        [Test]
        public void TrackOfAClipHoldsForwardKinematicsPositions()
        {
            MotionClip clip = PreviewMotion.Walker(40);
            PreviewTrack track = PreviewTrack.FromClip("walker", clip);
            int j = clip.Skeleton.JointCount;
            var expected = new double[40 * j * 3];
            ForwardKinematics.ComputeWithLocalPositions(clip.Skeleton, 40, clip.LocalPositions, clip.LocalRotations, expected, new double[40 * j * 4]);
            Assert.That(track.FrameCount, Is.EqualTo(40));
            Assert.That(track.GlobalPositions, Is.EqualTo(expected));
            // The walker's head is well above its hips: the positions are global, not local offsets.
            int head = clip.Skeleton.Names.ToList().IndexOf("Head");
            Assert.That(track.GlobalPositions[head * 3 + 1], Is.GreaterThan(track.GlobalPositions[1] + 50));
        }

        [Test]
        public void ErrorPerFrameIsTheMeanJointDistanceToTheGroundTruth()
        {
            MotionClip clip = PreviewMotion.Walker(30);
            PreviewTrack truth = PreviewTrack.FromClip("truth", clip);
            // Every joint moved by (3, 0, 4): a distance of exactly 5 on every frame.
            double[] moved = (double[])truth.GlobalPositions.Clone();
            for (int i = 0; i < moved.Length; i += 3)
            {
                moved[i] += 3;
                moved[i + 2] += 4;
            }

            var scene = new PreviewScene("t", clip.Skeleton.Names, clip.Skeleton.Parents, clip.FrameTime, new[] { truth, new PreviewTrack("moved", clip.Skeleton.JointCount, moved) }, new[] { 0, 29 }, 0);
            Assert.That(scene.ErrorPerFrame(1), Has.Length.EqualTo(30).And.All.EqualTo(5).Within(1e-9));
            Assert.That(scene.ErrorPerFrame(0), Has.All.EqualTo(0));
            Assert.That(scene.MeanErrorBetweenKeys(1), Is.EqualTo(5).Within(1e-9));
        }

        [Test]
        public void MeanErrorBetweenKeysLeavesTheKeyFramesOut()
        {
            MotionClip clip = PreviewMotion.Walker(31);
            int[] keys = { 0, 15, 30 };
            PreviewScene scene = PreviewScene.FromClips("slerp", new[] { ("truth", clip), ("slerp", PreviewMotion.SlerpBaked(clip, keys)) }, keys, 0);
            double[] errors = scene.ErrorPerFrame(1);
            Assert.That(keys.Select(k => errors[k]), Has.All.EqualTo(0).Within(1e-9), "SLERP keeps the key frames");
            double expected = Enumerable.Range(0, 31).Where(f => !keys.Contains(f)).Average(f => errors[f]);
            Assert.That(scene.MeanErrorBetweenKeys(1), Is.EqualTo(expected).Within(1e-12));
            Assert.That(expected, Is.GreaterThan(0.5), "SLERP across half a stride misses the swinging limbs");
        }

        [Test]
        public void ScenesRefuseDifferentSkeletonsAndBadKeys()
        {
            MotionClip walker = PreviewMotion.Walker(10);
            var names = walker.Skeleton.Names.ToArray();
            names[3] = "Skull";
            var other = new MotionClip(new Skeleton(names, walker.Skeleton.Parents, walker.Skeleton.OffsetSpan.ToArray()), 10, walker.FrameTime, walker.LocalPositions, walker.LocalRotations);
            var e = Assert.Throws<ArgumentException>(() => PreviewScene.FromClips("x", new[] { ("a", walker), ("b", other) }));
            Assert.That(e!.Message, Does.Contain("joint 3 is 'Skull' where the first has 'Head'"));
            var e2 = Assert.Throws<ArgumentException>(() => PreviewScene.FromClips("x", new[] { ("a", walker), ("b", PreviewMotion.Walker(10, 1.0 / 120)) }));
            Assert.That(e2!.Message, Does.Contain("120 fps where the first has 30 fps"));
            Assert.Throws<ArgumentOutOfRangeException>(() => PreviewScene.FromClips("x", new[] { ("a", walker) }, new[] { 0, 10 }));
            Assert.Throws<ArgumentException>(() => PreviewScene.FromClips("x", new[] { ("a", walker) }, new[] { 5, 5 }));
            Assert.Throws<ArgumentOutOfRangeException>(() => PreviewScene.FromClips("x", new[] { ("a", walker) }, null, 1));
        }

        [Test]
        public void PlayerDataRoundTripsPositionsToTheQuantum()
        {
            MotionClip clip = PreviewMotion.Walker(50);
            PreviewScene scene = PreviewScene.FromClips("walker <script>", new[] { ("truth", clip), ("wobbled", PreviewMotion.Wobbled(clip, 5)) }, new[] { 0, 25, 49 }, 0);
            string html = PreviewWriter.BuildHtml(scene);
            const string open = "<script type=\"application/json\" id=\"preview-data\">";
            int start = html.IndexOf(open, StringComparison.Ordinal) + open.Length;
            int end = html.IndexOf("</script>", start, StringComparison.Ordinal);
            Assert.That(html.Substring(start, end - start), Does.Not.Contain("<"), "the data never closes its script element");
            using JsonDocument doc = JsonDocument.Parse(html.Substring(start, end - start));
            JsonElement root = doc.RootElement;
            double quantum = root.GetProperty("quantum").GetDouble();
            Assert.That(quantum, Is.EqualTo(0.01), "a 1.6 m figure in centimetres is stored to 0.1 mm");
            Assert.That(root.GetProperty("fps").GetDouble(), Is.EqualTo(30).Within(1e-6));
            Assert.That(root.GetProperty("keys").EnumerateArray().Select(k => k.GetInt32()), Is.EqualTo(new[] { 0, 25, 49 }));
            for (int t = 0; t < 2; t++)
            {
                JsonElement track = root.GetProperty("tracks")[t];
                long[] deltas = track.GetProperty("deltas").EnumerateArray().Select(v => v.GetInt64()).ToArray();
                int stride = clip.Skeleton.JointCount * 3;
                double[] expected = scene.Tracks[t].GlobalPositions;
                Assert.That(deltas, Has.Length.EqualTo(expected.Length));
                var sum = new long[stride];
                double worst = 0;
                for (int i = 0; i < deltas.Length; i++)
                {
                    sum[i % stride] += deltas[i];
                    worst = Math.Max(worst, Math.Abs(sum[i % stride] * quantum - expected[i]));
                }

                Assert.That(worst, Is.LessThanOrEqualTo(quantum / 2 + 1e-9));
            }

            JsonElement errors = root.GetProperty("tracks")[1].GetProperty("errors");
            double[] truthErrors = scene.ErrorPerFrame(1);
            Assert.That(errors.EnumerateArray().Select(v => v.GetInt64() * quantum).ToArray(), Is.EqualTo(truthErrors).Within(quantum));
            Assert.That(html, Does.Contain("<title>walker &lt;script&gt;</title>"));
        }
    }
}
