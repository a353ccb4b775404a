from __future__ import annotations

import csv
import gc
import gzip
import io
import os
import shutil
from dataclasses import dataclass
from pathlib import Path

import _bytecode  # noqa: F401  (first: sass's modules get bytecode; tests/_bytecode.py)
import pytest
from _built_once import built_once, copy_database_file
from _paths import ANSUR, REPORT
from hypothesis import settings

from sass_tui.cli import main
from sass_tui.model import shipped

# One BLAS thread in each test process: `pytest -n 3` already keeps both cores
# busy, and OpenBLAS's own threads then wait on each other (calibrating the
# shipped target's weights, model/population/targets.py's Newton steps: 7.6 ms a step
# with its threads under load, 1.5 ms with one; the model tests' CPU time
# 47 s -> 39 s).  Set before anything imports numpy; `sass` processes the
# tests start inherit it.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

# No time limit on a hypothesis example: a deadline is a timed assertion, and
# under a loaded CI machine an example of a parser's test took 269 ms against
# hypothesis's default 200 ms (tests/db/test_fit.py, a clone without ../shared
# beside a suite run).  A test that sets its own settings keeps them.
settings.register_profile("sass", deadline=None)
settings.load_profile("sass")


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


@pytest.fixture(scope="session")
def shipped_db_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The database `sass db init` builds from the shipped data, built once per
    run (tests/_built_once.py) with its prediction fit beside it, and never
    written: each area copies both (`copy_database_file`: `db` in tests/ui,
    `default_db_file` in tests/db, `default_people_db` in tests/web) or only
    reads it."""
    from sass_tui.db.engine.schema import connect
    from sass_tui.db.people.default import create_default_database
    from sass_tui.db.populations.predict import open_predictor

    def build(folder: Path) -> None:
        create_default_database(folder / "sass.db")
        # the prediction fit, cached beside it as `sass predict` leaves it
        # (copy_database_file gives each copy the fit with the file)
        conn = connect(folder / "sass.db")
        try:
            open_predictor(conn)
        finally:
            conn.close()

    return built_once(tmp_path_factory, "shipped", build) / "sass.db"


# Every SAMPLED_EVERY-th soldier of each ANSUR II file and adult of the
# NHANES file (a systematic sample: the shipped target's calibration still
# finds enough people of each gender; every 20th left too few women).
SAMPLED_EVERY = 10


@dataclass(frozen=True)
class SampledPeople:
    """What `sass db init` stores from the sampled data sets (counted in their CSV)."""

    female: int  # ANSUR II women
    male: int  # ANSUR II men
    virtual: int  # NHANES adults with a stature and a mass: one virtual person each

    @property
    def ansur(self) -> int:
        return self.female + self.male

    @property
    def everyone(self) -> int:
        return self.ansur + 200 + self.virtual  # and the 200 synthetic people


@pytest.fixture(scope="session")
def sampled_datasets(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, SampledPeople]:
    """A copy of the shipped data sets with every SAMPLED_EVERY-th row of the
    ANSUR II and NHANES files (the other files linked), and what a build
    from it stores."""
    source = Path(shipped.directory())
    folder = tmp_path_factory.mktemp("sampled-datasets")
    for item in source.iterdir():
        if item.name not in ("ansur2", "nhanes"):
            (folder / item.name).symlink_to(item)
    rows: dict[str, list[bytes]] = {}
    for group in ("ansur2", "nhanes"):
        (folder / group).mkdir()
        for file in sorted((source / group).glob("*.csv.gz")):
            lines = gzip.decompress(file.read_bytes()).splitlines(keepends=True)
            kept = lines[1::SAMPLED_EVERY]
            (folder / group / file.name).write_bytes(gzip.compress(b"".join([lines[0], *kept])))
            rows[file.name] = [lines[0], *kept]
    nhanes = csv.DictReader(io.StringIO(b"".join(rows["nhanes_2017_2020_adults.csv.gz"]).decode()))
    people = SampledPeople(
        female=len(rows["ANSUR_II_FEMALE_Public.csv.gz"]) - 1,
        male=len(rows["ANSUR_II_MALE_Public.csv.gz"]) - 1,
        virtual=sum(1 for row in nhanes if row["stature[cm]"] and row["mass[kg]"]),
    )
    return folder, people


@pytest.fixture
def few_default_people(sampled_datasets, monkeypatch) -> SampledPeople:
    """In this test, `sass db init` (create_default_database) builds the
    default database from `sampled_datasets`: the same steps and tables, a
    tenth of the people (608 soldiers and 839 virtual civilians against
    6,068 and 8,381), 0.47 s of CPU against 2.2 s.  For the tests of how a
    build starts, asks, replaces, locks and recovers, which hold for any
    people; what the default database holds is tested on the whole data
    (tests/cli/test_db.py: every soldier of the CSV files, every NHANES adult
    with a stature and a mass, demonstration people and nobody else).  Only
    this process: a `sass` the test starts reads the shipped data."""
    folder, people = sampled_datasets
    monkeypatch.setattr(shipped, "directory", lambda: str(folder))
    return people


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


@pytest.fixture(autouse=True, scope="session")
def _private_cache(tmp_path_factory):
    """What sass caches in the user's cache directory (a PostgreSQL database's
    prediction fit, db/populations/predict.py) goes here, never in the user's."""
    saved = os.environ.get("XDG_CACHE_HOME")
    os.environ["XDG_CACHE_HOME"] = str(tmp_path_factory.mktemp("cache"))
    yield
    if saved is None:
        os.environ.pop("XDG_CACHE_HOME", None)
    else:
        os.environ["XDG_CACHE_HOME"] = saved


