using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Scheduling;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// What a running <see cref="MotionInbetweener"/> is built from its settings: the shared scheduler of its model
    /// and engine, Core's <see cref="TransitionCharacter"/> on the rig the settings describe, and the animation job
    /// bound to it. Disposing it releases them (the last character of a model disposes the scheduler).
    /// </summary>
    internal sealed class CharacterBuild : IDisposable
    {
        private CharacterBuild(TransitionScheduler scheduler, TransitionCharacter character, TransitionLayerBinder binder, AnimatorTransitionWatcher watcher, CharacterRequests requests, Transform[] bones, PlaybackSettings playback, SettingsSnapshot built)
        {
            Scheduler = scheduler;
            Character = character;
            Binder = binder;
            Watcher = watcher;
            Requests = requests;
            Bones = bones;
            Playback = playback;
            Built = built;
        }

        public TransitionScheduler Scheduler { get; }

        public TransitionCharacter Character { get; }

        public TransitionLayerBinder Binder { get; }

        /// <summary>Neural Animator transitions: the watched layers' state machines read for Core each frame.</summary>
        public AnimatorTransitionWatcher Watcher { get; }

        /// <summary>The requests game code makes (clip, pose, hand-off into a state).</summary>
        public CharacterRequests Requests { get; }

        /// <summary>The bones driven, the root bone first.</summary>
        public Transform[] Bones { get; }

        /// <summary>The character reads these at each request and frame, so edited blend times apply without a rebuild.</summary>
        public PlaybackSettings Playback { get; }

        /// <summary>What of the settings the build used (a change of it re-initialises).</summary>
        public SettingsSnapshot Built { get; }

        /// <summary>Builds from <paramref name="s"/>; refuses (with what to do) a missing model or engine and a rig that cannot be mapped.</summary>
        public static CharacterBuild Create(Animator animator, InbetweenerSettings s, MotionInbetweener component, string graphName, ushort sortingOrder)
        {
            IInferenceBackendFactory factory = Engine(s, out InbetweeningModel model);
            TransitionScheduler scheduler = SharedSchedulers.Acquire(model, factory);
            TransitionLayerBinder? binder = null;
            try
            {
                ModelContract contract = scheduler.Contract;
                CharacterRig rig = RigCollector.Collect(animator, s, contract.Skeleton, out Core.Retargeting.JointMap jointMap, out Transform[] bones);
                SkeletonPoseConverter converter = rig.CreatePoseConverter(contract.Skeleton, jointMap);
                var playback = new PlaybackSettings { BlendInSeconds = s.BlendInSeconds, BlendOutSeconds = s.BlendOutSeconds, PastFrames = s.PastFrames, LockFeet = s.LockFeet };
                var character = new TransitionCharacter(converter, scheduler, playback, rig.Armature, model.name, factory.Name);
                // The bones' pose now is the first frame shown, so a request may follow at once (e.g. right after AddComponent).
                var watcher = new AnimatorTransitionWatcher(animator, s.NeuralTransitions, character.Transitions, bones, component);
                binder = new TransitionLayerBinder(animator, bones, graphName, sortingOrder, watcher);
                // Neural transitions read states at their first transition: the controller copy is made now, not in that frame.
                if (watcher.Watching) binder.States.Warm();
                var requests = new CharacterRequests(character, binder, animator, s, component, bones.Length);
                return new CharacterBuild(scheduler, character, binder, watcher, requests, bones, playback, SettingsSnapshot.Take(s));
            }
            catch
            {
                // Whatever failed (the component stops once, PlaybackStatus.TryStart), nothing built so far is left behind: the
                // binder's graph and native buffers, and this character's hold on the model.
                binder?.Dispose();
                SharedSchedulers.Release(scheduler);
                throw;
            }
        }

        /// <summary>The settings' model and engine; refuses (with what to do) a missing model or an engine that is not installed.</summary>
        public static IInferenceBackendFactory Engine(InbetweenerSettings s, out InbetweeningModel model)
        {
            model = s.Model != null ? s.Model : throw new InvalidOperationException($"the settings {s.name} have no model; assign an imported in-betweening model");
            return InferenceBackends.Find(s.Backend)
                ?? throw new InvalidOperationException($"the inference engine '{s.Backend}' is not installed; install its package (Sentis: com.unity.ai.inference 2.4.0 or later) or choose another in {s.name}");
        }

        public void Dispose()
        {
            Binder.Dispose();
            SharedSchedulers.Release(Scheduler);
        }
    }
}
