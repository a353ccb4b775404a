"""`sass db init | import-flat | import-ansur` (spec §5) and `sass db copy` (the column copy)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sass_tui.cli.common.database_access import open_database
from sass_tui.cli.common.options import SubParsers, add_db_option, file_name, warn_of_a_password
from sass_tui.cli.common.progress import progress_for
from sass_tui.db.engine.addresses import is_url, shown
from sass_tui.db.engine.database import Database, configured_target, init_postgres
from sass_tui.db.engine.schema import DatabaseError, connect, default_db_path
from sass_tui.db.people.ansur import import_ansur_into
from sass_tui.db.people.default import SYNTHETIC_LABEL, create_default_database
from sass_tui.db.people.flatfile import FlatFileError, FlatFiles, import_flat_into
from sass_tui.db.people.replacing import Held, forget_column_copy, keep_targets, what_init_replaces
from sass_tui.db.query import accelerator
from sass_tui.db.query.query import QueryError, compile_query
from sass_tui.db.query.scope import VIRTUAL_PREFIX
from sass_tui.model.text import printable


def register(commands: SubParsers) -> None:
    db = commands.add_parser("db", help="create the database or import data into it")
    add_db_option(db)
    actions = db.add_subparsers(dest="db_command", metavar="ACTION", required=True)
    init = actions.add_parser(
        "init",
        help="(re)build the database: ANSUR II (6,068 people) and the synthetic people",
    )
    add_db_option(init)
    init.add_argument(
        "--force",
        action="store_true",
        help="replace a database that holds people (imports included) without asking",
    )
    init.set_defaults(func=run_init)
    flat = actions.add_parser("import-flat", help="import legacy flat files (report figure 12)")
    add_db_option(flat)
    flat.add_argument(
        "--person", required=True, metavar="F", type=file_name, help="the person flat file"
    )
    flat.add_argument(
        "--girth", required=True, metavar="F", type=file_name, help="the girth flat file"
    )
    flat.add_argument(
        "--jntlmt", required=True, metavar="F", type=file_name, help="the joint-limit flat file"
    )
    flat.add_argument(
        "--cmass", required=True, metavar="F", type=file_name, help="the center-of-mass flat file"
    )
    flat.add_argument(
        "strength",
        nargs="*",
        metavar="STRENGTH_FILE",
        type=file_name,
        help="strgh-par, shoulder-strgh, elbow-strgh, wrist-strgh files, "
        "in that order (leave out all to skip strength)",
    )
    flat.set_defaults(func=run_import_flat)
    ansur = actions.add_parser("import-ansur", help="import the ANSUR II public CSV files")
    add_db_option(ansur)
    ansur.add_argument(
        "files", nargs="+", metavar="FILE", type=file_name, help="CSV files (.csv or .csv.gz)"
    )
    ansur.add_argument(
        "--source",
        default="ansur2",
        metavar="LABEL",
        help="label of these people's source (default ansur2, the published survey)",
    )
    ansur.set_defaults(func=run_import_ansur)
    copy = actions.add_parser(
        "copy",
        help="build the DuckDB column copy that counts queries on 200,000 people and more",
        description="Build now the column copy of a SQLite database (a DuckDB file "
        "under $XDG_CACHE_HOME/sass/columns; pip install 'sass-tui[fast]') that "
        "counts a query on 200,000 people and more in milliseconds.  A count builds "
        "a missing or outdated copy in the background, which a one-shot `sass query` "
        "does not live to finish; after this, every process finds it until the next "
        "write to the database (the copy is then built anew).  It holds the columns "
        "it held, the person's gender, stature, mass, age and handedness, and every "
        "column the QUERYs name.",
    )
    add_db_option(copy)
    copy.add_argument(
        "queries",
        nargs="*",
        metavar="QUERY",
        help='queries whose columns to copy too, e.g. "girth.right_upper_arm.z > 28 cm"',
    )
    copy.set_defaults(func=run_copy)


def run_init(args: argparse.Namespace) -> int:
    warn_of_a_password(args)
    target = configured_target(getattr(args, "db", None))
    if is_url(target):
        return _init_postgres(str(target), args.force)
    path = Path(target) if target else default_db_path()
    held = Held({}, [])
    if path.exists() and path.stat().st_size:
        conn = connect(path, rebuild=True)
        try:
            held = what_init_replaces(conn)
        finally:
            conn.close()
    if held.count and not args.force and not _replace_confirmed(str(path), held):
        return 1
    bar = progress_for(sys.stderr, "building")
    counts = create_default_database(path, progress=bar, replace=True)
    if bar:
        bar.finish()
    # The old column copy follows another history: never read again, only
    # taking disk space.  None is built: the default people are fewer than
    # the copy's threshold (accelerator.MIN_PEOPLE), counted by SQLite.

    forget_column_copy(path.resolve())
    print(f"created {path}: {_built(counts)}")
    if held.targets:
        conn = connect(path)
        try:
            for line in keep_targets(conn, held):
                print(line)
        finally:
            conn.close()
    return 0


def _built(counts: dict[str, int]) -> str:
    """What `sass db init` stored (db/people/default.py's fill_default's counts per source)."""
    said = [
        f"{counts.get('ansur2', 0)} ANSUR II people and "
        f"{counts.get(SYNTHETIC_LABEL, 0)} synthetic people"
    ]
    for source, n in counts.items():
        if source.startswith(VIRTUAL_PREFIX):
            name = source.removeprefix(VIRTUAL_PREFIX)
            said.append(
                f"the shipped target {name} and its VIRTUAL population of {n} predicted "
                f"people (`--virtual {name}`)"
            )
    return "; ".join(said)


def _replace_confirmed(where: str, held: Held) -> bool:
    """Say what replacing deletes, one line each (the people by source, the
    stored targets), then ask; without a terminal to ask on, refuse saying
    what `--force` would replace."""
    lines = held.lines()
    if not (sys.stdin.isatty() and sys.stderr.isatty()):
        raise DatabaseError(
            f"{where} holds {held.count} people; `sass db init --force` replaces them "
            f"(imports included): {'; '.join(lines)}"
        )
    sys.stderr.write(f"{where} holds {held.count} people (imports included):\n")
    sys.stderr.write("".join(f"  {line}\n" for line in lines))
    sys.stderr.write("replace them with the default data set? [y/N] ")
    sys.stderr.flush()
    if sys.stdin.readline().strip().lower() in ("y", "yes"):
        return True
    print("nothing changed", file=sys.stderr)
    return False


def _init_postgres(url: str, force: bool) -> int:
    """`sass db init --db postgresql://...`: the schema and the default people,
    in one transaction; asks (or needs --force) before replacing people, and
    keeps the stored targets whose people are stored again."""
    db = Database.open(url, create=True)
    try:
        with db.connection() as conn:
            held = what_init_replaces(conn)
    finally:
        db.close()
    if held.count and not force and not _replace_confirmed(shown(url), held):
        return 1
    bar = progress_for(sys.stderr, "building")
    counts = init_postgres(url, bar, force=True)
    if bar:
        bar.finish()
    print(f"created the sass schema in {shown(url)}: {_built(counts)}")
    if held.targets:
        db = Database.open(url)
        try:
            with db.connection() as conn:
                for line in keep_targets(conn, held):
                    print(line)
        finally:
            db.close()
    return 0


def run_import_flat(args: argparse.Namespace) -> int:
    if len(args.strength) > 4:
        raise FlatFileError("at most four strength files: strgh-par, shoulder, elbow, wrist")
    strength = dict(zip(("strength_par", "shoulder", "elbow", "wrist"), args.strength))
    files = FlatFiles(
        person=Path(args.person),
        girth=Path(args.girth),
        joint_limits=Path(args.jntlmt),
        center_of_mass=Path(args.cmass),
        **{k: Path(v) for k, v in strength.items()},
    )
    count = import_flat_into(open_database(args, create=True), files)
    print(f"imported {count} people")
    return 0


def run_import_ansur(args: argparse.Namespace) -> int:
    db = open_database(args, create=True)
    bar = progress_for(sys.stderr)
    counts = import_ansur_into(db, args.files, progress=bar, label=args.source)
    if bar:
        bar.finish()
    print(f"imported {counts['male']} men and {counts['female']} women")
    return 0


def run_copy(args: argparse.Namespace) -> int:
    wanted: set[tuple[str, str]] = set()
    for text in args.queries:  # before opening: a bad query touches nothing
        compiled = compile_query(text)
        try:
            wanted |= accelerator.columns_named(compiled)
        except accelerator.Unsupported as exc:
            raise QueryError(
                f"the column copy cannot answer this query ({exc}); `sass query` counts it "
                "with SQLite",
                text,
            ) from None
    db = open_database(args)
    if db.dialect != "sqlite":
        raise DatabaseError(
            f"{db.name} is a PostgreSQL database: it counts with its own parallel scans "
            "and needs no column copy"
        )
    try:
        with db.connection() as conn:
            path = accelerator.database_path(conn)
            bar = progress_for(sys.stderr, "copying columns")
            done = accelerator.refresh(conn, wanted, progress=bar)
            if bar:
                bar.finish()
    finally:
        db.close()
    names = ", ".join(
        column if table == "person" else f"{table}.{column}" for table, column in done.columns
    )
    print(
        f"column copy of {printable(str(path))} {done.how}: {done.people} people, "
        f"{len(done.columns)} columns ({names}), in {printable(str(done.folder))}"
    )
    for table, column in done.refused:
        print(
            f"warning: {table}.{column} holds values of another type than declared: "
            "SQLite counts queries that name it",
            file=sys.stderr,
        )
    if done.people < accelerator.MIN_PEOPLE:
        print(
            f"note: counts use the copy from {accelerator.MIN_PEOPLE:,} people; "
            f"SQLite counts these {done.people:,} directly",
            file=sys.stderr,
        )
    return 0
