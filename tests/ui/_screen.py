"""What the UI tests read off a screen and how they wait for it (one module:
`conftest` is a name every test folder has)."""

from __future__ import annotations

from textual import events

from sass_tui.ui.query.query_screen import QueryScreen
from sass_tui.ui.widgets import MessageLine


def message(app) -> str:
    """The message line of the screen shown."""
    return str(app.screen.query_one("#message").render())


async def settle(pilot) -> None:
    """Wait for the app's workers (queries, files, families), then for the screen."""
    await pilot.app.workers.wait_for_complete()
    await pilot.pause()


async def paste(pilot, text: str) -> None:
    """A file name arrives as a paste (typing it key by key only slows the test)."""
    pilot.app.screen.query_one("#answer").post_message(events.Paste(text))
    await pilot.pause()


async def wait_until(pilot, condition, what) -> None:
    """Pause (no delay: until the app is idle) until `condition()` holds; fail
    with `what` (a text, or a callable giving one) if it never does."""
    for _ in range(500):
        if condition():
            return
        await pilot.pause()
    raise AssertionError(what() if callable(what) else what)


async def open_query_screen(pilot) -> QueryScreen:
    """From the spreadsheet: Query DB, the database opened."""
    await pilot.press("d")
    await settle(pilot)
    screen = pilot.app.screen
    assert isinstance(screen, QueryScreen)
    return screen


async def typed_query(pilot, text: str) -> None:
    """From the spreadsheet: Query DB, the builder, its query edited as
    `text`, Done; the query screen stays, its list filled."""
    app = pilot.app
    await open_query_screen(pilot)
    await pilot.press("d", "b", "e")
    app.screen.query_one(MessageLine).answer.value = ""
    await pilot.press(*text, "enter")
    labels = [str(o.prompt) for o in app.screen.query_one("#popup-options").options]
    await pilot.press(*["down"] * labels.index("Done"), "enter")
    await settle(pilot)


async def slash_query(pilot, text: str) -> None:
    """From the spreadsheet: Query DB, the query typed whole (`/`), run; the
    query screen stays, its list filled."""
    await open_query_screen(pilot)
    await pilot.press("slash")
    await paste(pilot, text)
    await pilot.press("enter")
    await settle(pilot)
