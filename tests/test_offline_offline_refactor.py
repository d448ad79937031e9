"""The reader's refactors of the eleventh session (issue 47): one definition where two modules had
twins, the lemmatiser where a hand rule told a word's form (docs/reader.md, "What it still
misreads": what was found and left). Sentences written for these tests, in more than one register each; near misses too."""

from __future__ import annotations

from typing import Any

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.clauses import presence_asked, verbless
from logicenveval.offline.lexicon import WORD
from logicenveval.offline.placement import described_placements
from logicenveval.offline.sentences import NORM_ADVERBS, expand, habitual

CATALOG = load_catalog()
ROLES = {"watch": "watch", "armchair": "armchair", "pot": "pot", "stove": "stove"}


def _words(text: str) -> list[str]:
    return WORD.findall(expand(text).lower())


def _read(text: str, *roles: str, kinds: frozenset[str] | None = None) -> set[str]:
    missing = [r for r in roles if CATALOG.get(ROLES[r]) is None]
    if missing:
        pytest.skip(f"the catalog lacks {missing}")
    brief: dict[str, Any] = {"id": "t", "description": text, "rooms": ["living_room", "kitchen"],
                             "roles": {r: {"category": ROLES[r]} for r in roles}}
    return set(described_placements(brief, CATALOG) if kinds is None
               else described_placements(brief, CATALOG, kinds=kinds))


# (a) a plural before a bare verb of resting, by the lemmatiser (`clauses._plural_finite`) -------

@pytest.mark.parametrize("segment", [
    "two cups sit on the desk",              # a tidy list
    "the spare towels hang by the door",     # a house note
    "my airpods sit in the tray",            # a word the dictionary lacks: the lemmatiser's rules
    "both kettles stand on the counter",     # a caretaker's log
])
def test_a_plural_before_a_bare_verb_of_resting_is_a_clause(segment: str) -> None:
    assert not verbless(segment.split())


@pytest.mark.parametrize("segment", [
    "glass stand by the sink",               # "glass" is no plural ("ss")
    "the bus stand",                         # nor "bus"
    "lens rest on the tripod",               # nor "lens"
    "gas stand by the boiler",               # a word of three letters is no noun's plural
])
def test_a_singular_ending_in_s_before_a_bare_verb_leaves_a_heading_verbless(segment: str) -> None:
    assert verbless(segment.split())


# (b) a condition that only asks whether its thing is there (`clauses.presence_asked`) --------

@pytest.mark.parametrize(("condition", "negated"), [
    ("it's still there", False),                 # a text message
    ("they are there", False),                   # a note
    ("it isn't there", True),                    # a chat
    ("they are not there", True),                # a formal note
    ("it turns up", False),                      # a chat
    ("your wallet ever shows up", False),        # an e-mail: the thing's noun phrase as subject
    ("the spare key is found", False),           # a work order
    ("it reappears", False),                     # a formal letter
    ("it's anywhere", False),                    # a chat
    ("it is anywhere in the house", False),      # a letter: "anywhere" and the place it spans
    ("they are here at all", False),             # a diary
    ("anywhere", False),                         # a terse list: the subject left out
    ("there at all", False),
])
def test_a_condition_that_only_asks_presence(condition: str, negated: bool) -> None:
    assert presence_asked(_words(condition)) is negated


@pytest.mark.parametrize("condition", [
    "it's anywhere else",            # a place of its own ("anywhere else")
    "it is on the table",            # a place
    "it's dirty",                    # a state
    "they are there on the desk",    # a place after "there"
    "the kids turn up late",         # more than the verb of appearing
    "she did leave it",              # an agent's leaving: the placement reader's own (`LEAVING`)
    "its flame still flickers there",  # a verb of its own before "there" (a tale)
    "the old key hangs there",         # a verb of resting before "there" (a note)
    "it is not on the shelf",
    "",
])
def test_a_condition_that_asks_more_than_presence(condition: str) -> None:
    assert presence_asked(_words(condition)) is None


@pytest.mark.parametrize("text", [
    "Thirdly, I may have left my watch in the flat. If it is still there, it will be on the armchair.",
    "lost my watch again!! it'll be on the armchair if it's anywhere",
    "My watch may be in the flat. It will be on the armchair, if it is here at all.",
])
def test_where_a_thing_will_be_if_it_is_there_is_its_stated_place(text: str) -> None:
    assert "on(watch, armchair)" in _read(text, "watch", "armchair")


@pytest.mark.parametrize("text", [
    "I may have left my watch here. If it is not there, it will be on the armchair.",
    "I may have left my watch here. It will be on the armchair if it is anywhere else.",
    "I may have left my watch here. If it is dirty, it will be on the armchair.",
])
def test_where_a_thing_will_be_near_misses(text: str) -> None:
    assert "on(watch, armchair)" not in _read(text, "watch", "armchair")


# (c) adverbs of a norm: one table (`sentences.NORM_ADVERBS`) ---------------------------------

@pytest.mark.parametrize("text", [
    "Upon the stove there ordinarily rests the heavy pot.",             # a household manual
    "On the stove customarily sits the big steel pot, as it always has.",  # a guest book
    "On the stove usually sits the old pot.",                           # a note
])
def test_a_place_put_first_with_a_norm_adverb_is_a_home(text: str) -> None:
    assert "on(pot, stove)" in _read(text, "pot", "stove", kinds=frozenset({"kept"}))
    assert "on(pot, stove)" not in _read(text, "pot", "stove", kinds=frozenset({"settled"}))


def test_a_place_put_first_without_a_norm_adverb_is_where_the_thing_is() -> None:
    text = "Upon the stove there now rests the heavy pot."
    assert "on(pot, stove)" in _read(text, "pot", "stove", kinds=frozenset({"settled"}))


@pytest.mark.parametrize(("words", "expected"), [
    ("the key commonly gets left on the hook", True),   # a norm adverb with a verb of an event: a habit
    ("the key ordinarily ends up on the sofa", True),
    ("the key commonly hangs on the hook", False),      # with a verb of resting: a norm, no habit
])
def test_a_norm_adverb_makes_a_habit_only_with_an_event(words: str, expected: bool) -> None:
    assert {"commonly", "ordinarily", "customarily"} <= NORM_ADVERBS
    assert habitual(words.split()) is expected
