using System;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// What the Timeline blend tests play: the Demo sample's CMU walk and jumps on one rig (the walk's T-pose frame as
    /// the rig's reference), and the editor baker's input for a blend laid out by hand, which a blend must equal.
    /// </summary>
    internal sealed class DemoBlendClips
    {
        private const string JumpsFile = "Samples~/Demo/cmu_01_01_jumps_turn.bvh";

        private DemoBlendClips(MotionClip demo, CharacterRig rig, MotionClip walk, MotionClip jumps)
        {
            Demo = demo;
            Rig = rig;
            Walk = walk;
            Jumps = jumps;
        }

        /// <summary>The whole walk take; frame 0 is the T-pose, the rig's reference.</summary>
        public MotionClip Demo { get; }

        /// <summary>The rig the Unity layer would collect from the walk's T-pose frame.</summary>
        public CharacterRig Rig { get; }

        /// <summary>3 s of walking at 120 fps.</summary>
        public MotionClip Walk { get; }

        /// <summary>401 frames of the jumps take, on the walk's skeleton.</summary>
        public MotionClip Jumps { get; }

        public static DemoBlendClips Load()
        {
            MotionClip demo = TwoRigBakeTests.DemoWalk();
            MotionClip jumps = BvhReader.Read(ShippedModels.Find(JumpsFile)).Motion;
            MotionClip excerpt = jumps.Excerpt(200, 401);
            return new DemoBlendClips(
                demo,
                BlendCacheTests.Rig(demo, RootFrame.Identity),
                demo.Excerpt(120, 361),
                new MotionClip(demo.Skeleton, 401, jumps.FrameTime, excerpt.LocalPositions, excerpt.LocalRotations));
        }

        /// <summary>
        /// A blend laid out by hand as the editor baker's input: <paramref name="from"/> sampled at
        /// <paramref name="historyTime"/>(k) for the past frames k = 0..<paramref name="pastFrames"/>−1,
        /// <paramref name="missingFrames"/> frames left to fill, and <paramref name="to"/> at <paramref name="toTime"/> as the target.
        /// </summary>
        public static CharacterPoseTrack LaidOut(CharacterRig rig, int pastFrames, int missingFrames, double frameTime, IClipPoses from, Func<int, double> historyTime, IClipPoses to, double toTime)
        {
            var track = new CharacterPoseTrack(rig, pastFrames + missingFrames + 1, frameTime);
            var root = new double[3];
            var rotations = new double[4 * rig.Skeleton.JointCount];
            for (int k = 0; k < pastFrames; k++)
            {
                from.Sample(historyTime(k), root, rotations);
                track.SetUnityPose(k, root, rotations);
            }

            to.Sample(toTime, root, rotations);
            track.SetUnityPose(pastFrames + missingFrames, root, rotations);
            return track;
        }
    }
}
