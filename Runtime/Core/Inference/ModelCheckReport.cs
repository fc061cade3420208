using System.Collections;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The results of checking a model (contract, graph, skeleton, request), in the order found. Checks
    /// add to it instead of throwing at the first problem, so a tool or an inspector can show every
    /// problem at once; code that must refuse calls <see cref="ThrowIfErrors"/>.
    /// </summary>
    public sealed class ModelCheckReport : IReadOnlyList<ModelCheck>
    {
        private readonly List<ModelCheck> _checks = new List<ModelCheck>();

        /// <summary>Number of results.</summary>
        public int Count => _checks.Count;

        /// <summary>Result <paramref name="index"/>.</summary>
        public ModelCheck this[int index] => _checks[index];

        /// <summary>True when any result is an <see cref="CheckSeverity.Error"/>.</summary>
        public bool HasErrors => FirstError != null;

        /// <summary>True when any result is a <see cref="CheckSeverity.Warning"/>.</summary>
        public bool HasWarnings
        {
            get
            {
                foreach (ModelCheck c in _checks)
                {
                    if (c.Severity == CheckSeverity.Warning) return true;
                }

                return false;
            }
        }

        /// <summary>Number of results of one severity.</summary>
        public int CountOf(CheckSeverity severity)
        {
            int n = 0;
            foreach (ModelCheck c in _checks)
            {
                if (c.Severity == severity) n++;
            }

            return n;
        }

        /// <summary>The first error, or null.</summary>
        public ModelCheck? FirstError
        {
            get
            {
                foreach (ModelCheck c in _checks)
                {
                    if (c.Severity == CheckSeverity.Error) return c;
                }

                return null;
            }
        }

        /// <summary>True when a result of this severity and message is already in the report.</summary>
        public bool Contains(CheckSeverity severity, string message)
        {
            foreach (ModelCheck c in _checks)
            {
                if (c.Severity == severity && string.Equals(c.Message, message, System.StringComparison.Ordinal)) return true;
            }

            return false;
        }

        /// <summary>Removes every result (to reuse one report for many checks).</summary>
        public void Clear() => _checks.Clear();

        /// <summary>Adds a result.</summary>
        public void Add(ModelCheck check) => _checks.Add(check);

        /// <summary>Adds an error.</summary>
        public void Error(string source, string message, string remedy) => Add(new ModelCheck(CheckSeverity.Error, source, message, remedy));

        /// <summary>Adds a warning.</summary>
        public void Warning(string source, string message, string remedy) => Add(new ModelCheck(CheckSeverity.Warning, source, message, remedy));

        /// <summary>Adds an information.</summary>
        public void Info(string source, string message, string remedy) => Add(new ModelCheck(CheckSeverity.Info, source, message, remedy));

        /// <summary>Throws the first error as a <see cref="ModelContractException"/>; does nothing without errors.</summary>
        /// <exception cref="ModelContractException">The report holds an error.</exception>
        public void ThrowIfErrors()
        {
            ModelCheck? e = FirstError;
            if (e != null) throw e.ToException();
        }

        /// <inheritdoc />
        public IEnumerator<ModelCheck> GetEnumerator() => _checks.GetEnumerator();

        IEnumerator IEnumerable.GetEnumerator() => _checks.GetEnumerator();
    }
}
