using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// Turns a BVH file into what Unity's <c>.bvh</c> importer makes of it (<see cref="BvhImportResult"/>):
    /// the file read by <see cref="BvhReader"/>, converted once to Unity's space through
    /// <see cref="Handedness"/> and to metres (<see cref="BvhUnitScale"/>), one key per frame at the file's
    /// frame rate, and a humanoid mapping with its T-pose when the joint names follow a built-in map.
    /// </summary>
    public static class BvhClipImport
    {
        /// <summary>Reads and converts the BVH file at <paramref name="path"/>.</summary>
        /// <param name="path">The file.</param>
        /// <param name="metresPerUnit">Metres per unit of the file; 0 (or less) to tell it from the skeleton's size.</param>
        /// <exception cref="BvhFormatException">The file is not valid BVH; the message names the file and line.</exception>
        /// <exception cref="DataFormatException">The unit cannot be told (no leg in the rest pose); the message names the file.</exception>
        /// <exception cref="InputPathException">The path is not a regular file.</exception>
        /// <exception cref="System.IO.IOException">The file cannot be read.</exception>
        /// <param name="up">The file's up axis (auto: decided from the file, as <c>inbetween --up</c>); a Z-up file is stood on Y.</param>
        public static BvhImportResult ImportFile(string path, double metresPerUnit = 0, UpAxis up = UpAxis.Auto)
        {
            byte[] data = InputFile.ReadAllBytes(path, "a .bvh file");
            return Import(data, path, metresPerUnit, up);
        }

        /// <summary>Converts BVH bytes; <paramref name="sourceName"/> names them in messages and gives the clip its name.</summary>
        /// <param name="data">The file's bytes.</param>
        /// <param name="sourceName">The file's path (the clip is named after its file name).</param>
        /// <param name="metresPerUnit">Metres per unit of the file; 0 (or less) to tell it from the skeleton's size.</param>
        /// <exception cref="BvhFormatException">The data is not valid BVH; the message names the source and line.</exception>
        /// <exception cref="DataFormatException">The unit cannot be told (no leg in the rest pose); the message names the source.</exception>
        /// <param name="up">The file's up axis (auto: decided from the file, as <c>inbetween --up</c>); a Z-up file is stood on Y.</param>
        public static BvhImportResult Import(byte[] data, string sourceName, double metresPerUnit = 0, UpAxis up = UpAxis.Auto)
        {
            string source = string.IsNullOrEmpty(sourceName) ? "<bvh>" : sourceName;
            BvhAnimation animation = BvhReader.Parse(data, source);
            UpAxisDecision? upDecision = StandOnY(ref animation, up);
            Skeleton skeleton = animation.Skeleton;
            MotionClip motion = animation.Motion;
            int jointCount = skeleton.JointCount;
            RequireBoundedPaths(skeleton, source);
            double scale = metresPerUnit > 0 && !double.IsInfinity(metresPerUnit) ? metresPerUnit : BvhUnitScale.Detect(skeleton, source);

            HumanoidMapping? humanoid = HumanoidMapping.Find(skeleton);
            double[] rest = humanoid != null ? HumanoidTPose.LocalRotations(skeleton, humanoid) : Identities(jointCount);
            Vector3D rootOffset = Vector3D.Read(skeleton.OffsetSpan, 0);
            var restPose = new ReferencePose(skeleton, rest, rootOffset);
            double lowest = double.PositiveInfinity;
            for (int j = 0; j < jointCount; j++) lowest = Math.Min(lowest, restPose.GlobalPosition(j).Y);
            // Stand the prefab on the ground: the file's rest root is often at the origin with the feet below it.
            Vector3D restRoot = rootOffset + new Vector3D(0.0, -lowest, 0.0);
            double legLength = scale * (rootOffset.Y - lowest);
            if (!FitsFloat(legLength))
            {
                throw new DataFormatException(source, $"its rest pose spans {legLength.ToString("R", System.Globalization.CultureInfo.InvariantCulture)} m from the root down", FloatRangeExpected);
            }

            string name = ClipName(source);
            var names = new HashSet<string>(skeleton.Names, StringComparer.Ordinal);
            string rootName = Unique(name, names);

            var joints = new ImportedJoint[jointCount];
            for (int j = 0; j < jointCount; j++)
            {
                int parent = skeleton.Parents[j];
                string path = parent < 0 ? skeleton.Names[j] : joints[parent].Path + "/" + skeleton.Names[j];
                Vector3D offset = j == 0 ? restRoot : Vector3D.Read(skeleton.OffsetSpan, 3 * j);
                if (!FitsFloat(scale * offset))
                {
                    string what = j == 0 ? "the root's rest position (raised to stand on the ground)" : "OFFSET";
                    throw new DataFormatException(source, $"joint '{Clip(skeleton.Names[j])}' has {what} {scale * offset} m, beyond float range", FloatRangeExpected);
                }

                bool positions = j == 0;
                foreach (BvhChannel c in animation.JointChannels[j]) positions |= !c.IsRotation();
                joints[j] = new ImportedJoint(
                    skeleton.Names[j],
                    parent,
                    path,
                    Handedness.PositionToUnity(scale * offset),
                    Handedness.RotationToUnity(QuaternionD.Read(rest, 4 * j)),
                    positions);
            }

            FigureBone[] figure = Figure(animation, joints, scale, legLength, names);
            double frameRate = FrameRate(motion.FrameTime);
            (float[] positionsUnity, float[] rotationsUnity) = Frames(motion, scale, source);
            IReadOnlyList<ClipCurve> curves = Curves(joints, motion.FrameCount, frameRate, positionsUnity, rotationsUnity);
            return new BvhImportResult(source, name, rootName, frameRate, motion.FrameCount, scale, legLength, joints, figure, humanoid, positionsUnity, rotationsUnity, curves)
            {
                UpAxis = upDecision?.Description,
                Turned = upDecision != null && !upDecision.IsIdentity,
            };
        }

        /// <summary>The animation stood on Y by <paramref name="up"/>'s decision (its rest pose and motion judged separately), with end sites turned like the bones.</summary>
        private static UpAxisDecision? StandOnY(ref BvhAnimation animation, UpAxis up)
        {
            JointMap? body = UpAxisDetection.BodyMap(animation.Skeleton);
            if (body == null) return null; // no hips, head and feet to judge by: the file is taken as it is
            UpAxisDecision decided = UpAxisDecision.Decide(up, ReferencePose.Zero(animation.Skeleton), false, animation.Motion, body);
            if (decided.IsIdentity) return decided;
            QuaternionD r = UpAxisDetection.ToYUp(decided.ReferenceUp);
            var sites = new Vector3D[animation.EndSites.Count][];
            for (int j = 0; j < sites.Length; j++)
            {
                sites[j] = new Vector3D[animation.EndSites[j].Length];
                for (int k = 0; k < sites[j].Length; k++) sites[j][k] = Quaternions.Apply(r, animation.EndSites[j][k]);
            }

            animation = new BvhAnimation(decided.Apply(animation.Motion), animation.JointChannels, sites, animation.SourceName);
            return decided;
        }

        /// <summary>
        /// The most characters all joints' transform paths may hold together (<see cref="ImportedJoint.Path"/>,
        /// which curve bindings need whole): 4,194,304, 8 MB of text. A humanoid's paths hold a few thousand; a
        /// chain of 16,000 joints each inside the last holds hundreds of millions (1.5 GB), so it is refused.
        /// </summary>
        public const long MaxPathCharacters = 1L << 22;

        /// <summary>
        /// Refuses, before any path is built, a hierarchy whose transform paths would not fit
        /// <see cref="MaxPathCharacters"/>: the sum is counted in one pass over the joints (a parent comes before its
        /// children in a BVH skeleton), so the check costs linear time and no memory per path.
        /// </summary>
        private static void RequireBoundedPaths(Skeleton skeleton, string source)
        {
            int count = skeleton.JointCount;
            var length = new long[count];
            var depth = new int[count];
            long total = 0;
            int deepest = 0;
            for (int j = 0; j < count; j++)
            {
                int parent = skeleton.Parents[j];
                length[j] = parent < 0 ? skeleton.Names[j].Length : length[parent] + 1 + skeleton.Names[j].Length;
                depth[j] = parent < 0 ? 1 : depth[parent] + 1;
                deepest = Math.Max(deepest, depth[j]);
                total += length[j];
                if (total > MaxPathCharacters)
                {
                    throw new DataFormatException(
                        source,
                        $"the transform paths of its {count} joints (nested up to {deepest} deep by joint {j}) exceed {MaxPathCharacters} characters",
                        $"expected a hierarchy whose joint paths hold at most {MaxPathCharacters} characters together (a humanoid's hold a few thousand); flatten the chain or split the file");
                }
            }
        }

        private const string FloatRangeExpected = "expected positions within float range (|x| up to 3.4e38 m, what Unity's transforms and curves hold); check the file's OFFSET and position channels, and its unit";

        private static bool FitsFloat(double value) => Math.Abs(value) <= float.MaxValue; // false for NaN and ±Infinity too

        private static bool FitsFloat(Vector3D v) => FitsFloat(v.X) && FitsFloat(v.Y) && FitsFloat(v.Z);

        private static string Clip(string name) => name.Length > 64 ? name.Substring(0, 64) + "…" : name;

        /// <summary>Frames per second from a frame time, whole when within 0.01 of a whole number.</summary>
        internal static double FrameRate(double frameTime)
        {
            double rate = 1.0 / frameTime;
            double whole = Math.Round(rate);
            return whole >= 1 && Math.Abs(rate - whole) <= 0.01 ? whole : rate;
        }

        private static double[] Identities(int count)
        {
            var q = new double[4 * count];
            for (int j = 0; j < count; j++) q[4 * j] = 1.0;
            return q;
        }

        private static string ClipName(string source)
        {
            int slash = Math.Max(source.LastIndexOf('/'), source.LastIndexOf('\\'));
            string file = source.Substring(slash + 1);
            int dot = file.LastIndexOf('.');
            string stem = dot > 0 ? file.Substring(0, dot) : file;
            return string.IsNullOrWhiteSpace(stem) ? "bvh" : stem;
        }

        /// <summary><paramref name="wanted"/>, or it with " 2", " 3", … when taken; the result is added to <paramref name="taken"/>.</summary>
        private static string Unique(string wanted, HashSet<string> taken)
        {
            string name = wanted;
            for (int k = 2; !taken.Add(name); k++) name = wanted + " " + k;
            return name;
        }

        private static FigureBone[] Figure(BvhAnimation animation, ImportedJoint[] joints, double scale, double legLength, HashSet<string> names)
        {
            Skeleton skeleton = animation.Skeleton;
            var pieces = new List<FigureBone>();
            // Each joint's children in one pass (file order): scanning every later joint for each joint was
            // quadratic (100,000 siblings took 7 s).
            var children = new List<int>[skeleton.JointCount];
            for (int c = 1; c < skeleton.JointCount; c++)
            {
                int parent = skeleton.Parents[c];
                if (parent >= 0) (children[parent] ??= new List<int>()).Add(c);
            }

            for (int j = 0; j < skeleton.JointCount; j++)
            {
                if (children[j] != null)
                {
                    foreach (int c in children[j]) AddPiece(pieces, j, skeleton.Names[c] + " bone", joints[c].RestPosition, legLength, names);
                }

                IReadOnlyList<Vector3D> sites = animation.EndSites[j];
                for (int s = 0; s < sites.Count; s++)
                {
                    string name = skeleton.Names[j] + " end" + (sites.Count > 1 ? " " + (s + 1) : "");
                    AddPiece(pieces, j, name, Handedness.PositionToUnity(scale * sites[s]), legLength, names);
                }
            }

            return pieces.ToArray();
        }

        private static void AddPiece(List<FigureBone> pieces, int joint, string name, Vector3D bone, double legLength, HashSet<string> names)
        {
            double length = bone.Length;
            // Zero-length joints (CMU's hip and shoulder joints sit on their parents) have nothing to show.
            if (length < 1e-6) return;
            double thickness = legLength > 0 ? Math.Min(0.06 * legLength, 0.5 * length) : 0.2 * length;
            QuaternionD along = Quaternions.Between(Vector3D.UnitY, bone, Vector3D.UnitZ);
            pieces.Add(new FigureBone(joint, Unique(name, names), 0.5 * bone, along, new Vector3D(thickness, length, thickness)));
        }

        /// <summary>Every frame's local positions (metres) and rotations ((x, y, z, w), one hemisphere per joint over time) in Unity space.</summary>
        private static (float[] Positions, float[] Rotations) Frames(MotionClip motion, double scale, string source)
        {
            int jointCount = motion.Skeleton.JointCount;
            var positions = new float[motion.FrameCount * jointCount * 3];
            var rotations = new float[motion.FrameCount * jointCount * 4];
            var previous = new QuaternionD[jointCount];
            for (int f = 0; f < motion.FrameCount; f++)
            {
                for (int j = 0; j < jointCount; j++)
                {
                    Vector3D p = Handedness.PositionToUnity(scale * Vector3D.Read(motion.LocalPositions, motion.PositionIndex(f, j)));
                    if (!FitsFloat(p))
                    {
                        // A float key of ±Infinity would put the character nowhere, silently.
                        throw new DataFormatException(source, $"frame {f}, joint '{Clip(motion.Skeleton.Names[j])}': position {p} m beyond float range", FloatRangeExpected);
                    }

                    int pi = motion.PositionIndex(f, j);
                    positions[pi] = (float)p.X;
                    positions[pi + 1] = (float)p.Y;
                    positions[pi + 2] = (float)p.Z;
                    QuaternionD q = Handedness.RotationToUnity(Quaternions.Normalize(QuaternionD.Read(motion.LocalRotations, motion.RotationIndex(f, j))));
                    // q and −q are one rotation, but curves interpolate components: stay in the previous key's hemisphere.
                    if (f > 0 && Quaternions.Dot(q, previous[j]) < 0) q = q.Negated;
                    previous[j] = q;
                    int ri = motion.RotationIndex(f, j);
                    rotations[ri] = (float)q.X;
                    rotations[ri + 1] = (float)q.Y;
                    rotations[ri + 2] = (float)q.Z;
                    rotations[ri + 3] = (float)q.W;
                }
            }

            return (positions, rotations);
        }

        /// <summary>The transform curves of an import's <paramref name="frames"/>, in that order, one key per frame from time 0 (a <see cref="BvhClipRange"/>).</summary>
        internal static IReadOnlyList<ClipCurve> Curves(BvhImportResult import, int[] frames)
        {
            var joints = new ImportedJoint[import.Joints.Count];
            for (int j = 0; j < joints.Length; j++) joints[j] = import.Joints[j];
            return Curves(joints, frames, import.FrameRate, import.LocalPositions, import.LocalRotations);
        }

        private static IReadOnlyList<ClipCurve> Curves(ImportedJoint[] joints, int frameCount, double frameRate, float[] positions, float[] rotations)
        {
            var frames = new int[frameCount];
            for (int f = 0; f < frameCount; f++) frames[f] = f;
            return Curves(joints, frames, frameRate, positions, rotations);
        }

        private static IReadOnlyList<ClipCurve> Curves(ImportedJoint[] joints, int[] frames, double frameRate, float[] positions, float[] rotations)
        {
            int frameCount = frames.Length;
            int jointCount = joints.Length;
            var times = new float[frameCount];
            for (int f = 0; f < frameCount; f++) times[f] = (float)(f / frameRate);
            var curves = new List<ClipCurve>();
            for (int j = 0; j < jointCount; j++)
            {
                for (int c = 0; c < 4; c++) curves.Add(ClipCurve.Create(joints[j].Path, CurveBuilder.RotationProperties[c], (float[])times.Clone(), Column(rotations, jointCount, 4, j, c, frames)));
            }

            for (int j = 0; j < jointCount; j++)
            {
                if (!joints[j].HasPositionCurves) continue;
                for (int c = 0; c < 3; c++) curves.Add(ClipCurve.Create(joints[j].Path, CurveBuilder.PositionProperties[c], (float[])times.Clone(), Column(positions, jointCount, 3, j, c, frames)));
            }

            return curves;
        }

        private static float[] Column(float[] values, int jointCount, int width, int joint, int component, int[] frames)
        {
            var column = new float[frames.Length];
            for (int f = 0; f < frames.Length; f++) column[f] = values[(frames[f] * jointCount + joint) * width + component];
            return column;
        }
    }
}
