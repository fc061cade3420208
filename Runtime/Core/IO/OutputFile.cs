using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.IO;
using System.Runtime.InteropServices;
using System.Text;

namespace DeltaInterpolator.Core.IO
{
    /// <summary>
    /// The one way this package writes a file: check the target before any work (<c>Check</c>), then
    /// write everything to a temporary file beside it and rename it into place (<see cref="Write"/>), so a
    /// failing or interrupted write leaves an existing file byte-identical and never leaves half a file.
    /// </summary>
    public static class OutputFile
    {
        // Full paths that Check found missing: Write must then create them exclusively, so that a file that
        // appeared meanwhile (a second run writing the same new path) is never silently replaced.
        private static readonly ConcurrentDictionary<string, byte> CheckedAsNew = new ConcurrentDictionary<string, byte>(StringComparer.Ordinal);

        // Temporary files being written now, for DeleteTemporaries (SIGINT, SIGTERM).
        private static readonly ConcurrentDictionary<string, byte> Temporaries = new ConcurrentDictionary<string, byte>(StringComparer.Ordinal);

        /// <summary>
        /// Deletes the temporary files of writes in progress. The CLI calls it when SIGINT or SIGTERM ends the
        /// process during a write: the old output stays intact and no <c>.NAME.XXXXXXXX.tmp</c> is left behind.
        /// </summary>
        public static void DeleteTemporaries()
        {
            foreach (string temporary in Temporaries.Keys)
            {
                TryDelete(temporary);
            }
        }

        /// <summary>
        /// Refuses, with <see cref="OutputPathException"/>, a target that cannot or must not be written: a
        /// folder, a named pipe, device or socket, an existing file without <paramref name="force"/>, one of
        /// the <paramref name="inputs"/> (by path, or by identity through links), or a place whose folder is
        /// not writable. Never opens the target (so a named pipe cannot block it). Call it before any long work.
        /// </summary>
        /// <param name="path">The output path as the user gave it.</param>
        /// <param name="force">True when the user allowed replacing an existing file (<c>--force</c>).</param>
        /// <param name="inputs">Every file the same command reads (null entries are ignored).</param>
        /// <returns>The full path of the target.</returns>
        public static string Check(string path, bool force, IEnumerable<string?> inputs)
        {
            if (string.IsNullOrWhiteSpace(path))
            {
                throw new OutputPathException("(empty path)", "no output path given", "expected a file path");
            }

            string full = Path.GetFullPath(path);
            FileNode target = FileNode.Of(full);
            foreach (string? input in inputs)
            {
                if (input != null && IsSameFile(full, target, input))
                {
                    throw new OutputPathException(path, "is also an input of this command", "expected a different output path (an output never replaces an input)");
                }
            }

            if (target.Kind == FileNodeKind.Directory)
            {
                throw new OutputPathException(path, "is a directory", "expected a file path");
            }

            if (target.Kind != FileNodeKind.Missing && target.Kind != FileNodeKind.RegularFile)
            {
                // Renaming over a pipe or device would replace the node, not write to it; refuse either way.
                throw new OutputPathException(path, FileNode.Describe(target.Kind), "expected a path for a regular file");
            }

            if (target.Kind == FileNodeKind.RegularFile && !force)
            {
                throw new OutputPathException(path, "already exists", "expected a new path, or --force to replace it");
            }

            string folder = NearestExistingFolder(Path.GetDirectoryName(full) ?? full, path);
            ProbeWritable(folder, path);
            if (target.Kind == FileNodeKind.Missing)
            {
                CheckedAsNew[full] = 0;
            }
            else
            {
                CheckedAsNew.TryRemove(full, out _);
            }

            return full;
        }

        /// <summary>Same as <see cref="Check(string, bool, IEnumerable{string})"/> with the inputs as arguments.</summary>
        public static string Check(string path, bool force, params string?[] inputs)
        {
            return Check(path, force, (IEnumerable<string?>)inputs);
        }

        /// <summary>
        /// Writes the file through <paramref name="write"/> into a temporary file in the target's folder
        /// (created when missing), flushes it to disk and renames it over the target. When
        /// <paramref name="write"/> throws, the temporary file is deleted and the target is untouched.
        /// A target that <see cref="Check(string, bool, IEnumerable{string})"/> found missing is created
        /// exclusively (a hard link that fails when the name exists): when another process wrote it
        /// meanwhile, its file stays and this write fails with <see cref="OutputPathException"/>.
        /// </summary>
        public static void Write(string path, Action<Stream> write)
        {
            if (write == null) throw new ArgumentNullException(nameof(write));
            string full = Path.GetFullPath(path);
            string folder = Path.GetDirectoryName(full) ?? ".";
            Directory.CreateDirectory(folder);
            string temporary = Path.Combine(folder, "." + Path.GetFileName(full) + "." + Guid.NewGuid().ToString("N").Substring(0, 8) + ".tmp");
            bool mustBeNew = CheckedAsNew.TryRemove(full, out _);
            Temporaries[temporary] = 0;
            try
            {
                using (var stream = new FileStream(temporary, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1 << 16))
                {
                    write(stream);
                    stream.Flush(true);
                }

                if (!mustBeNew && File.Exists(full))
                {
                    File.Replace(temporary, full, null);
                }
                else
                {
                    PublishNew(temporary, full, path);
                }
            }
            catch
            {
                TryDelete(temporary);
                throw;
            }
            finally
            {
                Temporaries.TryRemove(temporary, out _);
            }
        }

