using System;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Tests.Unity
{
    /// <summary>
    /// Loading ahead (<see cref="InbetweenerSettings.Preload"/>) refuses settings it cannot load, naming them, holds nothing
    /// after a failure of any exception type (a backend factory's own), and tries again when called again; new settings read
    /// the rig from the Animator (<see cref="CharacterRigKind.Automatic"/>). EditMode tests: a Unity user runs them in the Test
    /// Runner; here the Unity check compiles them.
    /// </summary>
    public sealed class ModelPreloadTests
    {
        private const string EngineName = "Δ-Interpolator test engine that throws";
        private InbetweenerSettings _settings = null!;
        private InbetweeningModel _model = null!;
        private ThrowingFactory _factory = null!;

        [SetUp]
        public void CreateAssets()
        {
            _settings = ScriptableObject.CreateInstance<InbetweenerSettings>();
            _settings.name = "Preload Test Settings";
            _model = ScriptableObject.CreateInstance<InbetweeningModel>();
            _model.name = "Preload Test Model";
            _factory = new ThrowingFactory();
            InferenceBackends.Register(_factory);
        }

        [TearDown]
        public void DestroyAssets()
        {
            _settings.ReleasePreload();
            UnityEngine.Object.DestroyImmediate(_settings);
            UnityEngine.Object.DestroyImmediate(_model);
        }

        [Test]
        public void NewSettingsReadTheRigFromTheAnimator()
        {
            Assert.That(_settings.Rig, Is.EqualTo(CharacterRigKind.Automatic));
            var character = new GameObject("Character without an avatar");
            try
            {
                Animator animator = character.AddComponent<Animator>();
                Assert.That(_settings.RigOf(animator), Is.EqualTo(CharacterRigKind.Generic), "no humanoid avatar: Generic");
                Assert.Throws<ArgumentNullException>(() => _settings.RigOf(null!));
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(character);
            }
        }

        [Test]
        public void PreloadWithoutAModelRefusesNamingTheSettings()
        {
            var e = Assert.Throws<InvalidOperationException>(() => _settings.Preload());
            Assert.That(e!.Message, Does.Contain(_settings.name).And.Contain("no model"));
            Assert.That(_settings.IsPreloaded, Is.False);
        }

        [Test]
        public void AFactoryThrowingItsOwnTypeFailsThePreloadAndHoldsNothing()
        {
            var s = new SerializedObject(_settings);
            s.FindProperty("model").objectReferenceValue = _model;
            s.FindProperty("backend").stringValue = EngineName;
            s.ApplyModifiedPropertiesWithoutUndo();

            Assert.Throws<EngineAssertionException>(() => _settings.Preload());
            Assert.That(_factory.Loads, Is.EqualTo(1));
            Assert.That(_settings.IsPreloaded, Is.False, "a failed load holds nothing");
            // Called again, it tries again: Preload is the caller's explicit request, not a frame loop.
            Assert.Throws<EngineAssertionException>(() => _settings.Preload());
            Assert.That(_factory.Loads, Is.EqualTo(2));
        }

        private sealed class EngineAssertionException : Exception
        {
            public EngineAssertionException(string message)
                : base(message)
            {
            }
        }

        private sealed class ThrowingFactory : IInferenceBackendFactory
        {
            public int Loads { get; private set; }

            public string Name => EngineName;

            public bool RunsOffMainThread => false;

            public IInferenceBackend Create(InbetweeningModel model, ModelGraphKind graph)
            {
                Loads++;
                throw new EngineAssertionException("Assertion failure. Value was False");
            }
        }
    }
}
