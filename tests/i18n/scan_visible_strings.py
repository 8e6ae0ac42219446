#!/usr/bin/env python3
"""Finds user-visible text that is not translatable, and names file:line of each.

What counts as visible (the scope; docs/ui.md, "Translations", says the same):
  QML (ui/qml/*.qml)
    - a string literal with a letter in it, in the value of a property that shows text:
      text, title, placeholderText, ToolTip.text, label, description, displayText, message,
      informativeText, detailedText, heading, subtitle, prefix, suffix, unit;
    - a string literal with a letter in a `model: [ ... ]` list (a ComboBox's choices);
    - a string literal with a letter after `return` in a QML function (they feed labels).
    unless it sits inside qsTr(), qsTranslate(), QT_TR_NOOP() or QT_TRANSLATE_NOOP().
  C++ (ui/, app/sortie, core/; .h and .cpp)
    - a string literal that reads as words for a person: a word of two or more letters and a
      space in it (so "row %1", "Take photo", "The server closed the connection"), outside tr(),
      QCoreApplication::translate(), QT_TR_NOOP and QT_TRANSLATE_NOOP.
  Everywhere: a literal that counts with "(s)" must use a %n plural form ("%n zone(s)").

Not counted (not visible, or not words):
  - log lines (qCDebug/qCInfo/qCWarning/qCCritical, qDebug/qInfo/qWarning/qCritical/qFatal),
    assertions (Q_ASSERT_X, static_assert), QML_UNCREATABLE/Q_CLASSINFO reasons, comments;
  - strings with no letter or with one word and no space: symbols ("—", "·", "+"), format-only
    strings ("%1, %2", "%1:%2"), JSON/XML keys, enum and state names, object names, roles,
    file suffixes ("gpx"), settings keys (single words are keys far more often than text, so
    they are reviewed by hand, not by this scan);
  - SQL statements, regular expressions, PROJ pipelines, date/time format patterns, colours,
    URL and host:port examples (placeholders that show syntax, e.g. "tcp://host:5760");
  - a literal compared (==, !=) or looked up (indexOf, contains, startsWith...): a key; in QML,
    the value of an object's key that is not a visible property ({value: "AGL"});
  - C++ that includes no Qt header (the Qt-free codecs: core/hci's frame codec, core/vci's codec,
    core/traffic/sbs): it cannot call tr(); its messages are protocol diagnostics, and they reach
    the operator untranslated, as the detail of a connection or protocol error;
  - the command-line programs' own output (app/sortie-plan, sortie-log, sortie-dump, sortie-sim)
    and sim/: they are not translated;
  - core code that only those programs run: core/endurance/fit (sortie-log fit), and sortie's own
    command line (app/sortie/LaunchOptions: --help and argument errors go to the terminal);
  - product names (core/mission/formats/DjiDroneModels.cpp: "DJI Matrice 30T").
  A line may opt out with a comment `i18n: not text (why)` when the scan cannot tell (a key
  with a space, a protocol string), a stretch with `i18n: not text below (why)` ... `i18n: text
  again`; each such opt-out says why.

Usage: scan_visible_strings.py SOURCE_DIR   -> exit 1 and one "file:line: literal" per finding.
"""
import os
import re
import sys

REGEX = re.compile(r"^\^.*\$$")
QML_PROPERTIES = r"(?:text|title|placeholderText|ToolTip\.text|label|description|displayText|message|" \
                 r"informativeText|detailedText|heading|subtitle|prefix|suffix|unit)"
TRANSLATING_CALLS = {"qsTr", "qsTranslate", "qsTrId", "tr", "translate", "QT_TR_NOOP", "QT_TRANSLATE_NOOP",
                     "QT_TR_N_NOOP", "QT_TRANSLATE_N_NOOP", "QT_TRID_NOOP"}
