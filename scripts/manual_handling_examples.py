"""The worked examples of docs/manual-handling.md, rerun: each command's
output as the doc shows it.

    python scripts/manual_handling_examples.py
"""

from __future__ import annotations

import contextlib
import io
import shlex
import sys
import tempfile
from pathlib import Path

from sass_tui.cli import main

JOB = """name,load,load_max,h,v,d,a,f,coupling
shelf,8kg,10kg,30cm,100cm,40cm,0,2,good
floor,8kg,10kg,45cm,20cm,60cm,30,1,fair
bench,8kg,,35cm,70cm,30cm,0,3,fair
"""

EXAMPLES = (
    "niosh --h 10in --v 22in --dest-h 20in --dest-v 59in --f 3 --duration short --load 26lb",
    "niosh --h 40cm --v 60cm --d 80cm --a 30 --f 2 --duration moderate --load 12kg",
    "niosh --tasks JOB --duration moderate",
    "handling lift --h 0.38 --v 1.03 --d 0.51 --f 1 --load 10kg",
    "handling pull --v 1.2 --d 20 --f 1 --load 200N",
    "handling lift shoulder_y=60 elbow_y=30 --d 0.5 --f 1 --load 10kg --gender female "
    "--percentile 5",
)


def run(command: str, job: Path) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        status = main(shlex.split(command.replace("JOB", str(job))))
    if status:
        raise SystemExit(f"sass {command}: exit {status}")
    return out.getvalue()


def main_() -> int:
    with tempfile.TemporaryDirectory() as tmp:
        job = Path(tmp) / "job.csv"
        job.write_text(JOB, encoding="utf-8")
        print(f"job.csv:\n{JOB}")
        for command in EXAMPLES:
            print(f"$ sass {command.replace('JOB', 'job.csv')}")
            text = run(command, job)
            print("\n".join(line for line in text.splitlines() if not line.startswith("Source:")))
            print()
    return 0


if __name__ == "__main__":
    sys.exit(main_())
