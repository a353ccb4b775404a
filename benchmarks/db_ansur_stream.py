"""Importing a large ANSUR-format file streams it: peak memory stays that of
a chunk, whatever the file's size.  Writes a file of about --mb MB (the
shipped male rows repeated with new subject ids) in a temporary directory,
imports it in a child process and reports time and peak resident memory,
against the same for the shipped 6,068 people (the baseline).
Run:  python benchmarks/db_ansur_stream.py [--mb 100]"""

from __future__ import annotations

import argparse
import gzip
import subprocess
import sys
import tempfile
from pathlib import Path

from sass_tui.db.people.default_people import shipped_ansur_files

CHILD = """
import resource, sys, time
from sass_tui.db.people.ansur import import_ansur
from sass_tui.db.engine.schema import connect
conn = connect(sys.argv[1], create=True)
start = time.perf_counter()
counts = import_ansur(conn, sys.argv[2:], label="bench")
elapsed = time.perf_counter() - start
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(f"{sum(counts.values())} {elapsed:.1f} {peak:.0f}")
"""


def big_file(path: Path, megabytes: float) -> int:
    lines = gzip.decompress(shipped_ansur_files()[0].read_bytes()).decode("cp1252").splitlines()
    header, rows = lines[0], lines[1:]
    written = 0
    subject = 1
    target = megabytes * 1e6
    with path.open("w", encoding="cp1252", newline="") as out:
        out.write(header + "\r\n")
        while written < target:
            for row in rows:
                line = f"{subject},{row.split(',', 1)[1]}\r\n"
                out.write(line)
                written += len(line)
                subject += 1
                if written >= target:
                    break
    return subject - 1


def run(db: Path, files: list[Path]) -> tuple[int, float, float]:
    done = subprocess.run(
        [sys.executable, "-c", CHILD, str(db), *map(str, files)],
        capture_output=True,
        text=True,
        check=True,
    )
    people, seconds, peak = done.stdout.split()
    return int(people), float(seconds), float(peak)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--mb", type=float, default=100.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        base = run(Path(tmp) / "base.db", shipped_ansur_files())
        print(f"baseline, the shipped files: {base[0]} people, {base[1]} s, peak {base[2]:.0f} MB")
        path = Path(tmp) / "big.csv"
        rows = big_file(path, args.mb)
        size = path.stat().st_size / 1e6
        big = run(Path(tmp) / "big.db", [path])
        print(
            f"{size:.0f} MB file: {big[0]} people ({rows} rows), {big[1]} s, peak {big[2]:.0f} MB "
            f"(memory ratio to baseline {big[2] / base[2]:.2f}; {big[0] / base[0]:.0f}x the people)"
        )


if __name__ == "__main__":
    main()
