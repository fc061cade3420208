using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Preview;
using DeltaInterpolator.Tests.Preview;
using Microsoft.Playwright;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// <c>demo</c> end to end (the bundled CMU clip, the shipped model, real Chromium) and <c>bake</c> on a
    /// CMU input (retargeted onto the model's skeleton and back): the files it writes read back, the
    /// preview plays, the key frames come back exactly, and bad input is refused with one line.
    /// </summary>
    public sealed class DemoVerbTests
    {
        private string _dir = "";

        private static string Root => TestEnvironment.RepositoryRoot!;

        private static string Sample => Path.Combine(Root, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        [SetUp]
        public void CreateFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "inbetween-demo-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void RemoveFolder() => Directory.Delete(_dir, true);

        [Test]
        public async Task DemoWritesReadableFilesAPlayingPreviewAndANonBlankSheet()
        {
            string folder = Path.Combine(_dir, "demo");
            CliRun run = CliHarness.Run("demo", "--out", folder);
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain("SLERP").And.Contain("Model").And.Contain("preview.html"), run.ToString());

            foreach (string name in new[] { "ground-truth.bvh", "slerp.bvh", "model.bvh", "model-on-source.bvh" })
            {
                string path = Path.Combine(folder, name);
                Assert.That(File.Exists(path), Is.True, name);
                CliRun info = CliHarness.Run("info", path);
                Assert.That(info.ExitCode, Is.EqualTo(0), info.ToString());
            }

            BvhAnimation source = BvhReader.Read(Sample);
            BvhAnimation onSource = BvhReader.Read(Path.Combine(folder, "model-on-source.bvh"));
            Assert.That(onSource.Skeleton.HasSameHierarchy(source.Skeleton), Is.True, "model-on-source.bvh is on the CMU skeleton");
            Assert.That(BvhReader.Read(Path.Combine(folder, "model.bvh")).Skeleton.JointCount, Is.EqualTo(22), "model.bvh is on the model's skeleton");

            string html = Path.Combine(folder, "preview.html");
            string png = Path.Combine(folder, "preview.png");
            string? chromium = ContactSheet.FindChromium();
            if (chromium == null)
            {
                Assert.That(File.Exists(ContactSheet.OutputPathFor(png)), Is.True, "without Chromium the contact sheet is an SVG");
                Assert.Ignore("Chromium absent: the HTML player and the PNG were not checked in a browser (./Tools~/test installs Chromium when it can).");
            }

            PngImage sheet = PngImage.Decode(File.ReadAllBytes(png));
            Assert.That(sheet.LuminanceVariance(), Is.GreaterThan(100), "the contact sheet is not blank");

            (IPlaywright playwright, IBrowser browser) = await Chromium.LaunchAsync(chromium!);
            try
            {
                IPage page = await browser.NewPageAsync();
                List<string> problems = PreviewBrowserTests.Watch(page, out List<string> requests);
                await page.GotoAsync(new Uri(html).AbsoluteUri);
                await page.WaitForFunctionAsync("window.preview !== undefined");
                Assert.That(await page.EvaluateAsync<int>("window.preview.frameCount"), Is.EqualTo(onSource.Motion.FrameCount));
                int first = await page.EvaluateAsync<int>("window.preview.frame");
                await page.WaitForFunctionAsync($"window.preview.frame !== {first} && document.querySelector('#frame').textContent !== '{first}'", null, new PageWaitForFunctionOptions { Timeout = 15000 });
                Assert.That(problems, Is.Empty, "console errors or page errors");
                Assert.That(requests, Has.Count.EqualTo(1), "no request other than the file itself");
            }
            finally
            {
                await browser.CloseAsync();
                playwright.Dispose();
            }
        }

        [Test]
        public void DemoRefusesANonEmptyFolderWithoutForceAndChangesNothing()
        {
            string folder = Path.Combine(_dir, "taken");
            Directory.CreateDirectory(folder);
            string kept = Path.Combine(folder, "notes.txt");
            File.WriteAllText(kept, "mine");
            CliRun run = CliHarness.Run("demo", "--out", folder);
            CliHarness.AssertOneErrorLine(run, "not empty");
            Assert.That(Directory.GetFileSystemEntries(folder), Is.EqualTo(new[] { kept }));
            Assert.That(File.ReadAllText(kept), Is.EqualTo("mine"));
        }

        [Test]
        public void BakeOfACmuClipRefusesKeysOutsideItsFrames()
        {
            string output = Path.Combine(_dir, "out.bvh");
            CliRun run = CliHarness.Run("bake", Sample, "--keys", "0,60,5000", "--out", output);
            CliHarness.AssertOneErrorLine(run, "5000");
            Assert.That(File.Exists(output), Is.False);
        }

        [Test]
        public void BakeOfACmuClipRefusesKeysThatFallOnOneModelFrame()
        {
            string output = Path.Combine(_dir, "out.bvh");
            // 120 fps input, 30 fps model: frames 0 and 1 are a quarter of a model frame apart.
            CliRun run = CliHarness.Run("bake", Sample, "--keys", "0,1,60", "--out", output);
            CliHarness.AssertOneErrorLine(run, "at least 4 frames apart");
            Assert.That(File.Exists(output), Is.False);
        }

        [Test]
        public void BakeOfACmuClipKeepsItsKeyFramesExactlyAndScoresBothMethods()
        {
            const int every = 40;
            BvhAnimation input = BvhReader.Read(Sample);
            // The keys --every places (issue 30: Core's KeyPlanner, the last gap kept at the shipped model's trained
            // minimum of 5 missing frames at its 30 fps), not a layout of the test's own.
            int[] keys = KeyPlanner.Plan(new KeySpacing(every, KeySpacingUnit.InputFrames), input.Motion.FrameCount, input.Motion.FrameTime, 30, 0, 5);
            var scores = new Dictionary<string, BakeAccuracy>();
            foreach (string method in new[] { "model", "slerp" })
            {
                string output = Path.Combine(_dir, method + ".bvh");
                CliRun run = CliHarness.Run("bake", Sample, "--every", every.ToString(System.Globalization.CultureInfo.InvariantCulture), "--method", method, "--out", output);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
                BvhAnimation baked = BvhReader.Read(output);
                Assert.That(baked.Skeleton.HasSameHierarchy(input.Skeleton), Is.True);
                Assert.That(baked.Motion.FrameCount, Is.EqualTo(keys[keys.Length - 1] - keys[0] + 1));
                Assert.That(baked.Motion.FrameTime, Is.EqualTo(input.Motion.FrameTime).Within(1e-9));
                AssertKeysExact(input.Motion, baked.Motion, keys);
                scores[method] = BakeAccuracy.Measure(input.Motion, baked.Motion, keys);
            }

            foreach (KeyValuePair<string, BakeAccuracy> score in scores)
            {
                Assert.That(double.IsFinite(score.Value.MeanPositionError) && double.IsFinite(score.Value.L2Q), Is.True, score.Key);
                Assert.That(score.Value.MeanPositionError, Is.GreaterThan(0), score.Key + ": the non-key frames were filled, not copied from the truth");
            }
        }

        [Test]
        public void BakePreviewIsWrittenAndItsOutputsAreCheckedBeforeAnyWork()
        {
            string output = Path.Combine(_dir, "jumps.bvh");
            string html = Path.Combine(_dir, "jumps.html");
            string png = Path.Combine(_dir, "jumps.png");
            File.WriteAllText(html, "mine");
            CliRun refused = CliHarness.Run("bake", Sample, "--every", "60", "--out", output, "--preview", html, "--png", png);
            CliHarness.AssertOneErrorLine(refused, "already exists");
            Assert.That(File.Exists(output), Is.False, "nothing is written when an output is refused");
            Assert.That(File.ReadAllText(html), Is.EqualTo("mine"));

            CliRun run = CliHarness.Run("bake", Sample, "--every", "60", "--out", output, "--preview", html, "--png", png, "--force");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(File.ReadAllText(html), Does.StartWith("<!DOCTYPE html").IgnoreCase);
            Assert.That(File.Exists(png) || File.Exists(ContactSheet.OutputPathFor(png)), Is.True, "a PNG, or an SVG without Chromium");
        }

        private static void AssertKeysExact(MotionClip input, MotionClip baked, int[] keys)
        {
            int j = input.Skeleton.JointCount;
            foreach (int key in keys)
            {
                int f = key - keys[0];
                for (int c = 0; c < 3; c++)
                {
                    Assert.That(baked.LocalPositions[baked.PositionIndex(f, 0) + c], Is.EqualTo(input.LocalPositions[input.PositionIndex(key, 0) + c]), $"root position {c} of key {key}");
                }

                for (int joint = 0; joint < j; joint++)
                {
                    int a = input.RotationIndex(key, joint), b = baked.RotationIndex(f, joint);
                    double dot = 0;
                    for (int c = 0; c < 4; c++) dot += input.LocalRotations[a + c] * baked.LocalRotations[b + c];
                    double sign = dot < 0 ? -1 : 1, worst = 0;
                    for (int c = 0; c < 4; c++) worst = Math.Max(worst, Math.Abs(input.LocalRotations[a + c] - sign * baked.LocalRotations[b + c]));
                    Assert.That(worst, Is.LessThan(1e-9), $"rotation (quaternion) of joint {input.Skeleton.Names[joint]} at key {key}");
                }
            }
        }
    }
}
