using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// A backend's bindings still open, so that disposing the backend closes every one of them (their native
    /// tensors would outlive the session otherwise) and a disposed backend binds nothing more. Every backend keeps
    /// one; a binding leaves it when it is disposed on its own.
    /// </summary>
    /// <typeparam name="TBinding">The backend's binding type.</typeparam>
    public sealed class OpenBindings<TBinding>
        where TBinding : class, IDisposable
    {
        private readonly List<TBinding> _open = new List<TBinding>();

        /// <summary>Whether the backend has been disposed (<see cref="Close"/> was called).</summary>
        public bool Closed { get; private set; }

        /// <summary>Throws where the backend has been disposed.</summary>
        /// <param name="backend">The backend's type name, for the exception.</param>
        /// <exception cref="ObjectDisposedException">The backend has been disposed.</exception>
        public void RequireOpen(string backend)
        {
            if (Closed) throw new ObjectDisposedException(backend);
        }

        /// <summary>Holds a new binding until it or the backend is disposed; returns it.</summary>
        public TBinding Add(TBinding binding)
        {
            _open.Add(binding);
            return binding;
        }

        /// <summary>Forgets a binding disposed on its own.</summary>
        public void Remove(TBinding binding) => _open.Remove(binding);

        /// <summary>Disposes every open binding; false where this was done already (the backend then has nothing left to release).</summary>
        public bool Close()
        {
            if (Closed) return false;
            Closed = true;
            foreach (TBinding binding in _open.ToArray()) binding.Dispose();
            return true;
        }
    }
}
