"""`sass predict`: a person's unmeasured values from the known ones, with 90 % intervals.

    sass predict --gender male --known stature=175.5cm --known mass=82.2kg -o P.fig
    sass predict --gender female --input known.csv --output predicted.csv

The model (sass_tui/model/population/prediction.py) is fitted on the database's people
and cached beside a SQLite file, or in the user's cache directory for a
PostgreSQL database (sass_tui/db/populations/predict.py).
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import sys
from typing import TYPE_CHECKING, Any, TextIO

import numpy as np

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import (
    SubParsers,
    add_db_option,
    add_virtual_option,
    file_name,
    weighting_name,
    whole_number,
)
from sass_tui.db.populations.predict import open_predictor
from sass_tui.db.populations.shipped import load_weights
from sass_tui.model.errors import SassError
from sass_tui.model.files.atomic import write_text_atomic
from sass_tui.model.files.paths import LARGEST_PEOPLE_TABLE, regular_file
from sass_tui.model.population.prediction import (
    MIN_PEOPLE,
    UnknownFieldError,
    field_unit,
    split_known,
)
from sass_tui.model.text import other_separator
from sass_tui.model.units import UnitError, parse_quantity
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.model.population.prediction import Prediction, Predictor


class PredictArgumentError(ValueError, SassError):
    """Options of `sass predict` that do not go together, or a batch file it cannot read."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


# `--virtual NAME`: the regression learns from the virtual people unweighted.
# Their predicted measures were drawn from sass's regression on the soldiers
# (db/populations/virtual.py), so weighting cannot change what it says of a measure given
# stature and mass; the survey weights would move only the stature-mass
# relation, and at the price of the sample: the shipped population's Kish
# effective size is 43 % of its people (docs/target-populations.md).
UNWEIGHTED = (
    "unweighted: each virtual person counts once, not by its survey weight "
    "(docs/target-populations.md, Predicting from virtual people)"
)


def register(commands: SubParsers) -> None:
    predict = commands.add_parser(
        "predict",
        help="predict every value of a person from the known ones (with 90 %% intervals)",
        description="Predict every girth and center-of-mass value and every ANSUR II "
        "measurement from the known ones, by regression on the database's people of the "
        "same gender, each with a 90 % prediction interval.  Known names: stature, mass, "
        "measure.<name>, girth.<segment>.<x|y|z>, center_of_mass.<segment>.<x|y|z>; values "
        "in cm and kg unless they carry a unit.",
    )
    add_db_option(predict)
    predict.add_argument(
        "--gender", choices=GENDERS, required=True, help="the person's gender: the people fitted"
    )
    predict.add_argument(
        "--known",
        metavar="NAME=VALUE",
        action="append",
        default=[],
        help="a known value, e.g. stature=175.5cm or mass='181 lb' (repeat for more)",
    )
    predict.add_argument(
        "--population",
        metavar="QUERY",
        help="learn from the people this query selects (the query language of `sass query`; "
        "those of --gender are used), e.g. \"branch = 'Combat Arms'\"; default: every "
        "real person of the gender",
    )
    add_virtual_option(predict)
    predict.add_argument(
        "--format",
        choices=("table", "json", "csv"),
        default="table",
        help="output format (default table)",
    )
    predict.add_argument(
        "-o",
        dest="figure",
        type=file_name,
        metavar="OUT.fig|OUT.x3d|OUT.glb",
        help="also write the predicted figure: a PEABODY .fig file, an HAnim .x3d humanoid "
        "or a glTF 2.0 body (.glb, or .gltf + .bin)",
    )
    predict.add_argument(
        "--nearest",
        metavar="K",
        type=whole_number,
        default=0,
        help="also list the K real people nearest to the known values (standardized distance)",
    )
    predict.add_argument(
        "--input",
        metavar="KNOWN.csv",
        type=file_name,
        help="batch: one person a row, columns named like --known (other columns pass through)",
    )
    predict.add_argument(
        "--output",
        metavar="PREDICTED.csv",
        type=file_name,
        help="batch output: the input columns and F, F.low, F.high for every predicted field F",
    )
    predict.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.input is not None:
        if args.known or args.figure or args.nearest:
            raise PredictArgumentError("--input takes neither --known, -o nor --nearest")
        if not args.output:
            raise PredictArgumentError("--input needs --output PREDICTED.csv")
    elif args.output:
        raise PredictArgumentError("--output is for a batch: give --input KNOWN.csv too")
    elif not args.known:
        raise PredictArgumentError("give at least one --known NAME=VALUE, or --input KNOWN.csv")
    if args.figure and not args.figure.lower().endswith((".fig", ".x3d", ".glb", ".gltf")):
        raise PredictArgumentError(
            f"-o {args.figure}: the file must end in .fig, .x3d, .glb or .gltf"
        )

    pairs = [pair for item in args.known for pair in split_known(item)]
    conn = open_db(args)
    try:
        if args.virtual is not None:
            # Learn from the virtual population's people (the shipped one made on first use).
            virtual = load_weights(conn, weighting_name(args) or "").target.population
            args.population = (
                virtual if args.population is None else f"({args.population}) AND {virtual}"
            )
        predictor = open_predictor(conn, population=args.population)
    finally:
        conn.close()
    if args.population is not None and args.gender not in predictor.models:
        raise PredictArgumentError(
            f"--population {args.population!r}: fewer than {MIN_PEOPLE} {args.gender} people "
            "with every value the prediction needs; widen the query",
            where=args.population,
        )
    if args.input is not None:
        rows = predict_csv(predictor, args.gender, args.input, args.output)
        print(f"wrote {args.output} ({rows} {'person' if rows == 1 else 'people'})")
        if args.virtual is not None:
            print(f"learnt from the VIRTUAL people of {args.virtual}, {UNWEIGHTED}")
        return 0
    known = predictor.parse_known(args.gender, pairs)
    prediction = predictor.predict(args.gender, known, nearest=args.nearest)
    out = sys.stdout
    if args.format == "json":
        document = prediction_json(predictor, prediction, args.population, args.virtual)
        json.dump(document, out, indent=1)
        out.write("\n")
    elif args.format == "csv":
        _write_csv(prediction, out)
    else:
        _write_table(prediction, out, args.population, args.virtual)
    if args.figure:
        # deferred: cli.prediction_figure (the figure writers) — off sass predict (sass_tui/startup.py)
        from sass_tui.cli.prediction_figure import write_prediction_figure

        path = write_prediction_figure(prediction, args.figure)
        print(f"wrote {path}", file=sys.stderr if args.format != "table" else out)
    return 0


