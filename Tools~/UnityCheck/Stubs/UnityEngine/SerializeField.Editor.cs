using System;

namespace UnityEngine
{
    // source: unity:Runtime/Export/Serialization/Serialization.cs
    public sealed partial class SerializeField : Attribute
    {
    }
}
