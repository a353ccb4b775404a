"""At 80 columns the footer keeps the most used keys visible beside ctrl+p."""

from __future__ import annotations

from sass_tui.ui.query.query_screen import QueryScreen


def footer_text(app) -> str:
    """The footer as the terminal shows it: the screen's last line."""
    return app.screen._compositor.render_strips()[-1].text


async def shown_footer(pilot, wanted: str = "palette") -> str:
    """The footer once it shows `wanted`: on a loaded machine (pytest -n 12 on
    two cores) one pause can come before the footer's next paint."""
    for _ in range(200):  # a bound on turns of the event loop, not a time
        await pilot.pause()
        text = footer_text(pilot.app)
        if wanted in text:
            return text
    return footer_text(pilot.app)


def test_the_spreadsheet_footer_at_80_columns(drive, app_at):
    async def scenario():
        async with app_at((80, 24)) as (app, pilot):
            text = await shown_footer(pilot)
            for item in ("n Next", "p Prev", "f Figure", "d Query", "u Undo", "w Warn"):
                assert item in text
            for item in ("b Draw", "q Quit", "^p palette"):
                assert item in text
            await pilot.press("s")  # the strength page: Right -> Left joins them
            text = await shown_footer(pilot, "r Side")
            assert "r Side" in text and "q Quit" in text and "^p palette" in text

    drive(scenario())


def test_the_query_screen_footer_at_80_columns(drive, app_at, db):
    async def scenario():
        async with app_at((80, 24), db=True) as (app, pilot):
            await pilot.press("d")
            await app.workers.wait_for_complete()
            assert isinstance(app.screen, QueryScreen)
            text = await shown_footer(pilot)
            for item in ("d Query", "a All", "s One", "l List", "e Exit"):
                assert item in text
            for item in ("b Build", "m Make", "f Fit", "q Quit", "^p palette"):
                assert item in text

    drive(scenario())
