#if UNITY_EDITOR
#nullable enable
using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Editor.Importers;
using DeltaInterpolator.Editor.Models;
using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using Object = UnityEngine.Object;

namespace DeltaInterpolator.Tests.PlayMode
{
    /// <summary>
    /// The Demo sample's figures in the engine, as the PlayMode verification tests set them up (a test's rig derives from
    /// it): a temporary folder under Assets, the Demo's <c>.bvh</c> files imported there by the package's BVH importer (cut
    /// as a test asks), the Demo's <see cref="InbetweenerSettings"/>, and instances of a figure with an Animator. Everything
    /// it makes or is given to keep is destroyed, and the folder deleted, on <see cref="Dispose"/>.
    /// </summary>
    /// <remarks>
    /// Editor only (it imports assets). The base of <c>HumanoidRootMotionVerification</c>'s rig and, in its own test
    /// assembly, <c>NeuralTrackRootMotionVerification</c>'s, which read the same sample files the same way.
    /// </remarks>
    public abstract class DemoFigureImport : IDisposable
    {
        private const string Package = "com.deltainterpolator.inbetweening";
        private readonly List<Object> _created = new List<Object>();

        /// <summary>Makes the folder <c>Assets/<paramref name="folderName"/></c> to import into.</summary>
        protected DemoFigureImport(string folderName)
        {
            Folder = AssetDatabase.GUIDToAssetPath(AssetDatabase.CreateFolder("Assets", folderName));
        }

        /// <summary>The temporary folder under Assets the files are imported into ("" if Unity did not make it).</summary>
        public string Folder { get; }

        /// <summary>The imported figure <see cref="Figure"/> instantiates.</summary>
        protected GameObject FigureAsset { get; set; } = null!;

        /// <summary>The avatar the instances' Animators are given.</summary>
        protected Avatar FigureAvatar { get; set; } = null!;

        /// <summary>
        /// Copies the Demo's <paramref name="file"/> into <see cref="Folder"/> and imports it with the package's BVH importer,
        /// cut into <paramref name="cuts"/> (none: as the importer makes it unasked, one clip of the whole take). Returns the
        /// clips by name, the figure and its avatar.
        /// </summary>
        protected Dictionary<string, AnimationClip> ImportBvh(string file, out GameObject figure, out Avatar avatar, params BvhClipSettings[] cuts)
        {
            string path = Folder + "/" + file;
            File.Copy(Path.GetFullPath("Packages/" + Package + "/Samples~/Demo/" + file), Path.GetFullPath(path));
            AssetDatabase.ImportAsset(path);
            bool hasCuts = cuts.Length > 0;
            if (hasCuts)
            {
                var importer = AssetImporter.GetAtPath(path) as BvhImporter;
                Assert.That(importer != null, Is.True, path + " is imported by the package's BVH importer");
                // A script's change to an importer's field is saved to the .meta and imported only once the importer is marked dirty.
                importer!.clips = cuts;
                EditorUtility.SetDirty(importer);
                importer.SaveAndReimport();
            }

            GameObject? found = AssetDatabase.LoadAssetAtPath<GameObject>(path);
            // Uncut, the importer was not asked for: the figure is the first sign that the package's importer took the file.
            Assert.That(found != null, Is.True, path + (hasCuts ? " is imported as a figure" : " is imported as a figure by the package's BVH importer"));
            figure = found!;
            avatar = null!;
            var clips = new Dictionary<string, AnimationClip>();
            foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(path))
            {
                if (o is AnimationClip c) clips[c.name] = c;
                if (o is Avatar a) avatar = a;
            }

            foreach (BvhClipSettings cut in cuts) Assert.That(clips.ContainsKey(cut.name), Is.True, $"{path} has the clip {cut.name}");
            Assert.That(avatar != null, Is.True, path + " has an avatar");
            return clips;
        }

        /// <summary>
        /// The settings the Demo uses, kept: the shipped model (an asset in <see cref="Folder"/>), <paramref name="rig"/>, CMU
        /// joint names, <paramref name="referenceClip"/>'s first frame as the reference pose (the walk's is a T-pose).
        /// </summary>
        protected InbetweenerSettings DemoSettings(CharacterRigKind rig, AnimationClip referenceClip)
        {
            var settings = Keep(ScriptableObject.CreateInstance<InbetweenerSettings>());
            var s = new SerializedObject(settings);
            s.FindProperty("model").objectReferenceValue = ShippedModelAssets.Create(Folder + "/Model.asset");
            s.FindProperty("rig").enumValueIndex = (int)rig;
            s.FindProperty("jointMap").enumValueIndex = (int)BuiltInJointMap.Cmu;
            s.FindProperty("referencePose").enumValueIndex = (int)ReferencePoseSource.ClipFrame;
            s.FindProperty("referenceClip").objectReferenceValue = referenceClip;
            s.FindProperty("referenceClipTime").floatValue = 0f;
            s.ApplyModifiedPropertiesWithoutUndo();
            return settings;
        }

        /// <summary>
        /// A kept instance of <see cref="FigureAsset"/> at <paramref name="position"/>, turned <paramref name="yaw"/>° about
        /// +Y, its Animator on <see cref="FigureAvatar"/> and <paramref name="controller"/> (none: nothing plays but what a
        /// test binds to it) with root motion applied or not.
        /// </summary>
        protected GameObject Figure(Vector3 position, float yaw, RuntimeAnimatorController? controller, bool applyRootMotion)
        {
            GameObject go = Keep(Object.Instantiate(FigureAsset));
            go.transform.SetPositionAndRotation(position, Quaternion.Euler(0f, yaw, 0f));
            Animator animator = go.GetComponent<Animator>();
            if (animator == null) animator = go.AddComponent<Animator>();
            animator.avatar = FigureAvatar;
            animator.runtimeAnimatorController = controller;
            animator.applyRootMotion = applyRootMotion;
            return go;
        }

        /// <summary>Destroys <paramref name="made"/> on <see cref="Dispose"/>.</summary>
        public T Keep<T>(T made) where T : Object
        {
            _created.Add(made);
            return made;
        }

        public void Dispose()
        {
            foreach (Object o in _created) if (o != null) Object.DestroyImmediate(o);
            if (Folder.Length > 0) AssetDatabase.DeleteAsset(Folder);
        }
    }
}
#endif
