using System.IO;

namespace DeltaInterpolator.Cli
{
    /// <summary>A track of a picture: <c>NAME=FILE.bvh</c>, or a bare <c>FILE.bvh</c> named by a default or by the file.</summary>
    internal static class TrackArgument
    {
        /// <summary>The name and file that <paramref name="value"/> means.</summary>
        /// <param name="value">The option's value.</param>
        /// <param name="defaultName">The name of a bare file; empty to name it by the file.</param>
        /// <param name="option">The option, for messages (<c>--truth</c>, <c>--track</c>).</param>
        /// <exception cref="CliErrors.UsageException">An empty name or file around the '='.</exception>
        public static (string Name, string Path) Parse(string value, string defaultName, string option)
        {
            int equals = value.IndexOf('=');
            if (equals < 0)
            {
                return (defaultName.Length > 0 ? defaultName : Path.GetFileNameWithoutExtension(value), value);
            }

            string name = value.Substring(0, equals).Trim();
            string path = value.Substring(equals + 1);
            if (name.Length == 0 || path.Length == 0)
            {
                throw new CliErrors.UsageException($"{option} {value}: empty name or file; expected NAME=FILE.bvh");
            }

            return (name, path);
        }
    }
}
