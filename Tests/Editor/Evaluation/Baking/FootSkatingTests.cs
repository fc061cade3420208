using System;
using System.IO;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Tests.Feet;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Baking
{
    /// <summary>The foot-skating measure: contacts from the truth alone, speeds in leg lengths per second, on filled frames only.</summary>
    public class FootSkatingTests
    {
        private const double FrameTime = 1.0 / 30;
        private static readonly int[] Keys = { 0, 10, 20, 30 };

        [Test]
        public void PlantedFlagsFollowTheContactRuleOnAnyTrack()
        {
            // One foot joint, leg length 1, 30 fps, ground 0: still on the ground (frames 0-9), sliding at 0.6 leg/s
            // on the ground (10-19), lifted 0.05 and still (20-29).
            const double dt = 1.0 / 30;
            var feet = new double[30 * 3];
            double x = 0;
            for (int f = 0; f < 30; f++)
            {
                if (f >= 10 && f < 20) x += 0.6 * dt;
                feet[3 * f] = x;
                feet[3 * f + 1] = f >= 20 ? 0.05 : 0.0;
            }

            bool[] planted = FootSkating.Planted(feet, 1, dt, 0.0, 1.0);
            Assert.That(planted.Length, Is.EqualTo(30));
            for (int f = 0; f < 30; f++)
            {
                // Frame 9's central difference already sees frame 10's step (0.3 leg/s: above the limit).
                bool expected = f < 9;
                Assert.That(planted[f], Is.EqualTo(expected), $"frame {f}");
            }
        }

        [Test]
        public void FeetSlidingAtAKnownSpeedMeasureThatSpeedInLegLengthsPerSecond()
        {
            Skeleton s = FeetFixtures.LowerBody();
            FootRig rig = FootRig.ForModel(s);
            MotionClip truth = FeetFixtures.Standing(s, 31, FrameTime);
            MotionClip sliding = FeetFixtures.Standing(s, 31, FrameTime, new Vector3D(0.4 * rig.LegLength, 0, 0));

            FootSkating score = FootSkating.Measure(truth, sliding, Keys, rig);
            // The toes stand on the ground; the ankles are 9 % of a leg up, above the 3 % contact height.
            Assert.That(score.ContactSamples, Is.EqualTo(27 * 2));
            Assert.That(score.MeanSpeed, Is.EqualTo(0.4).Within(1e-9));
            Assert.That(score.Ground, Is.EqualTo(0).Within(1e-9));
            FootSkating floor = FootSkating.OfTruth(truth, Keys, rig);
            Assert.That(floor.ContactSamples, Is.EqualTo(27 * 2));
            Assert.That(floor.MeanSpeed, Is.EqualTo(0).Within(1e-12));
        }

        [Test]
        public void OnlyTruthFeetThatAreLowAndSlowAreScored()
        {
            Skeleton s = FeetFixtures.LowerBody();
            FootRig rig = FootRig.ForModel(s);
            // Creeping at 10 % of a leg per second: planted (under 15 %), and the truth's own skating is that creep.
            MotionClip creeping = FeetFixtures.Standing(s, 31, FrameTime, new Vector3D(0, 0, 0.1 * rig.LegLength));
            FootSkating creep = FootSkating.OfTruth(creeping, Keys, rig);
            Assert.That(creep.ContactSamples, Is.EqualTo(54));
            Assert.That(creep.MeanSpeed, Is.EqualTo(0.1).Within(1e-9));
            // Walking at 20 % of a leg per second: nothing is planted, nothing is scored.
            MotionClip moving = FeetFixtures.Standing(s, 31, FrameTime, new Vector3D(0, 0, 0.2 * rig.LegLength));
            FootSkating none = FootSkating.OfTruth(moving, Keys, rig);
            Assert.That(none.ContactSamples, Is.Zero);
            Assert.That(double.IsNaN(none.MeanSpeed), Is.True);
        }

        [Test]
        public void AFootLiftedAboveThreePercentOfALegIsNotPlanted()
        {
            Skeleton s = FeetFixtures.LowerBody();
            FootRig rig = FootRig.ForModel(s);
            MotionClip truth = FeetFixtures.Standing(s, 31, FrameTime);
            // Raise the left leg's toe 4 % of a leg on frames 11..19 by turning the left thigh (the toe rises, the right stays).
            for (int f = 11; f < 20; f++) LiftLeftFoot(truth, f, 0.04 * rig.LegLength);
            MotionClip sliding = FeetFixtures.Standing(s, 31, FrameTime, new Vector3D(0.4 * rig.LegLength, 0, 0));
            FootSkating score = FootSkating.Measure(truth, sliding, Keys, rig);
            // The left toe is not planted on frames 11..19: 9 samples fewer.
            Assert.That(score.ContactSamples, Is.EqualTo(54 - 9));
            Assert.That(score.MeanSpeed, Is.EqualTo(0.4).Within(1e-9));
        }

        [Test]
        public void TheMeasureDoesNotDependOnUnits()
        {
            double a = Skating(1), b = Skating(10);
            Assert.That(b, Is.EqualTo(a).Within(1e-9));

            static double Skating(double scale)
            {
                Skeleton s = FeetFixtures.LowerBody(scale);
                FootRig rig = FootRig.ForModel(s);
                MotionClip truth = FeetFixtures.Walk(s, 61, FrameTime, 90 * scale);
                var keys = new[] { 0, 15, 30, 45, 60 };
                MotionClip slerp = new ClipBaker(new SlerpBaseline(), BakeSettings.ForBaseline()).Bake(truth, new ClipBaker(new SlerpBaseline(), BakeSettings.ForBaseline()).Plan(truth.FrameCount, keys));
                return FootSkating.Measure(truth, slerp, keys, rig).MeanSpeed;
            }
        }

        [Test]
        public void AResultThatDoesNotSpanTheKeysIsRefused()
        {
            Skeleton s = FeetFixtures.LowerBody();
            FootRig rig = FootRig.ForModel(s);
            MotionClip truth = FeetFixtures.Standing(s, 31, FrameTime);
            MotionClip short30 = FeetFixtures.Standing(s, 30, FrameTime);
            Assert.Throws<ArgumentException>(() => FootSkating.Measure(truth, short30, Keys, rig));
            Assert.Throws<ArgumentException>(() => FootSkating.Measure(truth, truth, new[] { 0, 40 }, rig));
        }

        [Test]
        public void OnLafan1TheTruthBarelySkatesAndSlerpSkatesMuchMore()
        {
            string dir = TestEnvironment.RequireLafan1();
            MotionClip truth = BvhReader.Read(Path.Combine(dir, "obstacles1_subject5.bvh")).Motion;
            FootRig rig = FootRig.ForModel(truth.Skeleton);
            int[] keys = KeyFrames.Every(15, truth.FrameCount);
            var baker = new ClipBaker(new SlerpBaseline(), BakeSettings.ForBaseline());
            MotionClip slerp = baker.Bake(truth, baker.Plan(truth.FrameCount, keys));
            FootSkating floor = FootSkating.OfTruth(truth, keys, rig);
            FootSkating skating = FootSkating.Measure(truth, slerp, keys, rig);
            Assert.That(floor.ContactSamples, Is.GreaterThan(1000));
            Assert.That(floor.MeanSpeed, Is.LessThan(0.05), "motion capture's planted feet creep, but slowly");
            Assert.That(skating.MeanSpeed, Is.GreaterThan(10 * floor.MeanSpeed));
        }

        [Test]
        public void ContactLabelsReplayPythonsGoldenVectors()
        {
            // Tests/Fixtures~/contact-labels.json: Python's `contacts.planted` (the labels the network learns and is
            // scored against) on synthetic walks; C# must give the same ground level per joint and the same flags.
            string? root = TestEnvironment.RepositoryRoot;
            string path = root == null ? "" : Path.Combine(root, "Tests", "Fixtures~", "contact-labels.json");
            if (!File.Exists(path)) Assert.Ignore($"Tests/Fixtures~/contact-labels.json not found above {AppContext.BaseDirectory}; skipping.");
            JsonValue doc = JsonValue.Parse(File.ReadAllText(path), path);
            int cases = 0, planted = 0;
            foreach (JsonValue c in doc.ExpectMember("cases").ExpectArray("cases"))
            {
                string name = c.ExpectMember("name").ExpectString("name");
                double[] feet = c.ExpectMember("feet").ExpectNumbers("feet", -1);
                double[] levels = c.ExpectMember("ground_levels").ExpectNumbers("ground_levels", 4);
                double[] flags = c.ExpectMember("planted").ExpectNumbers("planted", feet.Length / 3);
                double frameTime = c.ExpectMember("frame_time").ExpectNumber("frame_time"), leg = c.ExpectMember("leg_length").ExpectNumber("leg_length");
                double[] got = FootSkating.GroundLevels(feet, 4);
                for (int k = 0; k < 4; k++) Assert.That(got[k], Is.EqualTo(levels[k]).Within(1e-12), $"{name}: ground level of joint {k}");
                bool[] labels = FootSkating.ContactLabels(feet, 4, frameTime, leg);
                for (int i = 0; i < labels.Length; i++) Assert.That(labels[i], Is.EqualTo(flags[i] != 0), $"{name}: frame {i / 4}, joint {i % 4}");
                foreach (bool b in labels) planted += b ? 1 : 0;
                cases++;
            }

            Assert.That(cases, Is.EqualTo(4));
            Assert.That(planted, Is.GreaterThan(50), "the walks plant both joints of each foot");
        }

        [Test]
        public void AnAnkleStandingAHeelAboveTheToeIsPlantedFromItsOwnGroundLevel()
        {
            // Two joints of one foot standing still, the ankle 8 % of a leg above the toe: the measure's one ground
            // level (the lowest joint's) plants the toe only; the contact labels plant both.
            var feet = new double[10 * 2 * 3];
            for (int f = 0; f < 10; f++) feet[(f * 2) * 3 + 1] = 0.08;
            bool[] one = FootSkating.Planted(feet, 2, FrameTime, FootSkating.GroundLevel(feet, 2), 1.0);
            bool[] own = FootSkating.ContactLabels(feet, 2, FrameTime, 1.0);
            for (int f = 0; f < 10; f++)
            {
                Assert.That(one[f * 2], Is.False, $"frame {f}: ankle from the toe's level");
                Assert.That(own[f * 2] && own[f * 2 + 1] && one[f * 2 + 1], Is.True, $"frame {f}");
            }

            Assert.Throws<ArgumentException>(() => FootSkating.Planted(feet, 2, FrameTime, new double[1], 1.0));
        }

        private static void LiftLeftFoot(MotionClip clip, int frame, double height)
        {
            // Pitch the left thigh forward about the hips' lateral axis by the angle that raises the toe by about `height`
            // (the toe is ~94.5 below the hip joint): the exact rise does not matter, only that it is well above 3 %.
            FootRig rig = FootRig.ForModel(clip.Skeleton);
            int hip = rig.Left.Hip;
            double angle = Math.Acos(1 - height / (FeetFixtures.Thigh + FeetFixtures.Shin)) * 1.2;
            QuaternionD q = QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(frame, hip));
            QuaternionD global = Quaternions.Multiply(QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(frame, 0)), q);
            QuaternionD pitch = Quaternions.FromAxisAngle(Vector3D.UnitX, -angle);
            QuaternionD local = Quaternions.Multiply(Quaternions.Conjugate(QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(frame, 0))), Quaternions.Multiply(pitch, global));
            local.Write(clip.LocalRotations, clip.RotationIndex(frame, hip));
        }
    }
}
