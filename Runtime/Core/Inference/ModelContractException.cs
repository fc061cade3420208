namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// A model file that does not fit the model contract or the skeleton it is used with. The message
    /// reads <c>FILE: what was wrong; what to do</c> (no line: the problem is the file as a whole, and
    /// <see cref="DataFormatException.Line"/> is 0), the one-line form of every
    /// <see cref="DataFormatException"/>, so the command line prints it as is and the editor's model
    /// inspector shows it as an error.
    /// </summary>
    public sealed class ModelContractException : DataFormatException
    {
        /// <summary>Creates the exception.</summary>
        /// <param name="model">The model's file path or name.</param>
        /// <param name="problem">What was wrong, e.g. <c>"contract version 2"</c>.</param>
        /// <param name="expected">What was expected and what to do about it.</param>
        public ModelContractException(string model, string problem, string expected)
            : base(model, problem, expected)
        {
        }
    }
}
