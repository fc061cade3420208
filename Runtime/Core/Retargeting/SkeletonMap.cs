using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// Moves motion from a source skeleton (any humanoid: CMU, Mixamo, a Unity rig, another BVH) onto a
    /// target skeleton (the model's) and back, so that every mapped bone points the same way in the world
    /// on every frame.
    /// </summary>
    /// <remarks>
    /// <para><b>Correspondence.</b> A <see cref="JointMap"/> gives each target joint a chain of source
    /// joints. Target joint j turns as its chain's last source joint s(j) does. Every target joint must be
    /// found (otherwise <see cref="JointMapException"/> lists the missing ones); source joints outside the
    /// chains are unmapped: their rotations are folded into the next mapped joint below them on the way
    /// to the target and kept from the source clip on the way back.</para>
    /// <para><b>Reference poses.</b> Zero poses are not compared (LaFAN1's bones all point along +X at
    /// zero rotations). The target declares a reference pose (for the model
    /// <see cref="ReferencePose.ModelTPose"/>), the source gives one (its zero pose or a frame, e.g.
    /// CMU's T-pose at frame 0). The target's reference is first aligned to the source's: the root turns
    /// about +Y by the yaw that best matches the horizontal directions from the root to its children
    /// (to every mapped joint when those give none), so both face the same way; then, parents first,
    /// each target joint with exactly one child swings by the shortest arc that makes its bone point
    /// like the source's bone from s(j) to the first joint of the child's chain. A joint whose bone cannot be compared — several children (hips, chest),
    /// no child (hands, head, toes), or a zero-length bone on either side (CMU's LowerBack, Neck, hip and
    /// shoulder joints sit on their parents) — turns with its parent's alignment. The aligned pose keeps
    /// the declared twists, so the target's local rotations stay in the range it is used to.</para>
    /// <para><b>Rotations.</b> With G the reference global rotations (target aligned), the per-joint
    /// correction is C_j = G_s(j)⁻¹ · G_j. A target local rotation is q_j = C_p⁻¹ · (g_s(p)⁻¹ g_s(j)) · C_j,
    /// where the middle term is the product of the source's local rotations from below s(p) down to s(j);
    /// the root's is g_s(root) · C_root. So target globals are g_j = g_s(j) · C_j: every bone that was
    /// aligned points like the source's on every frame, and the map back is the exact inverse.</para>
    /// <para><b>Root.</b> The target root's position is the source's s(root) global position times
    /// <see cref="RootScale"/>: the ratio of the two skeletons' leg lengths, each measured as the root's
    /// height above its lowest mapped joint in the reference pose. It includes the unit change (CMU's
    /// 0.056444 m units to LaFAN1's centimetres) and the difference in size, so feet stay on the ground
    /// (Y = 0 in both) and strides keep their proportion to the legs. A caller that knows better (e.g.
    /// both files' units and no size change wanted) passes its own scale to <see cref="Create"/>.</para>
    /// <para><b>Joints the source lacks.</b> A target joint the map synthesizes (<see cref="JointMap.MayLack"/>)
    /// follows its parent's source joint: C_j = G_s(p)⁻¹ · G_j, so q_j = C_p⁻¹ · C_j is the aligned reference
    /// pose's local rotation on every frame (a rigid child at the reference offset), and its children map
    /// through it as through any joint. <see cref="SynthesizedJoints"/> names them.</para>
    /// <para><b>Frame rate.</b> Both directions keep the frame rate; use <see cref="MotionResampler"/>
    /// to reach the model's rate and back.</para>
    /// </remarks>
    public sealed class SkeletonMap
    {
        private readonly int[] _sourceOf;        // target joint → the last joint of its source chain
        private readonly int[] _sourceFirst;     // target joint → the first joint of its source chain
        private readonly int[][] _carried;       // target joint → source joints above s(j) on its path, top first
        private readonly QuaternionD[] _correction;
        private readonly double[] _scratchPositions;
        private readonly double[] _scratchRotations;

        private readonly bool[] _synthesized;     // target joint → true when the source lacks it (rigid child of its parent)
        private readonly QuaternionD _world;      // the source motion's world → the model's Y-up world (identity for Y-up files)

        private SkeletonMap(ReferencePose source, ReferencePose target, JointMap map, MapChains chains, double? rootScale, string sourceName, UpAxisDecision? up)
        {
            SourceReference = source;
            Up = up;
            _world = up?.MotionToYUp ?? QuaternionD.Identity;
            int[] sourceOf = chains.SourceOf, sourceFirst = chains.SourceFirst;
            bool[] synthesized = chains.Synthesized;
            _synthesized = synthesized;
            var made = new List<string>();
            for (int j = 0; j < synthesized.Length; j++) if (synthesized[j]) made.Add(target.Skeleton.Names[j]);
            SynthesizedJoints = made;
            Map = map;
            _sourceOf = sourceOf;
            _sourceFirst = sourceFirst;
            _carried = chains.Carried;
            Skeleton ts = target.Skeleton, ss = source.Skeleton;
            int jt = ts.JointCount;

            // 1. Align the target's declared reference to the source's.
            var declared = new QuaternionD[jt];
            for (int j = 0; j < jt; j++) declared[j] = target.GlobalRotation(j);
            QuaternionD[] align = ReferenceAlignment.Align(source, target, sourceOf, sourceFirst, out bool[] aligned);

            var targetLocal = new double[4 * jt];
            var global = new QuaternionD[jt];
            _correction = new QuaternionD[jt];
            for (int j = 0; j < jt; j++)
            {
                global[j] = Quaternions.Normalize(Quaternions.Multiply(align[j], declared[j]));
                int p = ts.Parents[j];
                QuaternionD local = p < 0 ? global[j] : Quaternions.Multiply(Quaternions.Conjugate(global[p]), global[j]);
                Quaternions.Normalize(local).Write(targetLocal, 4 * j);
                _correction[j] = Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(source.GlobalRotation(sourceOf[j])), global[j]));
            }

            TargetReference = new ReferencePose(ts, targetLocal, target.RootPosition);
            AlignedBones = aligned;

            // 2. Root scale from the leg lengths of the two reference poses.
            var sourceMeasured = new List<int>();
            for (int j = 0; j < jt; j++) if (!synthesized[j]) sourceMeasured.Add(sourceFirst[j]);
            SourceLegLength = LegLengths.Measure(source, sourceMeasured.ToArray(), sourceOf[0]);
            // Like with like: the target is measured down to its lowest joint that the source has too (a rig
            // without toes is measured to the ankles on both sides).
            var measured = new List<int>();
            for (int j = 0; j < jt; j++) if (!synthesized[j]) measured.Add(j);
            TargetLegLength = LegLengths.Measure(TargetReference, measured.ToArray(), 0);
            if (rootScale == null && (!(SourceLegLength > 0) || !(TargetLegLength > 0)))
            {
                // Named by the file whose pose it is (the map's name alone would hide which input is at fault).
                double standing = LegLengths.Measure(target, measured.ToArray(), 0);
                throw new JointMapException(sourceName, string.Format(System.Globalization.CultureInfo.InvariantCulture,
                    "the reference pose does not stand on Y: its hips are {0:0.###} (file units) above its lowest mapped joint, so the model's T-pose turned to match it has its hips {1:0.###} above its feet instead of {2:0.###} (joint map '{3}')",
                    SourceLegLength, TargetLegLength, standing, map.Name),
                    "expected a reference pose standing upright on Y with the feet below the hips; name a standing frame with --reference-frame, or pass the --up (auto, y or z) that matches the file");
            }

            RootScale = rootScale ?? TargetLegLength / SourceLegLength;

            _scratchPositions = new double[3 * ss.JointCount];
            _scratchRotations = new double[4 * ss.JointCount];
            var unmapped = new List<string>();
            var inChains = new bool[ss.JointCount];
            for (int j = 0; j < jt; j++)
            {
                if (synthesized[j]) continue;
                IReadOnlyList<string> chain = map.SourceChain(ts.Names[j])!;
                foreach (string n in chain) inChains[JointMap.FindJoint(ss, n)] = true;
            }

            for (int s = 0; s < ss.JointCount; s++)
            {
                if (!inChains[s]) unmapped.Add(ss.Names[s]);
            }

            UnmappedSourceJoints = unmapped;
        }

        /// <summary>The source skeleton's reference pose (stood on Y when <see cref="Up"/> turned it).</summary>
        public ReferencePose SourceReference { get; }

        /// <summary>The target skeleton's reference pose after alignment to the source's (the declared pose with corrected bone directions).</summary>
        public ReferencePose TargetReference { get; }

        /// <summary>The up axes the source was read with, or null when none was decided (a Y-up source).</summary>
        public UpAxisDecision? Up { get; }

        /// <summary>The joint correspondence used.</summary>
        public JointMap Map { get; }

        /// <summary>The source skeleton.</summary>
        public Skeleton Source => SourceReference.Skeleton;

        /// <summary>The target skeleton.</summary>
        public Skeleton Target => TargetReference.Skeleton;

        /// <summary>Target units per source unit for the root's position (target leg length ÷ source leg length).</summary>
        public double RootScale { get; }

        /// <summary>The source's leg length in its units: the root's height above its lowest mapped joint in the reference pose.</summary>
        public double SourceLegLength { get; }

        /// <summary>The target's leg length in its units, measured the same way on its aligned reference pose.</summary>
        public double TargetLegLength { get; }

        /// <summary>
        /// Target joints the source skeleton lacks (e.g. the toes and Spine2 of a Poser rig), in target order:
        /// each is a rigid child of its parent at the aligned reference pose's offset, so its local rotation
        /// is constant; mapping back ignores it. Tools print these names ("made up").
        /// </summary>
        public IReadOnlyList<string> SynthesizedJoints { get; }

        /// <summary>True when target joint <paramref name="targetJoint"/> is synthesized (see <see cref="SynthesizedJoints"/>).</summary>
        public bool IsSynthesized(int targetJoint) => _synthesized[targetJoint];

        /// <summary>Source joints outside every chain (they keep the source clip's rotations on the way back).</summary>
        public IReadOnlyList<string> UnmappedSourceJoints { get; }

        /// <summary>
        /// Per target joint: true when its bone (to its only child) was aligned to the source's, so its world
        /// direction follows the source bone on every frame; false for the root, joints with several or no
        /// children, and zero-length bones (they turn with their parent's alignment).
        /// </summary>
        public IReadOnlyList<bool> AlignedBones { get; }

        /// <summary>The source joint whose rotation target joint <paramref name="targetJoint"/> follows (the last of its chain).</summary>
        public int SourceJointOf(int targetJoint) => _sourceOf[targetJoint];

        /// <summary>
        /// Builds the map between <paramref name="source"/> and <paramref name="target"/>.
        /// </summary>
        /// <param name="source">The source skeleton's reference pose.</param>
        /// <param name="target">The target skeleton's declared reference pose (<see cref="ReferencePose.ModelTPose"/> for the model).</param>
        /// <param name="map">The correspondence; null picks the best built-in one (<see cref="JointMap.Detect"/>).</param>
        /// <param name="sourceName">The source's file or name, for messages.</param>
        /// <param name="rootScale">Target units per source unit for the root's position; null (the default) for the ratio of leg lengths.</param>
        /// <param name="up">The source's up axes (<see cref="UpAxisDecision.Decide"/>): its reference pose is stood on Y and its motion turned to Y up on the way to the target (and back); null for a Y-up source.</param>
        /// <exception cref="JointMapException">Target joints are missing from the source (all named), or a chain does not fit the source's hierarchy.</exception>
        public static SkeletonMap Create(ReferencePose source, ReferencePose target, JointMap? map, string sourceName, double? rootScale = null, UpAxisDecision? up = null)
        {
            if (rootScale.HasValue && (!(rootScale.Value > 0) || double.IsInfinity(rootScale.Value)))
            {
                throw new ArgumentOutOfRangeException(nameof(rootScale), "the root scale must be a positive number");
            }

            if (source == null) throw new ArgumentNullException(nameof(source));
            if (target == null) throw new ArgumentNullException(nameof(target));
            sourceName ??= "<source>";
            Skeleton ss = source.Skeleton, ts = target.Skeleton;
            map ??= JointMap.Detect(ss, ts);
            MapChains chains = MapChains.Resolve(ss, ts, map, sourceName);
            return new SkeletonMap(up == null ? source : up.Turn(source), target, map, chains, rootScale, sourceName, up);
        }

        /// <summary>
        /// The source motion on the target skeleton, at the source's frame rate: mapped rotations through the
        /// corrections, the root's position scaled by <see cref="RootScale"/>, the other joints at the
        /// target's offsets.
        /// </summary>
        public MotionClip ToTarget(MotionClip source)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            RequireSkeleton(source.Skeleton, Source, "source");
            int js = Source.JointCount, jt = Target.JointCount, n = source.FrameCount;
            var positions = new double[n * jt * 3];
            var rotations = new double[n * jt * 4];
            ReadOnlySpan<double> targetOffsets = Target.OffsetSpan;
            for (int f = 0; f < n; f++)
            {
                Span<double> tp = positions.AsSpan(f * jt * 3, jt * 3);
                targetOffsets.CopyTo(tp);
                ToTargetFrame(source.LocalPositions.AsSpan(source.PositionIndex(f, 0), 3 * js), source.LocalRotations.AsSpan(source.RotationIndex(f, 0), 4 * js),
                    tp.Slice(0, 3), rotations.AsSpan(f * jt * 4, jt * 4));
            }

            Quaternions.FixContinuity(rotations, n, jt);
            return new MotionClip(Target, n, source.FrameTime, positions, rotations);
        }

        /// <summary>
        /// One pose from the source skeleton onto the target's (allocation-free; uses scratch memory of this
        /// map, so one thread at a time per map).
        /// </summary>
        /// <param name="sourceLocalPositions">Source joints × 3 local translations (the root's is its position).</param>
        /// <param name="sourceLocalRotations">Source joints × 4 local rotations (w, x, y, z).</param>
        /// <param name="targetRootPosition">Output: the target root's position (3 values).</param>
        /// <param name="targetLocalRotations">Output: target joints × 4 local rotations.</param>
        public void ToTargetFrame(ReadOnlySpan<double> sourceLocalPositions, ReadOnlySpan<double> sourceLocalRotations, Span<double> targetRootPosition, Span<double> targetLocalRotations)
        {
            int js = Source.JointCount, jt = Target.JointCount;
            if (sourceLocalPositions.Length < 3 * js || sourceLocalRotations.Length < 4 * js || targetRootPosition.Length < 3 || targetLocalRotations.Length < 4 * jt)
            {
                throw new ArgumentException("a span is too short; expected source joints × 3 and × 4, 3, and target joints × 4 values");
            }

            double[] gPos = _scratchPositions, gRot = _scratchRotations;
            ForwardKinematics.ComputeFrame(Source.ParentSpan, sourceLocalPositions, Vector3D.Read(sourceLocalPositions, 0), sourceLocalRotations, gPos, gRot);
            ReadOnlySpan<int> parents = Target.ParentSpan;
            for (int j = 0; j < jt; j++)
            {
                QuaternionD g = QuaternionD.Read(gRot, 4 * _sourceOf[j]);
                QuaternionD q;
                if (j == 0)
                {
                    q = Quaternions.Multiply(_world, Quaternions.Multiply(g, _correction[0]));
                }
                else
                {
                    int p = parents[j];
                    QuaternionD relative = Quaternions.Multiply(Quaternions.Conjugate(QuaternionD.Read(gRot, 4 * _sourceOf[p])), g);
                    q = Quaternions.Multiply(Quaternions.Conjugate(_correction[p]), Quaternions.Multiply(relative, _correction[j]));
                }

                Quaternions.Normalize(q).Write(targetLocalRotations, 4 * j);
            }

            (RootScale * Quaternions.Apply(_world, Vector3D.Read(gPos, 3 * _sourceOf[0]))).Write(targetRootPosition, 0);
        }

        /// <summary>
        /// Target motion back on the source skeleton, at the target clip's frame times (frame i at
        /// i × its frame time, measured from the source clip's frame 0). Mapped joints get the exact inverse
        /// of <see cref="ToTarget"/>; every other value (unmapped joints, the leading joints of a chain,
        /// non-root translations) comes from <paramref name="source"/> at the same time, by SLERP (LERP for
        /// translations) between the source frames around it — or, when <paramref name="sourceKeyFrames"/>
        /// is given, between the key frames around it (before the first key the first is held, after the
        /// last the last), for a source that only holds valid poses at its keys.
        /// </summary>
        /// <param name="target">Dense motion on the target skeleton.</param>
        /// <param name="source">The source clip the unmapped values come from (on <see cref="Source"/>).</param>
        /// <param name="sourceKeyFrames">Optional strictly increasing frame indices of <paramref name="source"/> that hold valid poses.</param>
        public MotionClip ToSource(MotionClip target, MotionClip source, IReadOnlyList<int>? sourceKeyFrames = null)
        {
            if (target == null) throw new ArgumentNullException(nameof(target));
            if (source == null) throw new ArgumentNullException(nameof(source));
            RequireSkeleton(target.Skeleton, Target, "target");
            RequireSkeleton(source.Skeleton, Source, "source");
            if (source.FrameCount == 0) throw new ArgumentException("the source clip has no frames", nameof(source));
            int[]? keys = SourceKeyFrames.Check(sourceKeyFrames, source.FrameCount);
            int js = Source.JointCount, jt = Target.JointCount, n = target.FrameCount;
            var positions = new double[n * js * 3];
            var rotations = new double[n * js * 4];
            for (int f = 0; f < n; f++)
            {
                Span<double> lp = positions.AsSpan(f * js * 3, js * 3);
                Span<double> lr = rotations.AsSpan(f * js * 4, js * 4);
                double sourceFrame = f * target.FrameTime / source.FrameTime;
                if (keys == null)
                {
                    MotionResampler.Sample(source, sourceFrame, lp, lr);
                }
                else
                {
                    SourceKeyFrames.Sample(source, keys, sourceFrame, lp, lr);
                }

                ToSourceFrame(Vector3D.Read(target.LocalPositions, target.PositionIndex(f, 0)), target.LocalRotations.AsSpan(target.RotationIndex(f, 0), jt * 4), lp, lr);
            }

            Quaternions.FixContinuity(rotations, n, js);
            return new MotionClip(Source, n, target.FrameTime, positions, rotations);
        }

        /// <summary>
        /// One target pose back onto the source skeleton, in place (allocation-free): on input the source
        /// spans hold a source pose that supplies every unmapped value (e.g. the character's current pose);
        /// on output the mapped joints' rotations and the root's position are replaced.
        /// </summary>
        /// <param name="targetRootPosition">The target root's position.</param>
        /// <param name="targetLocalRotations">Target joints × 4 local rotations.</param>
        /// <param name="sourceLocalPositions">In/out: source joints × 3 local translations (only the root's is written).</param>
        /// <param name="sourceLocalRotations">In/out: source joints × 4 local rotations.</param>
        public void ToSourceFrame(Vector3D targetRootPosition, ReadOnlySpan<double> targetLocalRotations, Span<double> sourceLocalPositions, Span<double> sourceLocalRotations)
        {
            int js = Source.JointCount, jt = Target.JointCount;
            if (targetLocalRotations.Length < 4 * jt || sourceLocalPositions.Length < 3 * js || sourceLocalRotations.Length < 4 * js)
            {
                throw new ArgumentException("a span is too short; expected target joints × 4, and source joints × 3 and × 4 values");
            }

            ReadOnlySpan<int> parents = Target.ParentSpan;
            for (int j = 0; j < jt; j++)
            {
                if (_synthesized[j]) continue; // nothing in the source to write: the joint was made up
                QuaternionD qt = QuaternionD.Read(targetLocalRotations, 4 * j);
                // The source-side rotation from s(parent) to s(j) (for the root: its global rotation).
                QuaternionD wanted = j == 0
                    ? Quaternions.Multiply(Quaternions.Conjugate(_world), Quaternions.Multiply(qt, Quaternions.Conjugate(_correction[0])))
                    : Quaternions.Multiply(_correction[parents[j]], Quaternions.Multiply(qt, Quaternions.Conjugate(_correction[j])));
                QuaternionD above = QuaternionD.Identity;
                int[] carried = _carried[j];
                for (int i = 0; i < carried.Length; i++) above = Quaternions.Multiply(above, QuaternionD.Read(sourceLocalRotations, 4 * carried[i]));
                Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(above), wanted)).Write(sourceLocalRotations, 4 * _sourceOf[j]);
            }

            // The root: place the source root so that s(root) lands at the target root ÷ scale.
            Vector3D hips = (1.0 / RootScale) * Quaternions.Apply(Quaternions.Conjugate(_world), targetRootPosition);
            int[] path = _carried[0];
            if (path.Length == 0)
            {
                hips.Write(sourceLocalPositions, 0);
                return;
            }

            Vector3D offset = Vector3D.Zero;
            QuaternionD g = QuaternionD.Read(sourceLocalRotations, 0);
            for (int i = 1; i <= path.Length; i++)
            {
                int s = i < path.Length ? path[i] : _sourceOf[0];
                offset = offset + Quaternions.Apply(g, Vector3D.Read(sourceLocalPositions, 3 * s));
                if (i < path.Length) g = Quaternions.Multiply(g, QuaternionD.Read(sourceLocalRotations, 4 * s));
            }

            (hips - offset).Write(sourceLocalPositions, 0);
        }

        private static void RequireSkeleton(Skeleton given, Skeleton expected, string what)
        {
            if (!ReferenceEquals(given, expected) && !given.HasSameHierarchy(expected))
            {
                throw new ArgumentException($"the {what} clip is not on the map's {what} skeleton", what);
            }
        }
    }
}
