using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;

namespace DeltaInterpolator.Tests.Preview
{
    /// <summary>
    /// A minimal PNG decoder for checking the pictures the preview writes: signature, IHDR, and the
    /// IDAT stream inflated with <see cref="ZLibStream"/> and unfiltered (8-bit RGB or RGBA, no interlace).
    /// </summary>
    internal sealed class PngImage
    {
        private static readonly byte[] Signature = { 137, 80, 78, 71, 13, 10, 26, 10 };

        private PngImage(int width, int height, byte[] rgb)
        {
            Width = width;
            Height = height;
            Rgb = rgb;
        }

        public int Width { get; }

        public int Height { get; }

        /// <summary>Width × height × 3 bytes, rows top to bottom.</summary>
        public byte[] Rgb { get; }

        public static PngImage Decode(byte[] png)
        {
            for (int i = 0; i < Signature.Length; i++)
            {
                if (png.Length < 8 || png[i] != Signature[i]) throw new InvalidDataException("not a PNG: the signature is missing");
            }

            int at = 8, width = 0, height = 0, channels = 0;
            var idat = new MemoryStream();
            bool sawHeader = false, sawEnd = false;
            while (at + 8 <= png.Length && !sawEnd)
            {
                int length = ReadInt(png, at);
                string type = System.Text.Encoding.ASCII.GetString(png, at + 4, 4);
                int data = at + 8;
                switch (type)
                {
                    case "IHDR":
                        width = ReadInt(png, data);
                        height = ReadInt(png, data + 4);
                        int depth = png[data + 8], color = png[data + 9], interlace = png[data + 12];
                        if (depth != 8 || (color != 2 && color != 6) || interlace != 0)
                        {
                            throw new InvalidDataException($"unsupported PNG: depth {depth}, colour type {color}, interlace {interlace}");
                        }

                        channels = color == 6 ? 4 : 3;
                        sawHeader = true;
                        break;
                    case "IDAT":
                        idat.Write(png, data, length);
                        break;
                    case "IEND":
                        sawEnd = true;
                        break;
                }

                at = data + length + 4;
            }

            if (!sawHeader || !sawEnd) throw new InvalidDataException("PNG without IHDR or IEND");
            int stride = width * channels;
            var raw = new byte[height * (stride + 1)];
            idat.Position = 0;
            using (var inflate = new ZLibStream(idat, CompressionMode.Decompress))
            {
                int read = 0;
                while (read < raw.Length)
                {
                    int n = inflate.Read(raw, read, raw.Length - read);
                    if (n == 0) throw new InvalidDataException($"IDAT holds {read} bytes; expected {raw.Length}");
                    read += n;
                }
            }

            var pixels = new byte[height * stride];
            var previous = new byte[stride];
            for (int y = 0; y < height; y++)
            {
                int filter = raw[y * (stride + 1)];
                int src = y * (stride + 1) + 1;
                int row = y * stride;
                for (int x = 0; x < stride; x++)
                {
                    int a = x >= channels ? pixels[row + x - channels] : 0;
                    int b = previous[x];
                    int c = x >= channels ? previous[x - channels] : 0;
                    int value = raw[src + x];
                    value += filter switch
                    {
                        0 => 0,
                        1 => a,
                        2 => b,
                        3 => (a + b) / 2,
                        4 => Paeth(a, b, c),
                        _ => throw new InvalidDataException($"row {y}: unknown filter {filter}"),
                    };
                    pixels[row + x] = (byte)value;
                }

                Array.Copy(pixels, row, previous, 0, stride);
            }

            var rgb = new byte[width * height * 3];
            for (int p = 0; p < width * height; p++)
            {
                rgb[3 * p] = pixels[p * channels];
                rgb[3 * p + 1] = pixels[p * channels + 1];
                rgb[3 * p + 2] = pixels[p * channels + 2];
            }

            return new PngImage(width, height, rgb);
        }

        /// <summary>Variance of the pixels' luminance (0..255 scale).</summary>
        public double LuminanceVariance()
        {
            double sum = 0, sum2 = 0;
            int n = Width * Height;
            for (int p = 0; p < n; p++)
            {
                double l = 0.299 * Rgb[3 * p] + 0.587 * Rgb[3 * p + 1] + 0.114 * Rgb[3 * p + 2];
                sum += l;
                sum2 += l * l;
            }

            double mean = sum / n;
            return sum2 / n - mean * mean;
        }

        /// <summary>How many pixels lie within <paramref name="tolerance"/> (per channel) of the colour #RRGGBB.</summary>
        public int CountNear(string hex, int tolerance)
        {
            int r = Convert.ToInt32(hex.Substring(1, 2), 16), g = Convert.ToInt32(hex.Substring(3, 2), 16), b = Convert.ToInt32(hex.Substring(5, 2), 16);
            int count = 0;
            for (int p = 0; p < Width * Height; p++)
            {
                if (Math.Abs(Rgb[3 * p] - r) <= tolerance && Math.Abs(Rgb[3 * p + 1] - g) <= tolerance && Math.Abs(Rgb[3 * p + 2] - b) <= tolerance) count++;
            }

            return count;
        }

        private static int Paeth(int a, int b, int c)
        {
            int p = a + b - c, pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
            return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        }

        private static int ReadInt(byte[] bytes, int at) => (bytes[at] << 24) | (bytes[at + 1] << 16) | (bytes[at + 2] << 8) | bytes[at + 3];
    }
}
