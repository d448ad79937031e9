"""A role the reader named from a head said by a synonym ("the wall cupboard", "the cupboard over
the kettle": the wall cabinet, `naming._Reader.head_by_synonym`, `wall_sibling`) is found again
by those words when its conditions are read (`lexicon.Lexicon.build`: a kind's two-word name
whose head names another kind, "wall cabinet", is also said with that kind's one-word synonyms,
"cupboard" and "wall cupboard", where those words name no role of their own). From the thirtieth
session: the naming rules named the wall cabinet, but "If the cupboard over the kettle is open"
then asked of the kettle and "If the wall cupboard is open" of nothing. Rows written here before
the change and measured then: 0 of 6; after: 6 of 6. Near miss: where a cabinet is named too, the
cupboard is the cabinet's."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, the state asked)
SAID_HEADS = [
    ("If the wall cupboard is open, shut it.", "state(wall_cabinet, open)"),
    ("If the cupboard on the wall is open, shut it.", "state(wall_cabinet, open)"),
    ("If the cupboard over the kettle is open, shut it.", "state(wall_cabinet, open)"),
    ("The cupboard over the kettle: if it is open, shut it.", "state(wall_cabinet, open)"),
    ("If the TV cupboard is open, close it.", "state(tv_stand, open)"),
    ("If the medicine cupboard is open, close it.", "state(medicine_cabinet, open)"),
]


@pytest.mark.parametrize(("text", "state"), SAID_HEADS)
def test_a_head_said_by_a_synonym_is_found_again(text: str, state: str) -> None:
    assert any(state in values for values in factors(text, ("kitchen",)).values())


def test_a_cupboard_beside_a_named_cabinet_is_the_cabinets() -> None:
    got = factors("The cabinet under the sink and the wall cabinet: if the cupboard is open, shut it.", ("kitchen",))
    assert not any("wall_cabinet" in v for values in got.values() for v in values), got
