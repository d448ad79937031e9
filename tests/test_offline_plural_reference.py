"""Plural reference to enumerated things (tenth session): a plural pronoun ("them", "they",
"both") or a quantified noun phrase ("any drawer", "each cup", "all the drawers", "both
towels") whose head names a kind with several roles speaks of every one of them, so a condition
on it is asked of each member; a counted subject before a colon with a plural verb of resting
("Two cups sit on the desk: a tea cup and a coffee cup") is a statement, placing every member.
The sentences are written for these tests, in different rooms and registers; near misses: a
singular "it" after an enumeration, "one of them", a quantifier over a kind with one role."""

from __future__ import annotations

from logicenveval.offline.analysis import PLURAL_REFERENCE, _quantified
from logicenveval.offline.clauses import verbless
from tests.reading import factors, named, placed


def _asked(text: str, rooms: tuple[str, ...]) -> set[str]:
    """The conditions `text` asks (one value of each factor, its negation left out)."""
    return {c for values in factors(text, rooms).values() for c in values if not c.startswith("not ")}


# -- a plural pronoun takes up the whole group ----------------------------------------------


def test_them_after_an_enumeration_asks_the_elliptic_condition_of_every_member() -> None:
    text = "There are two cups on the tray: a tea cup and a coffee cup. Wash them if dirty."
    assert _asked(text, ("kitchen",)) == {"state(tea_cup, dirty)", "state(coffee_cup, dirty)"}


def test_they_in_a_fronted_condition_asks_of_every_member_in_another_room() -> None:
    # a chatty note in a bathroom
    text = ("So the rail's got two towels on it - a bath towel and a hand towel. If they're wet, "
            "just leave them hanging, ta!")
    assert {"state(bath_towel, wet)", "state(hand_towel, wet)"} <= _asked(text, ("bathroom",))


def test_both_alone_as_subject_asks_of_every_member() -> None:
    # a terse office checklist
    text = "Desk: two lamps - a desk lamp and a reading lamp. If both are on, switch them off."
    asked = _asked(text, ("office",))
    assert {"state(desk_lamp, toggled_on)", "state(reading_lamp, toggled_on)"} <= asked


def test_a_singular_it_after_an_enumeration_picks_one_member() -> None:
    text = "There are two mugs on the counter: a blue mug and a red mug. If it is dirty, wash it."
    asked = _asked(text, ("kitchen",))
    assert len(asked) == 1 and asked <= {"state(blue_mug, dirty)", "state(red_mug, dirty)"}


def test_one_of_them_is_a_member_not_a_plural_reference() -> None:
    assert PLURAL_REFERENCE.search("if one of them is dirty") is None
    assert PLURAL_REFERENCE.search("if none of them is dirty") is None
    assert PLURAL_REFERENCE.search("wash them if dirty") is not None


def test_them_meaning_one_thing_named_in_the_plural_spreads_nothing() -> None:
    # "them" is the wet wipes, not the two mugs of the sentence before
    text = ("There are two mugs on the counter: a blue mug and a red mug. The wet wipes are on the table; "
            "if they are on the floor, put them in the drawer.")
    asked = _asked(text, ("kitchen",))
    assert not asked & {"on(blue_mug, floor)", "on(red_mug, floor)"}


# -- a quantified noun phrase ----------------------------------------------------------------


def test_any_drawer_asks_of_every_drawer_the_text_enumerated() -> None:
    text = "The cabinet has two drawers: one for forks, one for spoons. Close any drawer that is open."
    assert _asked(text, ("kitchen",)) == {"state(fork_drawer, open)", "state(spoon_drawer, open)"}


def test_each_and_every_and_all_the_ask_of_every_member() -> None:
    enumerated = "The dresser has two drawers: a top drawer and a bottom drawer. "
    for instruction in ("Shut each drawer if it is open.", "Every drawer that is open should be closed.",
                        "If all the drawers are open, close them.", "Whichever drawer is open, close it."):
        asked = _asked(enumerated + instruction, ("bedroom",))
        assert {"state(top_drawer, open)", "state(bottom_drawer, open)"} <= asked, instruction


def test_the_plural_of_an_ambiguous_name_means_every_candidate() -> None:
    for text in ("There are two mugs on the counter: a blue mug and a red mug. If the mugs are dirty, wash up.",
                 "There are two mugs on the counter: a blue mug and a red mug. Mugs dirty? Into the sink."):
        assert {"state(blue_mug, dirty)", "state(red_mug, dirty)"} <= _asked(text, ("kitchen",)), text


def test_the_singular_of_an_ambiguous_name_means_the_latest_candidate() -> None:
    text = "There are two mugs on the counter: a blue mug and a red mug. If the mug is dirty, wash it."
    assert _asked(text, ("kitchen",)) == {"state(red_mug, dirty)"}


def test_a_quantifier_over_a_kind_with_one_role_asks_of_that_role() -> None:
    text = "The desk has a drawer. Close any drawer that is open."
    assert _asked(text, ("office",)) == {"state(drawer, open)"}


