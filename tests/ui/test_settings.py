"""The theme chosen in the palette is remembered in the user's config directory."""

from __future__ import annotations

import json

from sass_tui.ui.app import SassApp
from sass_tui.ui.settings import settings_path


def test_the_theme_chosen_in_the_palette_is_remembered(drive, tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    assert settings_path() == tmp_path / "sass" / "tui.json"

    async def choose_theme():
        app = SassApp()
        async with app.run_test(size=(100, 30)) as pilot:
            assert app.theme != "nord"
            await pilot.press("ctrl+p", *"theme")
            await pilot.pause(0.3)
            await pilot.press("enter")  # Change theme: the themes' own palette
            await pilot.pause(0.3)
            await pilot.press(*"nord")
            await pilot.pause(0.3)
            await pilot.press("enter")
            await pilot.pause(0.3)
            assert app.theme == "nord"

    drive(choose_theme())
    assert json.loads(settings_path().read_text())["theme"] == "nord"

    async def start_again():
        app = SassApp()
        async with app.run_test(size=(100, 30)):
            assert app.theme == "nord"

    drive(start_again())


def test_a_broken_settings_file_leaves_the_default_theme(drive, tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    settings_path().parent.mkdir(parents=True)
    settings_path().write_text("{not json")

    async def scenario():
        app = SassApp()
        async with app.run_test(size=(100, 30)):
            assert app.theme == "textual-dark"

    drive(scenario())
