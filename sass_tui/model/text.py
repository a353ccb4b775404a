"""Text from files and databases made safe to show on a terminal.

A name, title or source read from a file can hold control characters: an
escape sequence such as "\\x1b[2J\\x1b]0;pwned\\x07" clears the screen and sets
the terminal's title when printed.  Everything that shows such text (the
`sass query` table, the TUI's lists and titles) passes it through
`printable` first; the imports refuse such text (`control_character`).
"""

from __future__ import annotations

import re
from functools import cache

# C0 controls, DEL, C1 controls, the Unicode characters that reorder text
# (bidi marks and overrides) or break lines, and lone surrogates (which no
# terminal encoding can print).
# Compiled on first use (0.4 ms): most text is str.isprintable(), which no
# control character is (a test checks every code point), and needs no regex.
_CONTROLS = (
    "[\x00-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\u2028\u2029\ud800-\udfff]"
)


@cache
def _control() -> re.Pattern[str]:
    return re.compile(_CONTROLS)


def _escape(match: re.Match[str]) -> str:
    char = match.group(0)
    code = ord(char)
    if code == 0x1B:
        return "^["
    if code < 0x20:
        return "^" + chr(code + 0x40)  # ^A .. ^_ as terminals show them
    if code == 0x7F:
        return "^?"
    return f"\\u{code:04x}" if code > 0xFF else f"\\x{code:02x}"


def printable(text: object) -> str:
    """`text` as a string with every control character made visible.

    ESC becomes "^[", other C0 controls "^A".."^_", DEL "^?", C1 controls
    "\\x9b", and bidirectional overrides "\\u202e"; nothing a terminal would
    act on is left.  None becomes "".
    """
    if text is None:
        return ""
    string = str(text)
    if string.isprintable() or _control().search(string) is None:
        return string
    return _control().sub(_escape, string)


# What XML 1.0 allows no document to hold (clause 2.2, Char): the C0
# controls but tab, line feed and carriage return, surrogates, U+FFFE/FFFF.
_NOT_XML = "[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]"


def xml_safe(text: str) -> str:
    """`text` (an XML document, or a value for one) with every character XML
    1.0 forbids shown as printable() shows it: a name holding ESC made an
    X3D file no XML reader opens."""
    return re.sub(_NOT_XML, _escape, text)


def is_printable(text: str) -> bool:
    """Whether printable() would leave `text` as it is (one check for many values joined)."""
    return text.isprintable() or _control().search(text) is None


def is_printable_lines(text: str, lines: int) -> bool:
    """Whether `text` is `lines` lines, each ending in a newline, that
    printable() would leave as they are: one check for many values (a newline
    inside a value makes one line too many)."""
    if text.count("\n") != lines:
        return False
    return is_printable(text.replace("\n", ""))


def control_character(text: str) -> str | None:
    """Where `text`'s first control character is and what it is, e.g.
    "a control character (^[) at character 7", for an import that refuses
    it; None when `text` has none (the characters printable() escapes)."""
    if text.isprintable():
        return None
    found = _control().search(text)
    if found is None:
        return None
    return f"a control character ({_escape(found)}) at character {found.start() + 1}"


# The characters that make a spreadsheet (Excel, LibreOffice Calc, Google
# Sheets) read a CSV cell as a formula, or a tab/carriage return that shifts
# it into one: OWASP's "CSV Injection" page lists = + - @ TAB CR.
FORMULA_STARTS = "=+-@\t\r"
_FORMULA_START = re.compile("^[=+\\-@\t\r]", re.MULTILINE)


def spreadsheet_text(text: str) -> str:
    """`text` as a CSV cell a spreadsheet opens as text: one starting with a
    formula character gets a leading apostrophe (OWASP's advice), which
    spreadsheets take as "this cell is text"; the rest of the text is kept."""
    return "'" + text if text[:1] in tuple(FORMULA_STARTS) else text


def may_start_a_formula(texts: list[str]) -> bool:
    """Whether any of `texts` starts with a formula character: one search
    over them all joined (a text holding a newline may answer yes falsely)."""
    return _FORMULA_START.search("\n".join(texts)) is not None


