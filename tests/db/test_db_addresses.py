"""A PostgreSQL address given to a command that reads a SQLite file is refused
with a message naming the commands that take one, and no file is made; the
commands that take one try the server (and say when it cannot be reached)."""

from __future__ import annotations

import pytest

from sass_tui.cli import main
from sass_tui.db.engine.addresses import POSTGRES_COMMANDS, is_url

URL = "postgresql://lab@dbhost.invalid/sass"


def test_addresses_and_files_are_told_apart():
    assert is_url(URL) and is_url("POSTGRES://x/y")
    assert not is_url("postgresql.db") and not is_url(None)


def test_sass_serve_hands_an_address_to_its_sessions_in_the_environment(tmp_path, monkeypatch):
    """A served session opens the PostgreSQL database the server was given;
    the address (its password too) travels in $SASS_DB, never on a command
    line `ps` shows."""
    pytest.importorskip("textual_serve")
    from sass_tui.cli.serving import database_path
    from sass_tui.ui.serve.serve import ServeOptions
    from sass_tui.ui.serve.serve_session import SessionService

    secret = "postgresql://lab:s3cret@dbhost.invalid/sass"
    monkeypatch.setenv("SASS_DB", secret)
    args = type("Args", (), {"db": None})()
    db = database_path(args, read_only=False)
    assert db == secret
    options = ServeOptions(host="127.0.0.1", port=0, token="t" * 32, workdir=tmp_path, db=db)
    assert "s3cret" not in " ".join(options.command())
    assert "--db" not in options.command()

    async def nothing(*_args) -> None:
        return None

    service = SessionService(
        options,
        close_with=nothing,
        write_bytes=nothing,
        write_str=nothing,
        close=nothing,
        download_manager=None,
    )
    assert service._build_environment()["SASS_DB"] == secret


def test_sass_serve_read_only_on_an_address_tries_the_server(tmp_path, monkeypatch, capsys):
    pytest.importorskip("psycopg")
    monkeypatch.chdir(tmp_path)
    assert main(["serve", "--port", "0", "--read-only", "--db", URL]) == 2
    err = capsys.readouterr().err
    assert "cannot reach the PostgreSQL server" in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "argv",
    [
        ["fit", "stature <= 190 cm"],
        ["design", "--accommodate", "95", "stature <= ?"],
        ["family", "--gender", "female", "--measures", "stature,mass", "-o", "F"],
        ["population", "--query", "stature > 1", "-o", "x.dat"],
        ["predict", "--gender", "male", "--known", "stature=180cm"],
        ["target", "--list"],
        ["fig", "--person", "17", "-o", "x.fig"],
        ["export", "hanim", "--person", "17", "-o", "x.x3d"],
        ["strength", "--person", "17", "knee_extension", "knee_y=60"],
        ["reach", "--person", "17"],
        ["reach", "--point", "30,120,50", "--virtual", "nhanes-2017-2020"],
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


def test_a_default_path_is_never_made_of_an_address(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("SASS_DB", URL)
    pytest.importorskip("psycopg")
    assert main(["serve", "--port", "0", "--read-only"]) == 2
    assert "cannot reach the PostgreSQL server" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    ("address", "driver_says"),
    [
        # urllib.parse raised on both while the message was being made
        ("postgresql://lab:s3cret@127.0.0.1:abc/sass", 'invalid integer value "abc"'),
        ("postgresql://lab:s3cret@[::1/sass", "IPv6 host address"),
        ("postgresql://lab@127.0.0.1:1/sass?password=s3cret", "127.0.0.1"),
    ],
)
def test_an_address_the_driver_refuses_is_said_without_its_password(
    capsys, tmp_path, monkeypatch, address, driver_says
):
    """The driver's own words (libpq quotes a URI it cannot read, password
    and all) with the address shown as the message's start shows it."""
    pytest.importorskip("psycopg")
    monkeypatch.chdir(tmp_path)
    assert main(["query", "--db", address, "stature > 1 m"]) == 2
    err = capsys.readouterr().err
    assert "cannot reach the PostgreSQL server" in err and driver_says in err, err
    assert "s3cret" not in err and "***" in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []
