using System;
using System.Collections.Generic;
using System.Linq;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// What a preview shows: tracks of one skeleton played side by side and in sync at one frame rate,
    /// the key frames (marked on the timeline and highlighted on the skeletons) and, optionally, which
    /// track is the ground truth the others are measured against (per-frame error plot).
    /// Tracks may differ in length: the scene is as long as the longest; a shorter track holds its last
    /// frame, and errors are measured over the frames both tracks have.
    /// </summary>
    public sealed class PreviewScene
    {
        private readonly string[] _jointNames;
        private readonly int[] _parents;
        private readonly PreviewTrack[] _tracks;
        private readonly int[] _keyFrames;

        /// <summary>Creates a validated scene.</summary>
        /// <param name="title">Heading of the page and the sheet, e.g. the source file's name.</param>
        /// <param name="jointNames">Joint names in hierarchy order.</param>
        /// <param name="parents">Parent index per joint (−1 for the root, otherwise a smaller index).</param>
        /// <param name="frameTime">Seconds per frame (&gt; 0); playback runs at 1 / frameTime frames per second.</param>
        /// <param name="tracks">At least one track, every one with <paramref name="jointNames"/>' joint count.</param>
        /// <param name="keyFrames">Key frame indices, strictly increasing, inside the scene (empty for none).</param>
        /// <param name="groundTruthTrack">Index of the ground-truth track, or −1 when there is none.</param>
        /// <exception cref="ArgumentException">Anything above does not hold; the message says what.</exception>
        public PreviewScene(
            string title,
            IReadOnlyList<string> jointNames,
            IReadOnlyList<int> parents,
            double frameTime,
            IReadOnlyList<PreviewTrack> tracks,
            IReadOnlyList<int>? keyFrames = null,
            int groundTruthTrack = -1)
        {
            if (jointNames == null) throw new ArgumentNullException(nameof(jointNames));
            if (parents == null) throw new ArgumentNullException(nameof(parents));
            if (tracks == null) throw new ArgumentNullException(nameof(tracks));
            if (jointNames.Count == 0 || parents.Count != jointNames.Count)
            {
                throw new ArgumentException($"{jointNames.Count} joint names and {parents.Count} parents; expected one parent per joint", nameof(parents));
            }

            for (int j = 0; j < parents.Count; j++)
            {
                if ((j == 0 && parents[j] != -1) || (j > 0 && (parents[j] < 0 || parents[j] >= j)))
                {
                    throw new ArgumentException($"joint {j} has parent {parents[j]}; expected the root first and every parent before its children", nameof(parents));
                }
            }

            if (!(frameTime > 0) || double.IsInfinity(frameTime))
            {
                throw new ArgumentOutOfRangeException(nameof(frameTime), "frame time must be a positive number of seconds");
            }

            if (tracks.Count == 0) throw new ArgumentException("a scene needs at least one track", nameof(tracks));
            foreach (PreviewTrack track in tracks)
            {
                if (track == null) throw new ArgumentNullException(nameof(tracks), "a track is null");
                if (track.JointCount != jointNames.Count)
                {
                    throw new ArgumentException($"track '{track.Name}' has {track.JointCount} joints; expected {jointNames.Count} like the skeleton", nameof(tracks));
                }
            }

            if (groundTruthTrack < -1 || groundTruthTrack >= tracks.Count)
            {
                throw new ArgumentOutOfRangeException(nameof(groundTruthTrack), $"ground-truth track {groundTruthTrack} is not −1 or a track index below {tracks.Count}");
            }

            int frames = tracks.Max(t => t.FrameCount);
            int[] keys = keyFrames?.ToArray() ?? Array.Empty<int>();
            for (int i = 0; i < keys.Length; i++)
            {
                if (keys[i] < 0 || keys[i] >= frames)
                {
                    throw new ArgumentOutOfRangeException(nameof(keyFrames), $"key frame {keys[i]} is outside frames 0..{frames - 1}");
                }

                if (i > 0 && keys[i] <= keys[i - 1])
                {
                    throw new ArgumentException($"key frames {keys[i - 1]} and {keys[i]} are not strictly increasing", nameof(keyFrames));
                }
            }

            Title = title ?? "";
            _jointNames = jointNames.ToArray();
            _parents = parents.ToArray();
            FrameTime = frameTime;
            _tracks = tracks.ToArray();
            _keyFrames = keys;
            GroundTruthTrack = groundTruthTrack;
            FrameCount = frames;
            (BodyRoot, _drawsBone) = FindBodyRoot(_parents);
        }

        /// <summary>
        /// The body's root — the first joint with two or more children (the hips of a humanoid) — and which
        /// joints' bones to their parents are drawn: not those on the chain from the file's root down to the
        /// body root. Such joints (a "Reference" node at the world origin, a root projected on the floor)
        /// are not anatomy, and a bone from one to the hips would read as a third leg. A skeleton without
        /// a branch is one chain: its root is the body root and every bone is drawn.
        /// </summary>
        private static (int BodyRoot, bool[] DrawsBone) FindBodyRoot(int[] parents)
        {
            var children = new int[parents.Length];
            for (int j = 1; j < parents.Length; j++) children[parents[j]]++;
            int body = 0;
            for (int j = 0; j < parents.Length; j++)
            {
                if (children[j] >= 2)
                {
                    body = j;
                    break;
                }
            }

            var draws = new bool[parents.Length];
            for (int j = 1; j < parents.Length; j++) draws[j] = true;
            for (int j = body; j > 0; j = parents[j]) draws[j] = false;
            return (body, draws);
        }

        /// <summary>
        /// A scene of clips on one skeleton (global positions by forward kinematics). The first clip's
        /// skeleton names the joints and its frame time sets the frame rate.
        /// </summary>
        /// <param name="title">Heading of the page and the sheet.</param>
        /// <param name="clips">Named clips, in the order they are shown.</param>
        /// <param name="keyFrames">Key frame indices (or null).</param>
        /// <param name="groundTruthTrack">Index of the ground-truth clip, or −1.</param>
        /// <exception cref="ArgumentException">The clips' skeletons differ in joints or parents, or their frame rates differ.</exception>
        public static PreviewScene FromClips(string title, IReadOnlyList<(string Name, MotionClip Clip)> clips, IReadOnlyList<int>? keyFrames = null, int groundTruthTrack = -1)
        {
            if (clips == null || clips.Count == 0) throw new ArgumentException("a scene needs at least one clip", nameof(clips));
            Skeleton skeleton = clips[0].Clip.Skeleton;
            var tracks = new List<PreviewTrack>(clips.Count);
            foreach ((string name, MotionClip clip) in clips)
            {
                string? difference = SkeletonDifference(skeleton, clip.Skeleton);
                if (difference != null)
                {
                    throw new ArgumentException($"clip '{name}': {difference}", nameof(clips));
                }

                double frameTime = clips[0].Clip.FrameTime;
                if (Math.Abs(clip.FrameTime - frameTime) > 1e-6 * frameTime)
                {
                    throw new ArgumentException($"clip '{name}': {1 / clip.FrameTime:0.###} fps where the first has {1 / frameTime:0.###} fps; expected one frame rate (resample first)", nameof(clips));
                }

                tracks.Add(PreviewTrack.FromClip(name, clip));
            }

            return new PreviewScene(title, skeleton.Names, skeleton.Parents, clips[0].Clip.FrameTime, tracks, keyFrames, groundTruthTrack)
            {
                MetresPerUnit = UnitOf(skeleton),
            };
        }

        // The file's unit as the BVH importer tells it (from the leg length), so errors read in centimetres;
        // null when the skeleton has no leg to measure.
        private static double? UnitOf(Skeleton skeleton)
        {
            try
            {
                return DeltaInterpolator.Core.BvhImport.BvhUnitScale.Detect(skeleton, "the scene");
            }
            catch (DeltaInterpolator.Core.DataFormatException)
            {
                return null;
            }
        }

        /// <summary>
        /// Why <paramref name="other"/> is not the same skeleton as <paramref name="reference"/> (same joint
        /// names and parents in the same order), or null when it is.
        /// </summary>
        public static string? SkeletonDifference(Skeleton reference, Skeleton other)
        {
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            if (other == null) throw new ArgumentNullException(nameof(other));
            if (reference.JointCount != other.JointCount)
            {
                return $"{other.JointCount} joints where the first has {reference.JointCount}";
            }

            for (int j = 0; j < reference.JointCount; j++)
            {
                if (!string.Equals(reference.Names[j], other.Names[j], StringComparison.Ordinal))
                {
                    return $"joint {j} is '{other.Names[j]}' where the first has '{reference.Names[j]}'";
                }

                if (reference.Parents[j] != other.Parents[j])
                {
                    return $"joint {j} ('{other.Names[j]}') has parent {other.Parents[j]} where the first has {reference.Parents[j]}";
                }
            }

            return null;
        }

        private readonly bool[] _drawsBone;
        private int _firstFrame;
        private int[]? _extremities;

        /// <summary>Heading of the page and the sheet.</summary>
        public string Title { get; }

        /// <summary>
        /// The file's frame number of the scene's frame 0 (e.g. START of <c>--frames START-END</c>): frame
        /// labels on the page and the sheet are the file's, so they match the keys the user typed.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">A negative number.</exception>
        public int FirstFrame
        {
            get => _firstFrame;
            set => _firstFrame = value >= 0 ? value : throw new ArgumentOutOfRangeException(nameof(FirstFrame), $"first frame {value}; expected a frame number of 0 or more");
        }

        /// <summary>
        /// The hands and feet whose trails are drawn (joint indices), e.g. from a joint map; null: found by
        /// their names (LeftHand, l_foot, …).
        /// </summary>
        /// <exception cref="ArgumentException">An index outside the skeleton.</exception>
        public IReadOnlyList<int>? Extremities
        {
            get => _extremities;
            set
            {
                if (value != null)
                {
                    foreach (int j in value)
                    {
                        if (j < 0 || j >= _jointNames.Length)
                        {
                            throw new ArgumentException($"extremity joint {j} is outside the skeleton's {_jointNames.Length} joints", nameof(Extremities));
                        }
                    }
                }

                _extremities = value?.ToArray();
            }
        }

        /// <summary>
        /// What the files' up axis was taken to be and whether they were turned to stand on Y (e.g. "up axis auto:
        /// motion Z-up (…), reference pose Z-up (the rest pose); drawn turned to Y up"), for the console; empty for a
        /// scene not read from files.
        /// </summary>
        public string UpAxisDescription { get; set; } = "";

        /// <summary>
        /// Metres per data unit, when known (from the skeleton's leg length for a scene of clips): errors
        /// are then shown in centimetres; null: in data units.
        /// </summary>
        public double? MetresPerUnit { get; set; }

        /// <summary>
        /// A distance in data units as people read it: "3.2 cm" when <see cref="MetresPerUnit"/> is known,
        /// else "0.123 data units".
        /// </summary>
        public string FormatDistance(double value)
        {
            if (MetresPerUnit is double m && m > 0)
            {
                double cm = value * m * 100;
                return cm.ToString(cm >= 10 ? "0" : cm >= 1 ? "0.0" : "0.00", System.Globalization.CultureInfo.InvariantCulture) + " cm";
            }

            return value.ToString("0.###", System.Globalization.CultureInfo.InvariantCulture) + " data units";
        }

        /// <summary>The body's root (the hips of a humanoid): what the camera follows and the root trail shows.</summary>
        public int BodyRoot { get; }

        /// <summary>Whether the bone from <paramref name="joint"/>'s parent to it is drawn (false for the root and for joints above the body root).</summary>
        public bool DrawsBone(int joint) => _drawsBone[joint];

        /// <summary>Joint names in hierarchy order.</summary>
        public IReadOnlyList<string> JointNames => _jointNames;

        /// <summary>Parent index per joint (−1 for the root).</summary>
        public IReadOnlyList<int> Parents => _parents;

        /// <summary>Number of joints.</summary>
        public int JointCount => _jointNames.Length;

        /// <summary>Seconds per frame.</summary>
        public double FrameTime { get; }

        /// <summary>Frames in the scene: the longest track's.</summary>
        public int FrameCount { get; }

        /// <summary>The tracks, in the order they are shown.</summary>
        public IReadOnlyList<PreviewTrack> Tracks => _tracks;

        /// <summary>Key frame indices, strictly increasing.</summary>
        public IReadOnlyList<int> KeyFrames => _keyFrames;

        /// <summary>Index of the ground-truth track, or −1 when there is none.</summary>
        public int GroundTruthTrack { get; }

        /// <summary>
        /// Mean joint position error of <paramref name="track"/> against the ground truth on each frame both
        /// have (Euclidean distance per joint, averaged over joints, in the data's units).
        /// </summary>
        /// <exception cref="InvalidOperationException">The scene has no ground truth.</exception>
        public double[] ErrorPerFrame(int track)
        {
            if (GroundTruthTrack < 0) throw new InvalidOperationException("the scene has no ground-truth track to measure against");
            PreviewTrack truth = _tracks[GroundTruthTrack];
            PreviewTrack other = _tracks[track];
            int frames = Math.Min(truth.FrameCount, other.FrameCount);
            int values = JointCount * 3;
            var errors = new double[frames];
            for (int f = 0; f < frames; f++)
            {
                double sum = 0;
                for (int i = f * values; i < (f + 1) * values; i += 3)
                {
                    double dx = other.GlobalPositions[i] - truth.GlobalPositions[i];
                    double dy = other.GlobalPositions[i + 1] - truth.GlobalPositions[i + 1];
                    double dz = other.GlobalPositions[i + 2] - truth.GlobalPositions[i + 2];
                    sum += Math.Sqrt(dx * dx + dy * dy + dz * dz);
                }

                errors[f] = sum / JointCount;
            }

            return errors;
        }

        /// <summary>
        /// The mean of <see cref="ErrorPerFrame"/> over the frames that are not key frames (all frames when
        /// there are no keys): what a method got wrong where it had to invent motion.
        /// </summary>
        public double MeanErrorBetweenKeys(int track)
        {
            double[] errors = ErrorPerFrame(track);
            var keys = new HashSet<int>(_keyFrames);
            double sum = 0;
            int count = 0;
            for (int f = 0; f < errors.Length; f++)
            {
                if (keys.Contains(f)) continue;
                sum += errors[f];
                count++;
            }

            return count == 0 ? 0 : sum / count;
        }
    }
}
