"""A thing whose own phrase hangs it on a wall ("the cabinet on the wall by the door") or over
another thing ("the cupboard over the kettle", "the cabinet over the stove") is the kind hung on a
wall whose name is "wall" and its head, where the catalog has one (`naming._Reader.wall_sibling`,
`Category.placement` "wall": the wall cabinet), from the thirtieth session (four development texts
described their wall cabinets so: dev 47's ambulance station day room, dev 51's pool plant room,
dev 53's substation battery room, dev 54's stained glass studio). Rows written here in other
registers before the rule and measured then: 0 of 6; after: 6 of 6. Near misses: a cupboard under
or by something stays a cupboard; a shelf over the sink stays the wall shelf it was."""

from __future__ import annotations

import pytest
from reading import factors, kinds

#: (text, rooms)
ON_THE_WALL = [
    ("The glasses live in the cupboard over the kettle; if it is open, shut it.", ("kitchen",)),
    ("Keys go in the cabinet on the wall by the door. If it is open, close it.", ("porch",)),
    ("The plasters are in the little cupboard on the wall above the sink.", ("bathroom",)),
    ("Check the cupboard above the worktop: if its door is open, close it.", ("kitchen",)),
    ("The spices are kept in the cabinet over the stove.", ("kitchen",)),
    ("Put the towels in the cupboard on the wall.", ("utility_room",)),
]


@pytest.mark.parametrize(("text", "rooms"), ON_THE_WALL)
def test_a_cabinet_hung_on_a_wall_is_the_wall_cabinet(text: str, rooms: tuple[str, ...]) -> None:
    got = kinds(text, rooms)
    assert "wall_cabinet" in got and "cabinet" not in got, got


def test_the_wall_cabinets_state_is_asked() -> None:
    for text, rooms in ON_THE_WALL[:2]:
        got = factors(text, rooms)
        assert any("state(wall_cabinet, open)" in values for values in got.values()), got


@pytest.mark.parametrize("text", ["Put it in the cupboard under the sink.", "The cupboard by the wall is open; close it."])
def test_a_cupboard_under_or_by_something_stays_a_cupboard(text: str) -> None:
    got = kinds(text, ("kitchen",))
    assert "cabinet" in got and "wall_cabinet" not in got, got


def test_a_shelf_over_the_sink_stays_a_wall_shelf() -> None:
    assert "wall_shelf" in kinds("Put the mug on the shelf over the sink.", ("kitchen",))
