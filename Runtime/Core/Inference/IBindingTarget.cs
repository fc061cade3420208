using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// A backend's binding while it is built: it attaches Core's tensors to its engine one by one. Every backend
    /// builds its bindings through <see cref="BindingTargets.Fill"/>, which checks each tensor against the graph
    /// first and disposes the half-built binding when one is refused.
    /// </summary>
    public interface IBindingTarget : IDisposable
    {
        /// <summary>Attaches an input the graph has (already checked by name and element type).</summary>
        void BindInput(InferenceTensor tensor);

        /// <summary>Attaches an output the graph has (already checked by name and element type).</summary>
        void BindOutput(InferenceTensor tensor);
    }

    /// <summary>The one way a backend fills a binding.</summary>
    public static class BindingTargets
    {
        /// <summary>
        /// Checks every tensor against <paramref name="description"/> and attaches it to <paramref name="target"/>.
        /// </summary>
        /// <returns><paramref name="target"/>, fully bound.</returns>
        /// <exception cref="ModelContractException">The graph lacks a tensor or has it with another element type; <paramref name="target"/> is disposed.</exception>
        public static T Fill<T>(T target, ModelDescription description, IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs)
            where T : IBindingTarget
        {
            try
            {
                foreach (InferenceTensor t in inputs)
                {
                    description.RequireInput(t);
                    target.BindInput(t);
                }

                foreach (InferenceTensor t in outputs)
                {
                    description.RequireOutput(t);
                    target.BindOutput(t);
                }
            }
            catch
            {
                target.Dispose();
                throw;
            }

            return target;
        }
    }
}
