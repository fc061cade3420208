using System;
using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Tests.Unity
{
    /// <summary>
    /// Issue 28, item 2: the Motion Inbetweener is the character's <see cref="IAnimationWindowPreview"/>, and its
    /// <see cref="FillPreviewLayer"/> shows the key fill's filled copy over the window's pose where the window plays the
    /// keyed clip, at that clip's time, and the animator's own keys otherwise. The graph here is built as the Animation window
    /// builds its own (a mixer with the keyed clip's playable at weight 1, handed to BuildPreviewGraph; UpdatePreviewGraph
    /// before each evaluation); which clip and which character is Core's (<c>FillPreviewBoardTests</c>).
    /// </summary>
    public sealed class FillPreviewLayerTests
    {
        private GameObject _character = null!;
        private AnimationClip _keyed = null!;
        private AnimationClip _filled = null!;
        private AnimationClip _other = null!;
        private PlayableGraph _graph;

        [SetUp]
        public void CreateCharacterAndGraph()
        {
            _character = new GameObject("Character");
            _character.AddComponent<MotionInbetweener>();
            _keyed = new AnimationClip();
            _filled = new AnimationClip();
            _other = new AnimationClip();
            _graph = PlayableGraph.Create("FillPreviewLayerTests");
        }

        [TearDown]
        public void Destroy()
        {
            FillPreviewLayer.Clear(_character);
            _graph.Destroy();
            UnityEngine.Object.DestroyImmediate(_character);
            UnityEngine.Object.DestroyImmediate(_keyed);
            UnityEngine.Object.DestroyImmediate(_filled);
            UnityEngine.Object.DestroyImmediate(_other);
        }

        [Test]
        public void TheComponentIsTheCharactersAnimationWindowPreview()
        {
            IAnimationWindowPreview[] previews = _character.GetComponents<IAnimationWindowPreview>();
            Assert.That(previews.Length, Is.EqualTo(1), "what AnimationWindowControl and Timeline fetch with GetComponents<IAnimationWindowPreview>");
            Assert.That(previews[0], Is.InstanceOf<MotionInbetweener>());
        }

        [Test]
        public void TheFilledCopyShowsAtTheKeyedClipsTimeOnlyWhilePublishedForThisClip()
        {
            AnimationClipPlayable keyed = AnimationClipPlayable.Create(_graph, _keyed);
            AnimationMixerPlayable window = AnimationMixerPlayable.Create(_graph, 1);
            _graph.Connect(keyed, 0, window, 0);
            window.SetInputWeight(0, 1f);
            IAnimationWindowPreview preview = _character.GetComponent<MotionInbetweener>();
            preview.StartPreview();
            Playable root = preview.BuildPreviewGraph(_graph, window);
            Assert.That(root.GetPlayableType(), Is.EqualTo(typeof(AnimationLayerMixerPlayable)), "a layer mixer over the window's pose");
            Assert.That(root.GetInput(0).Equals((Playable)window), Is.True);

            preview.UpdatePreviewGraph(_graph);
            Assert.That((root.GetInputWeight(0), root.GetInputWeight(1)), Is.EqualTo((1f, 0f)), "nothing published: the animator's own keys");

            FillPreviewLayer.Publish(_character, _keyed, _filled);
            keyed.SetTime(0.4);
            preview.UpdatePreviewGraph(_graph);
            Assert.That((root.GetInputWeight(0), root.GetInputWeight(1)), Is.EqualTo((1f, 1f)), "published for this character and clip: the copy overrides the window's pose");
            Playable copy = root.GetInput(1);
            Assert.That(copy.GetPlayableType(), Is.EqualTo(typeof(AnimationClipPlayable)));
            Assert.That(((AnimationClipPlayable)copy).GetAnimationClip(), Is.EqualTo(_filled));
            Assert.That(copy.GetTime(), Is.EqualTo(0.4).Within(1e-9), "at the keyed clip's time");

            keyed.SetTime(1.25);
            preview.UpdatePreviewGraph(_graph);
            Assert.That(root.GetInput(1).GetTime(), Is.EqualTo(1.25).Within(1e-9), "follows the playhead, backwards or forwards");

            FillPreviewLayer.Publish(_character, _other, _filled);
            preview.UpdatePreviewGraph(_graph);
            Assert.That(root.GetInputWeight(1), Is.EqualTo(0f), "a preview of another clip does not show over this one");

            FillPreviewLayer.Clear(_character);
            preview.UpdatePreviewGraph(_graph);
            Assert.That((root.GetInputWeight(0), root.GetInputWeight(1)), Is.EqualTo((1f, 0f)), "cleared: the animator's own keys");
            Assert.That(root.GetInput(1).IsValid(), Is.False, "the copy's playable released");
            preview.StopPreview();
        }

        [Test]
        public void ADisabledComponentLeavesThePreviewAsItIs()
        {
            AnimationMixerPlayable window = AnimationMixerPlayable.Create(_graph, 1);
            MotionInbetweener component = _character.GetComponent<MotionInbetweener>();
            component.enabled = false;
            Playable root = ((IAnimationWindowPreview)component).BuildPreviewGraph(_graph, window);
            Assert.That(root.Equals((Playable)window), Is.True);
        }

        [Test]
        public void HostilePublishesAreRefusedNamingTheArgument()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => FillPreviewLayer.Publish(null!, _keyed, _filled))!.ParamName, Is.EqualTo("character"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => FillPreviewLayer.Publish(_character, null!, _filled))!.ParamName, Is.EqualTo("keyedClip"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => FillPreviewLayer.Publish(_character, _keyed, null!))!.ParamName, Is.EqualTo("filled"));
            Assert.That(Assert.Throws<ArgumentException>(() => FillPreviewLayer.Publish(_character, _keyed, _keyed))!.ParamName, Is.EqualTo("filled"));
            Assert.That(FillPreviewLayer.Clear(_character), Is.False, "nothing was published by a refusal");
        }
    }
}
