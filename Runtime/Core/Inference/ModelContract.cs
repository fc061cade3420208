using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The model contract (Documentation~/model-contract.md) of one exported graph, as data: the skeleton,
    /// units, axes, delta modes, training ranges and network size the <c>deltainterp</c> metadata holds.
    /// Parsed once (<see cref="Parse"/>, <see cref="FromMetadata"/>), written back with
    /// <see cref="ToJson"/> (so an engine asset can keep it as a string), and checked by
    /// <see cref="ModelChecks"/>, which report every problem with a severity and a remedy. The throwing
    /// <see cref="Read(ModelDescription, ModelGraphKind)"/> refuses a model at its first error.
    /// Python mirror: <c>Training/Python~/deltainterp/contract.py</c>.
    /// </summary>
    public sealed class ModelContract
    {
        /// <summary>The contract version this runtime implements (Python: <c>CONTRACT_VERSION</c>).</summary>
        public const int Version = 2;

        /// <summary>Oldest contract version this runtime reads.</summary>
        public const int MinSupportedVersion = 1;

        /// <summary>Newest contract version this runtime reads.</summary>
        public const int MaxSupportedVersion = 2;

        /// <summary>Features per joint in <c>key_features</c>: local 6D rotation then global position.</summary>
        public const int FeaturesPerJoint = 9;

        /// <summary>The metadata fields this runtime reads; others are reported as information.</summary>
        private static readonly string[] KnownFields =
        {
            "contract_version", "name", "graph", "skeleton", "unit_scale", "up_axis", "facing_local_axis", "facing_target_axis",
            "rotation_6d", "quaternion_order", "output_delta_mode", "input_delta_mode", "training", "max_frame_index", "architecture",
        };

        private Vector3D _facingTargetAsWritten;

        private ModelContract(string source)
        {
            Source = source;
        }

        /// <summary>The model file or asset the contract was read from (used in every message).</summary>
        public string Source { get; }

        /// <summary>The contract version the model was exported with.</summary>
        public int ContractVersion { get; private set; }

        /// <summary>
        /// True from contract version 2: every graph input and output has a leading batch axis (one row per
        /// transition), so many characters' work runs in one call. Version 1 graphs run one transition at a time.
        /// </summary>
        public bool HasBatchAxis => ContractVersion >= 2;

        /// <summary>The model's name, e.g. <c>DeltaInterpolator-LaFAN1</c>.</summary>
        public string Name { get; private set; } = "";

        /// <summary>Which graph the file holds.</summary>
        public ModelGraphKind Graph { get; private set; }

        /// <summary>The skeleton the model was trained on (offsets in data units).</summary>
        public Skeleton Skeleton { get; private set; } = null!;

        /// <summary>Model units per data unit (LaFAN1: 0.01, centimetres to metres).</summary>
        public double UnitScale { get; private set; }

        /// <summary>The world's up axis (this runtime runs [0, 1, 0] only).</summary>
        public Vector3D UpAxis { get; private set; }

        /// <summary>The root's local axis that counts as "forward" (LaFAN1 hips: +Y).</summary>
        public Vector3D FacingLocalAxis { get; private set; }

        /// <summary>The world axis the last past key is turned to face (+X), normalized.</summary>
        public Vector3D FacingTargetAxis { get; private set; }

        /// <summary>The 6D rotation convention, <c>rows</c> (first two rows of the matrix).</summary>
        public string Rotation6D { get; private set; } = "";

        /// <summary>The quaternion order, <c>wxyz</c>.</summary>
        public string QuaternionOrder { get; private set; } = "";

        /// <summary>What the deltas are added to.</summary>
        public OutputDeltaMode OutputDeltaMode { get; private set; }

        /// <summary>What the key features are relative to (this runtime runs <see cref="Inference.InputDeltaMode.LastPose"/> only).</summary>
        public InputDeltaMode InputDeltaMode { get; private set; }

        /// <summary>Largest frame index the embeddings know (P + n ≤ this).</summary>
        public int MaxFrameIndex { get; private set; }

        /// <summary>True when the metadata holds the training ranges (<see cref="TrainingPastFrames"/> and the others).</summary>
        public bool HasTrainingRanges { get; private set; }

        /// <summary>Training range of past key frames [min, max]; (0, 0) when unknown.</summary>
        public (int Min, int Max) TrainingPastFrames { get; private set; }

        /// <summary>Training range of future (target) key frames [min, max]; (0, 0) when unknown.</summary>
        public (int Min, int Max) TrainingFutureFrames { get; private set; }

        /// <summary>Training range of gap lengths [min, max]; longer gaps run but were never seen. (0, 0) when unknown.</summary>
        public (int Min, int Max) TrainingMissingFrames { get; private set; }

        /// <summary>Frames per second of the training data (0 when unknown): the rate a request's frames are at.</summary>
        public double TrainingFps { get; private set; }

        /// <summary>The lowest <c>training.fps</c> a model may declare (frames per second).</summary>
        public const double MinTrainingFps = 1;

        /// <summary>The highest <c>training.fps</c> a model may declare (motion capture rarely exceeds 240 fps).</summary>
        public const double MaxTrainingFps = 1000;

        /// <summary>What the model was trained on, as the exporter wrote it ("" when unknown).</summary>
        public string TrainingData { get; private set; } = "";

        /// <summary>
        /// Frame rate motion is resampled to before inference, and key frames are counted and baked clips
        /// sampled at: <see cref="TrainingFps"/>, or <see cref="DefaultFramesPerSecond"/> when a model does not
        /// say. Decided here once, when the metadata is read (and reported as a check then); every front
        /// end and the playback read it from here and default nothing again.
        /// </summary>
        public double FramesPerSecond => TrainingFps > 0 ? TrainingFps : DefaultFramesPerSecond;

        /// <summary>The rate of a model whose metadata has no <c>training.fps</c>: LaFAN1's (and the shipped models'), 30.</summary>
        public const double DefaultFramesPerSecond = 30;

        /// <summary>Network size.</summary>
        public ModelArchitecture Architecture { get; private set; } = new ModelArchitecture(0, 0, 0, 0, 0, 0);

        /// <summary>The metadata JSON object as exported (for tools that pass it on, e.g. the speed harness).</summary>
        public string DescriptionJson { get; private set; } = "";

        /// <summary>Number of joints J.</summary>
        public int JointCount => Skeleton.JointCount;

        /// <summary>Size of one key token's features, 9·J.</summary>
        public int KeyFeatureSize => FeaturesPerJoint * JointCount;

        /// <summary>
        /// Largest P + n a request may have: the metadata's <see cref="MaxFrameIndex"/>, and never past the
        /// last row of the embedding tables.
        /// </summary>
        public int LargestFrameIndex => Architecture.EmbeddingSize > 0 ? Math.Min(MaxFrameIndex, Architecture.EmbeddingSize - 1) : MaxFrameIndex;

        /// <summary>
        /// Reads and checks the contract of a loaded graph (<see cref="ModelChecks.Model"/>) and refuses it
        /// at the first error.
        /// </summary>
        /// <param name="model">What the backend reports about the graph.</param>
        /// <param name="expected">The graph kind the caller is loading (whole, keys or frame).</param>
        /// <exception cref="ModelContractException">Anything does not fit; the message names it.</exception>
        public static ModelContract Read(ModelDescription model, ModelGraphKind expected)
        {
            var report = new ModelCheckReport();
            ModelContract? contract = ModelChecks.Model(model, expected, report);
            report.ThrowIfErrors();
            return contract!;
        }

        /// <summary>
        /// Builds the contract from a model's <c>metadata_props</c>: the <c>deltainterp</c> JSON object and
        /// the <c>contract_version</c> string. Problems go to <paramref name="report"/>.
        /// </summary>
        /// <returns>The contract, or null when the metadata is missing or not a JSON object with a readable skeleton.</returns>
        public static ModelContract? FromMetadata(string source, IReadOnlyDictionary<string, string> metadata, ModelCheckReport report)
        {
            if (metadata == null) throw new ArgumentNullException(nameof(metadata));
            if (report == null) throw new ArgumentNullException(nameof(report));
            source ??= "<model>";
            if (!metadata.TryGetValue(TensorNames.DescriptionMetadata, out string? json) || string.IsNullOrWhiteSpace(json))
            {
                report.Error(source, "the model has no 'deltainterp' metadata",
                    $"expected an ONNX file written by `python3 -m deltainterp export` (contract version {Version}); export the checkpoint again");
                return null;
            }

            if (metadata.TryGetValue(TensorNames.ContractVersionMetadata, out string? versionText))
            {
                if (!int.TryParse(versionText, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v))
                {
                    report.Error(source, $"metadata contract_version is '{versionText}'", "expected an integer such as \"1\"");
                }
                else
                {
                    CheckVersion(source, v, report);
                }
            }

            // The JSON repeats the version: report a problem found in both places once.
            var inner = new ModelCheckReport();
            ModelContract? contract = Parse(json, source, inner);
            foreach (ModelCheck c in inner)
            {
                if (!report.Contains(c.Severity, c.Message)) report.Add(c);
            }

            if (contract != null && metadata.TryGetValue(TensorNames.ContractVersionMetadata, out versionText) &&
                int.TryParse(versionText, NumberStyles.Integer, CultureInfo.InvariantCulture, out int declared) && declared != contract.ContractVersion)
            {
                report.Error(source, $"metadata contract_version is {declared} but the 'deltainterp' object says {contract.ContractVersion}",
                    "expected both to agree; export the checkpoint again");
            }

            return contract;
        }

        /// <summary>
        /// Builds the contract from the <c>deltainterp</c> JSON object (as exported, or as written by
        /// <see cref="ToJson"/>). Every missing or unsupported field is reported; parsing goes on after
        /// each, so the report lists them all.
        /// </summary>
        /// <returns>The contract, or null when <paramref name="json"/> is not a JSON object with a readable skeleton.</returns>
        public static ModelContract? Parse(string json, string source, ModelCheckReport report)
        {
            if (report == null) throw new ArgumentNullException(nameof(report));
            source ??= "<model>";
            JsonValue root;
            try
            {
                root = JsonValue.Parse(json ?? "", source + " metadata 'deltainterp'");
                root.ExpectObject("the 'deltainterp' metadata");
            }
            catch (DataFormatException e)
            {
                report.Error(source, "the 'deltainterp' metadata is not a valid JSON object (" + e.Problem + ")", "expected the JSON object the exporter writes; export the checkpoint again");
                return null;
            }

            var contract = new ModelContract(source) { DescriptionJson = json! };
            return contract.ReadDescription(root.ExpectObject("the 'deltainterp' metadata"), report) ? contract : null;
        }

        /// <summary>
        /// <see cref="Parse"/> that throws at the first error: for an engine asset that stored
        /// <see cref="ToJson"/> at import time and rebuilds the contract when loaded.
        /// </summary>
        /// <exception cref="ModelContractException">The JSON is not a valid contract.</exception>
        public static ModelContract FromJson(string json, string source)
        {
            var report = new ModelCheckReport();
            ModelContract? c = Parse(json, source, report);
            report.ThrowIfErrors();
            return c!;
        }

        /// <summary>
        /// The contract as the <c>deltainterp</c> JSON object, every field this runtime reads in the
        /// exporter's order (numbers round-trip exactly): <see cref="Parse"/> of it gives an equal contract.
        /// </summary>
        public string ToJson()
        {
            var b = new StringBuilder(4096);
            b.Append('{');
            Key(b, "contract_version", true).Append(ContractVersion.ToString(CultureInfo.InvariantCulture));
            Key(b, "name").Append(Quote(Name));
            Key(b, "graph").Append(Quote(GraphName(Graph)));
            Key(b, "skeleton").Append("{\"names\": [");
            for (int j = 0; j < JointCount; j++) b.Append(j > 0 ? ", " : "").Append(Quote(Skeleton.Names[j]));
            b.Append("], \"parents\": [");
            for (int j = 0; j < JointCount; j++) b.Append(j > 0 ? ", " : "").Append(Skeleton.Parents[j].ToString(CultureInfo.InvariantCulture));
            b.Append("], \"offsets\": [");
            for (int j = 0; j < JointCount; j++)
            {
                b.Append(j > 0 ? ", " : "").Append('[').Append(Fmt(Skeleton.Offsets[3 * j])).Append(", ").Append(Fmt(Skeleton.Offsets[3 * j + 1])).Append(", ").Append(Fmt(Skeleton.Offsets[3 * j + 2])).Append(']');
            }

            b.Append("]}");
            Key(b, "unit_scale").Append(Fmt(UnitScale));
            Key(b, "up_axis").Append(Vector(UpAxis));
            Key(b, "facing_local_axis").Append(Vector(FacingLocalAxis));
            Key(b, "facing_target_axis").Append(Vector(_facingTargetAsWritten));
            Key(b, "rotation_6d").Append(Quote(Rotation6D));
            Key(b, "quaternion_order").Append(Quote(QuaternionOrder));
            Key(b, "output_delta_mode").Append(Quote(OutputDeltaMode == OutputDeltaMode.Slerp ? "slerp" : OutputDeltaMode == OutputDeltaMode.LastPose ? "last_pose" : "none"));
            Key(b, "input_delta_mode").Append(Quote(InputDeltaMode == InputDeltaMode.LastPose ? "last_pose" : "none"));
            if (HasTrainingRanges)
            {
                Key(b, "training").Append('{');
                Key(b, "past_frames", true).Append(Range(TrainingPastFrames));
                Key(b, "future_frames").Append(Range(TrainingFutureFrames));
                Key(b, "missing_frames").Append(Range(TrainingMissingFrames));
                Key(b, "fps").Append(Fmt(TrainingFps));
                if (TrainingData.Length > 0) Key(b, "data").Append(Quote(TrainingData));
                b.Append('}');
            }

            Key(b, "max_frame_index").Append(MaxFrameIndex.ToString(CultureInfo.InvariantCulture));
            ModelArchitecture a = Architecture;
            Key(b, "architecture").Append('{');
            Key(b, "width", true).Append(a.Width.ToString(CultureInfo.InvariantCulture));
            Key(b, "blocks").Append(a.Blocks.ToString(CultureInfo.InvariantCulture));
            Key(b, "heads").Append(a.Heads.ToString(CultureInfo.InvariantCulture));
            Key(b, "embedding_dim").Append(a.EmbeddingDim.ToString(CultureInfo.InvariantCulture));
            Key(b, "embedding_size").Append(a.EmbeddingSize.ToString(CultureInfo.InvariantCulture));
            Key(b, "parameters").Append(a.Parameters.ToString(CultureInfo.InvariantCulture));
            b.Append("}}");
            return b.ToString();
        }

        /// <summary>
        /// This contract as the metadata of another graph of the same export (only <see cref="Graph"/>
        /// differs): an engine asset stores the whole graph's contract once, and each graph's backend
        /// describes itself with it.
        /// </summary>
        public ModelContract ForGraph(ModelGraphKind graph)
        {
            var copy = (ModelContract)MemberwiseClone();
            copy.Graph = graph;
            return copy;
        }

        /// <summary>
        /// The <c>metadata_props</c> an exported graph carries for this contract (<c>contract_version</c> and
        /// <c>deltainterp</c> = <see cref="ToJson"/>): what a backend whose engine keeps no ONNX metadata (Sentis)
        /// passes in its <see cref="ModelDescription"/> when the contract was stored in an asset at import.
        /// </summary>
        public IReadOnlyDictionary<string, string> ToMetadata() => new Dictionary<string, string>(StringComparer.Ordinal)
        {
            [TensorNames.ContractVersionMetadata] = ContractVersion.ToString(CultureInfo.InvariantCulture),
            [TensorNames.DescriptionMetadata] = ToJson(),
        };

        /// <summary>
        /// Checks that poses given on <paramref name="skeleton"/> can be fed to this model
        /// (<see cref="ModelChecks.Skeleton"/>) and throws at the first error.
        /// </summary>
        /// <param name="skeleton">The skeleton of the request (e.g. a BVH file's or a character's).</param>
        /// <param name="skeletonSource">Where the skeleton came from, for the message.</param>
        /// <exception cref="ModelContractException">The skeletons differ; the message names the first difference.</exception>
        public void CheckSkeleton(Skeleton skeleton, string skeletonSource)
        {
            var report = new ModelCheckReport();
            ModelChecks.Skeleton(this, skeleton, skeletonSource, report);
            report.ThrowIfErrors();
        }

        /// <summary>
        /// Checks the constant outputs a graph computes (<see cref="ModelChecks.Constants"/>) and throws
        /// at the first error; a backend that runs the graph reads them once at load time.
        /// </summary>
        /// <exception cref="ModelContractException">They disagree.</exception>
        public void CheckConstants(long contractVersion, long jointCount, long keyFeatureSize)
        {
            var report = new ModelCheckReport();
            ModelChecks.Constants(this, contractVersion, jointCount, keyFeatureSize, report);
            report.ThrowIfErrors();
        }

        /// <summary>
        /// Checks that another graph of the same export describes the same network
        /// (<see cref="ModelChecks.SameExport"/>) and throws at the first error.
        /// </summary>
        /// <exception cref="ModelContractException">They differ: the files come from different exports.</exception>
        public void CheckSameExport(ModelContract other)
        {
            var report = new ModelCheckReport();
            ModelChecks.SameExport(this, other, report);
            report.ThrowIfErrors();
        }

        internal static void CheckVersion(string src, int version, ModelCheckReport report)
        {
            if (version < MinSupportedVersion || version > MaxSupportedVersion)
            {
                string what = version > MaxSupportedVersion
                    ? "update the package, or export the model with a trainer of the matching version"
                    : "export the checkpoint again with the current trainer";
                report.Error(src, $"the model has contract version {version}", $"expected a version from {MinSupportedVersion} to {MaxSupportedVersion}; {what}");
            }
        }

        /// <summary>The graph's name as the contract and messages write it ("whole", "keys", "frame").</summary>
        public static string GraphName(ModelGraphKind kind) => kind.ToString().ToLowerInvariant();

        /// <returns>False when no usable contract can be built (no readable skeleton).</returns>
        private bool ReadDescription(IReadOnlyDictionary<string, JsonValue> m, ModelCheckReport report)
        {
            var fields = new Fields(Source, m, report);
            int version = fields.Int("contract_version", "contract_version", -1);
            if (version >= 0) CheckVersion(Source, version, report);
            ContractVersion = version;
            Name = m.TryGetValue("name", out JsonValue? name) ? fields.Guard(() => name.ExpectString("name"), "") : "";

            string graph = fields.String("graph", "graph", "");
            switch (graph)
            {
                case "whole": Graph = ModelGraphKind.Whole; break;
                case "keys": Graph = ModelGraphKind.Keys; break;
                case "frame": Graph = ModelGraphKind.Frame; break;
                case "": break;
                default: report.Error(Source, $"metadata graph is '{graph}'", "expected \"whole\", \"keys\" or \"frame\""); break;
            }

            bool usable = ReadSkeleton(fields, report);

            UnitScale = fields.Number("unit_scale", "unit_scale", 1);
            if (!(UnitScale > 0) || double.IsInfinity(UnitScale))
            {
                report.Error(Source, $"metadata unit_scale is {Fmt(UnitScale)}", "expected a positive number of model units per data unit (LaFAN1: 0.01)");
            }

            UpAxis = fields.Axis("up_axis", new Vector3D(0, 1, 0));
            if (UpAxis.X != 0 || UpAxis.Y != 1 || UpAxis.Z != 0)
            {
                report.Error(Source, $"metadata up_axis is {UpAxis}", "expected [0, 1, 0]: this runtime implements Y-up model space only");
            }

            FacingLocalAxis = fields.Axis("facing_local_axis", new Vector3D(0, 1, 0));
            _facingTargetAsWritten = fields.Axis("facing_target_axis", new Vector3D(1, 0, 0));
            FacingTargetAxis = _facingTargetAsWritten;
            if (FacingTargetAxis.Y != 0 || FacingTargetAxis.Length == 0)
            {
                report.Error(Source, $"metadata facing_target_axis is {FacingTargetAxis}", "expected a horizontal axis such as [1, 0, 0]");
            }
            else
            {
                FacingTargetAxis = (1.0 / FacingTargetAxis.Length) * FacingTargetAxis;
            }

            Rotation6D = fields.Convention("rotation_6d", "rows", "this runtime decodes 6D rotations as the first two rows of the matrix");
            QuaternionOrder = fields.Convention("quaternion_order", "wxyz", "this runtime reads quaternions as (w, x, y, z)");

            string output = fields.String("output_delta_mode", "output_delta_mode", "slerp");
            switch (output)
            {
                case "slerp": OutputDeltaMode = OutputDeltaMode.Slerp; break;
                case "last_pose": OutputDeltaMode = OutputDeltaMode.LastPose; break;
                case "none": OutputDeltaMode = OutputDeltaMode.None; break;
                default: report.Error(Source, $"metadata output_delta_mode is '{output}'", "expected \"slerp\", \"last_pose\" or \"none\""); break;
            }

            string input = fields.String("input_delta_mode", "input_delta_mode", "last_pose");
            if (input == "none")
            {
                InputDeltaMode = InputDeltaMode.None;
                report.Error(Source, "the model uses input delta mode 'none' (an ablation with a query_features input)",
                    "expected input delta mode 'last_pose'; this runtime does not run ablation models — train with the default --input-delta-mode");
            }
            else if (input != "last_pose")
            {
                report.Error(Source, $"metadata input_delta_mode is '{input}'", "expected \"last_pose\"");
            }

            MaxFrameIndex = m.ContainsKey("max_frame_index") ? fields.Int("max_frame_index", "max_frame_index", 255) : 255;
            if (m.TryGetValue("training", out JsonValue? training) && training.Kind == JsonKind.Object)
            {
                IReadOnlyDictionary<string, JsonValue> t = training.ExpectObject("training");
                var tf = new Fields(Source, t, report, "training.");
                HasTrainingRanges = true;
                TrainingPastFrames = tf.Range("past_frames");
                TrainingFutureFrames = tf.Range("future_frames");
                TrainingMissingFrames = tf.Range("missing_frames");
                TrainingFps = t.ContainsKey("fps") ? tf.Number("fps", "training.fps", 0) : 0;
                if (t.ContainsKey("fps") && !(TrainingFps >= MinTrainingFps && TrainingFps <= MaxTrainingFps))
                {
                    // Retargeting resamples to this rate: 1e6 fps would turn a 7.5 s clip into 7.5 M frames.
                    report.Error(Source, $"metadata training.fps is {Fmt(TrainingFps)}",
                        $"expected a frame rate from {Fmt(MinTrainingFps)} to {Fmt(MaxTrainingFps)} fps (LaFAN1 and the shipped models: 30); export the checkpoint again");
                    TrainingFps = 0;
                }
                if (!t.ContainsKey("fps"))
                {
                    report.Info(Source, $"the metadata has no training.fps: its motion is taken at {Fmt(DefaultFramesPerSecond)} fps (LaFAN1's)",
                        "export the checkpoint again with a newer exporter if the model was trained at another rate");
                }

                TrainingData = t.TryGetValue("data", out JsonValue? data) ? tf.Guard(() => data.ExpectString("training.data"), "") : "";
            }
            else if (training != null)
            {
                report.Error(Source, "metadata training is not an object", "expected {\"past_frames\": [min, max], \"missing_frames\": [min, max], ...}; export the checkpoint again");
            }
            else
            {
                report.Info(Source, $"the metadata has no training ranges and no training.fps (its motion is taken at {Fmt(DefaultFramesPerSecond)} fps, LaFAN1's)", "requests are not checked against the past-frame and gap lengths the model was trained on; a newer exporter writes them");
            }

            if (m.TryGetValue("architecture", out JsonValue? archValue))
            {
                IReadOnlyDictionary<string, JsonValue>? a = fields.Guard(() => archValue.ExpectObject("architecture"), null);
                if (a != null)
                {
                    var af = new Fields(Source, a, report, "architecture.");
                    Architecture = new ModelArchitecture(
                        af.Int("width", "architecture.width", 0), af.Int("blocks", "architecture.blocks", 0), af.Int("heads", "architecture.heads", 0),
                        af.Int("embedding_dim", "architecture.embedding_dim", 0), af.Int("embedding_size", "architecture.embedding_size", 0),
                        a.TryGetValue("parameters", out JsonValue? p) ? (long)af.Guard(() => p.ExpectNumber("architecture.parameters"), 0) : 0);
                }
            }
            else
            {
                fields.Missing("architecture");
            }

            var unknown = new List<string>();
            foreach (string key in m.Keys)
            {
                if (Array.IndexOf(KnownFields, key) < 0) unknown.Add(key);
            }

            if (unknown.Count > 0)
            {
                report.Info(Source, "the metadata has fields this runtime does not read: " + string.Join(", ", unknown), "nothing to do unless the model's documentation says they matter");
            }

            return usable;
        }

        private bool ReadSkeleton(Fields fields, ModelCheckReport report)
        {
            IReadOnlyDictionary<string, JsonValue>? s = fields.Object("skeleton");
            if (s == null) return false;
            var sf = new Fields(Source, s, report, "skeleton.");
            IReadOnlyList<JsonValue>? namesJson = sf.Array("names");
            IReadOnlyList<JsonValue>? parentsJson = sf.Array("parents");
            IReadOnlyList<JsonValue>? offsetsJson = sf.Array("offsets");
            if (namesJson == null || parentsJson == null || offsetsJson == null) return false;
            if (parentsJson.Count != namesJson.Count || offsetsJson.Count != namesJson.Count)
            {
                report.Error(Source, $"metadata skeleton has {namesJson.Count} names, {parentsJson.Count} parents and {offsetsJson.Count} offsets",
                    "expected one parent and one offset [x, y, z] per joint; export the checkpoint again");
                return false;
            }

            int before = report.Count;
            var names = new string[namesJson.Count];
            var parents = new int[namesJson.Count];
            var offsets = new double[3 * namesJson.Count];
            for (int j = 0; j < names.Length; j++)
            {
                int joint = j;
                names[j] = sf.Guard(() => namesJson[joint].ExpectString($"skeleton.names[{joint}]"), "");
                parents[j] = (int)sf.Guard(() => parentsJson[joint].ExpectNumber($"skeleton.parents[{joint}]"), -1);
                double[] o = sf.Guard(() => offsetsJson[joint].ExpectNumbers($"skeleton.offsets[{joint}]", 3), new double[3]);
                offsets[3 * j] = o[0];
                offsets[3 * j + 1] = o[1];
                offsets[3 * j + 2] = o[2];
            }

            if (report.Count > before) return false;
            try
            {
                Skeleton = new Skeleton(names, parents, offsets);
                return true;
            }
            catch (ArgumentException e)
            {
                report.Error(Source, "metadata 'deltainterp' holds an invalid skeleton (" + e.Message + ")", "expected the skeleton of the training data; export the checkpoint again");
                return false;
            }
        }

        private static StringBuilder Key(StringBuilder b, string key, bool first = false) => b.Append(first ? "" : ", ").Append('"').Append(key).Append("\": ");

        private static string Vector(Vector3D v) => "[" + Fmt(v.X) + ", " + Fmt(v.Y) + ", " + Fmt(v.Z) + "]";

        private static string Range((int Min, int Max) r) => "[" + r.Min.ToString(CultureInfo.InvariantCulture) + ", " + r.Max.ToString(CultureInfo.InvariantCulture) + "]";

        private static string Quote(string s)
        {
            var b = new StringBuilder(s.Length + 2);
            b.Append('"');
            foreach (char c in s)
            {
                switch (c)
                {
                    case '"': b.Append("\\\""); break;
                    case '\\': b.Append("\\\\"); break;
                    case '\n': b.Append("\\n"); break;
                    case '\r': b.Append("\\r"); break;
                    case '\t': b.Append("\\t"); break;
                    default:
                        if (c < 0x20) b.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                        else b.Append(c);
                        break;
                }
            }

            return b.Append('"').ToString();
        }

        internal static string Fmt(double v) => v.ToString("R", CultureInfo.InvariantCulture);

        /// <summary>Reads members of one JSON object, reporting a missing or mistyped member as an error and returning a fallback.</summary>
        private sealed class Fields
        {
            private readonly string _source;
            private readonly IReadOnlyDictionary<string, JsonValue> _obj;
            private readonly ModelCheckReport _report;
            private readonly string _prefix;

            public Fields(string source, IReadOnlyDictionary<string, JsonValue> obj, ModelCheckReport report, string prefix = "")
            {
                _source = source;
                _obj = obj;
                _report = report;
                _prefix = prefix;
            }

            public void Missing(string key)
            {
                _report.Error(_source, $"metadata 'deltainterp' has no \"{_prefix}{key}\"",
                    $"expected every field of contract version {Version} (Documentation~/model-contract.md); export the checkpoint again");
            }

            public T Guard<T>(Func<T> read, T fallback)
            {
                try
                {
                    return read();
                }
                catch (DataFormatException e)
                {
                    _report.Error(_source, "metadata 'deltainterp': " + e.Problem, e.Expected);
                    return fallback;
                }
            }

            public JsonValue? Member(string key)
            {
                if (_obj.TryGetValue(key, out JsonValue? v)) return v;
                Missing(key);
                return null;
            }

            public double Number(string key, string what, double fallback)
            {
                JsonValue? v = Member(key);
                return v == null ? fallback : Guard(() => v.ExpectNumber(what), fallback);
            }

            public int Int(string key, string what, int fallback) => (int)Number(key, what, fallback);

            public string String(string key, string what, string fallback)
            {
                JsonValue? v = Member(key);
                return v == null ? fallback : Guard(() => v.ExpectString(what), fallback);
            }

            public IReadOnlyDictionary<string, JsonValue>? Object(string key)
            {
                JsonValue? v = Member(key);
                return v == null ? null : Guard(() => v.ExpectObject(_prefix + key), null);
            }

            public IReadOnlyList<JsonValue>? Array(string key)
            {
                JsonValue? v = Member(key);
                return v == null ? null : Guard(() => v.ExpectArray(_prefix + key), null);
            }

            public Vector3D Axis(string key, Vector3D fallback)
            {
                JsonValue? v = Member(key);
                if (v == null) return fallback;
                double[]? a = Guard(() => v.ExpectNumbers(_prefix + key, 3), null);
                return a == null ? fallback : new Vector3D(a[0], a[1], a[2]);
            }

            public string Convention(string key, string value, string why)
            {
                string actual = String(key, key, value);
                if (!string.Equals(actual, value, StringComparison.Ordinal))
                {
                    _report.Error(_source, $"metadata {key} is '{actual}'", $"expected \"{value}\": {why}");
                }

                return actual;
            }

            public (int, int) Range(string key)
            {
                if (!_obj.TryGetValue(key, out JsonValue? v)) return (0, 0);
                double[]? r = Guard(() => v.ExpectNumbers(_prefix + key, 2), null);
                return r == null ? (0, 0) : ((int)r[0], (int)r[1]);
            }
        }
    }
}
