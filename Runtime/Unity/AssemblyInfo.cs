using System.Runtime.CompilerServices;

// The editor tools (model import, bake window) fill the model asset through its internal setter.
[assembly: InternalsVisibleTo("DeltaInterpolator.Editor")]

// The EditMode tests of the glue (settings refusals, the AvatarMask bone mask) read its internal helpers.
[assembly: InternalsVisibleTo("DeltaInterpolator.Unity.Tests")]
