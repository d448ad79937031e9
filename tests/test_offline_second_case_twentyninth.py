"""A case that names nothing after another case of the same state ("Dirty: open the dishwasher,
put it in, shut the door. Clean: up on the shelf"), from the twenty-ninth session (dev 49's coffee
roastery close list: "Rinse bowl, on the cupping table. Dirty: dishwasher - open it, in it goes,
shut the door. Clean: up on the shelving"): cases of one state set side by side are the cases of
one thing, so the second speaks of what the first asked of, not of a thing only the first case's
instructions named (`analysis._second_case`). Rows written here in other registers before the
rule and measured then: 1 of 6 (the teapot); after: 6 of 6. Near misses: a thing named anew between the cases
("The sink: dirty?") is asked of; a second case already right stays so."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the thing both cases ask of, the thing only an instruction named)
CASES = [
    ("The bowl is on the table. Dirty: open the dishwasher, put it in, shut the door. Clean: up on the shelf.",
     ("cupping_room",), "bowl", "dishwasher"),
    ("Plate - on the tray. Dirty: open the dishwasher and load it in. Clean: into the cupboard.", ("pantry",),
     "plate", "dishwasher"),
    ("Cup on the windowsill. Dirty? Rinse it in the sink, leave the sink tidy. Clean? Back on the shelf.",
     ("parlour",), "cup", "sink"),
    ("Lunch box on the bench. Open: shut the cupboard first, then close it. Closed: leave it be.", ("cloakroom",),
     "lunch_box", "cabinet"),
    ("The towel is on the floor. Wet: open the washing machine, in it goes. Dry: fold it.", ("utility",),
     "towel", "washing_machine"),
    ("Teapot on the trolley. Full: tip it out in the sink and rinse the sink. Empty: back on the shelf.",
     ("tea_room",), "pot", "sink"),
]


@pytest.mark.parametrize(("text", "rooms", "thing", "other"), CASES)
def test_the_second_case_asks_of_the_first_cases_thing(text: str, rooms: tuple[str, ...], thing: str,
                                                        other: str) -> None:
    got = factors(text, rooms)
    subjects = {v.split("(")[1].split(",")[0] for values in got.values() for v in values if v.startswith("state(")}
    assert thing in subjects and other not in subjects, got


def test_a_thing_named_anew_between_the_cases_is_asked_of() -> None:
    got = factors("Mug on the desk. Dirty: wash it. The sink: dirty? Scrub it.", ("office",))
    assert {"mug_dirty", "sink_dirty"} <= set(got), got


def test_a_second_case_already_right_stays_so() -> None:
    text = "Mug on the desk. Dirty: take it to the sink and rinse it under the tap. Clean: back on the hook."
    assert set(factors(text, ("office",))) == {"mug_dirty"}