# What a message quotes of a bad value: enough to find it in the file, never
# the whole of a megabyte line (a 1 GB file of one line once made a 4 GB
# message).
QUOTE_LIMIT = 40


def quoted(text: str, limit: int = QUOTE_LIMIT, *, escape: bool = False) -> str:
    """`text` quoted for a message, as repr() quotes it, cut to `limit`
    characters with its length said: "'xxxx…' (1,048,576 characters)".
    `escape`: its control characters made visible first (printable)."""
    shown = text[:limit]
    if escape:
        shown = printable(shown)
    if len(text) <= limit:
        return repr(shown)
    return f"{shown + '…'!r} ({len(text):,} characters)"


# --- a database address's password ------------------------------------------

# RFC 3986 section 3.1 (the string module would cost a regular expression's compiling)
_SCHEME_CHARACTERS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789+-.")
# What urllib.parse.urlsplit drops from an address before reading it (WHATWG
# URL: leading C0 controls and spaces, and every tab, CR and LF).
_LEADING_DROPPED = "".join(map(chr, range(0x21)))
_DROPPED = "\t\r\n"


def _password_spans(address: str) -> tuple[str, list[tuple[int, int]]]:
    """The address as urlsplit reads it, and where its passwords stand in
    that text: the authority's (scheme://user:password@host/..., RFC 3986
    section 3.2.1: the user information before the authority's last "@", the
    password after its first ":"), then each `password=` parameter of the
    query, which libpq's connection URIs take too (PostgreSQL manual, 34.1.1).
    Reads text only: never raises, whatever the port or host is."""
    text = address.lstrip(_LEADING_DROPPED)
    for dropped in _DROPPED:
        text = text.replace(dropped, "")
    start = 0
    scheme, colon, _ = text.partition(":")
    if colon and scheme and scheme[0].isascii() and scheme[0].isalpha():
        if set(scheme) <= _SCHEME_CHARACTERS:
            start = len(scheme) + 1
    spans: list[tuple[int, int]] = []
    if not text.startswith("//", start):
        return text, spans
    authority_start = start + 2
    authority_end = len(text)
    for delimiter in "/?#":
        found = text.find(delimiter, authority_start)
        if found != -1:
            authority_end = min(authority_end, found)
    at = text.rfind("@", authority_start, authority_end)
    if at != -1:
        colon_at = text.find(":", authority_start, at)
        if colon_at != -1 and colon_at + 1 < at:
            spans.append((colon_at + 1, at))
    fragment_at = text.find("#", authority_start)
    query_end = len(text) if fragment_at == -1 else fragment_at
    query_at = text.find("?", authority_start, query_end)
    if query_at != -1:
        position = query_at + 1
        for parameter in text[query_at + 1 : query_end].split("&"):
            key, equals, value = parameter.partition("=")
            if equals and key == "password" and value:
                spans.append((position + len(key) + 1, position + len(parameter)))
            position += len(parameter) + 1
    return text, spans


def address_password(address: str) -> str:
    """The password an address carries, '' if none: the authority's, as
    urllib.parse.urlsplit(address).password reads it, else a `password=`
    query parameter's.  Without urllib.parse and the ipaddress module it
    brings (~3 ms of every command that reads its --db)."""
    text, spans = _password_spans(address)
    return text[spans[0][0] : spans[0][1]] if spans else ""


def without_password(address: str) -> str:
    """The address to show in a message: each password it carries (see
    `address_password`) replaced by ***, the rest as typed."""
    text, spans = _password_spans(address)
    if not spans:
        return address
    pieces = []
    last = 0
    for start, end in spans:
        pieces += [text[last:start], "***"]
        last = end
    return "".join(pieces) + text[last:]


def other_separator(header: list[str]) -> str | None:
    """Why a CSV header of one cell is no header, when that cell holds
    semicolons or tabs: a spreadsheet set for a decimal comma saves its CSV
    with ';' between cells, and tab-separated text is no CSV either; None
    for any other header."""
    if len(header) != 1:
        return None
    if ";" in header[0]:
        return (
            "the cells are separated by ';', not commas (as a spreadsheet set for a decimal "
            "comma saves CSV): save it with commas between cells and points in numbers"
        )
    if "\t" in header[0]:
        return "the cells are separated by tabs, not commas: save it as CSV"
    return None
