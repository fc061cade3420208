using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Preview;
using Microsoft.Playwright;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Preview
{
    /// <summary>
    /// The preview's pictures in a real headless Chromium (Debian's chromium through Playwright): the HTML
    /// player loads with no error or network request and animates, scrubbing shows the frame asked for,
    /// and the contact sheet is a valid, non-blank PNG. Skipped with a message where Chromium is absent
    /// (./Tools~/test installs it when it can). DELTAINTERP_PREVIEW_KEEP=DIR keeps the files written.
    /// </summary>
    public sealed class PreviewBrowserTests
    {
        private string _folder = "";

        [SetUp]
        public void CreateFolder()
        {
            _folder = Path.Combine(Path.GetTempPath(), "inbetween-preview-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(_folder);
        }

        [TearDown]
        public void RemoveFolder()
        {
            string? keep = Environment.GetEnvironmentVariable("DELTAINTERP_PREVIEW_KEEP");
            if (!string.IsNullOrEmpty(keep))
            {
                Directory.CreateDirectory(keep);
                foreach (string file in Directory.GetFiles(_folder))
                {
                    File.Copy(file, Path.Combine(keep, TestContext.CurrentContext.Test.MethodName + "-" + Path.GetFileName(file)), true);
                }
            }

            Directory.Delete(_folder, true);
        }

        [Test]
        public async Task HtmlPlaysScrubsAndMarksKeysInChromium()
        {
            string chromium = RequireChromium();
            MotionClip truth = PreviewMotion.Walker(120);
            int[] keys = PreviewMotion.KeysEvery(120, 20);
            PreviewScene scene = PreviewScene.FromClips(
                "synthetic walker",
                new[] { ("Ground truth", truth), ("SLERP", PreviewMotion.SlerpBaked(truth, keys)), ("Wobbled", PreviewMotion.Wobbled(truth, 6)) },
                keys,
                0);
            string html = Path.Combine(_folder, "walker.html");
            PreviewWriter.WriteHtml(scene, html);
            await CheckPlayer(chromium, html, scene, 77);
        }

        /// <summary>
        /// Issue 30's layout: on a 1280×800 screen the whole page — 3D view, controls and the error plot —
        /// is in view (a screenshot of the viewport holds the plot's curves: it fails when the plot falls
        /// below the fold, as it did with a 62vh stage and a 170 px plot); the figures stand side by side,
        /// each as far from the camera as the others (not on a diagonal where one looks bigger); the legend
        /// names the ground truth once and gives errors with their unit.
        /// </summary>
        [Test]
        public async Task PlayerFitsA1280By800ScreenWithFiguresSideBySide()
        {
            string chromium = RequireChromium();
            MotionClip truth = PreviewMotion.Walker(120);
            int[] keys = PreviewMotion.KeysEvery(120, 20);
            PreviewScene scene = PreviewScene.FromClips(
                "synthetic walker",
                new[] { ("Ground truth", truth), ("SLERP", PreviewMotion.SlerpBaked(truth, keys)), ("Model", PreviewMotion.Wobbled(PreviewMotion.SlerpBaked(truth, keys), 6)) },
                keys,
                0);
            // Planted feet marked, as a bake's preview has them: the legend then carries its note too.
            int[] feet = { truth.Skeleton.JointCount - 1, truth.Skeleton.JointCount - 4 };
            foreach (PreviewTrack track in scene.Tracks) track.MarkPlantedFeet(feet, new bool[track.FrameCount * feet.Length]);
            string html = Path.Combine(_folder, "layout.html");
            PreviewWriter.WriteHtml(scene, html);
            (IPlaywright playwright, IBrowser browser) = await Chromium.LaunchAsync(chromium);
            try
            {
                // A 1280×800 screen, and the page a browser window on it shows (tabs and address bar take ~100 px).
                foreach (int height in new[] { 700, 800 })
                {
                    await CheckLayout(browser, html, scene, height);
                }
            }
            finally
            {
                await browser.CloseAsync();
                playwright.Dispose();
            }
        }

        private async Task CheckLayout(IBrowser browser, string html, PreviewScene scene, int viewportHeight)
        {
            {
                IPage page = await browser.NewPageAsync(new BrowserNewPageOptions { ViewportSize = new ViewportSize { Width = 1280, Height = viewportHeight } });
                List<string> problems = Watch(page, out _);
                await page.GotoAsync(new Uri(html).AbsoluteUri + "#frame=0");
                await page.WaitForFunctionAsync("window.preview !== undefined");
                await page.WaitForTimeoutAsync(200);

                double[] plot = await page.EvaluateAsync<double[]>("(() => { const r = document.getElementById('plot').getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; })()");
                Assert.That(plot[3], Is.LessThanOrEqualTo(viewportHeight), $"the error plot's bottom is within the {viewportHeight} px viewport");
                Assert.That(plot[3] - plot[1], Is.GreaterThanOrEqualTo(100), "the plot keeps a readable height");
                Assert.That(await page.EvaluateAsync<double>("document.documentElement.scrollHeight"), Is.LessThanOrEqualTo(viewportHeight), "nothing to scroll to");

                // The screenshot shows what a person sees: the viewport only. The curves of SLERP and the
                // model must be in it, inside the plot's box.
                PngImage shot = PngImage.Decode(await page.ScreenshotAsync());
                Assert.That(shot.Height, Is.EqualTo(viewportHeight));
                for (int t = 1; t < scene.Tracks.Count; t++)
                {
                    int inPlot = CountNearIn(shot, TrackColors.Of(scene, t), 40, (int)plot[0], (int)plot[1], (int)plot[2], (int)Math.Min(plot[3], shot.Height));
                    Assert.That(inPlot, Is.GreaterThan(40), $"{scene.Tracks[t].Name}'s error curve is visible on screen");
                }

                // Frame 0 is a key: every track has the same pose, so equal depths mean a square-on row.
                double[][] roots = new double[scene.Tracks.Count][];
                for (int t = 0; t < roots.Length; t++) roots[t] = await page.EvaluateAsync<double[]>($"window.preview.screenOf({t}, {scene.BodyRoot})");
                for (int t = 1; t < roots.Length; t++)
                {
                    Assert.That(roots[t][2], Is.EqualTo(roots[0][2]).Within(0.01 * roots[0][2]), $"track {t} stands as far from the camera as track 0");
                    Assert.That(roots[t][1], Is.EqualTo(roots[0][1]).Within(2), $"track {t} stands on the same screen line");
                    Assert.That(Math.Abs(roots[t][0] - roots[t - 1][0]), Is.GreaterThan(60), $"tracks {t - 1} and {t} stand apart");
                }

                string legend = (await page.Locator("#legend").TextContentAsync())!;
                Assert.That(legend, Does.Not.Match("(?i)ground truth\\s*ground truth"));
                Assert.That(legend, Does.Contain("Ground truth"));
                Assert.That(legend, Does.Match("SLERP mean error [0-9.]+ cm per joint between keys"));
                Assert.That(await page.Locator("#truth-name").TextContentAsync(), Does.EndWith("(cm)"));
                Assert.That(problems, Is.Empty);
                await page.ScreenshotAsync(new PageScreenshotOptions { Path = Path.Combine(_folder, $"layout-1280x{viewportHeight}.png") });
                await page.CloseAsync();
            }
        }

        private static int CountNearIn(PngImage image, string hex, int tolerance, int left, int top, int right, int bottom)
        {
            int r = Convert.ToInt32(hex.Substring(1, 2), 16), g = Convert.ToInt32(hex.Substring(3, 2), 16), b = Convert.ToInt32(hex.Substring(5, 2), 16);
            int count = 0;
            for (int y = Math.Max(0, top); y < Math.Min(image.Height, bottom); y++)
            {
                for (int x = Math.Max(0, left); x < Math.Min(image.Width, right); x++)
                {
                    int p = 3 * (y * image.Width + x);
                    if (Math.Abs(image.Rgb[p] - r) <= tolerance && Math.Abs(image.Rgb[p + 1] - g) <= tolerance && Math.Abs(image.Rgb[p + 2] - b) <= tolerance) count++;
                }
            }

            return count;
        }

        [Test]
        public async Task PlantedFeetAreMarkedOnTheFramesTheFlagsSay()
        {
            string chromium = RequireChromium();
            MotionClip walker = PreviewMotion.Walker(60);
            PreviewScene scene = PreviewScene.FromClips("planted", new[] { ("a", walker), ("b", PreviewMotion.Wobbled(walker, 10)) });
            // Two "foot" joints: the first planted on even frames, the second from frame 30 on; track b unmarked.
            int[] feet = { walker.Skeleton.JointCount - 1, walker.Skeleton.JointCount - 2 };
            var planted = new bool[60 * 2];
            for (int f = 0; f < 60; f++)
            {
                planted[2 * f] = f % 2 == 0;
                planted[2 * f + 1] = f >= 30;
            }

            scene.Tracks[0].MarkPlantedFeet(feet, planted);
            Assert.Throws<ArgumentException>(() => scene.Tracks[1].MarkPlantedFeet(feet, new bool[7]), "flags that are not frames × foot joints");
            string html = Path.Combine(_folder, "planted.html");
            PreviewWriter.WriteHtml(scene, html);
            (IPlaywright playwright, IBrowser browser) = await Chromium.LaunchAsync(chromium);
            try
            {
                IPage page = await browser.NewPageAsync();
                var problems = Watch(page, out List<string> requests);
                await page.GotoAsync(new Uri(html).AbsoluteUri);
                await page.WaitForFunctionAsync("window.preview !== undefined");
                await page.EvaluateAsync("window.preview.pause()");
                foreach (int frame in new[] { 0, 1, 30, 31, 59 })
                {
                    await page.EvaluateAsync($"window.preview.setFrame({frame})");
                    var expected = new List<int>();
                    if (frame % 2 == 0) expected.Add(feet[0]);
                    if (frame >= 30) expected.Add(feet[1]);
                    Assert.That(await page.EvaluateAsync<int[]>("window.preview.plantedAt(0)"), Is.EqualTo(expected.ToArray()), $"track a, frame {frame}");
                    Assert.That(await page.EvaluateAsync<int[]>("window.preview.plantedAt(1)"), Is.Empty, $"track b, frame {frame}");
                }

                Assert.That(await page.Locator("#legend").TextContentAsync(), Does.Contain("planted feet"));
                Assert.That(problems, Is.Empty);
            }
            finally
            {
                await browser.CloseAsync();
                playwright.Dispose();
            }
        }

        [Test]
        public async Task HtmlWithoutGroundTruthHasNoErrorPlot()
        {
            string chromium = RequireChromium();
            MotionClip walker = PreviewMotion.Walker(60);
            PreviewScene scene = PreviewScene.FromClips("two", new[] { ("a", walker), ("b", PreviewMotion.Wobbled(walker, 10)) });
            string html = Path.Combine(_folder, "two.html");
            PreviewWriter.WriteHtml(scene, html);
            (IPlaywright playwright, IBrowser browser) = await Chromium.LaunchAsync(chromium);
            try
            {
                IPage page = await browser.NewPageAsync();
                var problems = Watch(page, out List<string> requests);
                string url = new Uri(html).AbsoluteUri;
                await page.GotoAsync(url);
                await page.WaitForFunctionAsync("window.preview && window.preview.frame >= 3");
                Assert.That(await page.Locator("#errors").IsHiddenAsync(), Is.True);
                Assert.That(await page.Locator("#legend .chip").CountAsync(), Is.EqualTo(2));

                // A link can open the page paused on a frame.
                IPage linked = await browser.NewPageAsync();
                List<string> linkedProblems = Watch(linked, out List<string> linkedRequests);
                await linked.GotoAsync(url + "#frame=17");
                await linked.WaitForFunctionAsync("window.preview !== undefined");
                await linked.WaitForTimeoutAsync(300);
                Assert.That(await linked.Locator("#frame").TextContentAsync(), Is.EqualTo("17"));
                Assert.That(await linked.EvaluateAsync<bool>("window.preview.playing"), Is.False);
                Assert.That(problems.Concat(linkedProblems), Is.Empty);
                Assert.That(requests.Concat(linkedRequests), Is.EqualTo(new[] { url, url }));
            }
            finally
            {
                await browser.CloseAsync();
                playwright.Dispose();
            }
        }

        [Test]
        public void ContactSheetIsAValidNonBlankPng()
        {
            string chromium = RequireChromium();
            MotionClip truth = PreviewMotion.Walker(90);
            int[] keys = PreviewMotion.KeysEvery(90, 15);
            PreviewScene scene = PreviewScene.FromClips("walker", new[] { ("Ground truth", truth), ("SLERP", PreviewMotion.SlerpBaked(truth, keys)) }, keys, 0);
            string png = Path.Combine(_folder, "walker.png");
            ContactSheet.WritePng(scene, png, chromium);
            CheckSheet(scene, File.ReadAllBytes(png));
        }

        [Test]
        public void WriteFallsBackToSvgWithoutChromium()
        {
            MotionClip walker = PreviewMotion.Walker(30);
            PreviewScene scene = PreviewScene.FromClips("walker", new[] { ("a", walker) });
            string previous = Environment.GetEnvironmentVariable("INBETWEEN_CHROMIUM") ?? "";
            Environment.SetEnvironmentVariable("INBETWEEN_CHROMIUM", Path.Combine(_folder, "no-such-browser"));
            try
            {
                string asked = Path.Combine(_folder, "sheet.png");
                Assert.That(ContactSheet.OutputPathFor(asked), Is.EqualTo(Path.Combine(_folder, "sheet.svg")));
                string written = ContactSheet.Write(scene, asked, false, out string? fallback);
                Assert.That(written, Is.EqualTo(Path.Combine(_folder, "sheet.svg")));
                Assert.That(fallback, Does.StartWith("no Chromium found").And.Contain("sheet.svg instead of"));
                Assert.That(File.Exists(asked), Is.False);
                string svg = File.ReadAllText(written);
                Assert.That(svg, Does.StartWith("<svg xmlns=\"http://www.w3.org/2000/svg\""));
                Assert.That(System.Xml.Linq.XDocument.Parse(svg).Root!.Name.LocalName, Is.EqualTo("svg"), "well-formed XML");
            }
            finally
            {
                Environment.SetEnvironmentVariable("INBETWEEN_CHROMIUM", previous.Length == 0 ? null : previous);
            }
        }

        [Test]
        public void WriteFallsBackToSvgWhenChromiumFailsToStart()
        {
            RequireChromium();
            MotionClip walker = PreviewMotion.Walker(30);
            PreviewScene scene = PreviewScene.FromClips("walker", new[] { ("a", walker) });
            string previous = Environment.GetEnvironmentVariable("INBETWEEN_CHROMIUM") ?? "";
            Environment.SetEnvironmentVariable("INBETWEEN_CHROMIUM", "/bin/false");
            try
            {
                string asked = Path.Combine(_folder, "sheet.png");
                string written = ContactSheet.Write(scene, asked, false, out string? fallback);
                Assert.That(written, Is.EqualTo(Path.Combine(_folder, "sheet.svg")));
                Assert.That(fallback, Does.StartWith("Chromium (/bin/false) failed:").And.EndWith("sheet.svg instead of " + asked));
                Assert.That(File.Exists(asked), Is.False);
                Assert.That(File.ReadAllText(written), Does.StartWith("<svg"));
            }
            finally
            {
                Environment.SetEnvironmentVariable("INBETWEEN_CHROMIUM", previous.Length == 0 ? null : previous);
            }
        }

        /// <summary>
        /// A LaFAN1 subject-5 excerpt of 300 frames as three tracks: the ground truth, a SLERP bake of keys
        /// every 15 frames, and a wobbled copy; written through BVH files and read back as the verb does.
        /// </summary>
        [Test]
        public async Task LafanPreviewOfThreeTracksPlaysAndRendersASheet()
        {
            string chromium = RequireChromium();
            BvhAnimation file = PreviewMotion.Lafan("obstacles1_subject5.bvh");
            MotionClip truth = PreviewMotion.Excerpt(file.Motion, 2000, 300);
            int[] keys = PreviewMotion.KeysEvery(300, 15);
            var clips = new List<(string, MotionClip)> { ("Ground truth", truth), ("SLERP", PreviewMotion.SlerpBaked(truth, keys)), ("Wobbled", PreviewMotion.Wobbled(truth, 4)) };
            foreach ((string name, MotionClip clip) in clips)
            {
                BvhWriter.Write(new BvhAnimation(clip, file.JointChannels, file.EndSites, name), Path.Combine(_folder, name.Replace(' ', '_') + ".bvh"));
            }

            var reread = clips.Select(c => (c.Item1, BvhReader.Read(Path.Combine(_folder, c.Item1.Replace(' ', '_') + ".bvh")).Motion)).ToList();
            PreviewScene scene = PreviewScene.FromClips("obstacles1_subject5.bvh, frames 2000–2299", reread, keys, 0);
            Assert.That(scene.MeanErrorBetweenKeys(1), Is.GreaterThan(0), "SLERP differs from the capture between keys");
            string html = Path.Combine(_folder, "lafan.html");
            PreviewWriter.WriteHtml(scene, html);
            TestContext.Progress.WriteLine($"lafan.html: {new FileInfo(html).Length} bytes for 300 frames × 3 tracks × {scene.JointCount} joints");
            await CheckPlayer(chromium, html, scene, 150, Path.Combine(_folder, "lafan-page.png"));
            string png = Path.Combine(_folder, "lafan.png");
            ContactSheet.WritePng(scene, png, chromium);
            TestContext.Progress.WriteLine($"lafan.png: {new FileInfo(png).Length} bytes");
            CheckSheet(scene, File.ReadAllBytes(png));
        }

        private static async Task CheckPlayer(string chromium, string html, PreviewScene scene, int scrubTo, string? screenshot = null)
        {
            (IPlaywright playwright, IBrowser browser) = await Chromium.LaunchAsync(chromium);
            try
            {
                IPage page = await browser.NewPageAsync(new BrowserNewPageOptions { ViewportSize = new ViewportSize { Width = 1280, Height = 900 } });
                List<string> problems = Watch(page, out List<string> requests);
                string url = new Uri(html).AbsoluteUri;
                await page.GotoAsync(url);
                await page.WaitForFunctionAsync("window.preview !== undefined");
                Assert.That(await page.EvaluateAsync<int>("window.preview.frameCount"), Is.EqualTo(scene.FrameCount));

                // It plays by itself: the frame shown advances, in the page's state and on screen.
                // (The player loops, and a loaded machine can let a whole loop pass between two calls, so the
                // frame is compared for change, with state and screen read in one call.)
                int first = await page.EvaluateAsync<int>("window.preview.frame");
                await page.WaitForFunctionAsync($"window.preview.frame !== {first} && document.querySelector('#frame').textContent !== '{first}'", null, new PageWaitForFunctionOptions { Timeout = 15000 });
                int[] now = await page.EvaluateAsync<int[]>("[window.preview.frame, parseInt(document.querySelector('#frame').textContent)]");
                Assert.That(now[0], Is.Not.EqualTo(first), "the frame shown advances while playing");
                Assert.That(Math.Abs(now[1] - now[0]), Is.LessThanOrEqualTo(3), "the frame on screen follows the player's state");

                // Scrubbing to K pauses and shows K; the arrow key steps one frame on.
                await page.Locator("#scrub").FillAsync(scrubTo.ToString(System.Globalization.CultureInfo.InvariantCulture));
                Assert.That(await page.Locator("#frame").TextContentAsync(), Is.EqualTo(scrubTo.ToString(System.Globalization.CultureInfo.InvariantCulture)));
                Assert.That(await page.EvaluateAsync<int>("window.preview.frame"), Is.EqualTo(scrubTo));
                Assert.That(await page.EvaluateAsync<bool>("window.preview.playing"), Is.False);
                await page.WaitForTimeoutAsync(300);
                Assert.That(await page.EvaluateAsync<int>("window.preview.frame"), Is.EqualTo(scrubTo), "paused after scrubbing");
                await page.Locator("#view").ClickAsync();
                await page.Keyboard.PressAsync("ArrowRight");
                Assert.That(await page.Locator("#frame").TextContentAsync(), Is.EqualTo((scrubTo + 1).ToString(System.Globalization.CultureInfo.InvariantCulture)));

                // Key frames: marked on the scrubber, and the skeletons show the key badge on a key frame only.
                Assert.That(await page.Locator("#keymarks b").CountAsync(), Is.EqualTo(scene.KeyFrames.Count));
                int key = scene.KeyFrames[1];
                await page.Locator("#scrub").FillAsync(key.ToString(System.Globalization.CultureInfo.InvariantCulture));
                await page.WaitForFunctionAsync("!document.getElementById('badge').hidden");
                await page.Locator("#scrub").FillAsync((key + 1).ToString(System.Globalization.CultureInfo.InvariantCulture));
                await page.WaitForFunctionAsync("document.getElementById('badge').hidden");

                // One error curve per track measured against the ground truth; the canvas shows something.
                int measured = scene.GroundTruthTrack >= 0 ? scene.Tracks.Count - 1 : 0;
                Assert.That(await page.Locator("#plot polyline").CountAsync(), Is.EqualTo(measured));
                PngImage canvas = PngImage.Decode(await page.Locator("#view").ScreenshotAsync());
                Assert.That(canvas.LuminanceVariance(), Is.GreaterThan(20), "the 3D view is not blank");

                // Orbiting the camera changes the picture.
                await page.Mouse.MoveAsync(640, 300);
                await page.Mouse.DownAsync();
                await page.Mouse.MoveAsync(760, 330, new MouseMoveOptions { Steps = 5 });
                await page.Mouse.UpAsync();
                PngImage orbited = PngImage.Decode(await page.Locator("#view").ScreenshotAsync());
                Assert.That(Difference(canvas, orbited), Is.GreaterThan(0.002), "dragging orbits the camera");
                if (screenshot != null)
                {
                    await page.Mouse.DblClickAsync(640, 300);
                    await page.Locator("#scrub").FillAsync((scrubTo + 7).ToString(System.Globalization.CultureInfo.InvariantCulture));
                    await page.ScreenshotAsync(new PageScreenshotOptions { Path = screenshot, FullPage = true });
                }

                Assert.That(problems, Is.Empty, "console errors or page errors");
                Assert.That(requests, Is.EqualTo(new[] { url }), "no request other than the file itself");
            }
            finally
            {
                await browser.CloseAsync();
                playwright.Dispose();
            }
        }

        private static void CheckSheet(PreviewScene scene, byte[] bytes)
        {
            PngImage image = PngImage.Decode(bytes);
            Assert.That(image.Width, Is.EqualTo(1800));
            Assert.That(image.Height, Is.GreaterThan(150 * scene.Tracks.Count));
            Assert.That(image.LuminanceVariance(), Is.GreaterThan(100), "not blank");
            // Every measured track's colour is drawn (poses and trails), and the key poses in gold.
            for (int t = 0; t < scene.Tracks.Count; t++)
            {
                if (t == scene.GroundTruthTrack) continue;
                string color = t == 1 ? "#f08a24" : "#3d8ff0";
                Assert.That(image.CountNear(color, 24), Is.GreaterThan(300), $"track {t} ({color}) is drawn");
            }

            Assert.That(image.CountNear("#ffc933", 24), Is.GreaterThan(300), "key poses are drawn in gold");
        }

        private static double Difference(PngImage a, PngImage b)
        {
            int differ = 0, n = Math.Min(a.Rgb.Length, b.Rgb.Length) / 3;
            for (int p = 0; p < n; p++)
            {
                if (Math.Abs(a.Rgb[3 * p] - b.Rgb[3 * p]) + Math.Abs(a.Rgb[3 * p + 1] - b.Rgb[3 * p + 1]) + Math.Abs(a.Rgb[3 * p + 2] - b.Rgb[3 * p + 2]) > 30) differ++;
            }

            return differ / (double)n;
        }

        internal static List<string> Watch(IPage page, out List<string> requests)
        {
            var problems = new List<string>();
            var seen = new List<string>();
            page.Console += (_, message) =>
            {
                if (message.Type == "error") problems.Add("console: " + message.Text);
            };
            page.PageError += (_, error) => problems.Add("page error: " + error);
            page.Request += (_, request) => seen.Add(request.Url);
            requests = seen;
            return problems;
        }

        internal static string RequireChromium()
        {
            string? chromium = ContactSheet.FindChromium();
            if (chromium == null)
            {
                Assert.Ignore("Chromium absent (no /usr/bin/chromium; INBETWEEN_CHROMIUM unset): install Debian's chromium (./Tools~/test does when root) to run the browser tests.");
            }

            return chromium!;
        }
    }
}
