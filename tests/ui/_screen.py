"""What the UI tests read off a screen and how they wait for it (one module:
`conftest` is a name every test folder has)."""

from __future__ import annotations

from textual import events


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
