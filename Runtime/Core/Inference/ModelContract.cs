using System;
using System.Collections.Generic;
using System.Globalization;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>Which of the three exported graphs a model file holds.</summary>
    public enum ModelGraphKind
    {
        /// <summary><c>NAME.onnx</c>: key features and query frames in, deltas out.</summary>
        Whole,
        /// <summary><c>NAME.keys.onnx</c>: key features in, <c>key_memory</c> out (lazy decoding).</summary>
        Keys,
        /// <summary><c>NAME.frame.onnx</c>: <c>key_memory</c> and query frames in, deltas out (lazy decoding).</summary>
        Frame,
    }

    /// <summary>What the network's deltas are added to (Documentation~/model-contract.md, "Decoding").</summary>
    public enum OutputDeltaMode
    {
        /// <summary>Root LERP and per-joint SLERP between the last past key and the target (the paper's choice).</summary>
        Slerp,
        /// <summary>The last past key's pose, repeated.</summary>
        LastPose,
        /// <summary>Zero: the network outputs absolute values (ablation).</summary>
        None,
    }

    /// <summary>Network size as exported (used by the speed harness to rebuild the same net in PyTorch).</summary>
    public sealed class ModelArchitecture
    {
        internal ModelArchitecture(int width, int blocks, int heads, int embeddingDim, int embeddingSize, long parameters)
        {
            Width = width;
            Blocks = blocks;
            Heads = heads;
            EmbeddingDim = embeddingDim;
            EmbeddingSize = embeddingSize;
            Parameters = parameters;
        }

        /// <summary>Token width D.</summary>
        public int Width { get; }
        /// <summary>Number of transformer blocks R.</summary>
        public int Blocks { get; }
        /// <summary>Attention heads per block.</summary>
        public int Heads { get; }
        /// <summary>Size of the frame and gap embeddings.</summary>
        public int EmbeddingDim { get; }
        /// <summary>Rows of the embedding tables (largest frame index + 1).</summary>
        public int EmbeddingSize { get; }
        /// <summary>Number of trained parameters (0 when the exporter did not say).</summary>
        public long Parameters { get; }
    }

    /// <summary>
    /// The model contract (Documentation~/model-contract.md) as read from one exported graph: what the
    /// network expects and how to interpret its outputs. <see cref="Read"/> refuses any model this runtime
    /// cannot run correctly, with a message that says what is wrong and what to do; nothing is guessed.
    /// Python mirror: <c>Training/deltainterp/contract.py</c>.
    /// </summary>
    public sealed class ModelContract
    {
        /// <summary>The contract version this runtime implements (Python: <c>CONTRACT_VERSION</c>).</summary>
        public const int Version = 1;

        /// <summary>Oldest contract version this runtime reads.</summary>
        public const int MinSupportedVersion = 1;

        /// <summary>Newest contract version this runtime reads.</summary>
        public const int MaxSupportedVersion = 1;

        /// <summary>Features per joint in <c>key_features</c>: local 6D rotation then global position.</summary>
        public const int FeaturesPerJoint = 9;

        private ModelContract(string source)
        {
            Source = source;
        }

        /// <summary>The model file the contract was read from.</summary>
        public string Source { get; }

        /// <summary>The contract version the model was exported with.</summary>
        public int ContractVersion { get; private set; }

        /// <summary>The model's name, e.g. <c>DeltaInterpolator-LaFAN1</c>.</summary>
        public string Name { get; private set; } = "";

        /// <summary>Which graph the file holds.</summary>
        public ModelGraphKind Graph { get; private set; }

        /// <summary>The skeleton the model was trained on (offsets in data units).</summary>
        public Skeleton Skeleton { get; private set; } = null!;

        /// <summary>Model units per data unit (LaFAN1: 0.01, centimetres to metres).</summary>
        public double UnitScale { get; private set; }

        /// <summary>The root's local axis that counts as "forward" (LaFAN1 hips: +Y).</summary>
        public Vector3D FacingLocalAxis { get; private set; }

        /// <summary>The world axis the last past key is turned to face (+X).</summary>
        public Vector3D FacingTargetAxis { get; private set; }

        /// <summary>What the deltas are added to.</summary>
        public OutputDeltaMode OutputDeltaMode { get; private set; }

        /// <summary>Largest frame index the embeddings know (P + n ≤ this).</summary>
        public int MaxFrameIndex { get; private set; }

        /// <summary>Training range of past key frames [min, max].</summary>
        public (int Min, int Max) TrainingPastFrames { get; private set; }

        /// <summary>Training range of gap lengths [min, max]; longer gaps run but were never seen.</summary>
        public (int Min, int Max) TrainingMissingFrames { get; private set; }

        /// <summary>
        /// Frame rate of the training data (metadata <c>training.fps</c>; 30, LaFAN1's, when a model does not
        /// say): motion is resampled to it before inference.
        /// </summary>
        public double FramesPerSecond { get; private set; } = 30.0;

        /// <summary>Network size.</summary>
        public ModelArchitecture Architecture { get; private set; } = null!;

        /// <summary>The metadata JSON object as exported (for tools that pass it on, e.g. the speed harness).</summary>
        public string DescriptionJson { get; private set; } = "";

        /// <summary>Number of joints J.</summary>
        public int JointCount => Skeleton.JointCount;

        /// <summary>Size of one key token's features, 9·J.</summary>
        public int KeyFeatureSize => FeaturesPerJoint * JointCount;

        /// <summary>
        /// Reads and checks the contract of a loaded graph: metadata present and of a supported version,
        /// the graph kind the caller expects, the conventions this runtime implements (6D rows, wxyz,
        /// Y up), and the input and output names and element types of that graph kind.
        /// </summary>
        /// <param name="model">What the backend reports about the graph.</param>
        /// <param name="expected">The graph kind the caller is loading (whole, keys or frame).</param>
        /// <exception cref="ModelContractException">Anything does not fit; the message names it.</exception>
        public static ModelContract Read(ModelDescription model, ModelGraphKind expected)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            string src = model.Source;
            var contract = new ModelContract(src);
            if (!model.Metadata.TryGetValue(TensorNames.DescriptionMetadata, out string? json) || string.IsNullOrWhiteSpace(json))
            {
                throw new ModelContractException(src, "the model has no 'deltainterp' metadata",
                    $"expected an ONNX file written by `python3 -m deltainterp export` (contract version {Version}); export the checkpoint again");
            }

            if (model.Metadata.TryGetValue(TensorNames.ContractVersionMetadata, out string? versionText))
            {
                if (!int.TryParse(versionText, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v))
                {
                    throw new ModelContractException(src, $"metadata contract_version is '{versionText}'", "expected an integer such as \"1\"");
                }

                CheckVersion(src, v);
            }

            JsonValue root;
            try
            {
                root = JsonValue.Parse(json, src + " metadata 'deltainterp'");
                root.ExpectObject("the 'deltainterp' metadata");
            }
            catch (DataFormatException e)
            {
                throw new ModelContractException(src, "the 'deltainterp' metadata is not a valid JSON object (" + e.Problem + ")", "expected the JSON object the exporter writes; export the checkpoint again");
            }

            contract.DescriptionJson = json;
            try
            {
                contract.ReadDescription(root, expected);
            }
            catch (ModelContractException)
            {
                throw;
            }
            catch (DataFormatException e)
            {
                throw new ModelContractException(src, "metadata 'deltainterp': " + e.Problem, e.Expected);
            }
            catch (ArgumentException e)
            {
                throw new ModelContractException(src, "metadata 'deltainterp' holds an invalid skeleton (" + e.Message + ")", "expected the skeleton of the training data; export the checkpoint again");
            }

            contract.CheckTensors(model);
            return contract;
        }

        /// <summary>
        /// Checks that poses given on <paramref name="skeleton"/> can be fed to this model: the same
        /// joint count, names and parents, in the same order.
        /// </summary>
        /// <param name="skeleton">The skeleton of the request (e.g. a BVH file's or a character's).</param>
        /// <param name="skeletonSource">Where the skeleton came from, for the message.</param>
        /// <exception cref="ModelContractException">The skeletons differ; the message names the first difference.</exception>
        public void CheckSkeleton(Skeleton skeleton, string skeletonSource)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            if (skeleton.JointCount != JointCount)
            {
                throw new ModelContractException(Source, $"the model has {JointCount} joints but {skeletonSource} has {skeleton.JointCount}",
                    "expected the skeleton the model was trained on; retarget the motion to it or train a model on this skeleton");
            }

            for (int j = 0; j < JointCount; j++)
            {
                if (!string.Equals(skeleton.Names[j], Skeleton.Names[j], StringComparison.Ordinal))
                {
                    throw new ModelContractException(Source, $"joint {j} is '{Skeleton.Names[j]}' in the model but '{skeleton.Names[j]}' in {skeletonSource}",
                        "expected the same joint names in the same order; rename or reorder the joints, or train a model on this skeleton");
                }

                if (skeleton.Parents[j] != Skeleton.Parents[j])
                {
                    throw new ModelContractException(Source, $"joint {j} ('{Skeleton.Names[j]}') has parent {Skeleton.Parents[j]} in the model but {skeleton.Parents[j]} in {skeletonSource}",
                        "expected the same hierarchy; train a model on this skeleton");
                }
            }
        }

        /// <summary>
        /// Checks the constant outputs a graph computes (contract version, joint count, key-feature size)
        /// against the metadata; a backend that runs the graph reads them once at load time.
        /// </summary>
        /// <exception cref="ModelContractException">They disagree.</exception>
        public void CheckConstants(long contractVersion, long jointCount, long keyFeatureSize)
        {
            if (contractVersion != ContractVersion)
            {
                throw new ModelContractException(Source, $"the graph's contract_version output is {contractVersion} but its metadata says {ContractVersion}",
                    "expected both to agree; the file was edited or exported by a broken exporter — export it again");
            }

            CheckVersion(Source, (int)contractVersion);
            if (jointCount != JointCount)
            {
                throw new ModelContractException(Source, $"the graph's joint_count output is {jointCount} but its metadata skeleton has {JointCount} joints",
                    "expected both to agree; export the checkpoint again");
            }

            if (keyFeatureSize != KeyFeatureSize)
            {
                throw new ModelContractException(Source, $"the graph's key_feature_size output is {keyFeatureSize}",
                    $"expected 9 × {JointCount} joints = {KeyFeatureSize}; export the checkpoint again");
            }
        }

        /// <summary>
        /// Checks that another graph of the same export (keys or frame beside the whole graph) describes
        /// the same network: name, skeleton, unit scale, architecture and delta mode.
        /// </summary>
        /// <exception cref="ModelContractException">They differ: the files come from different exports.</exception>
        public void CheckSameExport(ModelContract other)
        {
            string? difference = null;
            if (other.ContractVersion != ContractVersion) difference = $"contract version {other.ContractVersion} vs {ContractVersion}";
            else if (!other.Skeleton.HasSameHierarchy(Skeleton)) difference = "a different skeleton";
            else if (other.UnitScale != UnitScale) difference = $"unit scale {Fmt(other.UnitScale)} vs {Fmt(UnitScale)}";
            else if (other.OutputDeltaMode != OutputDeltaMode) difference = $"output delta mode {other.OutputDeltaMode} vs {OutputDeltaMode}";
            else if (other.Architecture.Width != Architecture.Width || other.Architecture.Blocks != Architecture.Blocks || other.Architecture.Heads != Architecture.Heads)
            {
                difference = "a different architecture";
            }

            if (difference != null)
            {
                throw new ModelContractException(other.Source, $"it has {difference} than {Source}",
                    "expected the .keys.onnx and .frame.onnx written by the same export as the whole graph; export them again together");
            }
        }

        private static void CheckVersion(string src, int version)
        {
            if (version < MinSupportedVersion || version > MaxSupportedVersion)
            {
                string what = version > MaxSupportedVersion
                    ? "update the package, or export the model with a trainer of the matching version"
                    : "export the checkpoint again with the current trainer";
                throw new ModelContractException(src, $"the model has contract version {version}",
                    $"expected a version from {MinSupportedVersion} to {MaxSupportedVersion}; {what}");
            }
        }

        private void ReadDescription(JsonValue root, ModelGraphKind expected)
        {
            IReadOnlyDictionary<string, JsonValue> m = root.ExpectObject("the 'deltainterp' metadata");
            int version = (int)Member(m, "contract_version").ExpectNumber("contract_version");
            CheckVersion(Source, version);
            ContractVersion = version;
            Name = m.TryGetValue("name", out JsonValue? name) ? name.ExpectString("name") : "";

            string graph = Member(m, "graph").ExpectString("graph");
            switch (graph)
            {
                case "whole": Graph = ModelGraphKind.Whole; break;
                case "keys": Graph = ModelGraphKind.Keys; break;
                case "frame": Graph = ModelGraphKind.Frame; break;
                default: throw new ModelContractException(Source, $"metadata graph is '{graph}'", "expected \"whole\", \"keys\" or \"frame\"");
            }

            if (Graph != expected)
            {
                throw new ModelContractException(Source, $"the file holds the '{graph}' graph",
                    $"expected the '{Lower(expected)}' graph here; pass NAME.onnx (the whole graph) — NAME.keys.onnx and NAME.frame.onnx are found beside it");
            }

            JsonValue skeletonValue = Member(m, "skeleton");
            IReadOnlyDictionary<string, JsonValue> s = skeletonValue.ExpectObject("skeleton");
            IReadOnlyList<JsonValue> namesJson = Member(s, "names", "skeleton.").ExpectArray("skeleton.names");
            double[] parentsJson = Member(s, "parents", "skeleton.").ExpectNumbers("skeleton.parents", namesJson.Count);
            IReadOnlyList<JsonValue> offsetsJson = Member(s, "offsets", "skeleton.").ExpectArray("skeleton.offsets");
            if (offsetsJson.Count != namesJson.Count)
            {
                throw new ModelContractException(Source, $"metadata skeleton has {namesJson.Count} names but {offsetsJson.Count} offsets", "expected one offset [x, y, z] per joint; export the checkpoint again");
            }

            var names = new string[namesJson.Count];
            var parents = new int[namesJson.Count];
            var offsets = new double[3 * namesJson.Count];
            for (int j = 0; j < names.Length; j++)
            {
                names[j] = namesJson[j].ExpectString($"skeleton.names[{j}]");
                parents[j] = (int)parentsJson[j];
                double[] o = offsetsJson[j].ExpectNumbers($"skeleton.offsets[{j}]", 3);
                offsets[3 * j] = o[0];
                offsets[3 * j + 1] = o[1];
                offsets[3 * j + 2] = o[2];
            }

            Skeleton = new Skeleton(names, parents, offsets);

            UnitScale = Member(m, "unit_scale").ExpectNumber("unit_scale");
            if (!(UnitScale > 0) || double.IsInfinity(UnitScale))
            {
                throw new ModelContractException(Source, $"metadata unit_scale is {Fmt(UnitScale)}", "expected a positive number of model units per data unit (LaFAN1: 0.01)");
            }

            Vector3D up = Axis(m, "up_axis");
            if (up.X != 0 || up.Y != 1 || up.Z != 0)
            {
                throw new ModelContractException(Source, $"metadata up_axis is {up}", "expected [0, 1, 0]: this runtime implements Y-up model space only");
            }

            FacingLocalAxis = Axis(m, "facing_local_axis");
            FacingTargetAxis = Axis(m, "facing_target_axis");
            if (FacingTargetAxis.Y != 0 || FacingTargetAxis.Length == 0)
            {
                throw new ModelContractException(Source, $"metadata facing_target_axis is {FacingTargetAxis}", "expected a horizontal axis such as [1, 0, 0]");
            }

            FacingTargetAxis = (1.0 / FacingTargetAxis.Length) * FacingTargetAxis;
            RequireString(m, "rotation_6d", "rows", "this runtime decodes 6D rotations as the first two rows of the matrix");
            RequireString(m, "quaternion_order", "wxyz", "this runtime reads quaternions as (w, x, y, z)");

            string output = Member(m, "output_delta_mode").ExpectString("output_delta_mode");
            switch (output)
            {
                case "slerp": OutputDeltaMode = OutputDeltaMode.Slerp; break;
                case "last_pose": OutputDeltaMode = OutputDeltaMode.LastPose; break;
                case "none": OutputDeltaMode = OutputDeltaMode.None; break;
                default: throw new ModelContractException(Source, $"metadata output_delta_mode is '{output}'", "expected \"slerp\", \"last_pose\" or \"none\"");
            }

            string input = Member(m, "input_delta_mode").ExpectString("input_delta_mode");
            if (input == "none")
            {
                throw new ModelContractException(Source, "the model uses input delta mode 'none' (an ablation with a query_features input)",
                    "expected input delta mode 'last_pose'; this runtime does not run ablation models — train with the default --input-delta-mode");
            }

            if (input != "last_pose")
            {
                throw new ModelContractException(Source, $"metadata input_delta_mode is '{input}'", "expected \"last_pose\"");
            }

            MaxFrameIndex = m.TryGetValue("max_frame_index", out JsonValue? mfi) ? (int)mfi.ExpectNumber("max_frame_index") : 255;
            if (m.TryGetValue("training", out JsonValue? training))
            {
                IReadOnlyDictionary<string, JsonValue> t = training.ExpectObject("training");
                TrainingPastFrames = Range(t, "past_frames");
                TrainingMissingFrames = Range(t, "missing_frames");
                if (t.TryGetValue("fps", out JsonValue? fps))
                {
                    FramesPerSecond = fps.ExpectNumber("training.fps");
                    if (!(FramesPerSecond > 0) || double.IsInfinity(FramesPerSecond))
                    {
                        throw new ModelContractException(Source, $"metadata training.fps is {Fmt(FramesPerSecond)}", "expected the positive frame rate of the training data (LaFAN1: 30)");
                    }
                }
            }

            IReadOnlyDictionary<string, JsonValue> a = Member(m, "architecture").ExpectObject("architecture");
            Architecture = new ModelArchitecture(
                Int(a, "width"), Int(a, "blocks"), Int(a, "heads"), Int(a, "embedding_dim"), Int(a, "embedding_size"),
                a.TryGetValue("parameters", out JsonValue? p) ? (long)p.ExpectNumber("architecture.parameters") : 0);
        }

        private void CheckTensors(ModelDescription model)
        {
            int kf = KeyFeatureSize;
            switch (Graph)
            {
                case ModelGraphKind.Whole:
                    RequireInput(model, TensorNames.KeyFeatures, TensorElementKind.Float32, 3, 2, kf);
                    RequireInput(model, TensorNames.KeyFrameIndices, TensorElementKind.Int64, 1, -1, 0);
                    RequireInput(model, TensorNames.QueryFrameIndices, TensorElementKind.Int64, 1, -1, 0);
                    RequireInput(model, TensorNames.GapLength, TensorElementKind.Int64, 1, -1, 0);
                    RequireOnlyInputs(model, TensorNames.KeyFeatures, TensorNames.KeyFrameIndices, TensorNames.QueryFrameIndices, TensorNames.GapLength);
                    RequireOutput(model, TensorNames.RootPositionDelta, TensorElementKind.Float32);
                    RequireOutput(model, TensorNames.Rotation6DDelta, TensorElementKind.Float32);
                    break;
                case ModelGraphKind.Keys:
                    RequireInput(model, TensorNames.KeyFeatures, TensorElementKind.Float32, 3, 2, kf);
                    RequireInput(model, TensorNames.KeyFrameIndices, TensorElementKind.Int64, 1, -1, 0);
                    RequireInput(model, TensorNames.GapLength, TensorElementKind.Int64, 1, -1, 0);
                    RequireOnlyInputs(model, TensorNames.KeyFeatures, TensorNames.KeyFrameIndices, TensorNames.GapLength);
                    RequireOutput(model, TensorNames.KeyMemory, TensorElementKind.Float32);
                    break;
                default:
                    RequireInput(model, TensorNames.KeyMemory, TensorElementKind.Float32, 4, -1, 0);
                    RequireInput(model, TensorNames.QueryFrameIndices, TensorElementKind.Int64, 1, -1, 0);
                    RequireInput(model, TensorNames.GapLength, TensorElementKind.Int64, 1, -1, 0);
                    RequireOnlyInputs(model, TensorNames.KeyMemory, TensorNames.QueryFrameIndices, TensorNames.GapLength);
                    RequireOutput(model, TensorNames.RootPositionDelta, TensorElementKind.Float32);
                    RequireOutput(model, TensorNames.Rotation6DDelta, TensorElementKind.Float32);
                    break;
            }

            RequireOutput(model, TensorNames.ContractVersion, TensorElementKind.Int64);
            RequireOutput(model, TensorNames.JointCount, TensorElementKind.Int64);
            RequireOutput(model, TensorNames.KeyFeatureSize, TensorElementKind.Int64);
        }

        private void RequireInput(ModelDescription model, string name, TensorElementKind kind, int rank, int fixedAxis, long fixedValue)
        {
            TensorDescription? t = model.FindInput(name);
            if (t == null)
            {
                throw new ModelContractException(Source, $"the {Lower(Graph)} graph has no input '{name}' (its inputs: {Names(model.Inputs)})",
                    $"expected the inputs of contract version {Version} (Documentation~/model-contract.md); export the checkpoint again");
            }

            if (t.Kind != kind)
            {
                throw new ModelContractException(Source, $"input '{name}' is {t.Kind}", $"expected {kind}; export the checkpoint again");
            }

            if (t.Shape.Count != rank)
            {
                throw new ModelContractException(Source, $"input '{name}' has rank {t.Shape.Count}", $"expected rank {rank}; export the checkpoint again");
            }

            if (fixedAxis >= 0 && t.Shape[fixedAxis] >= 0 && t.Shape[fixedAxis] != fixedValue)
            {
                throw new ModelContractException(Source, $"input '{name}' has {t.Shape[fixedAxis]} features per key frame",
                    $"expected 9 × {JointCount} joints = {fixedValue}; the graph and its metadata disagree — export the checkpoint again");
            }
        }

        private void RequireOnlyInputs(ModelDescription model, params string[] names)
        {
            foreach (TensorDescription t in model.Inputs)
            {
                if (Array.IndexOf(names, t.Name) >= 0) continue;
                if (t.Name == TensorNames.QueryFeatures)
                {
                    throw new ModelContractException(Source, "the graph has a 'query_features' input (input delta mode 'none', an ablation)",
                        "expected only " + string.Join(", ", names) + "; this runtime does not run ablation models");
                }

                throw new ModelContractException(Source, $"the graph has an unexpected input '{t.Name}'",
                    "expected only " + string.Join(", ", names) + "; export the checkpoint again");
            }
        }

        private void RequireOutput(ModelDescription model, string name, TensorElementKind kind)
        {
            TensorDescription? t = model.FindOutput(name);
            if (t == null)
            {
                throw new ModelContractException(Source, $"the {Lower(Graph)} graph has no output '{name}' (its outputs: {Names(model.Outputs)})",
                    $"expected the outputs of contract version {Version}; export the checkpoint again");
            }

            if (t.Kind != kind)
            {
                throw new ModelContractException(Source, $"output '{name}' is {t.Kind}", $"expected {kind}; export the checkpoint again");
            }
        }

        private JsonValue Member(IReadOnlyDictionary<string, JsonValue> obj, string key, string prefix = "")
        {
            if (!obj.TryGetValue(key, out JsonValue? value))
            {
                throw new ModelContractException(Source, $"metadata 'deltainterp' has no \"{prefix}{key}\"",
                    $"expected every field of contract version {Version} (Documentation~/model-contract.md); export the checkpoint again");
            }

            return value;
        }

        private Vector3D Axis(IReadOnlyDictionary<string, JsonValue> m, string key)
        {
            double[] v = Member(m, key).ExpectNumbers(key, 3);
            return new Vector3D(v[0], v[1], v[2]);
        }

        private void RequireString(IReadOnlyDictionary<string, JsonValue> m, string key, string value, string why)
        {
            string actual = Member(m, key).ExpectString(key);
            if (!string.Equals(actual, value, StringComparison.Ordinal))
            {
                throw new ModelContractException(Source, $"metadata {key} is '{actual}'", $"expected \"{value}\": {why}");
            }
        }

        private int Int(IReadOnlyDictionary<string, JsonValue> obj, string key)
        {
            return (int)Member(obj, key, "architecture.").ExpectNumber("architecture." + key);
        }

        private (int, int) Range(IReadOnlyDictionary<string, JsonValue> obj, string key)
        {
            if (!obj.TryGetValue(key, out JsonValue? v)) return (0, 0);
            double[] r = v.ExpectNumbers("training." + key, 2);
            return ((int)r[0], (int)r[1]);
        }

        private static string Names(IReadOnlyList<TensorDescription> list)
        {
            var names = new string[list.Count];
            for (int i = 0; i < names.Length; i++) names[i] = list[i].Name;
            return names.Length == 0 ? "none" : string.Join(", ", names);
        }

        private static string Lower(ModelGraphKind kind) => kind.ToString().ToLowerInvariant();

        private static string Fmt(double v) => v.ToString("R", CultureInfo.InvariantCulture);
    }
}
