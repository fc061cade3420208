using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    /// <summary>
    /// Issue 28, items 2 and 3: the key fill's preview shows in the Animation window's and Timeline's previews through the
    /// character's <c>IAnimationWindowPreview</c>. What is Core's: a preview shows on the character it was published for,
    /// only where the preview graph plays the very clip it was computed from at a weight above 0 (found below the
    /// window's input as the Animation window and Timeline build it), and each publish or clear is seen once. The nodes
    /// are a small stand-in graph with inputs and weights, as Unity's playables have.
    /// </summary>
    [TestFixture]
    public sealed class FillPreviewBoardTests
    {
        private const int Character = 101;
        private const int Other = 102;
        private const int Walk = 7;
        private const int Jump = 8;

        [Test]
        public void APreviewShowsOnItsCharacterWhereTheWindowPlaysItsKeyedClip()
        {
            var board = new FillPreviewBoard<string>();
            // The Animation window: its layer mixer plays a default pose, the clip and the candidate keys at weight 1.
            Node window = Mixer(("default pose", 1f, Clip(0)), ("clip", 1f, Clip(Walk)), ("candidates", 1f, Clip(0)));
            Assert.That(board.Weight(Character, Find(window, Walk)), Is.EqualTo(0f), "nothing published: the animator's own keys");

            board.Publish(Character, Walk, "walk filled");
            Assert.That(board.Weight(Character, Find(window, Walk)), Is.EqualTo(1f));
            Assert.That(board.Weight(Other, Find(window, Walk)), Is.EqualTo(0f), "another character shows its own keys");
            Node jumpWindow = Mixer(("clip", 1f, Clip(Jump)));
            Assert.That(board.Weight(Character, Find(jumpWindow, Walk)), Is.EqualTo(0f), "the window on another clip shows that clip");
            Assert.That(board.Weight(Character, Find(jumpWindow, Jump)), Is.EqualTo(0f), "a preview of the walk is not shown over the jump");
            Assert.That(board.TryGet(Character, out int keyed, out string? preview), Is.True);
            Assert.That((keyed, preview), Is.EqualTo((Walk, "walk filled")));

            Assert.That(board.Clear(Character), Is.True);
            Assert.That(board.Weight(Character, Find(window, Walk)), Is.EqualTo(0f), "cleared: the animator's own keys again");
            Assert.That(board.TryGet(Character, out _, out _), Is.False);
            Assert.That(board.Clear(Character), Is.False, "nothing left to clear");
        }

        [Test]
        public void OnATimelineTrackThePreviewShowsOnlyWhileTheKeyedClipPlays()
        {
            var board = new FillPreviewBoard<string>();
            board.Publish(Character, Walk, "walk filled");
            // Timeline: the track's mixer, each clip under an offset playable; clips the playhead is not on at weight 0.
            Node walkClip = Clip(Walk);
            Node track = Mixer(("walk offset", 0f, Mixer(("walk", 1f, walkClip))), ("jump offset", 1f, Mixer(("jump", 1f, Clip(Jump)))));
            PreviewGraphSearch.Shown shown = Find(track, Walk);
            Assert.That(shown.Found, Is.False, "the playhead is on the jump: the walk's preview does not show");
            Assert.That(board.Weight(Character, shown), Is.EqualTo(0f));

            track.Weights[0] = 0.25f;
            track.Weights[1] = 0.75f;
            shown = PreviewGraphSearch.Find(track, Walk, new Graph(), out Node? at);
            Assert.That(shown.Found, Is.True, "in a blend the walk plays");
            Assert.That(shown.Weight, Is.EqualTo(0.25f), "at the product of the weights on the way");
            Assert.That(at, Is.SameAs(walkClip), "the walk's own playable, whose time is the walk's time");
            Assert.That(board.Weight(Character, shown), Is.EqualTo(1f));
        }

        [Test]
        public void TheKeyedClipPlayedTwiceIsFoundWhereItWeighsMost()
        {
            Node first = Clip(Walk);
            Node second = Clip(Walk);
            Node track = Mixer(("first", 0.3f, first), ("second", 0.7f, second));
            PreviewGraphSearch.Shown shown = PreviewGraphSearch.Find(track, Walk, new Graph(), out Node? at);
            Assert.That(at, Is.SameAs(second));
            Assert.That(shown.Weight, Is.EqualTo(0.7f));
        }

        [Test]
        public void AGraphDeeperThanAnyPreviewOrWithACycleEndsTheSearch()
        {
            Node deep = Clip(Walk);
            for (int i = 0; i <= PreviewGraphSearch.MaxDepth; i++) deep = Mixer(("level", 1f, deep));
            Assert.That(Find(deep, Walk).Found, Is.False, "below the depth limit");

            Node loop = Mixer(("self", 1f, null));
            loop.Inputs[0] = loop;
            Assert.That(Find(loop, Walk).Found, Is.False, "a cycle ends at the depth limit instead of recursing forever");
            Assert.That(Find(Mixer(("unconnected", 1f, null)), Walk).Found, Is.False, "an unconnected port is skipped");
        }

        [Test]
        public void EachPublishAndClearIsSeenOnceThroughTheVersion()
        {
            var board = new FillPreviewBoard<string>();
            Assert.That(board.Version(Character), Is.EqualTo(0));
            board.Publish(Character, Walk, "a");
            int afterFirst = board.Version(Character);
            board.Publish(Character, Walk, "b");
            Assert.That(board.Version(Character), Is.GreaterThan(afterFirst), "a new preview of the same clip is a change");
            int afterSecond = board.Version(Character);
            Assert.That(board.Version(Other), Is.EqualTo(0), "other characters unchanged");
            board.Clear(Other);
            Assert.That(board.Version(Other), Is.EqualTo(0), "clearing nothing changes nothing");
            board.Clear(Character);
            Assert.That(board.Version(Character), Is.GreaterThan(afterSecond));
        }

        [Test]
        public void HostilePublishesAreRefusedNamingTheArgument()
        {
            var board = new FillPreviewBoard<string>();
            var e = Assert.Throws<ArgumentException>(() => board.Publish(0, Walk, "p"))!;
            Assert.That(e.ParamName, Is.EqualTo("character"));
            e = Assert.Throws<ArgumentException>(() => board.Publish(Character, 0, "p"))!;
            Assert.That(e.ParamName, Is.EqualTo("keyedClip"));
            var n = Assert.Throws<ArgumentNullException>(() => board.Publish(Character, Walk, null!))!;
            Assert.That(n.ParamName, Is.EqualTo("preview"));
            Assert.That(board.Version(Character), Is.EqualTo(0), "nothing published by a refusal");
            Assert.That(board.TryGet(Character, out _, out _), Is.False);
        }

        [Test]
        [Retry(5)] // the runtime now and then adds a few KB to this thread's count at a random frame (seen with no GC and with tiering off); bytes our code allocates repeat in every attempt
        public void SearchingTheGraphAllocatesNothing()
        {
            Node track = Mixer(("walk offset", 0.5f, Mixer(("walk", 1f, Clip(Walk)))), ("jump offset", 0.5f, Mixer(("jump", 1f, Clip(Jump)))));
            Find(track, Walk);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 100; i++) Find(track, Walk);
            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.EqualTo(0), "the preview layer searches at every preview evaluation");
        }

        private static PreviewGraphSearch.Shown Find(Node root, int clip) => PreviewGraphSearch.Find(root, clip, new Graph(), out _);

        private static Node Clip(int clip) => new Node { ClipId = clip };

        private static Node Mixer(params (string Name, float Weight, Node? Input)[] inputs)
        {
            var n = new Node();
            foreach ((string _, float w, Node? input) in inputs)
            {
                n.Inputs.Add(input);
                n.Weights.Add(w);
            }

            return n;
        }

        private sealed class Node
        {
            public int ClipId;
            public readonly List<Node?> Inputs = new List<Node?>();
            public readonly List<float> Weights = new List<float>();
        }

        private struct Graph : PreviewGraphSearch.IGraph<Node?>
        {
            public bool IsValid(Node? node) => node != null;

            public int InputCount(Node? node) => node!.Inputs.Count;

            public Node? Input(Node? node, int port) => node!.Inputs[port];

            public float InputWeight(Node? node, int port) => node!.Weights[port];

            public int ClipOf(Node? node) => node!.ClipId;
        }
    }
}
