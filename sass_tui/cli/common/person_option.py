"""The real person `--person` names (an id or a name, e.g. 'ANSUR II M 10037'),
read from the database: their record, or their figure measured against a
population figure.  The verbs that take `--person` (`sass fig`, `sass export`,
`sass strength`, `sass task`) import this module only when it is given: it
brings the db package and numpy (db/people/individual.py), which their start-up paths
keep out (sass_tui/startup.py)."""

from __future__ import annotations

import argparse

from sass_tui.cli.common.database_access import open_db
from sass_tui.db.people.individual import fetch_individual, find_person, person_record
from sass_tui.db.people.individual import person_figure as figure_of
from sass_tui.db.populations.population import population_of
from sass_tui.db.populations.shipped import load_weights
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.popfile import PopulationData
from sass_tui.model.text import printable


def person_figure(args: argparse.Namespace, population: Figure) -> Figure:
    """The person `--person` names, measured against the population figure."""
    conn = open_db(args)
    try:
        person = fetch_individual(conn, find_person(conn, args.person))
    finally:
        conn.close()
    figure = figure_of(person, population)
    figure.set_figure_type(population.figure_type)
    return figure


def weighted_groups(args: argparse.Namespace, weighting: str) -> dict[str, PopulationData]:
    """The population files `sass population --target NAME` (or `--virtual`)
    would write, in memory: girth, center of mass and the people's own
    stature and mass, their weighted 5th, 50th and 95th percentiles."""
    conn = open_db(args)
    try:
        return dict(population_of(conn, target=load_weights(conn, weighting)).groups)
    finally:
        conn.close()


def named_person_record(args: argparse.Namespace) -> dict[str, object]:
    """The database record (gender, age, mass, stature, ...) of the person `--person` names."""
    conn = open_db(args)
    try:
        record = person_record(conn, find_person(conn, args.person))
    finally:
        conn.close()
    # A stored name may hold ESC and BEL (a shared database, an older file).
    return {**record, "name": printable(record["name"])}
