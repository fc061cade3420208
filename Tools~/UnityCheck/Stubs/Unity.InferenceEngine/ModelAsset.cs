using UnityEngine;

namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/Internals/ModelAsset.cs
    public partial class ModelAsset : ScriptableObject
    {
    }
}
