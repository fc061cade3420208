using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>Tests/Fixtures~ (written by `python3 -m deltainterp fixtures --out Tests/Fixtures~`) and its golden vectors.</summary>
    public static class Fixtures
    {
        /// <summary>The fixtures folder; fails the test with what to run when it is missing.</summary>
        public static string Directory
        {
            get
            {
                string? dir = AppContext.BaseDirectory;
                while (dir != null)
                {
                    string candidate = Path.Combine(dir, "Tests", "Fixtures~");
                    if (File.Exists(Path.Combine(candidate, "golden.json"))) return candidate;
                    dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
                }

                Assert.Fail("Tests/Fixtures~/golden.json not found above " + AppContext.BaseDirectory + "; run `PYTHONPATH=Training/Python~ python3 -m deltainterp fixtures --out Tests/Fixtures~`");
                return "";
            }
        }

        /// <summary>Tests/Fixtures~/tiny-model.onnx.</summary>
        public static string TinyModel => Path.Combine(Directory, "tiny-model.onnx");

        /// <summary>Tests/Fixtures~/tiny-model-contacts.onnx: the tiny network with a contact head (contract version 3).</summary>
        public static string TinyContactModel => Path.Combine(Directory, "tiny-model-contacts.onnx");

        /// <summary>The golden cases.</summary>
        public static IReadOnlyList<GoldenCase> Golden => s_golden ??= Read("golden.json");

        /// <summary>The golden cases of <see cref="TinyContactModel"/>, whose outputs include <c>foot_contacts</c>.</summary>
        public static IReadOnlyList<GoldenCase> GoldenContacts => s_goldenContacts ??= Read("golden-contacts.json");

        private static List<GoldenCase> Read(string name)
        {
            string path = Path.Combine(Directory, name);
            JsonValue doc = JsonValue.Parse(File.ReadAllText(path), path);
            var cases = new List<GoldenCase>();
            foreach (JsonValue c in doc.ExpectMember("cases").ExpectArray("cases")) cases.Add(new GoldenCase(c));
            return cases;
        }

        private static List<GoldenCase>? s_golden, s_goldenContacts;
    }

    /// <summary>One golden case: a request, the PyTorch pipeline's intermediate values and its result.</summary>
    public sealed class GoldenCase
    {
        internal GoldenCase(JsonValue c)
        {
            Name = c.ExpectMember("name").ExpectString("name");
            PastFrames = (int)c.ExpectMember("past_frames").ExpectNumber("past_frames");
            MissingFrames = (int)c.ExpectMember("gap").ExpectNumber("gap");   // n; the fixture's field keeps the exporter's name
            PastRootPositions = Flatten(c.ExpectMember("past_root_positions"));
            PastLocalQuaternions = Flatten(c.ExpectMember("past_local_quaternions"));
            TargetRootPosition = Flatten(c.ExpectMember("target_root_position"));
            TargetLocalQuaternions = Flatten(c.ExpectMember("target_local_quaternions"));
            JsonValue loc = c.ExpectMember("localization");
            Yaw = Flatten(loc.ExpectMember("yaw"));
            Origin = Flatten(loc.ExpectMember("origin"));
            JsonValue inputs = c.ExpectMember("inputs");
            KeyFeatures = Flatten(inputs.ExpectMember("key_features"));
            KeyFrameIndices = Flatten(inputs.ExpectMember("key_frame_indices"));
            QueryFrameIndices = Flatten(inputs.ExpectMember("query_frame_indices"));
            GapLength = Flatten(inputs.ExpectMember("gap_length"));
            JsonValue outputs = c.ExpectMember("outputs");
            RootPositionDelta = Flatten(outputs.ExpectMember("root_position_delta"));
            Rotation6DDelta = Flatten(outputs.ExpectMember("rotation_6d_delta"));
            FootContacts = outputs.ExpectObject("outputs").TryGetValue("foot_contacts", out JsonValue? contacts) ? Flatten(contacts) : null;
            JsonValue result = c.ExpectMember("result");
            RootPositions = Flatten(result.ExpectMember("root_positions"));
            LocalQuaternions = Flatten(result.ExpectMember("local_quaternions"));
            GlobalPositions = Flatten(result.ExpectMember("global_positions"));
        }

        public string Name { get; }
        public int PastFrames { get; }
        public int MissingFrames { get; }
        public double[] PastRootPositions { get; }
        public double[] PastLocalQuaternions { get; }
        public double[] TargetRootPosition { get; }
        public double[] TargetLocalQuaternions { get; }
        public double[] Yaw { get; }
        public double[] Origin { get; }
        public double[] KeyFeatures { get; }
        public double[] KeyFrameIndices { get; }
        public double[] QueryFrameIndices { get; }
        public double[] GapLength { get; }
        public double[] RootPositionDelta { get; }
        public double[] Rotation6DDelta { get; }

        /// <summary>The graph's <c>foot_contacts</c> (n × 4), or null for a model without them.</summary>
        public double[]? FootContacts { get; }
        public double[] RootPositions { get; }
        public double[] LocalQuaternions { get; }
        public double[] GlobalPositions { get; }

        /// <summary>A transition on <paramref name="skeleton"/> holding this case's keys.</summary>
        public Transition ToTransition(Skeleton skeleton)
        {
            var t = new Transition(skeleton, PastFrames, MissingFrames);
            Array.Copy(PastRootPositions, t.KeyRootPositions, PastRootPositions.Length);
            Array.Copy(TargetRootPosition, 0, t.KeyRootPositions, PastFrames * 3, 3);
            Array.Copy(PastLocalQuaternions, t.KeyLocalRotations, PastLocalQuaternions.Length);
            Array.Copy(TargetLocalQuaternions, 0, t.KeyLocalRotations, PastLocalQuaternions.Length, TargetLocalQuaternions.Length);
            return t;
        }

        public override string ToString() => Name;

        private static double[] Flatten(JsonValue v)
        {
            var list = new List<double>();
            Add(v, list);
            return list.ToArray();
        }

        private static void Add(JsonValue v, List<double> into)
        {
            if (v.Kind == JsonKind.Number)
            {
                into.Add(v.ExpectNumber("value"));
                return;
            }

            foreach (JsonValue item in v.ExpectArray("values")) Add(item, into);
        }
    }
}
