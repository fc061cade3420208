using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Unity
{
    /// <summary>The inference engines present in the project, by name (engine assemblies register themselves).</summary>
    public static class InferenceBackends
    {
        private static readonly List<IInferenceBackendFactory> s_factories = new List<IInferenceBackendFactory>();

        /// <summary>Every registered engine.</summary>
        public static IReadOnlyList<IInferenceBackendFactory> All => s_factories;

        /// <summary>Adds <paramref name="factory"/>, replacing one of the same name.</summary>
        public static void Register(IInferenceBackendFactory factory)
        {
            if (factory == null) throw new ArgumentNullException(nameof(factory));
            s_factories.RemoveAll(f => string.Equals(f.Name, factory.Name, StringComparison.Ordinal));
            s_factories.Add(factory);
        }

        /// <summary>The engine called <paramref name="name"/>, or null when its package is not installed.</summary>
        public static IInferenceBackendFactory? Find(string name)
        {
            foreach (IInferenceBackendFactory f in s_factories)
            {
                if (string.Equals(f.Name, name, StringComparison.Ordinal)) return f;
            }

            return null;
        }
    }
}
