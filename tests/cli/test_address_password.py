"""The --db password warning's reading of an address (cli/common/options.py
`address_password`) against the standard library's: urllib.parse.urlsplit's
`.password` on any ASCII address, and the addresses a user types."""

from __future__ import annotations

import argparse
from urllib.parse import urlsplit

from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.cli.common.options import address_password, warn_of_a_password

# printable ASCII and the controls urlsplit strips, without "[" and "]" (an
# unbalanced bracket makes urlsplit raise: an IPv6 host, not a password)
_CHARACTERS = "".join(chr(c) for c in range(0x7F) if chr(c) not in "[]")
_PIECES = st.sampled_from(["postgresql", "postgres+x", "1x", ":", "//", "@", "/", "?", "#", " "])
_ADDRESSES = st.lists(st.one_of(_PIECES, st.text(_CHARACTERS, max_size=6)), max_size=8).map("".join)


@settings(max_examples=150, deadline=None)
@given(_ADDRESSES)
def test_the_password_is_urlsplits(address):
    assert address_password(address) == (urlsplit(address).password or "")


def test_addresses_a_user_types():
    assert address_password("postgresql://ann:secret@db.example/sass") == "secret"
    assert address_password("postgresql://ann:p@ss@db/sass") == "p@ss"  # the last @
    assert address_password("postgresql://ann@db/sass") == ""
    assert address_password("postgresql://ann:@db/sass") == ""
    assert address_password("postgresql://db/sass?user=ann:x@y") == ""  # past the authority
    assert address_password("/tmp/sass.db") == ""


def test_the_warning_names_the_verb(capsys):
    warn_of_a_password(argparse.Namespace(db="postgresql://a:b@h/d", command="niosh"))
    assert capsys.readouterr().err.startswith("sass niosh: warning: the password in --db")
    warn_of_a_password(argparse.Namespace(db="postgresql://a@h/d", command="niosh"))
    assert capsys.readouterr().err == ""
