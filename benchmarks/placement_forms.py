"""How well the offline reader reads a stated placement in its ordinary grammatical forms (issue 47).

The development sets state each placement in one wording; unseen text says it in any. This
benchmark composes placement sentences from data tables — a statement form (copular "the mug is
on the counter", existential "there is a mug on the counter", inverted "On the counter sits a
mug", possessive "the counter has a mug on it", participial "a mug lying on the counter", passive
and habitual "the mug is kept in ...", "the mug lives on ...", a speaker's report "I left the mug
on ...", relative "the counter, where the mug is", a pronoun after a topic, an aside) x a subject
(the, my, a, a person's name's, a pronoun after a naming sentence) x a preposition (on, on top
of, in, inside: only what an `on`/`inside` fact says) x catalog kind pairs where the holder can
hold the thing — sets each inside a short description, and checks that the reader
(`offline.placement.described_placements`, the entry `reader_generalisation.py --placements`
measures, given the sentence's own roles so naming is out of the figure) states the placement.

It also composes near misses that state *no* current placement (a condition, an instruction, a
goal, a negation, a past state, a question, a doubt) and counts every one read as a placement
of the thing at the holder: a false reading, which must stay at zero.

Since the thirteenth session a second table, `HARDER_FORMS` with `HARDER_NEAR_MISSES`, composes
the harder ways people refer to a place (a standing rule, a predictive "will be" framed by the
reader's arrival, reduced relatives, locative inversion, coordination, a place before its list,
glosses, a place at a part of its holder) and the hedged, negated or offered places that must place
nothing; its line `placement_forms harder=...` is printed before the old forms' `overall=` line.

Since the nineteenth session a third table, `NINETEENTH_FORMS` with `NINETEENTH_NEAR_MISSES` over
`PAIRS` and `NINETEENTH_PAIRS`, composes placements as registers write them (a shipping manifest's
counts "1 x mug - on the counter", a table row "item | where", a checklist with ticks, a stage
plot, an estate agent's listing, a museum label, a child's text, a learner's note), a place before
its thing after a dash, relative clauses on the thing, location adverbs ("over on", "up on"), a
person's holder ("on Sam's desk"), participles ("tucked", "stashed", "propped up"), passive and
progressive forms; and near misses that place nothing now (a past placement since ended, a goal, a
wish, a hypothetical, a suggestion, an unticked task). It was composed before that session's rules
(then 0.7165 read, 135 of 378 near misses read); its line `placement_forms nineteenth=...` is
printed before the old forms' `overall=` line.

Combinations English does not form ("There is my mug on the counter", "It has been put..." with
no thing named) are left out by the tables (`None` cells), so every sentence is one a writer
could write.

    python benchmarks/placement_forms.py            # the matrix, last line `placement_forms overall=...`
    python benchmarks/placement_forms.py --why      # and every sentence misread, every false reading
    python benchmarks/placement_forms.py --smoke    # every 10th sentence, a second
"""

from __future__ import annotations

import argparse
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.offline.placement import described_placements


@dataclass(frozen=True)
class Pair:
    """A thing and a holder that can hold it: catalog kinds, the nouns said, the room, and the
    prepositions that fit (`on` surfaces, `in` containers)."""

    item: str
    noun: str
    holder: str
    place: str
    room: str
    preps: tuple[str, ...]


#: kind pairs that fit (the holder holds the thing), across rooms and both relations
PAIRS: tuple[Pair, ...] = (
    Pair("mug", "mug", "kitchen_counter", "counter", "kitchen", ("on", "on top of")),
    Pair("book", "book", "coffee_table", "coffee table", "living_room", ("on", "on top of")),
    Pair("remote_control", "remote", "sofa", "sofa", "living_room", ("on",)),
    Pair("laptop", "laptop", "desk", "desk", "office", ("on", "on top of")),
    Pair("pillow", "pillow", "bed", "bed", "bedroom", ("on",)),
    Pair("wallet", "wallet", "nightstand", "nightstand", "bedroom", ("on", "on top of", "in", "inside")),
    Pair("towel", "towel", "laundry_basket", "laundry basket", "laundry_room", ("in", "inside")),
    Pair("sock", "sock", "drawer", "drawer", "bedroom", ("in", "inside")),
    Pair("apple", "apple", "fridge", "fridge", "kitchen", ("in", "inside")),
    Pair("jacket", "jacket", "wardrobe", "wardrobe", "bedroom", ("in", "inside")),
)

