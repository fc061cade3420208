using UnityObject = UnityEngine.Object;

namespace UnityEditor
{
    // source: unity:Editor/Mono/EditorGUIUtility.cs
    public sealed partial class EditorGUIUtility
    {
        public static void PingObject(UnityObject obj) => throw null!;
    }
}
