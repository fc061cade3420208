using System;
using DeltaInterpolator.Core.Playback;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Checks, once per clip, a humanoid character's clip target as <see cref="ClipTargetReadJob"/> read it (transform
    /// handles on the input stream of a muscle clip: no Unity code we can read demonstrates that path) against the pose
    /// <c>AnimationClip.SampleAnimation</c> gives at the same time on a hidden, renderer-free copy of the character's
    /// hierarchy with the same avatar (Core's <see cref="SampledTargetCheck"/>); one Console warning per clip when they
    /// differ. Generic characters are not checked: handles on a generic clip's input stream are what Unity's own
    /// animation-jobs samples do (<c>MixerJob</c>). See <c>Documentation~/unity-verification.md</c>.
    /// </summary>
    /// <remarks>The copy is made at the first check (bones only: names and local transforms) and never shown, saved or
    /// written to the scene's objects; main thread only.</remarks>
    internal sealed class HumanoidTargetCheck : IDisposable
    {
        private readonly Animator _animator;
        private readonly Transform[] _bones;
        private readonly double[] _reference;
        private GameObject? _copy;
        private Transform[]? _copyBones;
        private AnimationClip? _checked;
        private bool _unavailable;

        public HumanoidTargetCheck(Animator animator, Transform[] bones)
        {
            _animator = animator;
            _bones = bones;
            _reference = new double[4 * bones.Length];
        }

        /// <summary>The first time <paramref name="clip"/>'s target is read: compares <paramref name="target"/> (root 3, then bones × 4) with SampleAnimation's.</summary>
        public void Check(AnimationClip clip, float time, ReadOnlySpan<double> target)
        {
            if (clip == null || clip == _checked) return;
            _checked = clip;
            if (!_animator.isHuman || _unavailable) return;
            if (_copy == null && !Copy()) return;
            clip.SampleAnimation(_copy!, time);
            UnityPoses.ReadRotations(_copyBones!, _reference);

            string? differs = SampledTargetCheck.Compare(target.Slice(3), _reference, clip.name, time, b => _bones[b].name);
            if (differs != null) Debug.LogWarning(_animator.name + ": " + differs, _animator);
        }

        public void Dispose()
        {
            if (_copy != null) UnityEngine.Object.Destroy(_copy);
            _copy = null;
        }

        // The character's hierarchy under its Animator (names and local transforms only) with the same avatar, hidden and
        // never saved; false (said once) when a mapped bone is not below the Animator, so the copy cannot stand in for it.
        private bool Copy()
        {
            var copy = new GameObject(_animator.name + " (Δ-Interpolator target check)") { hideFlags = HideFlags.HideAndDontSave };
            CopyChildren(_animator.transform, copy.transform);
            Animator animator = copy.AddComponent<Animator>();
            animator.avatar = _animator.avatar;
            _copyBones = new Transform[_bones.Length];
            for (int b = 0; b < _bones.Length; b++)
            {
                string path = _bones[b].name;
                for (Transform t = _bones[b].parent; t != null && t != _animator.transform; t = t.parent) path = t.name + "/" + path;
                _copyBones[b] = copy.transform.Find(path);
                if (_copyBones[b] != null) continue;
                UnityEngine.Object.Destroy(copy);
                _unavailable = true;
                Debug.LogWarning($"{_animator.name}: humanoid clip targets are not checked against AnimationClip.SampleAnimation: bone {_bones[b].name} is not below the Animator's transform; expected every mapped bone below it", _animator);
                return false;
            }

            _copy = copy;
            return true;
        }

        private static void CopyChildren(Transform from, Transform to)
        {
            for (int i = 0; i < from.childCount; i++)
            {
                Transform child = from.GetChild(i);
                var go = new GameObject(child.name) { hideFlags = HideFlags.HideAndDontSave };
                go.transform.SetParent(to, false);
                go.transform.localPosition = child.localPosition;
                go.transform.localRotation = child.localRotation;
                go.transform.localScale = child.localScale;
                CopyChildren(child, go.transform);
            }
        }
    }
}
