using System;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Experimental.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The reading half of every off-scene target: a <see cref="ClipTargetReadJob"/> on its own pass-through output that
    /// reads the pose of whatever playable feeds its input 0 (a clip held at a time, a controller copy put in a state)
    /// in the next animation evaluation. The samplers own what they connect; this type owns the buffers and the
    /// request counter, so a newer request supersedes one not read yet in both.
    /// </summary>
    /// <remarks>
    /// The output sorts just before the component's transition layer and passes the controller's pose on unchanged (the
    /// job writes nothing). The graph owns the playables; <see cref="Dispose"/> frees the buffers.
    /// </remarks>
    internal sealed class TargetPoseReader : IDisposable
    {
        private NativeArray<double> _target;
        private NativeArray<int> _requests;
        private int _request;

        public TargetPoseReader(PlayableGraph graph, Animator animator, NativeArray<TransformStreamHandle> bones, int rootBone, ushort sortingOrder, string outputName)
        {
            _target = new NativeArray<double>(3 + 4 * bones.Length, Allocator.Persistent);
            _requests = new NativeArray<int>(2, Allocator.Persistent);
            var job = new ClipTargetReadJob { Bones = bones, Target = _target, Requests = _requests, RootBone = rootBone };
            Playable = AnimationScriptPlayable.Create(graph, job, 1);
            Playable.SetProcessInputs(false);
            AnimationPlayableOutput output = AnimationPlayableOutput.Create(graph, outputName, animator);
            output.SetSourcePlayable(Playable);
            output.SetAnimationStreamSource(AnimationStreamSource.PreviousInputs);
            output.SetSortingOrder(sortingOrder);
        }

        /// <summary>The reader's playable: the sampler connects its source to input 0.</summary>
        public AnimationScriptPlayable Playable { get; }

        /// <summary>The latest request's number (0 before the first).</summary>
        public int Request => _request;

        /// <summary>Asks for a read in the next animation evaluation; a newer request supersedes one not read yet.</summary>
        public void Ask() => _requests[0] = ++_request;

        /// <summary>The latest request's pose (root position, then bones × 4 rotations) once read; empty while it has not been.</summary>
        public ReadOnlySpan<double> Read() => _request != 0 && _requests[1] == _request ? _target.AsReadOnlySpan() : default;

        public void Dispose()
        {
            if (_target.IsCreated) _target.Dispose();
            if (_requests.IsCreated) _requests.Dispose();
        }
    }
}
