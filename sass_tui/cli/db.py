"""`sass db init | import-flat | import-ansur` (spec §5)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sass_tui.cli.options import SubParsers, add_db_option, open_db
from sass_tui.cli.progress import progress_for


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
    flat.add_argument("--person", required=True, metavar="F")
    flat.add_argument("--girth", required=True, metavar="F")
    flat.add_argument("--jntlmt", required=True, metavar="F")
    flat.add_argument("--cmass", required=True, metavar="F")
    flat.add_argument(
        "strength",
        nargs="*",
        metavar="STRENGTH_FILE",
        help="strgh-par, shoulder-strgh, elbow-strgh, wrist-strgh files, "
        "in that order (leave out all to skip strength)",
    )
    flat.set_defaults(func=run_import_flat)
    ansur = actions.add_parser("import-ansur", help="import the ANSUR II public CSV files")
    add_db_option(ansur)
    ansur.add_argument("files", nargs="+", metavar="FILE", help="CSV files (.csv or .csv.gz)")
    ansur.add_argument(
        "--source",
        default="ansur2",
        metavar="LABEL",
        help="label of these people's source (default ansur2, the published survey)",
    )
    ansur.set_defaults(func=run_import_ansur)


def run_init(args: argparse.Namespace) -> int:
    from sass_tui.db.default import create_default_database, people_count
    from sass_tui.db.schema import DatabaseError, connect, default_db_path

    path = Path(args.db) if getattr(args, "db", None) else default_db_path()
    if path.exists() and path.stat().st_size and not args.force:
        conn = connect(path, rebuild=True)
        try:
            held = people_count(conn) if _has_person_table(conn) else 0
        finally:
            conn.close()
        if held:
            question = (
                f"{path} holds {held} people (imports included); "
                "replace them with the default data set? [y/N] "
            )
            if not (sys.stdin.isatty() and sys.stderr.isatty()):
                raise DatabaseError(
                    f"{path} holds {held} people; `sass db init --force` replaces them "
                    "(imports included)"
                )
            sys.stderr.write(question)
            sys.stderr.flush()
            if sys.stdin.readline().strip().lower() not in ("y", "yes"):
                print("nothing changed", file=sys.stderr)
                return 1
    bar = progress_for(sys.stderr, "building")
    counts = create_default_database(path, progress=bar, replace=True)
    if bar:
        bar.finish()
    print(
        f"created {path}: {counts.get('ansur2', 0)} ANSUR II people and "
        f"{counts.get('synthetic', 0)} synthetic people"
    )
    return 0


def _has_person_table(conn) -> bool:  # sqlite3.Connection
    return bool(
        conn.execute(
            "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'person'"
        ).fetchone()
    )


def run_import_flat(args: argparse.Namespace) -> int:
    from sass_tui.db.flatfile import FlatFileError, FlatFiles, import_flat_files

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
    conn = open_db(args, create=True)
    count = import_flat_files(conn, files)
    print(f"imported {count} people")
    return 0


def run_import_ansur(args: argparse.Namespace) -> int:
    from sass_tui.db.ansur import import_ansur

    conn = open_db(args, create=True)
    bar = progress_for(sys.stderr)
    counts = import_ansur(conn, args.files, progress=bar, label=args.source)
    if bar:
        bar.finish()
    print(f"imported {counts['male']} men and {counts['female']} women")
    return 0
