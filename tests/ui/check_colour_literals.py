#!/usr/bin/env python3
"""Fails on a colour written into a QML view instead of taken from the theme (ui/theme, Theme).

A colour literal is a "#rgb"/"#rrggbb"/"#aarrggbb" string, a string naming an SVG colour
("red", "white"; "transparent" is no colour and allowed), or Qt.rgba/hsla/hsva/Qt.color with
numbers for its colour channels (Qt.rgba(theme.accent.r, ..., 0.15) derives from the theme and is
allowed); Qt.color("...") is caught by its string. Comments are skipped. Each literal is printed as file:line: text, and the exit status
is 1 when there is one.

    check_colour_literals.py QML_FILE_OR_FOLDER...   check these
    check_colour_literals.py --self-test             prove it catches what it should (and only that)
"""
import pathlib
import re
import sys

# SVG 1.1 / CSS colour keywords, as Qt's QColor::fromString knows them (QColor::colorNames()).
SVG_COLOURS = set("""
aliceblue antiquewhite aqua aquamarine azure beige bisque black blanchedalmond blue blueviolet brown
burlywood cadetblue chartreuse chocolate coral cornflowerblue cornsilk crimson cyan darkblue darkcyan
darkgoldenrod darkgray darkgreen darkgrey darkkhaki darkmagenta darkolivegreen darkorange darkorchid
darkred darksalmon darkseagreen darkslateblue darkslategray darkslategrey darkturquoise darkviolet
deeppink deepskyblue dimgray dimgrey dodgerblue firebrick floralwhite forestgreen fuchsia gainsboro
ghostwhite gold goldenrod gray grey green greenyellow honeydew hotpink indianred indigo ivory khaki
lavender lavenderblush lawngreen lemonchiffon lightblue lightcoral lightcyan lightgoldenrodyellow
lightgray lightgreen lightgrey lightpink lightsalmon lightseagreen lightskyblue lightslategray
lightslategrey lightsteelblue lightyellow lime limegreen linen magenta maroon mediumaquamarine
mediumblue mediumorchid mediumpurple mediumseagreen mediumslateblue mediumspringgreen
mediumturquoise mediumvioletred midnightblue mintcream mistyrose moccasin navajowhite navy oldlace
olive olivedrab orange orangered orchid palegoldenrod palegreen paleturquoise palevioletred
papayawhip peachpuff peru pink plum powderblue purple red rosybrown royalblue saddlebrown salmon
sandybrown seagreen seashell sienna silver skyblue slateblue slategray slategrey snow springgreen
steelblue tan teal thistle tomato turquoise violet wheat white whitesmoke yellow yellowgreen
""".split())

STRING = re.compile(r'"((?:[^"\\]|\\.)*)"|\'((?:[^\'\\]|\\.)*)\'')
HEX = re.compile(r'^#(?:[0-9a-fA-F]{3}|[0-9a-fA-F]{6}|[0-9a-fA-F]{8})$')
NUMBER = r'\s*[-+]?(?:\d+\.?\d*|\.\d+)\s*'
CALL = re.compile(r'\bQt\.(?:rgba|hsla|hsva)\(' + NUMBER + ',' + NUMBER + ',' + NUMBER + r'[,)]')


def strip_comments(text):
    """The text with // and /* */ comments blanked (strings kept), line numbers unchanged."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c in '"\'':
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            out.append(text[i:j + 1])
            i = j + 1
        elif text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i))
            i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(''.join(ch if ch == '\n' else ' ' for ch in text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def literals(text):
    """(line number, what) for each colour literal in QML text."""
    found = []
    for number, line in enumerate(strip_comments(text).split('\n'), start=1):
        for match in STRING.finditer(line):
            value = match.group(1) if match.group(1) is not None else match.group(2)
            if HEX.match(value) or value.lower() in SVG_COLOURS:
                found.append((number, match.group(0)))
        for match in CALL.finditer(line):
            found.append((number, match.group(0)))
    return found


def files(arguments):
    for argument in arguments:
        path = pathlib.Path(argument)
        if path.is_dir():
            yield from sorted(path.rglob('*.qml'))
        else:
            yield path


def check(arguments):
    problems = []
    for path in files(arguments):
        for number, what in literals(path.read_text(encoding='utf-8')):
            problems.append(f'{path}:{number}: colour literal {what}: take it from the theme (ui/theme/Theme.h)')
    for problem in problems:
        print(problem)
    if not problems:
        print(f'no colour literal in {", ".join(arguments)}')
    return 1 if problems else 0


def self_test():
    caught = {
        'color: "#e53935"': '"#e53935"',
        "border.color: '#fff'": "'#fff'",
        'color: x ? "white" : theme.text': '"white"',
        'color: "Red"': '"Red"',
        'color: "#80ff0000"': '"#80ff0000"',
        'color: Qt.rgba(1, 1, 1, 0.6)': 'Qt.rgba(1, 1, 1,',
        'color: Qt.hsla(0.5, .2, 0.3, 1)': 'Qt.hsla(0.5, .2, 0.3,',
        'color: Qt.color("steelblue")': '"steelblue"',
        'Rectangle { color: ["#43a047", theme.warning][i] }': '"#43a047"',
    }
    allowed = [
        'color: theme.problemText',
        'color: "transparent"',
        'text: "#1"',                    # not a colour: too short, and a waypoint's number
        'text: qsTr("Red alert")',       # words
        'objectName: "redButton"',
        'color: Qt.rgba(theme.accent.r, theme.accent.g, theme.accent.b, 0.15)',
        '// color: "#e53935" in a comment',
        '/* "white" */ color: theme.base',
        'font.family: "monospace"',
    ]
    failures = []
    for line, expected in caught.items():
        found = literals(line)
        if len(found) != 1 or not found[0][1].startswith(expected):
            failures.append(f'missed: {line!r} gave {found}')
    for line in allowed:
        if literals(line):
            failures.append(f'wrongly caught: {line!r} gave {literals(line)}')
    # A file: the line number is the literal's own.
    text = 'import QtQuick\n// a view\nRectangle {\n    color: theme.window\n    border.color: "#1e88e5"\n}\n'
    if literals(text) != [(5, '"#1e88e5"')]:
        failures.append(f'line numbers: {literals(text)}')
    for failure in failures:
        print(failure)
    print('self-test ' + ('failed' if failures else f'passed: {len(caught)} literals caught, {len(allowed)} lines allowed'))
    return 1 if failures else 0


if __name__ == '__main__':
    if sys.argv[1:] == ['--self-test']:
        sys.exit(self_test())
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    sys.exit(check(sys.argv[1:]))
