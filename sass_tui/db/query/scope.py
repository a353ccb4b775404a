"""Real people by default: which people a query reaches.

The default database holds the 6,068 real people of ANSUR II, 200
synthetic demonstration people (`source = synthetic`, docs/data-sources.md),
who exist only to show the strength, joint-limit and center-of-mass columns
ANSUR II did not measure, and the virtual people of NHANES 2017-2020
(`source = "virtual:nhanes-2017-2020"`, db/populations/virtual.py), predicted from
civilians' stature and mass.  A count, a list, a population, a fit or a
prediction must not mix them into an answer about real people, so a query
that names no `source` term reaches only the people whose source is neither
`synthetic` nor `virtual:...`; any `source` term (`source = synthetic`, `source != ansur2`)
leaves the choice to the query.

`real_only` is the one place that scope is added, on the query's tree
(db/query/query_tree.py), so every engine's SQL and the DuckDB copy carry it;
`db/query/query.py`'s `compile_query` calls it.  When the
scope leaves nobody, `query.demonstration_hint` says how many demonstration
people the query would reach, and the query that reaches them
(`demonstration_query`).
"""

from __future__ import annotations

from sass_tui.db.query.query_tree import PERSON_TABLE, And, Comparison, Expr, names_field

DEMONSTRATION_SOURCE = "synthetic"
# Virtual people (db/populations/virtual.py) are stored under `virtual:<population>`: a
# prediction from a civilian's stature and mass, never a person measured.
VIRTUAL_PREFIX = "virtual:"
# source is NOT NULL (db/engine/schema.py) and the default database stores the label
# in lower case, so a plain comparison.  Its field is not `source`: the user
# did not name it, and a query that does is not scoped (names_field).
REAL_PEOPLE = Comparison("(real people)", PERSON_TABLE, "source", "!=", DEMONSTRATION_SOURCE)
NOT_VIRTUAL = Comparison("(real people)", PERSON_TABLE, "source", "NOT LIKE", f"{VIRTUAL_PREFIX}%")


def source_label(text: str) -> str:
    """The label a person's source is stored under: a source whose first word
    is "synthetic" (the shipped flat files say "SYNTHETIC (not a real person):
    drawn by …") is the demonstration label, so that people imported from such
    a file are out of a real answer as the default database's are."""
    first = text.strip().split(None, 1)[0] if text.strip() else ""
    word = "".join(ch for ch in first if ch.isalpha()).lower()
    return DEMONSTRATION_SOURCE if word == DEMONSTRATION_SOURCE else text


def real_only(expr: Expr | None) -> Expr:
    """`expr` (None: everyone) limited to real people, unless it names a
    `source` term (or is limited already): the scope is one more term of its
    top-level AND."""
    if expr is None:
        return And((REAL_PEOPLE, NOT_VIRTUAL))
    if names_field(expr, "source") or REAL_PEOPLE in expr.comparisons():
        return expr
    terms = expr.terms if isinstance(expr, And) else (expr,)
    return And((*terms, REAL_PEOPLE, NOT_VIRTUAL))


def virtual_source(population: str) -> str:
    """The source label of a virtual population's people."""
    return f"{VIRTUAL_PREFIX}{population}"


def virtual_query(population: str) -> str:
    """The query term that reaches a virtual population's people (and only them)."""
    label = virtual_source(population).replace('"', "")
    return f'source = "{label}"'


def demonstration_query(text: str) -> str:
    """The query that reaches the demonstration people `text` would select."""
    return f"({text}) AND source = {DEMONSTRATION_SOURCE}"


# `source = synthetic` as the query language compiles it (free text: no regard to case).
DEMONSTRATION_PEOPLE = Comparison(
    "source", PERSON_TABLE, "source", "=", DEMONSTRATION_SOURCE, nocase=True
)


def demonstration_tree(scoped: Expr) -> Expr:
    """The tree of `demonstration_query` made from a query's scoped tree
    (`real_only`'s) without parsing its text again."""
    terms = scoped.terms if isinstance(scoped, And) else (scoped,)
    kept = tuple(term for term in terms if term != REAL_PEOPLE)
    asked = kept[0] if len(kept) == 1 else And(kept)
    return And((asked, DEMONSTRATION_PEOPLE))