NOT_TEXT_CALLS = {"qCDebug", "qCInfo", "qCWarning", "qCCritical", "qDebug", "qInfo", "qWarning", "qCritical",
                  "qFatal", "Q_ASSERT_X", "static_assert", "QML_UNCREATABLE", "Q_CLASSINFO", "QFAIL",
                  "qFormatLogMessage", "setObjectName", "QLoggingCategory", "Q_LOGGING_CATEGORY",
                  "printf", "fprintf", "puts", "fputs", "exec", "prepare", "QSqlQuery", "QRegularExpression",
                  "indexOf", "lastIndexOf", "startsWith", "endsWith", "contains", "remove", "split"}
# A statement that logs or prints to a terminal: its literals are for a developer or a script.
NOT_TEXT_STATEMENT = re.compile(r"\b(?:qC(?:Debug|Info|Warning|Critical)|q(?:Debug|Info|Warning|Critical|Fatal))\s*\(|"
                                r"\bstd::(?:cout|cerr|clog)\b|\b(?:printf|fprintf|puts|fputs)\s*\(")
OPT_OUT = "i18n: not text"
# A stretch of lines that are not text: from a comment `i18n: not text below (why)` to `i18n: text again`.
OPT_OUT_BELOW, OPT_IN = "i18n: not text below", "i18n: text again"
WORDS = re.compile(r"[^\W\d_]{2,}")
LETTER = re.compile(r"[^\W\d_]")  # QML: a unit alone ("m") is text too
COLOUR = re.compile(r"^#[0-9a-fA-F]{3,8}$")
PROJ = re.compile(r"^\s*\+\w+")  # a PROJ pipeline
SQL = re.compile(r"^\s*(SELECT|INSERT|CREATE|UPDATE|DELETE|PRAGMA|BEGIN|COMMIT|REPLACE|DROP|ALTER|WITH)\b")
DATE_FORMAT = re.compile(r"^(?=.*(?:yy|MM|dd|HH|hh|mm|ss))[yMdHhmszapAPt:\-./ ,'T]+$")
URLISH = re.compile(r"^[a-z][a-z0-9+.-]*://|^[\w.-]+:\d+$")
CLI_ONLY = ("core/endurance/fit/", "app/sortie/LaunchOptions.")
# Names that are the same in every language: DJI's product names.
NAMES_ONLY = ("core/mission/formats/DjiDroneModels.cpp",)


def literals(code):
    """Yields (start, end, text) of each "..." literal in code whose comments are blanked."""
    i, n = 0, len(code)
    while i < n:
        c = code[i]
        if c == "R" and code.startswith('R"', i) and (i == 0 or not (code[i - 1].isalnum() or code[i - 1] == "_")):
            m = re.match(r'R"([^(\s]*)\(', code[i:])
            if m:
                close = code.find(")" + m.group(1) + '"', i + m.end())
                close = n if close < 0 else close
                yield i, close + len(m.group(1)) + 2, code[i + m.end():close]
                i = close + len(m.group(1)) + 2
                continue
        if c == "'" and not (i > 0 and code[i - 1].isalnum()):  # char literal (not a digit separator)
            j = i + 1
            while j < n and code[j] != "'" and code[j] != "\n":
                j += 2 if code[j] == "\\" else 1
            i = j + 1
            continue
        if c == '"':
            j = i + 1
            while j < n and code[j] != '"' and code[j] != "\n":
                j += 2 if code[j] == "\\" else 1
            yield i, j + 1, code[i + 1:j]
            i = j + 1
            continue
        i += 1


def blank_comments(code, qml):
    """The code with // and /* */ comments turned into spaces (line breaks kept)."""
    out, i, n = [], 0, len(code)
    while i < n:
        c = code[i]
        if c in "\"'`" and not (c == "'" and not qml and i > 0 and code[i - 1].isalnum()):
            j = i + 1
            while j < n and code[j] != c and code[j] != "\n":
                j += 2 if code[j] == "\\" else 1
            out.append(code[i:j + 1])
            i = j + 1
        elif code.startswith("//", i):
            j = code.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif code.startswith("/*", i):
            j = code.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", code[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def open_calls(code, pos):
    """The names of the calls whose parentheses are still open at pos, innermost first."""
    names, depth, i = [], 0, pos - 1
    floor = max(0, pos - 4000)
    while i >= floor:
        c = code[i]
        if c in ")]}":
            depth += 1
        elif c in "([{":
            if depth == 0:
                if c == "(":
                    m = re.search(r"([A-Za-z_][A-Za-z_0-9]*)\s*$", code[max(0, i - 80):i])
                    names.append(m.group(1) if m else "")
                elif c == "{":
                    break  # a block or an initializer list: the statement starts here
            else:
                depth -= 1
        elif c == ";" and depth == 0:
            break
        i -= 1
    return names


