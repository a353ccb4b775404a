"""The query parser is Lark's own LALR parser, its tables kept in the user's
cache directory: read back, it parses as a parser built from the grammar
does, and a missing, damaged or unwritable cache only costs the build."""

from __future__ import annotations

import os
import stat

import lark
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.db import query_grammar
from sass_tui.db.query_grammar import GRAMMAR, parser, table_file

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
    """A tree as plain tuples: rule names, tokens with their columns and spans."""
    if hasattr(node, "children"):
        meta = node.meta
        span = (getattr(meta, "start_pos", None), getattr(meta, "end_pos", None))
        return (str(node.data), span, tuple(shape(c) for c in node.children))
    return (node.type, str(node), node.column)


def outcome(p, text: str) -> object:
    try:
        return shape(p.parse(text))
    except lark.exceptions.LarkError as exc:  # the parsers' own errors, by kind and place
        return f"{type(exc).__name__} at {getattr(exc, 'column', None)}"


@pytest.fixture
def own_cache(tmp_path, monkeypatch):
    """A cache directory of the test's own, and a parser made afresh in it."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    parser.cache_clear()
    yield tmp_path
    parser.cache_clear()


def test_the_tables_are_written_to_the_cache_with_the_users_umask(own_cache):
    old = os.umask(0o027)
    try:
        parser()
    finally:
        os.umask(old)
    path = table_file()
    assert path.parent == own_cache / "sass" / "parsers"
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert not [p.name for p in path.parent.iterdir() if p != path]  # no temporary left


def test_the_cached_tables_parse_as_the_grammar_built_afresh(own_cache):
    parser()  # writes the tables
    parser.cache_clear()
    built = []
    real_init = lark.Lark.__init__

    def counting_init(self, *args, **kwargs):
        built.append(args)
        real_init(self, *args, **kwargs)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(lark.Lark, "__init__", counting_init)
        loaded = parser()
    assert built == []  # read from the file, not built from the grammar
    fresh = reference()
    for text in SAMPLES:
        assert outcome(loaded, text) == outcome(fresh, text), text


def test_the_file_is_named_by_the_grammar_and_lark(own_cache, monkeypatch):
    first = table_file()
    monkeypatch.setattr(query_grammar, "GRAMMAR", GRAMMAR + "\n")
    assert table_file() != first
    monkeypatch.setattr(query_grammar, "GRAMMAR", GRAMMAR)
    monkeypatch.setattr(lark, "__version__", "0.0.1")
    assert table_file() != first


def test_a_damaged_cache_file_is_built_again(own_cache):
    path = table_file()
    path.parent.mkdir(parents=True)
    path.write_bytes(b"not lark's tables\n")
    assert outcome(parser(), SAMPLES[0]) == outcome(reference(), SAMPLES[0])
    parser.cache_clear()
    with open(path, "rb") as tables:  # written again, whole
        assert outcome(lark.Lark.load(tables), SAMPLES[1]) == outcome(reference(), SAMPLES[1])


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into a read-only directory")
def test_an_unwritable_cache_only_costs_the_build(own_cache):
    (own_cache / "sass").mkdir()
    (own_cache / "sass").chmod(0o500)
    try:
        assert outcome(parser(), SAMPLES[1]) == outcome(reference(), SAMPLES[1])
        assert not table_file().exists()
    finally:
        (own_cache / "sass").chmod(0o700)


def test_a_cache_path_that_is_a_file_only_costs_the_build(own_cache):
    (own_cache / "sass").write_text("a file where the folder would be")
    assert outcome(parser(), SAMPLES[2]) == outcome(reference(), SAMPLES[2])


def test_without_a_home_directory_the_parser_is_built(own_cache, monkeypatch):
    monkeypatch.delenv("XDG_CACHE_HOME")

    def no_home() -> None:
        raise RuntimeError("Could not determine home directory.")

    monkeypatch.setattr(query_grammar.Path, "home", staticmethod(no_home))
    assert outcome(parser(), SAMPLES[0]) == outcome(reference(), SAMPLES[0])


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet="ab.=<>!()'\" 0123456789cmANDORNTBWEand_", max_size=40))
def test_any_text_parses_as_lark_built_afresh_does(text):
    assert outcome(parser(), text) == outcome(reference_parser, text)


reference_parser = reference()
