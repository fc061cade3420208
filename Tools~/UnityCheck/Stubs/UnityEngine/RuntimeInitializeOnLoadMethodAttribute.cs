using System;

namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/RuntimeInitializeOnLoadAttribute.cs
    public enum RuntimeInitializeLoadType
    {
        AfterSceneLoad = 0,
        BeforeSceneLoad,
        AfterAssembliesLoaded,
        BeforeSplashScreen,
        SubsystemRegistration,
    }

    // source: unity:Runtime/Export/Scripting/RuntimeInitializeOnLoadAttribute.cs
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = false)]
    public partial class RuntimeInitializeOnLoadMethodAttribute : Scripting.PreserveAttribute
    {
        public RuntimeInitializeOnLoadMethodAttribute(RuntimeInitializeLoadType loadType) => throw null!;
    }
}

namespace UnityEngine.Scripting
{
    // source: unity:Runtime/Export/Scripting/PreserveAttribute.cs
    [AttributeUsage(AttributeTargets.Method | AttributeTargets.Class | AttributeTargets.Field | AttributeTargets.Property | AttributeTargets.Constructor | AttributeTargets.Interface | AttributeTargets.Delegate | AttributeTargets.Event | AttributeTargets.Struct | AttributeTargets.Assembly | AttributeTargets.Enum, Inherited = false)]
    public partial class PreserveAttribute : Attribute
    {
    }
}
