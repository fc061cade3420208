using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>Reading the <c>deltainterp</c> JSON object into the contract, every problem reported (<see cref="Parse"/>).</summary>
    public sealed partial class ModelContract
    {
        /// <returns>False when no usable contract can be built (no readable skeleton).</returns>
        private bool ReadDescription(IReadOnlyDictionary<string, JsonValue> m, ModelCheckReport report)
        {
            var fields = new MetadataFields(Source, m, report);
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
                var tf = new MetadataFields(Source, t, report, "training.");
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
                    var af = new MetadataFields(Source, a, report, "architecture.");
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

            if (usable) ReadContacts(m, fields, report);

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

        /// <summary>
        /// Contract version 3's optional contact fields: both or neither; four distinct joints of the skeleton and a
        /// threshold strictly between 0 and 1 (0 would plant every frame, 1 almost none).
        /// </summary>
        private void ReadContacts(IReadOnlyDictionary<string, JsonValue> m, MetadataFields fields, ModelCheckReport report)
        {
            bool joints = m.ContainsKey("contact_joints"), threshold = m.ContainsKey("contact_threshold");
            if (!joints && !threshold) return;
            if (ContractVersion < FirstVersionWithContacts)
            {
                report.Error(Source, $"metadata has contact fields but contract version {ContractVersion}", $"expected contact_joints and contact_threshold only from contract version {FirstVersionWithContacts}; export the checkpoint again");
                return;
            }

            if (joints != threshold)
            {
                report.Error(Source, $"metadata has \"{(joints ? "contact_joints" : "contact_threshold")}\" without \"{(joints ? "contact_threshold" : "contact_joints")}\"", "expected both (a model with a foot_contacts output) or neither; export the checkpoint again");
                return;
            }

            IReadOnlyList<JsonValue>? list = fields.Array("contact_joints");
            double t = fields.Number("contact_threshold", "contact_threshold", double.NaN);
            if (list == null) return;
            if (list.Count != ContactChannelCount)
            {
                report.Error(Source, $"metadata contact_joints has {list.Count} names", $"expected {ContactChannelCount}: the ankle and toe of each side, left first (LeftFoot, LeftToe, RightFoot, RightToe); export the checkpoint again");
                return;
            }

            var names = new string[ContactChannelCount];
            for (int c = 0; c < names.Length; c++)
            {
                int channel = c;
                names[c] = fields.Guard(() => list[channel].ExpectString($"contact_joints[{channel}]"), "");
                if (names[c].Length == 0) return;
                if (Skeleton.IndexOf(names[c]) < 0)
                {
                    report.Error(Source, $"metadata contact_joints[{c}] is '{names[c]}', not a joint of the model's skeleton", "expected the names of the skeleton's ankle and toe joints; export the checkpoint again");
                    return;
                }

                if (Array.IndexOf(names, names[c], 0, c) >= 0)
                {
                    report.Error(Source, $"metadata contact_joints names '{names[c]}' twice", "expected four different joints (each side's ankle and toe); export the checkpoint again");
                    return;
                }
            }

            if (!(t > 0 && t < 1))
            {
                report.Error(Source, $"metadata contact_threshold is {Fmt(t)}", "expected a probability strictly between 0 and 1 (the one chosen on validation); export the checkpoint again");
                return;
            }

            ContactJoints = names;
            ContactThreshold = t;
        }

        private bool ReadSkeleton(MetadataFields fields, ModelCheckReport report)
        {
            IReadOnlyDictionary<string, JsonValue>? s = fields.Object("skeleton");
            if (s == null) return false;
            var sf = new MetadataFields(Source, s, report, "skeleton.");
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
    }
}
