from __future__ import annotations

import os
from pathlib import Path

import pytest
from _paths import ANSUR, REPORT


@pytest.fixture(scope="session")
def report_lines() -> list[str]:
    if not REPORT.is_file():
        pytest.skip("../shared/seeds/sass-report.txt is absent")
    return REPORT.read_text(encoding="utf-8").splitlines()


@pytest.fixture(scope="session")
def ansur_dir() -> Path:
    if not (ANSUR / "ANSUR_II_MALE_Public.csv").is_file():
        pytest.skip("../shared/data/ansur2 is absent")
    return ANSUR


@pytest.fixture(autouse=True, scope="session")
def _private_default_database(tmp_path_factory: pytest.TempPathFactory):
    """A command run without --db builds its default database here, never in the
    user's data directory."""
    saved = os.environ.get("SASS_DB")
    os.environ["SASS_DB"] = str(tmp_path_factory.mktemp("default-db") / "sass.db")
    yield
    if saved is None:
        os.environ.pop("SASS_DB", None)
    else:
        os.environ["SASS_DB"] = saved


# --- the fault tests' small file systems (tests/_tmpfs.py; issue 17) ----------


@pytest.fixture(scope="module")
def small_db_file(tmp_path_factory) -> Path:
    from _tmpfs import build_small_db

    return build_small_db(tmp_path_factory.mktemp("small") / "small.db")


@pytest.fixture()
def tmpfs_with_db(tmp_path, small_db_file):
    """A tmpfs (the database's size + 2 MB) holding a copy of the small database."""
    from _tmpfs import mounted_tmpfs

    with mounted_tmpfs(tmp_path / "mnt", small_db_file.stat().st_size + 2 * 1024 * 1024) as mnt:
        db = mnt / "sass.db"
        db.write_bytes(small_db_file.read_bytes())
        yield mnt, db
