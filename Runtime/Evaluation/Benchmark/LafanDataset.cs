using System;
using System.Collections.Generic;
using System.IO;
using System.Threading.Tasks;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;

namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>
    /// LaFAN1's file naming and split: files are <c>&lt;theme&gt;&lt;take&gt;_subject&lt;k&gt;.bvh</c>;
    /// subjects 1–4 are the training set and subject 5 the test set.
    /// </summary>
    public static class LafanDataset
    {
        /// <summary>The test subject(s).</summary>
        public static readonly IReadOnlyList<string> TestSubjects = new[] { "subject5" };

        /// <summary>The training subjects.</summary>
        public static readonly IReadOnlyList<string> TrainingSubjects = new[] { "subject1", "subject2", "subject3", "subject4" };

        /// <summary>The subject of a LaFAN1 file name (the part after the last '_'), e.g. "subject5".</summary>
        public static string SubjectOf(string path)
        {
            string name = Path.GetFileNameWithoutExtension(path);
            int underscore = name.LastIndexOf('_');
            return underscore < 0 ? "" : name.Substring(underscore + 1);
        }

        /// <summary>
        /// The <c>.bvh</c> files in <paramref name="directory"/> whose subject is one of
        /// <paramref name="subjects"/>, sorted by name (ordinal) so that every run sees the same order.
        /// </summary>
        /// <exception cref="DirectoryNotFoundException">The directory does not exist.</exception>
        public static IReadOnlyList<string> FindFiles(string directory, IReadOnlyList<string> subjects)
        {
            var files = new List<string>();
            foreach (string path in Directory.GetFiles(directory, "*.bvh"))
            {
                string subject = SubjectOf(path);
                foreach (string s in subjects)
                {
                    if (string.Equals(s, subject, StringComparison.Ordinal))
                    {
                        files.Add(path);
                        break;
                    }
                }
            }

            files.Sort(StringComparer.Ordinal);
            return files;
        }

        /// <summary>
        /// Reads files in parallel (results in input order). The first malformed file's
        /// <see cref="BvhFormatException"/> is rethrown as is.
        /// </summary>
        public static BvhAnimation[] ReadAll(IReadOnlyList<string> paths, IProgress<StageProgress>? progress = null, string stage = "Reading BVH files")
        {
            var result = new BvhAnimation[paths.Count];
            int done = 0;
            progress?.Report(new StageProgress(stage, 0, paths.Count));
            try
            {
                Parallel.For(0, paths.Count, i =>
                {
                    result[i] = BvhReader.Read(paths[i]);
                    int completed = System.Threading.Interlocked.Increment(ref done);
                    progress?.Report(new StageProgress(stage, completed, paths.Count));
                });
            }
            catch (AggregateException e)
            {
                // Report the first failing file in path order, as a sequential read would.
                Exception first = e.InnerExceptions[0];
                foreach (Exception inner in e.InnerExceptions)
                {
                    if (inner is DataFormatException df && first is DataFormatException f0 &&
                        string.CompareOrdinal(df.Source, f0.Source) < 0)
                    {
                        first = inner;
                    }
                }

                System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(first).Throw();
                throw;
            }

            return result;
        }
    }
}