def _words(text: str) -> list[str]:
    return text.split(" ")


def test_quantified_reads_the_words_before_the_head() -> None:
    words = _words("close any drawer and all of the cups but not one cup or the box")
    assert _quantified(words, 2) and _quantified(words, 7)
    assert not _quantified(words, 11) and not _quantified(words, 14)


# -- a counted subject with a plural verb of resting ------------------------------------------


def test_a_plural_verb_of_resting_before_a_colon_is_a_clause_not_a_heading() -> None:
    assert not verbless(_words("two cups sit on the desk"))
    assert not verbless(_words("the towels hang on the rail"))
    assert verbless(_words("towel on the floor"))
    assert not verbless(_words("hang the towels on the rail"))  # an imperative, still no heading
    assert not verbless(_words("on the counter sit two mugs"))
    assert verbless(_words("on the counter"))


def test_a_placement_stated_of_an_enumerated_set_holds_for_every_member() -> None:
    text = "Two cups sit on the desk: a tea cup and a coffee cup."
    assert {"on(tea_cup, desk)", "on(coffee_cup, desk)"} <= placed(text, ("office",))
    text = "Two towels hang on the towel rack: a bath towel and a hand towel."
    assert {"on(bath_towel, towel_rack)", "on(hand_towel, towel_rack)"} <= placed(text, ("bathroom",))
    # a fronted place before the inverted verb and its counted subject
    text = "On the counter sit two mugs: a blue mug and a red mug."
    assert {"on(blue_mug, kitchen_counter)", "on(red_mug, kitchen_counter)"} <= placed(text, ("kitchen",))


def test_a_placement_of_an_enumerated_set_asks_nothing() -> None:
    text = "Two cups sit on the desk: a tea cup and a coffee cup. Wash them if dirty."
    assert _asked(text, ("office",)) == {"state(tea_cup, dirty)", "state(coffee_cup, dirty)"}


def test_whichever_fronted_is_the_condition_if_any() -> None:
    from logicenveval.offline.implied import implied

    assert implied("Whichever drawer is open, close it.") == "If any drawer is open, close it."
    assert implied("Take whichever cup you like.") == "Take whichever cup you like."  # no condition


def test_they_after_respectively_keeps_each_members_own_place() -> None:
    # each member already has its own fact: "they" spreads nothing across the pair
    text = ("The towel and the soap go on the towel rack and in the cabinet, respectively. "
            "If they are already there, leave them.")
    asked = _asked(text, ("bathroom",))
    assert "on(soap_bar, towel_rack)" not in asked and "inside(towel, cabinet)" not in asked


# -- an enumeration told apart by a colour the kind has no attribute for ----------------------


def test_a_colour_the_kind_lacks_still_tells_enumerated_items_apart() -> None:
    # a cardboard box has no colour attribute: "red" and "blue" tell the two boxes apart by name
    text = "There are two boxes in the room: a red box and a blue box. If the boxes are open, close them."
    assert set(named(text, ("bedroom",))) == {"red_box", "blue_box"}
    assert _asked(text, ("bedroom",)) == {"state(red_box, open)", "state(blue_box, open)"}


def test_an_enumerated_item_is_named_by_its_own_word_for_the_kind() -> None:
    # "bin" is the text's word for a trash can: a red_bin, not a red_can or a bin_can
    text = "There are two bins in the kitchen: a red bin and a blue bin. Empty them if full."
    assert set(named(text, ("kitchen",))) == {"red_bin", "blue_bin"}
    assert _asked(text, ("kitchen",)) == {"state(red_bin, filled)", "state(blue_bin, filled)"}


# -- a plural pronoun whose topic is a thing outside the group --------------------------------


def test_they_after_the_holder_of_an_enumeration_is_the_group_not_the_holder() -> None:
    # the sentence before is about the cabinet; "they", "them", "each of them" are its drawers
    enumerated = "The cabinet has two drawers: one for forks, one for spoons. "
    for instruction in ("If they're open, shut them.", "Check each of them; if open, shut it.",
                        "Are they open? Close them.", "Both should be closed if open."):
        asked = _asked(enumerated + instruction, ("kitchen",))
        assert asked == {"state(fork_drawer, open)", "state(spoon_drawer, open)"}, instruction


def test_they_after_the_holder_in_an_office_note() -> None:
    # a chatty office note: the filing cabinet (which opens too) has the drawers
    text = ("Our filing cabinet has got two drawers, one for bills and one for letters. If they're left open, "
            "shut them.")
    assert _asked(text, ("office",)) == {"state(bill_drawer, open)", "state(letter_drawer, open)"}


def test_a_state_word_between_the_quantifier_and_its_head() -> None:
    text = "The dresser has two drawers: a top drawer and a bottom drawer. Any dirty drawer gets wiped."
    assert _asked(text, ("bedroom",)) == {"state(top_drawer, dirty)", "state(bottom_drawer, dirty)"}