def prediction_json(
    predictor: Predictor,
    prediction: Prediction,
    population: str | None = None,
    virtual: str | None = None,
) -> dict[str, Any]:
    """The JSON document of one prediction; `population`
    the query the model learnt from (None: the default, every real person),
    `virtual` the virtual population it learnt from (`--virtual NAME`)."""
    cv = predictor.cv_rmse(prediction.gender, prediction.known)
    return {
        "gender": prediction.gender,
        "known": dict(prediction.known),
        "predicted": {
            name: {"value": e.value, "unit": e.unit, "low": e.low, "high": e.high}
            for name, e in prediction.predicted.items()
        },
        "nearest": [
            {"id": n.id, "name": n.name, "distance": round(n.distance, 4)}
            for n in prediction.nearest
        ],
        "model": {
            "n": prediction.n,
            "population": population,
            "cv_rmse": {k: round(v, 4) for k, v in cv.items()},
            # Every person counts once, survey weights or not (UNWEIGHTED says why).
            "weighted": False,
            "virtual": virtual,
        },
    }


def _write_csv(prediction: Prediction, out: TextIO) -> None:
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["field", "value", "unit", "low", "high", "known"])
    for name, e in prediction.values.items():
        writer.writerow(
            [name, f"{e.value:.3f}", e.unit, f"{e.low:.3f}", f"{e.high:.3f}", int(e.known)]
        )


def _write_table(
    prediction: Prediction,
    out: TextIO,
    population: str | None = None,
    virtual: str | None = None,
) -> None:
    among = "" if population is None else f" of {population}"
    out.write(
        f"{prediction.gender}, {prediction.label()} "
        f"(regression on {prediction.n} people{among}; 90 % prediction intervals)\n"
    )
    if virtual is not None:
        out.write(f"learnt from the VIRTUAL people of {virtual}, {UNWEIGHTED}\n")
    width = max(len(name) for name in prediction.values)
    out.write(f"{'field':<{width}}  {'value':>8} {'unit':<4}  {'90 % interval':>17}\n")
    for name, e in prediction.values.items():
        interval = "known" if e.known else f"{e.low:.2f} - {e.high:.2f}"
        out.write(f"{name:<{width}}  {e.value:8.2f} {e.unit:<4}  {interval:>17}\n")
    if prediction.nearest:
        who = "real people" if virtual is None else f"VIRTUAL people of {virtual}"
        out.write(f"\nnearest {who} (standardized distance over the known values):\n")
        for n in prediction.nearest:
            out.write(f"{n.id:>8}  {n.name:<24} {n.distance:7.3f}\n")


