"""Make Population makes the population's body: the tall women's own stature
and mass become the spreadsheet's Stature and Mass (their medians, computed
here from the published CSV), and the message says whose they are."""

from __future__ import annotations

import csv
import statistics

import pytest
from _screen import message, paste, settle
from test_query_screen import choose

from sass_tui.cli import main
from sass_tui.db.populations.population_files import global_path
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import GLOBAL, row_index
from sass_tui.ui.widgets import GlobalPanel

SIZE = (120, 40)


@pytest.mark.slow
def test_make_population_sizes_the_figure_by_the_peoples_stature_and_mass(
    drive, app_at, db, tmp_path, ansur_dir
):
    with (ansur_dir / "ANSUR_II_FEMALE_Public.csv").open(encoding="utf-8-sig") as handle:
        tall = [r for r in csv.DictReader(handle) if int(r["stature"]) > 1750]
    stature = statistics.median(int(r["stature"]) / 10 for r in tall)  # mm -> cm
    mass = statistics.median(int(r["weightkg"]) / 10 for r in tall)  # 0.1 kg -> kg
    target = tmp_path / "tall.dat"

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            await pilot.press("d", "b")
            for label in ("Global Information", "Gender", "Female", "And", "Global Information"):
                await choose(pilot, label)
            await choose(pilot, "Stature (cm)")
            await choose(pilot, "Greater Than (>)")
            await pilot.press(*"175", "enter")
            await choose(pilot, "Done")
            await settle(pilot)
            await pilot.press("a", "m")
            await paste(pilot, str(target))
            await pilot.press("enter")
            await settle(pilot)
            said = message(app)
            assert f"Population of {len(tall)} women written" in said
            assert f"Stature {stature:.1f} cm and Mass {mass:.1f} kg are theirs" in said
            figure = app.session.population
            assert figure.stature == pytest.approx(stature, abs=0.005)
            assert figure.mass == pytest.approx(mass, abs=0.005)
            assert figure.global_stats.path == str(global_path(target))
            await pilot.press("e")  # Exit Query: back to the spreadsheet
            await settle(pilot)
            panel = str(app.screen.query_one(GlobalPanel).render())
            assert f"{stature:.1f} cm" in panel and f"{mass:.1f} kg" in panel

    drive(scenario())


def test_input_data_of_a_population_girth_file_loads_its_stature_and_mass(
    drive, app_at, db, tmp_path, capsys
):
    target = tmp_path / "tall.dat"
    query = "gender = female AND stature > 175 cm"
    assert main(["population", "--db", str(db), "--query", query, "-o", str(target)]) == 0
    capsys.readouterr()
    own = read_population_file(global_path(target), GLOBAL).stats("female")[:, 0, 1]

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.press("tab", "down", "enter", *"female", "enter")
            assert app.figure.gender == "female"
            before = app.figure.stature, app.figure.mass
            await pilot.press("g", "i")
            await paste(pilot, str(target))
            await pilot.press("enter")
            await settle(pilot)
            stature, mass = own[row_index(GLOBAL, "stature")], own[row_index(GLOBAL, "mass")]
            assert (app.figure.stature, app.figure.mass) == (stature, mass)
            said = message(app)
            assert f"Stature {stature:.1f} cm and Mass {mass:.1f} kg are the people's own" in said
            assert "tall-global.dat" in said
            app.screen.query_one(GlobalPanel).focus()  # the global data, at Gender still
            await pilot.pause()
            await pilot.press("down", "enter")  # Mass: whose its percentiles are
            assert "Mass (kg, or e.g. 180 lb; of Population of gender = female" in message(app)
            await pilot.press("escape")
            await pilot.press("u")  # one edit: the girth and its stature and mass
            await settle(pilot)
            assert (app.figure.stature, app.figure.mass) == before
            assert "stature > 175 cm" not in app.figure.population

    drive(scenario())
