namespace UnityEngine
{
    // source: unity:Runtime/Transform/ScriptBindings/Transform.bindings.cs
    public partial class Transform : Component
    {
        public Vector3 position { get => throw null!; set => throw null!; }

        public Quaternion rotation { get => throw null!; set => throw null!; }

        public Vector3 lossyScale => throw null!;

        public Transform parent { get => throw null!; set => throw null!; }

        public Vector3 localPosition { get => throw null!; set => throw null!; }

        public Quaternion localRotation { get => throw null!; set => throw null!; }

        public Vector3 localScale { get => throw null!; set => throw null!; }

        public int childCount => throw null!;

        public Transform GetChild(int index) => throw null!;

        public Transform Find(string n) => throw null!;

        public void SetParent(Transform parent, bool worldPositionStays) => throw null!;

        public void SetPositionAndRotation(Vector3 position, Quaternion rotation) => throw null!;
    }
}
