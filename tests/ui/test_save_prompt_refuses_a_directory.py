"""A save prompt given the name of a directory says at once that it cannot
write there (model/files/atomic.py `check_target`); it offered to overwrite the
directory, and refused only after the user said y."""

from __future__ import annotations

import pytest
from _screen import message, settle
from textual import events

SIZE = (120, 40)


async def answer(pilot, text: str) -> None:
    pilot.app.screen.query_one("#answer").post_message(events.Paste(text))
    await pilot.pause()
    await pilot.press("enter")


@pytest.mark.slow
def test_create_figure_and_export_refuse_a_directory_without_asking(app_at, drive, tmp_path):
    folder = tmp_path / "figures"
    folder.mkdir()

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.press("f")  # Create Figure
            assert "Figure file name" in message(app)
            await answer(pilot, str(folder))
            if "Include strength" in message(app):
                await pilot.press("enter")
            await settle(pilot)
            said = message(app)
            assert "Overwrite" not in said
            assert f"cannot write {folder}: it is a directory" in said, said
            await pilot.press("G")  # Export glTF
            await answer(pilot, str(tmp_path / "body.glb"))
            await pilot.press("enter")  # standing
            await settle(pilot)
            (tmp_path / "odd.glb").mkdir()
            await pilot.press("G")
            await answer(pilot, str(tmp_path / "odd.glb"))
            await pilot.press("enter")
            await settle(pilot)
            said = message(app)
            assert "Overwrite" not in said
            assert "it is a directory" in said, said
            # a name the file system refuses: said without Python's "[Errno 36]"
            too_long = tmp_path / ("a" * 300 + ".json")
            await pilot.press("S")  # Save worksheet as
            await answer(pilot, str(too_long))
            await settle(pilot)
            assert message(app) == f"{too_long}: File name too long", message(app)
        assert folder.is_dir() and list(folder.iterdir()) == []

    drive(scenario())
