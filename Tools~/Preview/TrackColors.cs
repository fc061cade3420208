namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// One colour per track, the same in the player and on the contact sheet: neutral grey for the
    /// ground truth, then orange, blue, green, … in track order (readable on dark and white grounds).
    /// </summary>
    internal static class TrackColors
    {
        public const string GroundTruth = "#a3acb6";

        public const string Key = "#ffc933";

        private static readonly string[] Others = { "#f08a24", "#3d8ff0", "#3fb55a", "#a368e8", "#e5484d", "#19b3b0" };

        public static string Of(PreviewScene scene, int track)
        {
            if (track == scene.GroundTruthTrack) return GroundTruth;
            int rank = scene.GroundTruthTrack >= 0 && track > scene.GroundTruthTrack ? track - 1 : track;
            return Others[rank % Others.Length];
        }
    }
}
