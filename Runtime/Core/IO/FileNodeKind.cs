namespace DeltaInterpolator.Core.IO
{
    /// <summary>What a path names in the file system, as far as reading and writing files care.</summary>
    public enum FileNodeKind
    {
        /// <summary>Nothing is there.</summary>
        Missing,

        /// <summary>A regular file (the only kind the tools read or replace).</summary>
        RegularFile,

        /// <summary>A directory.</summary>
        Directory,

        /// <summary>A named pipe: opening it blocks until another process opens the other end.</summary>
        NamedPipe,

        /// <summary>A character or block device such as <c>/dev/null</c> or <c>/dev/zero</c>.</summary>
        Device,

        /// <summary>A Unix domain socket.</summary>
        Socket,
    }
}