# --- the fault tests' small file systems (tests/_tmpfs.py) --------------------


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
        shutil.copyfile(small_db_file, db)
        yield mnt, db


# --- the garbage collector ---------------------------------------------------


def pytest_collection_finish(session: pytest.Session) -> None:
    """Collect less often: a Textual session makes objects by the hundred
    thousand, and with Python's thresholds (700, 10, 10) the collector took a
    quarter of the UI tests' CPU, most of it rescanning the modules imported
    at collection.  Those are frozen out of every collection, and the young
    generation is collected every 20,000 allocations (tests/ui/test_keys.py,
    test_palette.py, test_query_snapshots.py and test_strength_page.py: 24.3 s
    of CPU, 20.6 s; 30 MB more at the peak).  Only when collection happens
    changes: every cycle is still collected, no test's assertion differs."""
    gc.collect()
    gc.freeze()
    gc.set_threshold(20_000, 10, 10)


# --- the slow marker --------------------------------------------------------

SLOW_S = 2.0
_unmarked_slow: list[tuple[str, float]] = []


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The files holding a slow test run first, each file's tests together and
    in their order (module fixtures are made once).  With `-n 2` a worker
    whose queue is empty waits for the other's test in progress: when a
    20-second PostgreSQL test came last, one worker sat idle for 12-26 s at
    the end of the run (shown as the last test's "teardown" by --durations).
    Short tests now fill the end."""
    slow_files = {item.path for item in items if item.get_closest_marker("slow")}
    items.sort(key=lambda item: item.path not in slow_files)


# --- both engines: a throwaway PostgreSQL cluster (tests/_postgres.py) ------------


# The database of the cluster after `sass db init`, that others are copied from.
TEMPLATE = "sass_template"


@pytest.fixture(scope="session")
def cluster(tmp_path_factory: pytest.TempPathFactory):
    """A running PostgreSQL cluster of this test process, a copy of the run's
    cluster made once with `sass db init` in its database TEMPLATE
    (tests/_built_once.py); the test skips, saying why, where none can start."""
    from _postgres import build_cluster_copy, running_cluster, why_not

    reason = why_not()
    if reason is not None:
        pytest.skip(f"PostgreSQL: {reason}")

    def sass_db_init(url: str) -> None:
        assert main(["db", "init", "--force", "--db", url]) == 0

    built = built_once(
        tmp_path_factory,
        "postgres",
        lambda folder: build_cluster_copy(folder / "data", TEMPLATE, sass_db_init),
    )
    with running_cluster(copy_of=built / "data") as running:
        yield running


@pytest.fixture(scope="session")
def postgres_template(cluster) -> str:
    """The name of the cluster's database after `sass db init` (made once per
    run, with the cluster it came in), that others are copied from (`CREATE
    DATABASE ... TEMPLATE`: a file copy, under a second where the import takes
    seconds).  Never connect to it: PostgreSQL copies only a template nobody is
    connected to."""
    return TEMPLATE


@pytest.fixture(scope="session")
def initialised(tmp_path_factory, cluster, postgres_template, shipped_db_file) -> dict[str, str]:
    """One database per engine after `sass db init`: {"sqlite": path, "postgresql": url}
    (PostgreSQL's a copy of `postgres_template`)."""

    sqlite_path = str(tmp_path_factory.mktemp("engines") / "sass.db")
    copy_database_file(shipped_db_file, sqlite_path)  # what `sass db init` builds
    url = cluster.create_database("initialised", postgres_template)
    return {"sqlite": sqlite_path, "postgresql": url}


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    """Note every test whose call took over SLOW_S without `@pytest.mark.slow`
    (under xdist this runs in the controller, on each worker's report)."""
    if report.when == "call" and report.duration > SLOW_S and "slow" not in report.keywords:
        _unmarked_slow.append((report.nodeid, report.duration))


def pytest_terminal_summary(terminalreporter) -> None:
    if _unmarked_slow:
        terminalreporter.write_sep("-", f"over {SLOW_S:g} s without @pytest.mark.slow")
        for nodeid, duration in sorted(_unmarked_slow, key=lambda item: -item[1]):
            terminalreporter.write_line(f"{duration:6.2f}s {nodeid}")


@pytest.fixture(scope="session")
def person_db(shipped_db_file, tmp_path_factory, ansur_dir):
    """The default database and three ANSUR II women (the first rows of the CSV)."""
    folder = tmp_path_factory.mktemp("persondb")
    db = folder / "people.db"
    lines = (ansur_dir / "ANSUR_II_FEMALE_Public.csv").read_text(encoding="latin-1").splitlines()
    small = folder / "ANSUR_II_FEMALE_Public.csv"
    small.write_text("\n".join(lines[:4]) + "\n", encoding="latin-1")
    copy_database_file(shipped_db_file, db)  # what `sass db init` builds
    assert main(["--db", str(db), "db", "import-ansur", str(small)]) == 0
    rows = list(csv.DictReader(lines[:4]))
    return db, rows
