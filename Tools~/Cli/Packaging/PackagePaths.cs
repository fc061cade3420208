using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.RegularExpressions;
using DeltaInterpolator.Core.IO;

namespace DeltaInterpolator.Cli.Packaging
{
    /// <summary>
    /// What may go into a release archive, checked before anything is written: the package name and
    /// version (they become archive and <c>Packages/NAME/</c> paths), each file's path (no <c>\</c>, no
    /// <c>..</c>, no control characters, short enough for a ustar header) and each file itself (a regular
    /// file whose real location, links resolved, is inside the package: a link to <c>/etc/passwd</c> or
    /// <c>/dev/zero</c>, a named pipe or a device is refused, never opened).
    /// </summary>
    internal static class PackagePaths
    {
        // The Package Manager's rule for names (reverse domain, lower case), at most 214 characters as npm's.
        private static readonly Regex NamePattern = new Regex(@"^[a-z0-9][a-z0-9._-]{0,213}$", RegexOptions.CultureInvariant);

        // Semantic versions: digits, letters, '.', '-', '+' (no separators, no "..").
        private static readonly Regex VersionPattern = new Regex(@"^[0-9]+\.[0-9]+\.[0-9]+([-+][0-9A-Za-z.+-]{1,100})?$", RegexOptions.CultureInvariant);

        /// <summary>Refuses a package name or version that is not a UPM name or a semantic version.</summary>
        public static void CheckManifest(string manifest, string name, string version)
        {
            if (!NamePattern.IsMatch(name) || name.Contains(".."))
            {
                throw new CliErrors.UsageException($"{manifest}: \"name\" is '{TerminalText.Safe(name, TerminalText.NameLength)}'; expected a Unity package name such as com.company.package (lower-case letters, digits, '.', '-', '_'; it becomes a folder name in both archives)");
            }

            if (!VersionPattern.IsMatch(version) || version.Contains(".."))
            {
                throw new CliErrors.UsageException($"{manifest}: \"version\" is '{TerminalText.Safe(version, TerminalText.NameLength)}'; expected a semantic version such as 1.2.3 or 1.2.3-preview.1");
            }
        }

        /// <summary>
        /// Refuses a file path (relative, '/'-separated) that an archive could not hold as it is: a '\' (a
        /// separator where the archive is unpacked on Windows), a '.' or '..' component, a control
        /// character, or a name too long for a ustar header under <paramref name="archivePrefix"/>.
        /// </summary>
        public static void CheckEntry(string root, string path, string archivePrefix)
        {
            string shown = Path.Combine(root, TerminalText.Safe(path, TerminalText.LineLength / 2));
            foreach (char c in path)
            {
                if (c == '\\')
                {
                    throw new CliErrors.UsageException($"{shown}: the name has a '\\'; expected names without backslashes (a '\\' separates folders on Windows, so '..\\' would climb out of the package there)");
                }

                if (TerminalText.IsUnsafe(c))
                {
                    throw new CliErrors.UsageException($"{shown}: the name has a control or direction character; expected printable file names (rename the file)");
                }
            }

            foreach (string part in path.Split('/'))
            {
                if (part.Length == 0 || part == "." || part == "..")
                {
                    throw new CliErrors.UsageException($"{shown}: the path has an empty, '.' or '..' component; expected a plain path inside the package");
                }
            }

            if (!FitsUstar(archivePrefix + path))
            {
                throw new CliErrors.UsageException($"{shown}: the path is too long for a ustar archive entry ({Encoding.UTF8.GetByteCount(archivePrefix + path)} bytes as {archivePrefix}…); expected at most 100 bytes of file name after a folder of at most 155 bytes (shorten the name or the folders)");
            }
        }

        /// <summary>
        /// Refuses a file that is not a regular file (a named pipe, device or socket: never opened) or whose
        /// real location (symbolic links resolved) lies outside <paramref name="root"/>.
        /// </summary>
        public static void CheckFile(string root, string path)
        {
            string full = Path.Combine(root, path);
            string shown = TerminalText.Safe(full, TerminalText.LineLength / 2);
            FileNodeKind kind = FileNode.Of(full).Kind;
            if (!OperatingSystem.IsWindows())
            {
                string real = RealPath(full);
                string realRoot = RealPath(root).TrimEnd('/') + "/";
                if (!real.StartsWith(realRoot, StringComparison.Ordinal))
                {
                    throw new CliErrors.UsageException($"{shown}: is a symbolic link to {TerminalText.Safe(real, TerminalText.LineLength / 4)}, outside the package; expected files inside the package (copy the file in, or remove the link)");
                }
            }

            if (kind != FileNodeKind.RegularFile)
            {
                throw new CliErrors.UsageException($"{shown}: {FileNode.Describe(kind)}; expected regular files only in a package");
            }
        }

        /// <summary>True when ustar can store <paramref name="name"/>: 100 bytes, or a '/' splitting it into ≤ 155 + ≤ 100 bytes.</summary>
        public static bool FitsUstar(string name)
        {
            byte[] bytes = Encoding.UTF8.GetBytes(name);
            if (bytes.Length <= 100) return true;
            if (bytes.Length > 256) return false;
            for (int i = 0; i < bytes.Length; i++)
            {
                if (bytes[i] == (byte)'/' && i <= 155 && bytes.Length - i - 1 <= 100 && bytes.Length - i - 1 > 0) return true;
            }

            return false;
        }

        /// <summary>The path with every symbolic link resolved (as realpath(3)), for Unix file systems.</summary>
        internal static string RealPath(string path)
        {
            var pending = new LinkedList<string>(Path.GetFullPath(path).Split('/', StringSplitOptions.RemoveEmptyEntries));
            string current = "/";
            int links = 0;
            while (pending.Count > 0)
            {
                string part = pending.First!.Value;
                pending.RemoveFirst();
                if (part == ".") continue;
                if (part == "..")
                {
                    current = Path.GetDirectoryName(current) ?? "/";
                    continue;
                }

                string next = current == "/" ? "/" + part : current + "/" + part;
                string? target = null;
                try
                {
                    target = new FileInfo(next).LinkTarget;
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    target = null;
                }

                if (target == null)
                {
                    current = next;
                    continue;
                }

                if (++links > 40) throw new CliErrors.UsageException($"{TerminalText.Safe(path, TerminalText.LineLength / 2)}: too many levels of symbolic links; expected links that end at a file");
                if (target.StartsWith("/", StringComparison.Ordinal)) current = "/";
                string[] parts = target.Split('/', StringSplitOptions.RemoveEmptyEntries);
                for (int i = parts.Length - 1; i >= 0; i--) pending.AddFirst(parts[i]);
            }

            return current;
        }
    }
}
