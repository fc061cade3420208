using System;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Inference;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// What the root-travel tests of a span (a gap or a blend) share: the Demo's CMU walk and jumps on one rig, read as
    /// root-motion clips (their hips' travel), the shipped model as a blend model, and the placements they compare.
    /// </summary>
    public abstract class DemoRootTravelFixture
    {
        protected Inbetweener Network { get; private set; } = null!;

        protected CharacterRig Rig { get; private set; } = null!;

        protected IClipPoses Walk { get; private set; } = null!;

        protected IClipPoses Jumps { get; private set; } = null!;

        protected BlendModel Model { get; private set; } = null!;

        [OneTimeSetUp]
        public void Load()
        {
            DemoBlendClips clips = DemoBlendClips.Load();
            Rig = clips.Rig;
            Walk = new MotionClipPoses("walk", Rig, clips.Walk);
            Jumps = new MotionClipPoses("jumps", Rig, clips.Jumps);
            Network = TwoRigBakeTests.ShippedModel();
            Model = new BlendModel(Network.Contract, Network, maxBoneDeviationDegrees: 30);
        }

        [OneTimeTearDown]
        public void Unload() => Network?.Dispose();

        /// <summary>Where <paramref name="clip"/>'s root bone stands at <paramref name="time"/> (its ground position and facing).</summary>
        protected RootPlacement Placement(IClipPoses clip, double time)
        {
            var root = new double[3];
            var rotations = new double[4 * Rig.Skeleton.JointCount];
            clip.Sample(time, root, rotations);
            return RootPlacement.OfPose(Rig, root, rotations.AsSpan(0, 4));
        }

        /// <summary>The larger of two placements' differences in X, Z and yaw (radians, wrapped).</summary>
        protected static double Distance(RootPlacement a, RootPlacement b) =>
            Math.Max(Math.Max(Math.Abs(a.X - b.X), Math.Abs(a.Z - b.Z)), Math.Abs(Math.IEEERemainder(a.Yaw - b.Yaw, 2 * Math.PI)));

        /// <summary>
        /// Asserts that a span without root travel leaves the pose sampled at <paramref name="fraction"/> as it is and moves
        /// nothing (no velocity, no turn).
        /// </summary>
        protected void AssertTravelMovesNothing(SpanRootTravel travel, BlendFrames frames, double fraction, double seconds)
        {
            double[] root = new double[3], rotations = new double[4 * Rig.Skeleton.JointCount];
            frames.Sample(fraction, root, rotations);
            double[] rootBefore = (double[])root.Clone(), rotationsBefore = (double[])rotations.Clone();
            travel.InPlace(Rig, fraction, root, rotations.AsSpan(0, 4));
            Assert.That(root, Is.EqualTo(rootBefore));
            Assert.That(rotations, Is.EqualTo(rotationsBefore));
            travel.Velocity(fraction, seconds, out double x, out double z, out double yawRate);
            Assert.That((x, z, yawRate), Is.EqualTo((0.0, 0.0, 0.0)));
        }

        /// <summary>The travel's step from model frame <paramref name="k"/> to the next.</summary>
        protected static RootPlacement Step(SpanRootTravel travel, int k) => travel.Frame(k).StepTo(travel.Frame(k + 1));
    }
}
