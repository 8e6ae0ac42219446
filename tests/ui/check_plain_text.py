#!/usr/bin/env python3
"""Fails on a Text or Label in a QML view that does not say `textFormat: Text.PlainText`.

Qt's default, Text.AutoText, renders a string that looks like HTML as HTML: a zone name from a KML
file, a vehicle's or route's name from a server, a server's error can then fetch an image
(`<img src="http://…">`) or fake a status (`<font color=green>`). Every Text and Label states its
format, so a string from outside is shown as it is (issue 36). Each offending item is printed as
file:line and the exit status is 1 when there is one.

    check_plain_text.py QML_FILE_OR_FOLDER...   check these
    check_plain_text.py --self-test             prove it catches what it should (and only that)
"""
import pathlib
import re
import sys

OPENING = re.compile(r'(?<![\w.])(Text|Label)\s*\{')


def blocks(text):
    """(line, block text) for each Text or Label item: from its brace to the matching one."""
    for m in OPENING.finditer(text):
        depth, i = 0, m.end() - 1
        while i < len(text):
            if text[i] == '{':
                depth += 1
            elif text[i] == '}':
                depth -= 1
                if depth == 0:
                    break
            i += 1
        body = text[m.end():i]
        # Only the item's own properties count, not those of a child item.
        own, nested = [], 0
        for ch in body:
            if ch == '{':
                nested += 1
            elif ch == '}':
                nested -= 1
            elif nested == 0:
                own.append(ch)
        yield text.count('\n', 0, m.start()) + 1, ''.join(own)


TOOLTIP = re.compile(r'(?<![\w.])ToolTip\s*\{')


def problems(path, text):
    text = re.sub(r'//[^\n]*', '', text)
    for line, own in blocks(text):
        if not re.search(r'\btextFormat\s*:', own):
            yield f'{path}:{line}: a Text or Label without textFormat (say Text.PlainText for anything from outside)'
    # A ToolTip item of its own renders its text at AutoText (the style's content item): PlainToolTip
    # is the one that does not. The attached ones share the instance Main.qml makes plain.
    if pathlib.Path(path).name != 'PlainToolTip.qml':
        for m in TOOLTIP.finditer(text):
            yield f'{path}:{text.count(chr(10), 0, m.start()) + 1}: a ToolTip item (use PlainToolTip, whose text is plain)'


def self_test():
    bad = 'Item {\n  Label { text: zone.name }\n  Text {\n    text: vehicle.name\n    Rectangle { textFormat: Text.PlainText }\n  }\n}\n'
    good = 'Item {\n  Label { textFormat: Text.PlainText; text: zone.name }\n  Text {\n    textFormat: Text.PlainText\n    text: x\n  }\n  TextField { text: y }\n  Component.onCompleted: console.log("Text {")\n}\n'
    found = list(problems('bad.qml', bad))
    assert len(found) == 2 and ':2:' in found[0] and ':3:' in found[1], found
    tips = list(problems('tips.qml', 'Item {\n  PlainToolTip { text: a }\n  ToolTip { text: b }\n  Button { ToolTip.text: c }\n}\n'))
    assert len(tips) == 1 and ':3:' in tips[0], tips
    assert not list(problems('PlainToolTip.qml', 'ToolTip {\n}\n'))
    assert not list(problems('good.qml', good.replace('console.log("Text {")', 'x()'))), list(problems('good.qml', good))
    print('check_plain_text: self-test passed')
    return 0


def main(args):
    if args == ['--self-test']:
        return self_test()
    found = []
    for a in args:
        p = pathlib.Path(a)
        for f in sorted(p.rglob('*.qml') if p.is_dir() else [p]):
            found += problems(f, f.read_text(encoding='utf-8'))
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
