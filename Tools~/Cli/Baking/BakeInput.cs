using System;
using System.Collections.Generic;
using System.Globalization;
using DeltaInterpolator.Cli.Verbs;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Core;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Baking
{
    /// <summary>
    /// The command line's side of a bake (<c>bake</c>, <c>demo</c>, <c>score</c>): reading the BVH at its true
    /// frame rate, the joint map, keys that work, and running Core's <see cref="InbetweenBake"/> with a
    /// progress bar, with Core's refusals turned into one line that names the file.
    /// </summary>
    internal static class BakeInput
    {
        /// <summary>The animation with its frame time replaced by 1 / <paramref name="fps"/> (a header that is wrong), or as it is.</summary>
        public static BvhAnimation WithFrameRate(BvhAnimation animation, double? fps)
        {
            if (fps == null) return animation;
            MotionClip m = animation.Motion;
            var clip = new MotionClip(m.Skeleton, m.FrameCount, 1.0 / fps.Value, m.LocalPositions, m.LocalRotations);
            return new BvhAnimation(clip, animation.JointChannels, animation.EndSites, animation.SourceName);
        }

        /// <summary>The user's joint map (omitted joints from the detected built-in map, else synthesized), or null.</summary>
        public static JointMap? LoadMap(string? path, BvhAnimation animation, ModelContract contract)
        {
            if (path == null) return null;
            JointMap map = JointMap.Load(path, JointMap.Detect(animation.Skeleton, contract.Skeleton));
            MapWarnings.UnknownTargets(map, contract.Skeleton, path); // keys that are no model joint: named, not ignored
            return map;
        }

        /// <summary>Keys <paramref name="spacing"/> apart from <paramref name="first"/> (<see cref="BakeKeys.Every(KeySpacing, MotionClip, int, ModelContract)"/>).</summary>
        public static int[] Every(KeySpacing spacing, MotionClip motion, int first, ModelContract contract, string input)
        {
            try
            {
                return BakeKeys.Every(spacing, motion, first, contract);
            }
            catch (KeyLayoutException e)
            {
                throw new CliErrors.UsageException($"{input}: --every {spacing}: {e.Message}");
            }
        }

        /// <summary>Keys given with --keys, checked against --from-frame.</summary>
        public static int[] CheckFrom(int[] keys, int first, string input)
        {
            if (keys.Length > 0 && keys[0] < first)
            {
                throw new CliErrors.UsageException(string.Format(CultureInfo.InvariantCulture,
                    "{0}: key frame {1} is before --from-frame {2}; expected keys from frame {2} on", input, keys[0], first));
            }

            return keys;
        }

        /// <summary>The standard pair every bake verb runs: the model, then SLERP (both foot-locked or neither).</summary>
        public static BakeMethod[] ModelAndSlerp(Inbetweener model, ShortContextPolicy? policy, bool filledContext, FootLockSettings? feet) =>
            new[] { BakeMethod.Model(model, policy, filledContext, feet), BakeMethod.Slerp(lockFeet: feet != null) };

        /// <summary>
        /// Bakes <paramref name="keys"/> of <paramref name="animation"/> with <paramref name="methods"/> on the model's
        /// skeleton (<see cref="RigRetargeting.For"/> decides how the file gets there), progress on stderr unless
        /// <paramref name="quiet"/>.
        /// </summary>
        /// <exception cref="CliErrors.UsageException">The keys or the rig do not work; the message names <paramref name="input"/>.</exception>
        public static BakeRun Bake(BvhAnimation animation, string input, int[] keys, ModelContract contract, IReadOnlyList<BakeMethod> methods,
            int? referenceFrame, JointMap? map, bool quiet = false, UpAxis up = UpAxis.Auto, bool acceptReferencePose = false)
        {
            try
            {
                IRigRetargeting rig = RigRetargeting.For(contract, animation.Motion, input, referenceFrame, map, up, acceptReferencePose);
                if (quiet) return InbetweenBake.Run(animation.Motion, keys, rig, methods);
                BakeRun? run = null;
                IAnsiConsole progressConsole = AnsiConsole.Create(new AnsiConsoleSettings
                {
                    Out = new AnsiConsoleOutput(Console.Error),
                    Interactive = Console.IsErrorRedirected ? InteractionSupport.No : InteractionSupport.Detect,
                });
                progressConsole.Progress()
                    .AutoClear(true)
                    .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn(), new RemainingTimeColumn())
                    .Start(ctx => run = InbetweenBake.Run(animation.Motion, keys, rig, methods,
                        Console.IsErrorRedirected ? null : new GapProgress(new SpectreProgress(ctx))));
                return run!;
            }
            catch (KeyLayoutException e)
            {
                throw new CliErrors.UsageException($"{input}: {e.Message}");
            }
            catch (JointMapException e)
            {
                throw new CliErrors.UsageException(e.Message);
            }
        }

        /// <summary>One line on how the retargeted output's key frames relate to the input's, or null for the model's own rig.</summary>
        public static string? KeyLine(IRigRetargeting rig) => rig.Map == null ? null : string.Format(CultureInfo.InvariantCulture,
            "key frames: the input's, copied exactly (mapping them to the model's skeleton and back came within {0:0.###e+0}° of them)", rig.KeyRoundTripDegrees);

        /// <summary>Gaps filled by every method → one progress bar ("Baking gaps"), updated synchronously.</summary>
        private sealed class GapProgress : IProgress<StageProgress>
        {
            private readonly IProgress<StageProgress> _bars;

            public GapProgress(IProgress<StageProgress> bars) => _bars = bars;

            public void Report(StageProgress value) => _bars.Report(new StageProgress("Baking gaps", value.Completed, value.Total));
        }
    }
}
