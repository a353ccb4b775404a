"""The palette finds commands by an engineer's words, not only their names:
each word the first users tried ("stats", "civilian", "NHANES", "virtual",
"accommodate", "design", "serve") finds the command that does it."""

from __future__ import annotations

from _screen import message, settle
from hypothesis import given
from hypothesis import strategies as st
from textual.command import CommandPalette

from sass_tui.ui.palette import ScreenCommands
from sass_tui.ui.palette_words import SYNONYMS, word_score, words_of

PICKER = "Population: virtual U.S. civilians (NHANES), targets, ANSUR II"
WORDS = {
    "stats": "Percentile table of the query's people",
    "statistics": "Percentile table of the query's people",
    "civilian": PICKER,
    "NHANES": PICKER,
    "virtual": PICKER,
    "accommodate": "Fit Test",
    "design": "Fit Test",
    "serve": "Serve sass in a web browser",
    "web": "Serve sass in a web browser",
    "manikin": "Family",
    "inches": "cm → in",
}


async def best_hits(app, query: str) -> list[str]:
    provider = ScreenCommands(app.screen)
    hits = [hit async for hit in provider.search(query)]
    hits.sort(key=lambda hit: -hit.score)
    return [str(hit.text) for hit in hits]


def test_each_engineers_word_finds_its_command(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, _pilot):
            for word, command in WORDS.items():
                found = await best_hits(app, word)
                assert found, f"{word!r} finds nothing"
                assert found[0] == command, (word, found[:5])

    drive(scenario())


def test_a_name_match_comes_before_a_help_word_match(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, _pilot):
            found = await best_hits(app, "create fig")
            assert found[0] == "Create Figure", found[:3]
            assert await best_hits(app, "zzqx") == []

    drive(scenario())


def test_choosing_serve_says_how_in_the_message_line(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("ctrl+p", *"serve")
            await settle(pilot)  # the palette searches in a worker
            assert isinstance(app.screen, CommandPalette)
            await pilot.press("enter")
            await settle(pilot)
            assert "sass serve" in message(app)

    drive(scenario())


def test_every_synonym_is_one_lowercase_word():
    """As a command's words are cut (words_of): else it could never match."""
    for word, wanted in SYNONYMS.items():
        assert words_of(word) == [word], word
        for synonym in wanted:
            assert words_of(synonym) == [synonym], (word, synonym)


@given(st.text(max_size=30), st.text(max_size=40), st.text(max_size=80))
def test_word_score_is_a_number_from_0_to_1(query, name, help_text):
    assert 0.0 <= word_score(query, name, help_text) <= 1.0
