"""`sass population --query QUERY -o FILE.dat`: population files (report
figure 7) made from the people a query selects: the empirical 5th/50th/95th
percentile, per gender, of every girth and center-of-mass row.  `--ids FILE`
makes them from a list of people instead (person ids one a line, or `sass
query --format csv` output; `-` reads standard input), as Make Population
does with the query screen's selected list; with --query too, from the
people of the list that the query selects.

`-o young.dat` writes the girth file to young.dat, the center-of-mass
file beside it as young-cmass.dat and the people's own stature and mass as
young-global.dat (`sass fig --girth young.dat --cmass young-cmass.dat` reads
all three)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import (
    SubParsers,
    add_db_option,
    add_virtual_option,
    file_name,
    weighting_name,
)
from sass_tui.db.populations.population import (
    IdListError,
    missing_ids,
    parse_id_list,
    people_words,
    population_of,
)
from sass_tui.db.populations.population_files import write_population_files
from sass_tui.db.query.query import parse
from sass_tui.model.errors import reason_text
from sass_tui.model.files.paths import LARGEST_ID_LIST, regular_file, size_text
from sass_tui.model.names import GROUP_TITLES


def register(commands: SubParsers) -> None:
    population = commands.add_parser(
        "population", help="make population files from the people a query selects"
    )
    add_db_option(population)
    population.add_argument(
        "--query",
        metavar="QUERY",
        help="the people this query selects (with --ids: of those people)",
    )
    population.add_argument(
        "--ids",
        type=file_name,
        metavar="FILE",
        help="person ids, one a line, or `sass query --format csv` output ('-': stdin)",
    )
    population.add_argument(
        "-o",
        "--output",
        type=file_name,
        required=True,
        metavar="FILE.dat",
        help="girth file; FILE-cmass.dat (center of mass) and FILE-global.dat (the "
        "people's stature and mass) beside it",
    )
    population.add_argument("--title", metavar="T", help="title (default: the query)")
    population.add_argument(
        "--target",
        metavar="NAME",
        help="the people of a target population (sass target), weighted percentiles "
        "(FILE-global.dat's stature and mass too)",
    )
    add_virtual_option(population)
    population.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    weighting = weighting_name(args)
    if args.query is None and args.ids is None and weighting is None:
        print(
            "sass population: error: give --query QUERY, --ids FILE or both (or --target NAME)",
            file=sys.stderr,
        )
        return 2
    # Parsed once, passed on; a bad query touches nothing.
    selection = None if args.query is None else parse(args.query)
    ids = read_id_file(args.ids) if args.ids is not None else None
    conn = open_db(args)
    try:
        absent = missing_ids(conn, ids) if ids is not None else []
        target = None
        if weighting is not None:
            # deferred: db.shipped (db.targets) — off sass population (sass_tui/startup.py)
            from sass_tui.db.populations.shipped import load_weights

            target = load_weights(conn, weighting)
        result = population_of(
            conn,
            selection,
            ids=ids,
            title=args.title,
            ids_from="the list on standard input" if args.ids == "-" else f"the list {args.ids}",
            target=target,
        )
    finally:
        conn.close()
    if absent:
        shown = ", ".join(map(str, absent[:10])) + (", ..." if len(absent) > 10 else "")
        print(
            f"{len(absent)} of the {len(ids or ())} listed ids are not in the database: {shown}",
            file=sys.stderr,
        )
    for group, path in write_population_files(result, Path(args.output)).items():
        modelled = result.modelled.get(group, 0)
        model = (
            f"; {modelled} cells the people lack from the report's, scaled by their stature "
            "or by appendix L.1's rules"
            if modelled
            else ""
        )
        print(f"wrote {path} ({GROUP_TITLES[group].lower()}{model})")
    print(f"from {people_words(result.counts)} selected by: {result.query}")
    return 0


def read_id_file(name: str) -> list[int]:
    """The person ids of file `name` (`-`: standard input), at most LARGEST_ID_LIST bytes."""
    if name == "-":  # a pipe has no size to check first: read one character past the limit
        text = sys.stdin.read(LARGEST_ID_LIST + 1)
        if len(text) > LARGEST_ID_LIST:
            raise IdListError(
                f"standard input: over {size_text(LARGEST_ID_LIST)}, too large for a list "
                "of person ids; nothing was used"
            )
        return parse_id_list(text, "standard input")
    # not a FIFO, which would block the read; a huge file is refused unread
    path = regular_file(name, largest=LARGEST_ID_LIST, kind="a list of person ids")
    try:
        text = path.read_text(encoding="utf-8-sig")  # Excel's CSV has a byte-order mark
    except UnicodeDecodeError as exc:
        raise OSError(f"{name}: not a text file of person ids ({exc.reason})") from None
    except OSError as exc:
        raise OSError(f"{name}: {reason_text(exc)}") from None
    return parse_id_list(text, name)
