using System;
using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEngine;

namespace DeltaInterpolator.Tests.Unity
{
    /// <summary>
    /// The neural Animator transition settings refuse what no controller could meet, naming the entry and field, and change
    /// nothing when they refuse (the refusal contract's C# API row). EditMode tests: a Unity user runs them in the Test Runner;
    /// here the Unity check compiles them.
    /// </summary>
    public sealed class NeuralTransitionSettingsTests
    {
        private InbetweenerSettings _settings = null!;

        [SetUp]
        public void CreateSettings() => _settings = ScriptableObject.CreateInstance<InbetweenerSettings>();

        [TearDown]
        public void DestroySettings() => UnityEngine.Object.DestroyImmediate(_settings);

        [Test]
        public void DefaultsKeepEveryCrossfade()
        {
            // The base layer's entry is there to tick, and off.
            Assert.That(_settings.NeuralTransitions, Has.Length.EqualTo(1));
            Assert.That(_settings.NeuralTransitions[0].layer, Is.EqualTo(0));
            Assert.That(_settings.NeuralTransitions[0].enabled, Is.False);
            var layer = new NeuralTransitionLayer();
            Assert.That(layer.layer, Is.EqualTo(0));
            Assert.That(layer.enabled, Is.True);
            Assert.That(layer.minSeconds, Is.EqualTo(0f));
            Assert.That(layer.maxSeconds, Is.EqualTo(0f));
        }

        [Test]
        public void AcceptsAValidLayer()
        {
            var layer = new NeuralTransitionLayer { layer = 1, minSeconds = 0.2f, maxSeconds = 1.2f, excludeTags = new[] { "Attack" } };
            _settings.SetNeuralTransitions(new[] { layer });
            Assert.That(_settings.NeuralTransitions, Has.Length.EqualTo(1));
            Assert.That(_settings.NeuralTransitions[0].layer, Is.EqualTo(1));
        }

        [TestCase(-1, 0f, 0f, "layers[0].layer")]
        [TestCase(0, -0.1f, 0f, "layers[0].minSeconds")]
        [TestCase(0, float.NaN, 0f, "layers[0].minSeconds")]
        [TestCase(0, float.PositiveInfinity, 0f, "layers[0].minSeconds")]
        [TestCase(0, 0f, -1f, "layers[0].maxSeconds")]
        [TestCase(0, 0f, float.NaN, "layers[0].maxSeconds")]
        [TestCase(0, 0.5f, 0.3f, "layers[0].maxSeconds")]
        public void RefusesOutOfRangeValuesNamingTheField(int layer, float min, float max, string parameter)
        {
            var entry = new NeuralTransitionLayer { layer = layer, minSeconds = min, maxSeconds = max };
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => _settings.SetNeuralTransitions(new[] { entry }));
            Assert.That(e!.ParamName, Is.EqualTo(parameter));
            Assert.That(e.Message, Does.Contain("expected"));
            Assert.That(_settings.NeuralTransitions[0].enabled, Is.False, "a refused value changes nothing");
            Assert.That(_settings.NeuralTransitions[0].minSeconds, Is.EqualTo(0f), "a refused value changes nothing");
        }

        [Test]
        public void RefusesTwoEntriesForOneLayer()
        {
            var e = Assert.Throws<ArgumentException>(() => _settings.SetNeuralTransitions(new[] { new NeuralTransitionLayer(), new NeuralTransitionLayer() }));
            Assert.That(e!.ParamName, Is.EqualTo("layers[1].layer"));
            Assert.That(_settings.NeuralTransitions, Has.Length.EqualTo(1), "a refused value changes nothing");
        }

        [Test]
        public void RefusesNullEntries()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => _settings.SetNeuralTransitions(null!))!.ParamName, Is.EqualTo("layers"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => _settings.SetNeuralTransitions(new NeuralTransitionLayer[] { null! }))!.ParamName, Is.EqualTo("layers[0]"));
        }
    }
}
