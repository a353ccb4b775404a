"""The database layer never imports Textual, and registering its commands
imports neither sqlite3 nor lark (so `sass fig` starts as fast as before)."""

from __future__ import annotations

import subprocess
import sys

CHECK = """
import argparse, sys
from sass_tui.db.commands import register
register(argparse.ArgumentParser().add_subparsers())
assert 'sqlite3' not in sys.modules and 'lark' not in sys.modules, 'eager import'
import sass_tui.db.schema, sass_tui.db.query, sass_tui.db.flatfile, sass_tui.db.ansur
import sass_tui.db.individual
assert not any(m == 'textual' or m.startswith('textual.') for m in sys.modules), 'textual imported'
"""


def test_db_layer_imports():
    result = subprocess.run([sys.executable, "-c", CHECK], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
