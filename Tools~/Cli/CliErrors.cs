using System;
using System.IO;
using DeltaInterpolator.Core;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// Turns failures into the CLI's contract: bad input → exit 2 and one line on stderr in the form
    /// <c>FILE:LINE: what was wrong; what was expected</c>, never a stack trace.
    /// </summary>
    public static class CliErrors
    {
        /// <summary>Exit status for bad input (files, options).</summary>
        public const int BadInput = 2;

        /// <summary>Exit status for an unexpected failure (a bug: please report it).</summary>
        public const int Failure = 1;

        /// <summary>Thrown by verbs for a bad option value or a missing file; carries the one-line message.</summary>
        public sealed class UsageException : Exception
        {
            public UsageException(string message) : base(message)
            {
            }
        }

        /// <summary>Runs <paramref name="action"/>, mapping known input errors to exit 2 with one line on stderr.</summary>
        public static int Guard(Func<int> action)
        {
            try
            {
                return action();
            }
            catch (DataFormatException e)
            {
                WriteLine(e.Message);
                return BadInput;
            }
            catch (Core.IO.OutputPathException e)
            {
                WriteLine(e.Message);
                return BadInput;
            }
            catch (Core.IO.InputPathException e)
            {
                WriteLine(e.Message);
                return BadInput;
            }
            catch (UsageException e)
            {
                WriteLine(e.Message);
                return BadInput;
            }
            catch (Core.Retargeting.JointMapException e)
            {
                WriteLine(e.Message); // names the rig and the joints
                return BadInput;
            }
            catch (Core.Workflows.MotionRequestException e)
            {
                WriteLine(e.Message); // names the file, the frame and the frames it has
                return BadInput;
            }
            catch (FileNotFoundException e)
            {
                WriteLine($"{e.FileName ?? "file"}: no such file; expected an existing file");
                return BadInput;
            }
            catch (DirectoryNotFoundException e)
            {
                WriteLine($"{e.Message.TrimEnd('.')}; expected an existing directory");
                return BadInput;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                // Inputs and outputs are checked before any work, so this is a file system failure on the
                // way (permissions changed, disk full, a file vanished): say what the system said.
                WriteLine($"inbetween: {e.Message.TrimEnd('.')}; expected readable inputs and writable outputs (check permissions and free space)");
                return BadInput;
            }
            catch (Exception e)
            {
                WriteLine($"inbetween: unexpected {e.GetType().Name}: {e.Message} (this is a bug; please report it with the command line)");
                return Failure;
            }
        }

        /// <summary>
        /// Writes one line to stderr, made safe for the terminal: line breaks become spaces, other control
        /// characters from file contents are escaped and an overlong line is clipped (<see cref="TerminalText"/>).
        /// </summary>
        public static void WriteLine(string line)
        {
            Console.Error.WriteLine(TerminalText.Safe(line.Replace("\r\n", " ").Replace('\n', ' '), TerminalText.LineLength));
        }
    }
}
