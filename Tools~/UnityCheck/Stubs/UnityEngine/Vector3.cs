namespace UnityEngine
{
    // source: unity:Runtime/Export/Math/Vector3.cs
    public partial struct Vector3
    {
        public float x;
        public float y;
        public float z;

        public Vector3(float x, float y, float z) => throw null!;

        public static Vector3 operator +(Vector3 a, Vector3 b) => throw null!;

        public static Vector3 operator -(Vector3 a, Vector3 b) => throw null!;
    }
}