        /// <summary>
        /// Gives the finished <paramref name="temporary"/> the name <paramref name="full"/> only if no file has
        /// that name: link(2) then unlink on Unix (atomic: it fails when the name exists), a move that does not
        /// replace elsewhere (atomic on Windows).
        /// </summary>
        private static void PublishNew(string temporary, string full, string shownPath)
        {
            if (!_linkMissing && !RuntimeInformation.IsOSPlatform(OSPlatform.Windows))
            {
                try
                {
                    if (Link(Encoding.UTF8.GetBytes(temporary + "\0"), Encoding.UTF8.GetBytes(full + "\0")) == 0)
                    {
                        TryDelete(temporary);
                        return;
                    }

                    if (FileNode.Of(full).Kind != FileNodeKind.Missing) throw Appeared(shownPath);
                    // Another failure (a file system without hard links): the move below.
                }
                catch (Exception e) when (e is DllNotFoundException || e is EntryPointNotFoundException || e is BadImageFormatException)
                {
                    _linkMissing = true;
                }
            }

            try
            {
                File.Move(temporary, full);
            }
            catch (IOException) when (FileNode.Of(full).Kind != FileNodeKind.Missing)
            {
                throw Appeared(shownPath);
            }
        }

        private static OutputPathException Appeared(string shownPath) => new OutputPathException(
            shownPath, "appeared while this command ran (another run wrote it?)", "expected a new path, or --force to replace it");

        private static bool _linkMissing;

        [DllImport("libSystem.Native", EntryPoint = "SystemNative_Link")]
        private static extern int Link(byte[] source, byte[] linkTarget);

        /// <summary>Writes <paramref name="text"/> as UTF-8 (no byte-order mark) through <see cref="Write"/>.</summary>
        public static void WriteAllText(string path, string text)
        {
            byte[] bytes = new UTF8Encoding(false).GetBytes(text);
            Write(path, s => s.Write(bytes, 0, bytes.Length));
        }

        /// <summary>Writes <paramref name="bytes"/> through <see cref="Write"/>.</summary>
        public static void WriteAllBytes(string path, byte[] bytes)
        {
            Write(path, s => s.Write(bytes, 0, bytes.Length));
        }

        /// <summary>
        /// True when <paramref name="input"/> names the output: the same full path (ignoring case where the
        /// file system usually does: Windows, macOS), or — for existing files — the same file by device and
        /// inode, which catches symbolic links, hard links and other spellings.
        /// </summary>
        private static bool IsSameFile(string fullOutput, FileNode output, string input)
        {
            string fullInput;
            try
            {
                fullInput = Path.GetFullPath(input);
            }
            catch (Exception e) when (e is ArgumentException || e is NotSupportedException || e is PathTooLongException)
            {
                return false;
            }

            bool ignoreCase = RuntimeInformation.IsOSPlatform(OSPlatform.Windows) || RuntimeInformation.IsOSPlatform(OSPlatform.OSX);
            if (string.Equals(fullOutput.TrimEnd(Path.DirectorySeparatorChar), fullInput.TrimEnd(Path.DirectorySeparatorChar), ignoreCase ? StringComparison.OrdinalIgnoreCase : StringComparison.Ordinal))
            {
                return true;
            }

            return output.Kind != FileNodeKind.Missing && output.IsSameFileAs(FileNode.Of(fullInput));
        }

        private static string NearestExistingFolder(string folder, string shownPath)
        {
            string? current = folder;
            while (current != null && !Directory.Exists(current))
            {
                if (File.Exists(current))
                {
                    throw new OutputPathException(shownPath, $"its folder {current} is a file", "expected a path inside a folder");
                }

                current = Path.GetDirectoryName(current);
            }

            return current ?? Directory.GetCurrentDirectory();
        }

        private static void ProbeWritable(string folder, string shownPath)
        {
            string probe = Path.Combine(folder, ".inbetween-write-probe-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            try
            {
                using (new FileStream(probe, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1, FileOptions.DeleteOnClose))
                {
                }
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is NotSupportedException)
            {
                throw new OutputPathException(shownPath, $"cannot write in the folder {folder}", "expected a writable folder");
            }
            finally
            {
                TryDelete(probe);
            }
        }

        private static void TryDelete(string path)
        {
            try
            {
                if (File.Exists(path)) File.Delete(path);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                // The temporary file is hidden and named as ours; leaving it is better than masking the real error.
            }
        }
    }
}
