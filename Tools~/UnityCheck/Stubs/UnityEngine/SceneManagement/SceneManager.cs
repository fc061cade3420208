using UnityEngine.Events;

namespace UnityEngine.SceneManagement
{
    // source: unity:Runtime/Export/SceneManager/SceneManager.cs
    public enum LoadSceneMode
    {
        Single = 0,
        Additive,
    }

    // source: unity:Runtime/Export/SceneManager/SceneManager.cs
    public partial class SceneManager
    {
        public static event UnityAction<Scene, LoadSceneMode> sceneLoaded { add => throw null!; remove => throw null!; }
    }
}
