"""The key footer every sass screen shows: Textual's `Footer`, rebuilt only
when what it shows has changed.

Textual's footer removes and mounts all its keys again each time a screen
publishes `bindings_updated_signal`: on every focus move and every
`refresh_bindings()` (the spreadsheet calls it after each edit), though the
keys are nearly always the same: six rebuilds while the spreadsheet opens,
two or three per prompt.  Each mounts every key again and restyles it.  The
footer here remembers the bindings it was built from and skips a rebuild that
would draw the same keys: the spreadsheet opens and closes in 0.15 s of CPU
instead of 0.23 s (one rebuild), and tests/ui/test_strength_page.py's 16
keyboard sessions take 10.6 s of CPU instead of 20.2 s.
"""

from __future__ import annotations

from textual.app import ComposeResult
from textual.widgets import Footer as TextualFooter

from sass_tui.ui.textual_api import footer_bindings_ready

# What the footer is built from (Footer.compose): each active binding with
# whether it is enabled and its tooltip, in the order the screen gives them,
# and the footer's own settings that compose reads.
Shown = tuple[object, ...]


class Footer(TextualFooter):
    """Textual's footer (same look, same keys) that rebuilds only on a change."""

    _built_from: Shown | None = None

    def _shown(self) -> Shown:
        return (
            self.compact,
            self.show_command_palette,
            self.combine_groups,
            *(
                (active.binding, active.enabled, active.tooltip)
                for active in self.screen.active_bindings.values()
            ),
        )

    def compose(self) -> ComposeResult:
        self._built_from = self._shown() if footer_bindings_ready(self) else None
        yield from super().compose()

    async def recompose(self) -> None:
        # Textual schedules a rebuild on each `bindings_updated_signal`; by the
        # time it runs the bindings are often back to what is shown (a focus
        # passing through a widget), so compare then, not when it is asked for.
        # Detached (its screen closed meanwhile): Textual's recompose does nothing.
        if not self.is_attached or (
            self._built_from is not None and self._shown() == self._built_from
        ):
            return
        await super().recompose()
