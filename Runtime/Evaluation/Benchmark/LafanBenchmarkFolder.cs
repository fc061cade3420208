using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.IO;

namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>
    /// A folder of LaFAN1 BVH files as the benchmark sees it: the test files (subject 5) it scores on and the
    /// training files (subjects 1–4) it may compute statistics from. Opening refuses a folder without test
    /// files before any work.
    /// </summary>
    public sealed class LafanBenchmarkFolder
    {
        private LafanBenchmarkFolder(string path, IReadOnlyList<string> testFiles, IReadOnlyList<string> trainingFiles)
        {
            Path = path;
            TestFiles = testFiles;
            TrainingFiles = trainingFiles;
        }

        /// <summary>The folder as the user gave it (messages name it so).</summary>
        public string Path { get; }

        /// <summary>The *_subject5.bvh files, by name.</summary>
        public IReadOnlyList<string> TestFiles { get; }

        /// <summary>The *_subject1..4.bvh files, by name (may be empty when statistics are given).</summary>
        public IReadOnlyList<string> TrainingFiles { get; }

        /// <summary>Lists the folder's test and training files.</summary>
        /// <exception cref="InputPathException">The folder does not exist or is a file.</exception>
        /// <exception cref="DataFormatException">The folder holds no test file.</exception>
        public static LafanBenchmarkFolder Open(string path)
        {
            if (!Directory.Exists(path))
            {
                string what = File.Exists(path) ? "is a file, not a directory" : "no such directory";
                throw new InputPathException(path, what, "expected the folder of LaFAN1 BVH files (e.g. ../shared/data/lafan1)");
            }

            IReadOnlyList<string> testFiles = LafanDataset.FindFiles(path, LafanDataset.TestSubjects);
            if (testFiles.Count == 0)
            {
                throw new DataFormatException(path, "no *_subject5.bvh files", "expected the LaFAN1 test files (subject 5) in --data");
            }

            return new LafanBenchmarkFolder(path, testFiles, LafanDataset.FindFiles(path, LafanDataset.TrainingSubjects));
        }

        /// <summary>The test files' total size in bytes (for the read speed a summary reports).</summary>
        public long TestBytes()
        {
            long total = 0;
            foreach (string file in TestFiles) total += new FileInfo(file).Length;
            return total;
        }
    }
}
