"""What a session served to a web browser may do.

`sass serve` starts one `sass` process per browser tab and tells it, in its
environment, the directory its files stay in (`sass serve --workdir`) and
whether the database is read-only (`--read-only`).  The TUI reads both when
it starts (ui/app.py's run_app); a `sass` started by hand with them set is
confined the same way.
"""

from __future__ import annotations

import os
from pathlib import Path

WORKDIR_ENV = "SASS_WORKDIR"
READ_ONLY_ENV = "SASS_READ_ONLY"


def served_workdir() -> Path | None:
    """The directory $SASS_WORKDIR names, or None when it is unset or empty."""
    value = os.environ.get(WORKDIR_ENV, "")
    return Path(value) if value else None


def served_read_only() -> bool:
    """True when $SASS_READ_ONLY is 1: the database is queried, never changed."""
    return os.environ.get(READ_ONLY_ENV, "") == "1"
