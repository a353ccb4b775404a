"""The TUI on a read-only and on a full file system: it opens and
lists, Input DB and Create Figure say what the file system refused and name
the file, nothing is half-written (tests/_tmpfs.py mounts a real tmpfs;
skipped where this process may not mount)."""

from __future__ import annotations

import hashlib
from pathlib import Path

import pytest
from _screen import message, settle
from _tmpfs import fill, remount_read_only
from textual import events

from sass_tui.ui.query.query_screen import ListSheet, QueryScreen

SIZE = (120, 40)


@pytest.fixture()
def one_person(tmp_path) -> list[Path]:
    """Person, girth, joint-limit and center-of-mass files of one new person."""
    person = tmp_path / "person.db"
    person.write_text("99901,NEW_PERSON,female,160.0,55.0,left,30,test\n")
    empty = []
    for name in ("girth", "jntlmt", "cmass"):
        path = tmp_path / f"{name}.db"
        path.write_text("")
        empty.append(path)
    return [person, *empty]


async def answer(pilot, text: str) -> None:
    pilot.app.screen.query_one("#answer").post_message(events.Paste(text))
    await pilot.pause()
    await pilot.press("enter")


async def input_db(pilot, files: list[Path]) -> None:
    await pilot.press("i")
    for path in files:
        await answer(pilot, str(path))
    await pilot.press("escape")  # no strength files
    await settle(pilot)


@pytest.mark.slow
def test_on_a_read_only_file_system_the_tui_opens_lists_and_refuses_input_db(
    drive, app_at, tmpfs_with_db, one_person
):
    mnt, db = tmpfs_with_db
    remount_read_only(mnt)
    digest = hashlib.sha256(db.read_bytes()).hexdigest()

    async def scenario():
        async with app_at(SIZE, db=db) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            screen = app.screen
            assert isinstance(screen, QueryScreen)
            # The small database holds the 200 shipped synthetic people only.
            screen.start_query("gender = female AND source = synthetic")
            await settle(pilot)
            names = [row["name"] for row in screen.query_one(ListSheet).rows]
            assert names and all(name.startswith("SYNTH_F_") for name in names)
            await input_db(pilot, one_person)
            text = message(app)
            assert text.startswith("Input DB failed, the database is unchanged: ")
            assert f"cannot write {db}" in text and "read-only file system" in text
            # the list still pages
            await pilot.press("n")
            await settle(pilot)
            assert screen.query_one(ListSheet).rows

    drive(scenario())
    assert hashlib.sha256(db.read_bytes()).hexdigest() == digest
    assert sorted(p.name for p in mnt.iterdir()) == ["sass.db"]


@pytest.mark.slow
def test_on_a_full_file_system_input_db_and_create_figure_name_the_file(
    drive, app_at, tmpfs_with_db, one_person
):
    mnt, db = tmpfs_with_db
    fill(mnt)
    digest = hashlib.sha256(db.read_bytes()).hexdigest()
    before = sorted(p.name for p in mnt.iterdir())

    async def scenario():
        async with app_at(SIZE, db=db) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            await input_db(pilot, one_person)
            text = message(app)
            assert text.startswith("Input DB failed, the database is unchanged: ")
            assert f"cannot write {db}: the disk is full" in text

    async def create_figure():
        async with app_at(SIZE, db=db) as (app, pilot):
            await pilot.press("f")
            await answer(pilot, str(mnt / "x.fig"))
            await pilot.press("enter")  # include strength: yes
            await settle(pilot)
            assert f"{mnt / 'x.fig'}: cannot write: No space left on device" in message(app)

    drive(scenario())
    drive(create_figure())
    assert hashlib.sha256(db.read_bytes()).hexdigest() == digest
    assert sorted(p.name for p in mnt.iterdir()) == before


@pytest.mark.slow
def test_the_query_screen_finishes_a_default_database_build_cut_short(
    drive, app_at, tmp_path, monkeypatch, few_default_people
):
    """What a disk that filled during the first build leaves: the schema and
    nobody in it.  The Query screen built the default database only when the
    file was missing, and listed nobody for good."""
    from sass_tui.db.engine.schema import connect

    path = tmp_path / "sass.db"
    connect(path, create=True).close()  # the schema, no people
    monkeypatch.setenv("SASS_DB", str(path))

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            screen = app.screen
            assert isinstance(screen, QueryScreen)
            screen.start_query("gender = male AND source = ansur2")
            await settle(pilot)
            names = [row["name"] for row in screen.query_one(ListSheet).rows]
            assert names and names[0].startswith("ANSUR II M ")

    drive(scenario())
