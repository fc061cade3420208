using System;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// The retargeting use case (the CLI's <c>retarget</c>, training data preparation): a rig's clip onto the
    /// model's skeleton at the model's rate, or through the model's skeleton onto another rig, every mapped
    /// bone's world direction kept, the root scaled by leg length, joints the source lacks synthesized.
    /// </summary>
    public static class MotionRetargeting
    {
        /// <summary>
        /// <paramref name="source"/> on the model's skeleton, resampled to <see cref="RetargetRequest.OutputFps"/>
        /// or the model's rate (a rate within 0.01 % of it is kept as written: BVH files round their frame time).
        /// </summary>
        /// <exception cref="JointMapException">Joints the model needs are missing.</exception>
        /// <exception cref="MotionRequestException">A frame of the request is not a frame of the clip.</exception>
        public static RetargetResult ToModel(MotionClip source, string sourceName, ModelContract contract, RetargetRequest request)
        {
            SkeletonMap toModel = MapToModel(source, sourceName, contract, request, out string? accepted);
            MotionClip onModel = toModel.ToTarget(Trim(source, request, sourceName));
            UpAxisDetection.RequireStanding(onModel, sourceName, toModel.Up!.Description);
            double frameTime = 1.0 / (request.OutputFps ?? contract.FramesPerSecond);
            MotionClip resampled = Math.Abs(frameTime - onModel.FrameTime) > 1e-4 * frameTime ? MotionResampler.Resample(onModel, frameTime, sourceName) : onModel;
            return new RetargetResult(resampled, toModel, null, accepted);
        }

        /// <summary>
        /// <paramref name="source"/> on <paramref name="target"/>'s skeleton (through the model's), at the source's
        /// rate (its true one with <see cref="RetargetRequest.InputFps"/>) or <see cref="RetargetRequest.OutputFps"/>.
        /// </summary>
        /// <exception cref="JointMapException">Joints the model needs are missing on either rig.</exception>
        /// <exception cref="MotionRequestException">A frame of the request is not a frame of its clip.</exception>
        public static RetargetResult ToRig(MotionClip source, string sourceName, MotionClip target, string targetName, ModelContract contract, RetargetRequest request)
        {
            SkeletonMap toModel = MapToModel(source, sourceName, contract, request, out string? accepted);
            MotionClip onModel = toModel.ToTarget(Trim(source, request, sourceName));
            UpAxisDetection.RequireStanding(onModel, sourceName, toModel.Up!.Description);
            ReferencePose targetReference = Reference(target, request.TargetReferenceFrame, "target reference frame", targetName);
            JointMap targetMap = request.Map ?? JointMap.Detect(target.Skeleton, contract.Skeleton);
            UpAxisDecision targetUp = UpAxisDecision.Decide(request.Up, targetReference, request.TargetReferenceFrame != null, target, targetMap);
            SkeletonMap fromModel = SkeletonMap.Create(targetReference, ReferencePose.ModelTPose(contract.Skeleton), targetMap, targetName, null, targetUp);
            string? targetAccepted = Humanoid(fromModel, contract, targetName, request.AcceptReferencePose);
            if (targetAccepted != null) accepted = (accepted == null ? "" : "source " + accepted + "; ") + "target " + targetAccepted;
            MotionClip onTarget = fromModel.ToSource(onModel, OneFrame(target.Skeleton, targetReference, source.FrameTime));
            if (request.InputFps.HasValue && !request.OutputFps.HasValue) onTarget = MotionResampler.Resample(onTarget, source.FrameTime, sourceName);
            if (request.OutputFps.HasValue) onTarget = MotionResampler.Resample(onTarget, 1.0 / request.OutputFps.Value, sourceName);
            return new RetargetResult(onTarget, toModel, fromModel, accepted);
        }

        private static SkeletonMap MapToModel(MotionClip source, string sourceName, ModelContract contract, RetargetRequest request, out string? accepted)
        {
            ReferencePose reference = Reference(source, request.ReferenceFrame, "reference frame", sourceName);
            JointMap map = request.Map ?? JointMap.Detect(source.Skeleton, contract.Skeleton);
            UpAxisDecision up = UpAxisDecision.Decide(request.Up, reference, request.ReferenceFrame != null, source, map);
            SkeletonMap toModel = SkeletonMap.Create(reference, ReferencePose.ModelTPose(contract.Skeleton), map, sourceName, request.Scale, up);
            // The one humanoid rule of the component (BoneDirections), without the arms: a file's reference pose is not declared a T-pose.
            accepted = Humanoid(toModel, contract, sourceName, request.AcceptReferencePose);
            return toModel;
        }

        /// <summary>Refuses a map whose reference pose fails the humanoid rule, or with <paramref name="accept"/> returns what it would have refused (null: nothing).</summary>
        private static string? Humanoid(SkeletonMap map, ModelContract contract, string name, bool accept)
        {
            if (accept) return BoneDirections.AcceptedDeviation(map, ReferencePose.ModelTPose(contract.Skeleton), BoneDirections.DefaultMaxDegrees, BoneDirections.UprightBones);
            BoneDirections.RequireTPose(map, ReferencePose.ModelTPose(contract.Skeleton), BoneDirections.DefaultMaxDegrees, name, BoneDirections.UprightBones);
            return null;
        }

        /// <summary>The source's frames from <see cref="RetargetRequest.FromFrame"/> on, at its true frame rate.</summary>
        private static MotionClip Trim(MotionClip motion, RetargetRequest request, string sourceName)
        {
            int first = request.FromFrame;
            if (first < 0 || first > motion.FrameCount - 2)
            {
                throw new MotionRequestException(sourceName, $"first frame {first} leaves fewer than two of the file's {motion.FrameCount} frames", $"expected 0 to {Math.Max(0, motion.FrameCount - 2)}");
            }

            if (first == 0 && !request.InputFps.HasValue) return motion;
            MotionClip trimmed = motion.Excerpt(first, motion.FrameCount - first);
            double frameTime = request.InputFps.HasValue ? 1.0 / request.InputFps.Value : motion.FrameTime;
            return new MotionClip(trimmed.Skeleton, trimmed.FrameCount, frameTime, trimmed.LocalPositions, trimmed.LocalRotations);
        }

        /// <summary>The clip's default pose, or its frame <paramref name="frame"/> (refused naming <paramref name="what"/> when it is not a frame of the clip): the one rule of every workflow.</summary>
        internal static ReferencePose Reference(MotionClip clip, int? frame, string what, string name)
        {
            if (frame == null) return ReferencePose.Default(clip.Skeleton);
            if (frame.Value < 0 || frame.Value >= clip.FrameCount)
            {
                throw new MotionRequestException(name, $"{what} {frame.Value} is not a frame of the file", $"expected 0 to {clip.FrameCount - 1}");
            }

            return ReferencePose.FromFrame(clip, frame.Value);
        }

        private static MotionClip OneFrame(Skeleton skeleton, ReferencePose pose, double frameTime)
        {
            int j = skeleton.JointCount;
            var positions = new double[3 * j];
            skeleton.OffsetSpan.CopyTo(positions);
            pose.RootPosition.Write(positions, 0);
            var rotations = new double[4 * j];
            for (int i = 0; i < rotations.Length; i++) rotations[i] = pose.LocalRotations[i];
            return new MotionClip(skeleton, 1, frameTime, positions, rotations);
        }
    }
}
