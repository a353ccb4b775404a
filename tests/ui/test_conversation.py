"""A command of several questions is one coroutine (SassScreen.converse,
MessageLine.answer_to): the keys typed are its answers, wherever they land
before the next question shows; Escape and a refused answer end it on the
message line; a bug in it is not swallowed."""

from __future__ import annotations

import asyncio

import pytest
from _screen import message, wait_until
from test_query_screen import open_query_screen
from textual.widgets import Input

from sass_tui.model.files.fig_reader import read_fig
from sass_tui.ui.widgets import DataSheet, MessageLine
from sass_tui.ui.widgets.message_line import CANCELLED

SIZE = (100, 34)


async def until(pilot, condition) -> None:
    await wait_until(pilot, condition, lambda: f"never held; the line says {message(pilot.app)!r}")


def test_create_figure_answered_key_by_key_writes_the_figure(app_at, drive, tmp_path, monkeypatch):
    # f (Create Figure), the name, Enter, n (no strength), Enter: no letter
    # of the name runs a command (b: See figure, u: Undo), and the file is a
    # figure without strength.
    monkeypatch.chdir(tmp_path)

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.pause()
            assert app.session.strength_sheet is not None  # so the strength question comes
            await pilot.press("f", *"bu.fig", "enter", "n", "enter")
            await until(pilot, lambda: message(app).startswith("Wrote"))
            assert app.screen is app.spreadsheet
            assert not app.spreadsheet.message_line.prompting
            assert isinstance(app.focused, DataSheet)

    drive(scenario())
    assert read_fig(tmp_path / "bu.fig").archive == "skinny.a"
    assert "strength variables" not in (tmp_path / "bu.fig").read_text()


def test_escape_and_a_refused_answer_end_the_questions(app_at, drive, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.pause()
            await pilot.press("f")
            await until(pilot, lambda: "Figure file name" in message(app))
            await pilot.press("escape")
            await until(pilot, lambda: message(app) == CANCELLED)
            assert not app.spreadsheet.message_line.prompting
            await pilot.press("f", *"x.fig", "enter", *"maybe", "enter")
            await until(pilot, lambda: "expected y, n or example" in message(app))
            assert message(app) == "expected y, n or example, got 'maybe'; nothing written"
            assert not app.spreadsheet.message_line.prompting
            assert isinstance(app.focused, DataSheet)

    drive(scenario())
    assert not (tmp_path / "x.fig").exists()


def test_answers_given_before_the_next_question_are_its_own(app_at, drive):
    # Two Enters handled before the coroutine asks its second question: the
    # second answer waits for it, in order.
    answers = []

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.pause()
            screen = app.spreadsheet

            async def two_questions():
                answers.append(await screen.answer_to("First:"))
                answers.append(await screen.answer_to("Second:"))

            screen.converse(two_questions())
            await until(pilot, lambda: "First:" in message(app))
            answer = screen.query_one(MessageLine).answer
            answer.post_message(Input.Submitted(answer, "one"))
            answer.post_message(Input.Submitted(answer, "two"))
            await until(pilot, lambda: len(answers) == 2)
            await until(pilot, lambda: not screen.message_line.prompting)

    drive(scenario())
    assert answers == ["one", "two"]


def test_a_bug_in_the_questions_is_raised_not_swallowed(app_at, drive):
    class Bug(Exception):
        pass

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.pause()

            async def broken():
                await app.spreadsheet.answer_to("Anything:")
                raise Bug("a bug, not a user's error")

            app.spreadsheet.converse(broken())
            await until(pilot, lambda: "Anything:" in message(app))
            await pilot.press("enter")
            await pilot.pause()
            await pilot.pause()

    with pytest.raises(Bug):
        drive(scenario())


def test_keys_before_the_first_question_are_its_answer(app_at, drive):
    # Keys typed after the command's key but before its first question shows
    # (its coroutine has not asked yet) are the answer's, not the screen's
    # commands: on the query screen x is Delete One and s Select One.
    answers = []

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            asked = asyncio.Event()

            async def late_question():
                await asked.wait()
                answers.append(await screen.answer_to("Q:"))

            screen.converse(late_question())
            await pilot.press("x", "s")
            assert not screen.message_line.answer.display  # not asked yet
            asked.set()
            await until(pilot, lambda: "Q:" in message(app))
            await pilot.press("enter")
            await until(pilot, lambda: answers)

    drive(scenario())
    assert answers == ["xs"]
