namespace UnityEngine
{
    // source: unity:Runtime/Export/BaseClass.cs
    public enum PrimitiveType
    {
        Cube = 3,
        Plane = 4,
    }
}
