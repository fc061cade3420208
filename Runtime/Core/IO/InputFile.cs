using System.IO;

namespace DeltaInterpolator.Core.IO
{
    /// <summary>
    /// The one check before this package reads a file the user named: it must be a regular file. A
    /// directory, a named pipe (which would block the reader forever), a device or a socket is refused
    /// with <see cref="InputPathException"/> naming what it is, before anything opens it.
    /// </summary>
    public static class InputFile
    {
        /// <summary>Refuses <paramref name="path"/> unless it names an existing regular file.</summary>
        /// <param name="path">The path as the user gave it.</param>
        /// <param name="expected">What the file should be, e.g. <c>"a .bvh file"</c>; the message says "expected" and this.</param>
        /// <exception cref="InputPathException">Missing, a directory or another non-regular file.</exception>
        public static void Check(string path, string expected)
        {
            if (string.IsNullOrEmpty(path))
            {
                throw new InputPathException("(empty path)", "no input path given", "expected " + expected);
            }

            FileNodeKind kind = FileNode.Of(path).Kind;
            if (kind == FileNodeKind.Missing)
            {
                throw new InputPathException(path, "no such file", "expected " + expected);
            }

            if (kind != FileNodeKind.RegularFile)
            {
                throw new InputPathException(path, FileNode.Describe(kind), "expected " + expected);
            }
        }

        /// <summary><see cref="Check"/>, then all bytes of the file.</summary>
        /// <exception cref="InputPathException">Not a regular file.</exception>
        /// <exception cref="IOException">The file cannot be read.</exception>
        public static byte[] ReadAllBytes(string path, string expected)
        {
            Check(path, expected);
            return File.ReadAllBytes(path);
        }
    }
}
