#!/usr/bin/env python3
"""Lists the failed tests of a TRX file (dotnet test's results) with the first lines of each message.

Tools~/test prints this after its summary: CI keeps only the tail of the output, where a failing test's
name would otherwise have scrolled away. Prints nothing when every test passed or was skipped."""
import sys
import xml.etree.ElementTree as ET

NS = "{http://microsoft.com/schemas/VisualStudio/TeamTest/2010}"
MESSAGE_LINES = 6


def failed_tests(path):
    for result in ET.parse(path).getroot().iter(NS + "UnitTestResult"):
        if result.get("outcome") not in ("Failed", "Error", "Timeout", "Aborted"):
            continue
        message = result.find(".//" + NS + "Message")
        text = (message.text or "") if message is not None else ""
        yield result.get("testName"), [line for line in text.splitlines() if line.strip()][:MESSAGE_LINES]


def main(argv):
    if len(argv) != 2:
        print("usage: failed_tests.py RESULTS.trx", file=sys.stderr)
        return 2
    try:
        failures = list(failed_tests(argv[1]))
    except (OSError, ET.ParseError) as error:
        print(f"failed_tests.py: cannot read {argv[1]}: {error}", file=sys.stderr)
        return 1
    if failures:
        print(f"\n=== Failed C# tests ({len(failures)})")
        for name, lines in failures:
            print(f"FAILED {name}")
            for line in lines:
                print(f"    {line}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
