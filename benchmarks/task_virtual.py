"""`sass task` for a virtual population (spec: under 1 s), beside a baseline
measured in the same run: `sass task --gender female` (the figure alone),
each in fresh processes, interleaved (A, B, A, B, ...) so both see the same
machine load.  The first `--virtual` run makes the virtual population in a
temporary database and is not counted.

    python benchmarks/task_virtual.py [--runs 7] [--hands | --squat]

--hands: the posture `hands=40cm,30cm` with 10 kg in each hand, each
gender's figure finding its own stoop (model/strength/hands_at.py);
--squat: `hands=40cm,30cm,squat`, its own squat.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PY = sys.executable
SASS = shutil.which("sass", path=str(Path(PY).parent)) or shutil.which("sass")
TASK = ["task", "shoulder_y=90", "elbow_y=0", "--right-load", "40N", "--right-direction", "forward"]
STOOP = ["task", "hands=40cm,30cm", "--left-load", "10 kg", "--right-load", "10 kg"]
SQUAT = ["task", "hands=40cm,30cm,squat", "--left-load", "10 kg", "--right-load", "10 kg"]


def timed(command: list[str], env: dict[str, str]) -> tuple[float, float]:
    """(wall s, CPU s of the child): on a shared machine the CPU time is the
    command's own work, the wall time adds the other processes' load."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    elapsed = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode:
        raise RuntimeError(f"{' '.join(command)}: {done.stderr.decode()[-500:]}")
    cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    return elapsed, cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=7)
    chosen = parser.add_mutually_exclusive_group()
    chosen.add_argument("--hands", action="store_true", help="a stoop to where the hands grasp")
    chosen.add_argument("--squat", action="store_true", help="a squat to where the hands grasp")
    args = parser.parse_args()
    task = STOOP if args.hands else SQUAT if args.squat else TASK
    assert SASS, "the sass console script (pip install -e .)"
    with tempfile.TemporaryDirectory() as folder:
        env = {**os.environ, "SASS_DB": str(Path(folder) / "task.db"), "HOME": folder}
        virtual = [SASS, *task, "--virtual", "nhanes-2017-2020"]
        baseline = [SASS, *task, "--gender", "female"]
        timed(virtual, env)  # makes the virtual population
        pairs = [(timed(virtual, env), timed(baseline, env)) for _ in range(args.runs)]
    for words, index in (("wall", 0), ("CPU", 1)):
        a = statistics.median(p[0][index] for p in pairs)
        b = statistics.median(p[1][index] for p in pairs)
        print(
            f"{words}: sass task {task[1]} ... --virtual nhanes-2017-2020 {a:.3f} s "
            "(target under 1 s); "
            f"--gender female (baseline) {b:.3f} s; ratio {a / b:.2f}"
        )


if __name__ == "__main__":
    main()
