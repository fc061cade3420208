using System;
using System.Linq;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Issue 27: a clip request (a deferred target the engine samples in place, its root bone relative to the character) made while root
    /// motion walks the character is placed where the character will stand at the arrival, not where it stood at the request: the
    /// character walks on through the visit instead of being pulled back. Stand-in controller of real CMU clips, shipped model, 60 fps.
    /// </summary>
    [TestFixture]
    public sealed class ClipTargetRootMotionTests
    {
        [Test]
        public void AClipTargetWithRootMotionIsPlacedWhereTheWalkingCharacterWillStand()
        {
            const double seconds = 0.5;
            using var loop = new StandInLoop(60, HandOffFrameLoopTests.Walking);
            loop.PlayWithRootMotion();
            loop.PlayUntil(1.5);
            StandInState walk = loop.Controller.States[0];
            StandInState dribble = loop.Controller.States.Single(s => s.Name == "Dribble");
            int bones = loop.Controller.BoneCount;
            double requestedAt = loop.Time;
            double arrival = requestedAt + seconds;
            // Where the walk brings the root by the arrival.
            walk.Sample(requestedAt, 0, out _, new double[4 * bones], out double x0, out double z0);
            walk.Sample(arrival, 0, out _, new double[4 * bones], out double x1, out double z1);
            Vector3D start = loop.RootWorld;
            var walkedTo = new Vector3D(start.X + x1 - x0, 0, start.Z + z1 - z0);
            double walked = Math.Sqrt((x1 - x0) * (x1 - x0) + (z1 - z0) * (z1 - z0));

            // The clip's pose as the engine samples it under root motion: in place (the stand-in answers with its root at x = z = 0).
            int id = loop.Character.DeferTransition(seconds);
            var root = new double[3];
            var rotations = new double[4 * bones];
            loop.Controller.SampleOffScene(new StateTarget(0, dribble.Hash, 3.5), 0, root, rotations);
            Assert.That(root[0] == 0 && root[2] == 0, Is.True, "sampled in place");
            loop.Character.Sampled(root, rotations);

            Vector3D arrivedAt = default;
            bool arrived = false;
            double slowest = double.PositiveInfinity;
            Vector3D before = loop.RootWorld;
            while (loop.Time < arrival + 0.3)
            {
                loop.Frame();
                if (loop.Player.CurrentRequestId == id && loop.Player.IsPlaying && loop.Player.DecodedFrames == 0) loop.Decode();
                Vector3D now = loop.RootWorld;
                slowest = Math.Min(slowest, Math.Sqrt((now.X - before.X) * (now.X - before.X) + (now.Z - before.Z) * (now.Z - before.Z)) / loop.Step);
                before = now;
                if (!arrived && loop.Completions.Any(c => c.RequestId == id))
                {
                    arrived = true;
                    Assert.That(loop.Completions.Single(c => c.RequestId == id).ReachedTarget, Is.True);
                    arrivedAt = now;
                }
            }

            double missed = Math.Sqrt((arrivedAt.X - walkedTo.X) * (arrivedAt.X - walkedTo.X) + (arrivedAt.Z - walkedTo.Z) * (arrivedAt.Z - walkedTo.Z));
            double fromStart = Math.Sqrt((arrivedAt.X - start.X) * (arrivedAt.X - start.X) + (arrivedAt.Z - start.Z) * (arrivedAt.Z - start.Z));
            TestContext.Out.WriteLine($"the walk would bring the root {walked:F3} m by the arrival; the clip's target was reached {missed:F3} m from there, {fromStart:F3} m from where the character stood at the request; slowest root speed {slowest:F3} m/s");
            Assert.That(arrived, Is.True);
            // Placed where the character stood at the request, it would arrive the whole walked distance short.
            Assert.That(missed, Is.LessThan(0.1 * walked), "the target is placed where the walking character will stand at the arrival");
        }
    }
}
