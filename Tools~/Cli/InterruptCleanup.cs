using System;
using System.Runtime.InteropServices;
using DeltaInterpolator.Core.IO;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// SIGINT (Ctrl+C), SIGTERM, SIGHUP and SIGQUIT during a write: the temporary file beside the output
    /// (<c>.NAME.XXXXXXXX.tmp</c>) is deleted before the process ends as the signal says, so an interrupted
    /// run leaves the old output intact and nothing of its own behind.
    /// </summary>
    internal static class InterruptCleanup
    {
        private static readonly object Gate = new object();
        private static PosixSignalRegistration[]? _registrations;

        /// <summary>Registers the handlers once per process (later calls do nothing).</summary>
        public static void Install()
        {
            lock (Gate)
            {
                if (_registrations != null) return;
                var registrations = new System.Collections.Generic.List<PosixSignalRegistration>();
                foreach (PosixSignal signal in new[] { PosixSignal.SIGINT, PosixSignal.SIGTERM, PosixSignal.SIGHUP, PosixSignal.SIGQUIT })
                {
                    try
                    {
                        registrations.Add(PosixSignalRegistration.Create(signal, OnSignal));
                    }
                    catch (Exception e) when (e is PlatformNotSupportedException || e is System.IO.IOException)
                    {
                        // Not on this platform: the signal keeps its default action.
                    }
                }

                _registrations = registrations.ToArray();
            }
        }

        private static void OnSignal(PosixSignalContext context)
        {
            // context.Cancel stays false: the signal's default action (ending the process) follows.
            OutputFile.DeleteTemporaries();
        }
    }
}
