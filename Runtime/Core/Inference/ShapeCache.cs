using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The one cache of what is built for a transition shape (P past keys, n missing frames): the whole graph's
    /// workspaces and the lazy decoders of an <see cref="Inbetweener"/>, a player's requests, a bake's transitions.
    /// Built on a shape's first use and found again by every later one, so steady-state frames allocate nothing.
    /// </summary>
    /// <remarks>
    /// A linear search: a game or a bake uses a handful of shapes, and a list walk allocates nothing where a
    /// dictionary's enumerator or a capturing predicate might. Several items of one shape may be held (a player
    /// keeps the request playing while it builds the next); <see cref="Find"/> picks one that is free. Not
    /// thread-safe (each owner uses its own on one thread).
    /// </remarks>
    internal sealed class ShapeCache<T>
        where T : class
    {
        private readonly List<T> _items = new List<T>();
        private readonly List<int> _past = new List<int>();
        private readonly List<int> _missing = new List<int>();

        /// <summary>Number of items held, of every shape.</summary>
        public int Count => _items.Count;

        /// <summary>Item <paramref name="index"/> (0..<see cref="Count"/> − 1), in the order added.</summary>
        public T this[int index] => _items[index];

        /// <summary>
        /// The first item of shape (<paramref name="past"/>, <paramref name="missing"/>) other than <paramref name="busy"/>
        /// that <paramref name="isFree"/> accepts (any, when null); null when none is.
        /// </summary>
        /// <param name="past">P, the shape's past keys.</param>
        /// <param name="missing">n, the shape's missing frames.</param>
        /// <param name="busy">An item in use (a player's playing request), never returned; or null.</param>
        /// <param name="isFree">A non-capturing test held in a static field, so a search allocates nothing; or null.</param>
        public T? Find(int past, int missing, T? busy = null, Func<T, bool>? isFree = null)
        {
            for (int i = 0; i < _items.Count; i++)
            {
                T item = _items[i];
                if (_past[i] == past && _missing[i] == missing && item != busy && (isFree == null || isFree(item))) return item;
            }

            return null;
        }

        /// <summary>Holds <paramref name="item"/> as one of shape (<paramref name="past"/>, <paramref name="missing"/>).</summary>
        public T Add(int past, int missing, T item)
        {
            if (item == null) throw new ArgumentNullException(nameof(item));
            _items.Add(item);
            _past.Add(past);
            _missing.Add(missing);
            return item;
        }

        /// <summary>Forgets every item (the owner disposes them first when they hold engine resources).</summary>
        public void Clear()
        {
            _items.Clear();
            _past.Clear();
            _missing.Clear();
        }
    }
}
