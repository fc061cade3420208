using System;

namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/AnimationClip.bindings.cs
    public sealed partial class AnimationClip : Motion
    {
        public AnimationClip() => throw null!;

        public float length => throw null!;

        public float frameRate { get => throw null!; set => throw null!; }

        public void SetCurve(string relativePath, Type type, string propertyName, AnimationCurve curve) => throw null!;

        public void SampleAnimation(GameObject go, float time) => throw null!;

        // AnimationClip.bindings.cs:86-114
        public bool empty => throw null!;

        //: what Timeline's AnimationPlayableAsset.HasRootTransforms reads (its fourth, hasRootMotion, is internal)
        public bool hasGenericRootTransform => throw null!;

        public bool hasMotionCurves => throw null!;

        public bool hasRootCurves => throw null!;
    }
}
