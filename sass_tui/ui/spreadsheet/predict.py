"""Predict on the spreadsheet: the known values are typed on the
message line with their names completed as they are typed; the prediction
model is opened in a worker (ui/query/people_work.py's open_predictor_at: the first
fit takes about a second) and posted back as `PredictorOpened`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from textual.message import Message
from textual.suggester import Suggester

from sass_tui.model.units import DISPLAY

if TYPE_CHECKING:  # the model is imported by the worker that opens it, not at start
    from sass_tui.model.population.prediction import Prediction, Predictor

KNOWN_PROMPT = "Known values for a {gender} (e.g. stature=180 cm, mass=85 kg):"


class KnownSuggester(Suggester):
    """Completes the name being typed after the last comma: `stature=180 cm,
    me` suggests `...,measure.…` from the predictor's fields."""

    def __init__(self, fields: Sequence[str]) -> None:
        super().__init__(use_cache=False, case_sensitive=True)
        self.fields = tuple(sorted(fields, key=lambda f: (f.count("."), f)))

    async def get_suggestion(self, value: str) -> str | None:
        head, comma, tail = value.rpartition(",")
        typed = tail.lstrip()
        if not typed or "=" in typed:
            return None
        lowered = typed.lower()
        for field in self.fields:
            if field.startswith(lowered) and field != lowered:
                return value + field[len(lowered) :]
        return None


class PredictorOpened(Message):
    """The worker's prediction model, fitted or read from its cache."""

    def __init__(self, predictor: Predictor) -> None:
        super().__init__()
        self.predictor = predictor


def interval_text(prediction: Prediction, field: str, unit: str, convert) -> str:
    """'38.2 cm (90 % interval 35.1–41.3)' for the message line, in the unit shown."""
    estimate = prediction.values.get(field)
    if estimate is None:
        return f"{field}: not predicted (taken from the population)"
    value, low, high = (
        convert(v, estimate.unit, unit) for v in (estimate.value, estimate.low, estimate.high)
    )
    if estimate.known:
        return f"{field} = {value:.1f} {DISPLAY[unit]}: known, as typed"
    return (
        f"{field} = {value:.1f} {DISPLAY[unit]}, 90 % prediction interval "
        f"{low:.1f} – {high:.1f} {DISPLAY[unit]}"
    )
