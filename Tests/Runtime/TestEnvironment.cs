using System;
using System.IO;
using NUnit.Framework;

namespace DeltaInterpolator.Tests
{
    /// <summary>Where the tests find the repository and the shared data, and when they must skip.</summary>
    public static class TestEnvironment
    {
        /// <summary>True inside the Unity Editor or a player (UnityEngine is loaded).</summary>
        public static bool InsideUnity => Type.GetType("UnityEngine.Application, UnityEngine.CoreModule") != null
            || Type.GetType("UnityEngine.Application, UnityEngine") != null;

        /// <summary>The repository root (the folder with package.json and .git), or null.</summary>
        public static string? RepositoryRoot
        {
            get
            {
                string? dir = AppContext.BaseDirectory;
                while (dir != null)
                {
                    if (File.Exists(Path.Combine(dir, "package.json")) && Directory.Exists(Path.Combine(dir, "Runtime")))
                    {
                        return dir;
                    }

                    dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
                }

                return null;
            }
        }

        /// <summary>
        /// The LaFAN1 folder: $DELTAINTERP_LAFAN1 if set, else ../shared/data/lafan1 beside the repository.
        /// Skips the calling test (Assert.Ignore) with a clear message when it is absent.
        /// </summary>
        public static string RequireLafan1()
        {
            string? fromEnv = Environment.GetEnvironmentVariable("DELTAINTERP_LAFAN1");
            string? root = RepositoryRoot;
            string? dir = !string.IsNullOrEmpty(fromEnv) ? fromEnv
                : root != null ? Path.GetFullPath(Path.Combine(root, "..", "shared", "data", "lafan1")) : null;
            if (dir == null || !Directory.Exists(dir) || Directory.GetFiles(dir, "*_subject5.bvh").Length == 0)
            {
                Assert.Ignore($"LaFAN1 data not found at {dir ?? "../shared/data/lafan1"} (set DELTAINTERP_LAFAN1 or place the BVH files in ../shared/data/lafan1); skipping the data-dependent test.");
            }

            return dir!;
        }
    }
}
