using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Blends;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Blends
{
    /// <summary>
    /// Issue 28, item 2: a neural track lets the character's <c>IAnimationWindowPreview</c> components into its editor
    /// preview as an Animation Track does — once per built graph, after Timeline connected the track, never in Play
    /// mode (where they run their own graphs), in component order, each given the chain so far — and a component that
    /// returns no node is left out, said, instead of breaking the preview. The nodes here are a small stand-in graph: each
    /// node knows its input and its parent, as Unity's playables do.
    /// </summary>
    [TestFixture]
    public sealed class PreviewInsertionTests
    {
        [Test]
        public void ComponentsFollowTheTracksMixInTheirOrderOnceTimelineConnectedIt()
        {
            var insertion = new PreviewInsertion<Node?>(n => n != null);
            var mixer = new Node("neural mixer");
            insertion.Built(mixer, editorPreview: true);
            Assert.That(insertion.Pending, Is.True);
            Assert.That(insertion.TryTake(Connected, out _), Is.False, "not before Timeline has connected the mixer");
            Assert.That(insertion.Pending, Is.True, "still waiting");

            var timeline = new Node("timeline");
            mixer.Parent = timeline;
            Assert.That(insertion.TryTake(Connected, out Node? taken), Is.True);
            Assert.That(taken, Is.SameAs(mixer));
            Assert.That(insertion.TryTake(Connected, out _), Is.False, "once per build: the binding is asked for again (Timeline's window lists outputs) without a second insertion");

            var rig = new Stage("RigBuilder");
            var other = new Stage("Other");
            var calls = new List<string>();
            Node? end = insertion.Chain<Stage>(taken, new[] { rig, other }, (s, input) => s.Insert(input!, calls), s => s.Name, w => Assert.Fail(w));
            Assert.That(calls, Is.EqualTo(new[] { "RigBuilder", "Other" }), "in component order, as AnimationTrack and the Animation window call them");
            Assert.That(end!.Name, Is.EqualTo("Other job"));
            Assert.That(end.Input!.Name, Is.EqualTo("RigBuilder job"), "each stage given the chain so far");
            Assert.That(end.Input.Input, Is.SameAs(mixer), "the first after the track's mix, neural blends included");
        }

        [Test]
        public void NothingIsInsertedInPlayModeOrForAGraphBuiltAgain()
        {
            var insertion = new PreviewInsertion<Node?>(n => n != null);
            var playing = new Node("mixer") { Parent = new Node("timeline") };
            insertion.Built(playing, editorPreview: false);
            Assert.That(insertion.Pending, Is.False);
            Assert.That(insertion.TryTake(Connected, out _), Is.False, "Play mode: the components run their own graphs after the track's output");

            var first = new Node("first build");
            insertion.Built(first, editorPreview: true);
            var second = new Node("second build") { Parent = new Node("timeline") };
            insertion.Built(second, editorPreview: true);
            Assert.That(insertion.TryTake(Connected, out Node? taken), Is.True);
            Assert.That(taken, Is.SameAs(second), "a rebuilt graph's mixer replaces the one still waiting");

            insertion.Built(null, editorPreview: true);
            Assert.That(insertion.Pending, Is.False, "no mixer, nothing to wait for");
        }

        [Test]
        public void AComponentThatReturnsNoNodeIsLeftOutAndSaid()
        {
            var insertion = new PreviewInsertion<Node?>(n => n != null);
            var mixer = new Node("mixer");
            var warnings = new List<string>();
            var calls = new List<string>();
            Node? end = insertion.Chain<Stage>(mixer, new[] { new Stage("Broken", returnsNothing: true), new Stage("RigBuilder") },
                (s, input) => s.Insert(input!, calls), s => s.Name, warnings.Add);
            Assert.That(end!.Input, Is.SameAs(mixer), "the next component gets the chain as it was");
            Assert.That(warnings, Has.Count.EqualTo(1));
            Assert.That(warnings[0], Does.StartWith("Broken returned no playable"));

            Node? untouched = insertion.Chain<Stage>(mixer, Array.Empty<Stage>(), (s, input) => s.Insert(input!, calls), s => s.Name, null);
            Assert.That(untouched, Is.SameAs(mixer), "no component: the track's mix itself");
        }

        [Test]
        public void RefusesWhatIsNoMixerOrStageList()
        {
            Assert.Throws<ArgumentNullException>(() => _ = new PreviewInsertion<Node?>(null!));
            var insertion = new PreviewInsertion<Node?>(n => n != null);
            var e = Assert.Throws<ArgumentException>(() => insertion.Chain<Stage>(null, Array.Empty<Stage>(), (s, n) => n, s => s.Name, null));
            Assert.That(e!.ParamName, Is.EqualTo("mixer"));
            Assert.That(e.Message, Does.Contain("expected"));
            Assert.Throws<ArgumentNullException>(() => insertion.Chain<Stage>(new Node("m"), null!, (s, n) => n, s => s.Name, null));
            Assert.Throws<ArgumentNullException>(() => insertion.TryTake(null!, out _));
        }

        private static bool Connected(Node? node) => node?.Parent != null;

        private sealed class Node
        {
            public Node(string name) => Name = name;

            public string Name { get; }

            public Node? Input { get; set; }

            public Node? Parent { get; set; }
        }

        /// <summary>What a preview component does in <c>BuildPreviewGraph</c>: its job takes the input and is returned.</summary>
        private sealed class Stage
        {
            private readonly bool _returnsNothing;

            public Stage(string name, bool returnsNothing = false)
            {
                Name = name;
                _returnsNothing = returnsNothing;
            }

            public string Name { get; }

            public Node? Insert(Node input, List<string> calls)
            {
                calls.Add(Name);
                if (_returnsNothing) return null;
                var job = new Node(Name + " job") { Input = input };
                input.Parent = job;
                return job;
            }
        }
    }
}
