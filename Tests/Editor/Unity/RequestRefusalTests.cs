using System;
using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEngine;

namespace DeltaInterpolator.Tests.Unity
{
    /// <summary>
    /// <see cref="MotionInbetweener"/>'s requests refuse a bad argument with an exception naming it, before they ask whether the
    /// component runs (so the refusal is the same in every state, and nothing changes). An EditMode component never runs (its
    /// OnEnable is not called outside Play mode): valid arguments then meet the not-running refusal, which shows the checks came first.
    /// What needs the controller (an unknown state, a layer beyond its layers) is refused by the running request and by Core's
    /// <c>TransitionCharacter.RequestState</c>, whose tests cover it with a stand-in controller.
    /// </summary>
    public sealed class RequestRefusalTests
    {
        private GameObject _character = null!;
        private MotionInbetweener _component = null!;
        private AnimationClip _clip = null!;

        [SetUp]
        public void CreateCharacter()
        {
            _character = new GameObject("Character");
            _component = _character.AddComponent<MotionInbetweener>();
            _clip = new AnimationClip();
        }

        [TearDown]
        public void DestroyCharacter()
        {
            UnityEngine.Object.DestroyImmediate(_character);
            UnityEngine.Object.DestroyImmediate(_clip);
        }

        [Test]
        public void StateRequestsNameTheirBadArgument()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => _component.RequestTransition((string)null!, 0, 0f))!.ParamName, Is.EqualTo("stateName"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransition("Roll", -1, 0f))!.ParamName, Is.EqualTo("layer"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransition(Animator.StringToHash("Roll"), -1, 0f))!.ParamName, Is.EqualTo("layer"));
            foreach (float time in new[] { -0.1f, float.NaN, float.PositiveInfinity })
            {
                Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransition("Roll", 0, time))!.ParamName, Is.EqualTo("timeInState"), $"time {time}");
            }

            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransition("Roll", 0, 0.2f, float.NaN))!.ParamName, Is.EqualTo("seconds"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransitionInFrames("Roll", 0, 0.2f, 0))!.ParamName, Is.EqualTo("modelFrames"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransitionInFrames(Animator.StringToHash("Roll"), 0, -1f, 10))!.ParamName, Is.EqualTo("timeInState"));
        }

        [Test]
        public void ClipAndPoseRequestsNameTheirBadArgument()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => _component.RequestTransition((AnimationClip)null!, 0f))!.ParamName, Is.EqualTo("clip"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransition(_clip, float.NaN))!.ParamName, Is.EqualTo("clipTime"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransition(_clip, 0.2f, float.NaN))!.ParamName, Is.EqualTo("seconds"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => _component.RequestTransitionInFrames(_clip, 0.2f, 0))!.ParamName, Is.EqualTo("modelFrames"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => _component.RequestTransition(new Vector3(0f, 0f, 0f), null!))!.ParamName, Is.EqualTo("localRotations"));
        }

        [Test]
        public void ValidArgumentsMeetTheNotRunningRefusal()
        {
            var e = Assert.Throws<InvalidOperationException>(() => _component.RequestTransition("Roll", 0, 0.2f, 0.5f));
            Assert.That(e!.Message, Does.Contain("not running"));
            Assert.Throws<InvalidOperationException>(() => _component.RequestTransition(_clip, 0.2f, 0.5f));
        }
    }
}
