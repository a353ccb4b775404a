"""`sass query` and `sass db init | import-flat | import-ansur` (spec §5).

Only argparse here at import time: sqlite3, lark and numpy are imported
inside the command functions so `sass fig` starts as fast as before.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def _add_db_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--db", metavar="PATH",
                        help="database file (default: $SASS_DB, else $XDG_DATA_HOME/sass/sass.db)")


def register(commands) -> None:
    """Add the database subcommands to `sass`'s subparsers."""
    query = commands.add_parser("query", help="query the anthropometric database")
    _add_db_option(query)
    query.add_argument("--format", choices=("table", "csv", "json"), default="table")
    query.add_argument("query", metavar="QUERY",
                       help="e.g. \"gender = male AND girth.right_upper_arm.z > 28 cm\"")
    query.set_defaults(func=cmd_query)

    db = commands.add_parser("db", help="create the database or import data into it")
    actions = db.add_subparsers(dest="db_command", metavar="ACTION", required=True)
    init = actions.add_parser("init", help="(re)create the database from the default data set")
    _add_db_option(init)
    init.set_defaults(func=cmd_init)
    flat = actions.add_parser("import-flat", help="import legacy flat files (report figure 12)")
    _add_db_option(flat)
    flat.add_argument("--person", required=True, metavar="F")
    flat.add_argument("--girth", required=True, metavar="F")
    flat.add_argument("--jntlmt", required=True, metavar="F")
    flat.add_argument("--cmass", required=True, metavar="F")
    flat.add_argument("strength", nargs="*", metavar="STRENGTH_FILE",
                      help="strgh-par, shoulder-strgh, elbow-strgh, wrist-strgh files, "
                           "in that order (leave out all to skip strength)")
    flat.set_defaults(func=cmd_import_flat)
    ansur = actions.add_parser("import-ansur", help="import the ANSUR II public CSV files")
    _add_db_option(ansur)
    ansur.add_argument("files", nargs="+", metavar="FILE")
    ansur.set_defaults(func=cmd_import_ansur)


def database_errors() -> tuple[type[Exception], ...]:
    from sass_tui.db.ansur import AnsurImportError
    from sass_tui.db.flatfile import FlatFileError
    from sass_tui.db.query import QueryError
    from sass_tui.db.schema import DatabaseError

    return AnsurImportError, FlatFileError, QueryError, DatabaseError


def _run(func, args) -> int:
    import sqlite3

    errors = database_errors()
    try:
        return func(args)
    except errors as exc:
        text = exc.pointer() if hasattr(exc, "pointer") else ""
        print(f"sass {args.command}: error: {exc}", file=sys.stderr)
        if text:
            print(text, file=sys.stderr)
        return 2
    except sqlite3.Error as exc:
        print(f"sass {args.command}: database error: {exc}", file=sys.stderr)
        return 2


def default_database():
    """Open the default database, creating it from the shipped data set on first use."""
    from sass_tui.db.schema import connect, default_db_path

    path = default_db_path()
    if not path.exists():
        create_default_database(path)
    return connect(path)


def create_default_database(path: str | Path) -> int:
    """Build a fresh database from datasets/db beside `path`, then rename it into place."""
    import os
    import tempfile

    from sass_tui.db.flatfile import FlatFiles, import_flat_files
    from sass_tui.db.schema import connect
    from sass_tui.model import datasets

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    os.unlink(tmp)
    try:
        conn = connect(tmp, create=True)
        try:
            count = import_flat_files(conn, FlatFiles.in_directory(datasets.directory() / "db"))
        finally:
            conn.close()
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return count


def _open(args, create: bool = False):
    from sass_tui.db.schema import connect

    if args.db:
        return connect(args.db, create=create)
    return default_database()


def cmd_query(args) -> int:
    return _run(_query, args)


def _query(args) -> int:
    import csv
    import json

    from sass_tui.db.query import PERSON_FIELDS, compile_query, Query

    compiled = compile_query(args.query)  # before opening: a bad query touches nothing
    conn = _open(args)
    query = Query(conn, compiled)
    count = query.count()
    people = ({k: row[k] for k in PERSON_FIELDS} for row in query.iter_all())
    out = sys.stdout
    if args.format == "json":
        json.dump({"count": count, "persons": list(people)}, out, indent=1)
        out.write("\n")
    elif args.format == "csv":
        writer = csv.DictWriter(out, fieldnames=PERSON_FIELDS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(people)
    else:
        out.write(f"{'id':>7}  {'name':<20} {'gender':<6} {'mass kg':>7} {'stature cm':>10} "
                  f"{'hand':<6} {'age':>4}  source\n")
        for p in people:
            out.write(f"{p['id']:>7}  {p['name']:<20.20} {p['gender']:<6} {_num(p['mass']):>7} "
                      f"{_num(p['stature']):>10} {p['handedness'] or '':<6} {_num(p['age'], 0):>4}  "
                      f"{p['source']}\n")
        out.write(f"{count} {'person' if count == 1 else 'people'}\n")
    return 0


def _num(value, digits: int = 1) -> str:
    return "" if value is None else f"{value:.{digits}f}"


def cmd_init(args) -> int:
    def init(args) -> int:
        from sass_tui.db.schema import default_db_path

        path = Path(args.db) if args.db else default_db_path()
        count = create_default_database(path)
        print(f"created {path} with {count} people from the default (synthetic) data set")
        return 0

    return _run(init, args)


def cmd_import_flat(args) -> int:
    def run(args) -> int:
        from sass_tui.db.flatfile import FlatFileError, FlatFiles, import_flat_files

        strength = dict(zip(("strength_par", "shoulder", "elbow", "wrist"), args.strength))
        if len(args.strength) > 4:
            raise FlatFileError("at most four strength files: strgh-par, shoulder, elbow, wrist")
        files = FlatFiles(person=Path(args.person), girth=Path(args.girth),
                          joint_limits=Path(args.jntlmt), center_of_mass=Path(args.cmass),
                          **{k: Path(v) for k, v in strength.items()})
        conn = _open(args, create=True)
        count = import_flat_files(conn, files)
        print(f"imported {count} people")
        return 0

    return _run(run, args)


def cmd_import_ansur(args) -> int:
    def run(args) -> int:
        from sass_tui.db.ansur import import_ansur

        conn = _open(args, create=True)
        bar = _ProgressBar(sys.stderr) if sys.stderr.isatty() else None
        counts = import_ansur(conn, args.files, progress=bar)
        if bar:
            bar.finish()
        print(f"imported {counts['male']} men and {counts['female']} women")
        return 0

    return _run(run, args)


class _ProgressBar:
    def __init__(self, stream, width: int = 40):
        self.stream = stream
        self.width = width

    def __call__(self, done: int, total: int) -> None:
        filled = int(self.width * done / max(total, 1))
        self.stream.write(f"\rimporting [{'#' * filled}{'.' * (self.width - filled)}] {done}/{total}")
        self.stream.flush()

    def finish(self) -> None:
        self.stream.write("\n")
        self.stream.flush()
