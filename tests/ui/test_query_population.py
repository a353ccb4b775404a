"""Make Population on the query screen: the people of the selected
list (Select One / Select All), driven by key presses, written as population
files and loaded for the next Create Figure; a gender with too few people
refused with the count."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from _screen import message, paste, settle
from test_query_screen import choose

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.individual import fetch_individual
from sass_tui.db.populations.population_files import cmass_path
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH

SIZE = (120, 40)


async def query_young_women(pilot) -> None:
    """gender = female AND age < 25, through the pop-up menus."""
    await pilot.press("d")
    await settle(pilot)
    await pilot.press("d", "b")
    for label in ("Global Information", "Gender", "Female", "And", "Global Information"):
        await choose(pilot, label)
    await choose(pilot, "Age (years)")
    await choose(pilot, "Less Than (<)")
    await pilot.press(*"25", "enter")
    await choose(pilot, "Done")
    await settle(pilot)


def young_women(db) -> list[int]:
    with connect(db) as conn:
        return [
            r[0]
            for r in conn.execute(
                "SELECT id_num FROM person WHERE gender = 'female' AND age < 25 "
                "AND source != 'synthetic' AND substr(source, 1, 8) != 'virtual:' ORDER BY id_num"  # a query reaches real people only
            )
        ]


def medians_of(db, ids: list[int]) -> dict[str, np.ndarray]:
    """Each girth and center-of-mass cell's median over exactly these people,
    from their own values (fetch_individual), not from the population code."""
    with connect(db) as conn:
        people = [fetch_individual(conn, i) for i in ids]
    # A cell nobody measured (every center of mass: real people have none) has
    # no median: NaN, which the test reads as such; numpy warns of it each time.
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "All-NaN slice encountered", RuntimeWarning)
        return {
            group: np.nanmedian(np.stack([p.groups[group] for p in people]), axis=0)
            for group in (GIRTH, CENTER_OF_MASS)
        }


@pytest.mark.slow
def test_make_population_writes_files_of_the_medians_and_loads_them(drive, app_at, db, tmp_path):
    ids = young_women(db)
    medians = medians_of(db, ids)
    target = tmp_path / "young.dat"

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await query_young_women(pilot)
            assert f"{len(ids):,} people found" in message(app)
            await pilot.press("a")  # Select All: the selected list is what Make Population uses
            await pilot.press("m")
            await paste(pilot, str(target))
            await pilot.press("enter")
            await settle(pilot)
            said = message(app)
            assert f"{len(ids):,} women" in said
            assert "joint limits and strength keep the loaded population" in said
            figure = app.session.population
            assert figure.gender == "female"  # the population holds women only
            for group, path in ((GIRTH, target), (CENTER_OF_MASS, cmass_path(target))):
                source = figure.groups[group].source
                assert source.path == str(path)
                assert "gender = female AND age < 25" in source.title
                np.testing.assert_allclose(
                    source.stats("female"),
                    read_population_file(path, group).stats("female"),
                    atol=0.006,
                )

    drive(scenario())
    for group, path in ((GIRTH, target), (CENTER_OF_MASS, cmass_path(target))):
        data = read_population_file(path, group)
        fiftieth = data.stats("female")[:, :, 1]
        expected = medians[group]
        measured = ~np.isnan(expected)
        # real women have no center of mass: that file is the report's scaled by stature
        assert measured.any() if group == GIRTH else not measured.any()
        np.testing.assert_allclose(fiftieth[measured], expected[measured], atol=0.006)
        assert np.isfinite(data.stats("female")).all()  # every cell filled


@pytest.mark.slow
def test_make_population_refuses_a_gender_with_fewer_than_20(drive, app_at, db, tmp_path):
    with connect(db) as conn:
        (count,) = conn.execute(
            "SELECT count(*) FROM person WHERE gender = 'female' AND stature > 180 "
            "AND substr(source, 1, 8) != 'virtual:'"  # what the query reaches
        ).fetchone()
    assert 0 < count < 20
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
            await pilot.press(*"180", "enter")
            await choose(pilot, "Done")
            await settle(pilot)
            await pilot.press("a", "m")
            await paste(pilot, str(target))
            await pilot.press("enter")
            await settle(pilot)
            word = "woman" if count == 1 else "women"
            assert f"only {count} {word}" in message(app)
            assert not target.exists()

    drive(scenario())


@pytest.mark.slow
def test_make_population_uses_the_selected_list_not_the_last_query(drive, app_at, db, tmp_path):
    """25 young women picked one by one, then another query run: the population
    is those 25 women's, whose medians the test computes from the database."""
    young = young_women(db)
    chosen = young[:25]
    assert len(young) > len(chosen)
    medians = medians_of(db, chosen)
    target = tmp_path / "picked.dat"

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await query_young_women(pilot)
            await pilot.press(*["s"] * len(chosen))  # Select One, 25 times
            screen = app.screen
            assert screen.lists.selected_ids() == chosen
            screen.start_query("gender = male")  # the last query is now other people
            await settle(pilot)
            await pilot.press("m")
            assert "25 selected people" in message(app)
            await paste(pilot, str(target))
            await pilot.press("enter")
            await settle(pilot)
            said = message(app)
            assert "25 women" in said, said
            assert app.session.population.gender == "female"

    drive(scenario())
    data = read_population_file(target, GIRTH)
    assert "25 selected from (gender = female AND age < 25)" in data.title
    fiftieth = data.stats("female")[:, :, 1]
    expected = medians[GIRTH]
    measured = ~np.isnan(expected)
    assert measured.sum() > 20
    np.testing.assert_allclose(fiftieth[measured], expected[measured], atol=0.006)
    assert "male" not in data.sections


@pytest.mark.slow
def test_make_population_with_nobody_selected_says_so(drive, app_at, db, tmp_path):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await query_young_women(pilot)
            await pilot.press("m")
            assert "selected list, which is empty" in message(app)
            assert not app.screen.message_line.prompting

    drive(scenario())
