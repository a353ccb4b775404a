"""The committed stand-alone parser is the grammar's: same digest, same trees as lark."""

from __future__ import annotations

import hashlib

import lark
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.db import _query_parser
from sass_tui.db.query import parser
from sass_tui.db.query_grammar import GRAMMAR

SAMPLES = [
    "gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb",
    "(stature < 190 cm OR mass < 100 kg) AND branch = 'Combat Arms'",
    'measure.sittingheight >= 95.5 cm and source = "ansur2"',
    "age ≤ 25 OR NOT",
    "stature >",
    "((a = 1))",
]


def reference() -> lark.Lark:
    return lark.Lark(GRAMMAR, parser="lalr", propagate_positions=True, maybe_placeholders=False)


def shape(node) -> object:
    """A tree as plain tuples (lark names rules by Token, the stand-alone by str)."""
    if hasattr(node, "children"):
        return (str(node.data), tuple(shape(c) for c in node.children))
    return (node.type, str(node), node.column)


def outcome(p, text: str) -> object:
    try:
        return shape(p.parse(text))
    except Exception as exc:  # the parsers' own errors, compared by kind and place
        return f"{type(exc).__name__} at {getattr(exc, 'column', None)}"


def test_the_generated_parser_was_made_from_this_grammar():
    # After editing query_grammar.py, run scripts/make_query_parser.py.
    assert _query_parser.GRAMMAR_SHA256 == hashlib.sha256(GRAMMAR.encode()).hexdigest()


def test_it_parses_as_lark_does():
    lark_parser = reference()
    for text in SAMPLES:
        assert outcome(parser(), text) == outcome(lark_parser, text), text


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet="ab.=<>!()'\" 0123456789cmANDORand_", max_size=40))
def test_any_text_parses_as_lark_does(text):
    assert outcome(parser(), text) == outcome(reference_parser, text)


reference_parser = reference()
