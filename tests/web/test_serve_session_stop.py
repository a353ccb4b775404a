"""A served session's process that does not quit when its tab closes is
killed: stopping the session never waits more than twice STOP_WAIT_S
(ui/serve/serve.py's SessionService.stop), under the 5 s the user guide promises."""

from __future__ import annotations

import asyncio
import dataclasses
import sys
import time

import pytest

pytest.importorskip("textual_serve")

from textual_serve.download_manager import DownloadManager

from sass_tui.ui.serve.serve import ServeOptions
from sass_tui.ui.serve.serve_session import STOP_WAIT_S, SessionService

# Says it is a Textual app (textual-serve waits for this line), then reads
# nothing and ignores SIGTERM: only SIGKILL ends it.
STUBBORN = (
    "import signal, time\n"
    "signal.signal(signal.SIGTERM, signal.SIG_IGN)\n"
    "print('__GANGLION__', flush=True)\n"
    "time.sleep(120)\n"
)


@dataclasses.dataclass(frozen=True)
class StubbornOptions(ServeOptions):
    def command(self) -> list[str]:
        return [sys.executable, "-c", STUBBORN]


@pytest.mark.slow
def test_a_session_process_that_will_not_quit_is_killed(tmp_path):
    options = StubbornOptions(host="localhost", port=1, token="t" * 32, workdir=tmp_path)

    async def nothing(*args) -> None:
        return None

    async def scenario() -> tuple[float, int | None]:
        service = SessionService(
            options,
            close_with=nothing,
            write_bytes=nothing,
            write_str=nothing,
            close=nothing,
            download_manager=DownloadManager(),
        )
        await service.start(80, 24)
        process = service._process
        await asyncio.sleep(0)  # the reader task starts
        started = time.monotonic()
        await service.stop()
        return time.monotonic() - started, process.returncode

    took, returncode = asyncio.run(scenario())
    print(f"a stubborn session process was killed {took:.2f} s after its session stopped")
    assert returncode == -9  # SIGKILL: it did not end by itself
    assert 2 * STOP_WAIT_S <= took < 5.0  # it was given its time to quit, then killed
