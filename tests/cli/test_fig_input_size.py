"""`sass fig --girth` of a 100 MB (and a 1 GB) sparse file, run as a user
runs it: refused at once by the file's size, with a one-line message of a
few hundred bytes at most, and the process's memory bounded (a 1 GB file ran
61 s, peaked at 13.6 GB and printed a 4 GB message; a 100 MB one took 1.36 GB)."""

from __future__ import annotations

import subprocess
import sys
import time

import pytest

# The interpreter, numpy and sass take some 60 MB; reading the file would
# take at least its own size.
MOST_MEMORY_KB = 150_000


@pytest.mark.parametrize("size", [100 * 10**6, 10**9], ids=["100MB", "1GB"])
def test_a_huge_population_file_is_refused_at_once(tmp_path, size):
    huge = tmp_path / "girth.dat"
    with huge.open("wb") as handle:
        handle.truncate(size)  # a hole: no disk used
    out = tmp_path / "x.fig"
    started = time.monotonic()
    child = subprocess.Popen(
        [sys.executable, "-m", "sass_tui", "fig", "--girth", str(huge), "-o", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    try:
        said = child.communicate(timeout=60)[1]
    except subprocess.TimeoutExpired:
        child.kill()
        child.communicate()
        raise
    took = time.monotonic() - started
    print(f"refused in {took:.2f} s, {len(said)} bytes of message")
    assert child.returncode == 2
    assert said.count(b"\n") == 1 and len(said) < 300, said[:300]
    assert b"too large for a population file" in said and str(huge).encode() in said
    assert not out.exists()


# The child runs sass and then says the most memory its process held
# (VmHWM: kept per address space, so a fresh one after exec; rusage's
# ru_maxrss would carry over the forking test process's own size).
MEASURED = """
import sys
from sass_tui.cli import main
status = main(sys.argv[1:])
peak = [line for line in open("/proc/self/status") if line.startswith("VmHWM:")]
print(peak[0].split()[1], file=sys.stderr)
sys.exit(status)
"""


def test_the_refusal_reads_nothing_of_the_file(tmp_path):
    """The peak resident memory of the refusing process stays far under
    the file's size."""
    huge = tmp_path / "girth.dat"
    with huge.open("wb") as handle:
        handle.truncate(200 * 10**6)
    child = subprocess.run(
        [
            sys.executable,
            "-c",
            MEASURED,
            "fig",
            "--girth",
            str(huge),
            "-o",
            str(tmp_path / "x.fig"),
        ],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert child.returncode == 2
    peak_kb = int(child.stderr.strip().splitlines()[-1])
    print(f"peak resident memory {peak_kb} KB for a 200 MB file")
    assert peak_kb < MOST_MEMORY_KB
