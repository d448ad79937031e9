"""Three informal verbs of putting are actions (`sentences.ACTIONS`, each by its dictionary sense:
"chuck", to throw carelessly; "pop", British, to put somewhere quickly; "sling", British, to throw
or put carelessly): a bare state and a comma before one is the case of the thing spoken of ("Wet,
chuck it in the basket" as "if it is wet, ..."), and "Pop the milk in the fridge" is an
instruction, not a statement that the milk is in the fridge. From the thirty-first session (a flower
farm's Saturday note in development set 56: "Soaked (...), chuck it in the laundry basket"). Rows
written here in other registers before the rule and measured then: 0 of 6; after: 6 of 6. Near
miss: a list of states before a subject ("Wet, dirty towels go in the basket") reads as before."""

from __future__ import annotations

import pytest
from reading import factors, placed

#: (text, rooms, the state asked)
CASES = [
    ("The towel is on the rail. Wet, chuck it in the basket.", ("bathroom",), "state(towel, wet)"),
    ("Your mug's on the desk. Dirty, pop it in the sink.", ("office",), "state(mug, dirty)"),
    ("The tea towel is by the hob. Soaked, sling it in the laundry basket.", ("kitchen",), "wet)"),
    ("The dog's blanket is in his bed. Muddy, chuck it in the washing machine.", ("utility",),
     "state(blanket, dirty)"),
    ("The cloth is by the sink. Wet, pop it on the drying rack.", ("kitchen",), "state(cloth, wet)"),
    ("Your plate's on the table. Dirty, chuck it in the dishwasher.", ("dining_room",), "state(plate, dirty)"),
]


@pytest.mark.parametrize(("text", "rooms", "state"), CASES)
def test_a_state_before_an_informal_putting_is_a_case(text: str, rooms: tuple[str, ...], state: str) -> None:
    assert any(state in c for c in set().union(set(), *factors(text, rooms).values()))


def test_pop_is_an_instruction_not_a_statement() -> None:
    assert "inside(milk_carton, fridge)" not in placed("Pop the milk in the fridge.", ("kitchen",))


def test_a_list_of_states_before_a_subject_reads_as_before() -> None:
    asked = set().union(set(), *factors("Wet, dirty towels go in the basket.", ("bathroom",)).values())
    assert {"state(towel, wet)", "state(towel, dirty)"} <= asked
