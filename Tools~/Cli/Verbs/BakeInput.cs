using System;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>What <c>bake</c> and <c>score</c> read before baking: the input at its true frame rate, the joint map, and keys that work.</summary>
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

        /// <summary>Every <paramref name="interval"/> frames from <paramref name="first"/>, never two keys within one model frame.</summary>
        public static int[] Every(int interval, MotionClip motion, int first, ModelContract contract, string input)
        {
            // Input frames per model frame (CMU at 120 fps: 4; BVH files round their frame time, so 4.0002 means 4),
            // and one more where it is above 1, so that rounding to model frames can never put two keys on one frame.
            double ratio = 1.0 / (contract.FramesPerSecond * motion.FrameTime);
            int spacing = ratio <= 1 + 1e-3 ? 1 : (int)Math.Ceiling(ratio - 1e-3) + 1;
            try
            {
                return KeyFrames.Every(interval, motion.FrameCount, first, spacing);
            }
            catch (KeyLayoutException e)
            {
                throw new CliErrors.UsageException($"{input}: --every {interval}: {e.Message}");
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

        /// <summary>
        /// The input's leg length in its own units, as <see cref="SkeletonMap"/> defines it (root height above its
        /// lowest mapped joint in the reference pose): what scores are divided by so that files and rigs compare.
        /// </summary>
        public static double LegLength(IBakeRetargeting seam, ModelContract contract, BvhAnimation animation)
        {
            if (seam is SkeletonRetargeting retargeted) return retargeted.Map.SourceLegLength;
            Skeleton skeleton = animation.Skeleton;
            return SkeletonMap.Create(ReferencePose.Default(skeleton), ReferencePose.ModelTPose(contract.Skeleton), null, animation.SourceName).SourceLegLength;
        }
    }
}
