"""The theme chosen in the palette is remembered in the user's config directory."""

from __future__ import annotations

import json

import pytest
from _screen import settle

from sass_tui.ui.settings import settings_path


@pytest.mark.slow
def test_the_theme_chosen_in_the_palette_is_remembered(drive, app_at, tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    assert settings_path() == tmp_path / "sass" / "tui.json"

    async def choose_theme():
        async with app_at((100, 30)) as (app, pilot):
            assert app.theme != "nord"
            await pilot.press("ctrl+p", *"theme")
            await settle(pilot)  # the palette searches in a worker
            await pilot.press("enter")  # Change theme: the themes' own palette
            await settle(pilot)
            await pilot.press(*"nord")
            await settle(pilot)
            await pilot.press("enter")
            await settle(pilot)
            assert app.theme == "nord"

    drive(choose_theme())
    assert json.loads(settings_path().read_text())["theme"] == "nord"

    async def start_again():
        async with app_at((100, 30)) as (app, _pilot):
            assert app.theme == "nord"

    drive(start_again())


def test_a_broken_settings_file_leaves_the_default_theme(drive, app_at, tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    settings_path().parent.mkdir(parents=True)
    settings_path().write_text("{not json")

    async def scenario():
        async with app_at((100, 30)) as (app, _pilot):
            assert app.theme == "textual-dark"

    drive(scenario())
