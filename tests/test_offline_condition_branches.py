"""Which branch an action falls under (issue 47, the twelfth session's second round on conditions):
the plan `analysis.nest` builds puts each instruction under the answer its condition says, and
the condition forms r22 found missing are read. Every rule on sentences written here in two
registers or more (none from the task sets, none produced by benchmarks/condition_forms.py),
with near misses that must not be read."""

from __future__ import annotations

from dataclasses import replace

import pytest
from reading import CATALOG, brief
from test_offline_condition_forms import FORMS

from logicenveval.offline.analysis import _unbiased, analyse, nest
from logicenveval.offline.clauses import _by_order, split_clauses


def plans(text: str, rooms: tuple[str, ...], fact: str) -> tuple[str, str]:
    """The plan under the value where `fact` holds, and under the one where it does not."""
    for f in analyse(brief(text, rooms), CATALOG).factors:
        if {fact, f"not {fact}"} <= set(f.values.values()):
            tree = nest([replace(f, context=[])])
            by_cond = {cond: " ".join(tree["branches"][v].get("plan") or []).lower() for v, cond in f.values.items()}
            return by_cond[fact], by_cond[f"not {fact}"]
    raise AssertionError(f"{fact} not asked in {text!r}")


def under(text: str, rooms: tuple[str, ...], fact: str, action: str, holds: bool) -> bool:
    """Whether `action` is planned under the value where `fact` holds (or not), and only there."""
    yes, no = plans(text, rooms, fact)
    return (action in yes, action in no) == (holds, not holds)


# -- a negated state's action is under "no" ------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "fact", "action"), [
    ("Evening rounds: if the porch lamp is off when you get in, switch it on and lock up.",
     ("living_room",), "state(table_lamp, toggled_on)", "switch it on"),
    ("hey, when ur in the kitchen: if the fridge is closed, open it pls x", ("kitchen",),
     "state(fridge, open)", "open it"),
    ("Before the guests arrive: should the bucket in the laundry room be empty, fill it with water.",
     ("laundry_room",), "state(bucket, filled)", "fill it"),
])
def test_a_condition_on_the_negated_state_plans_its_action_under_no(text: str, rooms: tuple[str, ...], fact: str,
                                                                     action: str) -> None:
    assert under(text, rooms, fact, action, holds=False)


@pytest.mark.parametrize(("text", "rooms", "fact", "action", "holds"), [
    # "unless the telly is off, leave it be": left be when it is on
    ("House rule: unless the telly is off, leave it be; otherwise switch it on for the match.",
     ("living_room",), "state(television, toggled_on)", "leave it be", True),
    ("House rule: unless the telly is off, leave it be; otherwise switch it on for the match.",
     ("living_room",), "state(television, toggled_on)", "switch it on", False),
    ("Unless my mug is clean already, wash it in the sink.", ("kitchen",), "state(mug, dirty)", "wash it", True),
    ("Unless the lamp is on, switch it on before the guests arrive.", ("living_room",),
     "state(table_lamp, toggled_on)", "switch it on", False),
])
def test_a_leading_unless_plans_its_instruction_under_its_condition_not_holding(
        text: str, rooms: tuple[str, ...], fact: str, action: str, holds: bool) -> None:
    assert under(text, rooms, fact, action, holds=holds)


def test_a_positive_condition_still_plans_its_action_under_yes_and_leaves_no_alone() -> None:
    text = "If the kettle is switched on, switch it off. Then you can go."
    yes, no = plans(text, ("kitchen",), "state(kettle, toggled_on)")
    assert "switch it off" in yes and no == "leave it as it is"


# -- an instruction before its condition --------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "fact", "action"), [
    ("Empty the pail only if it is full, please.", ("garage",), "state(bucket, filled)", "empty the pail"),
    ("Pick the bath towel up if it has been left on the floor. Cheers!", ("bathroom",), "on(towel, floor)",
     "pick the bath towel up"),
    ("The fridge - shut it if it was left open, the milk goes off otherwise.", ("kitchen",), "state(fridge, open)",
     "shut it"),
])
def test_an_instruction_before_its_condition_is_that_conditions_branch(text: str, rooms: tuple[str, ...],
                                                                       fact: str, action: str) -> None:
    assert under(text, rooms, fact, action, holds=True)


def test_the_instruction_before_whether_is_done_either_way_no_branch() -> None:
    # near miss: "Check whether ..." asks; "check" is not what the answer "yes" plans
    yes, no = plans("Check whether the oven is on; if it is, switch it off.", ("kitchen",), "state(oven, toggled_on)")
    assert "switch it off" in yes and "check" not in yes and "switch it off" not in no


# -- "Then" after a sentence that is only a condition -------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "fact", "action"), [
    ("Suppose the cupboard is open. Then close it before you leave.", ("bathroom",), "state(cabinet, open)",
     "close it"),
    ("The laptop's lid is open? Then shut it, it drains the battery.", ("office",), "state(laptop, open)", "shut it"),
])
def test_a_then_sentence_after_a_bare_condition_is_its_branch(text: str, rooms: tuple[str, ...], fact: str,
                                                              action: str) -> None:
    assert under(text, rooms, fact, action, holds=True)


# -- a negative question and a question's tag ask the positive proposition ----------------------