def statement_start(code, pos):
    i = pos - 1
    while i >= 0 and code[i] not in ";{}":
        i -= 1
    return code[i + 1:pos]


def is_words(text, qml):
    spaced = " " in text.strip()
    text = re.sub(r"%(?:\d+|n|L\d+)|\\.", " ", text)  # placeholders and escapes ("\n") are no words
    if not (LETTER if qml else WORDS).search(text) or COLOUR.match(text):
        return False
    if SQL.match(text) or PROJ.match(text) or REGEX.match(text) or DATE_FORMAT.match(re.sub(r"'[^']*'", "", text)) or URLISH.match(text.strip()):
        return False
    if qml:
        return True
    return spaced


WRAPPER_BEFORE = re.compile(r"(?:QStringLiteral|QLatin1String|QLatin1StringView|QStringView|QString|u8?)\s*\(?\s*$")
WRAPPER_AFTER = re.compile(r"^\)")


def compared(code, start, end):
    """A literal compared with something (`figure === "polygon"`) or looked up is a key, not text."""
    before = WRAPPER_BEFORE.sub("", code[max(0, start - 60):start].rstrip()).rstrip()
    after = WRAPPER_AFTER.sub("", code[end:end + 30].lstrip(), count=1).lstrip()
    return before.endswith(("==", "!=", "indexOf(", "contains(", "startsWith(", "endsWith(")) or after.startswith(("==", "!="))


def keyed(code, start):
    """A QML literal that is the value of an object's key other than a visible one ({value: "AGL"})."""
    m = re.search(r"([\w.]+)\s*:\s*$", code[max(0, start - 60):start])
    return bool(m) and not re.fullmatch(QML_PROPERTIES, m.group(1))


def qt_free(path):
    """C++ that includes no Qt header (the Qt-free codecs: core/hci's frame codec, core/vci's codec,
    core/traffic/sbs) cannot call tr(): its messages are protocol diagnostics, not counted."""
    stem = os.path.splitext(path)[0]
    for p in (stem + ".h", stem + ".cpp"):
        if os.path.exists(p) and re.search(r"#include\s*<Q", open(p, encoding="utf-8").read()):
            return False
    return True


def plural_finding(text):
    return ("(s)" in text or "(es)" in text) and "%n" not in text and re.search(r"%\d", text)


def opted_out(lines):
    """The 1-based numbers of the lines a comment takes out of the scan."""
    out, below = set(), False
    for number, line in enumerate(lines, 1):
        if OPT_OUT_BELOW in line:
            below = True
        elif OPT_IN in line:
            below = False
        if below or OPT_OUT in line:
            out.add(number)
    return out


def scan_cpp(path, rel, findings):
    raw = open(path, encoding="utf-8").read()
    code = blank_comments(raw, qml=False)
    lines = raw.split("\n")
    skipped = opted_out(lines)
    masked = mask_strings(code)
    run_text = {}  # a literal's start -> the text of the first literal of its run ("a" "b" is one string)
    previous_end, previous_text = -1, None
    for start, end, text in literals(code):
        joined = previous_end >= 0 and not masked[previous_end:start].strip()
        run_text[start] = run_text[previous_start] if joined else text
        previous_start, previous_end = start, end
    for start, end, text in literals(code):
        line = code.count("\n", 0, start) + 1
        if line in skipped:
            continue
        calls = open_calls(masked, start)
        statement = statement_start(masked, start)
        if set(calls) & NOT_TEXT_CALLS or NOT_TEXT_STATEMENT.search(statement) or SQL.match(run_text[start]):
            continue
        if code[max(0, start - 12):start].rstrip().endswith("#include") or compared(code, start, end):
            continue
        translated = bool(set(calls) & TRANSLATING_CALLS)
        if translated:
            if plural_finding(text):
                findings.append(f"{rel}:{line}: count with a %n plural form: \"{text}\"")
            continue
        if is_words(text, qml=False):
            findings.append(f"{rel}:{line}: \"{text}\"")


