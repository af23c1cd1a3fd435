// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

using System;
using NUnit.Framework;

namespace UnityEngine.TestTools
{
    // com.unity.test-framework@1.1.33 UnityEngine.TestRunner/NUnitExtensions/Attributes/UnityTestAttribute.cs
    // The test method must return IEnumerator; in play mode it runs as a coroutine (yield return null: one frame).
    // Interfaces Unity's class has (ISimpleTestBuilder, IImplyFixture, ITestBuilder, IApplyToTest) are left out: the
    // package only applies the attribute.
    [AttributeUsage(AttributeTargets.Method)]
    public class UnityTestAttribute : CombiningStrategyAttribute
    {
        public UnityTestAttribute() : base((NUnit.Framework.Interfaces.ICombiningStrategy)null, (NUnit.Framework.Interfaces.IParameterDataProvider)null) => throw null;
    }
}
