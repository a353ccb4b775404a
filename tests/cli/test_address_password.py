"""The reading of a database address's password (model/text.py
`address_password`, `without_password`), which the --db warning and every
message naming an address use: against the standard library's
urllib.parse.urlsplit `.password` on any ASCII address, libpq's `password=`
query parameter, and the addresses a user types, well formed or not."""

from __future__ import annotations

import argparse
from urllib.parse import urlsplit

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from sass_tui.cli.common.options import warn_of_a_password
from sass_tui.model.text import address_password, without_password

# printable ASCII and the controls urlsplit strips, without "[" and "]" (an
# unbalanced bracket makes urlsplit raise: an IPv6 host, not a password)
_CHARACTERS = "".join(chr(c) for c in range(0x7F) if chr(c) not in "[]")
_PIECES = st.sampled_from(["postgresql", "postgres+x", "1x", ":", "//", "@", "/", "?", "#", " "])
_ADDRESSES = st.lists(st.one_of(_PIECES, st.text(_CHARACTERS, max_size=6)), max_size=8).map("".join)


@settings(max_examples=150, deadline=None)
@given(_ADDRESSES)
def test_the_password_is_urlsplits(address):
    assume("password=" not in address)  # libpq's query parameter, which urlsplit does not read
    assert address_password(address) == (urlsplit(address).password or "")


@settings(max_examples=150, deadline=None)
@given(st.one_of(_ADDRESSES, st.text(max_size=40)))
def test_any_text_is_shown_without_raising(address):
    """Brackets, ports that are no number, any text: urlsplit raised on some."""
    shown = without_password(address)
    password = address_password(address)
    assert shown == address if not password else "***" in shown


@settings(max_examples=150, deadline=None)
@given(_ADDRESSES, st.text(st.characters(exclude_characters="@:/?#&[]"), min_size=1, max_size=8))
def test_only_the_password_is_replaced(rest, secret):
    assume(secret.isprintable() and secret.strip() == secret)
    rest = rest.lstrip("".join(map(chr, range(0x21))))
    assume(not any(c in rest for c in "\t\r\n") and "password=" not in rest)
    authority = rest.split("/")[0].split("?")[0].split("#")[0]
    assume("@" not in authority)  # the authority's last "@" is the one before the host
    typed = f"postgresql://ann:{secret}@{rest}"
    assert address_password(typed) == secret
    assert without_password(typed) == f"postgresql://ann:***@{rest}"


def test_addresses_a_user_types():
    assert address_password("postgresql://ann:secret@db.example/sass") == "secret"
    assert address_password("postgresql://ann:p@ss@db/sass") == "p@ss"  # the last @
    assert address_password("postgresql://ann@db/sass") == ""
    assert address_password("postgresql://ann:@db/sass") == ""
    assert address_password("postgresql://db/sass?user=ann:x@y") == ""  # past the authority
    assert address_password("/tmp/sass.db") == ""
    assert address_password("/tmp/a?password=x.db") == ""  # a file name, not an address
    assert address_password("postgresql://ann@db/sass?sslmode=require&password=pw") == "pw"
    assert address_password("postgresql://ann@db/sass#x?password=pw") == ""  # the fragment


def test_addresses_shown_in_messages():
    assert without_password("postgresql://ann:secret@db.example/sass") == (
        "postgresql://ann:***@db.example/sass"
    )
    # urlsplit raised on these two (a port that is no number, an unclosed bracket)
    assert (
        without_password("postgresql://ann:secret@db:abc/sass")
        == "postgresql://ann:***@db:abc/sass"
    )
    assert without_password("postgresql://ann:secret@[::1/sass") == "postgresql://ann:***@[::1/sass"
    # as typed: IPv6 brackets and the host's case kept
    assert (
        without_password("postgresql://ann:pw@[::1]:5432/Lab")
        == "postgresql://ann:***@[::1]:5432/Lab"
    )
    assert without_password("postgresql://ann@db/sass?password=pw&sslmode=require") == (
        "postgresql://ann@db/sass?password=***&sslmode=require"
    )
    assert (
        without_password("postgresql://ann:a@db/s?password=b")
        == "postgresql://ann:***@db/s?password=***"
    )
    assert without_password("postgresql://ann@db/sass") == "postgresql://ann@db/sass"


def test_the_warning_names_the_verb(capsys):
    warn_of_a_password(argparse.Namespace(db="postgresql://a:b@h/d", command="niosh"))
    assert capsys.readouterr().err.startswith("sass niosh: warning: the password in --db")
    warn_of_a_password(argparse.Namespace(db="postgresql://a@h/d", command="niosh"))
    assert capsys.readouterr().err == ""
    warn_of_a_password(argparse.Namespace(db="postgresql://a@h/d?password=b", command="query"))
    assert capsys.readouterr().err.startswith("sass query: warning: the password in --db")
