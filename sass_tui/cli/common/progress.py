"""A progress bar on the terminal for long command-line work."""

from __future__ import annotations

from typing import TextIO


class ProgressBar:
    def __init__(self, stream: TextIO, label: str = "importing", width: int = 40) -> None:
        self.stream = stream
        self.label = label
        self.width = width

    def __call__(self, done: int, total: int) -> None:
        filled = int(self.width * done / max(total, 1))
        self.stream.write(
            f"\r{self.label} [{'#' * filled}{'.' * (self.width - filled)}] {done}/{total}"
        )
        self.stream.flush()

    def finish(self) -> None:
        self.stream.write("\n")
        self.stream.flush()


def progress_for(stream: TextIO, label: str = "importing") -> ProgressBar | None:
    """A bar when `stream` is a terminal, else None (pipes and logs get no \\r noise)."""
    return ProgressBar(stream, label) if stream.isatty() else None
