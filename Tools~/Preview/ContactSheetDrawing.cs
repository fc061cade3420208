using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Net;
using System.Text;
using System.Text.RegularExpressions;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// Draws the contact sheet as SVG: one row per track, each with a side view (horizontal axis along
    /// the main direction of travel, vertical up) and a top view, poses at the key frames (gold) and
    /// between them (track colour), and trails of the root, hands and feet over every frame. Rows other
    /// than the ground truth show its poses and trails as a light ghost underneath, so a method's
    /// mistakes are where its colour leaves the grey.
    /// </summary>
    internal sealed class ContactSheetDrawing
    {
        private const double Width = 1800;
        private const double LabelWidth = 190;
        private const double Gap = 18;
        private const double SideWidth = 1010;
        private const double TopWidth = Width - LabelWidth - SideWidth - 3 * Gap;
        private const double HeaderHeight = 64;
        private const double Pad = 14;
        private const string Ghost = "#c3c9d0";
        private const string KeyStroke = "#b07a00";

        private static readonly CultureInfo Invariant = CultureInfo.InvariantCulture;

        private readonly PreviewScene _scene;
        private readonly SceneLayout _layout;
        private readonly int[] _poses;
        private readonly HashSet<int> _keys;
        private readonly int[] _trailJoints;
        private readonly ViewBox _side;
        private readonly ViewBox _top;
        private readonly double _rowHeight;
        private readonly double _sideReach;
        private readonly double _pixelsPerFrame;
        private readonly PreviewTrack _reference;

        private ContactSheetDrawing(PreviewScene scene)
        {
            _scene = scene;
            _layout = SceneLayout.Of(scene);
            _keys = new HashSet<int>(scene.KeyFrames);
            _poses = PoseFrames(scene);
            _trailJoints = TrailJoints(scene);

            // Bounds over every track and frame, so rows share one scale and line up. The side view is
            // unrolled in time: a joint's place along the travel is measured from the reference root.
            PreviewTrack reference = scene.Tracks[SceneLayout.ReferenceTrack(scene)];
            double sMin = double.PositiveInfinity, sMax = double.NegativeInfinity, lMin = double.PositiveInfinity, lMax = double.NegativeInfinity, yMax = double.NegativeInfinity;
            double reach = 0;
            foreach (PreviewTrack track in scene.Tracks)
            {
                double[] p = track.GlobalPositions;
                for (int i = 0; i < p.Length; i += 3)
                {
                    double s = Along(p[i], p[i + 2]);
                    double l = Across(p[i], p[i + 2]);
                    (double rx, _, double rz) = reference.At(i / 3 / scene.JointCount, scene.BodyRoot);
                    reach = Math.Max(reach, Math.Abs(s - Along(rx, rz)));
                    sMin = Math.Min(sMin, s);
                    sMax = Math.Max(sMax, s);
                    lMin = Math.Min(lMin, l);
                    lMax = Math.Max(lMax, l);
                    yMax = Math.Max(yMax, p[i + 1]);
                }
            }

            double sRange = Math.Max(sMax - sMin, 0.2 * _layout.Height);
            double lRange = Math.Max(lMax - lMin, 0.2 * _layout.Height);
            double yRange = Math.Max(yMax - _layout.Floor, 0.2 * _layout.Height);
            reach = Math.Min(reach, 0.8 * _layout.Height);

            const double rowInner = 210;
            double sideScale = rowInner / yRange;
            _rowHeight = rowInner + 2 * Pad + 22;
            _sideReach = reach * sideScale;
            double usable = SideWidth - 2 * Pad - 2 * _sideReach;
            _pixelsPerFrame = scene.FrameCount > 1 ? Math.Max(0, usable) / (scene.FrameCount - 1) : 0;
            double topScale = Math.Min((TopWidth - 2 * Pad) / sRange, rowInner / lRange);
            _side = new ViewBox(0, 1, _layout.Floor, yMax, sideScale, SideWidth, rowInner);
            _top = new ViewBox(sMin, sMax, lMin, lMax, topScale, TopWidth, rowInner);
            _reference = reference;
        }

        public double Height => HeaderHeight + _scene.Tracks.Count * (_rowHeight + Gap) + 26;

        public static double SheetWidth => Width;

        public static ContactSheetDrawing Of(PreviewScene scene) => new ContactSheetDrawing(scene);

        public string ToSvg()
        {
            var svg = new StringBuilder(256 * 1024);
            svg.Append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").Append(N(Width)).Append("\" height=\"").Append(N(Height))
                .Append("\" viewBox=\"0 0 ").Append(N(Width)).Append(' ').Append(N(Height)).Append("\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n");
            svg.Append("<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
            Header(svg);
            for (int t = 0; t < _scene.Tracks.Count; t++)
            {
                Row(svg, t, HeaderHeight + t * (_rowHeight + Gap));
            }

            double fy = Height - 10;
            svg.Append("<text x=\"").Append(N(Gap)).Append("\" y=\"").Append(N(fy)).Append("\" font-size=\"12\" fill=\"#7a838c\">")
                .Append(Escape(FooterText())).Append("</text>\n");
            svg.Append("</svg>\n");
            return svg.ToString();
        }

        private string FooterText()
        {
            string frames = string.Join(", ", _poses.Select(f => (f + _scene.FirstFrame).ToString(Invariant)));
            string trails = string.Join(", ", _trailJoints.Select(j => _scene.JointNames[j]));
            return $"poses at frames {frames}; gold: key frames; trails: {trails}; {_scene.FrameCount} frames at {1 / _scene.FrameTime:0.##} fps";
        }

        private void Header(StringBuilder svg)
        {
            string title = string.IsNullOrWhiteSpace(_scene.Title) ? "Motion contact sheet" : _scene.Title;
            svg.Append("<text x=\"").Append(N(Gap)).Append("\" y=\"30\" font-size=\"21\" font-weight=\"bold\" fill=\"#1d2329\">").Append(Escape(title)).Append("</text>\n");
            double sideX = Gap + LabelWidth + Gap;
            double topX = sideX + SideWidth + Gap;
            svg.Append("<text x=\"").Append(N(sideX)).Append("\" y=\"56\" font-size=\"14\" fill=\"#59626b\">side view, unrolled in time (→ frames; poses seen across the direction of travel)</text>\n");
            svg.Append("<text x=\"").Append(N(topX)).Append("\" y=\"56\" font-size=\"14\" fill=\"#59626b\">top view (→ direction of travel)</text>\n");
        }

        private void Row(StringBuilder svg, int track, double y)
        {
            string color = TrackColors.Of(_scene, track);
            PreviewTrack t = _scene.Tracks[track];
            svg.Append("<g>\n");
            svg.Append("<rect x=\"").Append(N(Gap)).Append("\" y=\"").Append(N(y)).Append("\" width=\"6\" height=\"").Append(N(_rowHeight)).Append("\" rx=\"3\" fill=\"").Append(color).Append("\"/>\n");
            svg.Append("<text x=\"").Append(N(Gap + 16)).Append("\" y=\"").Append(N(y + 26)).Append("\" font-size=\"18\" font-weight=\"bold\" fill=\"#1d2329\">").Append(Escape(t.Name)).Append("</text>\n");
            string? note = null;
            if (track == _scene.GroundTruthTrack)
            {
                note = "the reference for errors";
            }
            else if (_scene.GroundTruthTrack >= 0)
            {
                note = "mean error " + _scene.FormatDistance(_scene.MeanErrorBetweenKeys(track));
            }

            if (note != null)
            {
                svg.Append("<text x=\"").Append(N(Gap + 16)).Append("\" y=\"").Append(N(y + 48)).Append("\" font-size=\"13\" fill=\"#59626b\">").Append(Escape(note)).Append("</text>\n");
                if (track != _scene.GroundTruthTrack)
                {
                    string scope = _scene.KeyFrames.Count > 0 ? "per joint, between keys" : "per joint";
                    svg.Append("<text x=\"").Append(N(Gap + 16)).Append("\" y=\"").Append(N(y + 66)).Append("\" font-size=\"12\" fill=\"#7a838c\">").Append(scope).Append("</text>\n");
                }
            }

            double sideX = Gap + LabelWidth + Gap;
            double topX = sideX + SideWidth + Gap;
            Panel(svg, track, color, sideX, y, _side, side: true);
            Panel(svg, track, color, topX, y, _top, side: false);
            svg.Append("</g>\n");
        }

        private void Panel(StringBuilder svg, int track, string color, double x, double y, ViewBox box, bool side)
        {
            svg.Append("<rect x=\"").Append(N(x)).Append("\" y=\"").Append(N(y)).Append("\" width=\"").Append(N(box.PanelWidth)).Append("\" height=\"").Append(N(_rowHeight))
                .Append("\" rx=\"6\" fill=\"#f5f6f8\" stroke=\"#e1e4e8\"/>\n");
            // Top view: the drawing is centred in the panel. Side view: time runs left to right, each
            // joint placed by its distance along the travel from the reference root on that frame.
            double ox = x + (box.PanelWidth - (box.Max0 - box.Min0) * box.Scale) / 2;
            double oy = y + Pad + (box.Inner - (box.Max1 - box.Min1) * box.Scale) / 2 + (box.Max1 - box.Min1) * box.Scale;
            double timeX = x + Pad + _sideReach;
            Mapping map = (frame, px, py, pz) =>
            {
                if (side)
                {
                    (double rx, _, double rz) = _reference.At(frame, _scene.BodyRoot);
                    double u = timeX + frame * _pixelsPerFrame + (Along(px, pz) - Along(rx, rz)) * box.Scale;
                    return (u, oy - (py - box.Min1) * box.Scale);
                }

                return (ox + (Along(px, pz) - box.Min0) * box.Scale, oy - (Across(px, pz) - box.Min1) * box.Scale);
            };

            if (side)
            {
                (_, double gy) = map(0, 0, _layout.Floor, 0);
                svg.Append("<line x1=\"").Append(N(x + 6)).Append("\" x2=\"").Append(N(x + box.PanelWidth - 6)).Append("\" y1=\"").Append(N(gy)).Append("\" y2=\"").Append(N(gy))
                    .Append("\" stroke=\"#aeb6bf\" stroke-width=\"1.5\"/>\n");
            }

            svg.Append("<svg x=\"").Append(N(x)).Append("\" y=\"").Append(N(y)).Append("\" width=\"").Append(N(box.PanelWidth)).Append("\" height=\"").Append(N(_rowHeight))
                .Append("\" viewBox=\"").Append(N(x)).Append(' ').Append(N(y)).Append(' ').Append(N(box.PanelWidth)).Append(' ').Append(N(_rowHeight)).Append("\" overflow=\"hidden\">\n");
            int truth = _scene.GroundTruthTrack;
            bool ghost = truth >= 0 && truth != track;
            if (ghost)
            {
                Trails(svg, _scene.Tracks[truth], map, Ghost, 0.9);
                foreach (int f in _poses)
                {
                    if (!_keys.Contains(f)) Pose(svg, _scene.Tracks[truth], f, map, Ghost, 2.2, 0.9);
                }
            }

            Trails(svg, _scene.Tracks[track], map, color, 0.55);
            foreach (int f in _poses)
            {
                if (!_keys.Contains(f)) Pose(svg, _scene.Tracks[track], f, map, color, 2.4, 0.9);
            }

            foreach (int f in _poses)
            {
                if (_keys.Contains(f)) KeyPose(svg, _scene.Tracks[track], f, map);
            }

            svg.Append("</svg>\n");
            if (side)
            {
                double labelY = y + _rowHeight - 7;
                double lastX = double.NegativeInfinity;
                foreach (int f in _poses)
                {
                    double lx = timeX + f * _pixelsPerFrame;
                    if (lx - lastX < 30) continue;
                    lastX = lx;
                    string fill = _keys.Contains(f) ? KeyStroke : "#7a838c";
                    svg.Append("<text x=\"").Append(N(lx)).Append("\" y=\"").Append(N(labelY)).Append("\" font-size=\"11\" text-anchor=\"middle\" fill=\"").Append(fill).Append("\">")
                        .Append((f + _scene.FirstFrame).ToString(Invariant)).Append("</text>\n");
                }
            }
        }

        private void Trails(StringBuilder svg, PreviewTrack track, Mapping map, string color, double opacity)
        {
            foreach (int j in _trailJoints)
            {
                svg.Append("<polyline fill=\"none\" stroke=\"").Append(color).Append("\" stroke-opacity=\"").Append(N(opacity)).Append("\" stroke-width=\"1.3\" stroke-linejoin=\"round\"")
                    .Append(j == _scene.BodyRoot ? " stroke-dasharray=\"5 3\"" : "").Append(" points=\"");
                for (int f = 0; f < track.FrameCount; f++)
                {
                    (double x, double y, double z) = track.At(f, j);
                    (double u, double v) = map(f, x, y, z);
                    svg.Append(N(u)).Append(',').Append(N(v)).Append(' ');
                }

                svg.Append("\"/>\n");
            }
        }

        private void Pose(StringBuilder svg, PreviewTrack track, int frame, Mapping map, string color, double width, double opacity)
        {
            svg.Append("<path fill=\"none\" stroke=\"").Append(color).Append("\" stroke-opacity=\"").Append(N(opacity)).Append("\" stroke-width=\"").Append(N(width))
                .Append("\" stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\"").Append(Bones(track, frame, map)).Append("\"/>\n");
        }

        private void KeyPose(StringBuilder svg, PreviewTrack track, int frame, Mapping map)
        {
            string bones = Bones(track, frame, map);
            svg.Append("<path fill=\"none\" stroke=\"").Append(KeyStroke).Append("\" stroke-width=\"4.2\" stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\"").Append(bones).Append("\"/>\n");
            svg.Append("<path fill=\"none\" stroke=\"").Append(TrackColors.Key).Append("\" stroke-width=\"2.2\" stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\"").Append(bones).Append("\"/>\n");
        }

        private string Bones(PreviewTrack track, int frame, Mapping map)
        {
            var d = new StringBuilder();
            for (int j = 1; j < _scene.JointCount; j++)
            {
                if (!_scene.DrawsBone(j)) continue;
                int p = _scene.Parents[j];
                (double x0, double y0, double z0) = track.At(frame, p);
                (double x1, double y1, double z1) = track.At(frame, j);
                (double u0, double v0) = map(frame, x0, y0, z0);
                (double u1, double v1) = map(frame, x1, y1, z1);
                d.Append('M').Append(N(u0)).Append(' ').Append(N(v0)).Append('L').Append(N(u1)).Append(' ').Append(N(v1));
            }

            return d.ToString();
        }

        private double Along(double x, double z) => x * _layout.Travel[0] + z * _layout.Travel[2];

        private double Across(double x, double z) => x * _layout.Lateral[0] + z * _layout.Lateral[2];

        /// <summary>
        /// Frames drawn as poses: about seven key frames, evenly thinned, and between each two of them the
        /// middle of a gap between keys — never a key itself, since those poses are where in-betweening
        /// methods differ (with many keys, the midpoint of two thinned keys is often another key). Without
        /// keys, twelve evenly spaced frames.
        /// </summary>
        internal static int[] PoseFrames(PreviewScene scene)
        {
            int n = scene.FrameCount;
            var frames = new SortedSet<int>();
            if (scene.KeyFrames.Count == 0)
            {
                int count = Math.Min(12, n);
                for (int i = 0; i < count; i++) frames.Add(count == 1 ? 0 : (int)Math.Round(i * (n - 1) / (double)(count - 1)));
                return frames.ToArray();
            }

            IReadOnlyList<int> keys = scene.KeyFrames;
            int stride = (keys.Count + 6) / 7;
            var chosen = new List<int>();
            for (int i = 0; i < keys.Count; i += stride) chosen.Add(keys[i]);
            if (chosen[chosen.Count - 1] != keys[keys.Count - 1]) chosen.Add(keys[keys.Count - 1]);
            for (int i = 0; i < chosen.Count; i++)
            {
                frames.Add(chosen[i]);
                if (i + 1 < chosen.Count)
                {
                    int between = MiddleOfAGap(keys, chosen[i], chosen[i + 1]);
                    if (between >= 0) frames.Add(between);
                }
            }

            // Frames before the first key and after the last get poses too, about as far apart as the others.
            double spacing = chosen.Count > 1 ? (chosen[chosen.Count - 1] - chosen[0]) / (2.0 * (chosen.Count - 1)) : n / 12.0;
            spacing = Math.Max(spacing, n / 14.0);
            for (double f = chosen[0] - spacing; f > -0.5 * spacing; f -= spacing) frames.Add(Math.Max(0, (int)Math.Round(f)));
            for (double f = chosen[chosen.Count - 1] + spacing; f < n - 1 + 0.5 * spacing; f += spacing) frames.Add(Math.Min(n - 1, (int)Math.Round(f)));
            return frames.ToArray();
        }

        /// <summary>
        /// The frame midway through the gap between consecutive keys (inside <paramref name="from"/>..<paramref name="to"/>)
        /// whose middle lies nearest the middle of that span; −1 when every key there is next to the next.
        /// </summary>
        private static int MiddleOfAGap(IReadOnlyList<int> keys, int from, int to)
        {
            double middle = (from + to) / 2.0;
            int best = -1;
            double distance = double.PositiveInfinity;
            for (int g = 0; g + 1 < keys.Count; g++)
            {
                int a = keys[g], b = keys[g + 1];
                if (a < from || b > to || b - a < 2) continue;
                int m = (a + b) / 2;
                if (Math.Abs(m - middle) < distance)
                {
                    distance = Math.Abs(m - middle);
                    best = m;
                }
            }

            return best;
        }

        /// <summary>The body root, then the hands and feet: <see cref="PreviewScene.Extremities"/>, else found by name (left before right).</summary>
        internal static int[] TrailJoints(PreviewScene scene)
        {
            var joints = new List<int> { scene.BodyRoot };
            if (scene.Extremities != null)
            {
                foreach (int j in scene.Extremities)
                {
                    if (!joints.Contains(j)) joints.Add(j);
                }

                return joints.ToArray();
            }

            foreach (string part in new[] { "hand", "foot" })
            {
                foreach (string side in new[] { "left", "right" })
                {
                    int found = Find(scene, side, part);
                    if (found > 0 && !joints.Contains(found)) joints.Add(found);
                }
            }

            return joints.ToArray();
        }

        private static int Find(PreviewScene scene, string side, string part)
        {
            // "LeftHand", "l_hand", "mixamorig:LeftHand", "LHand": side first, then the part, nothing after it.
            string shortSide = side.Substring(0, 1);
            var pattern = new Regex("(^|[^a-z])(" + side + "|" + shortSide + ")[_ .:-]?" + part + "$", RegexOptions.IgnoreCase | RegexOptions.CultureInvariant);
            for (int j = 0; j < scene.JointCount; j++)
            {
                if (pattern.IsMatch(scene.JointNames[j])) return j;
            }

            return -1;
        }

        private static string N(double v) => v.ToString("0.#", Invariant);

        private static string Escape(string text) => WebUtility.HtmlEncode(text);

        private delegate (double X, double Y) Mapping(int frame, double x, double y, double z);

        private readonly struct ViewBox
        {
            public ViewBox(double min0, double max0, double min1, double max1, double scale, double panelWidth, double inner)
            {
                Min0 = min0;
                Max0 = Math.Max(max0, min0 + 1e-9);
                Min1 = min1;
                Max1 = Math.Max(max1, min1 + 1e-9);
                Scale = scale;
                PanelWidth = panelWidth;
                Inner = inner;
            }

            public double Min0 { get; }

            public double Max0 { get; }

            public double Min1 { get; }

            public double Max1 { get; }

            public double Scale { get; }

            public double PanelWidth { get; }

            public double Inner { get; }
        }
    }
}
