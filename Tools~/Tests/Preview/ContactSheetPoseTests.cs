using System;
using System.Collections.Generic;
using System.Linq;
using System.Text.RegularExpressions;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Preview;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Preview
{
    /// <summary>
    /// What the contact sheet draws (issue 30): poses between keys, not only at them; no bone from a root
    /// node at the world origin up to the hips; frame labels that are the file's.
    /// </summary>
    public sealed class ContactSheetPoseTests
    {
        /// <summary>
        /// Keys every 0.5 s on a 60 fps clip (a bake's keys: every 30 frames, the last frame a key): every
        /// row of the sheet shows poses that are not keys. Before the fix, 11 keys were thinned to every
        /// other one and the frame "between" two chosen keys was the skipped key, so every pose was a key.
        /// </summary>
        [Test]
        public void ABakeWithKeysEveryHalfSecondAt60FpsShowsPosesBetweenKeysInEveryRow()
        {
            foreach (int frames in new[] { 301, 601, 181, 1201 })
            {
                MotionClip truth = PreviewMotion.Walker(frames, 1.0 / 60);
                int[] keys = PreviewMotion.KeysEvery(frames, 30);
                Assert.That(keys[keys.Length - 1], Is.EqualTo(frames - 1), "a bake keys the last frame");
                PreviewScene scene = PreviewScene.FromClips(
                    "bake",
                    new[] { ("Ground truth", truth), ("SLERP", PreviewMotion.SlerpBaked(truth, keys)), ("Model", PreviewMotion.Wobbled(PreviewMotion.SlerpBaked(truth, keys), 5)) },
                    keys,
                    0);
                string svg = ContactSheet.BuildSvg(scene);

                // The drawing's own frame list (its footer), not the method that makes it.
                Match footer = Regex.Match(svg, "poses at frames ([0-9, ]+);");
                Assert.That(footer.Success, Is.True, "the sheet lists its pose frames");
                int[] poses = footer.Groups[1].Value.Split(',').Select(f => int.Parse(f.Trim(), System.Globalization.CultureInfo.InvariantCulture)).ToArray();
                int[] between = poses.Where(f => Array.IndexOf(keys, f) < 0).ToArray();
                Assert.That(between, Is.Not.Empty, $"{frames} frames: poses {string.Join(",", poses)} with keys every 30 frames");
                Assert.That(ContactSheetDrawing.PoseFrames(scene), Is.EqualTo(poses), "the footer lists the frames drawn");

                // Each method's row draws its in-between poses in its own colour (thin strokes, not the gold key pose).
                for (int t = 0; t < scene.Tracks.Count; t++)
                {
                    string color = TrackColors.Of(scene, t);
                    int drawn = Regex.Matches(svg, "<path fill=\"none\" stroke=\"" + Regex.Escape(color) + "\" stroke-opacity=\"0.9\"").Count;
                    Assert.That(drawn, Is.GreaterThanOrEqualTo(between.Length), $"{frames} frames: row {scene.Tracks[t].Name} draws its {between.Length} in-between poses");
                }
            }
        }

        /// <summary>
        /// A rig whose root node stays at the world origin with the hips below it in the hierarchy (a game
        /// studio's data set): no bone from the origin to the hips (the "third leg"), in the sheet and in
        /// the player's data; the root trail and the layout follow the hips.
        /// </summary>
        [Test]
        public void ARootNodeAtTheOriginIsNotDrawnAsABone()
        {
            string[] names = { "Reference", "Hips", "LeftUpLeg", "LeftFoot", "RightUpLeg", "RightFoot", "Spine", "Head" };
            int[] parents = { -1, 0, 1, 2, 1, 4, 1, 6 };
            const int frames = 40;
            var positions = new double[frames * names.Length * 3];
            for (int f = 0; f < frames; f++)
            {
                double z = 300 + 3 * f;
                double[] pose =
                {
                    0, 0, 0,
                    0, 95, z,
                    10, 50, z + 5, 10, 5, z + 8,
                    -10, 50, z - 5, -10, 5, z - 8,
                    0, 140, z, 0, 170, z,
                };
                Array.Copy(pose, 0, positions, f * pose.Length, pose.Length);
            }

            var track = new PreviewTrack("Ground truth", names.Length, positions);
            var scene = new PreviewScene("origin root", names, parents, 1.0 / 30, new[] { track, new PreviewTrack("Copy", names.Length, (double[])positions.Clone()) }, new[] { 0, 39 }, 0);
            Assert.That(scene.BodyRoot, Is.EqualTo(1), "the hips: the first joint with two children");
            Assert.That(Enumerable.Range(0, names.Length).Select(scene.DrawsBone), Is.EqualTo(new[] { false, false, true, true, true, true, true, true }));
            Assert.That(ContactSheetDrawing.TrailJoints(scene)[0], Is.EqualTo(1), "the root trail follows the hips");

            // Every drawn pose has the six bones below the hips and none from the origin.
            string svg = ContactSheet.BuildSvg(scene);
            foreach (Match pose in Regex.Matches(svg, " d=\"(M[^\"]*)\""))
            {
                Assert.That(Regex.Matches(pose.Groups[1].Value, "M").Count, Is.EqualTo(6), pose.Groups[1].Value);
            }

            string html = PreviewWriter.BuildHtml(scene);
            Assert.That(html, Does.Contain("\"bodyRoot\":1,\"drawsBone\":[0,0,1,1,1,1,1,1]"));

            // An ordinary skeleton (hips at the root with three children) keeps every bone.
            MotionClip walker = PreviewMotion.Walker(10);
            PreviewScene plain = PreviewScene.FromClips("walker", new[] { ("a", walker) });
            Assert.That(plain.BodyRoot, Is.EqualTo(0));
            Assert.That(Enumerable.Range(1, plain.JointCount - 1).All(plain.DrawsBone), Is.True);
        }

        /// <summary>A scene cut from frame START of its files labels its frames with the files' numbers.</summary>
        [Test]
        public void FrameLabelsAreTheFilesFrameNumbers()
        {
            MotionClip walker = PreviewMotion.Walker(61);
            int[] keys = PreviewMotion.KeysEvery(61, 20);
            PreviewScene scene = PreviewScene.FromClips("cut", new[] { ("Ground truth", walker), ("SLERP", PreviewMotion.SlerpBaked(walker, keys)) }, keys, 0);
            scene.FirstFrame = 1000;
            string svg = ContactSheet.BuildSvg(scene);
            Match footer = Regex.Match(svg, "poses at frames ([0-9, ]+);");
            int[] labels = footer.Groups[1].Value.Split(',').Select(f => int.Parse(f.Trim(), System.Globalization.CultureInfo.InvariantCulture)).ToArray();
            Assert.That(labels.Min(), Is.GreaterThanOrEqualTo(1000));
            Assert.That(labels, Does.Contain(1020).And.Contain(1060));
            Assert.That(svg, Does.Contain(">1040</text>"), "the side view's frame labels");
            Assert.That(PreviewWriter.BuildHtml(scene), Does.Contain("\"firstFrame\":1000"));
            Assert.Throws<ArgumentOutOfRangeException>(() => scene.FirstFrame = -1);
        }

        /// <summary>Errors read in centimetres when the skeleton tells its unit (the walker is in centimetres).</summary>
        [Test]
        public void ErrorsCarryTheirUnit()
        {
            MotionClip walker = PreviewMotion.Walker(60);
            int[] keys = PreviewMotion.KeysEvery(60, 20);
            PreviewScene scene = PreviewScene.FromClips("units", new[] { ("Ground truth", walker), ("SLERP", PreviewMotion.Wobbled(walker, 8)) }, keys, 0);
            Assert.That(scene.MetresPerUnit, Is.EqualTo(0.01));
            Assert.That(scene.FormatDistance(3.14159), Is.EqualTo("3.1 cm"));
            Assert.That(ContactSheet.BuildSvg(scene), Does.Match("mean error [0-9.]+ cm"));
            scene.MetresPerUnit = null;
            Assert.That(scene.FormatDistance(3.14159), Is.EqualTo("3.142 data units"));
        }
    }
}
