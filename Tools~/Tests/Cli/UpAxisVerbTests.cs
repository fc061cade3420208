using System;
using System.IO;
using System.Linq;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Preview;
using DeltaInterpolator.Tests.Retargeting;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Issue 30 through the CLI, on BVH files written here: <c>retarget --up</c> on a Y-up skeleton in a Z-up world
    /// and on a Z-up rest skeleton gives the walk authored Y up; a wrong forced axis, a four-legged rig and hostile
    /// <c>--up</c> values (retarget, bake, score, preview, info and score's manifest) are refused in one line with exit 2.
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

        // A four-legged rig (humanoid names on a dog's bones) walking 40 frames along +Z in its rest pose, as dog.bvh.
        private string WriteWalkingQuadruped()
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

            return Write("dog.bvh", new MotionClip(dog, 40, 1.0 / 30.0, positions, rotations));
        }

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

        [TestCase("walk-z-world.bvh")]
        [TestCase("walk-z-rest.bvh")]
        public void ForcingYOnAZUpFileIsRefusedNamingTheOption(string file)
        {
            string input = Write(file, file == "walk-z-world.bvh" ? UpAxisFixtures.InZUpWorld(Walk()) : UpAxisFixtures.OnZUpSkeleton(Walk()));
            string output = _dir["out.bvh"];
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--map", _dir["map.json"], "--up", "y", "--out", output, "--model", _model);
            string line = CliHarness.AssertOneErrorLine(run, "lies down");
            Assert.That(line, Does.Contain("--up z"));
            Assert.That(File.Exists(output), Is.False, "nothing written");
        }

        [Test]
        public void AFourLeggedRigIsRefusedNamingItsBonesOnRetargetAndBake()
        {
            string input = WriteWalkingQuadruped();
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
            string input = WriteWalkingQuadruped();
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
        [TestCase("\u001b[2J", TestName = "{m}(ESC[2J)")] // a raw ESC in the name: filtered runs (--filter) would skip the case
        public void HostileAcceptReferencePoseValuesAreRefusedInOneLine(string value)
        {
            string input = Write("walk-y.bvh", Walk());
            CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", input, "--to", "model", "--accept-reference-pose", value, "--out", _dir["a.bvh"], "--model", _model), "expected");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--every", "10", "--accept-reference-pose", value, "--out", _dir["b.bvh"], "--model", _model), "expected");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", _dir.Path, "--every", "10", "--accept-reference-pose", value, "--json", _dir["s.json"], "--model", _model), "expected");
            Assert.That(File.Exists(_dir["a.bvh"]) || File.Exists(_dir["b.bvh"]) || File.Exists(_dir["s.json"]), Is.False);
        }

        /// <summary>
        /// --up is on every verb that reads a user's BVH motion (retarget, bake, score, preview, info) and the help names
        /// them; check, whose --skeleton compares only joint names and parents, takes none and the help says why.
        /// </summary>
        [Test]
        public void UpIsOnEveryVerbThatReadsMotionAndTheHelpSaysWhichThoseAre()
        {
            foreach (string verb in new[] { "retarget", "bake", "score", "preview", "info" })
            {
                CliRun help = CliHarness.Run(verb, "--help");
                Assert.That(OneLine(help.Stdout), Does.Contain("--up").And.Contain("Taken by every verb that reads a user's BVH motion: retarget, bake, score, preview"), verb);
            }

            foreach (string verb in new[] { "retarget", "bake", "score" }) Assert.That(OneLine(CliHarness.Run(verb, "--help").Stdout), Does.Contain("--accept-reference-pose"), verb);
            Assert.That(CliHarness.Run("check", "--help").Stdout, Does.Not.Contain("--up"));
        }

        /// <summary>The walk on a rig named as the model is (the built-in names find its body without a map).</summary>
        private static MotionClip ModelNamed(MotionClip clip)
        {
            Skeleton s = clip.Skeleton;
            var named = new Skeleton(Model.Names, s.Parents, s.Offsets.ToArray());
            return new MotionClip(named, clip.FrameCount, clip.FrameTime, clip.LocalPositions, clip.LocalRotations);
        }

        /// <summary>
        /// preview --up: a Y-up walk in a Z-up world and on a Z-up rest skeleton is drawn as the walk authored Y up (every
        /// joint's position within 1e-4 data units, the BVH text's 6 decimals through forward kinematics) with --up auto
        /// and --up z, found by --map or by the built-in names, and the console says what was decided; --up y draws
        /// the file as written (lying down) and says so.
        /// </summary>
        [TestCase("walk-z-world.bvh", "auto", true)]
        [TestCase("walk-z-world.bvh", "z", true)]
        [TestCase("walk-z-rest.bvh", "auto", true)]
        [TestCase("walk-z-rest.bvh", "z", true)]
        [TestCase("walk-z-world.bvh", "auto", false)]
        [TestCase("walk-z-rest.bvh", "z", false)]
        public void PreviewDrawsAZUpFileStandingAndSaysSo(string file, string up, bool withMap)
        {
            MotionClip walk = withMap ? Walk() : ModelNamed(Walk());
            MotionClip zUp = file == "walk-z-world.bvh" ? UpAxisFixtures.InZUpWorld(walk) : UpAxisFixtures.OnZUpSkeleton(walk);
            string yFile = Write("walk-y.bvh", walk), zFile = Write(file, zUp);
            JointMap? map = withMap ? JointMap.Load(_dir["map.json"]) : null;
            UpAxis axis = UpAxes.Parse(up)!.Value;
            PreviewScene expected = BvhPreview.Build(new[] { ("Y", yFile) }, null, Array.Empty<int>(), false, map, UpAxis.Auto);
            PreviewScene actual = BvhPreview.Build(new[] { ("Z", zFile) }, null, Array.Empty<int>(), false, map, axis);
            Assert.That(expected.UpAxisDescription, Does.Contain("drawn as written"), "the Y-up walk is not turned");
            Assert.That(actual.UpAxisDescription, Does.Contain("drawn turned to Y up"));
            double[] a = expected.Tracks[0].GlobalPositions, b = actual.Tracks[0].GlobalPositions;
            Assert.That(b.Length, Is.EqualTo(a.Length));
            double worst = 0;
            for (int i = 0; i < a.Length; i++) worst = Math.Max(worst, Math.Abs(a[i] - b[i]));
            TestContext.WriteLine($"{file} --up {up} ({(withMap ? "--map" : "built-in names")}): largest joint position difference {worst:E2} data units");
            Assert.That(worst, Is.LessThan(1e-4));

            var args = new System.Collections.Generic.List<string> { "preview", zFile, "--up", up, "--out", _dir["z.html"], "--force" };
            if (withMap) args.AddRange(new[] { "--map", _dir["map.json"] });
            CliRun run = CliHarness.Run(args.ToArray());
            CliHarness.AssertSuccess(run);
            Assert.That(OneLine(run.Stdout), Does.Contain($"up axis {up}: motion").And.Contain("drawn turned to Y up"));

            args[3] = "y";
            CliRun asWritten = CliHarness.Run(args.ToArray());
            CliHarness.AssertSuccess(asWritten);
            Assert.That(OneLine(asWritten.Stdout), Does.Contain("up axis y: motion Y-up"));
        }

        /// <summary>
        /// A Z-up file's bake is written in the file's own world (keys unchanged), so preview shows it beside its
        /// truth with one decision for both: drawn standing, the key frames' error zero.
        /// </summary>
        [Test]
        public void AZUpBakePreviewsStandingBesideItsTruth()
        {
            string truth = Write("walk-z-world.bvh", UpAxisFixtures.InZUpWorld(Walk()));
            string baked = _dir["baked.bvh"];
            CliHarness.AssertSuccess(CliHarness.Run("bake", truth, "--every", "20", "--map", _dir["map.json"], "--feet", "off", "--out", baked, "--model", _model));
            JointMap map = JointMap.Load(_dir["map.json"]);
            PreviewScene scene = BvhPreview.Build(new[] { ("Ground truth", truth), ("Baked", baked) }, null, new[] { 0, 20, 40 }, true, map, UpAxis.Auto);
            Assert.That(scene.UpAxisDescription, Does.Contain("drawn turned to Y up"));
            double[] error = scene.ErrorPerFrame(1);
            TestContext.WriteLine($"error at keys 0, 20, 40: {error[0]:E2}, {error[20]:E2}, {error[40]:E2}; mean between keys {scene.MeanErrorBetweenKeys(1):0.###} data units");
            foreach (int k in new[] { 0, 20, 40 }) Assert.That(error[k], Is.LessThan(1e-3), $"key {k}");
            double[] p = scene.Tracks[1].GlobalPositions;
            int head = Model.IndexOf("Head");
            Assert.That(p[3 * head + 1], Is.GreaterThan(p[1] + 10), "the baked figure stands: its head above its hips along Y");
        }

        /// <summary>info says what retarget and bake would decide about the file's up axis (and --up forces it).</summary>
        [Test]
        public void InfoSaysWhatTheUpAxisIsTakenToBe()
        {
            string zFile = Write("walk-z-world.bvh", UpAxisFixtures.InZUpWorld(ModelNamed(Walk())));
            CliRun run = CliHarness.Run("info", zFile);
            CliHarness.AssertSuccess(run);
            Assert.That(OneLine(run.Stdout), Does.Contain("up axis auto: motion Z-up").And.Contain("retarget and bake turn it to Y up"));
            CliRun forced = CliHarness.Run("info", zFile, "--up", "y");
            CliHarness.AssertSuccess(forced);
            Assert.That(OneLine(forced.Stdout), Does.Contain("up axis y: motion Y-up"));
            CliRun unnamed = CliHarness.Run("info", Write("walk-src.bvh", Walk()));
            CliHarness.AssertSuccess(unnamed);
            Assert.That(OneLine(unnamed.Stdout), Does.Contain("not judged"));
        }

        /// <summary>
        /// A 3ds Max Biped rig written as BVH, thighs under Bip01_Spine or under Bip01_Pelvis, retargets onto the model
        /// with no --map: the built-in map for its layout is detected and named on the console. Before the second
        /// Biped map the pelvis layout was refused ("'LeftUpLeg' maps to 'Bip01_L_Thigh', which is not below 'Bip01_Spine'").
        /// </summary>
        [TestCase("Bip01_Spine", "biped")]
        [TestCase("Bip01_Pelvis", "biped-pelvis")]
        public void ABipedRigRetargetsWithTheBuiltInMapOfItsLayout(string thighParent, string mapName)
        {
            Skeleton biped = BipedMapTests.BipedRig(Model, thighParent);
            int n = biped.JointCount, frames = 40;
            var positions = new double[frames * n * 3];
            var rotations = new double[frames * n * 4];
            for (int f = 0; f < frames; f++)
            {
                for (int j = 0; j < n; j++)
                {
                    Vector3D o = Vector3D.Read(biped.OffsetSpan, 3 * j);
                    (j == 0 ? o + new Vector3D(0, 0, 3.0 * f) : o).Write(positions, (f * n + j) * 3);
                    QuaternionD.Identity.Write(rotations, (f * n + j) * 4);
                }
            }

            string input = Write("biped-" + mapName + ".bvh", new MotionClip(biped, frames, 1.0 / 30.0, positions, rotations));
            string output = _dir["biped-on-model-" + mapName + ".bvh"];
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--out", output, "--model", _model);
            CliHarness.AssertSuccess(run);
            Assert.That(OneLine(run.Stdout), Does.Contain("'" + mapName + "'"), "the console names the map it used");
            Assert.That(BvhReader.Read(output).Skeleton.JointCount, Is.EqualTo(Model.JointCount));
        }

        [Test]
        public void PreviewUpZOnARigWithNoBodyToTurnByIsRefusedInOneLine()
        {
            string input = Write("walk-src.bvh", Walk());
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("preview", input, "--up", "z", "--out", _dir["p.html"]), "--up z");
            Assert.That(line, Does.StartWith(input + ": ").And.Contain("expected --map"));
            Assert.That(File.Exists(_dir["p.html"]), Is.False, "nothing written");
        }

        [TestCase("x")]
        [TestCase("")]
        [TestCase("zz")]
        [TestCase("y\nz")]
        [TestCase("\u001b[2J", TestName = "{m}(ESC[2J)")] // a raw ESC in the name: filtered runs (--filter) would skip the case
        public void HostileUpValuesAreRefusedInOneLine(string value)
        {
            string input = Write("walk-y.bvh", Walk());
            CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", input, "--to", "model", "--up", value, "--out", _dir["a.bvh"], "--model", _model), "--up");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--every", "10", "--up", value, "--out", _dir["b.bvh"], "--model", _model), "--up");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", _dir.Path, "--every", "10", "--up", value, "--model", _model), "--up");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", input, "--up", value, "--out", _dir["p.html"]), "--up");
            CliHarness.AssertOneErrorLine(CliHarness.Run("info", input, "--up", value), "--up");
            Assert.That(File.Exists(_dir["a.bvh"]) || File.Exists(_dir["b.bvh"]) || File.Exists(_dir["p.html"]), Is.False);
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
