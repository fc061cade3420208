using System;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Playback;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The animation job of a neural track's mixer: its inputs (the track's clips, weighted by Timeline as on an
    /// Animation Track) are mixed into the stream before it runs; where a blend or gap shows the model's in-between,
    /// the main thread has put that pose in <see cref="Pose"/> with weight 1 and it replaces the rig's bones
    /// (<see cref="PoseBlend.Apply"/>), elsewhere the weight is 0 and the clips play as they are. Root motion is the
    /// clips' own (the stream's velocity is left as their mix made it), except in a blend or gap whose root travels
    /// (<see cref="Core.Blends.SpanRootTravel"/>): there the main thread's velocity and turn rate replace it, in the
    /// character's frame as Kinematica writes it (<c>unity-verification.md</c>); and on a track that places its clips
    /// (transform offsets) every frame, where the step onto the track's placement replaces it.
    /// Pose buffers hold the root position (3 values) then bones × 4 rotation values (w, x, y, z).
    /// </summary>
    internal struct TrackBlendJob : IAnimationJob
    {
        public NativeArray<TransformStreamHandle> Bones;
        public NativeArray<double> Pose;
        public NativeArray<double> Shown;
        public NativeArray<double> Weight;

        /// <summary>One element: the root motion the main thread decided for this frame.</summary>
        [ReadOnly]
        public NativeArray<TrackRootDrive> Root;

        public void ProcessRootMotion(AnimationStream stream)
        {
            // The Animator moves the character by what is on the stream, so the span's travel is written there, replacing what
            // the clips' mix left: in a gap nothing (or a held extrapolation, whose time stands still), in a blend Timeline's
            // mix of both clips' root motion — which the travel ends where (its target key was placed there), on the model's path.
            TrackRootDrive root = Root[0];
            switch (root.Kind)
            {
                case TrackRootDrive.Source.Placement:
                    // Transform offsets: the step from where the character stands to where the track has it, over the delta time
                    // the Animator applies this stream's velocity with — clips, spans and extrapolation alike, so the character is
                    // where Timeline's absolute root motion would put it whatever happened before (a jump, scrubbing back).
                    RootVelocity.Toward(root.Current, root.Target, stream.deltaTime, out double x, out double z, out double yawRate);
                    stream.velocity = new Vector3((float)x, 0, (float)z);
                    stream.angularVelocity = new Vector3(0, (float)yawRate, 0);
                    break;
                case TrackRootDrive.Source.SpanTravel:
                    stream.velocity = new Vector3((float)root.VelocityX, 0, (float)root.VelocityZ);
                    stream.angularVelocity = new Vector3(0, (float)root.YawRate, 0);
                    break;
            }
        }

        public void ProcessAnimation(AnimationStream stream)
        {
            if (Weight[0] <= 0) return;
            var pose = new AnimatorPoseStream(stream, Bones, 0);
            ReadOnlySpan<double> p = Pose.AsReadOnlySpan();
            Span<double> s = Shown.AsSpan();
            PoseBlend.Apply(ref pose, Weight[0], p.Slice(0, 3), p.Slice(3), s.Slice(0, 3), s.Slice(3));
        }
    }
}
