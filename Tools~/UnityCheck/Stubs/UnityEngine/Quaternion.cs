namespace UnityEngine
{
    // source: unity:Runtime/Export/Math/Quaternion.cs
    public partial struct Quaternion
    {
        public float x;
        public float y;
        public float z;
        public float w;

        public Quaternion(float x, float y, float z, float w) => throw null!;

        public static Quaternion Euler(float x, float y, float z) => throw null!;

        public static Vector3 operator *(Quaternion rotation, Vector3 point) => throw null!;
    }
}
