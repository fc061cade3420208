using System;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The inference engine failed while a transition played (a Sentis assert, a GPU worker failure, any
    /// exception from a run); <see cref="Exception.InnerException"/> is the engine's own. The transition that
    /// needed the run is ended. A front end stops using the model (see <c>Playback.PlaybackStatus</c>).
    /// </summary>
    public sealed class InferenceFailedException : InvalidOperationException
    {
        /// <summary>Creates the exception around the engine's <paramref name="engineError"/>.</summary>
        public InferenceFailedException(Exception engineError)
            : base("the in-betweening network failed: " + (engineError ?? throw new ArgumentNullException(nameof(engineError))).Message, engineError)
        {
        }
    }
}
