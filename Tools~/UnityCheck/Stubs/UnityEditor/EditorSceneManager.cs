using UnityEngine.SceneManagement;

namespace UnityEditor.SceneManagement
{
    // source: unity:Editor/Mono/EditorSceneManager.cs
    public enum NewSceneMode
    {
        Single,
        Additive,
    }

    // source: unity:Editor/Mono/EditorSceneManager.cs
    public enum NewSceneSetup
    {
        EmptyScene,
        DefaultGameObjects,
    }

    // source: unity:Editor/Mono/EditorSceneManager.bindings.cs
    public sealed partial class EditorSceneManager
    {
        // source: unity:Editor/Mono/EditorSceneManager.bindings.cs
        public static Scene NewScene(NewSceneSetup setup, NewSceneMode mode) => throw null!;

        // source: unity:Editor/Mono/EditorSceneManager.cs
        public static bool SaveScene(Scene scene, string dstScenePath) => throw null!;

        // source: unity:Editor/Mono/EditorSceneManager.cs
        public static bool SaveCurrentModifiedScenesIfUserWantsTo() => throw null!;
    }
}
