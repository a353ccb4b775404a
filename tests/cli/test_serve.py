"""`sass serve`: an address other machines can reach is refused before any
web server starts, saying what would allow it."""

from __future__ import annotations

import gc

import pytest

from sass_tui.cli import (
    COLLECT_AFTER_OBJECTS,
    PYTHON_COLLECT_THRESHOLD,
    build_parser,
    main,
    serving,
)


def test_a_remote_address_needs_allow_remote(capsys):
    assert main(["serve", "--host", "0.0.0.0"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("sass serve: error:") and "--allow-remote" in err


@pytest.mark.parametrize(
    ("port", "says"),
    [
        ("port", "'port' is not a whole number"),
        # the server printed http://localhost:99999/ and listened nowhere one could open
        ("99999", "99999 is no port: expected 0-65535"),
        ("65536", "65536 is no port: expected 0-65535"),
        ("-1", "-1 is negative"),  # it said "Servname not supported for ai_socktype"
    ],
)
def test_a_port_that_is_no_port_is_refused_by_the_parser(capsys, port, says):
    parser = build_parser(["serve"])
    with pytest.raises(SystemExit) as stop:
        parser.parse_args(["serve", "--port", port])
    assert stop.value.code == 2
    assert f"argument --port: {says}" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("url", "says"),
    [
        ("http://[::1", "Invalid IPv6 URL"),  # urlsplit raised: a traceback
        ("http://sass.example:abc/", "could not be cast to integer"),  # served, then unusable
        ("http://sass.example:99999/", "out of range"),
        ("ftp://sass.example/", "expected http(s)://HOST[:PORT]/"),
        ("https:///", "expected http(s)://HOST[:PORT]/"),
    ],
)
def test_a_public_url_that_is_no_url_of_a_server_is_refused(capsys, url, says):
    assert main(["serve", "--port", "0", "--public-url", url]) == 2
    err = capsys.readouterr().err
    assert err.startswith("sass serve: error: --public-url") and says in err, err


def test_the_server_collects_cycles_at_pythons_threshold(tmp_path, monkeypatch, capsys):
    """One-shot commands raise the collector's threshold (cli/__init__.py
    COLLECT_AFTER_OBJECTS); the server gives Python's back, or each
    session's cycles wait some 500 sessions (docs/reliability.md)."""
    seen = []
    monkeypatch.setattr(serving, "serve", lambda options: seen.append(gc.get_threshold()) or 0)
    before = gc.get_threshold()
    try:
        assert main(["serve", "--workdir", str(tmp_path)]) == 0
    finally:
        gc.set_threshold(*before)
    assert seen == [PYTHON_COLLECT_THRESHOLD]
    assert PYTHON_COLLECT_THRESHOLD[0] < COLLECT_AFTER_OBJECTS
    assert "Ctrl+C stops the server" in capsys.readouterr().err
