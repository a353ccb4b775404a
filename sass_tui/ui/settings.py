"""The user's TUI settings (for now the Textual theme), kept as JSON in the
user's config directory (platformdirs: ~/.config/sass/tui.json on Linux,
following $XDG_CONFIG_HOME).  A missing or unreadable file means the
defaults: settings never stop SASS from starting."""

from __future__ import annotations

import json
from pathlib import Path

from sass_tui.model.errors import SassError, error_text
from sass_tui.model.files.atomic import write_text_atomic
from sass_tui.model.files.paths import config_dir


def settings_path() -> Path:
    return config_dir() / "tui.json"


def load_settings() -> dict[str, object]:
    try:
        data = json.loads(settings_path().read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def save_setting(name: str, value: object) -> str | None:
    """Store one setting; the reason it could not be stored, or None."""
    settings = load_settings()
    settings[name] = value
    path = settings_path()
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text_atomic(path, json.dumps(settings, indent=2) + "\n")
    except (OSError, SassError) as exc:
        return error_text(exc)
    return None
