"""Placement rules from the tenth development set (docs/reader.md, "From dev 10 (placements)"): stated
placements the reader did not read, so that the scene put the thing elsewhere. Each rule is a kind of
sentence, tried on a dev 10 sentence and on sentences written for the test in other rooms with other
objects; each test fails without its rule."""

from __future__ import annotations

from reading import placed

# -- a participle set off by a comma rests the clause's subject ------------------------------------


def test_a_resting_participle_after_a_comma_places_the_clauses_subject() -> None:
    # dev 10 (a match commentary): the telly, said to be on, then "sitting up there on the TV stand"
    text = "The telly's been on since kick-off, sitting up there on the TV stand like it owns the place."
    assert "on(television, tv_stand)" in placed(text, ("rumpus_room",))
    # written for the test: a kitchen, a kettle said warm then standing on the hob
    assert "on(kettle, stove)" in placed("The kettle is still warm, standing on the hob.", ("kitchen",))
    # and a bedroom: a lamp said on, then lying on the floor
    assert "on(table_lamp, floor)" in placed("The lamp is on, lying on the floor.", ("bedroom",))


def test_a_participle_after_a_comma_with_no_clause_subject_places_nothing() -> None:
    # an instruction, or a clause whose subject is a person, lends its participle no thing
    assert not placed("Switch it off, sitting on the sofa.", ("living_room",))
    assert not placed("I was tired, sitting on the sofa.", ("living_room",))


# -- "over" after a verb of covering is "on" ---------------------------------------------------------


def test_over_after_a_covering_verb_is_on_the_thing_under() -> None:
    # dev 10 (a bedtime story): "the royal blanket, spread over the bed"
    assert "on(blanket, bed)" in placed("Then there was the royal blanket, spread over the bed.", ("tower_room",))
    # written for the test: a living room, a coat draped over an armchair; a towel over a chair's back
    assert "on(coat, armchair)" in placed("There is a coat, draped over the armchair.", ("living_room",))
    assert "on(towel, chair)" in placed("A towel is draped over the back of the chair.", ("bathroom",))
    assert "on(blanket, sofa)" in placed("The blanket is spread over the sofa.", ("living_room",))


def test_over_as_a_particle_or_an_instruction_places_nothing_on_what_follows() -> None:
    # "knocked over" is a particle: the place is the "on" after it
    assert placed("The mug was knocked over on the desk.", ("study",)) == {"on(mug, desk)"}
    # an instruction says where a thing goes, not where it is
    assert not placed("Spread the blanket over the bed.", ("bedroom",))
