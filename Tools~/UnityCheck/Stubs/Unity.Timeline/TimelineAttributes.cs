using System;

namespace UnityEngine.Timeline
{
    // source: timeline:Runtime/TimelineAttributes.cs
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public partial class TrackClipTypeAttribute : Attribute
    {
        public TrackClipTypeAttribute(Type clipClass, bool allowAutoCreate) => throw null!;
    }

    // source: timeline:Runtime/TimelineAttributes.cs
    [AttributeUsage(AttributeTargets.Class)]
    public partial class TrackBindingTypeAttribute : Attribute
    {
        public TrackBindingTypeAttribute(Type type) => throw null!;
    }
}
