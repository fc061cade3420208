using System;
using System.IO;
using System.Threading.Tasks;
using Microsoft.Playwright;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// Headless Chromium, driven by Playwright: the installed browser (Debian's <c>chromium</c>) is
    /// launched through <c>ExecutablePath</c>, because Playwright's own browser download is not
    /// possible everywhere this tool runs. <c>INBETWEEN_CHROMIUM</c> names another executable.
    /// </summary>
    internal static class Chromium
    {
        private static readonly string[] Candidates =
        {
            "/usr/bin/chromium",
            "/usr/bin/chromium-browser",
            "/usr/bin/google-chrome",
            "/usr/bin/google-chrome-stable",
            "/snap/bin/chromium",
        };

        /// <summary>The browser executable to use, or null when none is installed.</summary>
        public static string? Find()
        {
            string? chosen = Environment.GetEnvironmentVariable("INBETWEEN_CHROMIUM");
            if (!string.IsNullOrWhiteSpace(chosen))
            {
                return File.Exists(chosen) ? chosen : null;
            }

            foreach (string candidate in Candidates)
            {
                if (File.Exists(candidate)) return candidate;
            }

            return null;
        }

        /// <summary>Starts Playwright and the browser (headless, no sandbox: root in containers needs that).</summary>
        public static async Task<(IPlaywright Playwright, IBrowser Browser)> LaunchAsync(string executable)
        {
            IPlaywright playwright = await Playwright.CreateAsync().ConfigureAwait(false);
            try
            {
                IBrowser browser = await playwright.Chromium.LaunchAsync(new BrowserTypeLaunchOptions
                {
                    ExecutablePath = executable,
                    Headless = true,
                    ChromiumSandbox = false,
                    Args = new[] { "--disable-gpu", "--disable-dev-shm-usage" },
                }).ConfigureAwait(false);
                return (playwright, browser);
            }
            catch
            {
                playwright.Dispose();
                throw;
            }
        }

        /// <summary>Renders an SVG document of the given size to PNG bytes.</summary>
        public static async Task<byte[]> RasteriseSvgAsync(string executable, string svg, int width, int height, float scale)
        {
            (IPlaywright playwright, IBrowser browser) = await LaunchAsync(executable).ConfigureAwait(false);
            try
            {
                IPage page = await browser.NewPageAsync(new BrowserNewPageOptions
                {
                    ViewportSize = new ViewportSize { Width = width, Height = height },
                    DeviceScaleFactor = scale,
                }).ConfigureAwait(false);
                string html = "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><style>html,body{margin:0;background:#fff}svg{display:block}</style></head><body>" + svg + "</body></html>";
                await page.SetContentAsync(html).ConfigureAwait(false);
                return await page.ScreenshotAsync(new PageScreenshotOptions
                {
                    Type = ScreenshotType.Png,
                    Clip = new Clip { X = 0, Y = 0, Width = width, Height = height },
                }).ConfigureAwait(false);
            }
            finally
            {
                await browser.CloseAsync().ConfigureAwait(false);
                playwright.Dispose();
            }
        }
    }
}
