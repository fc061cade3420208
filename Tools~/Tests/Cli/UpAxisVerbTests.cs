using System;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Retargeting;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Issue 30 through the CLI, on BVH files written here: <c>retarget --up</c> on a Y-up skeleton in a Z-up world
    /// and on a Z-up rest skeleton gives the walk authored Y up; a wrong forced axis, a four-legged rig and hostile
    /// <c>--up</c> values (retarget, bake, score and score's manifest) are refused in one line with exit 2.
    /// </summary>
    public sealed class UpAxisVerbTests
    {
        private static readonly Skeleton Model = RetargetFixtures.Lafan1();
        private TempFolder _dir = null!;
        private string _model = "";

        [SetUp]
        public void SetUp()
        {
            _model = Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "LaFAN1Model", "DeltaInterpolator-LaFAN1.onnx");
            if (!File.Exists(_model)) Assert.Ignore("Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx absent; skipping.");
            _dir = new TempFolder();
            _dir.Write("map.json", RetargetFixtures.SourceMapJson(Model));
        }

        [TearDown]
        public void TearDown() => _dir?.Dispose();

        private string Write(string name, MotionClip motion)
        {
            var channels = new BvhChannel[motion.Skeleton.JointCount][];
            for (int j = 0; j < channels.Length; j++)
            {
                channels[j] = j == 0
                    ? new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation }
                    : new[] { BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation };
            }

            string path = _dir[name];
            BvhWriter.Write(new BvhAnimation(motion, channels, null, path), path);
            return path;
        }

        private static MotionClip Walk() => UpAxisFixtures.Walk(UpAxisFixtures.Standing(Model, QuaternionD.Identity), 120, 1.0 / 60.0);

        private MotionClip Retarget(string input, string up)
        {
            string output = _dir["model-" + Path.GetFileName(input) + "-" + up + ".bvh"];
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--map", _dir["map.json"], "--up", up, "--out", output, "--model", _model);
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain("up axis " + up), "the console says what was decided");
            return BvhReader.Read(output).Motion;
        }

        [TestCase("walk-z-world.bvh", "auto")]
        [TestCase("walk-z-world.bvh", "z")]
        [TestCase("walk-z-rest.bvh", "auto")]
        [TestCase("walk-z-rest.bvh", "z")]
        public void AZUpFileRetargetsAsTheWalkAuthoredYUp(string file, string up)
        {
            MotionClip walk = Walk();
            MotionClip expected = Retarget(Write("walk-y.bvh", walk), "auto");
            MotionClip zUp = file == "walk-z-world.bvh" ? UpAxisFixtures.InZUpWorld(walk) : UpAxisFixtures.OnZUpSkeleton(walk);
            MotionClip actual = Retarget(Write(file, zUp), up);
            Assert.That(actual.FrameCount, Is.EqualTo(expected.FrameCount));
            double worstAngle = 0, worstRoot = 0;
            for (int f = 0; f < expected.FrameCount; f++)
            {
                for (int j = 0; j < Model.JointCount; j++)
                {
                    worstAngle = Math.Max(worstAngle, RetargetFixtures.Angle(QuaternionD.Read(expected.LocalRotations, expected.RotationIndex(f, j)), QuaternionD.Read(actual.LocalRotations, actual.RotationIndex(f, j))));
                }

                worstRoot = Math.Max(worstRoot, (Vector3D.Read(expected.LocalPositions, expected.PositionIndex(f, 0)) - Vector3D.Read(actual.LocalPositions, actual.PositionIndex(f, 0))).Length);
            }

            TestContext.WriteLine($"{file} --up {up}: largest local-rotation difference {worstAngle:E2} rad, root {worstRoot:E2} model units (through BVH text at 6 decimals)");
            Assert.That(worstAngle, Is.LessThan(1e-4));
            Assert.That(worstRoot, Is.LessThan(1e-4));
        }

        [Test]
        public void ForcingYOnAZUpWorldIsRefusedNamingTheOption()
        {
            string input = Write("walk-z-world.bvh", UpAxisFixtures.InZUpWorld(Walk()));
            string output = _dir["out.bvh"];
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--map", _dir["map.json"], "--up", "y", "--out", output, "--model", _model);
            string line = CliHarness.AssertOneErrorLine(run, "lies down");
            Assert.That(line, Does.Contain("--up z"));
            Assert.That(File.Exists(output), Is.False, "nothing written");
        }

        [Test]
        public void AFourLeggedRigIsRefusedNamingItsBonesOnRetargetAndBake()
        {
            Skeleton dog = UpAxisFixtures.Quadruped(Model);
            var rotations = new double[dog.JointCount * 4 * 40];
            var positions = new double[dog.JointCount * 3 * 40];
            for (int f = 0; f < 40; f++)
            {
                for (int j = 0; j < dog.JointCount; j++)
                {
                    QuaternionD.Identity.Write(rotations, (f * dog.JointCount + j) * 4);
                    Vector3D o = Vector3D.Read(dog.OffsetSpan, 3 * j);
                    (j == 0 ? o + new Vector3D(0, 0, 2.0 * f) : o).Write(positions, (f * dog.JointCount + j) * 3);
                }
            }

            string input = Write("dog.bvh", new MotionClip(dog, 40, 1.0 / 30.0, positions, rotations));
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--map", _dir["map.json"], "--out", _dir["out.bvh"], "--model", _model);
            string line = CliHarness.AssertOneErrorLine(run, "src_Spine (Spine)");
            Assert.That(line, Does.StartWith(input + ": "));
            CliRun bake = CliHarness.Run("bake", input, "--every", "10", "--map", _dir["map.json"], "--out", _dir["baked.bvh"], "--model", _model);
            CliHarness.AssertOneErrorLine(bake, "src_Spine (Spine)");
        }

        /// <summary>The explicit override: the same four-legged rig is kept with --accept-reference-pose, and every output says which bones were accepted (retarget's console, bake's console and JSON, score's console); the refusal names the override.</summary>
        [Test]
        public void AcceptReferencePoseKeepsTheRigAndEveryOutputSaysSo()
        {
            Skeleton dog = UpAxisFixtures.Quadruped(Model);
            var rotations = new double[dog.JointCount * 4 * 40];
            var positions = new double[dog.JointCount * 3 * 40];
            for (int f = 0; f < 40; f++)
            {
                for (int j = 0; j < dog.JointCount; j++)
                {
                    QuaternionD.Identity.Write(rotations, (f * dog.JointCount + j) * 4);
                    Vector3D o = Vector3D.Read(dog.OffsetSpan, 3 * j);
                    (j == 0 ? o + new Vector3D(0, 0, 2.0 * f) : o).Write(positions, (f * dog.JointCount + j) * 3);
                }
            }

            string input = Write("dog.bvh", new MotionClip(dog, 40, 1.0 / 30.0, positions, rotations));
            string refusal = CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", input, "--to", "model", "--map", _dir["map.json"], "--out", _dir["out.bvh"], "--model", _model), "--accept-reference-pose");
            Assert.That(refusal, Does.Contain("--reference-frame"));
            Assert.That(refusal, Does.Contain("--map"));
            const string Accepted = "reference pose accepted by --accept-reference-pose";
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--map", _dir["map.json"], "--accept-reference-pose", "--out", _dir["out.bvh"], "--model", _model);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr + run.Stdout);
            Assert.That(OneLine(run.Stdout), Does.Contain(Accepted));
            Assert.That(OneLine(run.Stdout), Does.Contain("src_Spine (Spine)"));
            CliRun bake = CliHarness.Run("bake", input, "--every", "10", "--map", _dir["map.json"], "--accept-reference-pose", "--out", _dir["baked.bvh"], "--json", _dir["baked.json"], "--model", _model);
            Assert.That(bake.ExitCode, Is.EqualTo(0), bake.Stderr + bake.Stdout);
            Assert.That(OneLine(bake.Stdout), Does.Contain(Accepted));
            using (var json = System.Text.Json.JsonDocument.Parse(File.ReadAllText(_dir["baked.json"])))
            {
                Assert.That(json.RootElement.GetRawText(), Does.Contain(Accepted));
                Assert.That(json.RootElement.GetRawText(), Does.Contain("src_Spine (Spine)"));
            }

            _dir.Write("inbetween-data.json", "{\"defaults\": {\"map\": \"map.json\"}}");
            File.Delete(_dir["out.bvh"]);
            File.Delete(_dir["baked.bvh"]);
            CliRun score = CliHarness.Run("score", _dir.Path, "--every", "10", "--accept-reference-pose", "--json", _dir["score.json"], "--model", _model);
            Assert.That(score.ExitCode, Is.EqualTo(0), score.Stderr + score.Stdout);
            Assert.That(OneLine(score.Stdout), Does.Contain(Accepted));
            using (var json = System.Text.Json.JsonDocument.Parse(File.ReadAllText(_dir["score.json"])))
            {
                Assert.That(json.RootElement.GetProperty("accepted_reference_poses")[0].GetString(), Does.Contain(Accepted).And.Contain("src_Spine (Spine)"));
            }

            // The manifest's per-file key (prepare's reader takes the same): refused without it, kept and reported with it.
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", _dir.Path, "--every", "10", "--model", _model), "src_Spine (Spine)");
            _dir.Write("inbetween-data.json", "{\"defaults\": {\"map\": \"map.json\"}, \"files\": {\"dog.bvh\": {\"accept_reference_pose\": true}}}");
            CliRun manifest = CliHarness.Run("score", _dir.Path, "--every", "10", "--model", _model);
            Assert.That(manifest.ExitCode, Is.EqualTo(0), manifest.Stderr + manifest.Stdout);
            Assert.That(OneLine(manifest.Stdout), Does.Contain(Accepted));
        }

        // The console wraps at its width (80 columns when piped): the words are compared, not the line breaks.
        private static string OneLine(string text) => System.Text.RegularExpressions.Regex.Replace(text, @"\s+", " ");

        // A flag takes no value: System.CommandLine's own refusal (one line, exit 2, nothing written).
        [TestCase("maybe")]
        [TestCase("2")]
        [TestCase("\u001b[2J")]
        public void HostileAcceptReferencePoseValuesAreRefusedInOneLine(string value)
        {
            string input = Write("walk-y.bvh", Walk());
            CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", input, "--to", "model", "--accept-reference-pose", value, "--out", _dir["a.bvh"], "--model", _model), "expected");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--every", "10", "--accept-reference-pose", value, "--out", _dir["b.bvh"], "--model", _model), "expected");
            Assert.That(File.Exists(_dir["a.bvh"]) || File.Exists(_dir["b.bvh"]), Is.False);
        }

        /// <summary>--up is on the verbs that retarget and says so; info and check, which read only joints and offsets, take none (Documentation~/up-axis-keys-notes.md says why).</summary>
        [Test]
        public void UpIsOnTheVerbsThatRetargetAndTheHelpSaysWhichThoseAre()
        {
            foreach (string verb in new[] { "retarget", "bake", "score" })
            {
                CliRun help = CliHarness.Run(verb, "--help");
                Assert.That(OneLine(help.Stdout), Does.Contain("--up").And.Contain("Taken by the verbs that retarget (retarget, bake, score)"), verb);
                Assert.That(OneLine(help.Stdout), Does.Contain("--accept-reference-pose"), verb);
            }

            foreach (string verb in new[] { "info", "check" }) Assert.That(CliHarness.Run(verb, "--help").Stdout, Does.Not.Contain("--up"), verb);
        }

        [TestCase("x")]
        [TestCase("")]
        [TestCase("zz")]
        [TestCase("y\nz")]
        [TestCase("\u001b[2J")]
        public void HostileUpValuesAreRefusedInOneLine(string value)
        {
            string input = Write("walk-y.bvh", Walk());
            CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", input, "--to", "model", "--up", value, "--out", _dir["a.bvh"], "--model", _model), "--up");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--every", "10", "--up", value, "--out", _dir["b.bvh"], "--model", _model), "--up");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", _dir.Path, "--every", "10", "--up", value, "--model", _model), "--up");
            Assert.That(File.Exists(_dir["a.bvh"]) || File.Exists(_dir["b.bvh"]), Is.False);
        }

        [TestCase("\"yes\"")]
        [TestCase("1")]
        [TestCase("\"true\\u001b[2J\"")]
        public void AManifestsHostileAcceptReferencePoseIsRefusedInOneLine(string value)
        {
            Write("walk-y.bvh", Walk());
            _dir.Write("inbetween-data.json", "{\"defaults\": {\"accept_reference_pose\": " + value + "}}");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", _dir.Path, "--every", "10", "--model", _model), "\"accept_reference_pose\"");
        }

        [TestCase("\"x\"")]
        [TestCase("\"Z\"")]
        [TestCase("3")]
        [TestCase("\"z\\u001b[2J\"")]
        public void AManifestsHostileUpIsRefusedInOneLine(string value)
        {
            Write("walk-y.bvh", Walk());
            _dir.Write("inbetween-data.json", "{\"defaults\": {\"up\": " + value + "}}");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", _dir.Path, "--every", "10", "--model", _model), "\"up\"");
        }
    }
}
