using System;
using System.Collections.Generic;
using System.Globalization;
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
    public sealed partial class ModelContract
    {
        /// <summary>The contract version this runtime implements (Python: <c>CONTRACT_VERSION</c>).</summary>
        public const int Version = 3;

        /// <summary>Oldest contract version this runtime reads.</summary>
        public const int MinSupportedVersion = 1;

        /// <summary>Newest contract version this runtime reads.</summary>
        public const int MaxSupportedVersion = 3;

        /// <summary>Features per joint in <c>key_features</c>: local 6D rotation then global position.</summary>
        public const int FeaturesPerJoint = 9;

        /// <summary>The metadata fields this runtime reads; others are reported as information.</summary>
        private static readonly string[] KnownFields =
        {
            "contract_version", "name", "graph", "skeleton", "unit_scale", "up_axis", "facing_local_axis", "facing_target_axis",
            "rotation_6d", "quaternion_order", "output_delta_mode", "input_delta_mode", "training", "max_frame_index", "architecture",
            "contact_joints", "contact_threshold",
        };

        /// <summary>Channels of the <c>foot_contacts</c> output: left ankle, left toe, right ankle, right toe (<see cref="Feet.FootLocker.ChannelCount"/>).</summary>
        public const int ContactChannelCount = 4;

        /// <summary>The first contract version whose graphs may have a <c>foot_contacts</c> output.</summary>
        public const int FirstVersionWithContacts = 3;

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

        /// <summary>
        /// Contract version 3, optional: the model-skeleton joint of each channel of the <c>foot_contacts</c> output
        /// (metadata <c>contact_joints</c>: the ankle and toe of each side, left first, as <see cref="Feet.FootLocker"/>'s
        /// channels); empty when the graphs predict no contacts.
        /// </summary>
        public IReadOnlyList<string> ContactJoints { get; private set; } = Array.Empty<string>();

        /// <summary>The probability at or above which a predicted foot joint is planted (metadata <c>contact_threshold</c>, chosen on validation); 0 without contacts.</summary>
        public double ContactThreshold { get; private set; }

        /// <summary>True when the whole and frame graphs have the <c>foot_contacts</c> output (<see cref="ContactJoints"/>).</summary>
        public bool HasFootContacts => ContactJoints.Count > 0;

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

        internal static string Fmt(double v) => v.ToString("R", CultureInfo.InvariantCulture);
    }
}
