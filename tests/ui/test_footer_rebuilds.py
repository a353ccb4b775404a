"""The footer (sass_tui/ui/footer.py) rebuilds its keys only when the keys it
shows change: the strength page's keys (r Side) replace the sheet's, and
choosing the strength page again (its screen asks the footer to refresh,
`refresh_bindings`) keeps the same key widgets."""

from __future__ import annotations

from _screen import wait_until
from textual.widgets._footer import FooterKey

from sass_tui.ui.footer import Footer


def footer_keys(app) -> list[FooterKey]:
    return list(app.screen.query_one(Footer).query(FooterKey))


def test_the_footer_is_rebuilt_only_when_its_keys_change(drive, app_at):
    async def scenario():
        async with app_at((100, 37)) as (app, pilot):
            await wait_until(pilot, lambda: footer_keys(app), "the footer never showed its keys")
            sheet_keys = footer_keys(app)
            await pilot.press("s")  # the strength page: Right -> Left is offered
            await wait_until(
                pilot,
                lambda: any(key.action == "switch_side" for key in footer_keys(app)),
                lambda: f"no r Side in {[key.key for key in footer_keys(app)]}",
            )
            strength_keys = footer_keys(app)
            assert not set(strength_keys) & set(sheet_keys)
            await pilot.press("s")  # the same page again: the same keys
            for _ in range(5):  # a rebuild is scheduled after the next refresh
                await pilot.pause()
            assert footer_keys(app) == strength_keys  # the same widgets: not rebuilt

    drive(scenario())
