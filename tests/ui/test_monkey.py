"""Random key presses over every screen must never crash the app (a traceback
in the TUI is a bug).  Fixed seeds: a failure here replays exactly."""

from __future__ import annotations

import random

import numpy as np
import pytest

from sass_tui.model.names import GROUPS

KEYS = [
    *"njmgspciuwdvxeorbal",
    "enter",
    "escape",
    "up",
    "down",
    "left",
    "right",
    "pageup",
    "pagedown",
    "tab",
    "1",
    "2",
    ".",
    "5",
    "0",
    "9",
    "-",
    "space",
    "y",
]


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1988, 2026])
def test_random_keys_never_crash(drive, app_at, db, tmp_path, monkeypatch, seed):
    monkeypatch.chdir(tmp_path)  # figures and exports typed at random land here
    rnd = random.Random(seed)

    async def scenario():
        async with app_at((100, 37), db=True) as (app, pilot):
            for _ in range(150):
                await pilot.press(rnd.choice(KEYS))
                if rnd.random() < 0.05:
                    await app.workers.wait_for_complete()
            await app.workers.wait_for_complete()
            await pilot.pause()
            for group in GROUPS:  # the model is still whole
                state = app.figure.groups[group]
                stats = state.source.stats(app.figure.gender)
                has_value = ~np.isnan(stats[..., 1])
                assert np.isfinite(state.values[has_value]).all()

    drive(scenario())