def predict_csv(predictor: Predictor, gender: str, source: str, target: str) -> int:
    """Batch: predict every row of `source`, write `target`.  Returns the rows.

    Columns named like a known value are read (canonical units unless a cell
    carries one; an empty cell is unknown for that row); other columns pass
    through.  The output keeps the input columns as they were, an empty known
    cell filled with its prediction, and adds F, F.low, F.high for every
    predicted field F (F.low and F.high only, for a field that is an input column);
    an input column named like one of those is replaced by it (a file this
    wrote, run again after its values were edited)."""
    try:
        people_table = regular_file(source, largest=LARGEST_PEOPLE_TABLE, kind="a table of people")
        with open(people_table, encoding="utf-8-sig", newline="") as handle:
            reader = csv.reader(handle)
            rows = list(reader)
    except UnicodeDecodeError as exc:
        raise PredictArgumentError(f"{source}: not UTF-8 text ({exc.reason})") from None
    except csv.Error as exc:  # a field over csv's 131,072 characters, a NUL
        raise PredictArgumentError(f"{source}:{reader.line_num}: not CSV ({exc})") from None
    if not rows:
        raise PredictArgumentError(f"{source}:1: the file is empty; expected a header row")
    header, body = rows[0], rows[1:]
    wrong = other_separator(header)
    if wrong is not None:
        raise PredictArgumentError(f"{source}:1: {wrong}", where=f"{source}:1")
    fields = predictor.fields(gender)
    known_cols: list[int] = []
    known_fields: list[str] = []
    for c, name in enumerate(header):
        try:
            key = predictor.resolve(gender, name)
        except UnknownFieldError:
            continue  # a pass-through column
        if key in known_fields:
            raise PredictArgumentError(f"{source}:1: column {name!r} repeats {key}")
        known_cols.append(c)
        known_fields.append(key)
    if not known_cols:
        raise PredictArgumentError(
            f"{source}:1: no column names a known value (stature, mass, measure.<name>, "
            f"girth.<segment>.<axis>, center_of_mass.<segment>.<axis>)"
        )
    matrix = np.full((len(body), len(known_cols)), np.nan)
    for r, row in enumerate(body):
        line = r + 2
        if len(row) != len(header):
            raise PredictArgumentError(
                f"{source}:{line}: expected {len(header)} fields, found {len(row)}"
            )
        for j, c in enumerate(known_cols):
            text = row[c].strip()
            if text:
                try:
                    matrix[r, j] = parse_quantity(text, field_unit(known_fields[j]))
                except UnitError as exc:
                    raise PredictArgumentError(
                        f"{source}:{line}: column {header[c]}: {exc}", where=f"{source}:{line}"
                    ) from None
    out_fields, value, low, high = predictor.predict_matrix(
        gender, known_fields, matrix, where=[f"{source}:{r + 2}" for r in range(len(body))]
    )
    index = {f: i for i, f in enumerate(out_fields)}
    names: list[str] = []  # the added columns' names and values, in output order
    added: list[np.ndarray] = []
    for f in fields:
        i = index[f]
        if f not in known_fields:
            names.append(f)
            added.append(value[:, i])
        names += [f"{f}.low", f"{f}.high"]
        added += [low[:, i], high[:, i]]
    # A file this wrote, run again, holds the old F.low and F.high: the new
    # ones take their place rather than stand beside them under one name.
    replaced = set(names)
    kept = [c for c, name in enumerate(header) if name not in replaced]
    columns = [header[c] for c in kept] + names
    table = np.column_stack(added) if body else np.empty((0, 0))
    # one C-level format per row: 10,000 rows x 450 numbers in well under a second
    number_format = ",".join(["%.3f"] * len(added)) + "\n"
    buffer = io.StringIO()
    # Each row's own cells, then a comma and its numbers.  Python 3.13 refuses a
    # line terminator that is the delimiter, so the comma is written apart.
    writer = csv.writer(buffer, lineterminator="")
    csv.writer(buffer, lineterminator="\n").writerow(columns)
    known_index = [index[f] for f in known_fields]
    for r, row in enumerate(body):
        cells = list(row)
        for c, i in zip(known_cols, known_index):
            if not cells[c].strip():
                cells[c] = f"{value[r, i]:.3f}"
        writer.writerow([cells[c] for c in kept])
        buffer.write("," + number_format % tuple(table[r].tolist()))
    write_text_atomic(target, buffer.getvalue())
    return len(body)
