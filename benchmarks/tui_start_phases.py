"""Where the TUI's start goes, phase by phase, beside the bare Textual app.

Each start runs in a pseudo-terminal of 120x40 (as `tui_first_screen.py`).
Inside it a probe times, from the interpreter's start: Textual imported, the
app's module imported, and the first screen drawn; and it sums the time
spent in a few of Textual's and sass's functions (wrapped with
perf_counter; nested calls of the same function are counted once):
stylesheet parsing and applying, layout, rendering, `SassApp()` and the
default figure.  It also says whether numpy was imported by the first
screen (it must not be).

    python benchmarks/tui_start_phases.py [--runs 7]
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cli_ratios import BARE_APP, PY
from tui_first_screen import first_screen

# The probe's common part: wraps functions to sum their time (the outermost
# call of each only), reports on the terminal when the screen is drawn.
PROBE = """
import functools, importlib, os, sys, time
T0 = time.perf_counter()
import gc
gc.disable()  # as `sass` starts (cli.run_tui); the bare app is held alike
SPENT = {}
def wrap(module, qualified):
    owner = importlib.import_module(module)
    *path, name = qualified.split(".")
    for part in path:
        owner = getattr(owner, part)
    function = getattr(owner, name)
    depth = [0]
    @functools.wraps(function)
    def timed(*args, **kwargs):
        depth[0] += 1
        start = time.perf_counter()
        try:
            return function(*args, **kwargs)
        finally:
            depth[0] -= 1
            if not depth[0]:
                SPENT[qualified] = SPENT.get(qualified, 0.0) + time.perf_counter() - start
    setattr(owner, name, timed)
import textual.app
MARKS = {"textual imported": time.perf_counter()}
for module, qualified in (
    ("textual.css.stylesheet", "Stylesheet.parse"),
    ("textual.css.stylesheet", "Stylesheet.apply"),
    ("textual.screen", "Screen._refresh_layout"),
    ("textual._compositor", "Compositor.render_update"),
):
    wrap(module, qualified)
def drawn(app, numpy_before):
    now = time.perf_counter()
    phases = dict(MARKS, **{"first screen drawn": now})
    fields = [f"{name}={(t - T0) * 1000:.2f}" for name, t in phases.items()]
    fields += [f"{name}={t * 1000:.2f}" for name, t in SPENT.items()]
    fields.append(f"numpy={numpy_before}")
    os.write(1, ("RESULT " + ";".join(fields) + " END").encode())
    app.exit()
"""

SASS_PROBE = (
    PROBE
    + """
from sass_tui.ui import app as sass_app
from sass_tui.ui.spreadsheet.spreadsheet import SpreadsheetScreen
MARKS["app imported"] = time.perf_counter()
wrap("sass_tui.ui.app", "SassApp.__init__")
wrap("sass_tui.model.body.figure", "Figure.default")
def first_screen_drawn(screen):
    drawn(screen.app, "numpy" in sys.modules)
SpreadsheetScreen._first_screen_drawn = first_screen_drawn
sys.exit(sass_app.run_app(None))
"""
)

# cli_ratios's bare app, timed by the probe: its class as it is, started
# with the probe's hook after its first refresh.
_BARE_START = "\nBare().run()\n"
assert BARE_APP.endswith(_BARE_START)
BARE_PROBE = (
    PROBE
    + BARE_APP.removesuffix(_BARE_START)
    + """
MARKS["app imported"] = time.perf_counter()
class Probed(Bare):
    def on_mount(self):  # Textual runs Bare's on_mount too (each class's handler)
        self.call_after_refresh(lambda: drawn(self, "numpy" in sys.modules))
Probed().run()
"""
)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    env = dict(os.environ, TERM="xterm-256color")
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    results: dict[str, list[dict[str, str]]] = {"sass": [], "bare Textual app": []}
    with tempfile.TemporaryDirectory() as tmp:
        scripts = {"sass": Path(tmp) / "sass_probe.py", "bare Textual app": Path(tmp) / "bare.py"}
        scripts["sass"].write_text(SASS_PROBE)
        scripts["bare Textual app"].write_text(BARE_PROBE)
        for script in scripts.values():  # compile, warm caches
            first_screen([PY, str(script)], env, b" END")
        for _ in range(args.runs):
            for name, script in scripts.items():
                written = first_screen([PY, str(script)], env, b" END")[1]
                body = written[written.index(b"RESULT ") + 7 : written.index(b" END")].decode()
                results[name].append(dict(field.split("=") for field in body.split(";")))
    print(
        f"\n{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {os.cpu_count()} cores, "
        f"Python {sys.version.split()[0]}, load average {os.getloadavg()[0]:.2f}; "
        f"{args.runs} interleaved starts each, pty 120x40; medians in ms.\n"
    )
    names = list(dict.fromkeys(key for runs in results.values() for r in runs for key in r))
    print("| | " + " | ".join(results) + " |")
    print("| --- |" + " --- |" * len(results))
    for key in names:
        cells = []
        for runs in results.values():
            values = [r[key] for r in runs if key in r]
            if not values:
                cells.append("")
            elif key == "numpy":
                cells.append(", ".join(sorted(set(values))))
            else:
                cells.append(f"{statistics.median(float(v) for v in values):.1f}")
        print(f"| {key} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
