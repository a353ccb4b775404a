"""$SASS_READ_ONLY=1 (what `sass serve --read-only` gives its sessions, or a
user sets) keeps a SQLite database as it is, as it keeps a PostgreSQL one
(tests/db/test_postgres_read_only.py): it was honoured on PostgreSQL only."""

from __future__ import annotations

import hashlib

import pytest
from _built_once import copy_database_file

from sass_tui.cli import main
from sass_tui.model import datasets
from sass_tui.model.served import READ_ONLY_ENV

pytestmark = pytest.mark.sqlite_only("$SASS_READ_ONLY on a SQLite file")

REFUSED = "the database is open read-only ($SASS_READ_ONLY=1); nothing changed"


@pytest.mark.slow
def test_every_write_is_refused_and_queries_answer(shipped_db_file, tmp_path, monkeypatch, capsys):
    db = tmp_path / "s.db"
    copy_database_file(shipped_db_file, db)
    digest = hashlib.sha256(db.read_bytes()).hexdigest()
    monkeypatch.setenv(READ_ONLY_ENV, "1")
    flat = datasets.directory() / "db"
    writes = [
        ["db", "init", "--force", "--db", str(db)],
        ["db", "import-flat", "--db", str(db), "--person", str(flat / "person.db"),
         "--girth", str(flat / "girth.db"), "--jntlmt", str(flat / "jntlmt.db"),
         "--cmass", str(flat / "cmass.db")],
        ["db", "import-ansur", "--db", str(db), str(datasets.directory() / "ansur2" /
                                                     "ANSUR_II_MALE_Public.csv.gz")],
        ["db", "init", "--db", str(tmp_path / "new.db")],
    ]  # fmt: skip
    for argv in writes:
        assert main(argv) == 2, argv
        said = capsys.readouterr().err
        assert REFUSED in said and "Traceback" not in said, said
    assert hashlib.sha256(db.read_bytes()).hexdigest() == digest
    assert not (tmp_path / "new.db").exists()
    assert main(["query", "--db", str(db), "--count", "gender = male"]) == 0
    assert capsys.readouterr().out.strip() == "4082"
