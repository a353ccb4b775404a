"""A fuzz campaign over every sass parser (docs/reliability.md).

    python scripts/fuzz.py --budget 10000            # inputs per parser
    python scripts/fuzz.py --budget 2000 --targets query fig --timeout 5
    python scripts/fuzz.py --show flat 52            # print input 52 of flat

The targets, seeds and mutations are tests/fuzz/fuzz_targets.py's (the suite
runs the same ones with a small budget).  Each parser runs in a worker
process; the parent sends it input numbers and waits at most --timeout
seconds for each answer, so a hang (even inside numpy or SQLite, where no
Python signal reaches) is counted, the worker killed and a fresh one started.
Input k of a parser is generated from random.Random(f"{seed}:{parser}:{k}"),
so any input the table reports can be shown again with --show.

Per parser the table gives: inputs, accepted, clean errors (SassError or
OSError, what a user sees as "sass: error: ..."), tracebacks (any other
exception, or a worker that died), hangs, and inputs after which something
was printed on stdout (LAPACK's "DLASCL" lines were one such).
"""

from __future__ import annotations

import argparse
import os
import random
import select
import subprocess
import sys
import tempfile
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "fuzz"))


def _input(name: str, seed: int, index: int) -> object:
    from fuzz_targets import target

    return target(name).generate(random.Random(f"{seed}:{name}:{index}"))


# --- the worker -----------------------------------------------------------------


def worker(name: str, seed: int) -> None:
    """Answer input numbers on stdin with one line each on the original stdout."""
    import warnings

    from fuzz_targets import outcome, target

    warnings.simplefilter("ignore")
    answers = os.fdopen(os.dup(1), "w", buffering=1)
    # Whatever the parser prints (C libraries included) lands in a file we watch.
    spill = tempfile.TemporaryFile()
    os.dup2(spill.fileno(), 1)
    os.dup2(os.open(os.devnull, os.O_WRONLY), 2)
    target(name)
    answers.write("ready\n")
    for line in sys.stdin:
        index = int(line)
        before = os.fstat(spill.fileno()).st_size
        try:
            result = outcome(name, _input(name, seed, index))
        except Exception as exc:  # counting them is the point
            where = traceback.extract_tb(exc.__traceback__)[-1]
            place = f"{Path(where.filename).name}:{where.lineno}"
            message = " ".join(str(exc).split())[:160]
            result = f"traceback {type(exc).__name__} at {place}: {message}"
        sys.stdout.flush()
        if os.fstat(spill.fileno()).st_size != before and result in ("ok", "error"):
            result = "printed"
        answers.write(result.replace("\n", " ") + "\n")


# --- the parent -----------------------------------------------------------------


@dataclass
class Tally:
    name: str
    inputs: int = 0
    ok: int = 0
    errors: int = 0
    tracebacks: int = 0
    hangs: int = 0
    printed: int = 0
    seconds: float = 0.0
    examples: dict[str, int] = field(default_factory=dict)  # kind -> first input number


class Worker:
    def __init__(self, name: str, seed: int) -> None:
        self.process = subprocess.Popen(
            [sys.executable, __file__, "--worker", name, "--seed", str(seed)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            bufsize=1,
        )
        ready = self._read(120.0)
        if ready != "ready":
            raise RuntimeError(f"the {name} worker did not start")

    def _read(self, timeout: float) -> str | None:
        assert self.process.stdout is not None
        ready, _, _ = select.select([self.process.stdout], [], [], timeout)
        if not ready:
            return None
        line = self.process.stdout.readline()
        return line.strip() if line else "traceback the worker died"

    def ask(self, index: int, timeout: float) -> str | None:
        assert self.process.stdin is not None
        try:
            self.process.stdin.write(f"{index}\n")
            self.process.stdin.flush()
        except BrokenPipeError:
            return "traceback the worker died"
        return self._read(timeout)

    def kill(self) -> None:
        self.process.kill()
        self.process.wait()


def campaign(name: str, budget: int, seed: int, timeout: float) -> Tally:
    tally = Tally(name)
    start = time.perf_counter()
    worker_process = Worker(name, seed)
    for index in range(budget):
        answer = worker_process.ask(index, timeout)
        tally.inputs += 1
        if answer is None:
            tally.hangs += 1
            tally.examples.setdefault(f"hang (over {timeout:g} s)", index)
            worker_process.kill()
            worker_process = Worker(name, seed)
            continue
        if answer == "ok":
            tally.ok += 1
        elif answer == "error":
            tally.errors += 1
        elif answer == "printed":
            tally.printed += 1
            tally.examples.setdefault("printed on stdout", index)
        else:
            tally.tracebacks += 1
            tally.examples.setdefault(answer.removeprefix("traceback "), index)
            if answer.endswith("the worker died"):
                worker_process.kill()
                worker_process = Worker(name, seed)
    worker_process.kill()
    tally.seconds = time.perf_counter() - start
    return tally


def table(tallies: list[Tally]) -> str:
    lines = [
        "| parser | inputs | accepted | clean errors | tracebacks | hangs | printed | seconds |",
        "|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for t in tallies:
        lines.append(
            f"| {t.name} | {t.inputs} | {t.ok} | {t.errors} | {t.tracebacks} | {t.hangs} "
            f"| {t.printed} | {t.seconds:.0f} |"
        )
    total = Tally("total")
    for t in tallies:
        for key in ("inputs", "ok", "errors", "tracebacks", "hangs", "printed", "seconds"):
            setattr(total, key, getattr(total, key) + getattr(t, key))
    lines.append(
        f"| **total** | {total.inputs} | {total.ok} | {total.errors} | {total.tracebacks} "
        f"| {total.hangs} | {total.printed} | {total.seconds:.0f} |"
    )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    from fuzz_targets import TARGET_MAKERS

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--budget", type=int, default=10_000, help="inputs per parser")
    parser.add_argument("--timeout", type=float, default=10.0, help="seconds per input")
    parser.add_argument("--seed", type=int, default=17)
    parser.add_argument("--targets", nargs="+", choices=sorted(TARGET_MAKERS))
    parser.add_argument("--show", nargs=2, metavar=("PARSER", "INPUT"), help="print one input")
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        worker(args.worker, args.seed)
        return 0
    if args.show:
        print(repr(_input(args.show[0], args.seed, int(args.show[1]))))
        return 0
    names = args.targets or list(TARGET_MAKERS)
    tallies = []
    for name in names:
        tally = campaign(name, args.budget, args.seed, args.timeout)
        tallies.append(tally)
        print(
            f"{name}: {tally.inputs} inputs, {tally.tracebacks} tracebacks, "
            f"{tally.hangs} hangs, {tally.seconds:.0f} s",
            file=sys.stderr,
            flush=True,
        )
    print(
        f"fuzz campaign: seed {args.seed}, budget {args.budget} inputs a parser, "
        f"{args.timeout:g} s an input; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, "
        f"{os.cpu_count()} CPUs\n"
    )
    print(table(tallies))
    findings = [(t.name, kind, index) for t in tallies for kind, index in t.examples.items()]
    if findings:
        print("\nFirst input of each kind (show it with --show PARSER INPUT):\n")
        for name, kind, index in findings:
            print(f"- {name} input {index}: {kind}")
    return 1 if any(t.tracebacks or t.hangs for t in tallies) else 0


if __name__ == "__main__":
    sys.exit(main())
