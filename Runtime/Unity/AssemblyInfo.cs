using System.Runtime.CompilerServices;

// The editor tools (model import, bake window) fill the model asset through its internal setter.
[assembly: InternalsVisibleTo("DeltaInterpolator.Editor")]
