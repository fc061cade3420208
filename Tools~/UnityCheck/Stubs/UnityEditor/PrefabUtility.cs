using UnityEngine;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Prefabs/PrefabUtility.cs
    public sealed partial class PrefabUtility
    {
        public static Object InstantiatePrefab(Object assetComponentOrGameObject) => throw null!;
    }
}
