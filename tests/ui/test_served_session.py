"""A session `sass serve` starts for a browser tab: the app its process makes
from the environment the server gives it (ui/app.py's make_app,
model/served.py).  Its file prompts stay inside the served working directory;
with --read-only, Input DB is off and the database file is never changed."""

from __future__ import annotations

import hashlib
import os

import pytest
from test_query_screen import message, open_query_screen, settle
from textual import events

from sass_tui.model.served import READ_ONLY_ENV, WORKDIR_ENV
from sass_tui.ui.app import make_app

SIZE = (120, 40)


@pytest.fixture
def served(tmp_path, monkeypatch):
    """The environment `sass serve` gives a session: its working directory,
    and beside it a directory it must not reach, linked from inside."""
    work = tmp_path / "work"
    outside = tmp_path / "outside"
    work.mkdir()
    outside.mkdir()
    (work / "out").symlink_to(outside)
    monkeypatch.setenv(WORKDIR_ENV, str(work))
    monkeypatch.delenv(READ_ONLY_ENV, raising=False)
    monkeypatch.chdir(tmp_path)  # a relative name must not land here either
    return work, outside


async def answer(pilot, text: str) -> None:
    pilot.app.screen.query_one("#answer").post_message(events.Paste(text))
    await pilot.pause()
    await pilot.press("enter")
    await settle(pilot)


def files_under(path) -> list[str]:
    return sorted(
        os.path.relpath(os.path.join(d, f), path) for d, _, fs in os.walk(path) for f in fs
    )


@pytest.mark.parametrize(
    "key, prompt, suffix",
    [
        ("f", "Figure file name", "fig"),
        ("e", "HAnim file name", "x3d"),
        ("G", "glTF file name", "glb"),
    ],
    ids=["fig", "hanim", "gltf"],
)
def test_exports_stay_inside_the_served_directory(drive, served, tmp_path, key, prompt, suffix):
    work, outside = served
    refusals = {
        f"../x.{suffix}": "'..' is refused",
        str(tmp_path / f"x.{suffix}"): "not an absolute or ~ path",
        f"~/x.{suffix}": "not an absolute or ~ path",
        f"out/x.{suffix}": "a symbolic link leads out of",
    }

    async def scenario():
        app = make_app()
        assert app.workdir == work
        async with app.run_test(size=SIZE) as pilot:
            for name, why in refusals.items():
                await pilot.press(key)
                assert prompt in message(app)
                await answer(pilot, name)
                assert why in message(app), (name, message(app))
            # A plain name is written, inside the directory (not the current one).
            await pilot.press(key)
            await answer(pilot, f"mine.{suffix}")
            if key in "fG":  # Create Figure asks about strength next, Export glTF the pose
                await pilot.press("enter")
                await settle(pilot)
            assert str(work / f"mine.{suffix}") in message(app)

    drive(scenario())
    assert files_under(work) == [f"mine.{suffix}"]
    assert files_under(outside) == []
    assert files_under(tmp_path) == [f"work/mine.{suffix}"]


def test_input_data_reads_only_inside_the_served_directory(drive, served, tmp_path):
    work, outside = served
    population = "T MALE\n"  # refused before it is read, whatever it holds
    (tmp_path / "x.dat").write_text(population)
    (outside / "x.dat").write_text(population)

    async def scenario():
        app = make_app()
        async with app.run_test(size=SIZE) as pilot:
            for name, why in (
                ("../x.dat", "'..' is refused"),
                (str(tmp_path / "x.dat"), "not an absolute or ~ path"),
                ("out/x.dat", "a symbolic link leads out of"),
            ):
                await pilot.press("i")
                assert "population file" in message(app)
                await answer(pilot, name)
                assert why in message(app), (name, message(app))

    drive(scenario())


def test_read_only_refuses_input_db_and_leaves_the_database_as_it_was(
    drive, served, db, monkeypatch
):
    monkeypatch.setenv(READ_ONLY_ENV, "1")
    before = hashlib.sha256(db.read_bytes()).hexdigest()

    async def scenario():
        app = make_app(db)
        assert app.read_only
        async with app.run_test(size=SIZE) as pilot:
            await open_query_screen(pilot)
            assert "open" in message(app)  # opened read-only: the lists still work
            await pilot.press("i")
            await settle(pilot)
            assert message(app) == (
                "Input DB is off: this database is served read-only (sass serve)."
            )

    drive(scenario())
    assert hashlib.sha256(db.read_bytes()).hexdigest() == before
