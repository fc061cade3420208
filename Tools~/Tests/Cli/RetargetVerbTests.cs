using System;
using System.IO;
using DeltaInterpolator.Cli;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Retargeting;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary><c>inbetween retarget</c> through <see cref="Program.Main"/>: exit codes, the one-line errors, files left alone.</summary>
    public sealed class RetargetVerbTests
    {
        private string _dir = "";
        private string _model = "";

        [SetUp]
        public void SetUp()
        {
            string? root = TestEnvironment.RepositoryRoot;
            _model = root == null ? "" : Path.Combine(root, "Samples~", "LaFAN1Model", "DeltaInterpolator-LaFAN1.onnx");
            if (!File.Exists(_model)) Assert.Ignore("Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx absent; skipping the retarget verb tests.");
            _dir = Path.Combine(Path.GetTempPath(), "retarget-verb-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void TearDown()
        {
            if (_dir.Length > 0 && Directory.Exists(_dir)) Directory.Delete(_dir, true);
        }

        /// <summary>A generated BVH of the model's joints with other rest frames, proportions and units, optionally with some joints renamed.</summary>
        private string WriteSource(string name, params (string From, string To)[] renames)
        {
            Skeleton model = RetargetFixtures.Lafan1();
            (Skeleton generated, ReferencePose reference) = RetargetFixtures.Source(model, 7, 0.05, 40.0, "LeftArm");
            var names = new string[generated.JointCount];
            for (int j = 0; j < names.Length; j++)
            {
                string n = generated.Names[j].Substring("src_".Length);
                foreach ((string from, string to) in renames) if (n == from) n = to;
                names[j] = n;
            }

            var skeleton = new Skeleton(names, generated.Parents, generated.Offsets);
            var pose = new ReferencePose(skeleton, reference.LocalRotations, reference.RootPosition);
            // Rest pose = the generated reference (a standing T-pose): the CLI's default reference is the zero pose,
            // and issue 30's humanoid rule refuses a zero pose whose spine and legs point anywhere.
            MotionClip motion = RetargetFixtures.WithRestPose(RetargetFixtures.Motion(pose, 40, 1.0 / 60.0, 8, 0.2, "LeftHipJoint"), pose);
            skeleton = motion.Skeleton;
            var channels = new BvhChannel[skeleton.JointCount][];
            for (int j = 0; j < channels.Length; j++)
            {
                channels[j] = j == 0
                    ? new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation }
                    : new[] { BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation };
            }

            string path = Path.Combine(_dir, name);
            BvhWriter.Write(new BvhAnimation(motion, channels, null, path), path);
            return path;
        }

        private (int Code, string Error) Run(params string[] args)
        {
            TextWriter oldError = Console.Error, oldOut = Console.Out;
            var error = new StringWriter();
            try
            {
                Console.SetError(error);
                Console.SetOut(new StringWriter());
                int code = Program.Main(args);
                return (code, error.ToString());
            }
            finally
            {
                Console.SetError(oldError);
                Console.SetOut(oldOut);
            }
        }

        private static void AssertOneLine(string error, params string[] contains)
        {
            string trimmed = error.TrimEnd('\r', '\n');
            Assert.That(trimmed, Does.Not.Contain("\n"), "one line on stderr");
            foreach (string c in contains) Assert.That(trimmed, Does.Contain(c));
        }

        [Test]
        public void RetargetsOntoTheModelAndTheResultReadsBack()
        {
            string input = WriteSource("walk.bvh");
            string output = Path.Combine(_dir, "on_model.bvh");
            (int code, string error) = Run("retarget", input, "--to", "model", "--out", output, "--model", _model);
            Assert.That(code, Is.EqualTo(0), error);
            BvhAnimation result = BvhReader.Read(output);
            Assert.That(result.Skeleton.JointCount, Is.EqualTo(22));
            Assert.That(result.Motion.FrameTime, Is.EqualTo(1.0 / 30.0).Within(1e-6));
            Assert.That(result.Motion.FrameCount, Is.EqualTo(20));   // 40 frames at 60 fps span 39/60 s → frames 0..19 at 30 fps
        }

        [Test]
        public void TheDemoClipRetargetsAndItsResultReadsWithInfo()
        {
            string demo = Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_01_01_jumps_turn.bvh");
            string output = Path.Combine(_dir, "demo_on_model.bvh");
            (int code, string error) = Run("retarget", demo, "--to", "model", "--out", output, "--model", _model);
            Assert.That(code, Is.EqualTo(0), error);
            (code, error) = Run("info", output);
            Assert.That(code, Is.EqualTo(0), error);
            BvhAnimation result = BvhReader.Read(output);
            Assert.That(result.Motion.FrameCount, Is.EqualTo(225));   // 901 frames at 120 fps span 7.5 s → 226 frames at 30 fps would end past it; 225 fit
        }

        [Test]
        public void RetargetsOntoAnotherBvhSkeleton()
        {
            string input = WriteSource("walk.bvh");
            string other = WriteSource("other.bvh");
            string output = Path.Combine(_dir, "on_other.bvh");
            (int code, string error) = Run("retarget", input, "--to", other, "--out", output, "--model", _model);
            Assert.That(code, Is.EqualTo(0), error);
            BvhAnimation result = BvhReader.Read(output);
            Assert.That(result.Skeleton.HasSameHierarchy(BvhReader.Read(other).Skeleton), Is.True);
            Assert.That(result.Motion.FrameCount, Is.EqualTo(40));
        }

        [Test]
        public void MissingJointsAreNamedAndNothingIsWritten()
        {
            // Knees cannot be made up (toes can: MissingToesAreMadeUpAndNamed).
            string input = WriteSource("no_knees.bvh", ("LeftLeg", "LeftKnee"), ("RightLeg", "RightKnee"));
            string output = Path.Combine(_dir, "out.bvh");
            (int code, string error) = Run("retarget", input, "--to", "model", "--out", output, "--model", _model);
            Assert.That(code, Is.EqualTo(2));
            AssertOneLine(error, input + ": ", "LeftLeg", "RightLeg", "--map");
            Assert.That(File.Exists(output), Is.False);
        }

        [Test]
        public void MissingToesAreMadeUpAndNamed()
        {
            string input = WriteSource("no_toes.bvh", ("LeftToe", "LeftToeTip"), ("RightToe", "RightToeTip"));
            string output = Path.Combine(_dir, "out.bvh");
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--out", output, "--model", _model);
            CliHarness.AssertSuccess(run);
            Assert.That(string.Join(" ", run.Stdout.Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries)), Does.Contain("LeftToe, RightToe: the input lacks them"));
            Assert.That(BvhReader.Read(output).Skeleton.JointCount, Is.EqualTo(22));
        }

        [Test]
        public void AUserMapFillsTheMissingJoints()
        {
            string input = WriteSource("no_toes.bvh", ("LeftToe", "LeftToeTip"), ("RightToe", "RightToeTip"));
            string map = Path.Combine(_dir, "map.json");
            File.WriteAllText(map, "{\"LeftToe\": \"LeftToeTip\", \"RightToe\": \"RightToeTip\"}");
            string output = Path.Combine(_dir, "out.bvh");
            (int code, string error) = Run("retarget", input, "--to", "model", "--out", output, "--map", map, "--model", _model);
            Assert.That(code, Is.EqualTo(0), error);
            Assert.That(BvhReader.Read(output).Skeleton.JointCount, Is.EqualTo(22));
        }

        [Test]
        public void AnExistingOutputIsKeptWithoutForce()
        {
            string input = WriteSource("walk.bvh");
            string output = Path.Combine(_dir, "exists.bvh");
            File.WriteAllText(output, "keep me");
            (int code, string error) = Run("retarget", input, "--to", "model", "--out", output, "--model", _model);
            Assert.That(code, Is.EqualTo(2));
            AssertOneLine(error, "exists.bvh");
            Assert.That(File.ReadAllText(output), Is.EqualTo("keep me"));

            (code, error) = Run("retarget", input, "--to", "model", "--out", output, "--model", _model, "--force");
            Assert.That(code, Is.EqualTo(0), error);
            Assert.That(BvhReader.Read(output).Skeleton.JointCount, Is.EqualTo(22));
        }

        [Test]
        public void TheInputIsNeverTheOutput()
        {
            string input = WriteSource("walk.bvh");
            byte[] before = File.ReadAllBytes(input);
            (int code, string error) = Run("retarget", input, "--to", "model", "--out", input, "--model", _model, "--force");
            Assert.That(code, Is.EqualTo(2));
            AssertOneLine(error, "walk.bvh");
            Assert.That(File.ReadAllBytes(input), Is.EqualTo(before));
        }

        [Test]
        public void AGivenScaleReplacesTheLegLengthRatio()
        {
            string input = WriteSource("walk.bvh");
            string output = Path.Combine(_dir, "out.bvh");
            (int code, string error) = Run("retarget", input, "--to", "model", "--out", output, "--model", _model, "--scale", "0");
            Assert.That(code, Is.EqualTo(2));
            AssertOneLine(error, "--scale 0");
            Assert.That(File.Exists(output), Is.False);

            (code, error) = Run("retarget", input, "--to", "model", "--out", output, "--model", _model, "--scale", "2.5");
            Assert.That(code, Is.EqualTo(0), error);
            BvhAnimation source = BvhReader.Read(input), result = BvhReader.Read(output);
            // Frame 0 of both: the root's position times 2.5 (the file keeps 6 decimals).
            for (int c = 0; c < 3; c++)
            {
                Assert.That(result.Motion.LocalPositions[c], Is.EqualTo(2.5 * source.Motion.LocalPositions[c]).Within(1e-4));
            }
        }

        [Test]
        public void AReferenceFrameOutsideTheFileIsRefused()
        {
            string input = WriteSource("walk.bvh");
            string output = Path.Combine(_dir, "out.bvh");
            (int code, string error) = Run("retarget", input, "--to", "model", "--out", output, "--model", _model, "--reference-frame", "40");
            Assert.That(code, Is.EqualTo(2));
            AssertOneLine(error, "--reference-frame 40", "0 to 39");
            Assert.That(File.Exists(output), Is.False);
        }
    }
}
