#!/usr/bin/env python3
"""Checks that translation files are complete: every message translated and finished, none obsolete.

Usage: check_ts.py FILE.ts [FILE.ts ...]
One line per problem, naming the file and the count; exit 1 when there is any. A file that is not
there is a problem too (the translation has not landed). A plural message (numerus="yes") needs
each of its forms filled in.
"""
import os
import sys
import xml.etree.ElementTree as ET


def problems_of(path):
    if not os.path.exists(path):
        return [f"{path}: missing (the translation has not landed yet)"]
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        return [f"{path}: not a readable .ts file ({e})"]
    unfinished, obsolete, empty, total = [], [], [], 0
    for context in root.iter("context"):
        name = context.findtext("name", "")
        for message in context.iter("message"):
            total += 1
            source = message.findtext("source", "")
            translation = message.find("translation")
            kind = translation.get("type", "") if translation is not None else "unfinished"
            where = f"{name}: \"{source}\""
            if kind in ("obsolete", "vanished"):
                obsolete.append(where)
            elif kind == "unfinished":
                unfinished.append(where)
            else:
                forms = translation.findall("numerusform") if message.get("numerus") == "yes" else [translation]
                if any(not "".join(f.itertext()).strip() for f in forms):
                    empty.append(where)
    out = []
    for what, entries in (("unfinished", unfinished), ("obsolete", obsolete), ("finished but empty", empty)):
        if entries:
            shown = "; ".join(entries[:5]) + (" ..." if len(entries) > 5 else "")
            out.append(f"{path}: {len(entries)} of {total} message(s) {what}, e.g. {shown}")
    if total == 0:
        out.append(f"{path}: no messages at all")
    return out


def main():
    problems = [p for path in sys.argv[1:] for p in problems_of(path)]
    for p in problems:
        print(p)
    if not problems:
        print(f"{len(sys.argv) - 1} translation file(s) complete")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
