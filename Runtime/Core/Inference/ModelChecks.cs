using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Every check of a model against this runtime, a graph, a skeleton and a request. Each adds
    /// <see cref="ModelCheck"/>s (Info / Warning / Error, with a remedy) to a <see cref="ModelCheckReport"/>
    /// instead of throwing, so the command line (<c>inbetween check</c>) and the editor's model inspector
    /// show the same list; loading refuses a model when the list holds an error.
    /// </summary>
    public static class ModelChecks
    {
        /// <summary>
        /// Reads the contract from a loaded graph's metadata (<see cref="ModelContract.FromMetadata"/>),
        /// then checks the graph kind and its inputs and outputs (<see cref="Graph"/>).
        /// </summary>
        /// <param name="model">What the backend reports about the graph.</param>
        /// <param name="expected">The graph kind the caller is loading (whole, keys or frame).</param>
        /// <param name="report">Receives the results.</param>
        /// <returns>The contract, or null when the metadata is missing or unreadable.</returns>
        public static ModelContract? Model(ModelDescription model, ModelGraphKind expected, ModelCheckReport report)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            ModelContract? contract = ModelContract.FromMetadata(model.Source, model.Metadata, report);
            if (contract == null) return null;
            GraphKind(contract, expected, report);
            Graph(contract, model, report);
            return contract;
        }

        /// <summary>Reports an error when the file holds another graph than the one the caller loads.</summary>
        public static void GraphKind(ModelContract contract, ModelGraphKind expected, ModelCheckReport report)
        {
            if (contract.Graph != expected)
            {
                report.Error(contract.Source, $"the file holds the '{ModelContract.GraphName(contract.Graph)}' graph",
                    $"expected the '{ModelContract.GraphName(expected)}' graph here; pass NAME.onnx (the whole graph) — NAME.keys.onnx and NAME.frame.onnx are found beside it");
            }
        }

        /// <summary>
        /// Checks a graph's input and output names, element types and ranks against the contract of its
        /// kind (<see cref="ModelContract.Graph"/>), and the constant outputs' presence.
        /// </summary>
        public static void Graph(ModelContract contract, ModelDescription model, ModelCheckReport report)
        {
            int kf = contract.KeyFeatureSize;
            // A version this runtime does not read is one error already (the tensors may be anything).
            if (contract.ContractVersion < ModelContract.MinSupportedVersion || contract.ContractVersion > ModelContract.MaxSupportedVersion) return;
            // Version 2 adds a batch axis: indices [B, K] / [B, N], gap [B], key_memory [B, R, 2, K, D].
            int b = contract.HasBatchAxis ? 1 : 0;
            switch (contract.Graph)
            {
                case ModelGraphKind.Whole:
                    Input(contract, model, report, TensorNames.KeyFeatures, TensorElementKind.Float32, 3, 2, kf);
                    Input(contract, model, report, TensorNames.KeyFrameIndices, TensorElementKind.Int64, 1 + b, -1, 0);
                    Input(contract, model, report, TensorNames.QueryFrameIndices, TensorElementKind.Int64, 1 + b, -1, 0);
                    Input(contract, model, report, TensorNames.GapLength, TensorElementKind.Int64, 1, -1, 0);
                    OnlyInputs(contract, model, report, TensorNames.KeyFeatures, TensorNames.KeyFrameIndices, TensorNames.QueryFrameIndices, TensorNames.GapLength);
                    Output(contract, model, report, TensorNames.RootPositionDelta, TensorElementKind.Float32);
                    Output(contract, model, report, TensorNames.Rotation6DDelta, TensorElementKind.Float32);
                    ContactOutput(contract, model, report);
                    break;
                case ModelGraphKind.Keys:
                    Input(contract, model, report, TensorNames.KeyFeatures, TensorElementKind.Float32, 3, 2, kf);
                    Input(contract, model, report, TensorNames.KeyFrameIndices, TensorElementKind.Int64, 1 + b, -1, 0);
                    Input(contract, model, report, TensorNames.GapLength, TensorElementKind.Int64, 1, -1, 0);
                    OnlyInputs(contract, model, report, TensorNames.KeyFeatures, TensorNames.KeyFrameIndices, TensorNames.GapLength);
                    Output(contract, model, report, TensorNames.KeyMemory, TensorElementKind.Float32);
                    break;
                default:
                    Input(contract, model, report, TensorNames.KeyMemory, TensorElementKind.Float32, 4 + b, -1, 0);
                    Input(contract, model, report, TensorNames.QueryFrameIndices, TensorElementKind.Int64, 1 + b, -1, 0);
                    Input(contract, model, report, TensorNames.GapLength, TensorElementKind.Int64, 1, -1, 0);
                    OnlyInputs(contract, model, report, TensorNames.KeyMemory, TensorNames.QueryFrameIndices, TensorNames.GapLength);
                    Output(contract, model, report, TensorNames.RootPositionDelta, TensorElementKind.Float32);
                    Output(contract, model, report, TensorNames.Rotation6DDelta, TensorElementKind.Float32);
                    ContactOutput(contract, model, report);
                    break;
            }

            Output(contract, model, report, TensorNames.ContractVersion, TensorElementKind.Int64);
            Output(contract, model, report, TensorNames.JointCount, TensorElementKind.Int64);
            Output(contract, model, report, TensorNames.KeyFeatureSize, TensorElementKind.Int64);
        }

        /// <summary>
        /// Checks that poses given on <paramref name="skeleton"/> can be fed to the model: the same joint
        /// count (else one error and nothing more), then every joint's name and parent in the same order.
        /// </summary>
        /// <param name="contract">The model's contract.</param>
        /// <param name="skeleton">The skeleton of the request (a BVH file's, a character's after mapping).</param>
        /// <param name="skeletonSource">Where the skeleton came from, for the messages.</param>
        /// <param name="report">Receives the results.</param>
        public static void Skeleton(ModelContract contract, Skeleton skeleton, string skeletonSource, ModelCheckReport report)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            Skeleton model = contract.Skeleton;
            if (skeleton.JointCount != model.JointCount)
            {
                report.Error(contract.Source, $"the model has {model.JointCount} joints but {skeletonSource} has {skeleton.JointCount}",
                    "expected the skeleton the model was trained on; retarget the motion to it or train a model on this skeleton");
                return;
            }

            for (int j = 0; j < model.JointCount; j++)
            {
                if (!string.Equals(skeleton.Names[j], model.Names[j], StringComparison.Ordinal))
                {
                    report.Error(contract.Source, $"joint {j} is '{model.Names[j]}' in the model but '{skeleton.Names[j]}' in {skeletonSource}",
                        "expected the same joint names in the same order; rename or reorder the joints, or train a model on this skeleton");
                }
                else if (skeleton.Parents[j] != model.Parents[j])
                {
                    report.Error(contract.Source, $"joint {j} ('{model.Names[j]}') has parent {model.Parents[j]} in the model but {skeleton.Parents[j]} in {skeletonSource}",
                        "expected the same hierarchy; train a model on this skeleton");
                }
            }
        }

        /// <summary>
        /// Checks the constant outputs a graph computes (contract version, joint count, key-feature size),
        /// read by one probe run, against the metadata: the metadata alone cannot prove the graph matches it.
        /// </summary>
        public static void Constants(ModelContract contract, long contractVersion, long jointCount, long keyFeatureSize, ModelCheckReport report)
        {
            string src = contract.Source;
            if (contractVersion != contract.ContractVersion)
            {
                report.Error(src, $"the graph's contract_version output is {contractVersion} but its metadata says {contract.ContractVersion}",
                    "expected both to agree; the file was edited or exported by a broken exporter — export it again");
            }

            ModelContract.CheckVersion(src, (int)Math.Max(int.MinValue, Math.Min(int.MaxValue, contractVersion)), report);
            if (jointCount != contract.JointCount)
            {
                report.Error(src, $"the graph's joint_count output is {jointCount} but its metadata skeleton has {contract.JointCount} joints",
                    "expected both to agree; export the checkpoint again");
            }

            if (keyFeatureSize != contract.KeyFeatureSize)
            {
                report.Error(src, $"the graph's key_feature_size output is {keyFeatureSize}",
                    $"expected 9 × {contract.JointCount} joints = {contract.KeyFeatureSize}; export the checkpoint again");
            }
        }

        /// <summary>
        /// Checks the <c>foot_contacts</c> a probe run gave: probabilities, so finite and within [0, 1] (a graph whose
        /// sigmoid is missing or that computes NaN would plant or free every foot joint at random).
        /// </summary>
        public static void ContactProbabilities(ModelContract contract, ReadOnlySpan<float> probabilities, ModelCheckReport report)
        {
            for (int i = 0; i < probabilities.Length; i++)
            {
                float p = probabilities[i];
                if (p >= 0 && p <= 1) continue;
                report.Error(contract.Source, $"the graph's {TensorNames.FootContacts} output holds {(float.IsNaN(p) ? "NaN" : p.ToString("R", System.Globalization.CultureInfo.InvariantCulture))} (probe run, value {i})",
                    "expected probabilities in [0, 1] (a sigmoid inside the graph); export the checkpoint again");
                return;
            }
        }

        /// <summary>
        /// Checks that another graph of the same export (keys or frame beside the whole graph) describes
        /// the same network: version, skeleton, unit scale, delta mode and architecture.
        /// </summary>
        public static void SameExport(ModelContract whole, ModelContract other, ModelCheckReport report)
        {
            string? difference = null;
            if (other.ContractVersion != whole.ContractVersion) difference = $"contract version {other.ContractVersion} vs {whole.ContractVersion}";
            else if (!other.Skeleton.HasSameHierarchy(whole.Skeleton)) difference = "a different skeleton";
            else if (other.UnitScale != whole.UnitScale) difference = $"unit scale {ModelContract.Fmt(other.UnitScale)} vs {ModelContract.Fmt(whole.UnitScale)}";
            else if (other.OutputDeltaMode != whole.OutputDeltaMode) difference = $"output delta mode {other.OutputDeltaMode} vs {whole.OutputDeltaMode}";
            else if (other.Architecture.Width != whole.Architecture.Width || other.Architecture.Blocks != whole.Architecture.Blocks || other.Architecture.Heads != whole.Architecture.Heads)
            {
                difference = "a different architecture";
            }

            else if (other.HasFootContacts != whole.HasFootContacts) difference = other.HasFootContacts ? "a foot_contacts output, which the whole graph lacks," : "no foot_contacts output, unlike the whole graph,";
            else if (other.HasFootContacts && (other.ContactThreshold != whole.ContactThreshold || !SameNames(other.ContactJoints, whole.ContactJoints))) difference = "other contact joints or threshold";

            if (difference != null)
            {
                report.Error(other.Source, $"it has {difference} than {whole.Source}",
                    "expected the .keys.onnx and .frame.onnx written by the same export as the whole graph; export them again together");
            }
        }

        /// <summary>
        /// Checks a request shape: P past keys and a gap of n frames. At least one of each and P + n within
        /// the embeddings (<see cref="ModelContract.LargestFrameIndex"/>) are errors; P or n outside the
        /// ranges the model was trained on are warnings (it runs, but was never taught such requests).
        /// </summary>
        public static void Request(ModelContract contract, int pastFrames, int missingFrames, ModelCheckReport report)
        {
            string src = contract.Source;
            if (pastFrames < 1 || missingFrames < 1)
            {
                report.Error(src, $"the request has P = {pastFrames} past keys and n = {missingFrames} missing frames", "expected at least one past key and one missing frame");
                return;
            }

            int largest = contract.LargestFrameIndex;
            // In long: P + n of two ints past 2^31 − 1 wrapped to a negative sum that passed.
            long span = (long)pastFrames + missingFrames;
            if (span > largest)
            {
                report.Error(src, $"P + n = {pastFrames} + {missingFrames} = {span} exceeds the model's largest frame index {largest}",
                    "expected P + n within the model's frame embeddings; use fewer past keys or split the gap");
            }

            if (!contract.HasTrainingRanges) return;
            (int pMin, int pMax) = contract.TrainingPastFrames;
            if (pMax > 0 && (pastFrames < pMin || pastFrames > pMax))
            {
                report.Warning(src, $"the request has {pastFrames} past key frames but the model was trained with {Span(pMin, pMax)}",
                    $"expected P in [{pMin}, {pMax}] for results like the model card's; give {(pastFrames < pMin ? "more" : "fewer")} past frames{(pastFrames < pMin ? $", or retrain with --min-past {pastFrames}" : "")}");
            }

            (int nMin, int nMax) = contract.TrainingMissingFrames;
            if (nMax > 0 && (missingFrames < nMin || missingFrames > nMax))
            {
                report.Warning(src, $"the request has a gap of {missingFrames} frames but the model was trained on gaps of {Span(nMin, nMax)} frames",
                    $"expected a gap in [{nMin}, {nMax}] for results like the model card's; {(missingFrames > nMax ? "split the gap with an intermediate key" : "use a longer gap")}, or retrain on such gaps");
            }
        }

        /// <summary>
        /// The optional <c>foot_contacts</c> output (contract version 3) of the whole and frame graphs: float32
        /// [B, N, 4] when the metadata names contact joints, and only then; its channels must be the legs the
        /// foot locker finds on the model's skeleton, in its order (left ankle, left toe, right ankle, right toe).
        /// </summary>
        private static void ContactOutput(ModelContract c, ModelDescription model, ModelCheckReport report)
        {
            TensorDescription? t = model.FindOutput(TensorNames.FootContacts);
            if (!c.HasFootContacts)
            {
                if (t != null)
                {
                    report.Error(c.Source, $"the graph has a '{TensorNames.FootContacts}' output but its metadata names no contact_joints",
                        "expected contact_joints and contact_threshold beside a foot_contacts output (contract version 3); export the checkpoint again");
                }

                return;
            }

            if (t == null)
            {
                report.Error(c.Source, $"the metadata names contact_joints but the {ModelContract.GraphName(c.Graph)} graph has no output '{TensorNames.FootContacts}' (its outputs: {Names(model.Outputs)})",
                    "expected a foot_contacts output [B, N, 4] with contact joints in the metadata; export the checkpoint again");
                return;
            }

            int rank = c.HasBatchAxis ? 3 : 2;
            if (t.Kind != TensorElementKind.Float32)
            {
                report.Error(c.Source, $"output '{TensorNames.FootContacts}' is {t.Kind}", "expected Float32 probabilities; export the checkpoint again");
            }
            else if (t.Shape.Count != rank || t.Shape[rank - 1] >= 0 && t.Shape[rank - 1] != ModelContract.ContactChannelCount)
            {
                report.Error(c.Source, $"output '{TensorNames.FootContacts}' has shape [{string.Join(", ", t.Shape)}]",
                    $"expected [B, N, {ModelContract.ContactChannelCount}] (one probability per query frame and foot joint); export the checkpoint again");
            }

            if (!Feet.FootRig.HasModelLegs(c.Skeleton))
            {
                report.Error(c.Source, "the model predicts foot contacts but its skeleton has no legs the foot locker finds",
                    "expected a skeleton with LeftUpLeg/LeftLeg/LeftFoot(/LeftToe) and the right side's; export the checkpoint without a contact head");
                return;
            }

            var joints = new int[ModelContract.ContactChannelCount];
            Feet.FootLocker.ChannelJoints(Feet.FootRig.ForModel(c.Skeleton), joints);
            for (int ch = 0; ch < joints.Length; ch++)
            {
                string expected = joints[ch] >= 0 ? c.Skeleton.Names[joints[ch]] : "(no toe)";
                if (!string.Equals(c.ContactJoints[ch], expected, StringComparison.Ordinal))
                {
                    report.Error(c.Source, $"metadata contact_joints[{ch}] is '{c.ContactJoints[ch]}' but the foot locker's channel {ch} is '{expected}'",
                        "expected the ankle and toe of each side, left first (" + string.Join(", ", Expected(c, joints)) + "); export the checkpoint again");
                    return;
                }
            }
        }

        private static string[] Expected(ModelContract c, int[] joints)
        {
            var names = new string[joints.Length];
            for (int i = 0; i < joints.Length; i++) names[i] = joints[i] >= 0 ? c.Skeleton.Names[joints[i]] : "(no toe)";
            return names;
        }

        private static bool SameNames(IReadOnlyList<string> a, IReadOnlyList<string> b)
        {
            if (a.Count != b.Count) return false;
            for (int i = 0; i < a.Count; i++)
            {
                if (!string.Equals(a[i], b[i], StringComparison.Ordinal)) return false;
            }

            return true;
        }

        private static string Span(int min, int max) => min == max ? min.ToString(System.Globalization.CultureInfo.InvariantCulture) : $"{min} to {max}";

        private static void Input(ModelContract c, ModelDescription model, ModelCheckReport report, string name, TensorElementKind kind, int rank, int fixedAxis, long fixedValue)
        {
            TensorDescription? t = model.FindInput(name);
            string src = c.Source;
            if (t == null)
            {
                report.Error(src, $"the {ModelContract.GraphName(c.Graph)} graph has no input '{name}' (its inputs: {Names(model.Inputs)})",
                    $"expected the inputs of contract version {ModelContract.Version} (Documentation~/model-contract.md); export the checkpoint again");
                return;
            }

            if (t.Kind != kind)
            {
                report.Error(src, $"input '{name}' is {t.Kind}", $"expected {kind}; export the checkpoint again");
            }
            else if (t.Shape.Count != rank)
            {
                report.Error(src, $"input '{name}' has rank {t.Shape.Count}", $"expected rank {rank}; export the checkpoint again");
            }
            else if (fixedAxis >= 0 && t.Shape[fixedAxis] >= 0 && t.Shape[fixedAxis] != fixedValue)
            {
                report.Error(src, $"input '{name}' has {t.Shape[fixedAxis]} features per key frame",
                    $"expected 9 × {c.JointCount} joints = {fixedValue}; the graph and its metadata disagree — export the checkpoint again");
            }
        }

        private static void OnlyInputs(ModelContract c, ModelDescription model, ModelCheckReport report, params string[] names)
        {
            foreach (TensorDescription t in model.Inputs)
            {
                if (Array.IndexOf(names, t.Name) >= 0) continue;
                if (t.Name == TensorNames.QueryFeatures)
                {
                    report.Error(c.Source, "the graph has a 'query_features' input (input delta mode 'none', an ablation)",
                        "expected only " + string.Join(", ", names) + "; this runtime does not run ablation models");
                }
                else
                {
                    report.Error(c.Source, $"the graph has an unexpected input '{t.Name}'", "expected only " + string.Join(", ", names) + "; export the checkpoint again");
                }
            }
        }

        private static void Output(ModelContract c, ModelDescription model, ModelCheckReport report, string name, TensorElementKind kind)
        {
            TensorDescription? t = model.FindOutput(name);
            if (t == null)
            {
                report.Error(c.Source, $"the {ModelContract.GraphName(c.Graph)} graph has no output '{name}' (its outputs: {Names(model.Outputs)})",
                    $"expected the outputs of contract version {ModelContract.Version}; export the checkpoint again");
            }
            else if (t.Kind != kind)
            {
                report.Error(c.Source, $"output '{name}' is {t.Kind}", $"expected {kind}; export the checkpoint again");
            }
        }

        private static string Names(IReadOnlyList<TensorDescription> list)
        {
            var names = new string[list.Count];
            for (int i = 0; i < names.Length; i++) names[i] = list[i].Name;
            return names.Length == 0 ? "none" : string.Join(", ", names);
        }
    }
}
