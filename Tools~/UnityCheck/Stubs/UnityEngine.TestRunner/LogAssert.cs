namespace UnityEngine.TestTools
{
    // source: testframework:UnityEngine.TestRunner/Assertions/LogAssert.cs
    public static class LogAssert
    {
        public static void NoUnexpectedReceived() => throw null!;
    }
}
