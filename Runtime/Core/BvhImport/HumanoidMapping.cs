using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// Which joint of a skeleton plays each of Unity's body <c>HumanBodyBones</c> (by name: Hips,
    /// LeftUpperLeg, …), found through the built-in joint maps (<see cref="JointMap.BuiltIn"/>: a joint
    /// named as LaFAN1, CMU, Mixamo, Unity or Poser name it), so that a humanoid avatar can be built
    /// without asking the user.
    /// </summary>
    /// <remarks>
    /// The maps name the model's joints; <see cref="JointMap.UnityHumanoid"/> names the human bone each
    /// model joint is. Two rules make the result one that Unity accepts as its own auto-mapper would
    /// (<c>AvatarAutoMapper</c> refuses a human bone of zero length): a bone whose joint sits where its
    /// human parent's does (CMU's <c>LowerBack</c> at the hips, its shoulders at the upper chest) moves
    /// down to the first joint below it that does not, when that joint plays no other bone; otherwise an
    /// optional bone is left out and a required one makes the skeleton not humanoid. And as Unity does,
    /// an upper chest without a chest becomes the chest.
    /// </remarks>
    public sealed class HumanoidMapping
    {
        /// <summary>A human bone: its name, its human parent's name, and whether Unity requires it.</summary>
        private readonly struct HumanBone
        {
            public HumanBone(string name, string? parent, bool required)
            {
                Name = name;
                Parent = parent;
                Required = required;
            }

            public string Name { get; }

            public string? Parent { get; }

            public bool Required { get; }
        }

        // The body bones of Unity's humanoid (HumanTrait), parents first; the 15 required ones as Unity requires them.
        private static readonly HumanBone[] Body =
        {
            new HumanBone("Hips", null, true),
            new HumanBone("LeftUpperLeg", "Hips", true), new HumanBone("LeftLowerLeg", "LeftUpperLeg", true),
            new HumanBone("LeftFoot", "LeftLowerLeg", true), new HumanBone("LeftToes", "LeftFoot", false),
            new HumanBone("RightUpperLeg", "Hips", true), new HumanBone("RightLowerLeg", "RightUpperLeg", true),
            new HumanBone("RightFoot", "RightLowerLeg", true), new HumanBone("RightToes", "RightFoot", false),
            new HumanBone("Spine", "Hips", true), new HumanBone("Chest", "Spine", false), new HumanBone("UpperChest", "Chest", false),
            new HumanBone("Neck", "UpperChest", false), new HumanBone("Head", "Neck", true),
            new HumanBone("LeftShoulder", "UpperChest", false), new HumanBone("LeftUpperArm", "LeftShoulder", true),
            new HumanBone("LeftLowerArm", "LeftUpperArm", true), new HumanBone("LeftHand", "LeftLowerArm", true),
            new HumanBone("RightShoulder", "UpperChest", false), new HumanBone("RightUpperArm", "RightShoulder", true),
            new HumanBone("RightLowerArm", "RightUpperArm", true), new HumanBone("RightHand", "RightLowerArm", true),
        };

        private readonly KeyValuePair<string, string>[] _bones;
        private readonly int[] _joints;

        private HumanoidMapping(string mapName, KeyValuePair<string, string>[] bones, int[] joints)
        {
            MapName = mapName;
            _bones = bones;
            _joints = joints;
        }

        /// <summary>The built-in joint map whose names the skeleton follows (<see cref="JointMap.Name"/>, e.g. <c>cmu</c>).</summary>
        public string MapName { get; }

        /// <summary><c>HumanBodyBones</c> name → the joint (transform) that plays it, parents first.</summary>
        public IReadOnlyList<KeyValuePair<string, string>> Bones => _bones;

        /// <summary>The joint that plays <paramref name="humanName"/>, or null when no joint does.</summary>
        public string? JointOf(string humanName)
        {
            foreach (KeyValuePair<string, string> b in _bones) if (b.Key == humanName) return b.Value;
            return null;
        }

        /// <summary>The joint index that plays <paramref name="humanName"/> in the skeleton it was found on, or −1.</summary>
        internal int JointIndexOf(string humanName)
        {
            for (int i = 0; i < _bones.Length; i++) if (_bones[i].Key == humanName) return _joints[i];
            return -1;
        }

        /// <summary>
        /// The humanoid mapping of <paramref name="skeleton"/> through the built-in map that finds the most
        /// human bones, or null when no built-in map finds every required bone (the file then imports with a
        /// generic avatar).
        /// </summary>
        public static HumanoidMapping? Find(Skeleton skeleton)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            HumanoidMapping? best = null;
            foreach (JointMap map in JointMap.BuiltIn)
            {
                HumanoidMapping? found = Through(skeleton, map);
                if (found != null && (best == null || found._bones.Length > best._bones.Length)) best = found;
            }

            return best;
        }

        private static HumanoidMapping? Through(Skeleton skeleton, JointMap map)
        {
            // Candidates: each human bone's joint through the map (a chain's last joint, the one that turns
            // as the model joint does, as SkeletonMap reads it).
            var candidate = new Dictionary<string, int>(StringComparer.Ordinal);
            foreach (string modelJoint in JointMap.UnityHumanoid.TargetJoints)
            {
                IReadOnlyList<string>? human = JointMap.UnityHumanoid.SourceChain(modelJoint);
                IReadOnlyList<string>? chain = map.SourceChain(modelJoint);
                if (human == null || chain == null) continue;
                int[]? found = JointMap.FindChain(skeleton, chain);
                if (found != null) candidate[human[0]] = found[found.Length - 1];
            }

            foreach (HumanBone bone in Body)
            {
                if (bone.Required && !candidate.ContainsKey(bone.Name)) return null;
            }

            ReferencePose rest = ReferencePose.Default(skeleton);
            double tolerance = 1e-4 * Math.Max(BvhUnitScale.RestLegLength(skeleton), 1e-9);
            var children = new List<int>[skeleton.JointCount];
            for (int j = 0; j < children.Length; j++) children[j] = new List<int>();
            for (int j = 1; j < skeleton.JointCount; j++) children[skeleton.Parents[j]].Add(j);

            var chosen = new Dictionary<string, int>(StringComparer.Ordinal);
            foreach (HumanBone bone in Body)
            {
                if (!candidate.TryGetValue(bone.Name, out int joint)) continue;
                int parentJoint = MappedAncestor(bone, chosen);
                if (parentJoint >= 0 && Coincide(rest, joint, parentJoint, tolerance))
                {
                    joint = FirstApart(rest, children, joint, parentJoint, tolerance);
                    bool claimed = joint >= 0 && IsClaimed(candidate, chosen, bone.Name, joint);
                    if (joint < 0 || (claimed && !bone.Required))
                    {
                        if (bone.Required) return null;
                        continue;
                    }
                }

                chosen[bone.Name] = joint;
            }

            if (!chosen.ContainsKey("Chest") && chosen.TryGetValue("UpperChest", out int upper))
            {
                chosen.Remove("UpperChest");
                chosen["Chest"] = upper;
            }

            var bones = new List<KeyValuePair<string, string>>();
            var joints = new List<int>();
            var used = new HashSet<int>();
            foreach (HumanBone bone in Body)
            {
                if (!chosen.TryGetValue(bone.Name, out int joint)) continue;
                if (!used.Add(joint)) return null; // two bones on one joint: not a humanoid Unity accepts
                bones.Add(new KeyValuePair<string, string>(bone.Name, skeleton.Names[joint]));
                joints.Add(joint);
            }

            return new HumanoidMapping(map.Name, bones.ToArray(), joints.ToArray());
        }

        /// <summary>The joint of the nearest human ancestor already chosen, or −1 (the hips).</summary>
        private static int MappedAncestor(HumanBone bone, Dictionary<string, int> chosen)
        {
            string? parent = bone.Parent;
            while (parent != null)
            {
                if (chosen.TryGetValue(parent, out int joint)) return joint;
                parent = Array.Find(Body, b => b.Name == parent).Parent;
            }

            return -1;
        }

        private static bool Coincide(ReferencePose rest, int a, int b, double tolerance) =>
            a == b || (rest.GlobalPosition(a) - rest.GlobalPosition(b)).Length <= tolerance;

        /// <summary>Down through only children from <paramref name="joint"/> to the first joint away from <paramref name="parentJoint"/>, or −1.</summary>
        private static int FirstApart(ReferencePose rest, List<int>[] children, int joint, int parentJoint, double tolerance)
        {
            while (Coincide(rest, joint, parentJoint, tolerance))
            {
                if (children[joint].Count != 1) return -1;
                joint = children[joint][0];
            }

            return joint;
        }

        /// <summary>True when another human bone has <paramref name="joint"/> as its candidate or choice.</summary>
        private static bool IsClaimed(Dictionary<string, int> candidate, Dictionary<string, int> chosen, string bone, int joint)
        {
            foreach (KeyValuePair<string, int> c in candidate) if (c.Key != bone && c.Value == joint) return true;
            foreach (KeyValuePair<string, int> c in chosen) if (c.Key != bone && c.Value == joint) return true;
            return false;
        }

        /// <summary>The character's left in the rest pose (horizontal, unit): from the right thigh to the left one, else from hand to hand.</summary>
        internal Vector3D RestLeft(ReferencePose rest)
        {
            foreach ((string left, string right) in new[] { ("LeftUpperLeg", "RightUpperLeg"), ("LeftUpperArm", "RightUpperArm") })
            {
                Vector3D d = rest.GlobalPosition(JointIndexOf(left)) - rest.GlobalPosition(JointIndexOf(right));
                var flat = new Vector3D(d.X, 0.0, d.Z);
                if (flat.Length > 1e-9) return (1.0 / flat.Length) * flat;
            }

            return Vector3D.UnitX;
        }
    }
}
