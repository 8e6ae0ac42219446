#!/usr/bin/env python3
"""The two checks checked: the scanner reports exactly the fixture lines marked FOUND (as many times
as the mark is there) and nothing else; check_ts.py names each kind of incompleteness with its count.
Usage: selftest.py (from anywhere)."""
import collections
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURES = os.path.join(HERE, "fixtures")


def expected_findings(root):
    want = collections.Counter()
    for folder, _, files in os.walk(root):
        for name in files:
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, root)
            for number, line in enumerate(open(path, encoding="utf-8"), 1):
                if "each line saying FOUND" not in line:
                    want[f"{rel}:{number}"] += line.count("FOUND")
    return +want


def run(script, *args):
    done = subprocess.run([sys.executable, os.path.join(HERE, script), *args], capture_output=True, text=True)
    return done.returncode, done.stdout


def main():
    failures = []
    root = os.path.join(FIXTURES, "scan")
    code, out = run("scan_visible_strings.py", root)
    got = collections.Counter(re.match(r"(\S+:\d+):", l).group(1) for l in out.splitlines() if re.match(r"\S+:\d+: ", l))
    want = expected_findings(root)
    if code != 1:
        failures.append(f"the scanner exited {code} on the fixtures, not 1")
    for where in sorted(set(got) | set(want)):
        if got[where] != want[where]:
            failures.append(f"scanner: {where} reported {got[where]} time(s), marked FOUND {want[where]} time(s)")

    code, out = run("check_ts.py", os.path.join(FIXTURES, "incomplete.ts"), os.path.join(FIXTURES, "absent.ts"))
    for needle in ("1 of 4 message(s) unfinished", "1 of 4 message(s) obsolete", "1 of 4 message(s) finished but empty",
                   "absent.ts: missing"):
        if needle not in out:
            failures.append(f"check_ts.py did not say \"{needle}\":\n{out}")
    if code != 1:
        failures.append(f"check_ts.py exited {code} on an incomplete file, not 1")
    code, out = run("check_ts.py", os.path.join(HERE, "data", "sortie_de.ts"))
    if code != 0:
        failures.append(f"check_ts.py refused a complete file:\n{out}")

    for f in failures:
        print(f)
    print("self-test:", "failed" if failures else f"the scanner found the {sum(want.values())} marked literals; check_ts.py named each fault")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
