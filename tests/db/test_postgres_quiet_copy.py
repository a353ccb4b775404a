"""psycopg's "error ignored terminating <psycopg.Copy [BAD]>" (logged when a
COPY another error broke is ended) no longer reaches the terminal before
sass's own message (db/engine/postgres.py `_quiet_copy_teardown`); psycopg's other
warnings still do."""

from __future__ import annotations

import subprocess
import sys

import pytest

pytest.importorskip("psycopg")

SCRIPT = """
import logging
from sass_tui.db.engine.postgres import _driver
_driver()
log = logging.getLogger("psycopg")
log.warning("error ignored terminating %r: %s", "<psycopg.Copy [BAD]>", "server closed")
log.warning("another warning")
"""


def test_only_the_copy_teardown_warning_is_dropped():
    said = subprocess.run(
        [sys.executable, "-c", SCRIPT], capture_output=True, text=True, timeout=60, check=True
    ).stderr
    assert "error ignored terminating" not in said
    assert "another warning" in said


def test_a_password_on_the_command_line_is_warned_of(capsys):
    """`--db postgresql://user:pw@...` puts the password in `ps`; sass says
    so and names the places the driver reads one from.  (The server need not
    answer: the warning comes first.)"""
    from sass_tui.cli import main

    url = "postgresql://lab:s3cret@127.0.0.1:1/nowhere"
    assert main(["query", "--db", url, "--count", "gender = male"]) == 2
    said = capsys.readouterr().err
    assert "the password in --db shows in `ps`" in said and "~/.pgpass" in said
    assert "PGPASSWORD" in said and "s3cret" not in said
    main(["query", "--db", "postgresql://lab@127.0.0.1:1/nowhere", "--count", "gender = male"])
    assert "password in --db" not in capsys.readouterr().err
