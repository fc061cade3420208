using System;
using System.Collections.Generic;
using System.Formats.Tar;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace DeltaInterpolator.Cli.Packaging
{
    /// <summary>
    /// Writes the two release archives of a <see cref="PackageContents"/> as gzip'd ustar streams:
    /// the UPM tarball (<c>package/</c> + every file, as <c>npm pack</c> lays it out) and the
    /// <c>.unitypackage</c> (one folder per asset named by its GUID, holding <c>asset</c> for files,
    /// <c>asset.meta</c> and <c>pathname</c> = <c>Packages/NAME/PATH</c>). Entries are sorted and carry a
    /// fixed time, owner and mode, so the same tree always gives the same bytes.
    /// </summary>
    public static class PackageArchives
    {
        /// <summary>The fixed modification time of every entry (the one npm uses for reproducible tarballs).</summary>
        public static readonly DateTimeOffset EntryTime = new DateTimeOffset(1985, 10, 26, 8, 15, 0, TimeSpan.Zero);

        /// <summary>Writes the UPM <c>.tgz</c>.</summary>
        /// <param name="contents">What to pack.</param>
        /// <param name="output">The stream to write (left open).</param>
        /// <param name="progress">Called with the number of entries written so far; may be null.</param>
        public static void WriteUpmTarball(PackageContents contents, Stream output, Action<int>? progress = null)
        {
            using (var gzip = new GZipStream(output, CompressionLevel.Optimal, leaveOpen: true))
            using (var tar = new TarWriter(gzip, TarEntryFormat.Ustar, leaveOpen: true))
            {
                int done = 0;
                foreach (string file in contents.Files)
                {
                    AddFile(tar, "package/" + file, Path.Combine(contents.Root, file), Executable(contents.Root, file));
                    progress?.Invoke(++done);
                }
            }
        }

        /// <summary>Writes the <c>.unitypackage</c>.</summary>
        /// <param name="contents">What to pack.</param>
        /// <param name="output">The stream to write (left open).</param>
        /// <param name="progress">Called with the number of assets written so far; may be null.</param>
        public static void WriteUnityPackage(PackageContents contents, Stream output, Action<int>? progress = null)
        {
            using (var gzip = new GZipStream(output, CompressionLevel.Optimal, leaveOpen: true))
            using (var tar = new TarWriter(gzip, TarEntryFormat.Ustar, leaveOpen: true))
            {
                int done = 0;
                foreach (PackageAsset asset in contents.Assets)
                {
                    string folder = asset.Guid + "/";
                    AddDirectory(tar, folder);
                    if (!asset.IsFolder)
                    {
                        AddFile(tar, folder + "asset", Path.Combine(contents.Root, asset.Path), false);
                    }

                    AddFile(tar, folder + "asset.meta", Path.Combine(contents.Root, asset.Path + ".meta"), false);
                    AddBytes(tar, folder + "pathname", Encoding.UTF8.GetBytes(UnityPath(contents, asset)));
                    progress?.Invoke(++done);
                }
            }
        }

        /// <summary>Where Unity puts an asset of the package: <c>Packages/NAME/PATH</c>.</summary>
        public static string UnityPath(PackageContents contents, PackageAsset asset) => "Packages/" + contents.Name + "/" + asset.Path;

        private static void AddFile(TarWriter tar, string name, string path, bool executable)
        {
            using (FileStream data = File.OpenRead(path))
            {
                var entry = new UstarTarEntry(TarEntryType.RegularFile, name)
                {
                    DataStream = data,
                };
                Stamp(entry, executable ? 0b111_101_101 : 0b110_100_100);
                tar.WriteEntry(entry);
            }
        }

        private static void AddBytes(TarWriter tar, string name, byte[] bytes)
        {
            using (var data = new MemoryStream(bytes, false))
            {
                var entry = new UstarTarEntry(TarEntryType.RegularFile, name) { DataStream = data };
                Stamp(entry, 0b110_100_100);
                tar.WriteEntry(entry);
            }
        }

        private static void AddDirectory(TarWriter tar, string name)
        {
            var entry = new UstarTarEntry(TarEntryType.Directory, name);
            Stamp(entry, 0b111_101_101);
            tar.WriteEntry(entry);
        }

        private static void Stamp(PosixTarEntry entry, int mode)
        {
            entry.ModificationTime = EntryTime;
            entry.Mode = (UnixFileMode)mode;
            entry.Uid = 0;
            entry.Gid = 0;
            entry.UserName = "";
            entry.GroupName = "";
        }

        private static bool Executable(string root, string file)
        {
            if (OperatingSystem.IsWindows()) return false;
            UnixFileMode mode = File.GetUnixFileMode(Path.Combine(root, file));
            return (mode & UnixFileMode.UserExecute) != 0;
        }
    }
}
