using System.Globalization;
using System.Text;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>The contract written back as the exporter's <c>deltainterp</c> JSON object (<see cref="ToJson"/>).</summary>
    public sealed partial class ModelContract
    {
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
            b.Append('}');
            if (HasFootContacts)
            {
                Key(b, "contact_joints").Append('[');
                for (int c = 0; c < ContactJoints.Count; c++) b.Append(c > 0 ? ", " : "").Append(Quote(ContactJoints[c]));
                b.Append(']');
                Key(b, "contact_threshold").Append(Fmt(ContactThreshold));
            }

            b.Append('}');
            return b.ToString();
        }

        private static StringBuilder Key(StringBuilder b, string key, bool first = false) => b.Append(first ? "" : ", ").Append('"').Append(key).Append("\": ");

        private static string Vector(Vector3D v) => "[" + Fmt(v.X) + ", " + Fmt(v.Y) + ", " + Fmt(v.Z) + "]";

        private static string Range((int Min, int Max) r) => "[" + r.Min.ToString(CultureInfo.InvariantCulture) + ", " + r.Max.ToString(CultureInfo.InvariantCulture) + "]";

        private static string Quote(string s) => JsonText.Quote(s);
    }
}