#: statement forms: a template over {X} (the thing as the subject form says it), {Y} (the holder,
#: "the ..."), {P} (the preposition), {T} (the thing's naming sentence before, for a pronoun), and
#: which subject forms the form takes (an existential or inverted subject is indefinite)
FORMS: dict[str, tuple[str, tuple[str, ...]]] = {
    "copular": ("{X} is {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "copular contracted": ("{X}'s {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "copular still": ("{X} is still {P} {Y} from last night.", ("the", "my", "name's", "pronoun")),
    "existential": ("There is {X} {P} {Y}.", ("a",)),
    "existential contracted": ("There's {X} {P} {Y}.", ("a",)),
    "existential participle": ("There's {X} sitting {P} {Y}.", ("a",)),
    "inverted be": ("{P} {Y} is {X}.", ("a", "my", "name's")),
    "inverted sits": ("{P} {Y} sits {X}.", ("a", "my", "name's")),
    "possessive has": ("{Y} has {X} {Pit} it.", ("a", "my", "name's")),
    "participial": ("You'll see {X} lying {P} {Y}.", ("a", "the", "my", "name's")),
    "passive kept": ("{X} is kept {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "passive left": ("{X} was left {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "habitual lives": ("{X} lives {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "stative sits": ("{X} sits {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "report left": ("I left {X} {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "report put": ("I put {X} {P} {Y} earlier.", ("the", "my", "name's", "pronoun")),
    "report past perfect": ("We had put {X} {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "perfect passive": ("{X} has been left {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "progressive": ("{X} is sitting {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "habitual usually": ("{X} usually stays {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "third-person report": ("Tom left {X} {P} {Y} this morning.", ("the", "my", "name's", "pronoun")),
    "titled third person": ("The cleaner had put {X} {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "you'll find": ("You'll find {X} {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "found": ("I found {X} {P} {Y}.", ("the", "my", "name's", "pronoun")),
    "seen": ("I saw {X} sitting {P} {Y} this morning.", ("a", "the", "my", "name's")),
    "with on it": ("Look at {Y} with {X} {Pit} it.", ("a", "my", "name's")),
    "terse participle": ("{X} left {P} {Y} overnight.", ("bare", "a", "my", "name's")),
    "appositive holder": ("{X} is {P} the whatsit, {Y}.", ("the", "my", "name's", "pronoun")),
    "label colon": ("{X}: {P} {Y}.", ("the", "my", "name's")),
    "label dash": ("{X} - {P} {Y}, as far as I know.", ("the", "my", "name's")),
    "relative where": ("Have a look at {Y}, where {X} is.", ("the", "my", "name's")),
    "relative which": ("{X}, which is {P} {Y}, needs a wipe.", ("the", "my", "name's")),
    "topic pronoun": ("As for {X}: it's {P} {Y}.", ("the", "my", "name's")),
    "aside dash": ("{X} - it's {P} {Y} - needs a wipe.", ("the", "my", "name's")),
    "aside brackets": ("{X} (it's {P} {Y}) needs a wipe.", ("the", "my", "name's")),
}

#: near misses: no current placement is stated ("Find the mug on the counter" is no near miss:
#: an instruction's definite noun phrase takes its place for granted, `placement._resting`); {X} the thing ("the ..."), {Y} the holder ("belongs
#: on" names where a thing goes, `placement.MOTION`, which a condition may then doubt)
NEAR_MISSES: dict[str, str] = {
    "condition if": "If {X} is {P} {Y}, take it out.",
    "condition when": "When {X} is {P} {Y}, tell me.",
    "instruction put": "Put {X} {P} {Y}.",
    "goal make sure": "Make sure {X} ends up {P} {Y}.",
    "goal should": "{X} should be {P} {Y} when you're done.",
    "negation": "{X} is not {P} {Y}.",
    "negation contracted": "{X} isn't {P} {Y} any more.",
    "past used to": "{X} used to be {P} {Y}.",
    "question": "Is {X} {P} {Y}?",
    "check whether": "Check whether {X} is {P} {Y}.",
    "doubt": "{X} might be {P} {Y}.",
    "instruction leave": "Leave {X} {P} {Y} if it's there.",
    "prohibition": "Don't put {X} {P} {Y}.",
    "future": "{X} will go {P} {Y} later.",
    "where it belongs": "{X} belongs {P} {Y}.",
    "condition third person": "If Tom left {X} {P} {Y}, bring it back.",
    "question third person": "Did Tom leave {X} {P} {Y}?",
    "negated report": "I didn't put {X} {P} {Y}.",
    "doubted report": "Maybe Tom put {X} {P} {Y}.",
    "doubted finding": "You might find {X} {P} {Y}.",
    "condition finding": "If you see {X} {P} {Y}, leave it there.",
    "habit third person": "Tom always leaves {X} {P} {Y}.",
    "label question": "{X}: {P} {Y}?",
    "label choice": "{X}: {P} {Y} or in the car.",
    "generic participle": "Every {N} left {P} {Y} gets in the way.",
    "condition participle": "If {X} left {P} {Y}, take it out.",
    "apposition after a clause": "{X} fell {P} the way, {Y} wobbled.",
}

#: harder statement forms (the thirteenth session, written before its rules): the ways people
#: refer to a place beyond the ordinary forms above. Each is a template as in `FORMS`, the subject
#: forms it takes, and the prepositions it is composed with: `None` for the pair's own (the
#: template says {P}), else a relation the template says itself ("at the far end of" a surface is
#: `on` it; "at the bottom of" a container is `inside` it) and which holders it fits ("on": a
#: surface, "in": a container). {O} is a second thing, no role of the sentence; {Yn} the holder's
#: noun alone (a gloss in brackets). The bracketed glosses were added with their rule (dev 22).
HARDER_FORMS: dict[str, tuple[str, tuple[str, ...], str | None]] = {
    "predictive will be": ("{X} will be {P} {Y} when you get there.", ("the", "my", "name's"), None),
    "predictive you'll see": ("When you come in, {X} will be {P} {Y}.", ("the", "my", "name's"), None),
    "standing rule at all times": ("{X} should be {P} {Y} at all times.", ("the", "my", "name's", "pronoun"), None),
    "standing rule always": ("{X} must always be {P} {Y}, day and night.", ("the", "my", "name's"), None),
    "reduced relative left": ("{X} left {P} {Y} needs a wipe.", ("the", "my", "name's"), None),
    "reduced relative sitting": ("{X} sitting {P} {Y} is still dirty.", ("the", "my", "name's"), None),
    "locative inversion stands": ("{P} {Y} stands {X}.", ("a", "my", "name's"), None),
    "locative inversion lies": ("{P} {Y} lies {X}, untouched.", ("a", "my", "name's"), None),
    "coordinated subject": ("{X} and {O} are {P} {Y}.", ("the", "my", "name's"), None),
    "coordinated subject first": ("{O} and {X} are both {P} {Y}.", ("the", "my", "name's"), None),
    "place before its list": ("{P} {Y}: {X}, {O}.", ("a", "my", "name's"), None),
    "subject gloss": ("{X}, the thing I mean, is {P} {Y}.", ("the", "my", "name's"), None),
    "holder gloss brackets": ("{X} is {P} {Y} (the old one).", ("the", "my", "name's", "pronoun"), None),
    "bracketed gloss of a holder": ("{X} is {P} the kredens ({Yn}).", ("the", "my", "name's", "pronoun"), None),
    "bracketed gloss, bare holder": ("{X} stands {P} kredens ({Yn}), near the window.", ("the", "my", "name's"), None),
    "far end of a surface": ("{X} is left at the far end of {Y}.", ("the", "my", "name's", "pronoun"), "on"),
    "head of a surface": ("{X} sits at the head of {Y}.", ("the", "my", "name's"), "on"),
    "edge of a surface": ("{X} is at the edge of {Y}.", ("the", "my", "name's", "pronoun"), "on"),
    "bottom of a container": ("{X} is at the bottom of {Y}.", ("the", "my", "name's", "pronoun"), "in"),
    "back of a container": ("{X} is right at the back of {Y}.", ("the", "my", "name's"), "in"),
    # (the nineteenth session, written before its rule: a topic put first, then a report of placing
    # it with the object left unsaid, as learners from topic-first languages and afterthoughts write)
    "fronted topic, dash": ("{X} - I have put {P} {Y} for you.", ("the", "my", "name's"), None),
    "fronted topic, comma": ("{X}, we left {P} {Y}.", ("the", "my", "name's"), None),
}

#: harder near misses: no current placement of the thing at the holder ({O} a second thing)
HARDER_NEAR_MISSES: dict[str, str] = {
    "will be once done": "{X} will be {P} {Y} once you have finished.",
    "supposed to be": "{X} is supposed to be {P} {Y}, but it never is.",
    "meant to be": "{X} is meant to be {P} {Y}.",
    "no longer": "{X} is no longer {P} {Y}.",
    "neither nor": "{X} is neither {P} {Y} nor in the car.",
    "doubted statement": "I doubt {X} is {P} {Y}.",
    "disjunction of places": "{X} is {P} {Y} or in the car.",
    "other thing coordinated": "{O} are {P} {Y}, and {X} is in the car.",
    "should be by evening": "{X} should be {P} {Y} by this evening.",
    "side of": "{X} is at the side of {Y}.",
    "hoped": "Hopefully {X} is {P} {Y}.",
    "negated standing rule": "{X} should never be {P} {Y}.",
    "negated bracketed gloss": "{X} is not {P} the kredens ({Yn}).",
    "conditional bracketed gloss": "If {X} is {P} the kredens ({Yn}), leave it.",
    "fronted topic with its own verb": "{X} is dirty, I have put {P} {Y} some papers.",
    "conditional fronted topic": "If {X} - I have put {P} {Y}, fine.",
}

#: forms no grid had before the nineteenth session (composed before its rules): placements as
#: registers write them — a shipping manifest, a table row "item | where", a checklist with ticks,
#: a stage plot, an estate agent's listing, a museum label, a child's text, a learner's note — with
#: a quantity between thing and place, the place first, a relative clause on the thing, a location
#: adverb before the place ("over on", "up on"), a person's holder ("Sam's desk"), a past participle
#: ("tucked", "propped", "stashed"), passive and progressive forms. Each is (template, subject
#: forms, relation as in `HARDER_FORMS`, register). {Xn} is the thing's noun alone, {Yn} the holder's.
NINETEENTH_FORMS: dict[str, tuple[str, tuple[str, ...], str | None, str]] = {
    "manifest quantity dash": ("Packing list: 1 x {Xn} - {P} {Y}.", ("bare",), None, "manifest"),
    "manifest quantity colon": ("Contents, {Yn}: 2 x {Xn}s.", ("bare",), "on", "manifest"),
    "table row bar": ("Item | where\n{Xn} | {P} {Y}", ("bare",), None, "table row"),
    "checklist tick": ("Checklist:\n[x] {X} {P} {Y}\n[x] lights off", ("the", "my", "bare"), None, "checklist"),
    "checklist check mark": ("Done so far: {X} {P} {Y} \u2713", ("the", "my"), None, "checklist"),
    "place first one": ("{P} {Y}: one {Xn}.", ("bare",), None, "inventory"),
    "place first quantity dash": ("{P} {Y} - 1 {Xn}.", ("bare",), None, "inventory"),
    "stage plot with": ("Stage left: {Y} with {X} {Pit} it.", ("a", "the"), None, "stage plot"),
    "stage plot set": ("Set {P} {Y}: {X}.", ("a", "the"), None, "stage plot"),
    "listing featuring": ("The room features {Y} with {X} {Pit} it.", ("a",), None, "estate listing"),
    "listing sits proudly": ("{X} sits proudly {P} {Y}.", ("a", "the"), None, "estate listing"),
    "museum displayed": ("{Xn}, about 1920. Displayed {P} {Y}.", ("bare",), None, "museum label"),
    "museum on display": ("On display {P} {Y}: {X}, about 1920.", ("a", "the"), None, "museum label"),
    "child's text": ("my {Xn} is {P} {Y} and i like it", ("bare",), None, "child"),
    "child's there is": ("there is a {Xn} {P} {Y} and its mine", ("bare",), None, "child"),
    "learner staying": ("{X} is staying {P} {Y}.", ("the", "my", "pronoun"), None, "learner"),
    "learner resumptive": ("{X}, it is {P} {Y}.", ("the", "my"), None, "learner"),
    "relative clause on the thing": ("{X}, which Sam bought last week, is {P} {Y}.", ("the", "my"), None, "letter"),
    "relative that": ("{X} that Sam gave me is {P} {Y}.", ("the",), None, "letter"),
    "adverb over": ("{X} is over {P} {Y}.", ("the", "my", "pronoun"), None, "note"),
    "adverb up": ("{X} is up {P} {Y}.", ("the", "my"), "on", "note"),
    "adverb down": ("{X} is down {P} {Y}.", ("the", "my"), "in", "note"),
    "adverb back": ("{X} is back {P} {Y} now.", ("the", "my", "pronoun"), None, "note"),
    "person's holder": ("{X} is {P} Sam's {Yn}.", ("the", "my", "pronoun"), None, "note"),
    "my holder": ("{X} is {P} my {Yn}.", ("the", "pronoun"), None, "note"),
    "participle tucked": ("{X} is tucked {P} {Y}.", ("the", "my", "pronoun"), "in", "note"),
    "participle stashed": ("{X} was stashed {P} {Y}.", ("the", "my", "pronoun"), "in", "note"),
    "participle propped": ("{X} is propped up {P} {Y}.", ("the", "my"), "on", "note"),
    "participle terse tucked": ("{X} tucked {P} {Y}.", ("bare", "my"), "in", "note"),
    "participle comma left": ("{X}, left {P} {Y} by Sam.", ("the", "my"), None, "note"),
    "is sat": ("{X} is sat {P} {Y}.", ("the", "my", "pronoun"), None, "note"),
    "passive progressive": ("{X} is being kept {P} {Y} for now.", ("the", "my", "pronoun"), None, "note"),
    "perfect progressive": ("{X} has been sitting {P} {Y} all week.", ("the", "my", "pronoun"), None, "note"),
    "passive placed": ("{X} has been placed {P} {Y}.", ("the", "my", "pronoun"), None, "note"),
}

#: the nineteenth session's near misses: a past placement that no longer holds, a goal, a wish, a
#: hypothetical, a suggestion — none states where the thing is now
NINETEENTH_NEAR_MISSES: dict[str, str] = {
    "past, then moved": "{X} was {P} {Y} yesterday, but Sam moved it.",
    "past until": "{X} was {P} {Y} until this morning.",
    "used to sit": "{X} used to sit {P} {Y}.",
    "goal after a label": "{X}: put it {P} {Y}.",
    "goal needs to go": "{X} needs to go {P} {Y}.",
    "goal wants": "Sam wants {X} {P} {Y}.",
    "hypothetical had left": "If you had left {X} {P} {Y}, it would be dry.",
    "hypothetical would look": "{X} would look nice {P} {Y}.",
    "imagine": "Imagine {X} {P} {Y}.",
    "suggestion could go": "{X} could go {P} {Y}.",
    "ideally": "Ideally {X} would be {P} {Y}.",
    "unticked to do": "To do:\n[ ] put {X} {P} {Y}",
    "moved off": "Sam took {X} off {Y} an hour ago.",
    "formerly": "{X} was formerly kept {P} {Y}.",
}

#: more kind pairs for the nineteenth grid (holders of other rooms and kinds)
NINETEENTH_PAIRS: tuple[Pair, ...] = (
    Pair("candle", "candle", "dresser", "dresser", "bedroom", ("on",)),
    Pair("notebook", "notebook", "bookshelf", "bookshelf", "living_room", ("on",)),
    Pair("teddy_bear", "teddy", "bed", "bed", "bedroom", ("on",)),
    Pair("keys", "key", "bowl", "bowl", "kitchen", ("in",)),
    Pair("cell_phone", "phone", "dining_table", "dining table", "dining_room", ("on",)),
    Pair("scarf", "scarf", "basket", "basket", "hallway", ("in", "inside")),
)

#: the second thing of a coordinated form: a word the catalog names as no role of the sentence
OTHER_THING = "some papers"

#: how the thing is said by subject form; "pronoun" names it the sentence before
SUBJECT_DETS: dict[str, str] = {"the": "the", "my": "my", "a": "a", "name's": "Sam's", "pronoun": "the", "bare": ""}


@dataclass(frozen=True)
class Case:
    text: str
    fact: str
    form: str
    subject: str
    prep: str
    pair: str
    room: str
    item: str
    holder: str


def _cap(s: str) -> str:
    return s[0].upper() + s[1:]


def _article(det: str, noun: str) -> str:
    if det == "a" and noun[0] in "aeiou":
        return f"an {noun}"
    if not det:  # the terse register's bare noun ("Sock left in the drawer")
        return noun
    return f"{det} {noun}"


def _fact(pair: Pair, prep: str) -> str:
    """The placement a reader states: `inside` for "in"/"inside" (or "where" in a container
    only), `on` otherwise."""
    rel = "inside" if prep in ("in", "inside") else "on"
    return f"{rel}({pair.item}, {pair.holder})"


def _case(form: str, subject: str, pair: Pair, prep: str) -> Case | None:
    """The description for one cell of the matrix, or None where English does not form it."""
    template, subjects = FORMS[form]
    if subject not in subjects:
        return None
    if "{Pit}" in template and prep == "on top of":
        return None  # "has a mug on top of it" is formed, but says no more than "on it"
    if form == "relative where" and prep != pair.preps[0]:
        return None  # "where" says no preposition: one cell per pair
    np = _article(SUBJECT_DETS[subject], pair.noun)
    said = "it" if subject == "pronoun" else np
    body = template.format(X=said, Y=f"the {pair.place}", P=prep, Pit=prep.replace("inside", "in"))
    body = _cap(body)
    opening = f"Please go to the {pair.room.replace('_', ' ')}."
    if subject == "pronoun":
        opening += f" I bought {np} last week."
    text = f"{opening} {body} Then tell me when you're done."
    fact_prep = prep if form != "relative where" else pair.preps[0]
    return Case(text, _fact(pair, fact_prep), form, subject, prep, f"{pair.noun}/{pair.place}", pair.room,
                pair.item, pair.holder)


def cases() -> list[Case]:
    """Every statement of the matrix English forms, in a fixed order."""
    out: list[Case] = []
    for pair in PAIRS:
        for form in FORMS:
            for subject in SUBJECT_DETS:
                for prep in pair.preps:
                    case = _case(form, subject, pair, prep)
                    if case is not None:
                        out.append(case)
    return out


def near_misses() -> list[Case]:
    """Every near miss: one per form, pair and preposition, the thing said "the ..."."""
    out: list[Case] = []
    for pair in PAIRS:
        for form, template in NEAR_MISSES.items():
            for prep in pair.preps:
                body = _cap(template.format(X=f"the {pair.noun}", Y=f"the {pair.place}", P=prep, N=pair.noun))
                text = f"Please go to the {pair.room.replace('_', ' ')}. {body} Then tell me when you're done."
                out.append(Case(text, _fact(pair, prep), form, "the", prep, f"{pair.noun}/{pair.place}",
                                pair.room, pair.item, pair.holder))
    return out


def harder_cases() -> list[Case]:
    """Every statement of the harder forms English forms (`HARDER_FORMS`), in a fixed order; a
    form whose template says its own relation is composed once per pair whose holder fits it."""
    out: list[Case] = []
    for pair in PAIRS:
        for form, (template, subjects, relation) in HARDER_FORMS.items():
            for subject in SUBJECT_DETS:
                if subject not in subjects:
                    continue
                preps = pair.preps if relation is None else (relation,) if relation in pair.preps else ()
                for prep in preps:
                    np = _article(SUBJECT_DETS[subject], pair.noun)
                    said = "it" if subject == "pronoun" else np
                    body = _cap(template.format(X=said, Y=f"the {pair.place}", P=prep, O=OTHER_THING, Yn=pair.place))
                    opening = f"Please go to the {pair.room.replace('_', ' ')}."
                    if subject == "pronoun":
                        opening += f" I bought {np} last week."
                    text = f"{opening} {body} Then tell me when you're done."
                    out.append(Case(text, _fact(pair, prep), form, subject, prep, f"{pair.noun}/{pair.place}",
                                    pair.room, pair.item, pair.holder))
    return out


def harder_near_misses() -> list[Case]:
    """Every harder near miss (`HARDER_NEAR_MISSES`): one per form, pair and preposition."""
    out: list[Case] = []
    for pair in PAIRS:
        for form, template in HARDER_NEAR_MISSES.items():
            for prep in pair.preps:
                body = _cap(template.format(X=f"the {pair.noun}", Y=f"the {pair.place}", P=prep, O=OTHER_THING,
                                            Yn=pair.place))
                text = f"Please go to the {pair.room.replace('_', ' ')}. {body} Then tell me when you're done."
                out.append(Case(text, _fact(pair, prep), form, "the", prep, f"{pair.noun}/{pair.place}",
                                pair.room, pair.item, pair.holder))
    return out


def _nineteenth_pairs() -> tuple[Pair, ...]:
    return PAIRS + NINETEENTH_PAIRS


def nineteenth_cases() -> list[Case]:
    """Every statement of the nineteenth session's forms (`NINETEENTH_FORMS`) over the old and the
    new pairs; `Case.subject` carries the register after a slash, so the table prints both."""
    out: list[Case] = []
    for pair in _nineteenth_pairs():
        for form, (template, subjects, relation, register) in NINETEENTH_FORMS.items():
            preps = pair.preps if relation is None else (relation,) if relation in pair.preps else ()
            for subject in subjects:
                for prep in preps:
                    if "{Pit}" in template and prep == "on top of":
                        continue
                    np = _article(SUBJECT_DETS[subject], pair.noun)
                    said = "it" if subject == "pronoun" else np
                    body = template.format(X=said, Xn=pair.noun, Y=f"the {pair.place}", Yn=pair.place, P=prep,
                                           Pit=prep.replace("inside", "in"))
                    if register not in ("child", "table row"):
                        body = _cap(body)
                    opening = f"Please go to the {pair.room.replace('_', ' ')}."
                    if subject == "pronoun":
                        opening += f" I bought {np} last week."
                    text = f"{opening} {body}\nThen tell me when you're done."
                    out.append(Case(text, _fact(pair, prep), form, f"{subject}/{register}", prep,
                                    f"{pair.noun}/{pair.place}", pair.room, pair.item, pair.holder))
    return out


def nineteenth_near_misses() -> list[Case]:
    """Every nineteenth-session near miss (`NINETEENTH_NEAR_MISSES`): one per form, pair and preposition."""
    out: list[Case] = []
    for pair in _nineteenth_pairs():
        for form, template in NINETEENTH_NEAR_MISSES.items():
            for prep in pair.preps:
                body = _cap(template.format(X=f"the {pair.noun}", Y=f"the {pair.place}", P=prep))
                text = f"Please go to the {pair.room.replace('_', ' ')}. {body}\nThen tell me when you're done."
                out.append(Case(text, _fact(pair, prep), form, "the", prep, f"{pair.noun}/{pair.place}",
                                pair.room, pair.item, pair.holder))
    return out


def _brief(case: Case) -> dict[str, Any]:
    """The sentence's roles (the thing and the holder by their kinds), so naming is out of the figure."""
    roles = {case.item: {"category": case.item}, case.holder: {"category": case.holder}}
    return {"id": "t", "description": case.text, "rooms": [case.room], "roles": roles}


def facts(case: Case, catalog: Catalog) -> list[str]:
    return [f.replace(" ", "") for f in described_placements(_brief(case), catalog)]


def read_right(case: Case, catalog: Catalog) -> bool:
    """Whether the reader states the case's placement; "where" says no preposition, so on a
    holder that is both a surface and a container (a nightstand) either relation is read right."""
    told = facts(case, catalog)
    if case.form == "relative where":
        return any(f"({case.item},{case.holder})" in f for f in told)
    return case.fact.replace(" ", "") in told


def misread(case: Case, catalog: Catalog) -> bool:
    """Whether a near miss is read as a placement of the thing at the holder (on or inside)."""
    told = facts(case, catalog)
    return any(f"({case.item},{case.holder})" in f for f in told)


DIMENSIONS = ("form", "subject", "prep", "pair")


def _print_near_misses(title: str, misses: list[Case], false: list[Case]) -> None:
    """Per form of a near-miss table, how many of its sentences were read as a placement."""
    by_form: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    for c in misses:
        by_form[c.form][1] += 1
    for c in false:
        by_form[c.form][0] += 1
    print(title)
    for value, (bad, total) in by_form.items():
        print(f"  {value:28s} {bad:5d}/{total:<5d}")


def _print_by_form(title: str, cases: Sequence[Case], read: Sequence[bool]) -> None:
    """Per form of a grid, how many of its sentences are read (shared by the harder and the
    nineteenth-session grids)."""
    by_form: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    for c, ok in zip(cases, read, strict=True):
        by_form[c.form][0] += ok
        by_form[c.form][1] += 1
    print(title)
    for value, (good, total) in by_form.items():
        print(f"  {value:28s} {good:5d}/{total:<5d} {good / total:.3f}")


def _nineteenth(catalog: Catalog, why: bool, smoke: bool) -> None:
    """The nineteenth session's grid: per form, how many are read; its near misses; its summary line
    `placement_forms nineteenth=...`, printed before the old forms' `overall=` line."""
    todo = nineteenth_cases()[::10] if smoke else nineteenth_cases()
    read = [read_right(c, catalog) for c in todo]
    _print_by_form("nineteenth-session forms (registers, quantities, participles):", todo, read)
    misses = nineteenth_near_misses()[::10] if smoke else nineteenth_near_misses()
    false = [c for c in misses if misread(c, catalog)]
    _print_near_misses("nineteenth near misses read as a placement (must be 0):", misses, false)
    if why:
        for case, ok in zip(todo, read, strict=True):
            if not ok:
                print(f"MISSED NINETEENTH [{case.form} | {case.subject} | {case.prep}] {case.fact} "
                      f"{facts(case, catalog)}: {case.text!r}")
        for case in false:
            print(f"FALSE NINETEENTH [{case.form} | {case.prep}] {facts(case, catalog)}: {case.text!r}")
    print(f"placement_forms nineteenth={sum(read) / len(todo):.4f} read={sum(read)} sentences={len(todo)} "
          f"false={len(false)}/{len(misses)}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--why", action="store_true", help="print every sentence misread and every false reading")
    ap.add_argument("--smoke", action="store_true", help="every 10th sentence and near miss only")
    args = ap.parse_args()
    catalog = load_catalog()
    todo = cases()[::10] if args.smoke else cases()
    tally: dict[str, dict[str, list[int]]] = {d: defaultdict(lambda: [0, 0]) for d in DIMENSIONS}
    missed: list[Case] = []
    for case in todo:
        ok = read_right(case, catalog)
        for d in DIMENSIONS:
            cell = tally[d][getattr(case, d)]
            cell[0] += ok
            cell[1] += 1
        if not ok:
            missed.append(case)
    for d in DIMENSIONS:
        print(f"by {d}:")
        for value, (good, total) in sorted(tally[d].items(), key=lambda kv: kv[1][0] / kv[1][1]):
            print(f"  {value:28s} {good:5d}/{total:<5d} {good / total:.3f}")
    misses = near_misses()[::10] if args.smoke else near_misses()
    false: list[Case] = [c for c in misses if misread(c, catalog)]
    _print_near_misses("near misses read as a placement (must be 0):", misses, false)
    if args.why:
        for case in missed:
            print(f"MISSED [{case.form} | {case.subject} | {case.prep}] {case.fact}: {case.text}")
        for case in false:
            print(f"FALSE [{case.form} | {case.prep}] {facts(case, catalog)}: {case.text}")
    hard = harder_cases()[::10] if args.smoke else harder_cases()
    hard_read = [read_right(c, catalog) for c in hard]
    hard_missed = [c for c, ok in zip(hard, hard_read, strict=True) if not ok]
    hard_misses = harder_near_misses()[::10] if args.smoke else harder_near_misses()
    hard_false = [c for c in hard_misses if misread(c, catalog)]
    _print_by_form("harder forms (thirteenth session):", hard, hard_read)
    _print_near_misses("harder near misses read as a placement (must be 0):", hard_misses, hard_false)
    if args.why:
        for case in hard_missed:
            print(f"MISSED HARDER [{case.form} | {case.subject} | {case.prep}] {case.fact}: {case.text}")
        for case in hard_false:
            print(f"FALSE HARDER [{case.form} | {case.prep}] {facts(case, catalog)}: {case.text}")
    print(f"placement_forms harder={(len(hard) - len(hard_missed)) / len(hard):.4f} "
          f"read={len(hard) - len(hard_missed)} sentences={len(hard)} false={len(hard_false)}/{len(hard_misses)}")
    _nineteenth(catalog, args.why, args.smoke)
    good = len(todo) - len(missed)
    print(f"placement_forms overall={good / len(todo):.4f} read={good} sentences={len(todo)} "
          f"false={len(false)}/{len(misses)}")


if __name__ == "__main__":
    main()
