"""A pop-up screen (a menu, a picker, the help, the message log) whose keys
act in the order they were typed.

Textual runs a key's binding (an OptionList's Enter, a list's arrows) once
the key has bubbled up to the app, on the app's own queue.  The app hands on
the keys of one read one at a time, each once the screen shown has handled
the one before (ui/key_order.py); a binding left to the app would run after
that, so the next key of the read would reach the pop-up before the choice
the last one made (three Enters on the More Menu's Next: the pop-up took all
three).  A pop-up therefore looks the key up as it reaches it, as the app would once
it bubbled up (its focused widget's bindings, its containers', its own), as
every SassScreen runs them at once (ui/base.py).
"""

from __future__ import annotations

from typing import TypeVar

from textual import events
from textual.screen import ModalScreen

from sass_tui.ui.textual_api import run_bindings_now

ResultType = TypeVar("ResultType")


class PopUpScreen(ModalScreen[ResultType]):
    async def on_key(self, event: events.Key) -> None:
        event.stop()
        event.prevent_default()
        # Textual's own look-up stops at a pop-up (the modal binding chain):
        # the focused widget, its containers, the pop-up.
        await run_bindings_now(self.app, event.key)
