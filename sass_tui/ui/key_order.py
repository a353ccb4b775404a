"""Keys handed on one at a time, each once the last one's work is done.

Textual gives a key to the widget that has the focus when the app reads it,
on that widget's own message queue.  A key's work often moves the focus by a
Message its widget posts up to the screen: a digit on a cell asks for the
prompt, which then takes the focus.  When the terminal delivers several keys
in one read (a fast typist, a paste of a column, a script), the app would
hand the keys after that digit to the cell or to the prompt depending on
whether the screen had handled the request yet; the two routes reach the
prompt by different queues, in an order neither keeps ("40 Enter Down 41
Enter" set a cell to 4 and the next to 441 when the machine was busy).

So the app hands on a key (or a paste) only once the screen and every widget
on it have handled all that the key before it set going (`screen_settled`):
the prompt is open, or the cursor has moved, before the next key is routed.
Work a key hands to a worker, or a command's next question asked after one,
is not waited for: the message line takes the keys typed meanwhile in order
(ui/widgets/message_line.py).
"""

from __future__ import annotations

import asyncio

from textual.app import App, ScreenStackError
from textual.dom import DOMNode

from sass_tui.ui.widgets.editor import focused_line

# A handler still at work after this long (it awaits something slow) does
# not hold the keys typed after it any longer: they go on in order.
SETTLE_LIMIT_S = 2.0
# Rounds of asking every widget to finish its queue before giving up waiting:
# each round lets the Messages the last one posted reach their handlers.
SETTLE_ROUNDS = 20


def _nodes(app: App) -> list[DOMNode]:
    try:
        screen = app.screen
    except ScreenStackError:
        return []  # no screen yet, or the app is closing
    return [screen, *screen.walk_children()]


def _at_work(app: App) -> list[DOMNode]:
    """The widgets the last key may still keep busy: the focused one and
    those it sits in, to the screen (a key and the Messages its handlers
    post travel up that line), and any with a Message queued."""
    nodes = _nodes(app)
    if not nodes:
        return []
    screen = app.screen
    line = focused_line(screen)
    return [screen, *line, *(n for n in nodes[1:] if n.message_queue_size and n not in line)]


async def screen_settled(app: App) -> None:
    """Return once the widgets on the screen shown have handled every Message
    queued for them and those that handling posted (each round asks the
    widgets `_at_work` to call back after what is queued for them now), or
    after SETTLE_LIMIT_S.  The app's own queue is not waited on: this runs
    inside the app's handling of the next key."""
    loop = asyncio.get_running_loop()
    deadline = loop.time() + SETTLE_LIMIT_S
    for _ in range(SETTLE_ROUNDS):
        remaining = 0
        all_called = asyncio.Event()

        def called_back() -> None:
            nonlocal remaining
            remaining -= 1
            if remaining == 0:
                all_called.set()

        for node in _at_work(app):
            if node.call_later(called_back):
                remaining += 1
        if remaining:
            try:
                await asyncio.wait_for(all_called.wait(), deadline - loop.time())
            except TimeoutError:
                return
        # A task the round woke (a command's coroutine given the pop-up's
        # choice, SassScreen.converse) takes its turn before the queues are read.
        await asyncio.sleep(0)
        if not any(node.message_queue_size for node in _nodes(app)):
            return
