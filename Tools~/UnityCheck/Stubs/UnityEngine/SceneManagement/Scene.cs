namespace UnityEngine.SceneManagement
{
    // source: unity:Runtime/Export/SceneManager/Scene*.cs
    public partial struct Scene
    {
    }
}
