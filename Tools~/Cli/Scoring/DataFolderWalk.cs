using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.IO;

namespace DeltaInterpolator.Cli.Scoring
{
    /// <summary>
    /// The files under a data folder, each real folder visited once: a directory link back into the tree
    /// (<c>l -&gt; .</c>) or three links looping among each other add nothing, where following every path
    /// scored a file 17 times and looping links made 3^16 paths. Folders are told apart by device and inode
    /// (<see cref="FileNode"/>); where the platform does not tell them, directory links are not followed.
    /// </summary>
    internal static class DataFolderWalk
    {
        /// <summary>
        /// Every file under <paramref name="root"/> (hidden ones too), sorted ordinally by full path. Breadth first,
        /// so a folder reached both directly and through a link is named by its shortest path. Unreadable
        /// folders are skipped, as before.
        /// </summary>
        public static List<string> Files(string root)
        {
            var options = new EnumerationOptions { RecurseSubdirectories = false, AttributesToSkip = 0, IgnoreInaccessible = true };
            var seen = new HashSet<(long Device, long Inode)>();
            var files = new List<string>();
            var folders = new Queue<string>();
            folders.Enqueue(root);
            FileNode rootNode = FileNode.Of(root);
            if (rootNode.HasIdentity) seen.Add((rootNode.Device, rootNode.Inode));
            while (folders.Count > 0)
            {
                string folder = folders.Dequeue();
                var children = new List<string>();
                try
                {
                    files.AddRange(Directory.EnumerateFiles(folder, "*", options));
                    children.AddRange(Directory.EnumerateDirectories(folder, "*", options));
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    continue;
                }

                children.Sort(StringComparer.Ordinal);
                foreach (string child in children)
                {
                    FileNode node = FileNode.Of(child);
                    if (node.Kind != FileNodeKind.Directory) continue;
                    if (node.HasIdentity)
                    {
                        if (!seen.Add((node.Device, node.Inode))) continue;
                    }
                    else if (new DirectoryInfo(child).LinkTarget != null)
                    {
                        continue;
                    }

                    folders.Enqueue(child);
                }
            }

            files.Sort(StringComparer.Ordinal);
            return files;
        }
    }
}
