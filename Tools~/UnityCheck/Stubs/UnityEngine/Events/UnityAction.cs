namespace UnityEngine.Events
{
    // source: unity:artifacts/generated/UnityEvent/UnityEvent_2.cs
    public delegate void UnityAction<T0, T1>(T0 arg0, T1 arg1);
}
