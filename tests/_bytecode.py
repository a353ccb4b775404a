"""The test run writes and reuses bytecode even where PYTHONDONTWRITEBYTECODE is
set (this machine's environment and CI's set it).  Without bytecode every test
process, both xdist workers and each `sass` process a test starts (the kill,
serve, terminal and start-up tests: hundreds a run), compiled every sass module
it imported from source, and pytest rewrote every test module's assertions
again in each worker.  The files go where Python puts them by default
(`__pycache__` beside each source, ignored by git).

Imported by conftest.py before anything of sass's: a module imported before
this keeps having no bytecode written, and the workers and `sass` processes
inherit the environment as it is when they start."""

from __future__ import annotations

import os
import sys

sys.dont_write_bytecode = False
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
