using System.Collections.Generic;

namespace UnityEngine.Playables
{
    // source: unity:Runtime/Export/Director/Playable.cs
    public partial struct Playable : IPlayable
    {
        public static Playable Null => throw null!;

        public System.Type GetPlayableType() => throw null!;

        public bool Equals(Playable other) => throw null!;
    }

    // source: unity:Runtime/Export/Director/PlayableBindings.cs
    public partial struct PlayableBinding
    {
    }

    // source: unity:Runtime/Export/Director/PlayableAsset.cs
    public partial interface IPlayableAsset
    {
    }

    // source: unity:Runtime/Export/Director/PlayableAsset.cs
    public abstract partial class PlayableAsset : ScriptableObject, IPlayableAsset
    {
        public abstract Playable CreatePlayable(PlayableGraph graph, GameObject owner);

        public virtual IEnumerable<PlayableBinding> outputs => throw null!;
    }

    // source: unity:Runtime/Export/Director/IPlayableBehaviour.cs
    public partial interface IPlayableBehaviour
    {
    }

    // source: unity:Runtime/Export/Director/FrameData.cs
    public partial struct FrameData
    {
    }

    // source: unity:Runtime/Export/Director/PlayableBehaviour.cs
    public abstract partial class PlayableBehaviour : IPlayableBehaviour
    {
        public PlayableBehaviour() => throw null!;

        public virtual void OnPlayableDestroy(Playable playable) => throw null!;

        public virtual void PrepareFrame(Playable playable, FrameData info) => throw null!;
    }

    // source: unity:Runtime/Export/Director/ScriptPlayable.cs
    public partial struct ScriptPlayable<T> : IPlayable
        where T : class, IPlayableBehaviour, new()
    {
        public static ScriptPlayable<T> Create(PlayableGraph graph, int inputCount = 0) => throw null!;

        public T GetBehaviour() => throw null!;

        public static implicit operator Playable(ScriptPlayable<T> playable) => throw null!;
    }

    // source: unity:Runtime/Export/Director/ScriptPlayableOutput.cs
    public partial struct ScriptPlayableOutput : IPlayableOutput
    {
        public static ScriptPlayableOutput Create(PlayableGraph graph, string name) => throw null!;
    }

    // source: unity:Runtime/Export/Director/IPlayable.cs
    public partial interface IPlayable
    {
    }

    // source: unity:Runtime/Export/Director/IPlayableOutput.cs
    public partial interface IPlayableOutput
    {
    }

    // source: unity:Runtime/Export/Director/PlayableGraph.bindings.cs
    public enum DirectorUpdateMode
    {
        GameTime = 1,
    }

    // source: unity:Runtime/Export/Director/PlayableGraph.bindings.cs
    public partial struct PlayableGraph
    {
        public static PlayableGraph Create(string name) => throw null!;

        public void Destroy() => throw null!;

        public bool IsValid() => throw null!;

        public void Play() => throw null!;

        public void SetTimeUpdateMode(DirectorUpdateMode value) => throw null!;

        public bool Connect<U, V>(U source, int sourceOutputPort, V destination, int destinationInputPort)
            where U : struct, IPlayable
            where V : struct, IPlayable => throw null!;

        public void Disconnect<U>(U input, int inputPort)
            where U : struct, IPlayable => throw null!;

        public void DestroyPlayable<U>(U playable)
            where U : struct, IPlayable => throw null!;
    }

    // source: unity:Runtime/Export/Director/PlayableExtensions.cs
    public static partial class PlayableExtensions
    {
        public static bool IsValid<U>(this U playable)
            where U : struct, IPlayable => throw null!;

        public static void Pause<U>(this U playable)
            where U : struct, IPlayable => throw null!;

        public static void SetTime<U>(this U playable, double value)
            where U : struct, IPlayable => throw null!;

        public static double GetTime<U>(this U playable)
            where U : struct, IPlayable => throw null!;

        public static void SetSpeed<U>(this U playable, double value)
            where U : struct, IPlayable => throw null!;

        public static PlayableGraph GetGraph<U>(this U playable)
            where U : struct, IPlayable => throw null!;

        public static int GetInputCount<U>(this U playable)
            where U : struct, IPlayable => throw null!;

        public static int GetOutputCount<U>(this U playable)
            where U : struct, IPlayable => throw null!;

        public static Playable GetInput<U>(this U playable, int inputPort)
            where U : struct, IPlayable => throw null!;

        public static Playable GetOutput<U>(this U playable, int outputPort)
            where U : struct, IPlayable => throw null!;

        public static void SetInputWeight<U>(this U playable, int inputIndex, float weight)
            where U : struct, IPlayable => throw null!;

        public static float GetInputWeight<U>(this U playable, int inputIndex)
            where U : struct, IPlayable => throw null!;
    }

    // source: unity:Runtime/Export/Director/PlayableOutputExtensions.cs
    public static partial class PlayableOutputExtensions
    {
        public static void SetSourcePlayable<U, V>(this U output, V value)
            where U : struct, IPlayableOutput
            where V : struct, IPlayable => throw null!;
    }
}
