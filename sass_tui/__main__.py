"""`python -m sass_tui`: the `sass` command."""

import sys

from sass_tui.cli import command_line

sys.exit(command_line())
