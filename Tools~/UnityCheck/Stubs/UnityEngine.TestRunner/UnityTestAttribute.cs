using System;
using NUnit.Framework;

namespace UnityEngine.TestTools
{
    // source: testframework:UnityEngine.TestRunner/NUnitExtensions/Attributes/UnityTestAttribute.cs
    [AttributeUsage(AttributeTargets.Method)]
    public class UnityTestAttribute : CombiningStrategyAttribute
    {
        // NUnit's CombiningStrategyAttribute has no parameterless constructor: the stub passes what the real one does not need here.
        public UnityTestAttribute() : base((object)null!, (object)null!) => throw null!;
    }
}
