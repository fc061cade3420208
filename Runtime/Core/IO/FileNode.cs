using System;
using System.IO;
using System.Runtime.InteropServices;
using System.Text;

namespace DeltaInterpolator.Core.IO
{
    /// <summary>
    /// What a path names (<see cref="FileNodeKind"/>) and, where the platform tells, the identity of the
    /// file behind it (device and inode), so two spellings of one file — a symbolic link, a hard link,
    /// <c>a/../b</c> — compare equal.
    /// </summary>
    /// <remarks>
    /// .NET's managed file API does not tell a named pipe or a device from a regular file, and opening a
    /// named pipe blocks until a writer appears. On Unix this asks <c>stat(2)</c> through the runtime's own
    /// native shim (<c>SystemNative_Stat</c> in libSystem.Native, whose FileStatus layout is fixed); where
    /// that shim is missing (Windows, an older Mono) it falls back to the managed answer: a directory, a
    /// file (taken as regular) or nothing.
    /// </remarks>
    public readonly struct FileNode
    {
        // FileStatus of libSystem.Native (src/native/libs/System.Native/pal_io.h): Mode at byte 4; Dev, Ino
        // at bytes 88 and 104 since the nanosecond and RDev fields were added (.NET 8 and later).
        private const int ModeOffset = 4;
        private const int DeviceOffset = 88;
        private const int InodeOffset = 104;
        private const int TypeMask = 0xF000;
        private const int FifoType = 0x1000;
        private const int CharacterDeviceType = 0x2000;
        private const int DirectoryType = 0x4000;
        private const int BlockDeviceType = 0x6000;
        private const int RegularType = 0x8000;
        private const int SocketType = 0xC000;

        private static bool _nativeMissing;

        private FileNode(FileNodeKind kind, long device, long inode, bool hasIdentity)
        {
            Kind = kind;
            Device = device;
            Inode = inode;
            HasIdentity = hasIdentity;
        }

        /// <summary>What the path names (symbolic links followed).</summary>
        public FileNodeKind Kind { get; }

        /// <summary>The device holding the file (valid when <see cref="HasIdentity"/>).</summary>
        public long Device { get; }

        /// <summary>The file's inode number (valid when <see cref="HasIdentity"/>).</summary>
        public long Inode { get; }

        /// <summary>True when <see cref="Device"/> and <see cref="Inode"/> identify the file.</summary>
        public bool HasIdentity { get; }

        /// <summary>True when both name the same existing file (by identity where known).</summary>
        public bool IsSameFileAs(FileNode other)
        {
            return HasIdentity && other.HasIdentity && Kind != FileNodeKind.Missing && Device == other.Device && Inode == other.Inode;
        }

        /// <summary>Describes <paramref name="path"/>; never opens it (so never blocks on a named pipe).</summary>
        public static FileNode Of(string path)
        {
            if (!_nativeMissing && !RuntimeInformation.IsOSPlatform(OSPlatform.Windows))
            {
                try
                {
                    return FromStat(path);
                }
                catch (Exception e) when (e is DllNotFoundException || e is EntryPointNotFoundException || e is BadImageFormatException)
                {
                    _nativeMissing = true;
                }
            }

            return Managed(path);
        }

        /// <summary>A short phrase for a kind that is not a regular file, e.g. "is a named pipe (FIFO)".</summary>
        public static string Describe(FileNodeKind kind)
        {
            switch (kind)
            {
                case FileNodeKind.Missing: return "does not exist";
                case FileNodeKind.Directory: return "is a directory";
                case FileNodeKind.NamedPipe: return "is a named pipe (FIFO), not a regular file";
                case FileNodeKind.Device: return "is a device, not a regular file";
                case FileNodeKind.Socket: return "is a socket, not a regular file";
                default: return "is a regular file";
            }
        }

        private static FileNode FromStat(string path)
        {
            byte[] name = Encoding.UTF8.GetBytes(path + "\0");
            var status = new byte[256];
            if (Stat(name, status) != 0)
            {
                // Missing, or not reachable (permissions): the managed calls decide what to report.
                return Managed(path);
            }

            int type = BitConverter.ToInt32(status, ModeOffset) & TypeMask;
            FileNodeKind kind;
            switch (type)
            {
                case RegularType: kind = FileNodeKind.RegularFile; break;
                case DirectoryType: kind = FileNodeKind.Directory; break;
                case FifoType: kind = FileNodeKind.NamedPipe; break;
                case CharacterDeviceType:
                case BlockDeviceType: kind = FileNodeKind.Device; break;
                case SocketType: kind = FileNodeKind.Socket; break;
                default: kind = FileNodeKind.Device; break;
            }

            // Device and inode sit where they do only in the layout of .NET 8 and later (checked there).
            bool identity = Environment.Version.Major >= 8 && RuntimeInformation.FrameworkDescription.StartsWith(".NET", StringComparison.Ordinal)
                && !RuntimeInformation.FrameworkDescription.StartsWith(".NET Framework", StringComparison.Ordinal);
            return new FileNode(kind, identity ? BitConverter.ToInt64(status, DeviceOffset) : 0, identity ? BitConverter.ToInt64(status, InodeOffset) : 0, identity);
        }

        // The managed answer, without identity: a directory, a file (taken as regular) or nothing.
        private static FileNode Managed(string path)
        {
            if (Directory.Exists(path)) return new FileNode(FileNodeKind.Directory, 0, 0, false);
            if (File.Exists(path)) return new FileNode(FileNodeKind.RegularFile, 0, 0, false);
            return new FileNode(FileNodeKind.Missing, 0, 0, false);
        }

        [DllImport("libSystem.Native", EntryPoint = "SystemNative_Stat")]
        private static extern int Stat(byte[] path, byte[] status);
    }
}
