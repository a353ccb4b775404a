"""A PostgreSQL address given to a command that reads a SQLite file is refused
with a message naming the commands that take one, and no file is made; the
commands that take one try the server (and say when it cannot be reached)."""

from __future__ import annotations

import pytest

from sass_tui.cli import main
from sass_tui.db.addresses import POSTGRES_COMMANDS, is_url

URL = "postgresql://lab@dbhost.invalid/sass"


def test_addresses_and_files_are_told_apart():
    assert is_url(URL) and is_url("POSTGRES://x/y")
    assert not is_url("postgresql.db") and not is_url(None)


def test_a_sqlite_verb_refuses_an_address(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["serve", "--port", "0", "--db", URL]) == 2
    err = capsys.readouterr().err
    assert "`sass serve` reads a SQLite file only" in err and "`sass` (the spreadsheet)" in err
    for verb in POSTGRES_COMMANDS + ("db",):
        assert f"`sass {verb}" in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "argv",
    [
        ["fit", "stature <= 190 cm"],
        ["family", "--gender", "female", "--measures", "stature,mass", "-o", "F"],
        ["population", "--query", "stature > 1", "-o", "x.dat"],
        ["predict", "--gender", "male", "--known", "stature=180cm"],
        ["target", "--list"],
        ["fig", "--person", "17", "-o", "x.fig"],
        ["export", "hanim", "--person", "17", "-o", "x.x3d"],
        ["strength", "--person", "17", "knee_extension", "knee_y=60"],
    ],
)
def test_the_verbs_that_take_an_address_try_the_server(capsys, tmp_path, monkeypatch, argv):
    pytest.importorskip("psycopg")
    assert argv[0] in POSTGRES_COMMANDS
    monkeypatch.chdir(tmp_path)
    assert main([*argv, "--db", "postgresql://nobody@127.0.0.1:1/none"]) == 2
    err = capsys.readouterr().err
    assert "cannot reach the PostgreSQL server" in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_sass_serve_refuses_an_address_from_sass_db(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("SASS_DB", URL)
    assert main(["serve", "--port", "0"]) == 2
    assert "`sass serve` reads a SQLite file only" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_a_default_path_is_never_made_of_an_address(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("SASS_DB", URL)
    assert main(["serve", "--port", "0", "--read-only"]) == 2
    assert "SQLite file only" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []
