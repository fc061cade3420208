using System;
using System.IO;

namespace DeltaInterpolator.Cli.Speed
{
    /// <summary>
    /// The checkout of the package this tool was built in (the tool lives under Tools~/.build), found from
    /// the tool's folder or the working directory: where <c>speed</c> finds the shipped model and the Python
    /// trainer it times against.
    /// </summary>
    internal static class RepositoryCheckout
    {
        /// <summary>The checkout's root folder (it holds Runtime/Core and Training), or null outside a checkout.</summary>
        public static string? Find()
        {
            foreach (string start in new[] { AppContext.BaseDirectory, Directory.GetCurrentDirectory() })
            {
                string? dir = start;
                while (dir != null)
                {
                    if (Directory.Exists(Path.Combine(dir, "Runtime", "Core")) && Directory.Exists(Path.Combine(dir, "Training")))
                    {
                        return dir;
                    }

                    dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
                }
            }

            return null;
        }
    }
}
