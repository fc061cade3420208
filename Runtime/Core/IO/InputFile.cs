using System.Globalization;
using System.IO;
using System.Text;

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

        /// <summary>
        /// <see cref="Check"/>, then the file as UTF-8 text, refusing (with <see cref="InputPathException"/>)
        /// one larger than <paramref name="maxBytes"/> before reading it, so a small settings file (a joint
        /// map, a manifest, a key list) can never make the reader grow without bound.
        /// </summary>
        /// <exception cref="InputPathException">Not a regular file, or larger than <paramref name="maxBytes"/>.</exception>
        /// <exception cref="IOException">The file cannot be read.</exception>
        public static string ReadAllText(string path, string expected, long maxBytes)
        {
            Check(path, expected);
            using (var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read))
            {
                // The length once more from the open file (it may have grown since the check), and a read that
                // stops one byte past the limit either way.
                if (stream.Length > maxBytes) throw TooLarge(path, stream.Length, expected, maxBytes);
                var buffer = new MemoryStream();
                var chunk = new byte[1 << 16];
                int n;
                while ((n = stream.Read(chunk, 0, chunk.Length)) > 0)
                {
                    buffer.Write(chunk, 0, n);
                    if (buffer.Length > maxBytes) throw TooLarge(path, buffer.Length, expected, maxBytes);
                }

                return new UTF8Encoding(false).GetString(buffer.GetBuffer(), 0, (int)buffer.Length);
            }
        }

        private static InputPathException TooLarge(string path, long bytes, string expected, long maxBytes) => new InputPathException(
            path,
            string.Format(CultureInfo.InvariantCulture, "is {0:N0} bytes or more", bytes),
            string.Format(CultureInfo.InvariantCulture, "expected {0} of at most {1:N0} bytes", expected, maxBytes));

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
