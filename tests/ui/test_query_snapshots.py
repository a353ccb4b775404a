"""Snapshots of the database query spreadsheet, each pop-up menu of the query
builder, and an individual shown in the anthropometric spreadsheet.
Update with `pytest tests/ui/test_query_snapshots.py --snapshot-update`."""

from __future__ import annotations

import pytest
from _screen import settle
from test_query_screen import SAMPLE, choose

SIZE = (100, 37)


async def open_builder(pilot):
    await pilot.press("d")
    await settle(pilot)
    await pilot.press("d", "b")


def test_query_screen_with_results(snap_compare, new_app, db):
    async def run_before(pilot):
        await pilot.press("d")
        await settle(pilot)
        pilot.app.screen.start_query(SAMPLE)
        await settle(pilot)
        await pilot.press("down", "s")

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=SIZE)


# The menus of figure 13's sequence, each reached by the choices before it.
MENU_PATHS = {
    "query_menu": [],
    "global_information": ["Global Information"],
    "gender_menu": ["Global Information", "Gender"],
    "anthropometric_group": ["Anthropometric Groups"],
    "girth_menu": ["Anthropometric Groups", "Girth"],
    "strength_menu": ["Anthropometric Groups", "Strength"],
    "axis_menu": ["Anthropometric Groups", "Girth", "Right Upper Arm"],
    "relational_operation_menu": ["Anthropometric Groups", "Girth", "Right Upper Arm", "Z Axis"],
    "constraint_prompt": [
        "Anthropometric Groups",
        "Girth",
        "Right Upper Arm",
        "Z Axis",
        "Greater Than (>)",
    ],
    "conjunction_menu": ["Global Information", "Gender", "Male"],
}


@pytest.mark.slow
@pytest.mark.parametrize("menu", sorted(MENU_PATHS))
def test_popup_menu(snap_compare, new_app, db, menu):
    async def run_before(pilot):
        await open_builder(pilot)
        for label in MENU_PATHS[menu]:
            await choose(pilot, label)

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=SIZE)


@pytest.mark.slow
def test_measurement_menu_filtered(snap_compare, new_app, db):
    async def run_before(pilot):
        await open_builder(pilot)
        await choose(pilot, "Measurements")
        await pilot.press(*"sitting")

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=SIZE)


@pytest.mark.slow
def test_individual_displayed(snap_compare, new_app, db):
    async def run_before(pilot):
        await pilot.press("d")
        await settle(pilot)
        pilot.app.screen.start_query(SAMPLE)
        await settle(pilot)
        await pilot.press("s", "e", "v")

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=SIZE)


def test_more_menu(snap_compare, new_app, db):
    async def run_before(pilot):
        await pilot.press("d")
        await settle(pilot)
        pilot.app.screen.start_query(SAMPLE)
        await settle(pilot)
        await pilot.press("a", "e", "v", "x")

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=SIZE)
