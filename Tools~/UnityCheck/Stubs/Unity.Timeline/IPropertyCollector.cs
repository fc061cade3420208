namespace UnityEngine.Timeline
{
    // source: timeline:Runtime/Utilities/IPropertyCollector.cs
    public partial interface IPropertyCollector
    {
        void AddFromName<T>(GameObject obj, string name)
            where T : Component;
    }
}
