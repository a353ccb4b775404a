"""Reach (docs/reach.md): one hand's envelope (goal: under 0.5 s) and the
share of the virtual civilians reaching a point (goal: under 2 s), each
beside a baseline measured in the same run.

- envelope(): the right fingertip of the female 5th percentile figure over
  its shoulder and elbow limits, trunk fixed, then with the trunk free;
  baseline: build_humanoid() of the same figure (the skeleton it starts
  from).  Also the envelope written as glTF (render_reach_gltf).
- `sass reach --point ... --virtual nhanes-2017-2020`'s share, in this
  process (the database read, both genders' envelopes, 8,381 people
  counted); baseline: reading those people's statures and weights alone
  (weighted_people).  And the command end to end, a fresh process.

    python benchmarks/reach.py
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from sass_tui.cli.reach_people import population_shares
from sass_tui.db.people.default import create_default_database, open_database
from sass_tui.db.populations.task_people import weighted_people
from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.body.reach import envelope, linkage_of
from sass_tui.model.files.reach_gltf import render_reach_gltf

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))
sys.path.insert(0, str(ROOT / "scripts"))
from hanim_pictures import figure_at  # noqa: E402 - the scripts' percentile figure
from model_bench import best_of  # noqa: E402

VIRTUAL = "nhanes-2017-2020"
POINT = np.array([-0.18, 1.25, 0.6])


def main() -> int:
    folder = Path(tempfile.mkdtemp())
    db = folder / "sass.db"
    create_default_database(db)
    figure = figure_at("female", 5.0)
    linkage = linkage_of(figure)
    env = envelope(linkage)
    rows = [
        ("baseline: build_humanoid (female 5th)", best_of(lambda: build_humanoid(figure), 5, 20)),
        ("envelope, right fingertip, trunk fixed", best_of(lambda: envelope(linkage), 5, 3)),
        (
            "envelope, trunk free (27 trunk postures)",
            best_of(lambda: envelope(linkage, trunk=True), 3, 1),
        ),
        ("the envelope as glTF (render)", best_of(lambda: render_reach_gltf([env], "b"), 5, 5)),
    ]
    args = argparse.Namespace(
        db=str(db), target=None, virtual=VIRTUAL, hand="right", hand_point="fingertip"
    )
    args.seated = args.trunk = False

    def read_people() -> None:
        conn = open_database(db)
        try:
            weighted_people(conn, f"virtual:{VIRTUAL}")
        finally:
            conn.close()

    population_shares(args, POINT)  # the first call makes the virtual population's weights
    rows += [
        ("baseline: the virtual people's statures and weights", best_of(read_people, 3, 1)),
        (
            "share reaching a point, 8,381 virtual people",
            best_of(lambda: population_shares(args, POINT), 3, 1),
        ),
    ]
    env_vars = {**os.environ, "SASS_DB": str(db)}
    command = ["reach", "--point=-18,125,60", "--virtual", VIRTUAL]
    start = time.perf_counter()
    subprocess.run(
        [sys.executable, "-m", "sass_tui", *command], check=True, env=env_vars, capture_output=True
    )
    rows.append(
        ("`sass reach --point ... --virtual`, a fresh process", time.perf_counter() - start)
    )
    print(
        f"{platform.machine()} {platform.processor() or ''}, Python {platform.python_version()}, "
        f"load {os.getloadavg()[0]:.1f}"
    )
    for what, seconds in rows:
        print(f"{what:<56} {seconds * 1000:8.1f} ms")
    print(f"envelope / build_humanoid: {rows[1][1] / rows[0][1]:.1f}x")
    print(f"share / reading the people: {rows[5][1] / rows[4][1]:.1f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
