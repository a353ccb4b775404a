"""Bursts of keys: ten values typed down a column in one write (a paste of a
column, a fast typist, a script) all land, in order, and undo takes them
back one at a time.  The terminal's driver posts every key of one read
before the app has handled the first."""

from __future__ import annotations

import asyncio
import random
import shutil

import pytest
from _screen import settle, wait_until
from _tmux import sass_in_tmux
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from textual import events

from sass_tui.model.body.figure import Figure
from sass_tui.model.names import GIRTH
from sass_tui.ui.widgets import DataSheet, GlobalPanel

LARGE = (120, 40)
VALUES = [f"{40 + row}" for row in range(10)]
# The first ten rows of Girth, as the sheet labels them.
ROWS = [row.label for row in Figure.default().groups[GIRTH].rows[: len(VALUES)]]


def column_keys(values: list[str]) -> list[tuple[str, str | None]]:
    """`4 0 Enter Down 4 1 Enter Down ...`: each value typed into the cell,
    then the cursor to the next row."""
    keys: list[tuple[str, str | None]] = []
    for value in values:
        keys += [(c, c) for c in value] + [("enter", "\r"), ("down", None)]
    return keys


def column_values(app, rows: int) -> list[float]:
    return [float(app.figure.groups[GIRTH].values[row, 0]) for row in range(rows)]


async def undo_one_by_one(app, pilot, before: list[float], edited: list[float]) -> None:
    for undone in range(len(edited), 0, -1):
        await pilot.press("u")
        await pilot.pause()
        expected = edited[: undone - 1] + before[undone - 1 :]
        assert column_values(app, len(edited)) == expected, undone


async def column_typed(app, pilot) -> list[float]:
    """Wait until VALUES fill the column, the cursor below them and no
    prompt open; the values."""
    edited = [float(v) for v in VALUES]
    await wait_until(
        pilot,
        lambda: (
            column_values(app, len(VALUES)) == edited
            and app.query_one(DataSheet).chosen() == (len(VALUES), 0)
        ),
        lambda: f"the column is {column_values(app, len(VALUES))}",
    )
    await settle(pilot)
    assert not app.message_line.prompting
    return edited


def test_ten_values_down_a_column_in_one_burst(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            before = column_values(app, len(VALUES))
            # One read of the terminal: every key posted before the first is handled.
            for key, character in column_keys(VALUES):
                app.post_message(events.Key(key, character))
            edited = await column_typed(app, pilot)
            await undo_one_by_one(app, pilot, before, edited)

    drive(scenario())


@pytest.mark.parametrize("seed", range(6))
def test_keys_read_while_the_app_is_at_work_land_in_order(drive, app_at, seed):
    """The driver posts the keys of a read while the app handles the first
    ones: after each key, the app runs for a while (`seed` picks how long),
    so that the prompt opens, or the cursor moves, at any point of the
    burst.  The keys after a digit must not reach the prompt ahead of it."""

    async def scenario():
        turns = random.Random(seed)
        async with app_at(LARGE) as (app, pilot):
            for key, character in column_keys(VALUES):
                app.post_message(events.Key(key, character))
                for _ in range(turns.choice([0, 0, 1, 2, 3, 5, 8, 13])):
                    await asyncio.sleep(0)  # the app's turn, not a delay
            await column_typed(app, pilot)

    drive(scenario())


# Keys that act on the Girth sheet and its prompt without opening a screen or
# starting a worker: the parts of a value, the arrows, Enter, Escape,
# Backspace, undo and the unit switch.
SHEET_KEYS = [(c, c) for c in "0123456789.- "] + [
    ("enter", "\r"),
    ("down", None),
    ("up", None),
    ("left", None),
    ("right", None),
    ("escape", None),
    ("backspace", None),
    ("u", "u"),
    ("c", "c"),
]


def sheet_state(app) -> tuple:
    """The column's values, the cursor, and the prompt with its answer."""
    line = app.message_line
    return (
        app.figure.groups[GIRTH].values.round(4).tolist(),
        app.query_one(DataSheet).chosen(),
        line.prompting,
        line.answer.value if line.prompting else None,
    )


@settings(max_examples=8, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(keys=st.lists(st.sampled_from(SHEET_KEYS), min_size=1, max_size=16), seed=st.integers(0, 99))
@example(keys=[(".", "."), ("down", None), ("enter", "\r"), (" ", " "), ("down", None)], seed=0)
def test_a_burst_does_what_the_same_keys_typed_one_by_one_do(drive, app_at, keys, seed):
    """The same keys, posted in one read while the app is at work, and typed
    one at a time with the app idle in between: the same sheet, cursor and
    prompt.  (A Down typed into a prompt ran the sheet's Down once the
    prompt had closed: the app looked the key up after the next one.)"""

    async def typed(in_one_read: bool) -> tuple:
        turns = random.Random(seed)
        async with app_at(LARGE) as (app, pilot):
            for key, character in keys:
                app.post_message(events.Key(key, character))
                if in_one_read:
                    for _ in range(turns.choice([0, 0, 1, 3, 8])):
                        await asyncio.sleep(0)  # the app's turn, not a delay
                else:
                    await settle(pilot)
            await settle(pilot)
            await settle(pilot)
            return sheet_state(app)

    assert drive(typed(in_one_read=True)) == drive(typed(in_one_read=False))


def test_keys_after_an_escape_in_one_burst_are_the_sheets(drive, app_at):
    """`Enter 9 Escape Down 3 Enter`: the edit cancelled, the row below set."""

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            before = column_values(app, 2)
            burst = [("enter", "\r"), ("9", "9"), ("escape", None), ("down", None)]
            for key, character in [*burst, ("3", "3"), ("enter", "\r")]:
                app.post_message(events.Key(key, character))
            await wait_until(
                pilot,
                lambda: column_values(app, 2) == [before[0], 3.0],
                lambda: f"the column is {column_values(app, 2)}",
            )

    drive(scenario())


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("tmux") is None, reason="tmux is not installed")
def test_ten_values_down_a_column_in_one_tmux_write(tmp_path):
    """`send-keys 40 Enter Down 41 Enter Down ...`: one write to the terminal."""
    with sass_in_tmux(tmp_path) as pane:
        pane.wait_for(lambda text: "Bottom Head" in text and "q Quit" in text, "no first screen")
        keys: list[str] = []
        for value in VALUES:
            keys += [*value, "Enter", "Down"]
        pane.send(*keys)

        def landed(text: str) -> bool:
            rows = [line.split() for line in text.splitlines()]
            return all(
                [*label.split(), f"{value}.00"] in (row[: len(label.split()) + 1] for row in rows)
                for label, value in zip(ROWS, VALUES, strict=True)
            )

        pane.wait_for(landed, "not every value landed")
        pane.send("u")
        pane.wait_for(lambda text: "Undone:" in text and "49.00" not in text, "u undid nothing")


def test_a_word_typed_on_a_word_cell_is_its_value_not_commands(drive, app_at):
    """`female` on Gender: the f does not ask for a figure file."""

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            panel = app.query_one(GlobalPanel)
            panel.select("gender")
            panel.focus()
            await pilot.pause()
            for character in "female":
                app.post_message(events.Key(character, character))
            app.post_message(events.Key("enter", "\r"))
            await wait_until(pilot, lambda: app.figure.gender == "female", "still male")
            assert not app.message_line.prompting

    drive(scenario())