QML_VISIBLE = re.compile(r"(?:^|[;{\s])" + QML_PROPERTIES + r"\s*:\s*")
QML_MODEL = re.compile(r"(?:^|[;{\s])model\s*:\s*\[")
QML_RETURN = re.compile(r"(?:^|[;{\s])return\b")


def expression_end(code, pos):
    """Where a QML binding's expression that starts at pos ends: at a line break (or ';' / '}') when
    no bracket is open and the line does not end in an operator. An object (`header: ToolBar {`) is
    no expression."""
    if re.match(r"[A-Z][\w.]*\s*\{", code[pos:pos + 200]):
        return pos
    depth, i, n = 0, pos, len(code)
    while i < n:
        c = code[i]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                return i
            depth -= 1
        elif c in "\"'`":
            j = i + 1
            while j < n and code[j] != c and code[j] != "\n":
                j += 2 if code[j] == "\\" else 1
            i = j
        elif depth == 0 and c == ";":
            return i
        elif depth == 0 and c == "\n":
            before = code[pos:i].rstrip()
            after = code[i:].lstrip()
            if not (before.endswith(("+", "?", ":", "&&", "||", "(", ",")) or after.startswith(("+", "?", ":", "&&", "||", "."))):
                return i
        i += 1
    return n


def mask_strings(code):
    """The code with the inside of every literal blanked, so that patterns match code, not text."""
    out = list(code)
    for start, end, _ in literals(code):
        for i in range(start + 1, end - 1):
            if out[i] != "\n":
                out[i] = " "
    return "".join(out)


def scan_qml(path, rel, findings):
    raw = open(path, encoding="utf-8").read()
    code = blank_comments(raw, qml=True)
    masked = mask_strings(code)
    skipped = opted_out(raw.split("\n"))
    spans = []
    for pattern in (QML_VISIBLE, QML_MODEL, QML_RETURN):
        for m in pattern.finditer(masked):
            spans.append((m.end(), expression_end(code, m.end())))
    seen = set()
    for begin, end in spans:
        for start, stop, text in literals(code[begin:end]):
            start, stop = start + begin, stop + begin
            if start in seen:
                continue
            seen.add(start)
            line = code.count("\n", 0, start) + 1
            if line in skipped:
                continue
            calls = open_calls(masked, start)
            if set(calls) & TRANSLATING_CALLS:
                if plural_finding(text):
                    findings.append(f"{rel}:{line}: count with a %n plural form: \"{text}\"")
                continue
            if is_words(text, qml=True) and not compared(code, start, stop) and not keyed(code, start):
                findings.append(f"{rel}:{line}: \"{text}\"")


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    findings = []
    for top in ("ui", "app/sortie", "core"):
        for folder, _, files in sorted(os.walk(os.path.join(root, top))):
            for name in sorted(files):
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, root)
                if rel.startswith(CLI_ONLY) or rel in NAMES_ONLY:
                    continue
                if name.endswith(".qml"):
                    scan_qml(path, rel, findings)
                elif name.endswith((".cpp", ".h")) and not qt_free(path):
                    scan_cpp(path, rel, findings)
    for f in findings:
        print(f)
    if findings:
        print(f"{len(findings)} user-visible string(s) outside qsTr/tr (see the scope at the top of {sys.argv[0]})")
        return 1
    print("every user-visible string is translatable")
    return 0


if __name__ == "__main__":
    sys.exit(main())
