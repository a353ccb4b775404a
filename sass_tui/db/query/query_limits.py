"""What the query language refuses before it parses: a query too long, too
deeply nested, with too many comparisons or joining too many tables (db/query/query.py
checks each text here first), and the error every refusal of a query is.
Its own module so the language's bounds and its error are read in one place."""

from __future__ import annotations

from sass_tui.model.errors import SassError


class QueryError(ValueError, SassError):
    """A query that cannot be run; `column` is 1-based in the query text."""

    def __init__(self, message: str, text: str = "", column: int | None = None):
        self.column = column
        self.text = text
        where = f"column {column}: " if column else ""
        super().__init__(f"{where}{message}")

    def pointer(self) -> str:
        """The query with a caret under the offending column."""
        if not self.column:
            return self.text
        return f"{self.text}\n{' ' * (self.column - 1)}^"


# Bounds on a query's shape, checked before parsing: deeper nesting would
# exhaust Python's recursion in the tree walk, and more comparisons SQLite's
# expression tree (its limit is 1000 levels; "a OR b OR ..." nests one a term).
MAX_NESTING = 50
MAX_COMPARISONS = 200
MAX_LENGTH = 20_000
MAX_JOINED_TABLES = 63  # SQLite joins at most 64 tables: person and 63 more
# The grammar's comparison operators, the two-character ones first (OP in db/query/query_grammar.py).
_OPERATOR_SPELLINGS = ("<=", ">=", "!=", "<>", "<", ">", "=", "≤", "≥", "≠")


def _operator_at(text: str, column: int) -> int:
    """The length of the comparison operator starting at `column`, 0 if none."""
    for spelling in _OPERATOR_SPELLINGS:
        if text.startswith(spelling, column):
            return len(spelling)
    return 0


def check_size(text: str) -> None:
    """Refuse a query too long, too deeply nested or with too many comparisons."""
    if len(text) > MAX_LENGTH:
        raise QueryError(
            f"the query is {len(text)} characters long; at most {MAX_LENGTH} are allowed",
            text[:80],
            None,
        )
    depth = 0
    comparisons = 0
    negations = 0  # each NOT is one level more of the tree, as a parenthesis is
    quote: str | None = None  # brackets and operators inside quoted text do not count
    column = 0
    while column < len(text):
        char = text[column]
        if quote:
            if char == quote:
                quote = None
        elif char in "'\"":
            quote = char
        elif char == "(":
            depth += 1
            if depth > MAX_NESTING:
                raise QueryError(
                    f"parentheses nested more than {MAX_NESTING} deep", text, column + 1
                )
        elif char == ")":
            depth -= 1
        elif char.isalpha() or char == "_":
            end = column
            while end < len(text) and (text[end].isalnum() or text[end] in "_."):
                end += 1
            word = text[column:end].lower()
            if word == "not":
                negations += 1
                if negations > MAX_NESTING:
                    raise QueryError(
                        f"NOT more than {MAX_NESTING} times in one query", text, column + 1
                    )
            elif word == "between":  # one BETWEEN is two comparisons (>= and <=)
                comparisons += 2
                _check_comparisons(comparisons, text, column)
            column = end
            continue
        else:
            length = _operator_at(text, column)
            if length:
                comparisons += 1
                _check_comparisons(comparisons, text, column)
                column += length
                continue
        column += 1


def _check_comparisons(comparisons: int, text: str, column: int) -> None:
    if comparisons > MAX_COMPARISONS:
        raise QueryError(
            f"more than {MAX_COMPARISONS} comparisons in one query; "
            "split it or use a range (e.g. stature BETWEEN 170 cm AND 180 cm)",
            text,
            column + 1,
        )
