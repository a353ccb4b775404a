"""The words the command palette (ui/palette.py) finds commands by, beside
their names: an engineer's synonyms for the words of the commands' names
and help, how well a query's words name a command, and the things done
outside the TUI (`sass serve`) that the palette lists to say how."""

from __future__ import annotations

import re

# An engineer's word -> words the commands' names and help use.  A typed
# word finds a command when it, or one of these, begins one of its words.
SYNONYMS: dict[str, tuple[str, ...]] = {
    "stats": ("percentile", "table"),
    "statistics": ("percentile", "table"),
    "summary": ("percentile", "table"),
    "mean": ("percentile", "table"),
    "civilian": ("target", "population"),
    "civilians": ("target", "population"),
    "nhanes": ("target", "population"),
    "ansur": ("target", "query", "input"),
    "army": ("target", "query"),
    "soldier": ("target", "query"),
    "survey": ("target", "population"),
    "weight": ("weighted", "target"),
    "weights": ("weighted", "target"),
    "virtual": ("target", "population"),
    "accommodate": ("fit", "design", "limits", "family"),
    "accommodation": ("fit", "design", "limits", "family"),
    "design": ("fit", "design"),
    "spec": ("fit", "design", "limits"),
    "limit": ("fit", "design", "limits"),
    "manikin": ("family", "figure"),
    "mannequin": ("family", "figure"),
    "boundary": ("family",),
    "cases": ("family",),
    "serve": ("serve", "web", "browser"),
    "web": ("serve", "web", "browser"),
    "browser": ("serve", "web", "browser"),
    "share": ("serve", "web"),
    "load": ("input", "open", "read"),
    "open": ("input", "open", "read"),
    "import": ("input",),
    "read": ("input", "open", "read"),
    "write": ("write", "save", "export", "create"),
    "export": ("export", "write", "create"),
    "3d": ("gltf", "hanim", "export"),
    "mesh": ("gltf", "export"),
    "model": ("gltf", "hanim", "export", "predict"),
    "body": ("gltf", "hanim", "figure"),
    "units": ("units", "cm", "in"),
    "inches": ("units", "in"),
    "metric": ("units", "cm"),
    "imperial": ("units", "in"),
    "draw": ("figure", "draw"),
    "picture": ("figure", "draw"),
    "view": ("figure", "show"),
    "search": ("query", "jump", "type"),
    "find": ("query", "jump", "type"),
    "filter": ("query", "type"),
    "select": ("select", "query"),
    "posture": ("task", "strength"),
    "lift": ("task", "strength"),
    "niosh": ("task",),
    "force": ("strength", "torque", "task"),
    "torque": ("strength", "torque"),
    "capable": ("capable", "task"),
    "regression": ("predict",),
    "estimate": ("predict",),
    "history": ("message", "log", "undo"),
}


def words_of(text: str) -> list[str]:
    """The words of a command's name or help, lowercase."""
    return re.findall(r"[a-z0-9]+", text.lower())


def word_score(query: str, name: str, help_text: str) -> float:
    """How well the words typed name a command, 0 to 1: 0 when one of them
    (with its synonyms) begins no word of its name or help.  A word in the
    name counts twice one in the help; a synonym listed later a little less."""
    typed = words_of(query)
    if not typed:
        return 0.0
    in_name, in_help = words_of(name), words_of(help_text)
    score = 0.0
    for word in typed:
        best = 0.0
        for rank, want in enumerate((word, *SYNONYMS.get(word, ()))):
            weight = 1.0 - 0.05 * rank
            if any(w.startswith(want) for w in in_name):
                best = max(best, weight)
            elif any(w.startswith(want) for w in in_help):
                best = max(best, weight / 2)
        if best == 0.0:
            return 0.0
        score += best
    return score / len(typed)


# Done outside the TUI: listed so that the palette finds them, and says how.
OUTSIDE: tuple[tuple[str, str, str], ...] = (
    (
        "Serve sass in a web browser",
        "sass serve, in a shell: the spreadsheet in browser tabs (docs/user-guide.md).",
        "In a shell: `sass serve` serves this spreadsheet to web browsers, one session a "
        "tab (pip install 'sass-tui[serve]'); it prints the address to open.",
    ),
)