@pytest.mark.parametrize(("said", "meant"), [
    ("is not the sock on the floor?", "is the sock on the floor?"),
    ("has not the bin been emptied?", "has the bin been emptied?"),
    ("it is on, is not it?", "it is on?"),
    ("the towels are not dry, are they?", "the towels are not dry?"),
    # near misses: a negative polarity word keeps the negation; a statement is left as it is
    ("is not there any milk left?", "is not there any milk left?"),
    ("has not it been washed yet?", "has not it been washed yet?"),
    ("the lamp is not on.", "the lamp is not on."),
    ("is not it on, is not it", "is not it on, is not it"),
])
def test_the_bias_of_a_question_is_not_its_proposition(said: str, meant: str) -> None:
    assert _unbiased(said) == meant


@pytest.mark.parametrize(("text", "rooms", "fact", "action"), [
    ("Isn't the sock on the floor again? If so, pick it up.", ("bedroom",), "on(sock, floor)", "pick it up"),
    ("Wasn't the bath towel left on the floor this morning? Pick it up if so.", ("bathroom",), "on(towel, floor)",
     "pick it up"),
    ("The kettle's switched on, isn't it? Then switch it off.", ("kitchen",), "state(kettle, toggled_on)",
     "switch it off"),
    ("Ahoy - the sock be lying on the floor, is it not? If so, stow it in the basket.", ("bedroom",),
     "on(sock, floor)", "stow it"),
])
def test_a_negative_question_or_a_tag_plans_the_action_under_the_positive(text: str, rooms: tuple[str, ...],
                                                                           fact: str, action: str) -> None:
    assert under(text, rooms, fact, action, holds=True)


# -- a proposition or not, and its cases named by order -----------------------------------------

@pytest.mark.parametrize(("text", "rooms", "fact", "yes_action", "no_action"), [
    ("Either the mug is dirty or it is not. In the first case, wash it; in the second, put it away.",
     ("kitchen",), "state(mug, dirty)", "wash it", "put it away"),
    ("Lemma. Either the fridge is open or not. In the first case close it. In the second case leave it shut.",
     ("kitchen",), "state(fridge, open)", "close it", "leave it shut"),
    ("Is the bucket full? If the former, empty it; if the latter, fill it.", ("laundry_room",),
     "state(bucket, filled)", "empty it", "fill it"),
])
def test_cases_named_by_order_are_the_branches_of_the_question(text: str, rooms: tuple[str, ...], fact: str,
                                                               yes_action: str, no_action: str) -> None:
    yes, no = plans(text, rooms, fact)
    assert yes_action in yes and no_action in no


@pytest.mark.parametrize("sentence", [
    "Put the book in the first case on the shelf.",
    "The second case holds the spare fuses.",
    "In the first drawer, you will find the keys.",
])
def test_an_ordinal_that_names_no_case_of_a_question_is_left(sentence: str) -> None:
    assert _by_order(sentence) == sentence


def test_either_of_two_things_is_no_question() -> None:
    # near miss: "either ... or" between two things offers no proposition and its negation
    pieces = split_clauses("Either the mug or the bowl can go in the sink.")
    assert all(p.cue != "?" for p in pieces)


# -- a pointing cue needs no comma --------------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "fact", "action"), [
    ("Is the lamp on? If so switch it off.", ("bedroom",), "state(table_lamp, toggled_on)", "switch it off"),
    ("kettle full?? if so pour it out pls", ("kitchen",), "state(kettle, filled)", "pour it out"),
])
def test_if_so_without_a_comma_is_followed_by_its_instruction(text: str, rooms: tuple[str, ...], fact: str,
                                                              action: str) -> None:
    assert under(text, rooms, fact, action, holds=True)


# -- the matrix's new forms (benchmarks/condition_forms.py) -------------------------------------

def test_the_matrix_composes_the_forms_r22_found_missing_and_checks_the_branch() -> None:
    by_cell = {(c.connective, c.subject, c.verb, c.state, c.kind): c for c in FORMS.cases()}
    negative = by_cell[("Isn't X? If so", "noun", "simple", "on the floor", "sock")]
    assert "Isn't the sock on the floor? If so, pick it up." in negative.text
    tag = by_cell[("X, isn't it? Then", "noun", "contracted", "on", "table_lamp")]
    assert "The lamp's switched on, isn't it? Then switch it off." in tag.text
    tag_of_negated = by_cell[("X, isn't it? Then", "pronoun", "negated", "open", "fridge")]
    assert "It isn't shut, is it? Then close it." in tag_of_negated.text
    either = by_cell[("either; first case", "noun", "simple", "dirty", "mug")]
    assert "Either my mug is dirty or not. In the first case, wash it; in the second, leave it." in either.text
    off = by_cell[("if", "noun", "simple", "off", "television")]
    assert off.negative  # "if the tv is off, switch it on": the action under "no"
    # a negated verb group in a question asks the positive proposition: "Isn't the tv on? If so"
    asked = by_cell[("Is X? If so", "noun", "negated", "off", "television")]
    assert "Isn't the tv on? If so, switch it on." in asked.text and not asked.negative
    for case in (negative, tag, tag_of_negated, either, off, asked):
        assert FORMS.reading(case, CATALOG) == (True, True)
