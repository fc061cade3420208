using System.Linq;
using DeltaInterpolator.Cli;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    public class TerminalTextTests
    {
        [Test]
        public void ControlCharactersBecomeVisibleEscapes()
        {
            Assert.That(TerminalText.Safe("a\u001b[2Jb\u0007\t\u0000\u009b\u202ec\u007f", 100), Is.EqualTo("a\\x1b[2Jb\\x07\\t\\x00\\x9b\\u202ec\\x7f"));
            Assert.That(TerminalText.Safe("Hips → Spine, ünïcödé", 100), Is.EqualTo("Hips → Spine, ünïcödé"), "printable text is left alone");
            Assert.That(TerminalText.Safe(null, 10), Is.EqualTo(""));
        }

        [Test]
        public void LongTextKeepsItsStartAndEndAndSaysWhatWasLeftOut()
        {
            string name = "Start" + new string('x', 10_000_000) + "End";
            string safe = TerminalText.Safe(name, TerminalText.NameLength);
            Assert.That(safe, Does.StartWith("Startxxx"));
            Assert.That(safe, Does.EndWith("xxEnd"));
            Assert.That(safe, Does.Contain("…[9,999,928 characters]…"));
            Assert.That(safe.Length, Is.LessThan(TerminalText.NameLength + 40));
        }

        [Test]
        public void ClippingNeverSplitsASurrogatePair()
        {
            string emoji = string.Concat(Enumerable.Repeat("😀", 100));
            string safe = TerminalText.Safe(emoji, 21);
            Assert.That(safe.Where(char.IsHighSurrogate).Count(), Is.EqualTo(safe.Where(char.IsLowSurrogate).Count()));
            Assert.That(char.IsLowSurrogate(safe[0]), Is.False);
        }
    }
}
