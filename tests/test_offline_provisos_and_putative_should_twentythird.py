"""Two condition forms no grid had, from the twenty-third session, each a table of sentences
written here in several registers (a notice, a hotel card, a text message, a checklist, a
tenancy clause, learner English, a method) with near misses that must stay as they are; both
tables were measured before the rule (the counts in each test's docstring).

- a proviso opened by "providing (that)", a bare "provided", "so long as" or "on (the)
  condition that" ("Providing the towel is dry, fold it", "Put the mug away, provided it's
  clean"): read as "provided that" / "as long as", which the reader already reads
  (`sentences._PROVISO`);
- the putative "should" inside a condition ("If the kettle should be empty, fill it", "in case
  the towels should still be damp"; Quirk et al., the putative "should" of a conditional clause):
  a condition of what is, read with its verb finite ("If the kettle is empty"), where before
  "should be" was taken for a norm and nothing was asked (`sentences._PUTATIVE_SHOULD`)."""

from __future__ import annotations

import pytest
from reading import asks, factors, instruction_under, placed

#: (text, rooms, the condition asked). Before the rule 1 of 10 was asked ("On the condition that
#: the curtain is closed": the curtain's state read from the clause on its own)
PROVISOS = [
    # a house notice
    ("Providing the towel is dry, fold it and put it in the cabinet.", ("bathroom",), "state(towel, wet)"),
    ("Provided the mug is clean, put it in the cabinet; otherwise wash it.", ("kitchen",), "state(mug, dirty)"),
    # a text message
    ("put the mug in the cabinet, provided it's clean", ("kitchen",), "state(mug, dirty)"),
    ("providing the kettle's full u can switch it on", ("kitchen",), "state(kettle, filled)"),
    # a tenancy clause
    ("On condition that the laptop is closed, the Tenant may leave it on the desk.", ("office",),
     "state(laptop, open)"),
    ("On the condition that the curtain is closed, the heater may be left on.", ("bedroom",),
     "state(curtain, open)"),
    # a method
    ("So long as the pan is clean, hang it on the rail; if not, wash it in the sink.", ("kitchen",),
     "state(pan, dirty)"),
    # a checklist
    ("- Blanket: fold it, providing that it is dry.", ("living_room",), "state(blanket, wet)"),
    # learner English
    ("You can leave the lamp on provided the curtain is closed.", ("bedroom",), "state(curtain, open)"),
    ("So long as the remote is on the sofa, you leave it.", ("living_room",), "on(remote_control, sofa)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), PROVISOS)
def test_a_proviso_is_a_condition(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Measured before the rule: 1 of 10 asked; after: 10 of 10."""
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition", "asked", "placement"), [
    # "provided" as a participle: the towels the hotel provided, the soap provided
    ("Use the towels provided by the hotel and hang them on the rail if they are wet.", ("bathroom",),
     "state(towel, wet)", True, None),
    ("The soap provided is in the cabinet.", ("bathroom",), "state(soap_bar, dirty)", False, "inside(soap_bar, cabinet)"),
    # "providing" as a gerund
    ("Thanks for providing the towels! If they are wet, hang them on the rail.", ("bathroom",), "state(towel, wet)",
     True, None),
    ("We are providing the mug for guests. It is on the shelf.", ("kitchen",), "state(mug, dirty)", False, None),
    # "provided that" as written
    ("Provided that the mug is clean, put it in the cabinet.", ("kitchen",), "state(mug, dirty)", True, None),
])
def test_provided_as_a_participle_stays(text: str, rooms: tuple[str, ...], condition: str, asked: bool,
                                        placement: str | None) -> None:
    """Near misses: "provided" after a noun or before "by" / "in", "providing" before an object
    with no verb of its own, and "provided that" as written read as before (5 of 5 before the
    rule and after)."""
    assert asks(text, rooms, condition) == asked, factors(text, rooms)
    if placement is not None:
        assert placement in placed(text, rooms)


#: (text, rooms, the condition asked). Before the rule 0 of 10 were asked
PUTATIVE = [
    # a hotel card
    ("If the kettle should be empty, kindly fill it at the sink.", ("kitchen",), "state(kettle, filled)"),
    ("Before you go: if the fan should be switched on, switch it off.", ("bedroom",),
     "state(ceiling_fan, toggled_on)"),
    # a tenancy clause
    ("In case the laptop should be left open, the Tenant shall close it.", ("office",), "state(laptop, open)"),
    # a text message
    ("if the towels should still be damp hang them on the rail", ("bathroom",), "state(towel, wet)"),
    ("if the remote should be missing look under the sofa", ("living_room",), "exists(remote_control)"),
    # a notice with a negation and an adverb
    ("If the mug should not be clean, wash it.", ("kitchen",), "state(mug, dirty)"),
    ("If the laptop should by any chance still be open, close it.", ("office",), "state(laptop, open)"),
    # other verbs than "be"
    ("If the mug should look dirty, wash it in the sink.", ("kitchen",), "state(mug, dirty)"),
    ("If the blankets should turn out to be wet, hang them on the rail.", ("bedroom",), "state(blanket, wet)"),
    # a pronoun subject
    ("Check the pan. If it should be dirty, wash it.", ("kitchen",), "state(pan, dirty)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), PUTATIVE)
def test_a_putative_should_asks_what_is(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Measured before the rule: 0 of 10 asked; after: 10 of 10."""
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition", "asked"), [
    # "should" in the consequence, or as a statement's norm: what ought to be, not asked
    ("If the kettle is empty, it should be filled at the sink.", ("kitchen",), "state(kettle, filled)", True),
    ("The kettle should be full before the guests arrive.", ("kitchen",), "state(kettle, filled)", False),
    ("The mug should be clean. If it is dirty, wash it.", ("kitchen",), "state(mug, dirty)", True),
    # the inverted "should" and "should" after the agent, as before
    ("Should the towel be wet, hang it on the rail.", ("bathroom",), "state(towel, wet)", True),
    ("If you should find the mug dirty, wash it.", ("kitchen",), "state(mug, dirty)", True),
    # "should" after a subject that is a clause
    ("If you need the pan it should be clean.", ("kitchen",), "state(pan, dirty)", False),
])
def test_should_outside_a_condition_stays(text: str, rooms: tuple[str, ...], condition: str, asked: bool) -> None:
    """Near misses: a consequence's or a statement's "should", the inverted conditional, "you
    should find" and a subject that is a clause read as before (6 of 6 before the rule and after)."""
    assert asks(text, rooms, condition) == asked, factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition", "answer", "instruction"), [
    ("Providing the towel is dry, fold it and put it in the cabinet.", ("bathroom",), "state(towel, wet)", "no",
     "fold it"),
    ("put the mug in the cabinet, provided it's clean", ("kitchen",), "state(mug, dirty)", "no", "put the mug"),
    ("So long as the pan is clean, hang it on the rail; if not, wash it in the sink.", ("kitchen",),
     "state(pan, dirty)", "yes", "wash it"),
    ("If the kettle should be empty, kindly fill it at the sink.", ("kitchen",), "state(kettle, filled)", "no",
     "fill it"),
    ("If the mug should not be clean, wash it.", ("kitchen",), "state(mug, dirty)", "yes", "wash it"),
])
def test_the_instruction_falls_under_its_answer(text: str, rooms: tuple[str, ...], condition: str, answer: str,
                                                instruction: str) -> None:
    """The instruction is planned under the answer the proviso or the condition names (the
    proviso's under the condition holding, "if not" under the other), as for "provided that" and
    "if ... is" written out (0 of 5 before the rules, the conditions not being read; 5 of 5 after)."""
    assert instruction in instruction_under(text, rooms, condition).get(answer, ""), instruction_under(
        text, rooms, condition)
