"""The Textual private API sass uses, in one place.

Textual has no public way to ask which keys a widget or a screen binds: its
class's `BINDINGS` merged with its base classes' (`inherit_bindings`) and
any bound at run time.  sass needs the answer twice: a screen runs its own
bindings in the order keys arrive, after the focused widgets' own
(ui/base.py, ui/widgets/editor.py), and the help screen and the command palette list
every screen's bindings, shown or not (ui/palette.py).  Both read Textual's
`DOMNode._bindings` (an instance's map) and `DOMNode._merge_bindings()` (a
class's), here only; tests/ui/test_textual_api.py fails, naming what moved,
when a Textual release renames or reshapes either.

The footer (ui/footer.py) skips a rebuild that would draw the same keys; it
asks whether Textual's `Footer` has its bindings yet (`Footer._bindings_ready`,
set once the screen first publishes them), also here only.

A key held back while an answer is being handled is passed on afterwards
(ui/widgets/message_line.py) as the app passes a key on: marked forwarded
(`Message._set_forwarded`), so that the app does not route it a second time
when it bubbles up unhandled.

A key no widget took would bubble up to the app, which looks its binding up
along the focus chain (`App._check_bindings`) when the key reaches the app's
queue: by then a later key may have moved the focus (a prompt closed), and
the sheet's Down ran for a Down typed into the prompt.  The screens stop
such a key and look it up at once, the same way (`run_bindings_now`).

A key typed before an edit was refused is part of the value refused, never a
command (ui/widgets/editor.py): the widget compares the key's time stamp
with the moment of the refusal on the clock Textual stamps its Messages
with (`textual._time.get_time`, `event_clock` here).
"""

from __future__ import annotations

from textual import _time
from textual.app import App
from textual.binding import BindingsMap
from textual.dom import DOMNode
from textual.events import Event
from textual.widgets import Footer


def bindings_of(node: DOMNode) -> BindingsMap:
    """The keys `node` binds now (its class's, merged, and any bound since)."""
    bindings: BindingsMap = node._bindings
    return bindings


def class_bindings(node_class: type[DOMNode]) -> BindingsMap:
    """The keys an instance of `node_class` starts with."""
    return node_class._merge_bindings()


def footer_bindings_ready(footer: Footer) -> bool:
    """Whether Textual's footer has been given its screen's bindings (before
    that its compose draws no keys)."""
    return bool(footer._bindings_ready)


def forward_event(node: DOMNode, event: Event) -> None:
    """Give `node` a key (or paste) as the app gives the focused widget one."""
    event._set_forwarded()
    node.post_message(event)


async def run_bindings_now(app: App, key: str) -> bool:
    """Look `key` up as Textual does once it has bubbled up to the app (the
    focused widget's bindings, its containers', the screen's, the app's),
    but now; whether one ran."""
    ran: bool = await app._check_bindings(key)
    return ran


def event_clock() -> float:
    """Now, on the clock Textual stamps each Message's `time` with."""
    now: float = _time.get_time()
    return now
