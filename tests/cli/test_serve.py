"""`sass serve`: an address other machines can reach is refused before any
web server starts, saying what would allow it."""

from __future__ import annotations

import pytest

from sass_tui.cli import main


def test_a_remote_address_needs_allow_remote(capsys):
    assert main(["serve", "--host", "0.0.0.0"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("sass serve: error:") and "--allow-remote" in err


def test_a_port_that_is_not_a_number_is_refused_by_the_parser(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["serve", "--port", "port"])
    assert stop.value.code == 2
    assert "--port" in capsys.readouterr().err
