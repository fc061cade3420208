using System;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Reads an Animator state's pose at a time in the state, off-scene, for a hand-off target or a neural Animator
    /// transition's target: a second <c>AnimatorControllerPlayable</c> of the character's own controller, in the
    /// component's playable graph, is put in the state with <c>PlayInFixedTime(state, layer, time)</c>, given the
    /// character's current parameters (floats, ints and bools copied by type), and evaluated into a
    /// <see cref="ClipTargetReadJob"/> on its own pass-through output in the next animation evaluation.
    /// </summary>
    /// <remarks>
    /// <para>Why this route: no run-time API maps a state that is not playing to its clips (the state machine is
    /// editor data), but a controller playable evaluates any state of its controller — a single clip, or a 1D/2D
    /// blend tree at the parameters it is given — exactly as the character's own Animator does. A state → motion table
    /// written by the editor would go stale whenever the controller is edited and would re-implement blend trees.</para>
    /// <para>What it costs: one controller instance per character (created when the component starts with neural Animator
    /// transitions on, otherwise at the first state request; again when the Animator's controller changes), whose state machine updates every frame at speed 0 (its clock never moves, so
    /// its states stay where they were put and its clips' events never fire), and one evaluation of its pose in a frame
    /// that reads a target (the reader does not process its input otherwise). Layers other than the requested one are
    /// weighted 0, so the target is the state's own pose; bones a masked layer above drives keep that layer's pose
    /// through the mask in the settings. Triggers are not copied: they only start transitions, and the reader must
    /// stay in the state it was put in.</para>
    /// <para>The graph owns the playables (destroying it destroys them); <see cref="Dispose"/> frees the buffers.</para>
    /// </remarks>
    internal sealed class StateTargetSampler : IDisposable
    {
        private readonly PlayableGraph _graph;
        private readonly Animator _animator;
        private readonly TargetPoseReader _reader;
        private AnimatorControllerPlayable _controllerPlayable;
        private RuntimeAnimatorController? _controller;
        private int[] _parameterHashes = new int[0];
        private AnimatorControllerParameterType[] _parameterTypes = new AnimatorControllerParameterType[0];
        private int _stateHash;
        private int _layer;
        private int _checkedRequest;
        private bool _warned;

        public StateTargetSampler(PlayableGraph graph, Animator animator, NativeArray<TransformStreamHandle> bones, int rootBone, ushort sortingOrder)
        {
            _graph = graph;
            _animator = animator;
            _reader = new TargetPoseReader(graph, animator, bones, rootBone, sortingOrder, "Δ-Interpolator state target");
        }

        /// <summary>
        /// Asks for the pose of state <paramref name="stateHash"/> on <paramref name="layer"/> at <paramref name="timeInState"/>
        /// seconds, with the character's parameters now; it is read in the next animation evaluation.
        /// </summary>
        /// <exception cref="InvalidOperationException">The Animator has no controller.</exception>
        public void Sample(int stateHash, int layer, float timeInState)
        {
            Prepare();
            if (_animator.parameterCount != _parameterHashes.Length) CacheParameters();
            for (int p = 0; p < _parameterHashes.Length; p++)
            {
                int hash = _parameterHashes[p];
                switch (_parameterTypes[p])
                {
                    case AnimatorControllerParameterType.Float: _controllerPlayable.SetFloat(hash, _animator.GetFloat(hash)); break;
                    case AnimatorControllerParameterType.Int: _controllerPlayable.SetInteger(hash, _animator.GetInteger(hash)); break;
                    case AnimatorControllerParameterType.Bool: _controllerPlayable.SetBool(hash, _animator.GetBool(hash)); break;
                }
            }

            int layers = _controllerPlayable.GetLayerCount();
            for (int l = 1; l < layers; l++) _controllerPlayable.SetLayerWeight(l, l == layer ? 1f : 0f);
            _controllerPlayable.PlayInFixedTime(stateHash, layer, timeInState);
            _stateHash = stateHash;
            _layer = layer;
            _reader.Ask();
        }

        /// <summary>The pose of the latest <see cref="Sample"/> once the animation evaluation has read it; empty while it has not.</summary>
        public ReadOnlySpan<double> Read()
        {
            ReadOnlySpan<double> pose = _reader.Read();
            if (!pose.IsEmpty && _checkedRequest != _reader.Request) CheckEntered();
            return pose;
        }

        // The run-time check of the route: the copy took the Play in the evaluation that read the pose (a speed-0 controller
        // playable still updates its state machine). If the engine ever did not, the target would be another state's pose: say so once.
        private void CheckEntered()
        {
            _checkedRequest = _reader.Request;
            AnimatorStateInfo entered = _controllerPlayable.GetCurrentAnimatorStateInfo(_layer);
            if (_warned || entered.fullPathHash == _stateHash || entered.shortNameHash == _stateHash) return;
            _warned = true;
            Debug.LogWarning($"{_animator.name}: the Motion Inbetweener's state reader was not in the requested state (hash {_stateHash}, layer {_layer}) when it read the target pose, so the transition's target is another state's pose; expected the controller copy to enter the state in the same evaluation (please report it with your Unity version)", _animator);
        }

        /// <summary>
        /// Creates the controller instance now rather than at the first request (a character with neural Animator transitions
        /// needs it at its first transition: making it then would cost that frame); nothing without a controller.
        /// </summary>
        public void Warm()
        {
            if (_animator.runtimeAnimatorController != null) Prepare();
        }

        /// <summary>Creates the controller instance at the first request, and again when the Animator's controller changed since.</summary>
        private void Prepare()
        {
            RuntimeAnimatorController controller = _animator.runtimeAnimatorController;
            if (controller == null) throw new InvalidOperationException($"{_animator.name}: the Animator has no Animator Controller; assign one to read its states");
            if (controller == _controller && _controllerPlayable.IsValid()) return;
            if (_controllerPlayable.IsValid()) _graph.DestroyPlayable(_controllerPlayable);
            _controllerPlayable = AnimatorControllerPlayable.Create(_graph, controller);
            // Speed 0 rather than paused: the state machine still updates (with no time passing), so a Play is applied
            // in the next evaluation, and the state stays at the time it was put in.
            _controllerPlayable.SetSpeed(0);
            _graph.Connect(_controllerPlayable, 0, _reader.Playable, 0);
            _controller = controller;
            CacheParameters();
        }

        // The parameters' hashes and types, read once (reading them allocates); again when their count changes, e.g. when the copy
        // was made before the Animator had read its controller (warmed at start), when it reports none.
        private void CacheParameters()
        {
            int count = _animator.parameterCount;
            _parameterHashes = new int[count];
            _parameterTypes = new AnimatorControllerParameterType[count];
            for (int p = 0; p < count; p++)
            {
                AnimatorControllerParameter parameter = _animator.GetParameter(p);
                _parameterHashes[p] = parameter.nameHash;
                _parameterTypes[p] = parameter.type;
            }
        }

        public void Dispose() => _reader.Dispose();
    }
}
