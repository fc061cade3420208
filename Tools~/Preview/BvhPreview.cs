using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// A <see cref="PreviewScene"/> from named BVH files of one skeleton: each file read and refused when it
    /// has no frames, motion too large to draw, another skeleton or another frame rate than the first; an
    /// optional frame range cut from every file; key frames checked against the frames shown.
    /// </summary>
    public static class BvhPreview
    {
        /// <summary>Reads the files and builds the scene.</summary>
        /// <param name="tracks">Track names and BVH files, in the order shown.</param>
        /// <param name="range">Frames START..END (inclusive, frame indices of the files) to show, or null for all.</param>
        /// <param name="keys">Key frame indices of the files, increasing.</param>
        /// <param name="firstIsTruth">True when the first track is the ground truth the others are measured against.</param>
        /// <param name="map">A joint map (model joint → the files' joints) naming the hands and feet whose trails are drawn; null: found by name.</param>
        /// <param name="up">The files' up axis (<c>--up</c>): decided from the first file (the ground truth when there is one) and applied to every track, since they share one skeleton and one world; what was decided is <see cref="PreviewScene.UpAxisDescription"/>.</param>
        /// <exception cref="DataFormatException">A file cannot be shown with the others, a key lies outside the frames shown, the map names a hand or foot the files lack, or <c>--up z</c> is asked of a rig with no hips, head or feet to turn by.</exception>
        public static PreviewScene Build(IReadOnlyList<(string Name, string Path)> tracks, (int Start, int End)? range, IReadOnlyList<int> keys, bool firstIsTruth, JointMap? map = null, UpAxis up = UpAxis.Auto)
        {
            var clips = new List<(string Name, MotionClip Clip)>();
            BvhAnimation? first = null;
            UpAxisDecision? upright = null;
            string upDescription = "";
            foreach ((string name, string path) in tracks)
            {
                BvhAnimation animation = BvhReader.Read(path);
                if (animation.Motion.FrameCount == 0) throw new DataFormatException(path, "has no frames (Frames: 0)", "expected at least one frame to show");
                FinitePositions.Require(animation.Motion, path, "the motion");
                if (first == null)
                {
                    first = animation;
                    upright = DecideUp(animation, path, map, up, out upDescription);
                }
                else
                {
                    RequireSameKind(first, animation, path);
                }

                MotionClip motion = upright == null ? animation.Motion : upright.Apply(animation.Motion);
                clips.Add((name, Slice(motion, range, path)));
            }

            int frames = 0;
            foreach ((string _, MotionClip clip) in clips) frames = Math.Max(frames, clip.FrameCount);
            int offset = range?.Start ?? 0;
            var sceneKeys = new int[keys.Count];
            for (int i = 0; i < keys.Count; i++)
            {
                int key = keys[i];
                if (key - offset < 0 || key - offset >= frames)
                {
                    string where = range == null ? $"frames 0..{frames - 1} of the files" : $"the shown frames {offset}..{offset + frames - 1} (--frames)";
                    throw new DataFormatException("--keys", $"key frame {key} is outside {where}", "expected key frames inside them");
                }

                sceneKeys[i] = key - offset;
            }

            string title = Path.GetFileName(tracks[0].Path) + (range == null ? "" : $", frames {offset}–{offset + frames - 1}");
            PreviewScene scene = PreviewScene.FromClips(title, clips, sceneKeys, firstIsTruth ? 0 : -1);
            scene.FirstFrame = offset;
            scene.UpAxisDescription = upDescription;
            if (map != null) scene.Extremities = Extremities(map, first!.Skeleton, tracks[0].Path);
            return scene;
        }

        /// <summary>The model's hands and feet whose trails a preview draws.</summary>
        public static IReadOnlyList<string> ExtremityJoints { get; } = new[] { "LeftHand", "RightHand", "LeftFoot", "RightFoot" };

        /// <summary>
        /// The joints of <paramref name="skeleton"/> that play the model's hands and feet: the last joint of
        /// each one's chain in <paramref name="map"/>, or of a built-in map's chain when the map does not
        /// name it (as retargeting merges a partial map with the built-in names).
        /// </summary>
        /// <exception cref="DataFormatException">The map names a hand or foot joint the file lacks (a typo, another rig's map).</exception>
        public static int[] Extremities(JointMap map, Skeleton skeleton, string path)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            var joints = new List<int>();
            foreach (string name in ExtremityJoints)
            {
                IReadOnlyList<string>? chain = map.SourceChain(name);
                if (chain != null)
                {
                    int j = JointMap.FindJoint(skeleton, chain[chain.Count - 1]);
                    if (j < 0)
                    {
                        throw new DataFormatException(map.Name, $"maps {name} to '{chain[chain.Count - 1]}', which {Path.GetFileName(path)} lacks", "expected joint names of the files shown (--map is the map of their rig)");
                    }

                    joints.Add(j);
                    continue;
                }

                foreach (JointMap builtIn in JointMap.BuiltIn)
                {
                    IReadOnlyList<string>? fallback = builtIn.SourceChain(name);
                    int j = fallback == null ? -1 : JointMap.FindJoint(skeleton, fallback[fallback.Count - 1]);
                    if (j >= 0)
                    {
                        joints.Add(j);
                        break;
                    }
                }
            }

            return joints.ToArray();
        }

        /// <summary>
        /// The first file's up axis, as the verbs that retarget decide it (<see cref="UpAxisDecision"/>: its rest pose
        /// and its motion's floor), found by <paramref name="map"/> when it names the hips, head and feet, else by the
        /// built-in names; null when nothing is turned. A Z-up file is drawn standing, as retarget and bake see it.
        /// </summary>
        private static UpAxisDecision? DecideUp(BvhAnimation animation, string path, JointMap? map, UpAxis up, out string description)
        {
            ReferencePose rest = ReferencePose.Zero(animation.Skeleton);
            JointMap? body = map != null && UpAxisDetection.OfPose(rest, map) != null ? map : UpAxisDetection.BodyMap(animation.Skeleton);
            if (body == null)
            {
                if (up == UpAxis.Z)
                {
                    throw new DataFormatException(path, "--up z, but the skeleton has no hips, head and feet that a built-in map or --map finds to turn by",
                        "expected --map naming the rig's Hips, Head, LeftFoot and RightFoot");
                }

                description = $"up axis {UpAxes.Name(up)}: no hips, head or feet found in {Path.GetFileName(path)} to judge by (--map names them); drawn as written";
                return null;
            }

            UpAxisDecision decided = UpAxisDecision.Decide(up, rest, false, animation.Motion, body);
            description = decided.Description.Replace("turned to the model's Y up", "drawn turned to Y up", StringComparison.Ordinal)
                .Replace("nothing turned", "drawn as written", StringComparison.Ordinal) + $" (decided on {Path.GetFileName(path)}, applied to every track)";
            return decided.IsIdentity ? null : decided;
        }

        /// <summary>Refuses a file that cannot play beside the first: another skeleton or another frame rate.</summary>
        private static void RequireSameKind(BvhAnimation first, BvhAnimation animation, string path)
        {
            string? difference = PreviewScene.SkeletonDifference(first.Skeleton, animation.Skeleton);
            if (difference != null)
            {
                throw new DataFormatException(path, $"{difference} ({first.SourceName})", "expected the same skeleton in every file (retarget first)");
            }

            double a = first.Motion.FrameTime, b = animation.Motion.FrameTime;
            if (Math.Abs(a - b) > 1e-6 * a)
            {
                throw new DataFormatException(path, string.Format(CultureInfo.InvariantCulture, "{0:0.###} fps where {1} has {2:0.###} fps", 1 / b, first.SourceName, 1 / a), "expected one frame rate in every file");
            }
        }

        /// <summary>Frames START..END of a clip (END clipped to its last frame).</summary>
        private static MotionClip Slice(MotionClip clip, (int Start, int End)? range, string path)
        {
            if (range == null) return clip;
            (int start, int end) = range.Value;
            if (start >= clip.FrameCount)
            {
                throw new DataFormatException(path, $"--frames starts at {start} but the file has {clip.FrameCount} frames", $"expected a start below {clip.FrameCount}");
            }

            int last = Math.Min(end, clip.FrameCount - 1);
            int count = last - start + 1;
            int j = clip.Skeleton.JointCount;
            var positions = new double[count * j * 3];
            var rotations = new double[count * j * 4];
            Array.Copy(clip.LocalPositions, start * j * 3, positions, 0, positions.Length);
            Array.Copy(clip.LocalRotations, start * j * 4, rotations, 0, rotations.Length);
            return new MotionClip(clip.Skeleton, count, clip.FrameTime, positions, rotations);
        }
    }
}
