using System.Collections.Generic;

namespace DeltaInterpolator.Cli.Scoring
{
    /// <summary>
    /// A file-name glob with the rules of Python's <c>fnmatch.fnmatchcase</c> (which the trainer's <c>prepare</c>
    /// applies to the same manifests): <c>*</c> any run of characters ('/' too), <c>?</c> any one, <c>[seq]</c> and
    /// <c>[!seq]</c> sets with ranges (a reversed range such as <c>z-a</c> is empty, as Python has it), a <c>[</c>
    /// without a closing <c>]</c> is itself. Matched without regular expressions, in at most (pattern × name)
    /// steps: a translated regex threw on <c>[!]</c> and <c>[z-a]</c> and timed out on backtracking globs.
    /// </summary>
    internal sealed class FileGlob
    {
        private readonly Token[] _tokens;

        private FileGlob(Token[] tokens, string? reversedRange)
        {
            _tokens = tokens;
            ReversedRange = reversedRange;
        }

        /// <summary>The first reversed range in a set (e.g. <c>z-a</c>, which matches nothing), or null.</summary>
        public string? ReversedRange { get; }

        /// <summary>Reads <paramref name="pattern"/>; every pattern is a glob (nothing is refused here).</summary>
        public static FileGlob Parse(string pattern)
        {
            var tokens = new List<Token>();
            string? reversed = null;
            int n = pattern.Length;
            for (int i = 0; i < n; i++)
            {
                char c = pattern[i];
                if (c == '*')
                {
                    // Runs of stars are one star: fewer restarts when matching.
                    if (tokens.Count == 0 || tokens[tokens.Count - 1].Kind != TokenKind.Star) tokens.Add(new Token(TokenKind.Star));
                    continue;
                }

                if (c == '?')
                {
                    tokens.Add(new Token(TokenKind.Any));
                    continue;
                }

                if (c == '[')
                {
                    int j = i + 1;
                    bool negated = j < n && pattern[j] == '!';
                    if (negated) j++;
                    if (j < n && pattern[j] == ']') j++; // a ']' first in the set is one of its characters
                    int close = pattern.IndexOf(']', j);
                    if (close >= 0)
                    {
                        var set = new Token(TokenKind.Set) { Negated = negated };
                        int from = i + 1 + (negated ? 1 : 0);
                        for (int k = from; k < close; k++)
                        {
                            if (k + 2 < close && pattern[k + 1] == '-')
                            {
                                char low = pattern[k], high = pattern[k + 2];
                                if (low <= high) set.Ranges.Add((low, high));
                                else reversed ??= pattern.Substring(k, 3);
                                k += 2;
                            }
                            else
                            {
                                set.Ranges.Add((pattern[k], pattern[k]));
                            }
                        }

                        tokens.Add(set);
                        i = close;
                        continue;
                    }
                }

                tokens.Add(new Token(TokenKind.Literal) { Literal = c });
            }

            return new FileGlob(tokens.ToArray(), reversed);
        }

        /// <summary>True when the whole of <paramref name="text"/> matches (case-sensitive).</summary>
        public bool Matches(string text)
        {
            // One remembered star: on a mismatch the last star takes one more character. Every other token takes
            // exactly one character, so this finds a match whenever one exists, in at most (tokens × text) steps.
            int t = 0, p = 0, star = -1, starText = 0;
            while (t < text.Length)
            {
                if (p < _tokens.Length && _tokens[p].Kind == TokenKind.Star)
                {
                    star = p++;
                    starText = t;
                }
                else if (p < _tokens.Length && _tokens[p].Takes(text[t]))
                {
                    p++;
                    t++;
                }
                else if (star >= 0)
                {
                    p = star + 1;
                    t = ++starText;
                }
                else
                {
                    return false;
                }
            }

            while (p < _tokens.Length && _tokens[p].Kind == TokenKind.Star) p++;
            return p == _tokens.Length;
        }

        private enum TokenKind
        {
            Literal,
            Any,
            Set,
            Star,
        }

        private sealed class Token
        {
            public Token(TokenKind kind)
            {
                Kind = kind;
            }

            public TokenKind Kind { get; }

            public char Literal { get; set; }

            public bool Negated { get; set; }

            public List<(char Low, char High)> Ranges { get; } = new List<(char Low, char High)>();

            public bool Takes(char c)
            {
                switch (Kind)
                {
                    case TokenKind.Literal: return c == Literal;
                    case TokenKind.Any: return true;
                    case TokenKind.Set:
                        bool inside = false;
                        foreach ((char low, char high) in Ranges) inside |= c >= low && c <= high;
                        return inside != Negated;
                    default: return false;
                }
            }
        }
    }
}
