namespace DeltaInterpolator.Tests.Bvh
{
    /// <summary>Small BVH texts for reader tests.</summary>
    public static class BvhSamples
    {
        /// <summary>Two joints and an End Site, two frames; LF line endings, tab indentation.</summary>
        public const string TwoJoints =
            "HIERARCHY\n" +
            "ROOT Hips\n" +
            "{\n" +
            "\tOFFSET 1 2 3\n" +
            "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n" +
            "\tJOINT Spine\n" +
            "\t{\n" +
            "\t\tOFFSET 0 10 0\n" +
            "\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n" +
            "\t\tEnd Site\n" +
            "\t\t{\n" +
            "\t\t\tOFFSET 0 5 0\n" +
            "\t\t}\n" +
            "\t}\n" +
            "}\n" +
            "MOTION\n" +
            "Frames: 2\n" +
            "Frame Time: 0.033333\n" +
            "10 20 30 0 0 0 90 0 0\n" +
            "11 21 31 0 90 0 0 0 0\n";
    }
}
