using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// Which source joint(s) each target joint takes its motion from: a target joint name → a chain of
    /// source joint names, parent first. Usually the chain is one joint; a longer chain maps several
    /// source joints onto one target joint (CMU <c>Neck</c> + <c>Neck1</c> → LaFAN1 <c>Neck</c>): the target
    /// joint then turns as the chain's <b>last</b> joint does (the product of the chain's rotations), and
    /// when mapping back the chain's leading joints keep the source clip's own rotations while the last
    /// one takes the rest, so the round trip is exact (<see cref="SkeletonMap"/>).
    /// Names match exactly, or after dropping a namespace prefix up to the last ':' on either side
    /// (Mixamo's <c>mixamorig:Hips</c> matches <c>Hips</c>).
    /// Built-in maps target the model's skeleton (LaFAN1's 22 joint names).
    /// </summary>
    /// <remarks>
    /// <b>Joints a rig lacks.</b> A target joint mapped to <c>null</c> is <i>synthesized</i>: it becomes a
    /// rigid child of its parent at the reference pose's offset (<see cref="SkeletonMap"/>). A joint in
    /// <see cref="MayLack"/> is synthesized when its chain is not found in the source skeleton (the built-in
    /// maps allow this for toes, the upper chest, the neck and the shoulders; a JSON map for every joint
    /// it does not name). Every other joint must be found.
    /// </remarks>
    public sealed class JointMap
    {
        /// <summary>The model joints a built-in map synthesizes when a rig lacks them (toes, upper chest, neck, shoulders).</summary>
        public static IReadOnlyList<string> OptionalModelJoints { get; } = new[] { "LeftToe", "RightToe", "Spine2", "Neck", "LeftShoulder", "RightShoulder" };

        private readonly Dictionary<string, string[]?> _chains;
        private readonly HashSet<string> _mayLack;
        private readonly string[] _targets;

        /// <summary>Creates a map from target joint names to source chains (parent first, each non-empty; null: synthesize the joint).</summary>
        /// <param name="name">A short name for messages, e.g. <c>cmu</c> or a file path.</param>
        /// <param name="chains">Target joint name → source joint names, parent first, or null for a joint the source lacks.</param>
        /// <param name="mayLack">Target joints synthesized when their chain is not found in a source skeleton.</param>
        public JointMap(string name, IEnumerable<KeyValuePair<string, string[]?>> chains, IEnumerable<string>? mayLack = null)
        {
            Name = name ?? throw new ArgumentNullException(nameof(name));
            if (chains == null) throw new ArgumentNullException(nameof(chains));
            _chains = new Dictionary<string, string[]?>(StringComparer.Ordinal);
            var order = new List<string>();
            foreach (KeyValuePair<string, string[]?> kv in chains)
            {
                if (string.IsNullOrWhiteSpace(kv.Key)) throw new ArgumentException("a target joint name is empty", nameof(chains));
                if (kv.Value != null && kv.Value.Length == 0) throw new ArgumentException($"target joint '{kv.Key}' has no source joint", nameof(chains));
                if (_chains.ContainsKey(kv.Key)) throw new ArgumentException($"target joint '{kv.Key}' is listed twice", nameof(chains));
                _chains.Add(kv.Key, kv.Value == null ? null : (string[])kv.Value.Clone());
                order.Add(kv.Key);
            }

            _targets = order.ToArray();
            _mayLack = new HashSet<string>(mayLack ?? Array.Empty<string>(), StringComparer.Ordinal);
        }

        /// <summary>True when the map says <paramref name="targetJoint"/> has no source joint (null): it is synthesized.</summary>
        public bool IsSynthesized(string targetJoint) => _chains.TryGetValue(targetJoint, out string[]? chain) && chain == null;

        /// <summary>True when <paramref name="targetJoint"/> is synthesized if a source skeleton lacks its chain (see remarks).</summary>
        public bool MayLack(string targetJoint) => _mayLack.Contains(targetJoint) || IsSynthesized(targetJoint);

        /// <summary>The map's name for messages.</summary>
        public string Name { get; }

        /// <summary>The target joints the map names, in the order given.</summary>
        public IReadOnlyList<string> TargetJoints => _targets;

        /// <summary>The source chain (parent first) of <paramref name="targetJoint"/>, or null when the map does not name it.</summary>
        public IReadOnlyList<string>? SourceChain(string targetJoint) => _chains.TryGetValue(targetJoint, out string[]? chain) ? chain : null;

        /// <summary>
        /// The CMU database in the cgspeed "Daz-friendly" Poser conversion (43 joints, <c>ROOT hip</c>; e.g.
        /// <c>../shared/data/cmu-more</c>): two spine joints and no toes, so Spine2 and the toes are
        /// synthesized; the buttock joints between hip and thigh are folded into the thighs.
        /// </summary>
        public static JointMap Poser { get; } = Build("poser", new[]
        {
            "Hips", "hip", "LeftUpLeg", "lThigh", "LeftLeg", "lShin", "LeftFoot", "lFoot", "LeftToe", null,
            "RightUpLeg", "rThigh", "RightLeg", "rShin", "RightFoot", "rFoot", "RightToe", null,
            "Spine", "abdomen", "Spine1", "chest", "Spine2", null, "Neck", "neck", "Head", "head",
            "LeftShoulder", "lCollar", "LeftArm", "lShldr", "LeftForeArm", "lForeArm", "LeftHand", "lHand",
            "RightShoulder", "rCollar", "RightArm", "rShldr", "RightForeArm", "rForeArm", "RightHand", "rHand",
        });

        /// <summary>LaFAN1 (and the model) onto itself: every joint by its own name.</summary>
        public static JointMap Lafan1 { get; } = Build("lafan1", new[]
        {
            "Hips", "Hips", "LeftUpLeg", "LeftUpLeg", "LeftLeg", "LeftLeg", "LeftFoot", "LeftFoot", "LeftToe", "LeftToe",
            "RightUpLeg", "RightUpLeg", "RightLeg", "RightLeg", "RightFoot", "RightFoot", "RightToe", "RightToe",
            "Spine", "Spine", "Spine1", "Spine1", "Spine2", "Spine2", "Neck", "Neck", "Head", "Head",
            "LeftShoulder", "LeftShoulder", "LeftArm", "LeftArm", "LeftForeArm", "LeftForeArm", "LeftHand", "LeftHand",
            "RightShoulder", "RightShoulder", "RightArm", "RightArm", "RightForeArm", "RightForeArm", "RightHand", "RightHand",
        });

        /// <summary>
        /// The CMU database in B. Hahne's 2010 MotionBuilder-friendly BVH conversion (31 joints): LowerBack,
        /// Spine, Spine1 become Spine, Spine1, Spine2; Neck + Neck1 become Neck; ToeBase becomes Toe.
        /// LHipJoint, RHipJoint and the finger and thumb joints have no counterpart.
        /// </summary>
        public static JointMap Cmu { get; } = Build("cmu", new[]
        {
            "Hips", "Hips", "LeftUpLeg", "LeftUpLeg", "LeftLeg", "LeftLeg", "LeftFoot", "LeftFoot", "LeftToe", "LeftToeBase",
            "RightUpLeg", "RightUpLeg", "RightLeg", "RightLeg", "RightFoot", "RightFoot", "RightToe", "RightToeBase",
            "Spine", "LowerBack", "Spine1", "Spine", "Spine2", "Spine1", "Neck", "Neck|Neck1", "Head", "Head",
            "LeftShoulder", "LeftShoulder", "LeftArm", "LeftArm", "LeftForeArm", "LeftForeArm", "LeftHand", "LeftHand",
            "RightShoulder", "RightShoulder", "RightArm", "RightArm", "RightForeArm", "RightForeArm", "RightHand", "RightHand",
        });

        /// <summary>Mixamo rigs (<c>mixamorig:Hips</c>, …; the prefix is ignored): the names equal LaFAN1's except the toes.</summary>
        public static JointMap Mixamo { get; } = Build("mixamo", new[]
        {
            "Hips", "Hips", "LeftUpLeg", "LeftUpLeg", "LeftLeg", "LeftLeg", "LeftFoot", "LeftFoot", "LeftToe", "LeftToeBase",
            "RightUpLeg", "RightUpLeg", "RightLeg", "RightLeg", "RightFoot", "RightFoot", "RightToe", "RightToeBase",
            "Spine", "Spine", "Spine1", "Spine1", "Spine2", "Spine2", "Neck", "Neck", "Head", "Head",
            "LeftShoulder", "LeftShoulder", "LeftArm", "LeftArm", "LeftForeArm", "LeftForeArm", "LeftHand", "LeftHand",
            "RightShoulder", "RightShoulder", "RightArm", "RightArm", "RightForeArm", "RightForeArm", "RightHand", "RightHand",
        });

        /// <summary>
        /// Unity's <c>HumanBodyBones</c> names (Hips, LeftUpperLeg, …, Chest, UpperChest), as the Unity layer
        /// names the joints it reads from an <c>Avatar</c>.
        /// </summary>
        public static JointMap UnityHumanoid { get; } = Build("unity-humanoid", new[]
        {
            "Hips", "Hips", "LeftUpLeg", "LeftUpperLeg", "LeftLeg", "LeftLowerLeg", "LeftFoot", "LeftFoot", "LeftToe", "LeftToes",
            "RightUpLeg", "RightUpperLeg", "RightLeg", "RightLowerLeg", "RightFoot", "RightFoot", "RightToe", "RightToes",
            "Spine", "Spine", "Spine1", "Chest", "Spine2", "UpperChest", "Neck", "Neck", "Head", "Head",
            "LeftShoulder", "LeftShoulder", "LeftArm", "LeftUpperArm", "LeftForeArm", "LeftLowerArm", "LeftHand", "LeftHand",
            "RightShoulder", "RightShoulder", "RightArm", "RightUpperArm", "RightForeArm", "RightLowerArm", "RightHand", "RightHand",
        });

        /// <summary>
        /// 3ds Max Biped rigs as BVH exporters write them (<c>Bip01_Pelvis</c>, <c>Bip01_L_Thigh</c>, …; spaces become
        /// underscores) with the thighs under <c>Bip01_Spine</c>, as Biped links them without its Triangle Pelvis
        /// option: the hips follow the chain <c>Bip01_Pelvis</c> → <c>Bip01_Spine</c> and the model's three spine
        /// joints map to Spine1..Spine3 (a rig with two spine links makes Spine2 up); the clavicles hang under the
        /// neck, which the map carries. The root node <c>Bip01</c> above the pelvis is unmapped.
        /// <see cref="BipedPelvis"/> is the same rig with the thighs under the pelvis.
        /// </summary>
        public static JointMap Biped { get; } = BuildBiped("biped", "Bip01_Pelvis|Bip01_Spine", "Bip01_Spine1", "Bip01_Spine2", "Bip01_Spine3");

        /// <summary>
        /// 3ds Max Biped rigs whose thighs hang under <c>Bip01_Pelvis</c> (Biped's Triangle Pelvis, and exporters that
        /// relink the legs to the pelvis): the hips are <c>Bip01_Pelvis</c> alone and the model's three spine joints
        /// map to <c>Bip01_Spine</c>..<c>Bip01_Spine2</c> (a rig with two spine links makes Spine2 up; links above
        /// <c>Bip01_Spine2</c> are carried between it and the neck). Which of the two Biped maps a rig gets is decided
        /// by where its thighs hang (<see cref="Detect"/> counts only joints that fit the hierarchy).
        /// </summary>
        public static JointMap BipedPelvis { get; } = BuildBiped("biped-pelvis", "Bip01_Pelvis", "Bip01_Spine", "Bip01_Spine1", "Bip01_Spine2");

        /// <summary>The built-in maps, in the order <see cref="Detect"/> prefers them on a tie.</summary>
        public static IReadOnlyList<JointMap> BuiltIn { get; } = new[] { Lafan1, Cmu, Mixamo, UnityHumanoid, Poser, Biped, BipedPelvis };

        /// <summary>The built-in map called <paramref name="name"/> (lafan1, cmu, mixamo, unity-humanoid, poser, biped, biped-pelvis), or null.</summary>
        public static JointMap? Named(string name)
        {
            foreach (JointMap map in BuiltIn) if (string.Equals(map.Name, name, StringComparison.OrdinalIgnoreCase)) return map;
            return null;
        }

        /// <summary>
        /// The built-in map that finds the most of <paramref name="target"/>'s joints in
        /// <paramref name="source"/> where the hierarchy lets them play their part (all of them when the source
        /// follows one of the conventions): two maps that find the same names — the two Biped layouts — are told
        /// apart by which one's joints hang where the model's do.
        /// </summary>
        public static JointMap Detect(Skeleton source, Skeleton target)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            if (target == null) throw new ArgumentNullException(nameof(target));
            JointMap best = BuiltIn[0];
            int bestCount = -1;
            foreach (JointMap map in BuiltIn)
            {
                int count = map.PlacedJoints(source, target);
                if (count > bestCount)
                {
                    best = map;
                    bestCount = count;
                }
            }

            return best;
        }

        /// <summary>
        /// Reads a user map: a JSON object whose keys are target (model) joint names and whose values are
        /// a source joint name or an array of names (a chain, parent first), e.g.
        /// <c>{"Hips": "pelvis", "Neck": ["neck_01", "neck_02"], "LeftToe": "ball_l"}</c>.
        /// Target joints the file does not name are taken from <paramref name="fallback"/> (when given).
        /// </summary>
        /// <exception cref="DataFormatException">Not valid JSON, or a value is not a name or an array of names (file and line named).</exception>
        public static JointMap FromJson(string text, string sourceName, JointMap? fallback = null)
        {
            JsonValue root = JsonValue.Parse(text, sourceName);
            IReadOnlyDictionary<string, JsonValue> members = root.ExpectObject("the joint map");
            var chains = new List<KeyValuePair<string, string[]?>>();
            var named = new HashSet<string>(StringComparer.Ordinal);
            var mayLack = new List<string>();
            foreach (KeyValuePair<string, JsonValue> kv in members)
            {
                if (string.IsNullOrWhiteSpace(kv.Key))
                {
                    throw new DataFormatException(sourceName, kv.Value.Line, "a target joint name is blank", "expected model joint names as keys");
                }

                string[]? chain;
                if (kv.Value.Kind == JsonKind.Null)
                {
                    chain = null; // the rig lacks this joint: synthesize it
                }
                else if (kv.Value.Kind == JsonKind.String)
                {
                    chain = new[] { kv.Value.ExpectString(kv.Key) };
                }
                else
                {
                    IReadOnlyList<JsonValue> items = kv.Value.ExpectArray($"\"{kv.Key}\" (a source joint name or an array of names)");
                    if (items.Count == 0)
                    {
                        throw new DataFormatException(sourceName, kv.Value.Line, $"\"{kv.Key}\" maps to an empty array", "expected one or more source joint names, parent first");
                    }

                    chain = new string[items.Count];
                    for (int i = 0; i < chain.Length; i++) chain[i] = items[i].ExpectString($"\"{kv.Key}\"[{i}]");
                }

                foreach (string s in chain ?? Array.Empty<string>())
                {
                    if (string.IsNullOrWhiteSpace(s))
                    {
                        throw new DataFormatException(sourceName, kv.Value.Line, $"\"{kv.Key}\" maps to an empty name", "expected source joint names");
                    }
                }

                if (!named.Add(kv.Key))
                {
                    throw new DataFormatException(sourceName, kv.Value.Line, $"\"{kv.Key}\" is listed twice", "expected each model joint once");
                }

                chains.Add(new KeyValuePair<string, string[]?>(kv.Key, chain));
            }

            if (fallback != null)
            {
                foreach (string t in fallback.TargetJoints)
                {
                    if (named.Contains(t)) continue;
                    string[]? chain = fallback._chains[t];
                    chains.Add(new KeyValuePair<string, string[]?>(t, chain == null ? null : (string[])chain.Clone()));
                    mayLack.Add(t); // omitted from the file: taken from the built-in names when the rig has them, else synthesized
                }
            }

            return new JointMap(sourceName, chains, mayLack);
        }

        /// <summary>
        /// The map's target joints that <paramref name="target"/> does not have (a typo, another skeleton's
        /// names): a user map's keys that would otherwise be ignored without a word.
        /// </summary>
        public IReadOnlyList<string> TargetsNotIn(Skeleton target)
        {
            if (target == null) throw new ArgumentNullException(nameof(target));
            var unknown = new List<string>();
            foreach (string t in _targets) if (target.IndexOf(t) < 0) unknown.Add(t);
            return unknown;
        }

        /// <summary>
        /// This map with some target joints played by other bones (one bone each), e.g. a character whose
        /// thigh is called <c>thigh_l</c> in an otherwise Mixamo-named rig. Joints not listed keep their chains.
        /// </summary>
        /// <param name="bones">Target joint name → the bone that plays it; blank entries are skipped.</param>
        public JointMap WithBones(IEnumerable<KeyValuePair<string, string>> bones)
        {
            if (bones == null) throw new ArgumentNullException(nameof(bones));
            var renamed = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (KeyValuePair<string, string> kv in bones)
            {
                if (!string.IsNullOrWhiteSpace(kv.Key) && !string.IsNullOrWhiteSpace(kv.Value)) renamed[kv.Key] = kv.Value;
            }

            if (renamed.Count == 0) return this;
            var chains = new List<KeyValuePair<string, string[]?>>();
            foreach (string t in _targets) chains.Add(new KeyValuePair<string, string[]?>(t, renamed.TryGetValue(t, out string? bone) ? new[] { bone } : _chains[t]));
            foreach (KeyValuePair<string, string> kv in renamed)
            {
                if (!_chains.ContainsKey(kv.Key)) chains.Add(new KeyValuePair<string, string[]?>(kv.Key, new[] { kv.Value }));
            }

            return new JointMap(Name, chains, _mayLack);
        }

        /// <summary>The largest map file read (a map of a few hundred joints is a few kilobytes).</summary>
        public const long MaxFileBytes = 1 << 20;

        /// <summary>
        /// Reads a user map file (see <see cref="FromJson"/>) through the safe input path: a regular file of at
        /// most <see cref="MaxFileBytes"/> (a folder, a named pipe or a device is refused before it is opened).
        /// </summary>
        /// <exception cref="IO.InputPathException">Not a regular file, or too large.</exception>
        public static JointMap Load(string path, JointMap? fallback = null) =>
            FromJson(IO.InputFile.ReadAllText(path, "a JSON joint map such as {\"Hips\": \"pelvis\", ...}", MaxFileBytes), path, fallback);

        /// <summary>
        /// Index of the joint named <paramref name="name"/> in <paramref name="skeleton"/>: an exact match
        /// first, then a match ignoring namespace prefixes up to the last ':' (−1 when none or ambiguous).
        /// </summary>
        public static int FindJoint(Skeleton skeleton, string name)
        {
            int exact = skeleton.IndexOf(name);
            if (exact >= 0) return exact;
            string bare = StripNamespace(name);
            int found = -1;
            for (int j = 0; j < skeleton.JointCount; j++)
            {
                if (string.Equals(StripNamespace(skeleton.Names[j]), bare, StringComparison.Ordinal))
                {
                    if (found >= 0) return -1;
                    found = j;
                }
            }

            return found;
        }

        /// <summary>
        /// How many of <paramref name="target"/>'s joints this map finds in <paramref name="source"/> below their
        /// parent's joint, with no other mapped joint between (what <see cref="MapChains"/> would carry wrongly):
        /// a thigh under <c>Bip01_Pelvis</c> does not fit a map whose hips end at <c>Bip01_Spine</c>, and a thigh
        /// under <c>Bip01_Spine</c> does not fit one that maps <c>Bip01_Spine</c> to the model's Spine.
        /// </summary>
        private int PlacedJoints(Skeleton source, Skeleton target)
        {
            var found = new int[target.JointCount][];
            var owner = new int[source.JointCount];
            for (int s = 0; s < owner.Length; s++) owner[s] = -1;
            for (int j = 0; j < found.Length; j++)
            {
                IReadOnlyList<string>? chain = SourceChain(target.Names[j]);
                int[]? joints = chain == null ? null : FindChain(source, chain);
                if (joints == null) continue;
                found[j] = joints;
                foreach (int s in joints) owner[s] = j;
            }

            int placed = 0;
            for (int j = 0; j < found.Length; j++)
            {
                if (found[j] == null) continue;
                int parent = target.Parents[j];
                if (parent < 0 || found[parent] == null)
                {
                    placed++; // the root, or a parent the rig lacks: nothing to hang from
                    continue;
                }

                int stop = found[parent][found[parent].Length - 1];
                int walk = source.Parents[found[j][0]];
                while (walk >= 0 && walk != stop && owner[walk] < 0) walk = source.Parents[walk];
                if (walk == stop) placed++;
            }

            return placed;
        }

        /// <summary>The indices of a chain's joints in <paramref name="skeleton"/> (<see cref="FindJoint"/>), or null when any is missing.</summary>
        public static int[]? FindChain(Skeleton skeleton, IReadOnlyList<string> chain)
        {
            var indices = new int[chain.Count];
            for (int i = 0; i < indices.Length; i++)
            {
                indices[i] = FindJoint(skeleton, chain[i]);
                if (indices[i] < 0) return null;
            }

            return indices;
        }

        private static string StripNamespace(string name)
        {
            int colon = name.LastIndexOf(':');
            return colon >= 0 ? name.Substring(colon + 1) : name;
        }

        // The two Biped layouts differ only in the hips and spine chains; legs, neck, head and arms are named alike.
        private static JointMap BuildBiped(string name, string hips, string spine, string spine1, string spine2) => Build(name, new[]
        {
            "Hips", hips, "LeftUpLeg", "Bip01_L_Thigh", "LeftLeg", "Bip01_L_Calf", "LeftFoot", "Bip01_L_Foot", "LeftToe", "Bip01_L_Toe0",
            "RightUpLeg", "Bip01_R_Thigh", "RightLeg", "Bip01_R_Calf", "RightFoot", "Bip01_R_Foot", "RightToe", "Bip01_R_Toe0",
            "Spine", spine, "Spine1", spine1, "Spine2", spine2, "Neck", "Bip01_Neck", "Head", "Bip01_Head",
            "LeftShoulder", "Bip01_L_Clavicle", "LeftArm", "Bip01_L_UpperArm", "LeftForeArm", "Bip01_L_Forearm", "LeftHand", "Bip01_L_Hand",
            "RightShoulder", "Bip01_R_Clavicle", "RightArm", "Bip01_R_UpperArm", "RightForeArm", "Bip01_R_Forearm", "RightHand", "Bip01_R_Hand",
        });

        private static JointMap Build(string name, string?[] pairs)
        {
            var chains = new List<KeyValuePair<string, string[]?>>(pairs.Length / 2);
            for (int i = 0; i < pairs.Length; i += 2)
            {
                chains.Add(new KeyValuePair<string, string[]?>(pairs[i]!, pairs[i + 1]?.Split('|')));
            }

            return new JointMap(name, chains, OptionalModelJoints);
        }
    }
}
