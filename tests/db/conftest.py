"""The database tests' fixtures.

Both engines: a test that takes `engine_db` (a connection), `engine_target`
(an address for `QueryLists.open`, `Database.open` or a CLI's `--db`) or
`shared_target` runs twice, on SQLite and on PostgreSQL (the same answers on
both is the contract; docs/architecture.md).  The PostgreSQL run skips, saying
why, where no server can start (tests/_postgres.py's `why_not`).  Each test
process imports the shipped data once per engine (tests/conftest.py): SQLite's
`shipped_db_file`, PostgreSQL's `postgres_template` (`sass db init`); a test
that writes gets its own copy (`engine_target`: a file copy, `CREATE DATABASE
... TEMPLATE`), the read-only tests share one (`shared_target`, `engine_db`),
and the tests of a refused import share one a module (`refusal_target`,
`refusal_db`: each checks the database is as it found it).

SQLite only: `default_db` and `default_db_file`, for the tests about SQLite
itself (its files, locks, PRAGMAs, schema migrations, the DuckDB copy).
"""

from __future__ import annotations

import itertools
import shutil
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from _built_once import copy_database_file

from sass_tui.db.engine.schema import connect

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_FLAT = ROOT / "datasets" / "db"

ENGINES = ("sqlite", "postgresql")
_copies = itertools.count()


@pytest.fixture(scope="session")
def default_db_file(shipped_db_file, tmp_path_factory) -> Path:
    """The default database the database tests share (their queries keep lists
    in it): a copy of the session's build, which other areas copy too."""
    path = tmp_path_factory.mktemp("db") / "default.db"
    copy_database_file(shipped_db_file, path)
    return path


@pytest.fixture()
def default_db(default_db_file, tmp_path):
    """A private copy of the default database (tests may write to it)."""
    copy = tmp_path / "default.db"
    copy_database_file(default_db_file, copy)
    conn = connect(copy)
    yield conn
    conn.close()


# --- both engines -------------------------------------------------------------


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line(
        "markers",
        "sqlite_only(why): a test about SQLite itself; its PostgreSQL run (if its "
        "fixtures give it one) is skipped saying why",
    )


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        marker = item.get_closest_marker("sqlite_only")
        callspec = getattr(item, "callspec", None)
        if marker and callspec is not None and callspec.params.get("engine") == "postgresql":
            why = marker.args[0] if marker.args else "a test about SQLite itself"
            item.add_marker(pytest.mark.skip(reason=f"SQLite only: {why}"))


@pytest.fixture(scope="session", params=ENGINES)
def engine(request) -> str:
    """The engine a test runs on; "postgresql" skips, saying why, without a server."""
    if request.param == "postgresql":
        from _postgres import why_not

        reason = why_not()
        if reason is not None:
            pytest.skip(f"PostgreSQL: {reason}")
    return str(request.param)


@pytest.fixture(scope="session")
def shared_target(engine, request) -> str:
    """The address of the database the read-only tests of `engine` share."""
    if engine == "sqlite":
        return str(request.getfixturevalue("default_db_file"))
    template = request.getfixturevalue("postgres_template")
    return str(request.getfixturevalue("cluster").create_database("sass_shared", template))


@pytest.fixture(scope="session")
def copy_database(request, tmp_path_factory) -> Callable[[str], str]:
    """copy(address) -> the address of a new copy of that database, on its
    engine: a file copy, or `CREATE DATABASE ... TEMPLATE` (nobody may be
    connected to the original meanwhile; the copy goes with the cluster)."""
    from sass_tui.db.engine.addresses import is_url

    def copy(address: str) -> str:
        if not is_url(address):
            path = tmp_path_factory.mktemp("copy") / "sass.db"
            copy_database_file(Path(address), path)
            return str(path)
        name = f"sass_copy_{next(_copies)}"
        return str(request.getfixturevalue("cluster").create_database(name, _name_of(address)))

    return copy


def _name_of(url: str) -> str:
    return url.rsplit("/", 1)[-1]


@pytest.fixture(scope="session")
def template_target(engine, request) -> str:
    """The address to copy the default database of `engine` from (never open it:
    PostgreSQL copies only a template nobody is connected to)."""
    if engine == "sqlite":
        return str(request.getfixturevalue("default_db_file"))
    return str(request.getfixturevalue("cluster").url(request.getfixturevalue("postgres_template")))


@pytest.fixture()
def engine_target(engine, template_target, request, copy_database) -> Iterator[str]:
    """The address of a private copy of the default database on `engine` (the
    test may write to it), dropped after the test."""
    yield from _copy_of_default(engine, template_target, request, copy_database)


@pytest.fixture(scope="module")
def refusal_target(engine, template_target, request, copy_database) -> Iterator[str]:
    """The address of a copy of the default database on `engine` that the
    refusal tests of one module share: each imports what must be refused and
    checks that the database holds what it held before (its own row counts
    before and after), so the next may begin where the last ended, as a
    user's database goes through one refused file after another.  A test
    whose import wrongly stored something still fails on its own counts.
    One copy a module, not one a test: a PostgreSQL copy costs the server
    0.3-0.4 s of CPU (`CREATE DATABASE ... TEMPLATE` of the 102 MB default
    database), and there are about 30 refusal tests on each engine."""
    yield from _copy_of_default(engine, template_target, request, copy_database)


@pytest.fixture()
def refusal_db(refusal_target) -> Iterator[object]:
    """A connection of its own to `refusal_target`."""
    yield from _opened(refusal_target)


def _copy_of_default(
    engine: str,
    template_target: str,
    request: pytest.FixtureRequest,
    copy_database: Callable[[str], str],
) -> Iterator[str]:
    """A copy of the default database on `engine`, removed when the fixture ends."""
    url = copy_database(template_target)
    yield url
    if engine == "postgresql":
        request.getfixturevalue("cluster").drop_database(_name_of(url))
    else:  # its folder (copy_database's) would hold the 59 MB to the run's end
        shutil.rmtree(Path(url).parent, ignore_errors=True)


def _opened(target: str) -> Iterator[object]:
    from sass_tui.db.engine.database import Database

    db = Database.open(target)
    try:
        with db.connection() as conn:
            yield conn
    finally:
        db.close()


@pytest.fixture()
def engine_db(shared_target) -> Iterator[object]:
    """A connection of its own to the shared database of `engine`, through the
    Database service (sqlite3's, or db/engine/postgres.py's PostgresConnection).  Read
    only: a test that writes takes `engine_db_copy`."""
    yield from _opened(shared_target)


@pytest.fixture(scope="session")
def shared_db(shared_target) -> Iterator[object]:
    """One connection per test process to the shared database of `engine`, for
    the read-only tests that make no query lists (their TEMP tables live in
    the connection's session)."""
    yield from _opened(shared_target)


@pytest.fixture()
def engine_db_copy(engine_target) -> Iterator[object]:
    """A connection to a private copy of the default database on `engine`."""
    yield from _opened(engine_target)
