"""A small natural-language analyser of task descriptions (the offline model's reading).

It reads only what an LLM would read (the brief: description, rooms, roles) and finds sentences
and clauses; conditional and uncertainty cues ("if", "unless", "in case", "whether", "should
there be", "otherwise", "may", "if available", ...); mentions grounded to roles (names, catalog
categories and synonyms, colour words, pronouns resolved to the sentence topic); and facts in the
condition language (on/inside/in_room/state/attr/exists). A fact is a *condition* when it
describes the current situation (`if the bottle is empty`, `a toy lying on the floor`,
`a dirty plate`) and a *goal* when it follows an action (`put it in the fridge`, `goes into the
bin`). Conditions in conditional, uncertain or descriptive-modifier position become factors —
uncertain variables with exclusive, exhaustive values — grouped into independent subtasks.
"""

from __future__ import annotations

import json
import re
from collections import Counter
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from lemminflect import getAllLemmas, getInflection

from logicenveval.domain.catalog import Catalog, Category, load_catalog
from logicenveval.domain.lemmas import noun_plurals
from logicenveval.offline.clauses import (
    AGENT_TIMES,
    AGENTS,
    ANAPHORIC,
    ARTICLES,
    AVAILABILITY,
    CLAUSE_WORDS,
    FINITE_VERBS,
    FRONT_LEADS,
    LEAD_INS,
    NEGATIONS,
    OBJECT_STARTS,
    PERMITTED,
    PLACE_PREPS,
    PRESENCE_DETERMINERS,
    PRESENCE_QUESTION,
    SOFTENERS,
    SUBJECTS,
    SUBORDINATORS,
    UNCERTAIN,
    Piece,
    ends_asking,
    imperative,
    points_back,
    presence_asked,
    split_clauses,
    uncertain_words,
)
from logicenveval.offline.implied import any_at, implied
from logicenveval.offline.lexicon import (
    COLOR_WORDS,
    FUNCTION_WORDS,
    PART_TIES,
    VERB_OBJECTS,
    WORD,
    Lexicon,
    Mention,
    singular,
    tokens,
    without_modifiers,
    words_of,
)
from logicenveval.offline.placement import (
    BECOMING,
    GOING,
    LEFT_PASSIVES,
    RESULT,
    STATIVE,
    described_placements,
)
from logicenveval.offline.sentences import (
    ACTIONS,
    CARELESS,
    DISCOVERY,
    EVENT_VERBS,
    FORMS,
    FOUND_PARTICIPLES,
    FREQUENCY,
    GOING_ON,
    HABITUAL_WORDS,
    MACHINE_EPITHETS,
    NORM_ADVERBS,
    PREP_IN,
    PREP_ON,
    STATE_WORDS,
    TAKING_FROM,
    TEND,
    TRAILING_ADVERBIALS,
    as_read,
    as_tokens,
    code_switched,
    determiner,
    expand,
    foreign,
    habitual,
    predicate_state,
    split_sentences,
    taken_word,
)
from logicenveval.offline.vocabulary import reading_catalog
from logicenveval.scene.compat import can_hold

#: words between a subject and its predicate that describe a current situation
DESCRIPTIVE = frozenset(
    ["is", "are", "was", "were", "be", "been", "being", "am", "seem", "seems", "seemed", "look", "looks", "appear", "appears", "still", "already", "currently", "left", "lying", "lie", "lies", "sitting", "sit", "sits", "standing", "stand", "stands", "resting", "rests", "kept", "found", "dropped", "fallen", "ended", "up", "have", "has", "had", "got", "gotten", "remain", "remains", "remained", "now", "itself", "themselves", "just", "somehow", "accidentally", "again", "there", "here", "turned", "switched", "scattered", "sitting", "lays", "fell", "slipped", "rolled", "may", "might", "could", "possibly", "perhaps", "maybe", "probably", "sometimes", "will",
     "also", "too", "even", "lives", "live", "stays", "stay", "keep", "keeps", "rolling", "falling",
     "ending", "somewhere",
     # a predicate adjective of presence ("a book may be present on the floor", a manual's register)
     "present",
     # slang verbs of resting ("my mug might be chilling on the desk")
     "chill", "chills", "chilling",
     # "land (up)" for "end up" (British, South African: "if a cushion landed up on the floor")
     "landed", "lands", "landing",
     # "wind up" for "end up" (American: "if that detergent bottle has wound up on the floor")
     "wound", "winds", "wind", "winding",
     # a verb of posture before a state is the copula: "if its door is hanging open", as "the
     # safe is standing open" (where a thing hangs is read by the location reader all the same)
     "hanging", "hangs",
     # (and its base form, also the singular the tokens make of "hangs": "should its door hang open")
     "hang",
     # verbs of falling (`FALLS`): "a pillow may have tumbled to the floor"
     "tumbled", "tumbles", "toppled", "slid",
     # the British progressive of resting with the participle ("if they're already sat on the
     # shoe rack", "if the laptop's sat on the sofa"): sitting ("stood" is also the passive of
     # standing a thing somewhere: "it is stood in the umbrella stand", a goal)
     "sat"]
) | CARELESS  # the participles of leaving a thing carelessly ("if it is dumped on the sofa")
#: verbs after a subject that announce where it must go (a goal, not a condition)
MOTION = frozenset(
    ["go", "goes", "going", "belong", "belongs", "should", "must", "needs", "need", "get", "gets", "gotten", "put", "placed", "hung", "moved", "returned", "stored", "back", "brought", "taken", "carried",
     # passive voice: "a dirty shirt is put into the hamper", "clean ones are folded onto the shelf"
     "laid", "thrown", "tossed", "loaded", "folded", "filed", "shelved", "stowed", "sorted", "tucked",
     "packed", "stacked", "transferred", "binned", "hanged", "set", "parked", "wiped", "refilled",
     "end"]  # "should end up on the rack"
)
PARTS = frozenset({"door", "lid", "leaf", "screen", "soil", "surface", "top", "inside", "water",
                   "content", "bottom", "side", "handle", "shelf", "drawer", "bag", "glass", "bottle",
                   "box", "pack", "packet", "jar", "carton", "tub", "container", "roll",
                   # parts whose failure is their thing's: "unless its bulb is broken", "if the
                   # torch's batteries are dead" ask the lamp's and the torch's state
                   "bulb", "battery", "batteries", "wick", "lens"})
PRONOUNS = frozenset({"it", "they", "them", "one", "ones", "its", "their", "whose"})
#: prepositions of time whose noun is an occasion, not a thing spoken of ("after bath", "during
#: the show": `_Reader._occasion`); not "before", also a place ("before the fire")
OCCASION_PREPS = frozenset({"after", "during"})
#: determiners of a definite plural: "the white ones" are particular things, "white ones" a kind
DEFINITE_PLURAL = frozenset({"the", "these", "those", "your", "my", "our", "their", "its"})
#: the parts by which a piece of furniture opens: said alone ("open the drawer"), they mean the
#: piece last named that opens (`_Reader._opener`)
OPENING_PARTS = frozenset({"drawer", "door"})
#: kinds of thing that depict a person or an animal, which a child calls "she" or "he", and the
#: pronouns that may then mean them (`_Reader.mentions`)
PERSONIFIED = frozenset({"doll", "teddy_bear"})
PERSON_PRONOUNS = frozenset({"she", "he", "her", "him"})
#: the personal pronouns that refer to one particular thing or group already named ("it", "them";
#: not "one", "ones", which stand for any thing of a kind): a placement said of one is stated
DEFINITE_REFERENCE = frozenset({"it", "they", "them"}) | PERSON_PRONOUNS
#: verbs that say where a thing belongs ("it is kept in the vanity", "the remote lives on the
#: stand"): said of a definite object they are still askable (see `Fact.definite`)
#: (with the words as `tokens` gives them, `as_tokens`: the noun lemma of a verb form, "lives" -> "life")
HOMES = as_tokens({"kept", "lives", "live",
                   # where a doll or a pet sleeps is its place (`placement.KEEP_VERBS` reads it so)
                   "sleeps", "sleep"})
DESCRIPTIVE |= frozenset(singular(w) for w in HOMES)
#: the verbs that put a thing away where it belongs ("put it away", "tidy the mug away",
#: `_Reader._back_home`); "throw it away", "give it away" send it nowhere it belongs
PUT_AWAY = frozenset({"put", "tidy", "pack", "store", "clear"})
#: at most how many words an aside between a subject and its predicate runs to ("as ever",
#: "as far as I know", `_Reader._aside_end`)
ASIDE_WORDS = 5
#: prepositions of direction: after one, a participle of the perfect that is also a state word
#: ("has blown onto", "have smashed into") says where the thing went, not its state ("the fuse
#: has blown", "a smashed cup"); "when it is running, into the hamper" keeps its state
TOWARDS = frozenset({"onto", "into", "off", "away", "down", "across"})
PERFECT = frozenset({"have", "has", "had", "'ve", "ve"})
#: verbs of falling: "to" after one says where the thing came to rest ("a pillow may have
#: tumbled to the floor", "if the spoon has fallen to the floor"), not where someone moves it
FALLS = frozenset({"fallen", "fell", "falls", "tumbled", "tumbles", "toppled", "dropped", "slipped", "slid",
                   "rolled"})
#: participles that turn a noun phrase into a description of the current situation
SITUATION_PARTICIPLES = frozenset({"left", "lying", "lie", "lies", "sitting", "found", "dropped", "fallen", "fell",
                                   "slipped", "rolled", "landed", "wound",
                                   "scattered", "forgotten", "standing", "ended", "rolling", "falling",
                                   "ending", "tumbled", "toppled", "slid", "sat"}) | HOMES
#: determiners of an object already known to be there ("the", "my"): see `Fact.definite`
DEFINITE = frozenset({"the", "my", "our", "your", "his", "her", "its", "their", "this", "that", "these",
                      "those"})
#: prepositions of where a thing is now (not where it goes: "into", "onto", "to")
WHERE_PREPS = frozenset({"on", "in", "inside", "by", "near", "under"})
INDEFINITE = frozenset({"a", "an", "any", "every", "each", "some", "no"})
ELSEWHERE = ("anywhere else", "elsewhere", "somewhere else", "any other place", "not there",
             # a thing that has left its place on its own: "if it has wandered off, bring it back"
             "wandered off", "wandered away", "walked off", "walked away", "gone astray", "strayed")
#: verbs whose "from" names a source ("fill the bowl from the bag"), not a location
#: verb particles between an object and its place ("rolled out onto the floor")
PARTICLES = frozenset({"out", "down", "over", "around", "away", "about"})
SOURCE_VERBS = frozenset({"fill", "refill", "pour", "top", "water", "feed",
                          # a past act of taking: where the thing was, not where it is ("borrowed
                          # the headphones from the hall cupboard?", "took a towel from the shelf")
                          "borrowed", "took", "taken", "fetched", "grabbed", "removed", "collected"})
#: the forms of "use" and what may stand before them when someone's using a thing is said
#: (`_Reader._used`: "if you didn't use it", "have you used the mug?")
USING = frozenset({"used", "use", "using"})
USERS = frozenset({"you", "i", "we", "they", "someone", "somebody", "not", "never", "have", "has", "had", "been"})
#: verbs that say a thing has come to be there ("if a parcel has arrived")
ARRIVALS = frozenset({"arrived", "come", "turned", "appeared", "shown", "showed", "been", "behind"})
#: words that say an object is absent: "the roll is missing"
ABSENT = frozenset({"missing", "absent", "gone", "lacking", "unavailable"})
#: the particles that make "gone" a phrasal verb, no absence: "if it has gone out" (a candle, a
#: fire: no longer burning), "if the heater's gone off", "the milk has gone off"
GONE_PARTICLES = frozenset({"out", "off"})


@dataclass(frozen=True)
class Fact:
    """An atomic condition on the initial state found in the text."""

    subject: str
    condition: str  # positive form, condition language
    kind: str  # "location" | "state" | "attr" | "exists"
    key: str = ""  # attribute key, state flag, or location target
    negated: bool = False
    goal: bool = False  # where something must end up (not a condition on the initial state)
    modifier: bool = False  # described as a noun modifier ("a toy lying on the floor")
    #: an attribute the catalog has no domain for, read from the wording ("a ripe one", "it is a
    #: bill"); kept only when the text contrasts it (see `_contrasted`)
    derived: bool = False
    #: said of a definite object ("the tablet is lying on the chair"): in a plain statement a
    #: fact the environment keeps, not an uncertain factor
    definite: bool = False
    #: where the thing is kept or lives (`HOMES`): its norm, never a situation to ask about
    home: bool = False
    #: the source of an instruction of taking ("take a spare fuse from the drawer"): the
    #: instruction presupposes the thing is there, so in a plain instruction (no condition or
    #: doubt governs it) it is a stated fact, not a factor
    presupposed: bool = False


@dataclass(frozen=True)
class Clause:
    text: str
    sentence: int
    cue: str | None
    role: str  # "condition" | "consequence" | "else" | "uncertain" | "statement" | "scene"
    facts: tuple[Fact, ...]
    mentions: tuple[str, ...]


@dataclass
class Factor:
    id: str
    subject: str
    question: str
    values: dict[str, str]
    kind: str
    order: int
    sentence: int = -1
    clause: int = -1
    consequences: list[str] = field(default_factory=list)
    roles: set[str] = field(default_factory=set)
    #: for each consequence, whether it holds when the factor's condition does ("if the lamp is
    #: on, switch it off") or when it does not ("if the lamp is off, ...", "unless ...", an
    #: "otherwise" after the condition): the branch `nest` plans it under
    under: list[bool] = field(default_factory=list)
    #: (factor id, values) under which this factor is asked: the conditions it was stated under
    context: list[tuple[str, frozenset[str]]] = field(default_factory=list)
    raw_context: list[tuple[tuple[str, str, str], bool, str]] = field(default_factory=list, repr=False)
    #: every (sentence, clause) where the factor's condition is stated, not only the first
    places: set[tuple[int, int]] = field(default_factory=set, repr=False)
    #: a location whose "no" leaves the thing out of the task ("if the toy is on the floor"), not
    #: one the task moves it to ("unless it is already in the box": its "no" is the main case)
    stops: bool = True


def _allowed(dep: Factor, negated: bool, value: str) -> frozenset[str]:
    """Values of `dep` under which a condition `[not] dep = value` holds."""
    if dep.kind in ("state", "exists") or (dep.kind == "location" and set(dep.values) == {"yes", "no"}):
        return frozenset({"no" if negated else "yes"})
    if value in dep.values:
        return frozenset(set(dep.values) - {value}) if negated else frozenset({value})
    return frozenset(dep.values)


@dataclass
class TaskAnalysis:
    sentences: list[str]
    clauses: list[Clause]
    factors: list[Factor]
    groups: list[list[str]]  # factor ids per independent subtask
    group_roles: list[set[str]]
    other_roles: set[str]


#: "if we still have one", "if we don't have a spare": the household owns the object, or not
_WE_HAVE = re.compile(r"\b(?:we|you|i)(?: still| also| even)?(?: do| does| did)?(?: not)? (?:have|has)(?: not)?(?: still| also)?"
                      r"(?: got)?"
                      r"(?: (?:a|an|any|some))?$")
_ASIDE = re.compile(r"\s*\([^()]*\)\W*$")

#: a condition of coming upon a thing it names ("if you find a wallet", "should we come across
#: my headphones in here", "if you happen to spot a watch anywhere in the office"): an agent
#: first, then a verb of discovery (`DISCOVERY`); said with no place or state of the thing, it asks
#: whether the thing is there at all
_FIND_NAMED = re.compile(r"^\W*(?:you|we|i)\s+(?:(?:ever|do|does|did|should|can|could|happen\s+to|manage\s+to|still)\s+)*"
                         r"(?:find|spot|see|notice|discover|come\s+(?:across|upon)|stumble\s+(?:across|upon|on))\s+"
                         r"(?!it\b|them\b|one\b|ones\b|any\b|some\b|that\b|this\b|out\b|time\b)")
#: after a place put first, an agent who may come upon what follows ("On the floor we may find the
#: game controller", "In the sink you will probably see a mug"): the things found may be at that
#: place, as after "On the bed there may be" (a finding said outright, "you will find the lamp",
#: is left to the placement reader)
_FRONTED_FINDING = re.compile(r"(?:you|we|i)\s+(?:(?:can|will|would|should|also|still|often|sometimes)\s+)*"
                              r"(?:may|might|could|probably|possibly|perhaps)\s+(?:(?:also|still|well|even)\s+)*"
                              r"(?:find|spot|see|notice|discover)\b")
#: a trailing ellipsis ("... if it's dirty straight into the washing machine...")
_TRAILING = ("...", "\u2026")
#: "it is the X", "that's the X": a clause that says which thing was spoken of
_IDENTIFYING = (["it", "is"], ["that", "is"], ["this", "is"], ["it", "was"])
#: a guess before it ("I think it's the standing lamp", "probably it's the red one")
_HEDGE_LEADS = frozenset({"i", "think", "guess", "reckon", "believe", "suppose", "probably", "maybe", "pretty",
                          "sure", "am"})
#: the verb and adverbs between "she" and a state ("if she be still burning", "if she's on")
_SHE_BE = frozenset({"is", "be", "was", "still", "already", "left", "now"})
#: states a thing can be in and a person, in these texts, is not said to be (not "dirty", "wet")
_MACHINE_STATES = frozenset({"toggled_on", "open", "filled"})
#: a dash between words, set off by spaces, that ends a clause as a comma does
_DASHES = frozenset({"-", "\u2013", "\u2014", "--"})

#: a verb and its particle that together say a state ("the drawer may be pulled out" is open):
#: read as the state word (`STATE_WORDS`) before the clause is read
PHRASAL_STATES = tuple((re.compile(rf"\b(?:{verbs}) (?:{particles})\b"), state) for verbs, particles, state in (
    ("pulled|drawn|slid", "out|open", "open"),
    ("pushed|slid", "in|shut|back in", "shut"),
    # a machine "shut down" or "powered down/off" is off, not shut like a door
    ("shut|shuts|shutting|powered|powers|power", "down", "off"),
    ("powered|powers|power", "off", "off"),
    # a covering (curtains, drapes, blinds) is drawn across to shut it and drawn back to open it
    ("drawn", "shut|closed|across|together", "shut"),
    ("drawn|pulled", "back|apart|aside", "open"),
))
#: a participle whose sense as a state is fixed only as a clause's predicate, after a form of
#: "be" (or "still", "already", "left", a question's subject) and before the clause ends: "unless
#: they are already drawn, close them", "are they drawn?" say the covering is drawn across (shut),
#: where "the plan is drawn up", "a map drawn on the pad", "drawn to the light" say nothing of it
PREDICATE_STATES = tuple(
    (re.compile("(?:" + "|".join(rf"(?<=\b{lead} )" for lead in (
        "is", "are", "was", "were", "be", "been", "still", "already", "left", "kept", "stay", "stays", "remain",
        "remains", "it", "they")) + rf"){word}(?=\s*(?:[^\w\s]|$)| (?:and|or|but|at|during|before|after|when|"
        rf"while|overnight|all|again|now|then|so|because|if|unless)\b)"), state)
    for word, state in (("drawn", "shut"),))


#: a general noun for a machine after its determiner (`_Reader.machine_again`)
_EPITHET = re.compile(rf"\b(the|this|that) ({'|'.join(sorted(MACHINE_EPITHETS))})\b(?!['-])")

#: what a container is filled with: "there is still wine in it" and "there's still juice left in
#: the bottle" say the bottle is full, "there is milk left" (of the carton spoken of) and "the
#: carton still has milk in it" that the carton is, not that there is a wine bottle or a milk
#: carton ("wine", "milk" also name them); read as the state before the clause is (`_contents`)
LIQUIDS = ("water", "wine", "milk", "juice", "coffee", "tea", "beer", "soup", "oil", "soda", "liquid", "drink")
_LIQUID = rf"(?:{'|'.join(LIQUIDS)})"
#: the amount words between "there is" and the liquid ("there is still some milk")
_AMOUNT = r"(?:still |some |any |already |now |even |a little |a bit of |a drop of )*"
#: where a clause ends: a mark or the text's end (a bare "in" there, "unless it's got water in, ...",
#: has the thing spoken of hold it)
_IN_END = r"(?=\s*(?:[,;:.!?)]|$))"
#: a short definite noun phrase ("the kettle", "your watering can")
_DEFINITE_NP = r"(?:the|your|my|our|this|that) [a-z]+(?: [a-z]+)?"
#: the container a "there is ... in" names: "it", "them" or a short definite noun phrase ending its clause
_HELD_IN = rf"(?P<np>it|them|{_DEFINITE_NP}{_IN_END})"
#: "in it", "in them", or "in" ending its clause: its subject holds the liquid
_IN_IT = rf"(?:in|inside)(?: (?:it|them)\b|{_IN_END})"
_CONTENTS = re.compile(rf"\bthere (?:is|are) {_AMOUNT}(?P<no>no |not any )?{_LIQUID}(?: left)? (?:in|inside) {_HELD_IN}")
#: "when there is milk left" (no container named): the liquid's own container is full, as "the
#: milk" names the carton ("if there is milk left" asks of the carton, not of the kettle spoken
#: of before); "left" is needed, as "if there is milk" asks whether there is any milk at all
_LEFT = re.compile(rf"\bthere (?:is|are) {_AMOUNT}(?P<no>no |not any )?(?P<liquid>{_LIQUID}) left\b(?! (?:in|inside|on|over)\b)")
#: "the carton still has milk in it", "if the bottle has no juice left in it": its subject holds it;
#: "have got" is the same "have" of possession, as British English says it ("unless it's got
#: water in it", "if the vase hasn't got any water in it": "not ... any" is "no")
_HAS_IN = re.compile(rf"\b(?P<has>has|have)(?P<not> not)?(?: got)? {_AMOUNT}(?P<no>no |not any |any )?"
                     rf"{_LIQUID}(?: left)? {_IN_IT}")
#: the asked forms (the twenty-seventh session): "is there still water in the kettle?", "has the
#: watering can still got water in it?", and the subject left out as notes leave it ("Still got
#: water in? Leave it.": of the thing spoken of)
_CONTENTS_ASKED = re.compile(rf"\b(?P<be>is|are) there {_AMOUNT}(?P<no>no |not any |any )?{_LIQUID}(?: left)? "
                             rf"(?:in|inside) {_HELD_IN}")
_HAS_IN_ASKED = re.compile(rf"\b(?P<has>has|have)(?P<not> not)? (?P<np>it|they|{_DEFINITE_NP}) {_AMOUNT}got "
                           rf"{_AMOUNT}(?P<no>no |not any |any )?{_LIQUID}(?: left)? {_IN_IT}")
_GOT_IN = re.compile(rf"(?:^|(?<=[.?!:;-] ))(?P<adv>(?:still |already )?)got {_AMOUNT}{_LIQUID}(?: left)? "
                     rf"(?:in|inside)(?: (?:it|them))?(?= *\?)")


#: the auxiliaries that open a question or make its tag
_AUX = r"(?:is|are|was|were|has|have|had|does|do|did|will|would|can|could|should)"
#: a question's tag, after `expand` ("it's on, isn't it?" -> "it is on, is not it?"): it asks for
#: agreement and says nothing of the clause, whatever its polarity
_QUESTION_TAG = re.compile(rf",\s*{_AUX}(?: not)? (?:it|they|he|she|there|you|we|i)(?: not)?\s*(?=\?\s*$)")
#: a negative question ("isn't the mug there?", "hasn't the bin been emptied?"): its "not" is
#: the asker's expectation, not the proposition asked, which is the positive one; a negative
#: polarity word ("isn't there any milk?", "hasn't it been washed yet?") keeps the negation
_NEGATIVE_QUESTION = re.compile(rf"^(\W*{_AUX}) not\b(?=(?:(?!\b(?:any|anything|anyone|anybody|anywhere|ever|yet)\b)"
                                rf"[^?])*\?\s*$)")


#: a tag after a statement, wherever it ends (before a vocative, a full stop or a question mark:
#: "there's one on the floor, isn't there, Maureen.", "it lives on the hook, doesn't it?")
_TAG = re.compile(rf",\s*{_AUX}(?: not)? (?:it|they|he|she|there|you|we|i)(?: not)?\s*(?=[,.?!]|$)", re.M)


def _unbiased(said: str) -> str:
    """A question's proposition without its bias: the tag dropped and a negative question's
    "not" (`_QUESTION_TAG`, `_NEGATIVE_QUESTION`); a statement is left as it is."""
    return _NEGATIVE_QUESTION.sub(r"\1", _QUESTION_TAG.sub("", said))


#: a container that has run empty ("run dry" is read so by `expand`) is empty, asked ("has it run
#: empty?", "Run empty?", its subject dropped; its perfect said is "has been empty" by then) or
#: said in the present or the past ("when it runs empty", "it's run empty" spelled "it is run")
_RUN_EMPTY_ASKED = re.compile(r"(?:\b(?:has|have|had) (?P<np>it|they) |^\W*)(?P<adv>(?:already |now |just )?)run empty\b"
                              r"(?= *\?)")
_RUN_EMPTY = re.compile(r"\b(?:(?P<be>is|are) run|runs|ran) empty\b")


#: a bracket of a few words right after a word and right before a preposition of place ("the
#: laptop (silver) on the desk", "KETTLE (JUG) ON COUNTER", "the towel (the green one) on the
#: floor", "a pillow (small, square) may be on the armchair"; its verb of being between them):
#: an attribute or another name of the thing before it (`_bracket_read_past`)
_BRACKET_BEFORE_PLACE = re.compile(r"(?<=[a-z0-9'])\s*\(([^()]{1,40})\)"
                                   r"(?=\s+(?:(?:is|are|may|might|could|be|probably|still|have|has|been|left|lying)\s+){0,3}"
                                   r"(?:on|onto|atop|upon|in|inside|into|within)\b)")
#: words that make a bracket more than an attribute: a place of its own ("(on the desk)"), a
#: condition or a time ("(if dry)", "(when you're done)"), a negation ("(not the red one)"); a
#: state word (`STATE_WORDS`: "(dirty)", "(still on)") is kept too, a state the text gives the thing
_BRACKET_CLAUSE = PREP_ON | PREP_IN | frozenset({
    "if", "unless", "when", "once", "whenever", "while", "until", "or", "not", "no", "under", "by", "at", "behind"})
#: the most words a bracket read past holds
_BRACKET_WORDS = 4


def _bracket_read_past(said: str, named: Callable[[str], bool]) -> str:
    """The text with a short bracket between a thing and its place dropped: "someone may have
    left the laptop (silver) on the desk" is "... the laptop on the desk". In any register the
    bracket says which thing is meant (a colour, "the green one", an owner) or gives it another
    name ("(jug)", "(the clicker)"); the place after it is the thing's, and a reader that stops at
    the bracket asks nothing. A bracket with a place, a condition, a time or a negation of its
    own (`_BRACKET_CLAUSE`), a state word, or more words than `_BRACKET_WORDS` is more than that,
    and kept; so is a bracket after a word that names no thing of the task (`named`: whether the
    text up to it ends with a thing's name), which glosses it ("the sufuria (pot) is on the
    stool": the bracket is the only name the reader knows)."""
    def drop(m: re.Match[str]) -> str:
        inner = re.findall(r"[a-z0-9']+", m.group(1))
        kept = set(inner) & (_BRACKET_CLAUSE | set(STATE_WORDS))
        if not inner or len(inner) > _BRACKET_WORDS or kept or not named(said[:m.start()]):
            return m.group(0)
        return ""
    return _BRACKET_BEFORE_PLACE.sub(drop, said)


#: a bracket holding a comma right after a word and right before the verb of its clause ("the dog
#: bowl (metal, on the mat, by the back door) is empty", "the laptop (work one, silver, dented lid)
#: still on?"): an aside about the thing before it (`_aside_read_past`)
_ASIDE_BEFORE_VERB = re.compile(r"(?<=[a-z0-9'])\s*\(([^()]*,[^()]*)\)"
                                r"(?=\s+(?:is|are|was|were|be|has|have|had|still|stays|remains|gets|got)\b)")


def _aside_read_past(said: str, named: Callable[[str], bool]) -> str:
    """The text with an aside between a thing and its verb dropped: its commas part the subject
    from its predicate, so the state after it would fall on a thing the aside names ("the dog bowl
    (metal, on the mat, by the back door) is empty" asks whether the bowl is empty, not the door).
    An aside with a condition or a time of its own ("(if it rang, silence it)") is a clause, and a
    bracket after a word that names no thing of the task (`named`) glosses it: both are kept."""
    def drop(m: re.Match[str]) -> str:
        inner = set(re.findall(r"[a-z']+", m.group(1).lower()))
        if inner & SUBORDINATORS or not named(said[:m.start()]):
            return m.group(0)
        return ""
    return _ASIDE_BEFORE_VERB.sub(drop, said)


#: the state a definite thing is left in by an act done to it (`_done_by_someone`): "closed the
#: laptop" leaves it closed, "emptied the bin" empty, "switched the lamp off" off
#: `DEFINITE` of one thing: the determiners before the thing an act by nobody or "over" speaks of
_SINGULAR_DEFINITE = DEFINITE - {"these", "those"}
RESULT_STATES = {"closed": "closed", "shut": "closed", "opened": "open", "emptied": "empty", "filled": "full",
                 "washed": "clean", "cleaned": "clean", "wiped": "clean", "dried": "dry",
                 "switched off": "off", "turned off": "off", "switched on": "on", "turned on": "on"}
#: people no one names, as a clause's subject: "nobody" denies the act, "someone" asserts it
_NOBODY = frozenset({"nobody", "no one", "no-one", "noone"})
_SOMEONE = frozenset({"someone", "somebody", "anyone", "anybody", "someone else", "somebody else"})
_RESULT_VERB = "|".join(sorted({v.split()[0] for v in RESULT_STATES}, key=len, reverse=True))
_DONE_BY_SOMEONE = re.compile(
    rf"\b(?P<who>{'|'.join(sorted(_NOBODY | _SOMEONE, key=len, reverse=True))})\s+(?:(?:has|have|had)\s+)?"
    rf"(?:(?:already|yet|ever)\s+)?(?P<verb>{_RESULT_VERB})\s+(?:(?P<p1>off|on)\s+)?"
    rf"(?P<np>(?:{'|'.join(sorted(_SINGULAR_DEFINITE - {'its'}))})\s+[a-z'-]+(?:\s+[a-z'-]+){{0,2}}?)(?:\s+(?P<p2>off|on))?"
    r"(?:\s+(?P<adv>yet|already|today|tonight))?(?=\s*(?:[,.;:!?)]|\s-|$))")


def _done_by_someone(said: str) -> str:
    """"if nobody closed the laptop" -> "if the laptop is not closed"; "unless someone has emptied
    the bin" -> "unless the bin is empty". An act by nobody named, said of a definite thing, asks
    the state the act leaves it in (`RESULT_STATES`): denied with "nobody" / "no one" (a double
    negation, "if nobody closed it, close it": it is open), asserted with "someone" / "anyone".
    People say it so in any register (a house rule, a rota, a text); the reader otherwise finds
    no state word after the thing. A verb with no result state ("nobody used the laptop") or a
    subject who is named ("if Sam closed it") is left as it is."""
    def state(m: re.Match[str]) -> str:
        verb = m.group("verb")
        particle = m.group("p1") or m.group("p2")
        result = RESULT_STATES.get(f"{verb} {particle}" if particle else verb)
        if result is None:
            return m.group(0)
        negation = "not " if m.group("who") in _NOBODY else ""
        return f"{m.group('np')} is {negation}{result}"
    return _DONE_BY_SOMEONE.sub(state, said)


#: "over" before a determiner: where a thing lies draped or laid on another ("the towel may be
#: over the chair", "is my coat still over the armchair?", "the scarf is draped over the bed"); not
#: a quantity or a time ("over an hour", "over 30 degrees", "over the weekend" name no thing) nor a
#: direction ("over there", "over here", no determiner)
_OVER = re.compile(rf"\bover(?=\s+(?:{'|'.join(sorted(_SINGULAR_DEFINITE))})\s)")


def _contents(said: str) -> str:
    """"there is still wine in it" -> "it is full"; "there is no water left in the jug" -> "the
    jug is empty"; "there is milk left" -> "the milk is full"; "it still has milk in it" -> "it is full";
    "has it run dry?" -> "is it empty?", "when it runs dry" -> "when it is empty" (`_CONTENTS`,
    `_LEFT`, `_HAS_IN`, `_RUN_EMPTY`)."""
    said = _RUN_EMPTY_ASKED.sub(lambda m: f"{'are they' if m.group('np') == 'they' else 'is it'} {m.group('adv')}empty",
                                said)
    said = _RUN_EMPTY.sub(lambda m: f"{m.group('be') or 'is'} empty", said)
    def state(m: re.Match[str]) -> str:
        empty = m.group("no") not in (None, "any ") or m.groupdict().get("not") is not None
        return "empty" if empty else "full"
    said = _CONTENTS_ASKED.sub(lambda m: f"{m.group('be')} {m.group('np')} {state(m)}", said)
    said = _HAS_IN_ASKED.sub(lambda m: f"{'are' if m.group('np') == 'they' else 'is'} {m.group('np')} {state(m)}", said)
    said = _GOT_IN.sub(lambda m: f"{m.group('adv')}full", said)
    said = _CONTENTS.sub(lambda m: f"{m.group('np')} {'are' if m.group('np') == 'them' else 'is'} {state(m)}", said)
    said = _LEFT.sub(lambda m: f"the {m.group('liquid')} is {state(m)}", said)
    return _HAS_IN.sub(lambda m: f"{'are' if m.group('has') == 'have' else 'is'} {state(m)}", said)


#: soil said to be on a thing (`_Reader._soiled`): a stain's name in any number ("a mark", "marks":
#: the catalog's floor stain is a "stain", a "dirty mark", a "spot") or a bare noun that names no
#: kind of the task ("whey", "grease", "sauce"); water on a thing wets it
STAIN_WORDS = frozenset({"stain", "mark", "spot"})
_SOIL = r"(?P<det>(?:any|some|no|a|an|a bit of|bits of) )?(?P<soil>[a-z]+)"
_SOILED_GROUND = rf"(?P<np>it|they|them|{_DEFINITE_NP})"
#: "has it got marks on it?", "have they got mud on them?"
_SOIL_ASKED = re.compile(rf"\b(?P<has>has|have)(?P<not> not)? {_SOILED_GROUND} (?:got )?{_SOIL} on (?:it|them)\b")
#: "it has got grease on it", "the coat has whey on it", "they have mud on them"
_SOIL_HAD = re.compile(rf"\b{_SOILED_GROUND} (?P<has>has|have)(?P<not> not)? (?:got )?{_SOIL} on (?:it|them)\b")
#: "there is a mark on it", "there are stains on the plate"
_SOIL_THERE = re.compile(rf"\bthere (?:is|are)(?P<not> not)? {_SOIL} on {_SOILED_GROUND}")
#: a question with its verb left out, opening its clause: "any mud on it?", "coffee on it?"
_SOIL_BARE = re.compile(rf"^(?P<lead>\W*){_SOIL} on (?P<np>it|them)(?= *\?)")
#: the floor and what covers it: a stain there is a floor stain, a thing of its own
_FLOORING = frozenset({"floor", "ground", "carpet", "rug"})
#: words that stand for things, not for what soils them ("there is one on the sofa", "there is
#: stuff on the table": a thing lies there, the sofa is not dirty); "anything on it (leaks, sick)"
#: of a blanket may be soil, as dev 46's nursery handover says it
_NOT_SOIL = PRONOUNS | {"stuff", "thing"}


def _plural_only(word: str) -> bool:
    """A noun with no singular, named in the plural ("scissors", "tongs", "pliers", "jeans"):
    lemminflect gives it as its own plural, so "they" may take it up as it takes up "the cups"."""
    return word.endswith("s") and not word.endswith("ss") and getInflection(word, "NNS")[:1] == (word,)


#: words of operation: said of a thing, it is switched on ("if the oven is working", "the fan is
#: still going"); `_Reader._offered` reads them as the state `OPERATION`, never as an attribute
OPERATION = "toggled_on"
OPERATION_WORDS = frozenset({"working", "operating", "functioning", "going", "running", "whirring", "humming",
                             # a light or a kettle going ("the lamp is still shining", "the kettle
                             # is whistling"): of a thing that cannot be switched on ("the floor is
                             # shining") nothing is read (`_offered`)
                             "shining", "whistling"})
#: words of a machine's being out of order in the varieties and registers of English, said as a
#: predicate ("the ceiling fan spoil already" and "the kettle is spoilt" in Singapore, Malaysian,
#: Indian and Nigerian English; "the printer's kaput", "the toaster's bust", "the drill is
#: knackered" in informal British and American English; Malay "rosak" in a Singlish or Manglish
#: chat): `_Reader._offered` reads them as `BREAKAGE`, only of a thing that switches on, since of
#: food "spoilt" is gone off and of a person "knackered" is tired, neither a broken thing
BREAKAGE = "broken"
BREAKAGE_WORDS = frozenset({"spoil", "spoils", "spoilt", "spoiled", "kaput", "bust", "knackered", "rosak"})


#: a verb that raises its subject before "to be" says what the subject is, as "is" does ("it
#: turns out to be a bill", "the jar happens to be empty", "the lamp seems to be on")
RAISING = re.compile(r"\b(?:turns? out|turned out|happens?|happened|seems?|seemed|appears?|appeared|proves?"
                     r"|proved) to be\b")


def _joined(words: list[str], a: Mention, b: Mention, commas: frozenset[int] = frozenset()) -> bool:
    """Mentions `a` and `b` are items of one list (`a book or a toy`, `cups, plates and bowls`);
    two bare names of things (no determiner) with only a comma between (`commas`: the words a
    comma stands before) are items of a terse list ("On bed maybe: book, alarm clock, phone";
    not "clean the mark, wet wipes from the table are best", two clauses run together)."""
    between = words[a.end : b.start]
    if not between:
        return a.kind == b.kind == "role" and b.start in commas and (a.start == 0 or words[a.start - 1] not in LIST_WORDS)
    return len(between) <= 3 and all(w in LIST_WORDS for w in between)


#: words that may stand between two items of one list: conjunctions and determiners, possessive
#: ones included ("a book, my alarm clock or my phone")
LIST_WORDS = frozenset({"or", "and", "a", "an", "the", "some", "any", "either", "my", "your", "our", "his",
                        "her", "their"})


def _verb_read(toks: list[tuple[str, int, int]], m: Mention) -> bool:
    """A one-word mention that is a verb in its context: a base or present form right before its
    object (no punctuation between: "a book, an alarm clock" lists two things)."""
    if m.end - m.start != 1 or m.end >= len(toks) or toks[m.end][0] not in VERB_OBJECTS \
            or toks[m.end][1] - toks[m.start][2] > 1 \
            or m.start > 0 and toks[m.start - 1][0] in ARTICLES | INDEFINITE | NEGATIONS | PLACE_PREPS | set(STATE_WORDS):
        return False  # "on the counter it must ...", "a dirty plate the ...": a noun after all
    word = toks[m.start][0]
    verbs = getAllLemmas(word).get("VERB", ())
    return bool(verbs) and (word in verbs or word.endswith("s") and word[:-1] in verbs)


def _participle(words: list[str], k: int) -> bool:
    """Word `k` is a verb's past participle after "been" or a perfect's "have" ("has been knocked
    onto the floor", "may have been shoved under the bed", "if they've blown onto the floor"): part
    of the verb group, not the end of the clause."""
    if k == 0 or words[k - 1] not in ("been", "has", "have", "had") or not words[k].endswith(("ed", "en", "wn", "ung")):
        return False
    return any(lemma != words[k] for lemma in getAllLemmas(words[k]).get("VERB", ()))


#: what fills a container: "there is water in it" says it is filled
FILLINGS = frozenset({"water", "coffee", "tea", "milk", "juice", "soup", "liquid", "fluid", "oil"})
#: the words that open a clause telling a time ("when they have gone", "once they've left",
#: "until the last of them leaves"): a plural pronoun right after one is the people the time is
#: told by (`_in_time_clause`)
_TIME_OPENERS = frozenset({"when", "whenever", "once", "after", "until", "till", "before"})
#: of `_TIME_OPENERS`, those that say *at* what time a state is asked ("Spinning when you come
#: in?", "still on once we've left?", `_before_time_clause`): the splitter's own table of them,
#: `clauses.AGENT_TIMES` (its "while" opens no time a state is asked at here); "before", "after",
#: "until" with the reader as subject more often say by when or how long ("keep it on until you
#: leave"), and cutting at them too would change what is read
_TIME_CUES = AGENT_TIMES & _TIME_OPENERS


#: `TRAILING_ADVERBIALS` as word tuples
_ADVERBIAL_WORDS = tuple(sorted((tuple(a.split()) for a in TRAILING_ADVERBIALS), key=len, reverse=True))


def _before_time_clause(words: list[str]) -> list[str]:
    """The words before a time clause whose subject is the reader or the speaker ("Spinning when
    you come in?", "still on once we've left?"): the clause says when the state is asked, not the
    state; all the words when there is none."""
    cut = next((k for k in range(1, len(words) - 1) if words[k] in _TIME_CUES and words[k + 1] in AGENTS), None)
    core = words if cut is None else words[:cut]
    # and before an adverbial of time or of the place spoken of that ends it ("the lamp: if off
    # right now", "if switched on in there": `TRAILING_ADVERBIALS`), so a state before it ends
    # the clause as its predicate
    while len(core) > 1 and (ending := next((a for a in _ADVERBIAL_WORDS if len(a) < len(core)
                                             and tuple(core[-len(a):]) == a), None)):
        core = core[:-len(ending)]
    return core


def _home_said(text: str, opens: bool) -> bool:
    """Whether a statement of a home says it of the thing itself, not of one pointed to ("there's
    one in the vanity"): no pronoun, or "it"/"they" opening its sentence (`opens`) as the subject
    of the verb of home ("It lives in the vanity, so it goes back in there": the cloth's home, as
    "The cloth lives in the vanity"). Inside a sentence ("clean it with the cloth if we still have
    one; it lives in the vanity") the pronoun may take up the clause's own object, which the
    pronoun reader does not tell apart, so no home is read there."""
    words = [w for w, _, _ in tokens(text)]
    pointing = set(words) & {"it", "they", "them", "one"}
    return not pointing or opens and words[:1] in (["it"], ["they"]) and words[1:2] != [] \
        and words[1] in HOMES and pointing <= {"it", "they"}


def _perfect_moved(words: list[str], start: int, k: int) -> bool:
    """Whether a perfect moved the thing at `start` before the "to" at `k` ("if the wind has
    thrown it to the floor", "if the cat has knocked the vase to the floor", "if it has been
    blown to the floor"): the participle of a perfect (`_participle`) right before the thing
    (past its determiners) or between it and "to". Then "to" says where the thing came to rest,
    as after a verb of falling (`FALLS`); an instruction's "take it to the shelf" stays a goal."""
    j = start - 1
    while j > 0 and words[j] in ARTICLES:
        j -= 1
    return j >= 0 and _participle(words, j) or any(_participle(words, i) for i in range(start + 1, k))


#: verbs of giving that take two objects, the receiver first ("bring the plant the can", "hand
#: the guest a towel"): the second object is the thing moved
GIVING = frozenset({"bring", "give", "hand", "pass", "fetch", "take", "send", "offer"})


def _direct_object(words: list[str], found: list[Mention], first: Mention | None) -> Mention | None:
    """The thing a clause speaks of when its first mention is the receiver of a verb of giving
    with two objects ("the helper brings the plant the watering can, filled"): the second object,
    right after the first (its determiner between), is what is carried and what a pronoun after
    it means ("filling it at the sink"); otherwise the first mention itself."""
    if first is None or first.kind != "role" or first.start < 1:
        return first
    k = first.start - 1 if words[first.start - 1] in ARTICLES else first.start
    verb = words[k - 1] if k >= 1 else ""
    if not GIVING & set(getAllLemmas(verb).get("VERB", ())):
        return first
    second = next((m for m in found if m.kind == "role" and m.start > first.end), None)
    if second is None or second.start - first.end > 1 or words[first.end:second.start] not in ([], ["the"], ["a"],
                                                                                               ["an"], ["your"], ["my"]):
        return first
    return second


def _later_object(words: list[str], found: list[Mention], commas: frozenset[int]) -> Mention | None:
    """The object of a participle clause after a comma that ends a clause ("mist them with the
    mister, filling the mister at the sink first if it is empty"): what the clause spoke of last,
    so a pronoun after it (in a condition put after it) means that thing, not the clause's first
    mention. None without such a clause."""
    for c in sorted(commas, reverse=True):
        if c >= len(words) or not words[c].endswith("ing") or words[c] not in _verb_forms(words[c]):
            continue
        obj = next((m for m in found if m.kind == "role" and c < m.start <= c + 2
                    and all(w in ARTICLES for w in words[c + 1:m.start])), None)
        if obj is not None:
            return obj
    return None


#: the words that open a clause of result after its reason ("We need light at the desk, so the desk
#: lamp should be on", "The stove remains in use; therefore the pot must be clean")
RESULT_CUES = frozenset({"so", "therefore", "hence", "thus", "consequently"})


def _result_subject(words: list[str], found: list[Mention], first: Mention | None) -> Mention | None:
    """The thing a sentence speaks of when a clause of result follows its reason ("We need light at
    the desk, so the desk lamp should be on. If it's off, ...", "grandma sleeps on the sofa tonight,
    so the blanket has to be clean. if it's dirty, ..."): the reason says why, the result says what
    must be so of its subject, and a pronoun after it means that subject, not the reason's first
    thing; otherwise `first`. Only a result whose subject is a thing named right after the cue
    (determiners between) and followed by its predicate; "so" before an instruction ("so bring it
    to the sink"), a condition ("so if it's wet"), a degree ("so dirty") or an inversion ("and so is
    the mug") opens no such clause."""
    if first is None or first.kind not in ("role", "floor"):
        return first
    for k in (k for k, w in enumerate(words) if w in RESULT_CUES and k > first.start):
        subject = next((m for m in found if m.kind == "role" and m.start > k), None)
        if subject is not None and all(w in ARTICLES for w in words[k + 1:subject.start]) \
                and subject.end < len(words) and (words[subject.end] in _PREDICATE_OPENERS
                                                  or words[subject.end] in CLAUSE_WORDS):
            return subject
    return first


#: prepositions of a fronted place, a covering verb's "across" and "over" included
_FRONT_PREPS = frozenset({"on", "in", "inside", "upon", "atop", "across", "over"})
#: the words that tie a second place to a fronted place ("on the mantelpiece above the fireplace",
#: "on the shelf next to the window", "in the drawer of the desk"): it says where the place is
_PLACE_MODIFIERS = frozenset({"above", "below", "beneath", "beside", "behind", "under", "near", "over", "by",
                              "next", "to", "of", "at", "in", "on", "inside", "front", "opposite"})


def _fronted_thing(words: list[str], found: list[Mention], first: Mention | None) -> Mention | None:
    """The thing a clause speaks of when it opens with a place (locative inversion: "On the utility
    shelf lies the flashlight", "draped across the sofa, the blanket", "On the floor we may find the
    game controller"): the first thing named after the place and not itself a place, so a pronoun
    after it means that thing, not the place; otherwise `first`. A thing tied to the place by a
    preposition of its own ("On the mantelpiece above the fireplace sits the candle", "On the bench
    by the back door") says where the place is: it is no more the thing than the place is."""
    if first is None or first.kind not in ("role", "floor"):
        return first
    lead = [w for w in words[:first.start] if w not in FRONT_LEADS and w not in ARTICLES]
    # "On the mantelpiece above the fireplace sits the candle" with no role for the mantelpiece
    # (a part the catalog has no kind for, `lexicon.PART_TIES`): the place is the fireplace's part
    tied = len(lead) == 3 and lead[0] in _FRONT_PREPS and lead[1].isalpha() and lead[2] in PART_TIES
    if not tied and (not lead or lead[-1] not in _FRONT_PREPS or len(lead) > 2
                     or len(lead) == 2 and not _a_participle(lead[0])):
        return first
    end = first.end
    for m in (m for m in found if m.kind == "role" and m.start >= first.end):
        between = [w for w in words[end:m.start] if w not in ARTICLES]
        if between and between[0] in _PLACE_MODIFIERS and len(between) <= 3 \
                and not any(w in FINITE_VERBS or not w.isalpha() for w in between):
            # "On the mantelpiece above the fireplace sits the candle": a thing named after the
            # place's own preposition says where the place is; it is part of the place, not the thing
            end = m.end
        elif not _placed(words, m):
            return m
    return first


def _determines(words: list[str], i: int, m: Mention) -> bool:
    """Whether the word at `i` ("her", "his") is the determiner of the mention `m`: right before it,
    or with only modifiers between, words lemminflect lists as adjectives or nouns and as no verb
    ("her doll", "her denim jacket", "his old coat"; not "put her on the bed")."""
    between = words[i + 1:m.start]
    return 0 <= len(between) <= 2 and all(
        (lemmas := getAllLemmas(w)) and not lemmas.get("VERB") and (lemmas.get("ADJ") or lemmas.get("NOUN"))
        for w in between)


def _modified_determiner(words: list[str], start: int) -> str:
    """`determiner`, reading through one noun modifier that is also a verb's form ("the work
    boots", "my tea cup", "the wash bag"): `determiner` takes such a word for the determiner, as
    it would a verb ("put the ..."), so a definite thing named with its place ("Inspect the work
    boots on the boot rack") read as a thing described by its place, an uncertain factor. A
    participle or a state word there ("the drying rack", "the folded towel", "the dirty mug") is
    still no modifier of this kind (as the placement reader's `_the_before`)."""
    article = determiner(words, start)
    if start > 1 and article == words[start - 1] and words[start - 2] in DEFINITE and article.isalpha() \
            and article not in ARTICLES | DEFINITE | STATE_WORDS.keys() and not article.endswith(("ing", "ed")) \
            and getAllLemmas(article).get("NOUN"):
        return words[start - 2]
    return article


def _habit_of_state(said: str) -> bool:
    """Whether a statement is a habit of its subject's state said after the subject's place: a
    definite or bare singular subject with a place ("the TV on the TV stand", "printer on desk"),
    then, with or without "is", an adverb of frequency and a participle of leaving or switching
    ("is frequently left running", "often left on"), and no place after it. A habit of place ("the
    mug often ends up on the desk", "the laptop is often left on the desk") or a generic subject
    ("printers on the desk are often left on", "a printer on ...") is none: there the place is
    what may or may not be so."""
    words = re.findall(r"[a-z']+", said.lower())  # (as written: `tokens` makes "sometimes" "sometime")
    h = next((k for k, w in enumerate(words) if w in FREQUENCY), None)
    if h is None or h < 3 or words[0] in INDEFINITE or words[h - 1] in ("are", "were"):
        return False
    before, after = words[:h], words[h + 1:]
    if not set(before) & (PREP_ON | PREP_IN) or after[:1] not in ([w] for w in LEFT_PASSIVES):
        return False
    place_after = any(w in PREP_ON | PREP_IN and after[k + 1:k + 2] and (after[k + 1] in ARTICLES | DEFINITE)
                      for k, w in enumerate(after))
    return not place_after


def _a_participle(word: str) -> bool:
    """Whether `word` is a participle of some verb (lemminflect): "draped", "lying", "spread"."""
    return any(word in getInflection(lemma, tag) for lemma in getAllLemmas(word).get("VERB", ())
               for tag in ("VBN", "VBG"))


def _verb_forms(word: str) -> set[str]:
    """The -ing forms of `word`'s verb lemmas (lemminflect): "filling" is a form of "fill"."""
    return {f for lemma in getAllLemmas(word).get("VERB", ()) for f in getInflection(lemma, "VBG")}


def _placed(words: list[str], m: Mention) -> bool:
    """The mention names a place or a goal: a preposition stands before it ("on the table",
    "from the big dresser"); not one with no object of its own ("a towel inside and the dryer
    has stopped")."""
    return _prep_within(words, m, PLACE_PREPS)


def _beside_its_head(words: list[str], m: Mention, mentions: list[Mention]) -> bool:
    """The mention is the place of a "next to" / "against" (`BESIDE_PREPS`) right after a thing's
    name, its head ("the mug next to the kettle"); further on, as in an aside, it is not, and a
    state said after it is carried as before ("the lamp in the hall (by the door, next to the
    coats) is on")."""
    return _prep_within(words, m, BESIDE_PREPS) and any(
        x.kind == "role" and m.start - 4 <= x.end <= m.start for x in mentions)


def _prep_within(words: list[str], m: Mention, preps: frozenset[str] | set[str]) -> bool:
    """One of `preps` within three words before the mention, and not one with no object of its
    own, right before "and" / "but" ("a towel inside and the dryer has stopped")."""
    before = words[max(0, m.start - 3) : m.start]
    return any(w in preps and before[i + 1:i + 2] not in (["and"], ["but"]) for i, w in enumerate(before))


#: the words that open a noun phrase meaning every thing of its kind the text names ("any drawer
#: that is open", "each cup", "every towel", "whichever box", "both drawers", "all (of) the
#: drawers"): a condition on it is asked of each of them (`_Reader._recent_first`)
QUANTIFIERS = frozenset({"any", "each", "every", "whichever", "both", "all"})
_QUANTIFIER_GAP = frozenset({"the", "of", "these", "those", "two", "three", "four", "your", "my", "our"})


def _quantified(words: list[str], start: int) -> bool:
    """Whether a quantifier (`QUANTIFIERS`) opens the noun phrase whose head starts at `start`,
    with only articles, "of", a count or a state word between ("all of the drawers", "both the
    cups", "every open drawer")."""
    i = start - 1
    while i >= 0 and (words[i] in _QUANTIFIER_GAP or words[i] in STATE_WORDS):
        i -= 1
    return i >= 0 and words[i] in QUANTIFIERS


def _negation(word: str) -> bool:
    return word in NEGATIONS


#: The state words of languages English is often mixed with in writing (those of `NATIVE_IF`, and
#: Portuguese), as their English state word (`STATE_WORDS`): read only in a condition in good part
#: of another language (`_Reader.code_switched`), where the English words the clause carries
#: say what is asked and the other language's adjective may be all there is ("Agar ganda hai
#: toh ...", "wenn sie noch an ist", "si está sucio"). Words that are as likely a conjunction,
#: preposition or noun there (Hindi "band", German "auf", "zu") are left out.
NATIVE_STATES = {
    # Hindi-Urdu, romanised
    "ganda": "dirty", "gandi": "dirty", "gande": "dirty", "saaf": "clean", "khaali": "empty", "khali": "empty",
    "bhara": "full", "bhari": "full", "geela": "wet", "gila": "wet", "sukha": "dry", "khula": "open", "khuli": "open",
    # German
    "an": "on", "aus": "off", "offen": "open", "geschlossen": "closed", "schmutzig": "dirty", "dreckig": "dirty",
    "sauber": "clean", "leer": "empty", "voll": "full", "nass": "wet", "trocken": "dry",
    # Spanish
    "sucio": "dirty", "sucia": "dirty", "limpio": "clean", "limpia": "clean", "vacio": "empty", "vacia": "empty",
    "lleno": "full", "llena": "full", "mojado": "wet", "mojada": "wet", "seco": "dry", "seca": "dry",
    "abierto": "open", "abierta": "open", "cerrado": "closed", "cerrada": "closed", "prendido": "on",
    "encendido": "on", "apagado": "off",
    # Portuguese
    "sujo": "dirty", "suja": "dirty", "limpo": "clean", "vazio": "empty", "cheio": "full", "molhado": "wet",
    "aberto": "open", "fechado": "closed", "ligado": "on", "desligado": "off",
    # Tagalog, Malay and Indonesian
    "marumi": "dirty", "malinis": "clean", "basa": "wet", "tuyo": "dry", "sarado": "closed",
    "kotor": "dirty", "bersih": "clean", "basah": "wet", "kering": "dry", "kosong": "empty", "penuh": "full",
    "tutup": "closed",
}


def _native_state(words: list[str], k: int) -> str | None:
    """The English state word (`NATIVE_STATES`) another language's word at `k` is, when it is one
    there: a word of no English (`sentences.foreign`), or one English has too ("an") only where
    the word after it is also of no English or none follows ("noch an ist": not "an apple")."""
    english = NATIVE_STATES.get(words[k])
    if english is None or not foreign(words[k]) and k + 1 < len(words) and not foreign(words[k + 1]):
        return None
    return english


#: what a clause that is only a place may hold besides its place: articles, a norm or frequency
#: adverb, "usually" ("On the TV stand, usually.")
_BARE_PLACE_WORDS = ARTICLES | NORM_ADVERBS | FREQUENCY | {"just", "right", "back", "over", "there"}


#: adverbs that may lead a verbless goal (`_bare_place`)
_GOING_LEADS = frozenset({"straight", "right", "directly", "back", "then", "just"})
#: every word a bare place may hold besides its things' names (`_bare_place`), built once
_BARE_PLACE_ALL = _BARE_PLACE_WORDS | PLACE_PREPS | _GOING_LEADS


def _bare_place(words: list[str], found: list[Mention]) -> bool:
    """Whether the clause is a place and nothing else, opened by its preposition, with no verb or
    other thing ("Where does it live? On the TV stand.", "Where's the remote? In the drawer,
    normally."): the answer to where the thing spoken of is. Its place is no new topic: a later
    "it" ("If it's lying on the floor, ...") is still the thing, not the TV stand."""
    covered = {k for m in found for k in range(m.start, m.end)}
    # (an adverb of going may lead the place: "Dirty? Straight in the laundry basket.", "Back in
    # the bucket", "Right into the washing machine": still the thing's goal, no new topic)
    lead = next((k for k, w in enumerate(words) if w not in _GOING_LEADS), len(words))
    return lead < len(words) and words[lead] in PLACE_PREPS and any(m.kind == "role" for m in found) and all(
        m.kind != "pronoun" for m in found) and all(
        k in covered or w in _BARE_PLACE_ALL for k, w in enumerate(words))


#: what may open an instruction before its verb ("Then just put back on the counter")
_INSTRUCTION_LEADS = frozenset({"then", "just", "please", "so", "and"})
#: the subjects of a report of one's own or another's move ("I have put on the chair") and the
#: verbs such a report uses, by their lemma (`_objectless_move`)
_REPORTERS = frozenset({"i", "we", "he", "she", "they"})
_REPORTED_MOVES = ACTIONS | {"keep"}
#: whom a move is done for, after its place ("put on the chair for you")
_BENEFICIARIES = frozenset({"you", "me", "him", "her", "us", "them"})


def _objectless_move(words: list[str], found: list[Mention]) -> bool:
    """Whether the clause is an instruction of moving with its object left out, then only its
    place ("Is it dirty? Then put on the trolley.", "Dirty? Take to the sink.", "put back on the
    counter"), or someone's report of such a move ("Your gamchha - the towel - I have put on the
    chair", "The scarf: we left on the sofa"): it moves the thing spoken of, so, as with a bare
    place (`_bare_place`), its place is no new topic and a later "if it is clean" still speaks of
    that thing."""
    k = next((i for i, w in enumerate(words) if w not in _INSTRUCTION_LEADS), len(words))
    if k < len(words) and words[k] in _REPORTERS:
        k += 1 + (words[k + 1:k + 2] in (["have"], ["has"], ["had"]))
        if k >= len(words) or not set(getAllLemmas(words[k]).get("VERB", ())) & _REPORTED_MOVES:
            return False
    elif k >= len(words) or words[k] not in ACTIONS:
        return False
    k += 1 + (words[k + 1:k + 2] == ["back"])
    # (whom it is done for follows the place and leaves it bare: "put on the chair for you")
    end = len(words) - 2 if words[-2:-1] == ["for"] and words[-1] in _BENEFICIARIES else len(words)
    return _bare_place(words[k:end], [replace(m, start=m.start - k, end=m.end - k) for m in found if m.start >= k]) \
        and all(m.start >= k for m in found)


def _participle_place(words: list[str], found: list[Mention]) -> bool:
    """Whether the clause is a bare participle of a result or of resting, its subject left out,
    then its place ("b) My cup. Left on the desk, next to the scales, as ever.", "Kettle. Sitting
    on the stove, as usual.", "Torch. Kept on the shelf by the door."): the terse item says where
    the thing its heading named is (`placement._headed_participle`), so, as with a bare place
    (`_bare_place`), the place is no new topic and a later "If it's dirty" still speaks of the
    thing. A participle with an object of its own ("Left the mug on the desk") is none."""
    return len(words) > 2 and (words[0] in RESULT or words[0] in STATIVE and words[0].endswith("ing")) \
        and words[1] in PLACE_PREPS and bool(found) and all(m.kind == "role" and m.start > 1 for m in found)


#: the words that may stand between "no" and the thing said to be absent ("no clean sponge")
_ABSENT_GAP = 2


def _absent_only(words: list[str], found: list[Mention]) -> bool:
    """Whether the clause says one thing is absent and speaks of nothing else ("No sponge?", "If
    there's no sponge", "we have no clean cloth left"): a thing said not to be there is no topic a
    later "it" takes up ("No sponge? Then wipe it out with a paper towel" wipes the bowl spoken of
    before). A thing missing from a place ("If there is no lid on the pot, put it on") names the
    place too and sets the topic as before."""
    things = [m for m in found if m.kind in ("role", "floor", "room", "pronoun")]
    return len(things) == 1 and things[0].kind == "role" and "no" in words[
        max(0, things[0].start - 1 - _ABSENT_GAP):things[0].start]


#: the state words that are also particles of place or of a phrasal verb ("on the table", "off
#: the shelf", "out of the box"), and those of them that are a state where nothing follows them
#: (`_stranded`); a stranded "out" stays a place ("the mug. If out, put it away": left out)
PARTICLE_STATES = frozenset({"on", "off", "out"})
STRANDED_STATES = frozenset({"on", "off"})


#: adverbs of degree before a state word ("wide open", "very dirty", "completely empty", "soaking
#: wet", "bone dry", "half open"): they grade the state and leave it the state it is
DEGREE = frozenset({"very", "really", "quite", "rather", "so", "completely", "totally", "fully", "entirely",
                    "wide", "half", "partly", "partially", "slightly", "somewhat", "extremely", "pretty",
                    "super", "soaking", "sopping", "bone", "properly", "absolutely", "thoroughly"})


def _graded(words: list[str], k: int) -> bool:
    """Whether the word at `k` is an adverb of degree (`DEGREE`) whose run of degree words ends in
    a state word other than a particle ("wide open", "really very dirty"; not "so on the shelf",
    nor "pretty" before a noun): the state after it is read as if the adverb were not there."""
    j = k
    while j < len(words) and words[j] in DEGREE:
        j += 1
    return j > k and j < len(words) and words[j] in STATE_WORDS and words[j] not in PARTICLE_STATES


#: a word after "on" or "off" with no article that makes it a place, not a state: "the box with
#: the blanket on top", "put it on the cabinet, on top", "the towel has slid off top" ("on top
#: of", "on the top" are places by their "of" or article too)
PLACE_AFTER_ON = frozenset({"top"})


def _stranded(words: list[str], k: int) -> bool:
    """Whether the particle at `k` (`STRANDED_STATES`) ends its clause, with no object after it:
    then it is the predicate of an elided "it is" ("Heater: if on, switch it off", "The lamp - if
    still on -> off"), not a preposition ("if on the floor", "when off the hook")."""
    return words[k] in STRANDED_STATES and k == len(words) - 1

class _Reader:
    """Extracts facts clause by clause, remembering topics for pronouns."""

    def __init__(self, lex: Lexicon, capable: Mapping[str, frozenset[str]] | None = None,
                 kinds: Mapping[str, Category] | None = None) -> None:
        self.lex = lex
        #: role -> the state flags its kind can take (`FITTED`), from the catalog
        self.capable = dict(capable or {})
        #: role -> its catalog category, to tell a placement the scene can hold from a misreading
        self.kinds = dict(kinds or {})
        self.topic: tuple[str, ...] = ()
        self.topic_kind = "role"
        self.recent: list[str] = []
        self.last_location: dict[str, Fact] = {}
        #: the last goal location and the last state spoken of ("put the pan on the stove",
        #: "switch the toaster on"), for "unless it is already there / on"
        self.last_goal: Fact | None = None
        #: every goal location of the last clause that had one (one per thing after
        #: "respectively"), for "unless they are already there"
        self.last_goals: list[Fact] = []
        #: where each thing is kept or lives, as the text said (`HOMES`): where "put it back" goes
        self.homes: dict[str, Fact] = {}
        #: places asked by "unless it's already there" (`_already`): a home does not settle them
        self.asked_already: set[str] = set()
        #: placements said, then asked by a condition pointing back with "there" ("There's a plate
        #: on the counter ... no plate there at all?", `_there_named`) or naming them again
        #: (`_asked_again`): no statement settles them
        self.doubted: set[str] = set()
        self.last_state: dict[str, Fact] = {}
        #: the thing last spoken of, not a place it goes to ("Bath towel on the floor? Wet: into
        #: the basket. Dry: ..."): what a heading without a subject is said of
        self.heading_topic: tuple[str, ...] = ()
        #: roles last named in the plural ("the wet wipes"), for "they" / "them"
        self.plural: set[str] = set()
        #: whether the plural last named is people ("Families like it left going while they sit
        #: with him. Once they've gone, ..."): a plural noun of persons (`PEOPLE_NOUNS`) after
        #: the last thing named in the plural, for `_time_people`
        self.people_last = False
        #: role -> whether the last pronoun that took it up was plural ("them", not "it"): a topic
        #: named in the plural and still taken up so is none an "it" speaks of
        self.plural_ref: dict[str, bool] = {}
        #: the clause before named a thing's part (`PARTS` in the plural: "Potted plant. Check the
        #: leaves."): a "they" after it takes up the part, which is its thing's, not a thing named
        #: in the plural before it
        self.parts_last = False
        #: part word -> the thing it was last named as a part of ("the plant's soil", "the lid of
        #: the kettle"): a later bare "if the soil is dry" / "Soil dry ->" is said of that thing,
        #: not of the topic of the clauses between (`_read_heading` too)
        self.part_of: dict[str, tuple[str, ...]] = {}
        #: the clause read starts with the reader's own "it" ("dry:" read as "it is dry", "-> on
        #: the rack" as "it goes on the rack"): the topic it set, whatever its number
        self.own_it = False
        #: the clause read is a time clause cut from its main clause, its opener the cue ("Is the
        #: lamp still on | when they have gone?"): its first word is the time clause's subject
        self.timed = False
        #: the clause read is a condition that opens its sentence (`mentions`' "one")
        self.opening = False
        #: the last clause joined things with "and" ("the pillow ... and the toy ..."): "they" is them
        self.coordinated = False
        #: the words of the clause being read that a comma stands before (`_joined`)
        self.commas: frozenset[int] = frozenset()
        self.dashes: frozenset[int] = frozenset()
        #: the words of the clause being read that a hyphen joins to the word before ("the
        #: lost-property cart"): a hyphenated modifier counts as one word between a preposition
        #: and its place (`_location`)
        self.hyphens: frozenset[int] = frozenset()
        #: the words of the clause being read where a thing's name starts (`_state`)
        self.starts: frozenset[int] = frozenset()
        #: the tokens of the clause read written in the plural ("mugs"): an ambiguous name so
        #: written means every thing it may name (`_recent_first`)
        self.plural_at: frozenset[int] = frozenset()
        #: the members of the group the sentence read takes up as a whole (`PLURAL_REFERENCE`,
        #: `_members`): what its "they" / "them" means when the topic is a thing outside it
        self.group: tuple[str, ...] = ()

    def _gone_thing(self, m: Mention) -> tuple[str, ...]:
        """What a pronoun says has gone ("pop it in the fridge and close the door. Gone? She's
        been."): the thing carried about that the last instruction put somewhere, when the
        pronoun's own referent is that place, a piece of furniture or an appliance (the fridge,
        whose door was closed last), which stays where it is. A pronoun that points to such a
        thing with no such instruction before ("The old fridge was collected; if it's gone, ...")
        keeps its referent."""
        goal = self.last_goal
        if m.kind != "pronoun" or goal is None or set(m.roles) != {goal.key} or any(self._carried(r) for r in m.roles) \
                or not self._carried(goal.subject):
            return m.roles
        return (goal.subject,)

    def _carried(self, role: str) -> bool:
        """Whether the role's kind is carried about (`Category.pickable`)."""
        kind = self.kinds.get(role)
        return kind is not None and kind.pickable

    def _recent_first(self, m: Mention, words: list[str]) -> Mention:
        """An ambiguous singular mention (`the rack`) means the candidate mentioned last; one a
        quantifier opens (`any drawer that is open`, `each cup`, `both drawers`, `all the
        drawers`: `_quantified`), or written in the plural ("if the mugs are dirty" with a blue
        and a red mug), means every candidate."""
        shortened = self._shortened(m, words)
        if shortened is not None:
            return shortened
        if m.kind != "role" or len(m.roles) < 2 or _quantified(words, m.start) or m.end - 1 in self.plural_at:
            return m
        # "the drying rack ... the utility shelf ... left on the rack": a word of a thing's own
        # name shortens that name, before a word only a synonym of another's kind has ("storage rack")
        own = [r for r in m.roles if self._own_name(r, words[m.end - 1])]
        known = [r for r in self.recent if r in (own if 0 < len(own) < len(m.roles) else m.roles)]
        return Mention((known[-1],), m.start, m.end, m.kind) if known else m

    def _shortened(self, m: Mention, words: list[str]) -> Mention | None:
        """"bring the plant the watering can - if you find the can empty, fill it": a bare head
        noun said of one thing ("the can") names the thing spoken of last whose compound name ends
        in it (the watering can), when that was spoken of after every thing the word names by
        itself (a food can named earlier, "the old biscuit tin"): a speaker shortens the name just
        used. None when the word names its own thing more recently, or is no bare singular."""
        if m.kind != "role" or m.end - m.start != 1 or _quantified(words, m.start) or m.end - 1 in self.plural_at:
            return None
        head = singular(words[m.start])
        for r in reversed(self.recent):
            if r in m.roles:
                return None
            names = {r, str(self.lex.roles.get(r, {}).get("category") or "")}
            if any("_" in n and n.rsplit("_", 1)[1] == head for n in names):
                return Mention((r,), m.start, m.end, m.kind)
        return None

    def _own_name(self, role: str, word: str) -> bool:
        """Whether `word` (a noun of a mention) is a word of the role's name or of its kind's."""
        names = {role, str(self.lex.roles.get(role, {}).get("category") or "")}
        return any(singular(word) in n.split("_") or word in n.split("_") for n in names)

    def _opener(self, before: list[str]) -> str | None:
        """The furniture piece last named (in the clause, else before it) whose kind opens and
        is not carried about: what a drawer or a door said alone belongs to."""
        for role in reversed(self.recent + before):
            kind = self.kinds.get(role)
            if kind is not None and kind.openable and not kind.pickable:
                return role
        return None

    def _group_taken_up(self) -> bool:
        """Whether a plural pronoun means the group its sentence takes up (`PLURAL_REFERENCE`:
        "The cabinet has two drawers: one for forks, one for spoons. If they're open, shut them")
        rather than a singular topic outside it (the cabinet)."""
        return bool(self.group) and self.topic_kind == "role" and bool(self.topic) \
            and not self.plural & set(self.topic) and not set(self.topic) <= set(self.group)

    def _time_people(self, words: list[str], i: int, before: list[Mention]) -> bool:
        """Whether the plural pronoun at word `i`, the subject of a time clause (`_in_time`),
        is the people the time is told by, not a thing ("If the lamp is still on when they've
        gone", "unless the heater is off once they have left", "If it's still on when the last of
        them's gone"): so when nothing it could mean is plural. What it could mean is the things
        named before it in its clause (`before`), else, with none, a group its sentence takes up
        (`_group_taken_up`: plural, so never the people), else the topic and the things named
        lately. One test for both cases, a thing named in the clause or only before it, where two
        branches of `mentions` once asked them apart; the thing's absence, which "gone" would ask,
        is not read either way."""
        if words[i] not in ("they", "them") or not self._in_time(words, i):
            return False
        if before:
            return not any(r in self.plural for m in before for r in m.roles)
        if self.people_last:
            return True  # "Families like it left going ... Once they've gone": the families
        return self.topic_kind == "role" and not self._group_taken_up() and not self.plural & set(self.topic) \
            and not any(r in self.plural for r in self.recent)

    def _occasion(self, words: list[str], m: Mention) -> bool:
        """Whether mention `m` is the occasion of a time phrase that ends its clause or is set off by
        a comma ("After bath if it is wet, hang it on the rack", "after your shower, if it is
        damp", "During the show, if it falls ..."): the bath or the shower is when, not a thing the
        clause speaks of, so it becomes no topic a later "it" takes up (the towel spoken of before
        stays). A clause after the word ("after the bath is drained") is no such phrase."""
        k = m.start - 1
        while k >= 0 and words[k] in ARTICLES:
            k -= 1
        return m.kind == "role" and k >= 0 and words[k] in OCCASION_PREPS \
            and (m.end == len(words) or m.end in self.commas)

    def mentions(self, words: list[str], toks: list[tuple[str, int, int]], surface: list[str]) -> list[Mention]:
        """The clause's mentions of things, pronouns resolved; `surface`: its words as written."""
        found = [self._recent_first(m, words) for m in self.lex.find_mentions(toks) if not _verb_read(toks, m)]
        # "the kitchen sink", "the bathroom mirror": a room's name right before a thing's names the thing
        found = [m for m in found if m.kind != "room" or not any(x.start == m.end and x.kind == "role" for x in found)]
        found = without_modifiers(found, toks, surface)
        found = [m for m in found if not self._occasion(words, m)]
        relative = words[:1] in (["which"], ["who"]) and bool(self.recent) and self.topic_kind == "role"
        if relative:
            # "... hung in the wardrobe, which is opened first if its door is closed": a clause
            # opening with a relative pronoun speaks of the thing named last, now the topic
            self.topic = (self.recent[-1],)
            found.append(Mention(self.topic, 0, 1, "pronoun"))
        covered = {i for m in found for i in range(m.start, m.end)}
        for i, w in enumerate(words):
            if i not in covered and w in OPENING_PARTS and i > 0 and words[i - 1] in ARTICLES | {"its", "their"}:
                # "Any other book goes in the nightstand drawer: open the drawer first": a drawer
                # or a door said alone is that of the furniture piece last named that opens
                owner = self._opener([r for m in found if m.end <= i for r in m.roles])
                if owner is not None:
                    found.append(Mention((owner,), i, i + 1, "role"))
                    covered.add(i)
        for i, w in enumerate(words):
            if i not in covered and w in PERSON_PRONOUNS and not any(_determines(words, i, m) for m in found):
                # "my doll sleeps on the bed but if she fell on the floor put her back": a child
                # speaks of a doll or a teddy as of a person (never "her" before a noun: "her doll",
                # "her denim jacket")
                dolls = [r for r in self.recent + [r for m in found if m.end <= i for r in m.roles]
                         if str(self.lex.roles.get(r, {}).get("category", "")) in PERSONIFIED]
                if dolls:
                    found.append(Mention((dolls[-1],), i, i + 1, "pronoun"))
                elif (machine := self._machine(words, i, [r for m in found if m.end <= i for r in m.roles])):
                    found.append(Mention((machine,), i, i + 1, "pronoun"))
                continue
            if i not in covered and w in FORMS and i > 0 and words[i - 1] == "the" and words[i - 2 : i - 1] not in (
                    [p] for p in PLACE_PREPS) \
                    and self.topic_kind == "role" and self.topic and not set(words[i + 1:i + 2]) & {"of", "for"}:
                # "Tin foil: in case the roll has fallen on the floor": no thing is named by the
                # word, so it is the topic's own roll or bottle (`offline.naming` names no other)
                found.append(Mention(self.topic, i, i + 1, "pronoun"))
                continue
            if i in covered or w not in PRONOUNS:
                continue
            if w == "it" and words[i + 1 : i + 2] in (["is"], ["was"], ["seems"], ["may"], ["might"], ["could"]) \
                    and "that" in words[i + 2 : i + 5]:
                continue  # "it is possible that my toothbrush fell": an empty subject, not a reference
            if w in ("one", "ones") and (i == 0 and words[1:2] not in (["that"], ["which"], ["is"], ["are"], ["can"]) or i > 0 and words[i - 1] in {"no", "any", "each", "every", "which",
                                                                   "this", "that"}
                                          or words[i + 1 : i + 2] == ["of"]):
                continue  # "one of the cushions", "each one": not an anaphoric "one"
            before = [m for m in found if m.kind == "role" and m.end <= i]
            if w == "one" and not before and _says_who(words, i):
                continue  # "Wren was the last one left in the classroom": the subject, a person

            places = [m for m in found if m.kind in ("role", "floor") and m.end <= i]
            if w in ("one", "ones"):  # "a dirty one": the kind the clause or sentence is about
                before = [m for m in before if all(x in ARTICLES | set(STATE_WORDS) or self._unknown(x)
                                                   for x in words[: m.start])]
            elif (w == "it" and words[i + 1 : i + 3] in (["is", "a"], ["is", "an"])
                  or w in ("it", "they") and i > 0 and words[i - 1] in ("is", "are", "was", "were")
                  and i - 1 in self.commas
                  or w in ("it", "they") and i > 0 and (words[i - 1] in CONJOINED_SUBJECT or words[i - 2:i] in (
                      [c, "if"] for c in CONJOINED_SUBJECT))
                  and words[i + 1 : i + 2] in ([b] for b in COPULAS)) and len(before) > 1:
                # "a document on the desk and it is a bill": the pronoun of a predicate noun is the
                # clause's subject, not a place named after a preposition; so is the pronoun of a
                # question asked of a thing put first ("the wine bottle on the table, is it empty?")
                # and the subject of a second conjunct ("if a plate is on the counter and it is
                # dirty", "there are towels on the rail but they are still wet")
                subj = [m for m in before if m.start == 0 or words[m.start - 1] not in PREP_ON | PREP_IN]
                before = subj[:1] or before
            elif i > 0 and words[i - 1] in ACTIONS and any(_placed(words, m) for m in before):
                # "fetch a spare from the dresser, lay it on the table": what is moved is a thing
                # spoken of, not a place it comes from or goes to
                moved = [m for m in before if not _placed(words, m)]
                before = moved or ([] if self.topic_kind == "role" and self.topic else before)
            elif i > 0 and words[i - 1] in PREP_ON | PREP_IN and before:
                # "a book or a phone on it": not the listed objects themselves
                listed = [before[-1]]
                for m in reversed(before[:-1]):
                    if not _joined(words, m, listed[-1], self.commas):
                        break
                    listed.append(m)
                # the place spoken about first in the clause ("the floor ... a toy on it")
                before = [m for m in places if m not in listed][:1]
            if self._time_people(words, i, before):
                continue  # "If the lamp is still on when they've gone": the people, not the lamp
            if before:
                found.append(Mention(before[-1].roles, i, i + 1,
                                     "pronoun" if before[-1].kind == "role" else before[-1].kind))
            elif w == "one" and ({"there", "have", "has", "got"} & set(words[max(0, i - 3) : i]) or i == 0 and words[
                    1:2] in (["is"], ["are"], ["can"])) and self.recent:
                # "if one is still to be had": the subject "one" is the thing named last
                # "... with the cloth if there is one" / "if we still have one": the object named
                # last, not the topic,
                # unless the clause already spoke of something ("if it is elsewhere or there is none")
                prior = [p for p in found if p.kind == "pronoun" and p.start < i]
                # (a thing carried about that holds things is one too: "Lunch box left on the floor.
                # If there is one, into the lost property box" asks of the lunch box, not of a
                # ceiling fan named before it)
                things = [r for r in self.recent if r not in self.lex.holders or self._carried(r)] or self.recent
                # (a condition opening its sentence, "If there isn't one, fine", asks again of the
                # thing spoken of, the else of "There might be a magazine on the stool. If so, put
                # it in the basket": not the basket named last as where it goes, `opening`)
                if self.opening and self.topic_kind == "role" and len(self.topic) == 1 and self.topic[0] in things:
                    things = [*things, self.topic[0]]
                found.append(Mention(prior[-1].roles if prior else (things[-1],), i, i + 1, "pronoun"))
            elif w in ("they", "them") and self._group_taken_up():
                # "The cabinet has two drawers: one for forks, one for spoons. If they're open,
                # shut them": a plural pronoun in a sentence that takes up a group (`PLURAL_REFERENCE`)
                # is the group, not a singular topic outside it (the cabinet); so is an elided
                # subject after it ("Check each of them; if open, ...")
                self.topic = self.group
                found.append(Mention(self.group, i, i + 1, "pronoun"))
            elif w in ("they", "them") and self.topic_kind == "role" and not self.plural & set(self.topic) \
                    and not self.coordinated and any(r in self.plural for r in self.recent) \
                    and not (self.parts_last or any(words[k] in PARTS and k in self.plural_at for k in range(i))):
                # "The mark is cleaned - with the wet wipes if they are on the table": a plural
                # pronoun means the nearest thing named in the plural, not a singular topic
                found.append(Mention((next(r for r in reversed(self.recent) if r in self.plural),), i, i + 1,
                                     "pronoun"))
            elif w in ("it", "its") and any(p.kind == "pronoun" and p.start < i for p in found):
                # "if there is one (it is kept in the vanity)": with nothing named before it, a
                # pronoun speaks of what the clause's earlier pronoun meant
                prior = [p for p in found if p.kind == "pronoun" and p.start < i]
                found.append(Mention(prior[-1].roles, i, i + 1, "pronoun"))
            elif w in ("it", "its") and not (self.own_it and i == 0) and self.topic_kind == "role" \
                    and set(self.topic) <= self.plural \
                    and all(self.plural_ref.get(r, True) for r in self.topic) \
                    and self.recent and self.recent[-1] not in self.plural and self.recent[-1] not in self.topic:
                # "Sandy jandals on the floor? Biff them in the bucket. It's the red one": "it" is
                # the nearest thing named in the singular, not a topic named in the plural; the
                # clause's later "one", "it" speak of it too
                self.topic = (self.recent[-1],)
                found.append(Mention(self.topic, i, i + 1, "pronoun"))
            elif self.topic:
                found.append(Mention(self.topic, i, i + 1, "pronoun" if self.topic_kind == "role" else "floor"))
        found.sort(key=lambda m: m.start)
        named = {r for m in found if m.kind == "role" and not _placed(words, m) for r in m.roles}
        if found:
            self.coordinated = "and" in words and len(named) > 1
        for n, m in enumerate(found):
            # "use the sponge in case it lies on the counter": a thing is not on itself
            later = {r for x in found[n + 1:] if x.kind == "role"
                     and set(words[max(0, x.start - 2) : x.start]) & (PREP_ON | PREP_IN) for r in x.roles}
            if m.kind == "pronoun" and set(m.roles) <= later:
                other = [r for r in self.recent if r not in later]
                if other:
                    found[n] = Mention((other[-1],), m.start, m.end, m.kind)
        for m in found:
            if m.kind in ("role", "pronoun"):
                self.recent = [r for r in self.recent if r not in m.roles] + list(m.roles)
            for r in m.roles if m.kind in ("role", "pronoun") else ():
                if m.kind == "pronoun":
                    self.plural_ref[r] = words[m.start] in ("they", "them", "their", "ones")
                else:
                    self.plural_ref.pop(r, None)
        covered = {k for m in found for k in range(m.start, m.end)}  # ("the guest bedroom": a room)
        people = [k for k, w in enumerate(words) if w in PEOPLE_NOUNS and k not in covered]
        # (a thing named in the plural here, as `facts` will record it, or before: "The keys are hung
        # on the hook when they are on the floor", after "Everyone just came in")
        plural_at = [m.start for m in found if m.kind == "role" and (
            m.end - 1 in self.plural_at or _plural_only(surface[m.end - 1]) or any(r in self.plural for r in m.roles))]
        if people or plural_at:
            self.people_last = max(people, default=-1) > max(plural_at, default=-1)
        first = next((m for m in found if m.kind in ("role", "floor", "pronoun")), None)
        first = _direct_object(words, found, first)
        # a participle clause set off by a dash as by a comma ("mists them with the plant mister -
        # filling the mister at the sink first if it has run empty")
        first = _later_object(words, found, self.commas | self.dashes) or first
        first = _fronted_thing(words, found, first)
        first = _result_subject(words, found, first)
        lead = next((k for k, w in enumerate(words) if w not in _HEDGE_LEADS), len(words))
        if words[lead:lead + 2] in _IDENTIFYING and words[lead + 2:lead + 3] and words[lead + 2] in ARTICLES:
            # "Tech log ... ON BRIEFING DESK. It's the blue binder - if it's been knocked onto the
            # floor, ...", "I think it's the standing lamp by her armchair": "it is the X" says
            # which thing was spoken of; what follows speaks of X
            named_as = next((m for m in found if m.kind == "role" and m.start >= lead + 2), None)
            if named_as is not None and not any(w in PLACE_PREPS for w in words[lead + 2:named_as.start]):
                first = named_as
        if first is not None and first.kind != "pronoun" and not _bare_place(words, found) \
                and not _participle_place(words, found) and not (
                self.topic and (_absent_only(words, found) or _objectless_move(words, found))):
            self.topic, self.topic_kind = first.roles, first.kind
        thing = next((m for m in found if m.kind == "role" and not _placed(words, m)), None)
        if thing is not None:
            self.heading_topic = thing.roles  # the thing spoken of, not a place it goes to
        for k, w in enumerate(words):
            part_owner = next((m for m in found if m.kind == "role" and (
                m.end == k or words[k + 1 : k + 2] == ["of"] and m.start in (k + 2, k + 3))), None) if w in PARTS else None
            if part_owner is not None:
                self.part_of[w] = part_owner.roles  # "the plant's soil", "the soil of the fern"
        # (for the next clause only, and unless a thing named in the plural follows the part: "1
        # dresser (the chest of drawers ...)" said in a list of materials is long past when a
        # later row's "If they are not on the floor" speaks of the scissors)
        parts = [k for k, w in enumerate(words) if w in PARTS and k in self.plural_at]
        self.parts_last = bool(parts) and not any(m.kind == "role" and m.start > parts[-1]
                                                  and m.end - 1 in self.plural_at for m in found)
        return found

    def _in_time(self, words: list[str], i: int) -> bool:
        """Whether the pronoun at word `i` is a time clause's subject (`_in_time_clause`), or opens
        a time clause whose opener the clause cut took as its cue (`timed`)."""
        return _in_time_clause(words, i) or self.timed and _in_time_clause(["when", *words], i + 1)

    def _ends_named(self, said: str) -> bool:
        """Whether `said` ends with the name of a thing of the task (a role's mention)."""
        toks = tokens(said)
        return any(m.kind == "role" and m.end == len(toks) for m in self.lex.find_mentions(toks))

    def facts(self, text: str) -> tuple[list[Fact], tuple[str, ...]]:
        said = _done_by_someone(_unbiased(expand(text).lower()))
        for pattern, state in PHRASAL_STATES:
            said = pattern.sub(state, said)
        # the flags a predicate participle gave, kept only for a thing that can take them ("if the
        # curtains are drawn" is shut, "if the bath is drawn" asks nothing of the bath)
        predicated: set[str] = set()
        for pattern, state in PREDICATE_STATES:
            said, found = pattern.subn(state, said)
            if found:
                predicated.add(STATE_WORDS[state][0])
        said = self.machine_again(said)
        said = RAISING.sub("is", said)
        said = _OVER.sub("on", _bracket_read_past(_aside_read_past(self._soiled(_contents(said)), self._ends_named),
                                                  self._ends_named))
        toks = tokens(said)
        words = [t[0] for t in toks]
        self.commas = frozenset(k for k in range(1, len(toks)) if "," in said[toks[k - 1][2]:toks[k][1]])
        self.hyphens = frozenset(k for k in range(1, len(toks)) if said[toks[k - 1][2]:toks[k][1]] == "-")
        self.dashes = frozenset(k for k in range(1, len(toks)) if said[toks[k - 1][2]:toks[k][1]].strip() in _DASHES
                                and said[toks[k - 1][2]:toks[k][1]] != "-")
        self.plural_at = frozenset(k for k, (w, a, b) in enumerate(toks) if said[a:b] != w and said[a:b].endswith("s"))
        mentions = self.mentions(words, toks, [said[a:b] for _, a, b in toks])
        self.starts = frozenset(x.start for x in mentions if x.kind == "role")
        for m in mentions:
            if m.kind == "role" and len(m.roles) == 1:
                surface = said[toks[m.end - 1][1] : toks[m.end - 1][2]]
                if surface != words[m.end - 1] and surface.endswith("s") or _plural_only(surface):
                    self.plural.add(m.roles[0])
                else:
                    self.plural.discard(m.roles[0])
        subjects = [m for m in mentions if m.kind in ("role", "pronoun")]
        negated = any(_negation(w) for w in words)
        # ("If it is already closed" of an air conditioner: off, as the same state is read
        # without "already", `_switched`)
        already = [self._switched(f) for f in self._already(words, mentions, negated)]
        if already:
            self.asked_already |= {f.condition for f in already if f.kind == "location"}
            return already, tuple(dict.fromkeys(f.subject for f in already))
        goal_of = {self.last_goal.subject} if self.last_goal is not None else set()
        if subjects and subjects[0].kind == "pronoun" and any(p in " ".join(words) for p in ELSEWHERE) and not (
                set(subjects[0].roles) & (set(self.last_location) | goal_of)) and not any(
                x.kind in ("role", "floor", "room") for x in mentions):
            # "if it is somewhere else": the thing whose place was just spoken of
            placed = [r for r in self.recent if r in self.last_location]
            if placed:
                first = Mention((placed[-1],), subjects[0].start, subjects[0].end, "pronoun")
                mentions = [first if x is subjects[0] else x for x in mentions]
                subjects = [first, *subjects[1:]]
                self.recent = [r for r in self.recent if r != placed[-1]] + [placed[-1]]
        facts: list[Fact] = []
        for idx, m in enumerate(mentions):
            if m.kind not in ("role", "pronoun"):
                continue
            facts += self._location(words, mentions, idx, negated)
            if not (m.kind == "role" and (_prep_within(words, m, WHERE_PREPS | SPATIAL_PREPS)
                                          or _beside_its_head(words, m, mentions)) and any(
                    x.kind in ("role", "pronoun") and x.end <= m.start for x in mentions)
                    and words[m.end : m.end + 1] not in (["which"], ["that"])):
                # "Candle on the coffee table still lit": the state is the candle's, not its place's
                # (unless a relative clause speaks of the place: "in the wardrobe, which is open")
                facts += self._state(words, m, negated)
            facts += self._attribute(words, m, negated)
            facts += self._used(words, m, negated)
        if any(p in " ".join(words) for p in ELSEWHERE) and subjects:
            for r in subjects[0].roles:
                base = self.last_location.get(r)
                if base is None and r in goal_of and self.last_goal is not None and not any(
                        f.subject == r and f.kind == "location" and not f.goal for f in facts):
                    # "The remote is returned to the stand if it has been left anywhere else": with
                    # no place said of it, "elsewhere" is away from where the instruction puts it
                    base = self.last_goal
                if base is not None:
                    facts.append(Fact(r, base.condition, "location", base.key, negated=True))
        facts += self._fronted_place(words, mentions)
        facts += self._derived_attributes(words, mentions)
        for m in subjects:
            k = m.end
            while k < len(words) and (words[k] in DESCRIPTIVE or self._pp_at(words, k)):
                k = self._pp_at(words, k) or k + 1
            phrasal = words[k:k + 1] == ["gone"] and bool(set(words[k + 1:k + 2]) & GONE_PARTICLES)
            if k < len(words) and words[k] in ABSENT and not phrasal or words[max(0, m.start - 2) : m.start] == ["out", "of"]:
                # "the roll by the toilet is missing", "we are out of bread" (not "it has gone out",
                # "the milk's gone off": a phrasal verb of a flame, a machine or food, `GONE_PARTICLES`)
                facts += [Fact(r, f"exists({r})", "exists", negated=True) for r in self._gone_thing(m)]
                break
            # "there may or may not be a loaf", "if we still have one", "if one is still to be had"
            before = words[max(0, m.start - 8) : m.start]
            if _existential_place(before, m.kind == "pronoun"):
                # "If there was water in it already, leave it", "Is there a film on it?": the thing
                # is the place of what may be there, and a filling in it says it is filled
                # (`FILLINGS`), not that it is there at all
                if before[-1] in PREP_IN and set(before) & FILLINGS:
                    facts += [Fact(r, f"state({r}, filled)", "state", "filled",
                                   negated=negated != ("no" in before)) for r in m.roles]
                break
            if _WE_HAVE.search(" ".join(before[-6:])) and _had_somewhere(words, m) and not _existential(before):
                # "maybe I have it in my bag": where the thing is had, not whether it is at all
                break
            if _existential(before) or "no" in before[-2:] or _WE_HAVE.search(" ".join(before[-6:])) or (
                    m.start == 0 and m.kind == "pronoun" and words[0] == "one"):
                facts += [Fact(r, f"exists({r})", "exists", negated=negated) for r in m.roles]
                break
        else:
            none = next((i for i, w in enumerate(words) if i > 0 and (
                w == "none" and words[i - 1] in {"have", "has", "is", "are", "there"}
                # "Bread anywhere else, or none left?": "or none" after an alternative of place is
                # "or there is none" (not "a book, a phone, or any of them, or none": things listed)
                or w == "none" and words[i - 1] == "or" and any(p in " ".join(words[:i]) for p in ELSEWHERE)
                # "or we haven't got any", "if we do not have any": "none" said with a negation
                or w == "any" and words[i - 1] in {"have", "has", "got"} and any(_negation(x) for x in words[:i]))),
                None)
            if none is not None and subjects and subjects[0].start < none:
                # "if it is anywhere else, or we have none": the thing spoken of may be absent
                facts += [Fact(r, f"exists({r})", "exists", negated=True) for r in subjects[0].roles]
        for m in subjects:
            # "if an umbrella has been left", "in case a letter has turned up": an indefinite
            # thing whose predicate says neither where nor how it is - whether there is one
            rest = words[m.end :]
            if m.kind == "role" and m.start > 0 and words[m.start - 1] in INDEFINITE - {"no"} and rest and all(
                    w in DESCRIPTIVE | SITUATION_PARTICIPLES | PARTICLES | ARRIVALS for w in rest) and not {
                    "there", "here"} & set(rest) and not any(
                    f.subject in m.roles for f in facts):
                facts += [Fact(r, f"exists({r})", "exists", negated=negated) for r in m.roles]
        if not subjects and self.topic and self.topic_kind == "role":
            # "The potted plant: dusty leaves get misted ..." - a state of a part of the topic
            for i, w in enumerate(words[:-1]):
                if w in STATE_WORDS and w not in ("on", "off", "out") and words[i + 1] in PARTS:
                    flag, pol = STATE_WORDS[w]
                    facts += [Fact(r, f"state({r}, {flag})", "state", flag, negated=not pol, modifier=True)
                              for r in self.part_of.get(words[i + 1], self.topic)]
                    break
                # "if the door is shut": a part's state is its thing's - the nearest that can take it
                j = i + 1
                while j < len(words) and words[j] in DESCRIPTIVE | NEGATIONS:
                    j += 1
                if w in PARTS and j > i + 1 and j < len(words) and words[j] in STATE_WORDS and words[j] not in (
                        "on", "off", "out"):
                    flag, pol = STATE_WORDS[words[j]]
                    neg = any(_negation(x) for x in words[i + 1 : j]) != (not pol)
                    facts += [self._fit(Fact(r, f"state({r}, {flag})", "state", flag, negated=neg))
                              for r in self.part_of.get(w, self.topic)]
                    break
        core = _before_time_clause(words)
        if not subjects and not facts and self.topic and self.topic_kind == "role" and len(core) <= 4:
            # an elliptic condition about the topic: "when dry, ...", "if not ripe, ..."; states
            # joined by "and" / "but" are each asked ("if clean but wet", "clean and dry"), a later
            # one negated only by its own "not"; a time clause after it says when, not what
            # ("Spinning when you come in?")
            flags: set[str] = set()
            for k, w in enumerate(core):
                if w in STATE_WORDS and (w not in PARTICLE_STATES or _stranded(core, k)) \
                        and STATE_WORDS[w][0] not in flags:
                    if flags and words[k - 1] not in ("and", "but", "not", "still", "yet"):
                        break
                    flag, pol = STATE_WORDS[w]
                    neg = negated if not flags else words[k - 1] == "not"
                    facts += [Fact(r, f"state({r}, {flag})", "state", flag, negated=neg != (not pol))
                              for r in self.topic]
                    flags.add(flag)
        if "respectively" in words:
            facts = _respectively(facts)
        said_by_pronoun = {r for m in mentions if m.kind == "pronoun" for r in m.roles}
        facts = [self._fitting_referent(f) if f.subject in said_by_pronoun and not self._holds(f) else f
                 for f in facts]
        facts = [self._fit(f) if f.kind == "state" and f.subject in said_by_pronoun
                 else self._fit_place(f, words) if f.kind == "location" and f.subject in said_by_pronoun
                 else self._fit_named(f, mentions)
                 for f in facts if self._holds(f)]
        facts = [self._switched(f) for f in facts]
        facts = [g for f in facts if (g := self._offered(f)) is not None]
        facts += self._back_home(words, mentions, facts)
        goals = [f for f in facts if f.kind == "location" and f.goal]
        if goals:
            self.last_goals = goals
        for f in facts:
            if f.kind == "location" and f.home:
                self.homes[f.subject] = f
            if f.kind == "location" and not f.goal:
                self.last_location[f.subject] = f
            if f.kind == "location" and f.goal:
                self.last_goal = f
            if f.kind == "state":
                self.last_state[f.key] = f
        facts = [f for f in facts if f.key not in predicated or not self._misfit(f)]
        names = tuple(dict.fromkeys(r for m in subjects for r in m.roles))
        return list(dict.fromkeys(facts)), names

    def code_switched(self, text: str, thing: tuple[str, ...]) -> list[Fact]:
        """A condition in another language's grammar with English words in it ("If naka-on pa",
        "Agar abhi bhi on hai", "if it deh pon di floor", "If madumi pa (dirty)", a gloss in
        brackets kept): read when a third of the clause's words or more are of no English
        (`sentences.code_switched`, the names of things counted English) and its grammar gave
        nothing. The English words it carries still say what is asked: a state
        word (`STATE_WORDS`, "on" too unless a place follows it) is the state asked, a place
        noun with no English preposition before it (the floor, a surface or container named) is
        where the thing may be (on the floor or a surface, inside a container). What is asked
        about is a thing the clause names that is carried about, else `thing`: the item's topic
        (what the reader last spoke of that is no place), which a pronoun or an elided subject
        takes up."""
        said = expand(text).lower()
        toks = tokens(said)
        words = [t[0] for t in toks]
        mentions = [m for m in self.lex.find_mentions(toks) if not _verb_read(toks, m)]
        named = {i for m in mentions for i in range(m.start, m.end)}
        if not code_switched([w if i not in named else "" for i, w in enumerate(words)]):
            return []  # (a thing's name is English, whatever lemminflect lists: "the fridge")
        carried = [m for m in mentions if m.kind == "role" and len(m.roles) == 1 and self._carried(m.roles[0])]
        subject = carried[0].roles if carried else thing
        places = [m for m in mentions if m.kind == "floor" or m.kind == "role" and m not in carried]
        negated = any(_negation(w) for w in words)
        facts: list[Fact] = []
        for k, w in enumerate(words):
            w = _native_state(words, k) or w
            if w not in STATE_WORDS or any(p.start in (k + 1, k + 2) for p in places):
                continue  # ("on di floor": a place, not a state)
            flag, pol = STATE_WORDS[w]
            facts += [f for r in subject
                      if not self._misfit(f := Fact(r, f"state({r}, {flag})", "state", flag, negated=negated != (not pol)))]
        for p in places:
            for r in subject:
                for t in p.roles:
                    relation = "inside" if t in self.lex.containers else "on"
                    f = Fact(r, f"{relation}({r}, {t})", "location", t, negated=negated)
                    if t != r and self._holds(f):
                        facts.append(f)
        return list(dict.fromkeys(facts))

    def _back_home(self, words: list[str], mentions: list[Mention], facts: list[Fact]) -> list[Fact]:
        """"put it back", "pop them back in", "put her there": an instruction that moves a thing
        back (or "there", right after it) and names no place sends it to where the text said it
        is kept or lives ("the salt and pepper shakers live in the sideboard ... pop it back in",
        "your doll sleeps on the bed. Put her there")."""
        there = [k for k in range(1, len(words)) if words[k] == "there" and any(
            m.end == k and m.kind == "pronoun" for m in mentions)]
        # "put it away", "tidy the mug away": a verb of putting away sends the thing where it
        # belongs, as "back" does ("throw it away" sends it nowhere it belongs)
        away = [k for k in range(2, len(words)) if words[k] == "away" and any(
            m.end == k and m.kind in ("pronoun", "role") and m.start > 0 and (
                words[m.start - 1] in PUT_AWAY or m.start > 1 and words[m.start - 2] in PUT_AWAY)
            for m in mentions)]
        if "back" not in words and not there and not away or any(f.kind == "location" for f in facts) \
                or not imperative(words):
            return []
        k = words.index("back") if "back" in words else there[0] if there else away[0]
        if any(m.kind in ("role", "room", "floor") and m.start > k for m in mentions):
            return []
        kinds = ("pronoun", "role") if away and k == away[0] else ("pronoun",)
        moved = [r for m in mentions if m.kind in kinds and m.end <= k for r in m.roles]
        # (where it belongs, said as a goal: "The bottle belongs in the cabinet. ... put it away")
        belongs = {self.last_goal.subject: self.last_goal} if away and self.last_goal is not None else {}
        return [replace(self.homes.get(r) or belongs[r], goal=True, negated=False, definite=False, home=False,
                        modifier=False)
                for r in dict.fromkeys(moved) if r in self.homes or r in belongs]

    def _holds(self, f: Fact) -> bool:
        """A thing on or in a role that cannot hold it (a sofa in a toy box, a phone on a book:
        `scene.compat.can_hold` on their catalog sizes and kinds) is a misreading, not a fact; so
        is a piece of furniture (a surface or container nobody carries: a dishwasher) on or in
        another, which the sizes alone may allow ("unless the dishwasher is running, then just
        chuck it in the sink" is no dishwasher in the sink), and a thing that lies on the floor
        alone and is never carried (a puddle, a stain: catalog placement `floor`) inside
        anything: the sizes of a flat puddle let it "fit" a cabinet."""
        relation = f.condition.split("(", 1)[0]
        item, holder = self.kinds.get(f.subject), self.kinds.get(f.key)
        if f.kind != "location" or relation not in ("on", "inside") or item is None or holder is None:
            return True
        if not item.pickable and (item.surface or item.container):
            return False
        if relation == "inside" and not item.pickable and item.placement == ["floor"]:
            return False
        return can_hold(item, holder, relation)

    def _fitting_referent(self, f: Fact) -> Fact:
        """A place a pronoun's referent cannot take (`_holds`) is said of the nearest thing
        named before that can, carried about ("wipe the puddle with the old towel - it's kept in
        the vanity, unless somebody's stuffed it in the cabinet": the towel, not the puddle the
        item spoke of; "mop up the spill with the cloth, unless you left it in the bucket"):
        pronouns go to the nearest fitting mention. `f` unchanged (and then dropped) when none
        fits, or when the referent is itself a thing carried about and the place is of the kind
        that takes such things (a surface for "on", a container for "in"): only the catalog's sizes
        rule it out ("is the hat on the floor? hang it back on the hook", "the coat - if it's still
        on its peg, leave it": a hat or coat hangs on a hook its top cannot hold), and the pronoun
        still means the thing just spoken of, not one named paragraphs before (a torch)."""
        relation = f.condition.split("(", 1)[0]
        item, holder = self.kinds.get(f.subject), self.kinds.get(f.key)
        if item is not None and holder is not None and item.pickable and (
                holder.surface if relation == "on" else holder.container):
            return f
        for r in reversed(self.recent):
            if r in (f.subject, f.key) or not self._carried(r):
                continue
            other = replace(f, subject=r, condition=f"{relation}({r}, {f.key})")
            if self._holds(other):
                return other
        return f

    def machine_again(self, said: str) -> str:
        """"If the unit is still running, switch it off", "is the appliance on?": a general noun
        for a machine (`MACHINE_EPITHETS`) after "the" / "this" / "that", when the thing named
        last switches on and off and no thing of the task is called by the noun, is that thing
        spoken of again, read as "it"; after a preposition of place ("on the unit") it stays a
        place."""
        last = self.recent[-1] if self.recent else None
        if last is None or "toggled_on" not in self.capable.get(last, ()):
            return said

        def again(m: re.Match[str]) -> str:
            before = said[: m.start()].split()[-1:]
            if (m.group(2),) in self.lex.phrases or before and before[0] in PLACE_PREPS | PREP_ON | PREP_IN:
                return m.group(0)
            return "it"
        return _EPITHET.sub(again, said)

    def _misfit(self, f: Fact) -> bool:
        """Whether `f` is an on/open state (`FITTED`) of a thing that cannot take it."""
        return f.kind == "state" and f.key in FITTED and f.key not in self.capable.get(f.subject, FITTED)

    def _machine(self, words: list[str], i: int, before: list[str]) -> str | None:
        """"The ship's lantern - if she be still burning, switch her off": "she" as the subject of
        a state that a person cannot be in but a thing can (on, open, running, full) is the
        nearest thing named that can take it, as people speak of a lamp, a boat or an engine;
        None when no state follows or nothing named can take it."""
        k = i + 1
        while k < len(words) and words[k] in _SHE_BE:
            k += 1
        state = STATE_WORDS.get(words[k]) if k < len(words) and k > i + 1 else None
        if state is None or state[0] not in _MACHINE_STATES:
            return None
        return next((r for r in reversed(self.recent + before) if state[0] in self.capable.get(r, ())), None)

    def _switched(self, f: Fact) -> Fact:
        """"If the air conditioner is open, please close it": a state said of a thing that cannot
        take it but can take its switched sense (`SWITCHED_SENSE`) is that sense, as the speakers
        of the many languages that open and close a light, a fan or a television say it; a thing
        that opens (a laptop, a washing machine) keeps its "open", and a pronoun's "open" goes to
        a thing nearby that opens first (`_fit`)."""
        sense = SWITCHED_SENSE.get(f.key) if f.kind == "state" else None
        if sense is None or not self._misfit(f) or sense not in self.capable.get(f.subject, ()):
            return f
        return replace(f, key=sense, condition=f"state({f.subject}, {sense})")

    def _can_take(self, f: Fact, roles: Iterable[str]) -> list[str]:
        """The roles among `roles`, other than `f`'s subject, that can take `f`'s state, in order,
        each once."""
        return list(dict.fromkeys(r for r in roles if r != f.subject and f.key in self.capable.get(r, ())))

    def _fit(self, f: Fact) -> Fact:
        """A pronoun's state said of a thing that cannot take it ("hang the shirt in the wardrobe
        - open it first if its doors are shut") means the nearest thing that can."""
        fitting = self._can_take(f, reversed(self.recent)) if self._misfit(f) else []
        return _state_of(f, fitting[0]) if fitting else f

    def _fit_place(self, f: Fact, words: list[str]) -> Fact:
        """A pronoun's move to the floor ("onto the floor", "has fallen on the floor": `TOWARDS`, a
        perfect) said of a piece of furniture that stands nowhere else (a desk, a wardrobe: not
        carried, placed on the floor only) means the nearest thing named before that is carried
        ("Tech log: on the briefing desk. It's the blue binder - if it's been knocked onto the
        floor, ...": the binder, not the desk; "The scarf usually hangs by the wardrobe. If it has
        slipped onto the floor, ...": the scarf): furniture is not knocked over onto the floor, and
        the situations such a question plans cannot be built. "The hamper is the blue one, it stays
        on the floor" still states the hamper's place."""
        kind = self.kinds.get(f.subject)
        if f.condition != f"on({f.subject}, floor)" or kind is None or kind.pickable or kind.placement != ["floor"] \
                or not set(words) & (TOWARDS | PERFECT | {"been"}):
            return f
        fitting = [r for r in reversed(self.recent) if r != f.subject and (k := self.kinds.get(r)) is not None
                   and k.pickable]
        if not fitting:
            return f
        return replace(f, subject=fitting[0], condition=f"on({fitting[0]}, floor)")

    def _fit_named(self, f: Fact, mentions: list[Mention]) -> Fact:
        """"Desk lamp over chart table left on last night": an on/open state read of a thing named
        in the clause that cannot take it (the table, the nearest noun) is the state of the one
        thing the clause names that can (the lamp); with none or several, as read."""
        fitting = self._can_take(f, (r for m in mentions if m.kind == "role" for r in m.roles)) \
            if self._misfit(f) else []
        return _state_of(f, fitting[0]) if len(fitting) == 1 else f

    def _soiled(self, said: str) -> str:
        """Soil said to be on a thing, read as the thing's state ("has it got marks on it?" -> "is
        it dirty", "the coat has whey on it" -> "the coat is dirty", "there is a mark on the plate"
        -> "the plate is dirty", "any mud on them?" -> "are they dirty"; water: wet), so no stain
        of its own is asked of (`STAIN_WORDS`, `_SOIL_ASKED`, `_SOIL_HAD`, `_SOIL_THERE`,
        `_SOIL_BARE`). A stain on the floor or its covering (`_FLOORING`) is a floor stain; a
        thing's part with its article ("a lid on it") or a kind's name soils nothing."""
        def soil(m: re.Match[str]) -> str | None:
            word, det = m.group("soil"), (m.group("det") or "").strip()
            np = m.group("np")
            if np.split()[-1] in _FLOORING or word in FUNCTION_WORDS or word in _NOT_SOIL:
                return None
            if singular(word) not in STAIN_WORDS:
                bare = det in ("", "any", "some", "no", "a bit of", "bits of") and singular(word) == word
                named = any(x.kind == "role" for x in self.lex.find_mentions(tokens(word)))
                if not bare or named or "NOUN" not in getAllLemmas(word):
                    return None
            return "wet" if word == "water" else "dirty"

        def read(m: re.Match[str], np: str, asked: bool, lead: str = "") -> str:
            """The soil's match as the thing's state: asked ("is it dirty") or said ("the coat is
            dirty"), negated by "not" or by "no" soil; unchanged where it is no soil."""
            state = soil(m)
            if state is None:
                return m.group(0)
            be = "are" if np in ("they", "them") else "is"
            negated = (m.groupdict().get("not") is not None) != ((m.group("det") or "").strip() == "no")
            return f"{lead}{f'{be} {np}' if asked else f'{np} {be}'} {'not ' if negated else ''}{state}"

        def subject(np: str) -> str:
            return "they" if np == "them" else np

        said = _SOIL_ASKED.sub(lambda m: read(m, m.group("np"), asked=True), said)
        said = _SOIL_HAD.sub(lambda m: read(m, m.group("np"), asked=False), said)
        said = _SOIL_THERE.sub(lambda m: read(m, subject(m.group("np")), asked=False), said)
        return _SOIL_BARE.sub(lambda m: read(m, subject(m.group("np")), asked=True, lead=m.group("lead")), said)

    def _already(self, words: list[str], mentions: list[Mention], negated: bool) -> list[Fact]:
        """`unless it is already there / on`: the condition is the previous instruction's result;
        so is a place said only as "in there" / "on there" of a pronoun ("leo's car goes in the
        toy box. if it's not in there put it in there", "the mugs go on the rack; if they are not
        on there, ..."): "there" is where the instruction before put it."""
        while words and words[-1] in SIGN_OFFS:  # "unless they're there already, thx": a note's thanks
            words = words[:-1]
        mentions = [m for m in mentions if m.start < len(words)]  # "cheers" may be read as a name
        if any(m.kind == "role" for m in mentions) or len(words) > 6:
            return []
        if "already" not in words and "now" in words and set(words) & {"there", "here"}:
            # "unless it's there now": "now" said of a thing at the place just named is "already"
            words = ["already" if w == "now" else w for w in words]
        if "already" not in words:
            rest = [w for w in words if w not in ALREADY_FILLER and w not in PRONOUNS]
            if len(rest) != 2 or rest[0] not in PREP_ON | PREP_IN or rest[1] != "there" or not any(
                    m.kind == "pronoun" for m in mentions):
                return []
            words = [*words, "already"]  # read as "it is (not) already in there"
        pronouns = [m for m in mentions if m.kind == "pronoun"]
        said = set(pronouns[0].roles) if pronouns else set()
        after = [w for w in words[words.index("already") + 1 :] if w not in {"is", "are", "be", "was", "were"}]
        # what the clause says besides its subject: "there" / "on it" / nothing at all ("unless
        # it is on it already", "if it is not already") is where the previous instruction put it
        content = [w for i, w in enumerate(words) if w not in ALREADY_FILLER | SITUATION_PARTICIPLES
                   and not (pronouns and i == pronouns[0].start)]
        there = after[:1] in (["there"], ["here"]) or set(content) <= {"there", "here"} or (
            len(content) > 1 and content[0] in PREP_ON | PREP_IN and all(w in PRONOUNS | ARTICLES | {"there"}
                                                                         for w in content[1:]))
        # "my bat and my racket go in the bin and on the bench, respectively. If they're already
        # there, ...": a plural pronoun after an instruction with a goal per thing asks each
        # thing whether it is at its own goal
        plural = [g for g in self.last_goals if pronouns and words[pronouns[0].start] in ("they", "them")]
        if there and len({g.subject for g in plural}) > 1 and (not said or said & {g.subject for g in plural}):
            return [Fact(g.subject, g.condition, "location", g.key, negated=negated) for g in plural]
        if there and self.last_goal is not None and (not said or self.last_goal.subject in said):
            g = self.last_goal
            return [Fact(g.subject, g.condition, "location", g.key, negated=negated)]
        if after and after[0] in STATE_WORDS:
            flag, pol = STATE_WORDS[after[0]]
            st = self.last_state.get(flag)
            if st is not None:  # pronouns before "already on" are often the sentence topic: trust the state
                return [Fact(st.subject, st.condition, "state", flag, negated=negated != (not pol))]
            if self.recent:  # "opening the wardrobe first, unless the door is already open"
                r = self.recent[-1]
                return [Fact(r, f"state({r}, {flag})", "state", flag, negated=negated != (not pol))]
        return []

    def _unknown(self, word: str) -> bool:
        """A word the analyser has no meaning for: not a role, room, state, cue or function word."""
        return (len(word) > 2 and word.isalpha() and word not in _KNOWN_WORDS
                and word not in self.lex.role_words() and word not in self.lex.attribute_words()
                and not any(word in room for room in self.lex.room_phrases))

    def _derived_attributes(self, words: list[str], mentions: list[Mention]) -> list[Fact]:
        """Attributes the catalog has no domain for: `a ripe one` / `it is not ripe yet` (an
        adjective, key = its noun `ripeness`; `unripe` negates `ripe`) and `it is a bill` (a kind)."""
        out: list[Fact] = []
        for m in mentions:
            if m.kind not in ("role", "pronoun"):
                continue
            j = m.start - 1
            while j >= 0 and words[j] in ARTICLES:
                j -= 1
            if j >= 0 and words[j] in PREP_ON | PREP_IN and any(
                    x.kind in ("role", "pronoun") and x.end <= j for x in mentions):
                continue  # "the banana on the table is overripe" speaks of the banana
            k = m.end
            placed = False  # a place said before the adjective: "if it's on the counter and ripe"
            while k < len(words) and (words[k] in DESCRIPTIVE | NEGATIONS | {"that", "which"} or self._pp_at(words, k)
                                      or placed and words[k] == "and" and self._unknown(words[k + 1:k + 2][0] if
                                                                                       k + 1 < len(words) else "")):
                placed = bool(self._pp_at(words, k))
                k = self._pp_at(words, k) or k + 1
            neg = any(_negation(w) for w in words[m.end : k])
            if k > m.end and k < len(words) and (words[k - 1] in DESCRIPTIVE | NEGATIONS or words[k - 1] == "and"):
                if words[k] in ("a", "an") and k + 2 == len(words) and self._unknown(words[k + 1]):
                    # "... and it is a bill": a kind of the object (the clause ends with the noun)
                    out += [Fact(r, f"attr({r}, kind, {words[k + 1]})", "attr", "kind", negated=neg,
                                 modifier=True, derived=True) for r in m.roles]
                elif self._unknown(words[k]) and (k + 1 == len(words) or words[k + 1] in _AFTER_PREDICATE):
                    out += self._adjective(m, words[k], neg)
            if m.start > 0 and (m.kind == "role" or words[m.start] in ("one", "ones")) and self._unknown(
                    words[m.start - 1]) and (
                    m.start == 1 or words[m.start - 2] in ARTICLES):
                out += self._adjective(m, words[m.start - 1], False)  # "a ripe one", "an unripe one"
        return out

    def _offered(self, f: Fact) -> Fact | None:
        """`f` as the brief allows it (the one guard on the attributes this reader states or asks).
        The prompts show the condition language's state flags (`open`, `toggled_on`, ...) and the
        catalog's kinds; a kind's catalog attribute domain (`color`, `material`, `kind`, `size`)
        bounds its values. So an attribute whose value is a word of a state (`STATE_WORDS`) or of
        operation (`OPERATION`: "if the oven is working") is that state where the kind takes it
        and nothing where it does not (never `attr(oven, workingness, working)`, which no brief
        offers and which makes every environment refused), a word of breakage (`BREAKAGE_WORDS`:
        "the fan spoil already") is `broken` of a machine and nothing of anything else, and a value outside the kind's domain
        for one of its catalog keys is dropped. A key the catalog has for no kind, made from a
        word the text contrasts ("a ripe one ... an unripe one": `ripeness`), stays: the prompts
        bound no other key (the plan's schema takes any snake_case key)."""
        if f.kind != "attr":
            return f
        value = f.condition.rsplit(", ", 1)[1][:-1]
        role = self.lex.roles.get(f.subject) or {}
        if dict(role.get("attributes") or {}).get(f.key) == value:
            return f  # the brief's own attribute of the role
        kind = self.kinds.get(f.subject)
        domain = dict(kind.attributes or {}) if kind is not None else {}
        if f.key in domain:
            return f if value in domain[f.key] else None
        if value in BREAKAGE_WORDS:
            if "toggled_on" not in self.capable.get(f.subject, frozenset()):
                return None  # "the milk is spoilt", "the dog is knackered": no machine out of order
            # said of it, not a doubted modifier: "the fan spoil already" states the fan's state
            return replace(f, condition=f"state({f.subject}, {BREAKAGE})", kind="state", key=BREAKAGE,
                           derived=False, modifier=False)
        flag, pol = STATE_WORDS.get(value) or ((OPERATION, True) if value in OPERATION_WORDS else ("", True))
        if not flag:
            return f
        if flag in FITTED and flag not in self.capable.get(f.subject, frozenset({flag})):
            return None  # a word of operation said of a thing that cannot be switched on
        return replace(f, condition=f"state({f.subject}, {flag})", kind="state", key=flag,
                       negated=f.negated != (not pol), derived=False)

    def _adjective(self, m: Mention, word: str, negated: bool) -> list[Fact]:
        if word.startswith("un") and len(word) > 5:
            word, negated = word[2:], not negated
        noun = (word[:-1] + "i" if word.endswith("y") else word) + "ness"
        return [Fact(r, f"attr({r}, {noun}, {word})", "attr", noun, negated=negated, modifier=True, derived=True)
                for r in m.roles]

    def _fronted_place(self, words: list[str], mentions: list[Mention]) -> list[Fact]:
        """`On the bed there may be a book, an alarm clock or a phone`: the place comes first; so
        it does before an agent coming upon the things (`_FRONTED_FINDING`: "On the floor we may
        find the game controller", "In the sink you might spot a mug")."""
        if not words or words[0] not in PREP_ON | PREP_IN:
            return []
        place = next((m for m in mentions if m.kind in ("role", "floor")), None)
        if place is None or not all(w in ARTICLES for w in words[1 : place.start]):
            return []
        finding = _FRONTED_FINDING.match(" ".join(words[place.end:]))
        if finding is not None:
            there = place.end + len(finding.group(0).split()) - 1
        elif "there" in words:
            there = words.index("there")
        else:
            return []
        if place.end > there:
            return []
        out = []
        for m in mentions:
            if m.start > there and m.kind == "role":
                for s in m.roles:
                    for t in place.roles:
                        if s != t:
                            cond = f"on({s}, {t})" if words[0] in PREP_ON or t == "floor" else f"inside({s}, {t})"
                            out.append(Fact(s, cond, "location", t, modifier=True))
        return out

    def _subjects(self, words: list[str], mentions: list[Mention], idx: int) -> list[str]:
        group = [idx]
        j = idx - 1
        while j >= 0 and mentions[j].kind in ("role", "pronoun") and _joined(words, mentions[j], mentions[j + 1],
                                                                             self.commas) \
                and not _placed(words, mentions[j]):
            # "the book on the couch, a toy in the box": a place named before a new item is no
            # item of its list (the comma is gone from the words)
            group.insert(0, j)
            j -= 1
        return [r for g in group for r in mentions[g].roles]

    def _is_goal(self, words: list[str], m: Mention, skipped: list[str]) -> bool:
        before = words[max(0, m.start - 4) : m.start]
        # "pop it on the desk": where an imperative's object goes ("a pack of wipes on the
        # table" is no action: the word after an article is a noun, and so is one before "of":
        # "a spare set of keys on the side table", "a tall stack of plates")
        verbs = [w for i, w in enumerate(before) if w in ACTIONS and not (i > 0 and before[i - 1] in ARTICLES)
                 and before[i + 1:i + 2] != ["of"]]
        # (after words that say nothing of the mood: "Then pop it in the laundry basket", "simply hang it up")
        lead = next((i for i, w in enumerate(words) if w not in LEAD_INS | SOFTENERS), len(words))
        return bool(set(skipped) & MOTION) or bool(verbs) or (
            m.start > lead and imperative(words[lead:]) and all(w in ARTICLES for w in words[lead + 1 : m.start]))

    def _location(self, words: list[str], mentions: list[Mention], idx: int, negated: bool) -> list[Fact]:
        m = mentions[idx]
        if idx + 1 < len(mentions) and mentions[idx + 1].kind in ("role", "pronoun") and _joined(
                words, m, mentions[idx + 1], self.commas):
            return []  # the last item of a list carries the location
        k = self._aside_end(words, mentions, m.end)
        skipped: list[str] = []
        # "keeps ending up on", "tends to end up on", "usually gets left on": the habitual form's
        # words lead to the place, and its event verb moves nothing (`sentences.habitual`)
        habit = habitual(words[m.end:])
        aspect = (HABITUAL_WORDS - {"to"}) | EVENT_VERBS if habit else frozenset()
        while k < len(words) and (words[k] in DESCRIPTIVE | MOTION | NEGATIONS | PARTS | PARTICLES | aspect
                                  | {"top", "of", "straight", "that", "which"}
                                  or words[k] == "to" and bool(skipped) and skipped[-1] in TEND
                                  or _participle(words, k)) and words[k] not in PREP_ON | PREP_IN:
            skipped.append(words[k])
            k += 1
            if skipped[-1] == "of" and k < len(words) and words[k].isalpha() and words[k] not in PREP_ON | PREP_IN \
                    and not any(x.start == k for x in mentions):
                k += 1  # "a tin of food in the basket", "a bar of soap in the tub"
        if k >= len(words) or words[k] not in PREP_ON | PREP_IN | {"from", "to"} or (
                skipped and skipped[-1] in ("switched", "turned")):  # "switched on" is not a place
            return []
        if habit:
            skipped = [w for w in skipped if w not in aspect and w != "to"]
        if words[k] == "to" and not self._is_goal(words, m, skipped) and not set(skipped) & FALLS \
                and not _perfect_moved(words, m.start, k):
            return []  # "to" names a place only where something is moved: "returned to the armchair"
        if words[k] == "from" and (skipped or m.kind != "role" or set(words[max(0, m.start - 4) : m.start]) & SOURCE_VERBS):
            return []  # "fill it from the bag" names a source, not where the object is
        # "the wipes from the table": where the object is now, whatever verb precedes it
        # "a book is placed on the sofa and a toy in its toy box": a second item after a place
        # shares the first one's verb (the verb is gapped), and so its goal
        prev = mentions[idx - 1] if idx > 0 else None
        gapped = prev is not None and _placed(words, prev) and 0 < m.start - prev.end <= 4 and all(
            w in LIST_WORDS or w in STATE_WORDS for w in words[prev.end : m.start]) and bool(
            set(words[: prev.start]) & MOTION)  # (its adjectives too: "... and a clean one on the counter")
        goal = words[k] != "from" and (self._is_goal(words, m, skipped) or gapped or (
            words[k] in ("into", "onto") and not set(skipped) & SITUATION_PARTICIPLES))
        # "Return any board game found lying on the floor to the bookcase", "bring the mug left on
        # the desk to the sink": a participle of situation after the verb's object says where the
        # object is ("on", "in"); only a place after it that the verb moves it to ("to") is the goal
        situated = goal and words[k] in PREP_ON | PREP_IN and bool(set(skipped) & SITUATION_PARTICIPLES) \
            and not set(skipped) & MOTION
        goal = goal and not situated
        article = _modified_determiner(words, m.start)
        # "My jacket. I left it on the sofa.", "The tea towel. It is on the counter": a personal
        # pronoun is the particular thing it points back to, as definite as a name with "the" or
        # "my" (`DEFINITE_REFERENCE`); a participle of situation after it ("finding it lying on
        # the floor", "wherever they lie") still describes how the thing may be found
        particular = m.kind == "pronoun" and words[m.start] in DEFINITE_REFERENCE \
            and not set(skipped) & SITUATION_PARTICIPLES - HOMES
        # where a thing is kept or lives is a norm `_settle_stated` weighs against the rest of
        # the text
        definite = (article in DEFINITE or particular) and not set(skipped) & HOMES
        described = bool(set(skipped) & SITUATION_PARTICIPLES) or (
            not skipped and not particular and (article in INDEFINITE or article not in ARTICLES)) or (
            skipped[:1] in (["that"], ["which"]) and article in INDEFINITE)  # "any toy that is on the floor"
        modifier = not goal and described
        subjects = self._subjects(words, mentions, idx)
        out: list[Fact] = []
        prep = ""
        elided = False  # "on the office chair or the floor": the second place shares the first's preposition
        while k < len(words) and (words[k] in PREP_ON | PREP_IN | {"from", "to"} or elided):
            if elided:
                k -= 1  # no preposition of its own: the place is found from the word before it
            else:
                prep = words[k]
            target = next((t for t in mentions if t.start > k and (
                t.kind in ("role", "room", "floor") or t.kind == "pronoun" and words[t.start] in ("it", "them"))),
                None)
            if target is None or target.start - k - len(self.hyphens & set(range(k + 1, target.start))) > 3:
                break
            for s in dict.fromkeys(subjects):
                for t in target.roles:
                    if t == s or (prep == "from" and target.kind == "role" and t not in self.lex.holders):
                        continue
                    if target.kind == "room":
                        cond = f"in_room({s}, {t})"
                    elif prep in PREP_ON or t == "floor" or (prep in ("from", "to") and t not in self.lex.containers):
                        cond = f"on({s}, {t})"
                    else:
                        cond = f"inside({s}, {t})"
                    out.append(Fact(s, cond, "location", t, negated=negated and not goal, goal=goal,
                                    modifier=modifier and not goal, definite=definite, home=bool(set(skipped) & HOMES),
                                    presupposed=prep == "from" and _taken(words, m.start)))
            k = target.end
            alternative = k < len(words) and words[k] == "or"
            if situated and not alternative:
                goal = True  # the verb's own goal after the object's place ("... to the bookcase")
            while k < len(words) and words[k] in {"or", "and", "either", "the", "a"}:
                k += 1
            elided = alternative and self._elided_place(words, mentions, k)
        return out

    def _aside_end(self, words: list[str], mentions: list[Mention], k: int) -> int:
        """Where the predicate goes on after a short aside set off by commas right after the
        subject ("The remote, as ever, belongs on the stand", "the key, I think, is in the
        drawer"): the aside says nothing of the thing, and its place is read after it. An aside
        naming a thing or a place ("the mug, on the desk, ...", "the mug, the plate ...") is none.

        Not `sentences.COMMENT_ASIDES`: those named comment adverbials are dropped from the whole
        text before any reading (a condition's or a state's too); this passes over any short
        aside ("I think", "if memory serves"), but only between a subject and its place, where
        an unnamed aside can hide nothing else."""
        if k not in self.commas:
            return k
        end = next((j for j in sorted(self.commas) if k < j <= k + ASIDE_WORDS), None)
        if end is None or any(k <= x.start < end for x in mentions) or set(words[k:end]) & (
                PREP_ON | PREP_IN | {"to", "from", "and", "or"}):
            return k
        return end

    def _elided_place(self, words: list[str], mentions: list[Mention], k: int) -> bool:
        """After "on the office chair or", a place with no preposition of its own ("the floor")
        is a second place the first preposition governs, when nothing but the clause's end, a
        comma or another "or" follows it (else it opens a clause: "... or the plate is dirty")."""
        m = next((t for t in mentions if t.start == k), None)
        return m is not None and m.kind in ("role", "floor") and (
            m.end == len(words) or m.end in self.commas or words[m.end] == "or")

    def _state(self, words: list[str], m: Mention, negated: bool) -> list[Fact]:
        k = m.end
        skipped: list[str] = []
        while k < len(words) and len(skipped) < 8 and (words[k] in DESCRIPTIVE | PARTS | NEGATIONS | BECOMING
                                                       | {"but", "and", "that", "which"}
                                                       or self._pp_at(words, k) or _graded(words, k)):
            if self._pp_at(words, k):
                k = self._pp_at(words, k)
                continue
            skipped.append(words[k])
            k += 1
        found: list[tuple[str, bool, bool]] = []  # (word, polarity-negated, modifier)
        local_neg = any(_negation(w) for w in skipped)
        # "a water bowl that has water but is dirty": a restrictive relative clause describes
        art = m.start - 1  # the article before any adjectives: "a clean coat that is wet"
        while art > 0 and (words[art] in STATE_WORDS or self._unknown(words[art])):
            art -= 1
        relative = skipped[:1] in (["that"], ["which"]) and art >= 0 and words[art] in INDEFINITE
        while k < len(words) and words[k] in STATE_WORDS:
            w = words[k]
            if w in ("on", "off", "out", "up") and set(skipped) & GOING:
                break  # "if the smoke alarm goes off", "when the fire went out": it sounds, it dies down
            if w == "out" and not set(skipped) & {"is", "are", "was", "were", "already", "still"}:
                break  # `take it out` is an action, `it is out` a state
            if w == "out" and k + 1 < len(words) and words[k + 1] in PREP_ON | PREP_IN | {"of", "there", "here"}:
                break  # "still out on the table", "out of the box": where it is, not switched off
            if w in ("on", "off") and k + 1 < len(words) and (words[k + 1] in ARTICLES | PRONOUNS | {"floor"} or (
                    words[k + 1] in PLACE_AFTER_ON and k + 1 not in self.commas)) \
                    and not (skipped and skipped[-1] in ("switched", "turned")):
                break  # `on the table`, `with a book on top` are places, not `switched on`
            if w == "off" and skipped and skipped[-1] in FALLS:
                break  # "it has slipped off", "if it fell off": the fall's particle, not switched off
            if w == "used" and not self._used_ends(words, k):
                break  # "the cloth is used for wiping": the passive of "use", with its complement
            if k + 1 < len(words) and words[k + 1] in TOWARDS and set(skipped) & PERFECT:
                break  # "has blown onto the floor", "have smashed into it": a motion, not a state
            if k in self.starts:
                break  # "clean the mark, wet wipes ...": the first word of another thing's name
            found.append((w, local_neg, relative))
            k += 1
            j = k
            while j < len(words) and words[j] in {"and", "but", "or", ","}:
                j += 1
            extra: list[str] = []
            while j > k and j < len(words) and words[j] in DESCRIPTIVE | NEGATIONS and len(extra) < 3:
                extra.append(words[j])  # "not empty but is dirty": each state has its own negation
                j += 1
            if j < len(words) and words[j] in STATE_WORDS:
                if extra:
                    local_neg = any(_negation(x) for x in extra)
                k = j
        # "a dirty plate", "wet ones", "a full mop bucket", but not "open it"
        named = self._past_modifiers(words, m.start - 1) + 1 if m.kind == "role" else m.start
        j = named - 1 if m.kind == "role" or words[m.start] in ("one", "ones") else -1
        while j >= 0 and words[j] in set(STATE_WORDS) | {"and", "but"} and words[j] not in ("on", "off"):
            if words[j] in STATE_WORDS:
                found.append((words[j], False, True))
            j -= 1
        # "grab a clean towel from the cupboard": the state a thing is taken in from its source is
        # presupposed with the source (`Fact.presupposed`)
        source = words[m.end:m.end + 1] == ["from"] or words[m.end:m.end + 2] == ["out", "of"]
        taken = source and _taken(words, named)
        out = []
        for w, neg, modifier in found:
            flag, pol = STATE_WORDS[w]
            for r in m.roles:
                if w == "used" and not self._carried(r):
                    continue  # a used towel or mug is dirty, a used bath or dishwasher is not (`_used`)
                out.append(Fact(r, f"state({r}, {flag})", "state", flag, negated=neg != (not pol),
                                modifier=modifier, presupposed=taken and modifier))
        return out

    def _used(self, words: list[str], m: Mention, negated: bool) -> list[Fact]:
        """"Used the bath towel?", "if you didn't use it", "have you used the mug?": that someone
        used a thing says it is dirty, as "a used towel" does (`STATE_WORDS`): a verb of using
        (`USING`) right before the thing, opening the clause or after its subject or negation
        ("use the sponge" is an instruction, "the cloth is used" a passive: neither)."""
        j = m.start - 1
        while j >= 0 and words[j] in ARTICLES:
            j -= 1
        if m.kind not in ("role", "pronoun") or j < 0 or words[j] not in USING:
            return []
        before = [w for w in words[:j] if w not in LEAD_INS]
        if before[-1:] and before[-1] in USERS or not before and words[j] == "used":
            # (a carried thing: a used towel or mug is dirty, a used dishwasher is not)
            return [Fact(r, f"state({r}, dirty)", "state", "dirty", negated=negated) for r in m.roles
                    if ("dirty" not in FITTED or "dirty" in self.capable.get(r, FITTED))
                    and self._carried(r)]
        return []

    def _used_ends(self, words: list[str], k: int) -> bool:
        """Whether "used" at `k` ends its clause as its predicate ("if it's been used, wash it",
        "Used? Then it goes in the basket", "if it was used last night"): the clause's end, a
        comma, a word going on to another clause, or an adverbial of time (`TRAILING_ADVERBIALS`).
        So said, that a thing has been used says it is dirty, as "a used towel" does; with a
        complement ("is used for wiping", "is used by the staff", "as a mat") it is the passive
        of "use", which says nothing of the thing's state."""
        rest = tuple(words[k + 1:])
        return not rest or k + 1 in self.commas or rest[0] in GOING_ON \
            or any(rest[:len(a)] == a for a in _ADVERBIAL_WORDS) or self._used_once(words, k)

    @staticmethod
    def _used_once(words: list[str], k: int) -> bool:
        """Whether "used" at `k` with a complement of what for or by whom tells of one occasion, not
        of the thing's purpose: in the past or the perfect, or opening its clause ("if it was used
        by a guest", "if the cup has been used for coffee"), and not for a deed ("is used for
        wiping" is what it is for)."""
        rest = words[k + 1:k + 3]
        if len(rest) < 2 or rest[0] not in ("for", "by") or rest[1].endswith("ing"):
            return False
        before = words[k - 1] if k > 0 else ""
        return before in ("was", "were", "been") or k == 0 or before in LEAD_INS or before in ("-", ",")

    def _past_modifiers(self, words: list[str], j: int) -> int:
        """The word before the modifier nouns (at most `MODIFIER_NOUNS`) that end at `j`: in "a full
        mop bucket", "a dirty dish towel" the state is said of the thing even where the task's
        name for it is only the head noun, so the words between are skipped when the reader walks
        back for a state. A modifier noun is one the lemmatiser knows as a noun, the reader has no
        meaning for, and that starts no mention of its own."""
        skipped = 0
        while (j >= 0 and skipped < MODIFIER_NOUNS and j not in self.starts and self._unknown(words[j])
               and getAllLemmas(words[j]).get("NOUN")):
            j -= 1
            skipped += 1
        return j

    def _pp_at(self, words: list[str], k: int) -> int:
        """End of a short prepositional phrase `on the coffee table` starting at k, else 0; after a
        preposition of place only (`SPATIAL_PREPS`), also without an article, as notes write it
        ("Desk lamp over chart table left on": the state is the lamp's)."""
        if words[k] not in PREP_ON | PREP_IN | {"at", "by", "near", "under"} | SPATIAL_PREPS | BESIDE_PREPS:
            return 0
        if words[k] == "next":
            if words[k + 1 : k + 2] != ["to"]:
                return 0  # "the bin next week": no place
            k += 1  # "the mug next to the kettle": one preposition
        if words[k + 1 : k + 2] in (["there"], ["here"]):
            return k + 2  # "the ceiling fan in there is broken", "the mop out here is wet": the state is the fan's
        toks = [(w, 0, 0) for w in words[k + 1 : k + 6]]
        for m in self.lex.find_mentions(toks):
            if all(w in ARTICLES for w in words[k + 1 : k + 1 + m.start]):
                return k + 1 + m.end
        # a place the task has no role for ("the candle on the coffee table is burning")
        j = k + 1
        while j < len(words) and words[j] in ARTICLES:
            j += 1
        end = j
        while end < min(j + 2, len(words)) and words[end].isalpha() and words[end] not in (
                STATE_WORDS.keys() | DESCRIPTIVE | NEGATIONS | MOTION | PREP_ON | PREP_IN | {"and", "or", "but"}):
            end += 1
        return end if (j > k + 1 or words[k] in SPATIAL_PREPS | BESIDE_PREPS) and end > j else 0

    def _attribute(self, words: list[str], m: Mention, negated: bool) -> list[Fact]:
        k = m.end
        while k < len(words) and words[k] in DESCRIPTIVE | {"made", "of", "kind", "type", "sort", "a", "an"}:
            k += 1
        after = words[k : k + 1]
        if after and after[0] in STATE_WORDS and words[k + 1:k + 2] in (["and"], ["but"]):
            after = words[k + 2 : k + 3]  # "if it's dirty and white": a value joined to a state
        before = words[max(0, m.start - 1) : m.start]
        fixed = {v for attrs in self.lex.fixed.values() for v in attrs.values()}
        out = []
        for w in [*after, *before]:
            if w in fixed:
                continue
            for r in m.roles:
                hit = self.lex.attribute_of(r, w)
                if hit is not None:
                    key, value = hit
                    # "a dirty white one goes in the washing machine": an indefinite "one" with
                    # the value before it describes which of its kind is meant, as "a ripe one" does
                    # (or a bare plural "ones": "dirty white ones go in the washing machine")
                    one = bool(before) and w == before[0] and words[m.start] in ("one", "ones") and (any(
                        x in ("a", "an") for x in words[max(0, m.start - 3):m.start - 1]) or m.start in self.plural_at
                        and not set(words[max(0, m.start - 3):m.start - 1]) & DEFINITE_PLURAL)
                    out.append(Fact(r, f"attr({r}, {key}, {value})", "attr", key,
                                    negated=negated and bool(after) and w == after[0], modifier=one))
        return out

    def attribute_classes(self, text: str) -> dict[tuple[str, str], list[str]]:
        """Attribute values used as classes (`a red box for dolls`, `novels go on shelf one`)."""
        toks = tokens(expand(text))
        words = [t[0] for t in toks]
        mentions = self.lex.find_mentions(toks)
        covered = {i for mm in mentions for i in range(mm.start, mm.end)}
        fixed = {v for attrs in self.lex.fixed.values() for v in attrs.values()}
        found: dict[tuple[str, str], list[str]] = {}
        for i, w in enumerate(words):
            if w in fixed or (i in covered and not any(
                    m.start == i and m.end - m.start > 1 for m in mentions)):
                continue
            for role in self.lex.roles:
                hit = self.lex.attribute_of(role, w)
                if hit is None:
                    continue
                near = [mm for mm in mentions if 0 < mm.start - i <= 2]
                if w in COLOR_WORDS:
                    if not near or role not in near[0].roles:
                        continue  # a colour word only describes the object it precedes
                elif near and near[0].start == i + 1 and role not in near[0].roles:
                    continue  # "the metal rack": a value right before another thing's name is that thing's
                values = found.setdefault((role, hit[0]), [])
                if hit[1] not in values:
                    values.append(hit[1])
        for (role, key), value in self._contrasted_kinds(text):
            values = found.setdefault((role, key), [])
            if value not in values:
                values.append(value)
        return found

    def _contrasted_kinds(self, text: str) -> list[tuple[tuple[str, str], str]]:
        """"A bill goes into the filing cabinet; any other document goes on the bookshelf", "a
        novel belongs on the top shelf, every other book on the lower one": an indefinite noun no
        role names, the subject of a clause, set against "other <thing>" later in its sentence, is
        a kind of that thing (a derived `kind`, as in "it is a bill")."""
        out: list[tuple[tuple[str, str], str]] = []
        for sentence in re.split(r"(?<=[.!?])\s+", expand(text)):
            toks = tokens(sentence)
            words = [t[0] for t in toks]
            mentions = self.lex.find_mentions(toks)
            covered = {i for m in mentions for i in range(m.start, m.end)}
            for m in mentions:
                if m.kind != "role" or m.start < 1 or words[m.start - 1] not in CONTRAST:
                    continue
                for i in range(m.start - 3):
                    if (words[i] in ("a", "an") and i + 1 not in covered and self._unknown(words[i + 1])
                            and words[i + 2] in MOTION | DESCRIPTIVE):
                        out += [((r, "kind"), words[i + 1]) for r in m.roles]
        return out


#: words that set a thing against the kinds named before it ("any other document")
CONTRAST = frozenset({"other"})
#: words of an "already" clause that say nothing of a place or a state
ALREADY_FILLER = frozenset({"already", "is", "are", "be", "was", "were", "been", "not", "still", "yet"})
_RANK = {"exists": 0, "location": 1, "state": 2, "attr": 3}
#: words that end a predicate adjective: "one that is not ripe yet belongs in the bowl"
_AFTER_PREDICATE = frozenset({"yet", "enough", "anymore", "already", "now", "and", "or", "but"}) | MOTION
#: how many modifier nouns may stand between a state word and the head of a thing's name ("a
#: full mop bucket", "a dirty dish towel"): two covers the compounds of household speech, more
#: would let a state word reach across a clause
MODIFIER_NOUNS = 2
#: words with a meaning of their own, never an attribute read from the wording
_KNOWN_WORDS = (frozenset(STATE_WORDS) | DESCRIPTIVE | MOTION | ACTIONS | ARTICLES | PARTS | PRONOUNS
                | NEGATIONS | UNCERTAIN | ABSENT | AVAILABILITY | PREP_ON | PREP_IN | COLOR_WORDS
                | SITUATION_PARTICIPLES | ARRIVALS | frozenset(
                    {"other", "another", "else", "same", "different", "done", "finished", "ready",
                     "sure", "fine", "alone", "there", "here", "where", "what", "whatever", "which",
                     "whichever", "yet", "enough", "anymore", "and", "but", "then", "also", "only",
                     "new", "old", "spare", "fresh", "own", "whole", "nearest", "next", "last",
                     "first", "second", "third", "kind", "sort", "type", "need", "time", "for",
                     "with", "without", "from", "place", "way", "lot", "mess", "problem", "close",
                     "switch", "turn", "shut", "check", "use", "wipe", "clean", "empty", "fill"}))


def _respectively(facts: list[Fact]) -> list[Fact]:
    """"my bat and my racket go in the storage bin and on the bench, respectively": a list of
    things and a list of places as long pair in order, the first thing with the first place; the
    places of one reading (goals or conditions) and their things are paired apart. Lists of
    unequal length pair nothing (each thing keeps every place)."""
    out: list[Fact] = []
    for goal in (False, True):
        placed = [f for f in facts if f.kind == "location" and f.goal == goal]
        things = list(dict.fromkeys(f.subject for f in placed))
        places = list(dict.fromkeys(f.key for f in placed))
        if len(things) < 2 or len(things) != len(places):
            out += placed
            continue
        out += [f for f in placed if things.index(f.subject) == places.index(f.key)]
    return [f for f in facts if f.kind != "location"] + [f for f in facts if f in out]


def _question(subject: str, kind: str, key: str, targets: list[str]) -> str:
    s = subject.replace("_", " ")
    if kind == "exists":
        return f"Is there a {s}?"
    if kind == "state":
        return f"Is the {s} {key.replace('_', ' ')}?"
    if kind == "attr":
        return f"What is the {key} of the {s}?"
    return f"Where is the {s}: " + ", ".join(t.replace("_", " ") for t in targets) + " or elsewhere?"


#: brief (canonical JSON) -> (catalog, analysis); generators ask about one brief many times
_MEMO: dict[str, tuple[Catalog, TaskAnalysis]] = {}


def analyse(brief: Mapping[str, Any], catalog: Catalog | None = None) -> TaskAnalysis:
    """Analyse a task brief (`id`, `description`, `rooms`, `roles`).

    A pure function of the brief and the catalog, so it is memoised per brief; callers get
    their own copy and may change it.
    """
    catalog = catalog or load_catalog()
    key = json.dumps(brief, sort_keys=True, default=str)
    hit = _MEMO.get(key)
    if hit is None or hit[0] is not catalog:
        if len(_MEMO) >= 64:
            _MEMO.clear()
        hit = _MEMO[key] = (catalog, _analyse(brief, catalog))
    return _copy(hit[1])


#: a state atom of a factor's value ("on(shirt, floor) and state(shirt, dirty)")
_STATE_ATOM = re.compile(r"state\([a-z0-9_]+, [a-z_]+\)")


def stated_states(brief: Mapping[str, Any], catalog: Catalog | None = None) -> list[str]:
    """States the description gives a thing outright, in a plain statement, that no factor asks
    ("the ceiling fan in there spoil already", "the kettle in the shed is broken", "the fridge
    door is open, the seal went"): the environment keeps them, as it keeps the places the text
    states (`described_placements`), so `offline.realise` sets them where no situation fact
    speaks of the state. A state read from a modifier, a goal or a derived word is no such fact."""
    a = analyse(brief, catalog)
    roles = set(brief.get("roles") or {})
    capable = _capabilities(brief, catalog) if catalog is not None else {}
    # a state any factor's value speaks of, alone or in a conjunction, is asked
    asked = {atom for f in a.factors for v in f.values.values() for atom in _STATE_ATOM.findall(v)}
    out: list[str] = []
    for c in a.clauses:
        # an instruction ("open it, load them, shut the door") states no state of the scene
        if c.role != "statement" or imperative(re.findall(r"[a-z0-9']+", c.text.lower())):
            continue
        for f in c.facts:
            if f.kind != "state" or f.goal or f.modifier or f.derived or f.subject not in roles:
                continue
            # the statement's subject is the thing it names first ("the ceiling fan in there spoil
            # already"): a state the clause's words give a thing named later ("dirty white ones go
            # into the washing machine (open it, ...)") is an instruction's or another thing's
            if not c.mentions or c.mentions[0] != f.subject:
                continue
            # a state the thing's kind cannot take ("the cup ... on") is a misreading, not a fact
            if f.key in FITTED and f.key not in capable.get(f.subject, FITTED):
                continue
            if f.condition in asked or f"not {f.condition}" in asked:
                continue
            said = f"not {f.condition}" if f.negated else f.condition
            if said not in out:
                out.append(said)
    # a state said both ways ("The shirt on the floor is dirty ... The shirt on the floor is
    # clean" in a quiz's questions) states cases, not the scene: neither is kept
    both = {c.removeprefix("not ") for c in out if c.startswith("not ")} & set(out)
    return [c for c in out if c.removeprefix("not ") not in both]

def _copy(a: TaskAnalysis) -> TaskAnalysis:
    """A copy whose containers are the caller's own (clauses and tuples are immutable)."""
    return TaskAnalysis(
        sentences=list(a.sentences),
        clauses=list(a.clauses),
        factors=[replace(f, values=dict(f.values), consequences=list(f.consequences), under=list(f.under),
                         roles=set(f.roles),
                         context=list(f.context), raw_context=list(f.raw_context),
                         places=set(f.places)) for f in a.factors],
        groups=[list(g) for g in a.groups],
        group_roles=[set(r) for r in a.group_roles],
        other_roles=set(a.other_roles),
    )


#: adverbs of a norm ("Normally a fresh diaper is lying on the changing table"): a statement
#: with one says how things should be, not what the situation is
NORMS = frozenset({"normally", "usually", "generally", "ordinarily", "typically"})


def _norm(clause: Clause) -> bool:
    return bool({w for w, _, _ in tokens(clause.text)} & NORMS)


_HERE = frozenset({"there", "here"})
#: a room said as the place of a finding ("if you find any in the media room", "should you spot
#: one in this room"): where the finder is, "here"
_THIS_ROOM = re.compile(r"\b(?:in|inside)\s+(?:the|this)\s+(?:[a-z]+\s+)?room\b", re.I)
#: the indefinite pronouns of "if you find one there", "should you spot any there": one of the
#: things the clause before said may be there, not whether such a thing exists at all
FOUND_ONE = frozenset({"one", "ones", "any", "some"})


def _state_of(f: Fact, role: str) -> Fact:
    """The state fact `f` said of `role` instead of its subject."""
    return replace(f, subject=role, condition=f"state({role}, {f.key})")


def _second_case(reader: _Reader, clauses: list[Clause], text: str, facts: list[Fact]) -> list[Fact]:
    """A case that names nothing ("Clean:", "Clean?") after another case of the same state
    ("Dirty: open the dishwasher, put it in, shut the door. Clean: up on the shelf") speaks of
    what that case asked of, not of a thing only its instructions named (the dishwasher): cases
    of one state set side by side are the cases of one thing. Only instructions may stand
    between them; a thing named in a heading or a statement between ("The sink: dirty?") is
    spoken of anew."""
    if not facts or any(f.kind != "state" for f in facts) or len({(f.subject, f.key) for f in facts}) != 1:
        return facts
    toks = tokens(expand(text))
    if any(m.kind == "role" for m in reader.lex.find_mentions(toks)) or {w for w, _, _ in toks} & PRONOUNS:
        return facts
    for clause in reversed(clauses):
        if clause.role == "condition":
            asked = {f.subject for f in clause.facts if f.kind == "state" and f.key == facts[0].key}
            subject = next(iter(asked)) if len(asked) == 1 else facts[0].subject
            return [_state_of(f, subject) for f in facts]
        if clause.role not in ("consequence", "else") and not (
                clause.role == "statement" and imperative([w for w, _, _ in tokens(expand(clause.text))])):
            return facts
    return facts


def _anaphoric(text: str, facts: list[Fact]) -> bool:
    """A condition with no fact of its own whose words only point back ("if it is not" too; "should
    you find it there": an agent coming upon the thing, `DISCOVERY`)."""
    words = {w for w, _, _ in tokens(_THIS_ROOM.sub(" here ", expand(text)))}
    if words & DISCOVERY and words & AGENTS and words & _HERE and words & FOUND_ONE \
            and all(f.goal or f.kind == "exists" for f in facts):
        # "if you find one there": the one found is one of the things just said to be there
        return words <= ANAPHORIC | {"not"} | DISCOVERY | AGENTS | _HERE | FOUND_ONE
    if any(not f.goal for f in facts):
        return False
    if words & DISCOVERY and words & AGENTS:
        # "if you find it", "if you find one": one of the things just spoken of
        return words <= ANAPHORIC | {"not"} | DISCOVERY | AGENTS | _HERE | FOUND_ONE
    return points_back(text)


def _place_before(clauses: list[Clause], sentence: int, names: tuple[str, ...]) -> bool:
    """Whether a clause of this sentence or the one before says where one of `names` is, goes or
    lives: what a pronoun's "if it is not there" may point back to ("The remote goes on the TV
    stand. If it is not there, ..."). With no such place ("Have a look at the mug. If it isn't
    there, tell me"), "there" is the scene itself and the condition asks whether the thing is
    there at all."""
    return any(f.kind == "location" and f.subject in names for cl in clauses if cl.sentence >= sentence - 1
               for f in cl.facts)


def _there_before(clauses: list[Clause], sentence: int, names: tuple[str, ...],
                  words: list[str]) -> list[Fact]:
    """What a presence said with an existential and a deictic "there" ("if there's a bin bag (down)
    there", "is there a cup over there?") asks: whether the thing is at the place a clause of this
    sentence or the one before put it (`_place_before`'s reach; a location said of it, not a
    goal unless others habitually put it there, whatever its polarity there: "there's always one
    left on the floor, isn't there"). A
    presence with no deictic "there" after the thing ("if there's a bin bag, ...") or no such
    place before asks whether the thing is there at all: nothing here."""
    if "there" not in words[1:] or sum(w in ("there", "theres") for w in words) < 2:
        return []  # (a chat's "theres" is the existential too)
    k = len(words) - 1 - words[::-1].index("there")
    if words[k - 1] in _BE_WORDS | {"there"} or k < len(words) - 2:
        return []  # the deictic after the thing ends the condition ("... down there", "... there now")
    for cl in reversed(clauses):
        if cl.sentence < sentence - 1:
            break
        # (where others habitually leave a thing is where it may be: "The lodgers leave their cups
        # on the windowsill", as `_antecedent` reads it)
        habit = _habit_of_others(cl.text)
        said = [replace(f, negated=False, goal=False, modifier=False, definite=False, home=False)
                for f in cl.facts if f.kind == "location" and f.subject in names and not f.home
                and (not f.goal or habit)]
        if said:
            return said[:1]
    return []


#: the subjects of a conjunct about people, not the scene ("she hasn't come back", "you leave
#: before six", "nobody's collected it"); "they" and "it" may be things, and are left out
_PERSON_CONJUNCT = (SUBJECTS - {"they"}) | _NOBODY | {"everyone", "everybody"}


def _conjunct_presence(words: list[str]) -> bool | None:
    """`presence_asked` of the one conjunct of a condition that asks it, when every other
    conjunct is about people ("If she hasn't come back and the bag's still here", "When we're
    done and the kettle's still here"): what the people do or have done asks nothing of the
    scene, so the condition asks what its other conjunct asks alone. None otherwise (two things'
    conditions, "if the lamp is on and the bag's still here", are read as they were)."""
    parts: list[list[str]] = [[]]
    for w in words:
        if w == "and":
            parts.append([])
        else:
            parts[-1].append(w)
    if len(parts) < 2 or not all(parts):
        return None
    found = [presence_asked(p) for p in parts]
    asked = [f for f in found if f is not None]
    if len(asked) == 1 and all(p[0] in _PERSON_CONJUNCT for p, f in zip(parts, found, strict=True) if f is None):
        return asked[0]
    return None


def _absence_of_asked(facts: list[Fact], said: str, lex: Lexicon, clauses: list[Clause], sentence: int) -> list[Fact]:
    """An absence that names nothing ("Gone - great, nothing to do", "Gone? Fine.", "Not here:
    nothing to do") right after a condition asking whether a thing is there ("If the bag's still
    here, lock it in the cupboard and shut the door."): that thing's absence, the other answer to
    the question just asked, not the absence of whatever the instruction handled last (the
    cupboard). `facts` unchanged otherwise."""
    if not facts or not all(f.kind == "exists" and f.negated for f in facts) \
            or any(m.kind == "role" for m in lex.find_mentions(tokens(expand(said)))):
        return facts
    everything = tuple(dict.fromkeys(f.subject for cl in clauses for f in cl.facts))
    asked = _presence_asked(clauses, sentence, everything)
    return [Fact(r, f"exists({r})", "exists", negated=True) for r in asked[:1]] if asked else facts


def _presence_asked(clauses: list[Clause], sentence: int, names: tuple[str, ...]) -> tuple[str, ...]:
    """Which of `names` a condition of this or the previous sentence asked the presence of
    (`exists`, not negated: "if you find a wallet"), the nearest such condition first."""
    for cl in reversed(clauses):
        if cl.sentence < sentence - 1:
            break
        if cl.role == "condition":
            asked = tuple(f.subject for f in cl.facts if f.kind == "exists" and f.subject in names)
            if asked:
                return asked
    return ()


def _come_upon(clauses: list[Clause], sentence: int, text: str) -> tuple[list[Fact], tuple[str, ...]]:
    """What "if you find it / one" asks when the clause it points back to says nothing of where
    or how the thing is ("Laptops get left behind. If you find one, ...", "somebody's reported a
    wallet left in there. If you find it, ..."): whether the thing that clause names is there at
    all. Nothing for a condition that is no coming upon, or with no such clause."""
    words = {w for w, _, _ in tokens(expand(text))}
    if not (words & DISCOVERY and words & AGENTS):
        return [], ()
    # the sentence before, or the one before that when it names nothing ("I've left my spare key
    # somewhere. I can't remember whether I gave it back or not. If you come across it, ...")
    said = [cl for cl in clauses if cl.mentions and cl.role in ("statement", "scene", "uncertain", "consequence")]
    reach = sentence - 1 if any(cl.sentence == sentence - 1 for cl in said) else sentence - 2
    for cl in reversed(clauses):
        if cl.sentence < reach:
            break
        if cl in said:
            r = cl.mentions[0]
            return [Fact(r, f"exists({r})", "exists")], (r,)
    return [], ()


#: nouns of persons, as a text names the people a time is told by ("Families like it left going
#: while they sit with him. Once they've gone, ..."): `clauses.PERMITTED`'s nouns and the
#: households' and visitors' other names, as `tokens` gives them (singular)
PEOPLE_NOUNS = frozenset(singular(w) for w in PERMITTED if w not in SUBJECTS) | frozenset({
    "family", "parent", "people", "friend", "relative", "mourner", "patient", "client", "child"})


#: adverbs that make what someone does a habit ("always", "never" too: "the door never gets shut")
_HABIT_ADVERBS = FREQUENCY | NORM_ADVERBS | {"never"}
#: the adverbs that may stand between "be" and a ranked "one" (`_says_who`; `_HABIT_ADVERBS`
#: holds them as `tokens` gives them too, "always" -> "alway")
_RANK_ADVERBS = _HABIT_ADVERBS | {"still"}


def _habit_of_others(text: str) -> bool:
    """A clause saying what someone other than the reader habitually does ("The band kept
    dumping them on the floor", "The Y7s always manage to leave a pair of scissors on the
    floor"): a habit (`sentences.habitual`) or a frequency adverb, and no "you" acting."""
    words = re.findall(r"[a-z']+", expand(text).lower())
    return (habitual(words) or bool(set(words) & _HABIT_ADVERBS)) and not set(words) & {"you", "u"}


def _antecedent(clauses: list[Clause], sentence: int, pointing: set[int]) -> tuple[list[Fact], tuple[str, ...]]:
    """What an anaphoric condition points back to: the situation described by the nearest clause
    of this or the previous sentence that describes one ("Someone keeps leaving the fan running;
    if so, ..."). That clause is then no instruction of its own: it is relabelled a statement."""
    reach = sentence - 1
    for j in range(len(clauses) - 1, -1, -1):
        cl = clauses[j]
        if cl.sentence < reach:
            break
        if j in pointing:  # "If it isn't, fine. If it is, ...": both point to the same clause
            reach = min(reach, cl.sentence - 1)
            continue
        said = [replace(f, modifier=False, definite=False) for f in cl.facts if not f.goal]
        if not said and _habit_of_others(cl.text):
            # "The band kept dumping them on the floor - if they're still there, ...", "The Y7s
            # always manage to leave a pair of scissors on the floor. If you find any there": where
            # others habitually put a thing is where it may be now, not a goal of the reader's
            said = [replace(f, goal=False, modifier=False, definite=False) for f in cl.facts
                    if f.goal and f.kind == "location"]
        if said:
            if cl.role == "consequence":
                clauses[j] = replace(cl, role="statement", cue=None)
            return said, tuple(dict.fromkeys(f.subject for f in said))
    return [], ()


_DASH = re.compile(r"\s+[-\u2013]\s+")


#: how an item of a bulleted list opens its line ("* ", "- ", "• ")
BULLET = re.compile(r"^\s*[*\u2022\u2023\u25e6-]\s+")


def _bullet_items(text: str, sentences: list[str]) -> list[int | None]:
    """Per sentence, the bullet item (its line's number) it belongs to, or None outside a
    bulleted list (fewer than two bullet lines): the sentences of one bullet item are one unit
    of the list, as the clauses of one sentence are ("* Bedroom: table lamp on? -> off.
    Wardrobe doors open? -> close." is one item, said of one room)."""
    lines = text.splitlines()
    if sum(1 for line in lines if BULLET.match(line)) < 2:
        return [None] * len(sentences)
    out: list[int | None] = []
    line, cursor = 0, 0
    for sent in sentences:
        while line < len(lines) and sent not in lines[line][cursor:]:
            line, cursor = line + 1, 0
        if line == len(lines):
            return [None] * len(sentences)
        cursor = lines[line].index(sent, cursor) + len(sent)
        out.append(line if BULLET.match(lines[line]) else None)
    return out


def _speaker(reader: _Reader, text: str, speakers: frozenset[str] = frozenset()) -> bool:
    """A heading that is a speaker's label in a transcript, a chat or a Q&A ("DAD:", "ME:", "Q:",
    "Priya:"): one word that names no thing, room or place of the task, written in capitals, or
    one of `speakers` (`_speakers`)."""
    label = text.strip()
    toks = tokens(expand(label))
    return len(toks) == 1 and label.isalpha() and (label.isupper() or label in speakers) and not (
        reader.lex.find_mentions(toks))


#: a line opened by a capitalised word and a colon ("Priya: morning!!")
_LINE_LABEL = re.compile(r"^[ \t]*([A-Z][a-z]+):", re.M)


def _speakers(reader: _Reader, text: str) -> frozenset[str]:
    """The names of a chat's speakers: capitalised words that open two or more lines before a
    colon ("Priya: ...", "Sam: ...") and mean nothing to the reader (not "Wet:", "Dry:", "Note:"
    ... a word it knows)."""
    counts = Counter(_LINE_LABEL.findall(text))
    return frozenset(w for w, n in counts.items() if n >= 2 and reader._unknown(w.lower()))


def _turn_starts(reader: _Reader, pieces: list[Piece], speakers: frozenset[str]) -> bool:
    """Whether a sentence is a speaker's label alone ("Priya:"): a new turn of a transcript, so
    whatever the turn before left open (a line without a full stop) ends there."""
    return len(pieces) == 1 and pieces[0].role == "heading" and _speaker(reader, pieces[0].text, speakers)


def _instructs(reader: _Reader, text: str) -> bool:
    """The piece after a place heading is an instruction, not what lies there ("On the chair /
    on the floor -> onto the desk", "On the rug: pick it up"): the heading is then a condition
    on the thing spoken of, as a subjectless heading is (`_read_heading`)."""
    toks = tokens(expand(text))
    words = [w for w, _, _ in toks]
    lead = 1 if words[:1] == ["back"] else 0
    goal = len(words) > lead and words[lead] in PLACE_PREPS - {"from", "by", "near", "on", "in"}
    return (goal or imperative(words)) and not any(
        m.kind == "role" and not _placed(words, m) for m in reader.lex.find_mentions(toks))


def _answers_quality(reader: _Reader, heading: str, answer: str) -> bool:
    """Whether a heading whose only reading is a quality the catalog has no attribute for ("Ripe:",
    "Not ripe yet:", said of the thing last spoken of) is answered as a case of that thing: the
    heading names a thing itself, or the piece after it names a thing, a room or the floor ("Ripe:
    fridge", "Unripe -> the fruit bowl") or instructs ("Cracked: bin it"). A heading answered by
    nothing of the scene ("Included: all walking between rooms. Not included: meals, travel
    insurance") heads a list of its own (a question's answer in its next sentence, "A ripe one? It
    goes into the fridge.", is not seen here: kept): it says no quality of the thing, and a factor on it
    decides nothing and makes every environment state a key no task reads."""
    if any(m.kind == "role" for m in reader.lex.find_mentions(tokens(expand(heading)))):
        return True
    toks = tokens(expand(answer))
    words = [w for w, _, _ in toks]
    return not words or imperative(words) or _instructs(reader, answer) or any(
        m.kind in ("role", "room", "floor") for m in reader.lex.find_mentions(toks))


#: an instruction's opening verb and the bare noun after it, its article dropped as notes drop
#: it ("open washing machine; put shirt in; close door")
_TELEGRAPHIC = re.compile(r"^(\W*)([A-Za-z]+)(\s+)(?=[A-Za-z])")


def _telegraphic(m: re.Match[str]) -> str:
    """The instruction with "the" before the bare noun after its opening verb when that verb is
    also a state word ("open washing machine", "empty bin") and the clause has no other verb: the
    state is what the instruction brings about, not the thing's state now, as with "open the
    washing machine". A state word before an article, a pronoun or a particle, that is no verb,
    or in a clause with a finite verb of its own ("clean towels go on the rack"), is left alone."""
    verb = m.group(2).lower()
    rest = m.string[m.end():].split(maxsplit=1)
    nxt = rest[0].lower().strip(",.;:") if rest else ""
    if set(re.findall(r"[a-z]+", expand(m.string).lower())) & (CLAUSE_WORDS | FINITE_VERBS):
        return m.group(0)  # "clean towels are on the shelf": a clause with its own verb, its subject's state
    if verb not in STATE_WORDS or verb not in getAllLemmas(verb).get("VERB", ()) or not nxt or (
            nxt in OBJECT_STARTS | PRONOUNS | PREP_ON | PREP_IN or nxt in STATE_WORDS):
        return m.group(0)
    return f"{m.group(1)}{m.group(2)}{m.group(3)}the "


def _goes(reader: _Reader, text: str) -> bool:
    """An instruction that is only a place ("on the shoe rack", "back into the hamper"): where
    the thing spoken of goes."""
    toks = tokens(expand(text))
    words = [w for w, _, _ in toks]
    lead = 1 if words[:1] == ["back"] else 0
    return len(words) > lead and words[lead] in PLACE_PREPS - {"from", "by", "near"} and reader.topic_kind == "role" \
        and bool(reader.topic) and not any(m.kind == "role" and not _placed(words, m)
                                           for m in reader.lex.find_mentions(toks))


#: a purpose after a bare goal ("Dirty -> laundry basket for wardrobe dept."): who or what the
#: place is for, no second thing spoken of
_PURPOSE = re.compile(r"\s+for\s+[^,;:.!?]*?(?=[.!;]?\s*$)", re.I)


def _bare_goal(reader: _Reader, text: str) -> tuple[str, str] | None:
    """An instruction that is only the name of something that holds things ("dirty? kitchen
    sink.", "wet -> laundry basket", a note's shorthand, "Dirty -> laundry basket for wardrobe
    dept.": its purpose `_PURPOSE` dropped): where the thing spoken of goes, as if its
    preposition were said ("in" a container that is no surface, else "on"), and the text without
    the purpose; None for any other text, or when nothing is spoken of."""
    text = _PURPOSE.sub("", text)
    toks = tokens(expand(text))
    words = [w for w, _, _ in toks]
    found = reader.lex.find_mentions(toks)
    roles = [m for m in found if m.kind == "role"]
    covered = {i for m in found for i in range(m.start, m.end)}
    if len(roles) != 1 or len(roles[0].roles) != 1 or reader.topic_kind != "role" or not reader.topic \
            or roles[0].roles[0] in reader.topic \
            or any(i not in covered and w not in ARTICLES | {"back", "instead"} for i, w in enumerate(words)):
        return None
    kind = reader.kinds.get(roles[0].roles[0])
    if kind is None or not (kind.container or kind.surface):
        return None
    return ("in" if kind.container and not kind.surface else "on"), text


#: imperatives that take a thing up to use it where the work is, and put it nowhere: a place said
#: on or in after their object is where the thing is ("use the wet wipes on the tea table", "grab
#: the torch in the drawer"), not where it goes, as after "put" (`_where_taken_from`)
TAKEN_FOR_USE = frozenset({"use", "grab", "fetch", "borrow"})


def _where_taken_from(said: str, facts: list[Fact]) -> list[Fact]:
    """"Use the wet wipes on the tea table if there are any", "grab the spare bulb in the drawer
    if there is one": an instruction that takes a thing for use (`TAKEN_FOR_USE`), under a
    condition of its availability, says where the thing is, and the condition asks whether it is
    there (as "wipe it with the paper towels on the counter if there are any" does); a place it
    is moved to ("use it, then put it in the drawer", "into", "to") stays a goal, and so does a
    room ("borrow the stepladder in the garage if there is one" asks whether there is one at all)."""
    words = [w for w, _, _ in tokens(expand(said).lower())]
    lead = next((i for i, w in enumerate(words) if w not in LEAD_INS | SOFTENERS), len(words))
    if words[lead:lead + 1] and words[lead] in TAKEN_FOR_USE and not set(words) & (MOTION | {"into", "onto", "to"}):
        return [replace(f, goal=False) if f.kind == "location" and f.goal and f.condition.startswith(("on(", "inside("))
                else f for f in facts]
    return facts


def _available(reader: _Reader, text: str) -> list[Fact]:
    """"clean it with the microfibre cloth if any": with no place said, whether there is one of
    the thing named last before the cue (not a place it is used on or kept in)."""
    low = expand(text).lower()
    cue = re.search(r"\b(?:if|in case)\b", low)
    toks = tokens(low[: cue.start()] if cue else low)
    words = [w for w, _, _ in toks]
    things = [m for m in reader.lex.find_mentions(toks) if m.kind == "role" and not _placed(words, m)]
    if things:
        return [Fact(r, f"exists({r})", "exists") for r in things[-1].roles]
    after = [w for w, _, _ in tokens(low[cue.end():])] if cue else []
    if not words and after[:1] in (["it"], ["they"]) and reader.topic_kind == "role":
        # "Wallet. If it's there, lost property basket": a cue opening the text with a pronoun
        # subject asks whether the thing the pronoun speaks of is there at all
        return [Fact(r, f"exists({r})", "exists") for r in reader.topic]
    return []


def _in_time_clause(words: list[str], i: int) -> bool:
    """Whether the pronoun at word `i` is the subject of a time clause: a time word
    (`_TIME_OPENERS`) right before it, or before "the last/rest/first of" it ("when the last of
    them's gone")."""
    k = i - 1
    if k >= 2 and words[k] == "of" and words[k - 1] in ("last", "rest", "first", "all") and words[k - 2] == "the":
        k -= 3
    elif k >= 1 and words[k] == "of" and words[k - 1] == "all":
        k -= 2
    return k >= 0 and words[k] in _TIME_OPENERS


#: a subject before a form of "be": "there" right after them is a place ("it's there", "they are
#: still there"), not the existential "there" ("there is a towel", "is there a towel")
_THERE_SUBJECTS_BE = frozenset({"it", "they", "he", "she", "this", "that"})


#: what stands between a place preposition and a thing named after it ("on the towel", "in my mug")
_PLACE_DETERMINERS = ARTICLES | frozenset({"my", "your", "his", "her", "its", "our", "their", "this", "that"})


def _existential_place(before: list[str], pronoun: bool) -> bool:
    """Whether the thing named after `before` is the place of an existential ("is there a film
    on it?", "if there is a stain on the towel", "should there be water in it"): a place
    preposition right before it (a determiner between for a noun), and before that an
    existential "there". What may or may not be there is the existential's own thing (no role:
    a role said there is read first); the thing named is where."""
    k = len(before) - 1
    while not pronoun and k >= 0 and before[k] in _PLACE_DETERMINERS:
        k -= 1
    return k >= 1 and before[k] in PREP_IN | PREP_ON and _existential(before[:k])


def _existential(before: list[str]) -> bool:
    """Whether `before` holds an existential "there" ("there may or may not be a loaf", "is there
    a cloth"), not the adverb of place after a subject and its verb ("if it is still there, the
    basket": the basket is no thing whose presence is asked)."""
    for k, w in enumerate(before):
        if w != "there":
            continue
        j = k - 1
        while j >= 0 and before[j] in ("still", "already", "not"):
            j -= 1
        if j >= 1 and before[j] in _BE_WORDS and before[j - 1] in _THERE_SUBJECTS_BE:
            continue
        # (the twenty-first session) after a verb of the agent's own and before no "be" or modal,
        # "there" is where they are: "When you finish up there at night it should be off", "once
        # you get there"; "I think there is a cloth" is still an existential
        lemmas = getAllLemmas(before[j]) if j >= 0 else {}
        if j >= 0 and "VERB" in lemmas and "AUX" not in lemmas and not (
                k + 1 < len(before) and "AUX" in getAllLemmas(before[k + 1])):
            continue
        return True
    return False


#: a sentence opening with "then" (after a condition left without its consequence)
_THEN_OPENS = re.compile(r"^\W*then\b", re.I)


def _taken(words: list[str], start: int) -> bool:
    """Whether the thing at `start` is the object of an instruction of taking (`TAKING_FROM`:
    "take a spare fuse", "grab two clean towels", "get one of the bags"), its verb the clause's
    first word after lead-ins; "if you take a fuse", "the kids take a fuse" are no instruction."""
    j = start - 1
    while j >= 0 and taken_word(words[j]):
        j -= 1
    if j < 0 or words[j] not in TAKING_FROM:
        return False
    lead = j - 1
    while lead >= 0 and words[lead] in LEAD_INS | SOFTENERS:
        lead -= 1
    return lead < 0 or words[lead] in (",", ";", ":", "-", "(")


#: verbs of carrying a thing somewhere, whose list after a colon says where each kind of it goes
#: ("Take it through to the kitchen: a dirty mug in the sink, a clean one on the counter")
_TAKING = frozenset({"take", "bring", "carry"})


def _elaborates(clauses: list[Clause], sentence: int, text: str) -> bool:
    """The piece has no verb of its own (no finite or modal verb, no action) and follows, in the
    same sentence, a clause whose verb moves things (`MOTION`): it lists what goes where. Items
    before it that are such a list's items themselves (their places all goals: "put each thing in
    its place: the book on the shelf; the alarm clock on the nightstand; the phone on the desk")
    carry the list on to it."""
    last = len(clauses) - 1
    while last > 0 and clauses[last].sentence == sentence and clauses[last].role == "statement" and any(
            f.goal and f.kind == "location" for f in clauses[last].facts) and all(
            f.goal for f in clauses[last].facts if f.kind == "location") and _verbless(clauses[last].text):
        last -= 1
    if last < 0 or clauses[last].sentence != sentence or clauses[last].role not in ("statement", "consequence"):
        return False
    before = {w for w, _, _ in tokens(expand(clauses[last].text))}
    return bool(before & (MOTION | _TAKING)) and _verbless(text)


#: a request with no verb: a plea closing it, with at most thanks or a place it must not go after
#: it ("Mugs in the sink please", "... please, not on the pipes", "... pls, ta"), or opening it
_PLEA = re.compile(
    r"^(?:\W*(?:please|pls|plz)\b[\s,:-]+(?P<after>.+?)"
    r"|(?P<before>.*?\w)[\s,]+(?:please|pls|plz)\b(?:\W*(?:(?:and\s+)?(?:thank\s+you|thanks|thx|ta|cheers)\b)?"
    r"|[\s,]+not\s+(?:on|in|into|onto|under|by)\b[^.;!?]*))\W*$", re.I | re.S)


def _verbless_request(text: str) -> bool:
    """Whether a piece is a request with no verb of its own (`_PLEA`, the rest `_verbless`):
    "Wet towels in the basket please", "Cups in the dishwasher pls, not in the sink"; not
    "Plates on the table please clear them away", whose plea opens an instruction of its own."""
    m = _PLEA.match(text.strip())
    return m is not None and _verbless(m.group("after") or m.group("before"))


def _verbless(text: str) -> bool:
    """Whether a piece has no verb of its own (`_elaborates`): no finite or modal verb, action,
    verb of moving or description, no hedge."""
    words = {w for w, _, _ in tokens(expand(text))}
    return not words & (CLAUSE_WORDS | ACTIONS | MOTION | DESCRIPTIVE | UNCERTAIN)


def _place_heading(reader: _Reader, text: str) -> bool:
    """The heading is a place where things lie and nothing else ("On the floor", "On the table";
    a room, "In the kitchen:", only says where the instructions happen)."""
    toks = tokens(expand(text))
    mentions = reader.lex.find_mentions(toks)
    return bool(toks) and toks[0][0] in PLACE_PREPS and any(m.kind in ("role", "floor") for m in mentions) and not any(
        m.kind == "room" or m.kind == "role" and not _placed([w for w, _, _ in toks], m) for m in mentions)


def _room_list_heading(reader: _Reader, text: str, after: str) -> bool:
    """The heading is a room alone ("In the living room -") before a list of things it holds ("her
    sofa and the coffee table"): it says where they are, as a place heading does, and asks nothing
    of the thing spoken of before (a room heading before an instruction still says where the
    instruction happens, `_read_heading`)."""
    toks, next_toks = tokens(expand(text)), tokens(expand(after))
    mentions = reader.lex.find_mentions(toks)
    listed = reader.lex.find_mentions(next_toks)
    return bool(toks) and toks[0][0] in PLACE_PREPS and bool(mentions) and all(m.kind == "room" for m in mentions) \
        and any(m.kind == "role" and m.start <= 1 for m in listed) and not imperative([w for w, _, _ in next_toks])


#: words that say an action is done before the instruction is carried out
DONE_WORDS = frozenset({"already"})


def _done_before(clauses: list[Clause], sentence: int, said: str, names: tuple[str, ...]) -> list[Fact]:
    """For a factless condition saying an action is already done to a thing the clause before
    (in the same sentence) moves, that move's goal read as the situation ("unless Maya already
    took it down" = "unless it is already in the bin"); else nothing."""
    if not clauses or clauses[-1].sentence != sentence or not {w for w, _, _ in tokens(expand(said))} & DONE_WORDS:
        return []
    return [replace(f, goal=False, definite=False) for f in clauses[-1].facts
            if f.goal and f.kind == "location" and f.subject in names]


def _cataphor(reader: _Reader, condition: str, main: str) -> tuple[str, ...] | None:
    """The thing a pronoun of a condition put first speaks of when nothing was named just before
    it (the caller's test) and the condition names nothing itself: the first thing its main
    clause names, not after a preposition of place ("If it is still on, switch off the lamp on
    the desk": the lamp, not the desk). None when the condition names a thing, has no "it"/"they", or the main clause names no
    such thing (a thing named in the sentence before stays the pronoun's: "The torch is on the
    stool. If it's on, ...")."""
    toks = tokens(expand(condition).lower())
    if not {w for w, _, _ in toks} & {"it", "they"} or any(
            m.kind == "role" for m in reader.lex.find_mentions(toks)):
        return None
    words = [w for w, _, _ in tokens(expand(main).lower())]
    for m in reader.lex.find_mentions(tokens(expand(main).lower())):
        if set(words[:m.start]) & {"it", "they", "them"}:
            return None  # "If it is dusty, it will be wiped with the cloth": the main clause's own "it"
        lead = m.start - 1
        while lead >= 0 and words[lead] in ARTICLES:
            lead -= 1
        if m.kind == "role" and not (lead >= 0 and words[lead] in PREP_ON | PREP_IN | PLACE_PREPS | _INSTRUMENTAL):
            return m.roles
    return None


#: prepositions of place and means before which a thing is no cataphor's ("switch off the lamp at
#: the wall", "wipe it with the cloth")
_INSTRUMENTAL = frozenset({"at", "with", "using"})


#: verbs whose particle says the state they leave ("switch off the lamp", "turn the lights on",
#: "shut the laptop down"), and what each particle says
_PARTICLE_VERBS = frozenset({"switch", "turn", "flick", "power", "shut"})
_PARTICLES = {"on": "on", "off": "off", "down": "off", "out": "off"}
#: the verbs of an instruction whose particle, right after its pronoun, says the state it leaves
#: (`_undone`: "switch it off", "turn them on", "put it on"): `_PARTICLE_VERBS` and "put", which
#: sets a state only in that tight order ("put the kettle on" may be a place's "on", so
#: `_elided`, which looks a few words on, leaves it out)
_SETTERS = _PARTICLE_VERBS | {"put"}
#: verbs that, said of a running device, switch it off with no particle ("if it's still going kill
#: it", "if the fan is still whirring, stop it"): the state word they mean
_STOPPERS = {"kill": "off", "stop": "off"}
_OBJECT_PRONOUNS = frozenset({"it", "them"})


def _undone(reader: _Reader, condition: str, instruction: str) -> list[Fact]:
    """The state a condition with no fact of its own (or only a made-up attribute, "drawn") asks,
    read off its answer: an instruction
    that sets a state of the thing the condition's pronoun means ("if they've been drawn, open
    them": not open; "if it's been left like that, switch it off": on). Only when both clauses
    speak of the thing by a pronoun, the thing is the topic and can take the state.

    Not `_elided`: that one reads a condition that *says* "already"/"yet" and takes the state from
    anywhere in its instruction; this one reads a condition it cannot read at all, so it trusts
    only an instruction that opens with the setting verb and the pronoun, and answers "not yet"."""
    said = {w for w, _, _ in tokens(expand(condition).lower())}
    words = [w for w, _, _ in tokens(expand(instruction).lower())]
    if not said & {"it", "they"} or not reader.topic or reader.topic_kind != "role" or len(words) < 2:
        return []
    if words[0] in STATE_WORDS and words[1] in _OBJECT_PRONOUNS:
        state = STATE_WORDS[words[0]]  # "open them", "shut it"
    elif words[0] in _SETTERS and words[1] in _OBJECT_PRONOUNS and words[2:3] and words[2] in STATE_WORDS:
        state = STATE_WORDS[words[2]]  # "switch it off", "turn them on"
    elif words[0] in _STOPPERS and words[1] in _OBJECT_PRONOUNS:
        state = STATE_WORDS[_STOPPERS[words[0]]]  # "kill it", "stop it"
    else:
        return []
    flag, result = state
    return [Fact(r, f"state({r}, {flag})", "state", flag, negated=result)
            for r in reader.topic if flag in reader.capable.get(r, frozenset())]


#: verbs whose bare use leaves a thing in a state ("close it", "empty the bin"), as the state word
#: that state is said by: for a condition whose predicate is elided (`_elided`)
RESULT_VERBS: dict[str, str] = {
    "close": "closed", "shut": "shut", "open": "open", "empty": "empty", "fill": "full", "refill": "full",
    "clean": "clean", "wash": "clean", "dry": "dry",
}
#: a note's thanks or plea said after its last clause ("unless they're there already, thx", "...
#: already, cheers"; lemmatised "cheer", "thank"): no word of the condition, so an elided
#: condition ending in one is still read
SIGN_OFFS = frozenset({"thx", "thanks", "thank", "ta", "cheers", "cheer", "ty", "pls", "plz", "please"})

#: the words an elided condition has besides its subject ("if it isn't already", "unless they
#: already are", "if it has not been yet"): no state, place or thing of its own, and a note's
#: thanks or plea (`SIGN_OFFS`: "if not already pls")
_ELIDED_WORDS = ALREADY_FILLER | {"has", "have", "had", "done", "do", "does", "did"} | SIGN_OFFS


def _elided(reader: _Reader, condition: str, names: tuple[str, ...], instruction: str) -> list[Fact]:
    """A condition whose predicate is elided ("close the microwave if it isn't already", "unless
    they already are, turn the lights off", "switch it off if not already"): "already" or "yet" with only a thing's pronoun and
    "be" / "have" says the thing is (not) yet in the state the instruction it goes with leaves it
    in, so that state is asked. The state is the instruction's particle ("switch off", "turn ...
    on") or its verb's result (`RESULT_VERBS`); a place ("put it in the sink unless it already
    is") is `_Reader._already`'s. Only of the thing the pronoun means (or, put first, the thing the
    instruction names).

    Not `_undone`: the condition here says by its "already"/"yet" that the instruction's state is
    asked, so the state may be read further into the instruction and its polarity is the
    condition's own "not"; `_undone` has no such word."""
    words = WORD.findall(expand(condition.split(",")[0]).lower())  # a vocative after a comma ("..., love")
    if not words or words[0] not in ("it", "they", "not", "already") or not set(words) & {"already", "yet"} \
            or not set(words[1:]) <= _ELIDED_WORDS:
        return []
    said = [w for w, _, _ in tokens(expand(instruction).lower())]
    state = ""
    for k, w in enumerate(said):
        particle = next((p for p in said[k + 1 : k + 6] if p in _PARTICLES), None) if w in _PARTICLE_VERBS else None
        if particle is not None:
            state = _PARTICLES[particle]
        elif w in RESULT_VERBS:
            state = RESULT_VERBS[w]
        if state:
            break
    if not state:
        return []
    flag, pol = STATE_WORDS[state]
    things = names or tuple(r for m in reader.lex.find_mentions(tokens(expand(instruction)))
                            if m.kind == "role" for r in m.roles)[:1]
    if not things and set(said) & _OBJECT_PRONOUNS and reader.topic_kind == "role":
        things = reader.topic  # "Kettle: switch it off if not already": the pronoun's thing is the topic
    negated = "not" in words
    # (a state the thing cannot take means the nearest thing that can, as a stated one does: `_fit`)
    return [reader._fit(Fact(r, f"state({r}, {flag})", "state", flag, negated=negated != (not pol))) for r in things]


#: the conjunctions after which a pronoun opening a conjunct with its verb "be" is the subject of
#: the conjunct before ("a plate on the counter and it is dirty"), not a place named in it; so
#: after an alternative's "or" ("if the mug is on the desk, or it's on the floor", "or if it's
#: on the floor": the twenty-first session)
CONJOINED_SUBJECT = frozenset({"and", "but", "or"})
#: the forms of "be" (and "seem", "look") that make that conjunct say a state of the pronoun
COPULAS = frozenset({"is", "are", "was", "were", "seems", "seem", "looks", "look", "feels", "feel"})

#: the determiners that open a heading about a thing that may not be there at all ("A bottle left
#: on the coffee table: if it's empty, ...", "Any book on the bed - if it's a novel, ...")
MAYBE_THERE = frozenset({"a", "an", "any", "some"})


def _indefinite_heading(text: str) -> bool:
    """Whether a heading names its thing with an indefinite determiner ("A mug on the desk:",
    "Any towel on the floor -"): the writer does not know the thing is there, so where it lies
    is asked as well as the condition after the heading; a bare or definite heading ("Towel on
    the shelves: if it's dirty", "The lamp on the desk: if it's on") only says what is spoken
    of and where it is."""
    words = [w for w, _, _ in tokens(expand(text))]
    return bool(words) and words[0] in MAYBE_THERE


#: the words that make a sentence without an instruction a supposition a "Then" sentence answers:
#: a thing absent or a state denied ("no spare bag anywhere", "the lamp is not on") or a state
#: the instruction would set being so already ("the kettle is already on")
SUPPOSED = frozenset({"no", "not", "none", "nothing", "never", "already", "still"})


def _premise_of_then(reader: _Reader, text: str, cut: list[list[Piece]], si: int) -> bool:
    """Whether a sentence that only says how things are, with no instruction of its own, is the
    premise of the next sentence opening with "Then" and an instruction ("Exception: no spare bag
    anywhere in the house. Then just take the full bag out.", "The kettle is already on. Then
    leave it."): said as a supposition, the way "Suppose ..." or a question would say it, when it
    says what is not so or is so already (`SUPPOSED`). A sentence that instructs ("Put the book
    away. Then shut the drawer.") is a step before the next, and a plain description ("The kettle
    is on the counter. Then fill it.") the scene the next step starts from, not a premise."""
    if si + 1 >= len(cut) or not cut[si + 1] or not _THEN_OPENS.match(cut[si + 1][0].text):
        return False
    words = [w for w, _, _ in tokens(expand(text))]
    then = [w for w, _, _ in tokens(expand(_THEN_OPENS.sub("", cut[si + 1][0].text)))]
    then = then[1:] if then[:1] == ["just"] else then
    return bool(set(words) & SUPPOSED) and not imperative(words) and not _instructs(reader, text) \
        and imperative(then)


def _role_after(cut: list[list[Piece]], si: int, pi: int) -> str:
    """The role of the piece after piece `pi` of sentence `si`, whether it ends the sentence's
    heading (the next sentence goes on after a colon) or not; "" after a full stop."""
    if pi + 1 < len(cut[si]):
        return cut[si][pi + 1].role
    # (a question mark ends a heading: "Towel on the floor? If wet, ..." asks where the towel is)
    ended = not cut[si] or cut[si][-1].text.rstrip().endswith((".", "!", "?")) or (
        cut[si][-1].role == "heading" and cut[si][-1].cue == "?")
    return cut[si + 1][0].role if si + 1 < len(cut) and cut[si + 1] and not ended else ""


def _read_heading(reader: _Reader, text: str) -> tuple[list[Fact], tuple[str, ...]]:
    """A heading's facts. A heading without its own subject is said of the object spoken of
    ("Shoes - wet:", "Keys - on the floor or on the console table:"): it reads as `it is ...`."""
    toks = tokens(expand(text))
    words = [w for w, _, _ in toks]
    subject = any(m.kind == "role" and not _placed(words, m) for m in reader.lex.find_mentions(toks))
    if subject or not (reader.heading_topic or reader.topic):
        facts, names = reader.facts(text)
        reader.heading_topic = names[:1] or reader.heading_topic
        return facts, names
    # "Bath towel on the floor? Wet: into the basket. Dry: ...": said of the last heading's
    # object, whatever the instructions between named
    part = WORD.findall(text.lower())[:1]
    if part and part[0] in reader.part_of:
        # "Soil dry -> water it" after "the plant's soil": the state of the part named, its thing's
        return reader.facts(re.sub(rf"^\W*{part[0]}\b", f"the {part[0]} is", text, count=1, flags=re.I))
    reader.topic, reader.topic_kind = reader.heading_topic or reader.topic, "role"
    reader.own_it = True
    try:
        return reader.facts("it is " + text)
    finally:
        reader.own_it = False


#: state flags only some kinds of thing take (a shirt does not open, a towel is not switched on),
#: with the catalog capability that allows each
FITTED_BY = {"open": "openable", "toggled_on": "toggleable", "filled": "fillable"}
FITTED = frozenset(FITTED_BY)
#: a state's sense for a thing that switches but cannot take the state itself: "open" / "closed"
#: said of an air conditioner, a lamp or a television is on / off (Turkish "açık", Chinese "开",
#: Greek "ανοιχτό", Arabic "مفتوح" say both), `_Reader._switched`
SWITCHED_SENSE = {"open": "toggled_on"}
#: prepositions with a sense of place only (not "on", "in": "left on", "plugged in"), after which
#: a bare noun phrase is a place even without an article ("lamp over chart table", "kettle
#: beside sink": `_pp_at`)
SPATIAL_PREPS = frozenset({"over", "above", "below", "beneath", "beside", "behind", "under", "near"})
#: the other words of place a noun phrase's modifier opens ("the mug next to the kettle", "the mop
#: against the fridge", "the towel alongside the sink"): the state said after it is the head's,
#: as after `SPATIAL_PREPS`
BESIDE_PREPS = frozenset({"next", "against", "alongside", "opposite"})


def _capabilities(brief: Mapping[str, Any], catalog: Catalog) -> dict[str, frozenset[str]]:
    """Role -> the `FITTED` flags its category takes (roles of unknown categories are left out)."""
    out: dict[str, frozenset[str]] = {}
    for name, role in dict(brief.get("roles") or {}).items():
        cat = catalog.get(str(role.get("category", "")))
        if cat is not None:
            out[name] = frozenset(flag for flag, attr in FITTED_BY.items() if getattr(cat, attr))
    return out


#: a phrase that distributes what follows over the members of a group just named ("2 cups ...:
#: Dave's cup and Priya's cup. Each one: if dirty, wash it"; "Both of them: if wet, hang them up")
#: (the phrase alone, before its instruction: "Every evening, ..." distributes nothing)
DISTRIBUTIVE = re.compile(r"^\W*(?:for\s+)?(?:each|every|both)(?:\s+(?:one|ones|of\s+them|of\s+these|of\s+those))?"
                          r"(?=\W*$|\s*[:,;\-\u2013])", re.I)


#: "either of them", "any of these", "one of the two": a condition on whichever member of the group
#: just named, asked of each of them as "each one" is; so is "either one" / "neither one" ("Marco's
#: glass and Lena's glass ... If either one is dirty")
ANY_OF = re.compile(r"\b(?:(?:either|neither|any|one|each|both|all)\s+of\s+(?:them|these|those|the\s+two)"
                    r"|(?:either|neither)\s+one)\b|" + r"\b(?:either|neither)(?=\s+(?:has|have|is|was|are|were|gets|got|"
                    r"ends|ended|falls|fell|seems|looks|should|may|might)\b)", re.I)
#: "If either has been left out": "either" alone as the subject, read as "either of them" so that
#: its pronoun takes up the group
#: a plural pronoun ("them", "they", "both", "each of them", "all of them"; not "one of them", a
#: member, nor "either of them": `ANY_OF`) takes up the group just named as a whole: what its
#: sentence says of it, it says of every member ("two cups on the tray: a tea cup and a coffee cup.
#: Wash them if dirty"); `_distributed` spreads only facts said of a member, so a "them" that
#: means one thing named in the plural ("the wet wipes") spreads nothing
PLURAL_REFERENCE = re.compile(r"(?<!\bone of )(?<!\bnone of )\b(?:they|them|themselves|both)\b", re.I)
_BARE_EITHER = re.compile(r"\b(either|neither)(?=\s+(?:has|have|is|was|are|were|gets|got|ends|ended|falls|fell|"
                          r"seems|looks|should|may|might)\b)", re.I)

#: "If both are on": "both" alone as the subject, read as "both of them" (`PLURAL_REFERENCE`)
_BARE_BOTH = re.compile(r"\b(both)(?=\s+(?:are|were|have|had|look|seem|need|get|got|end|ended|fall|fell|"
                        r"should|may|might|still)\b)", re.I)


def _listed(lex: Lexicon, text: str) -> tuple[str, ...]:
    """The things a clause lists first, joined by "and", "or" or commas with nothing but articles
    between ("toothpaste and soap -", "The stapler and the tape belong on ..."), not after a
    preposition: a group a later "either of them" may take up."""
    toks = tokens(expand(text).lower())
    words = [w for w, _, _ in toks]
    things = [m for m in lex.find_mentions(toks) if m.kind == "role" and len(m.roles) == 1]
    run: list[Mention] = []
    for m in things:
        gap = words[run[-1].end:m.start] if run else words[:m.start]
        if run and gap and set(gap) <= {"and", "or"} | ARTICLES | {"your", "my", "our", "his", "her", "their"}:
            run.append(m)
        elif run:
            break
        elif not set(gap) & (PREP_ON | PREP_IN | PLACE_PREPS):
            run = [m]
    return tuple(r for m in run for r in m.roles) if len(run) > 1 else ()


def _members(clauses: list[Clause], kinds: Mapping[str, str], sentence: int,
             lex: Lexicon | None = None) -> tuple[str, ...]:
    """The roles of the group last named: the latest clause of this sentence or the one before
    naming two or more roles of one category (the items of an enumeration), or else saying one
    thing of two or more things ("the salt and pepper shakers live in the sideboard", "the doll
    and the teddy are on the bed": what its facts are said of), or else listing two or more
    things first ("toothpaste and soap - if either of them ...": `_listed`)."""
    for cl in reversed(clauses):
        if cl.sentence < sentence - 1:
            break
        by_kind: dict[str, list[str]] = {}
        for r in cl.mentions:
            if r in kinds:
                by_kind.setdefault(kinds[r], []).append(r)
        group = max(by_kind.values(), key=len, default=[])
        if len(group) > 1:
            return tuple(group)
        said_of = list(dict.fromkeys(f.subject for f in cl.facts if f.subject in kinds))
        if len(said_of) > 1 and len({f.condition.replace(f.subject, "") for f in cl.facts}) == 1:
            return tuple(said_of)
        if lex is not None and (listed := _listed(lex, cl.text)):
            return listed
    return ()


def _distributed(facts: tuple[Fact, ...], members: tuple[str, ...]) -> tuple[Fact, ...]:
    """`facts` said of one member of a group, said of every member (a pronoun of a distributive
    clause resolves to one of them). Facts already said of every member ("the bat and the racket go
    in the bin and on the bench, respectively. If they're already there": each its own place)
    are left as they are."""
    if set(members) <= {f.subject for f in facts}:
        return facts
    out = list(facts)
    for f in facts:
        if f.subject not in members:
            continue
        for other in members:
            if other != f.subject:
                swap = re.compile(rf"\b{re.escape(f.subject)}\b")
                out.append(replace(f, subject=other, condition=swap.sub(other, f.condition)))
    return tuple(dict.fromkeys(out))


#: "Check the bed for my phone", "Search the floor for the keys", "Look in the drawer for a pen":
#: an instruction to look at a place for a thing says the thing may be there, and a later "if
#: it's there" asks it; the verbs that look, with the preposition each may take before the place
_CHECK = re.compile(r"^(?P<lead>\W*(?:please\s+|now\s+|then\s+|first\s+)?)(?:check|search|inspect|"
                    r"look\s+(?:on|in|under|at|over|through|inside))\s+(?P<place>[^,;.!?]+?)\s+for\s+"
                    r"(?P<thing>[^,;.!?]+?)(?P<end>\s*[.!;]?\s*)$", re.I)


#: a bracketed aside with a comma in it ("(my teddy bear, don't judge me, Diary)")
_COMMA_ASIDE = re.compile(r"\((?P<head>[^(),]+)(?P<tail>(?:,[^(),]*)+)\)")


def _remark_dropped(sentence: str, lex: Lexicon) -> str:
    """A bracketed aside that names a thing, then goes on after a comma with words that name
    nothing ("Mr Buttons (my teddy bear, don't judge me, Diary) keeps ending up on the floor",
    "The cactus (Spike, yes, he has a name) sits on the sill") as its first part alone: the rest
    is a remark to the reader, and its commas cut the subject from its verb. An aside whose later
    parts name things too is a list ("(plates, bowls and cups)") and stays."""
    def keep(m: re.Match[str]) -> str:
        if not any(x.kind == "role" for x in lex.find_mentions(tokens(expand(m.group("head"))))):
            return m.group(0)
        rest = [p for p in m.group("tail").split(",") if p.strip()]
        if any(lex.find_mentions(tokens(expand(p))) for p in rest):
            return m.group(0)
        return f"({m.group('head').strip()})"

    return _COMMA_ASIDE.sub(keep, sentence)


def _checked(sentence: str, lex: Lexicon, kinds: Mapping[str, Category]) -> str:
    """A sentence that looks at a place for a thing ("Check the bed for my phone.") as the doubt
    it implies ("My phone may be on the bed."): in a container that is no surface the thing is
    inside, elsewhere on it. Only when the place is a named object or the floor and the thing a
    named object; any other sentence is returned as it is."""
    m = _CHECK.match(sentence)
    if m is None:
        return sentence
    places = lex.find_mentions(tokens(expand(m.group("place"))))
    things = lex.find_mentions(tokens(expand(m.group("thing"))))
    if len(places) != 1 or places[0].kind not in ("role", "floor") or not any(t.kind == "role" for t in things):
        return sentence
    kind = kinds.get(places[0].roles[0]) if places[0].kind == "role" else None
    prep = "in" if kind is not None and kind.container and not kind.surface else "on"
    thing = m.group("thing").strip()
    return f"{m.group('lead')}{thing[:1].upper()}{thing[1:]} may be {prep} {m.group('place').strip()}{m.group('end')}"


def _parallel(said: str, facts: list[Fact], clauses: list[Clause], sentence: int) -> list[Fact]:
    """"If it's dirty and white, put it in the washing machine: open the machine, ... If it's
    dirty and coloured, put it in the hamper": a condition opening its sentence whose pronoun asks
    a state the condition of the sentence before asked of another thing speaks of that thing, not
    of one its instruction named in between."""
    words = [w for w, _, _ in tokens(expand(said))]
    if not words or words[0] not in ("it", "they") or clauses and clauses[-1].sentence == sentence:
        return facts  # (only a condition opening its sentence: "turn off the lamp if it's on" is the lamp)
    before = next((cl for cl in reversed(clauses) if cl.role == "condition"), None)
    if before is None or before.sentence != sentence - 1:
        return facts
    asked = {f.key: f.subject for f in before.facts if f.kind == "state" and not f.goal}
    out = []
    for f in facts:
        s = asked.get(f.key) if f.kind == "state" and not f.goal else None
        if s is not None and s != f.subject:
            f = replace(f, subject=s, condition=f.condition.replace(f"({f.subject},", f"({s},", 1))
        out.append(f)
    return out


#: prepositions of a place "there" may take up (the place, not where something goes through)
_THERE_PREPS = {"on": "on", "onto": "on", "in": "in", "into": "in", "inside": "in"}
_BE_WORDS = frozenset({"is", "are", "was", "were", "be", "been"})
#: the words that rank a "one" said of a subject ("the last one", "the only one", "the first one")
_RANKS = frozenset({"last", "first", "only", "next", "sole"})


def _says_who(words: list[str], i: int) -> bool:
    """Whether the "one" at `i` is a predicate noun ranking its clause's subject ("Wren was the last
    one left in the classroom", "I'm the only one here", "Gran is always the first one up"): "be",
    an adverb or none, "the" and a rank (`_RANKS`) before it. Said of a subject that names no thing
    of the task (the caller's `not before`), the "one" is that subject, a person, not a thing the
    text named before it."""
    if i < 3 or words[i - 1] not in _RANKS or words[i - 2] != "the":
        return False
    k = i - 4 if words[i - 3] in _RANK_ADVERBS else i - 3
    return k >= 0 and words[k] in _BE_WORDS | {"am"}
#: pronoun subjects of such a condition before a participle of finding or leaving, or "still"
#: ("if they're still there": not "already", which asks of a goal, `_already`): "If found
#: there" (its subject elided, read "if it is found there", `sentences._ELIDED_SUBJECT`) after
#: "Scissors are not to be left out on the counter" ("if they're already there" is no such place:
#: it asks whether they are where the instruction before put them)
_THERE_SUBJECTS = frozenset({"it", "they"})


#: the words of a condition that asks only whether its thing is (still) there ("if it's there",
#: "if they are still there", "unless it isn't there"), for `_named_with_place`
_STILL_THERE = frozenset({"it", "they", "is", "are", "still", "not", "there"})
#: prepositions of a place said with a thing's name that a condition asks ("the sponge on the
#: shelf", "the cloth in the drawer"; "by the wall" is no place the conditions read)
_WITH_PREPS = frozenset(_THERE_PREPS)
#: prepositions of nearness said with a thing's name ("the sponge by the sink", "the cloth next
#: to the tap", "the torch beside the bed"): no place the conditions read, but they tell the thing
#: "if it is still there" takes up, whose presence it then asks (the eighteenth session)
_NEAR_PREPS = frozenset({"by", "near", "beside", "next", "alongside"})


def _named_with_place(reader: _Reader, said: str, instruction: str) -> str:
    """"Wipe it with the sponge on the shelf if it's there", "Preferred method: the wet wipes on
    the table, if they are there": a condition that asks only "if it is there", after an
    instruction (of its sentence) that names a thing with the place it should be at, asks whether
    that thing is at that place; read as "if the sponge is on the shelf" (the pronoun is the thing
    named with a place, not the topic the instruction works on, and "there" is that place, not the
    scene). Not after a verb of putting (`ACTIONS`: "put the mug on the shelf" names a goal).
    A thing named by a place the conditions do not read (`_NEAR_PREPS`: "the sponge by the sink,
    if it is still there") is the pronoun's too, and "there" then asks whether it is there at all."""
    text = expand(said)
    words = WORD.findall(text.lower())
    if "there" not in words or words[0] not in ("it", "they") or not set(words) <= _STILL_THERE:
        return said
    source = expand(instruction)
    toks = tokens(source)
    verbs = [w for w, _, _ in toks if w != "please"]
    if not verbs or verbs[0] in ACTIONS:
        return said
    iw = [w for w, _, _ in toks]
    mentions = reader.lex.find_mentions(toks)
    for m in reversed(mentions):
        if m.kind != "role" or m.end >= len(iw) or iw[m.end] not in _WITH_PREPS | _NEAR_PREPS:
            continue
        k = m.end + 1
        if iw[m.end] in _NEAR_PREPS:
            # (the place need not be a thing the catalog knows: "the cloth near the printer")
            k += iw[k:k + 1] == ["to"]
            if k < len(iw) and iw[k] in _PLACE_DETERMINERS or any(
                    x.start == k and x.kind in ("role", "floor") for x in mentions):
                thing = "the " + source[toks[m.start][1] : toks[m.end - 1][2]]
                return re.sub(r"\b(?:it|they)\b", thing, text, count=1, flags=re.I)
            continue
        while k < len(iw) and iw[k] in ARTICLES:
            k += 1
        place = next((x for x in mentions if x.start == k and x.kind in ("role", "floor")), None)
        if place is None:
            continue
        thing = "the " + source[toks[m.start][1] : toks[m.end - 1][2]]
        where = source[toks[m.end][1] : toks[place.end - 1][2]]
        text = re.sub(r"\b(?:it|they)\b", thing, text, count=1, flags=re.I)
        return re.sub(r"\bthere\b", where, text, count=1, flags=re.I)
    return said


def _there_named(reader: _Reader, said: str, clauses: list[Clause], sentence: int) -> str:
    """"Pillows are not to be left on the floor. Should a pillow have fallen there, ...", "Keep
    the lead off the sofa; if the lead has been dropped there, ...": in a condition that names
    a thing (or speaks of it by a pronoun: "If found there, return them to the drawer") but no
    place, "there" after its verb is the place last named in the clause before (of
    this sentence or the one before), read as that place. Not "there is" nor "is it there"."""
    text = expand(said)
    toks = tokens(text)
    words = [w for w, _, _ in toks]
    if "there" not in words:
        return said
    k = words.index("there")
    mentions = reader.lex.find_mentions(toks)
    if k == 0 or words[k + 1:k + 2] and words[k + 1] in _BE_WORDS or words[k - 1] in CLAUSE_WORDS \
            or not (any(m.kind == "role" and m.end <= k for m in mentions)
                    or set(words[:k]) & _THERE_SUBJECTS and (words[k - 1] in FOUND_PARTICIPLES or words[k - 1] == "still")) \
            or any(m.kind in ("role", "floor") and m.start > k for m in mentions):
        return said
    thing = next((m for m in reversed(mentions) if m.kind == "role" and m.end <= k), None)
    seen = reader.last_location.get(thing.roles[0]) if thing is not None and len(thing.roles) == 1 else None
    if seen is not None and not seen.goal and not seen.negated and seen.key in reader.lex.roles:
        # "There's a plate on the counter - ... put it into the sink; and no plate there at
        # all?": "there" after a thing named is where the text said that thing is, before
        # any place it was told to go since
        name = seen.key.replace("_", " ")
        grounded = [m for m in reader.lex.find_mentions(tokens(name)) if m.kind == "role"]
        if grounded and grounded[0].roles == (seen.key,) and grounded[0].end == len(name.split()):
            prep = "in" if seen.condition.startswith("inside") else "on"
            reader.doubted.add(seen.condition)
            return f"{text[:toks[k][1]]}{prep} the {name}{text[toks[k][2]:]}"
    for cl in reversed(clauses):
        if cl.sentence < sentence - 1:
            break
        ctoks = tokens(expand(cl.text))
        cwords = [w for w, _, _ in ctoks]
        places = [m for m in reader.lex.find_mentions(ctoks) if m.kind in ("role", "floor")]
        for m in reversed(places):
            j = m.start - 1
            while j >= 0 and cwords[j] in ARTICLES:
                j -= 1
            if j >= 0 and cwords[j] in _THERE_PREPS:
                name = " ".join(cwords[m.start:m.end])
                return f"{text[:toks[k][1]]}{_THERE_PREPS[cwords[j]]} the {name}{text[toks[k][2]:]}"
    return said


#: the verb a placement is asked with ("is it on the floor now?", "should it be found lying on
#: the floor"), a "be" or a verb of resting in its finite or bare form ("if it lies upon the
#: floor", "if they still sit on the bench", "does it hang on the hook?": where a thing lies is
#: where it is); a verb of seeing, living or belonging asks no place ("see that bottle on the
#: bench?", "whether it could live somewhere else", "if it belongs on the shelf" is its home)
_ASKED_BE = frozenset({"is", "are", "was", "were", "be", "been",
                       "lies", "lie", "sits", "sit", "stands", "stand", "rests", "rest", "hangs", "hang"})


#: the modal words of a guess at the present ("it may be lying on the bed", "the keys might be on
#: the counter"): a placement guessed is not known, as one asked is not; a habit ("sometimes",
#: "occasionally") says how things often are, not that the writer does not know how they are now
_HEDGES = frozenset({"may", "might", "could", "possibly", "perhaps", "maybe", "probably", "likely"})
#: the roles of a clause a hedge makes a guess: a doubt read as such, and a main clause the cut
#: reads as a statement or as the consequence of a time clause after it ("The pillow might be on
#: the armchair when you arrive - if so, ...")
_HEDGED_ROLES = frozenset({"uncertain", "statement", "consequence"})
#: the adverbs of `_HEDGES`: they say how sure the writer is, not what is guessed ("maybe the mug
#: is there" guesses "the mug is there"); the modals are part of the guess's verb group
_DOUBT_ADVERBS = _HEDGES - {"may", "might", "could"}


def _pronoun_question(words: list[str]) -> bool:
    """Whether a condition's words are a question whose subject is a pronoun ("are they there?",
    "isn't it here?", "might it still be there?")."""
    lead = 2 if words[1:2] == ["not"] else 1
    return len(words) > lead and words[0] in PRESENCE_QUESTION and words[lead] in ("it", "they")


def _doubted_presence(said: str) -> bool:
    """Whether a guess ("Maybe the mug is there", "it will probably be here", "the keys might
    still be there") guesses only that its thing is there at all: its words without the adverbs
    of doubt (`_DOUBT_ADVERBS`) ask a presence (`clauses.presence_asked`; the nineteenth session:
    "if that's the case" after such a guess pointed back to a clause with nothing read)."""
    words = [w for w in WORD.findall(expand(said).lower()) if w not in _DOUBT_ADVERBS]
    return presence_asked(words) is False

#: what a verbless condition of place may hold besides its thing and its place ("Kettle not on the
#: counter", "Towel still on the floor?")
_VERBLESS_WORDS = ARTICLES | PLACE_PREPS | NEGATIONS | {"still", "now", "there"}


def _verbless_place(toks: list[tuple[str, int, int]], lex: Lexicon) -> bool:
    """Whether a condition is a thing and a place and nothing else ("Kettle on the counter = it
    ends up switched on", "Towel still on the floor?"): a heading that asks where the thing is as
    "is the kettle on the counter?" does, its verb left out."""
    found = [m for m in lex.find_mentions(toks) if m.kind in ("role", "floor")]
    covered = {k for m in found for k in range(m.start, m.end)}
    words = [w for w, _, _ in toks]
    return len(found) >= 2 and all(k in covered or w in _VERBLESS_WORDS or not w.isalnum()
                                   for k, w in enumerate(words))


def _asked_again(said: str, facts: list[Fact], lex: Lexicon | None = None) -> set[str]:
    """The placements a condition asks of the situation: "Ned left his exercise book on the
    floor. ... Is it on the floor now? Then pick it up", "A counter with a plate upon it ...
    And if there is no plate on the counter at all?", "Should it be found lying on the floor
    (it is always found lying on the floor), pick it up". Why: a writer who asks where a thing
    is does not know it, whatever a statement (a past one, a stage direction, a habit in an
    aside) said of it; so the statement does not settle the factor (`_settle_stated`). Not a
    goal, a home, nor "already" (`_already`: "put it on the shelf unless it's already there"
    asks whether the instruction is done, which a statement of where it is does answer). Only a
    condition that asks only where one thing is (or whether it is there at all), with a verb "be"
    or of resting, or none at all in a heading (`_verbless_place`, given the lexicon `lex`),
    and only of a thing on or in a holder: in "if the mug on the coffee table is dirty" the place
    names the mug and the state is asked; a clause read with an instruction and an aside ("take
    the spare roll (we keep spares in the vanity cabinet), put it ...") asks no place; a room is
    where the scene is set ("even when, as in your house, the nearest sink is in the kitchen next
    door" asks nothing)."""
    toks = tokens(expand(said))
    words = {w for w, _, _ in toks}
    if "already" in words or not (words & _ASKED_BE or lex is not None and _verbless_place(toks, lex)) or len(
            {f.subject for f in facts}) != 1 or any(
            f.kind not in ("location", "exists") for f in facts):
        return set()
    return _placed_where(facts)


def _placed_where(facts: list[Fact]) -> set[str]:
    """The on/inside placements among `facts` that say where a thing is (no goal, no home): what
    a condition asking a place again, or an "already" relative, leaves unsettled."""
    return {f.condition for f in facts if f.kind == "location" and not (f.goal or f.home)
            and f.condition.startswith(("on(", "inside("))}


#: a restrictive relative clause that says a thing is already at a place ("dry shoes which are
#: already on the shoe rack are left where they are", "leave any book that is already on the
#: shelf"): the class it picks out is those things the instruction finds done, as "unless they
#: are already on it" says, so whether the thing is there is asked
_ALREADY_RELATIVE = re.compile(r"\b(?:that|which|who)\s+(?:is|are)\s+(?:still\s+|now\s+)?already\s+"
                               r"(?:on|in|inside|upon|at)\b")


def _already_relative(said: str, facts: list[Fact]) -> list[Fact]:
    """`facts` of `said` with the place a restrictive relative with "already" gives its thing
    (`_ALREADY_RELATIVE`) read as where the thing is, not where it goes ("move dry shoes which
    are already on the shoe rack": the rack is no goal of "move"), when the clause names one
    place only; a placement said plainly ("the mug is already in the sink") is left as it is."""
    if not _ALREADY_RELATIVE.search(" ".join(w for w, _, _ in tokens(expand(said)))) or len(
            {f.key for f in facts if f.kind == "location"}) != 1:
        return facts
    return [replace(f, goal=False, modifier=True) if f.kind == "location" and not f.home else f for f in facts]


#: the conjunctions "make sure" may follow ("... is lovely but do make sure it's off"); after a
#: condition earlier in the sentence (`_IN_CONDITION`) it is part of that condition's instruction
#: and asks nothing of its own
_ENSURE_JOINS = frozenset({"but", "and", "so"})
#: "please make sure it's switched off before you leave", "ensure the curtains are open",
#: "check the hair dryer is off" (a check with its "that" left out), "... is lovely but do make sure
#: it's turned off" (after "but", "and" or "so", with an emphatic "do"): an
#: instruction to see that a thing is in a state says it may not be, as "if it is not switched
#: off, make it switched off" does; the verbs that ask it and the states they ask of
#: ("see that the TV is on?" points a thing out, `placement.PERCEIVE`; "make sure the book is on
#: the shelf" says where it goes: no state before a place)
_ENSURE = re.compile(rf"(?P<lead>^\W*|\s[-\u2013\u2014]\s+|[;:,]\s*|\s(?:{'|'.join(sorted(_ENSURE_JOINS))})\s+)(?:please\s+)?(?:do\s+)?"
                     r"(?:make sure|ensure|see to it|(?:double[- ]?)?check)\s+(?:that\s+)?(?P<subj>it|they|(?:the|your|my)\s+[a-z][a-z ]*?)"
                     r"(?:\s+(?P<be>is|are)|(?P<short>['\u2019](?:s|re)))\s+(?P<state>(?:switched|turned|left|shut|powered)\s+(?:off|on|open|down)"
                     r"|off|on|open|closed|shut|locked|unlocked)\b(?!\s+(?:the|a|an|its|their|your|my|top|to|of)\b)"
                     r"[^.;!?]*", re.I)


#: a cue of a condition before "make sure" in its sentence (`_ENSURE_JOINS`)
_IN_CONDITION = re.compile(r"\b(?:if|in case|unless|when|whenever|should|once)\b", re.I)


def _ensured(sentence: str) -> str:
    """"... - please make sure it's switched off before you leave." as the condition it implies,
    "... - if it is not switched off, make it switched off." (`_ENSURE`)."""
    def plain(m: re.Match[str]) -> str:
        if m.group("lead").strip().lower() in _ENSURE_JOINS and _IN_CONDITION.search(sentence[:m.start()]):
            return m.group(0)  # "in case the bread is out, put it on the plate and make sure ...": its instruction
        be = m.group("be") or ("is" if m.group("short")[1:].lower() == "s" else "are")
        subj, state = m.group("subj"), m.group("state")
        return f"{m.group('lead')}if {subj} {be} not {state}, make {subj} {state}"
    return _ENSURE.sub(plain, sentence)


#: cues of a clause that asks, not conditions: the instruction before "whether" ("Check whether
#: the lamp is on") is done either way, no branch of the answer
_ASKING_CUES = frozenset({"whether"})


def _analyse(brief: Mapping[str, Any], catalog: Catalog) -> TaskAnalysis:
    lex = Lexicon.build(brief, reading_catalog(catalog))
    kinds = {name: cat for name, role in dict(brief.get("roles") or {}).items()
             if (cat := catalog.get(str(role.get("category", "")))) is not None}
    reader = _Reader(lex, _capabilities(brief, catalog), kinds)
    categories = {name: str(role.get("category", "")) for name, role in dict(brief.get("roles") or {}).items()}
    # the description as the readers read it (`as_read`: `unquote`, a long chain of rewrites, and
    # a subject's relative clause dropped), made once
    plain = as_read(str(brief["description"]))
    described = any_at(plain)
    # the conditions a sentence implies without a cue are spelled out after its bullet item is
    # found (`_bullet_items` finds a sentence by its words in the text)
    found_in_text = [_ensured(_checked(_remark_dropped(sent, lex), lex, kinds))
                     for sent in split_sentences(described)]
    sentences = [implied(sent) for sent in found_in_text]
    clauses: list[Clause] = []
    grammatical = 0  # pieces split at ':' or ';' still belong to one sentence for grouping
    headed = -1  # the sentence whose heading ("Shirt on the floor:") the pieces after it answer
    named = -1  # the sentence whose heading named an object ("Keys - on the floor: ...")
    place: tuple[int, str] = (-1, "")  # a place heading ("On the floor: ...") and its sentence
    pointing: set[int] = set()  # clauses that point back ("if it isn't"): never an antecedent
    colon_closed: set[int] = set()  # conditions closed by a colon ("If X: ..."): `_frame`
    colon_ends_line: set[int] = set()  # ... where the colon ends its line ("If X:" over a list)
    #: (sentence, members) of a distributive phrase: its sentence's facts hold for each member
    spread: tuple[int, tuple[str, ...]] = (-1, ())
    cut = [split_clauses(sent) for sent in sentences]
    bullets = _bullet_items(any_at(str(brief["description"])), found_in_text)
    speakers = _speakers(reader, plain)
    lines = _lines(described)
    #: per grammatical sentence, (line, paragraph) of the text it starts on (`_answered`)
    line_of: dict[int, tuple[int, int]] = {}
    for si, sent in enumerate(sentences):
        line_of.setdefault(grammatical, lines[si] if si < len(lines) else (-1, -1))
        pieces = cut[si]
        # the piece after each (a heading's answer may open the next part: "On the floor: into ...")
        after = [p.text for p in pieces[1:]] + [cut[si + 1][0].text if si + 1 < len(cut) and cut[si + 1] and not
                                                sent.rstrip().endswith((".", "!", "?")) else ""]
        for pi, (text, cue, role) in enumerate(pieces):
            if (DISTRIBUTIVE.match(text) or ANY_OF.search(text) or PLURAL_REFERENCE.search(expand(text))) and (
                    members := _members(clauses, categories, grammatical, lex)):
                spread = (grammatical, members)
            if role == "heading" and _speaker(reader, text, speakers):
                clauses.append(Clause(text, grammatical, cue, "statement", (), ()))
                continue  # "DAD: ...", "ME: ...", "Q: ...": who speaks, nothing of the scene
            if role == "heading":
                if (_place_heading(reader, text) or _room_list_heading(reader, text, after[pi])) \
                        and named != grammatical and not _instructs(reader, after[pi]):
                    # "On the floor: a dirty mark, and possibly a book": the place of what follows
                    place = (grammatical, text)
                    clauses.append(Clause(text, grammatical, cue, "statement", (), ()))
                    continue
                facts, names = _read_heading(reader, text)
                facts = _absence_of_asked(facts, text, lex, clauses, grammatical)
                if facts and all(f.derived for f in facts) and not _answers_quality(reader, text, after[pi]):
                    facts = []  # "Included: all walking. Not included: meals": a list's heading
                if spread[0] == grammatical:
                    facts = list(_distributed(tuple(facts), spread[1]))
                role = "condition" if any(not f.goal and not f.derived for f in facts) else "statement"
                if role == "condition" and names and _role_after(cut, si, pi) == "condition" \
                        and not _indefinite_heading(text):
                    # "towel on the shelves: if it's dirty -> ...": the condition comes after the
                    # heading, which only says what is spoken of and where it is (a question
                    # would end with "?": "dumbbell on the floor? put it ...")
                    role = "statement"
                    facts = [replace(f, modifier=False) for f in facts]  # a heading drops its articles
                headed = grammatical if role == "condition" else headed
                named = grammatical if names else named
                if role == "condition":
                    # "Kettle on the counter = ...", "Kettle not on the counter: skip it": a
                    # heading that asks where its thing is, its verb left out, as "is it ...?" does
                    reader.doubted |= _asked_again(text, facts, lex)
                if role == "condition" and (paired := _second_case(reader, clauses, text, facts)) != facts:
                    facts, names = paired, tuple(dict.fromkeys(f.subject for f in paired))
                clauses.append(Clause(text, grammatical, cue, role, tuple(facts), names))
                continue
            if role in ("statement", "scene") and headed == grammatical:
                role = "consequence"
            if role == "statement" and len(pieces) == 1 and _premise_of_then(reader, text, cut, si):
                role = "condition"  # "No spare bag anywhere. Then skip the re-stock."
            # "should there be an umbrella: ..." - the cue itself says the object may be absent
            # "if we still have one (it lives in the vanity - ...)": a closing aside says where the
            # object is kept (offline.placement), it asks nothing
            said = _ASIDE.sub("", text) if role == "condition" and _ASIDE.sub("", text).strip() else text
            if role == "condition" and _DASH.split(said)[0].strip():
                said = _DASH.split(said)[0]  # "if one is still to be had - it is kept in the vanity"
            if role == "condition" and ")" in said and "(" not in said.split(")")[0]:
                said = said.split(")")[0]  # "(open the wardrobe if the door's shut) and shut it": the aside ends
            if role in ("consequence", "else", "statement"):
                said = _TELEGRAPHIC.sub(_telegraphic, said)  # "open washing machine": "open the washing machine"
            own = False  # the reader's own "it" (`_Reader.own_it`)
            if role == "consequence" and _goes(reader, said):
                said, own = f"it goes {said}", True  # "dry: on the shoe rack", "clean - onto the armchair"
            elif (role == "consequence" or role == "statement" and clauses and clauses[-1].role == "condition"
                  and clauses[-1].cue == "?") and (bare := _bare_goal(reader, said)):
                said, own = f"it goes {bare[0]} {bare[1]}", True  # "dirty? kitchen sink.", "wet -> laundry basket"
            if place[0] == grammatical:
                said = f"{said.rstrip(' .;,')} {place[1]}"
                doubt = bool({w for w, _, _ in tokens(place[1])} & UNCERTAIN)
                role = ("uncertain" if doubt else "scene") if role == "statement" else role
            if role == "condition" and pi == 0 and pi + 1 < len(pieces) \
                    and not any(cl.mentions for cl in clauses if cl.sentence >= grammatical - 1) \
                    and (ahead := _cataphor(reader, said, pieces[pi + 1].text)) is not None:
                # "Unless it has already been shut down, the computer on the desk is to be switched
                # off": a pronoun in a condition put first, with nothing named in its sentence or
                # the one before, speaks of the thing its main clause names
                reader.topic, reader.topic_kind = ahead, "role"
            said = _BARE_BOTH.sub(r"\1 of them", _BARE_EITHER.sub(r"\1 of them", said))
            reader.own_it = own
            reader.group = spread[1] if spread[0] == grammatical else ()
            if role == "condition" and pi > 0 and pieces[pi - 1].role == "consequence":
                # "wipe it with the sponge on the shelf if it's there": the thing at that place
                said = _named_with_place(reader, said, pieces[pi - 1].text)
            if role == "condition":
                # "if my mug hasn't been washed wash it": the predicate the cut ended
                said = _there_named(reader, predicate_state(said), clauses, grammatical)
            thing = reader.heading_topic or (reader.topic if reader.topic_kind == "role" else ())
            # "Is the desk lamp still on when they have gone?": the question is cut at its time
            # clause, read with "they" as the people, not the lamp (whose absence "gone" asks)
            reader.timed = role == "condition" and cue in _TIME_OPENERS
            reader.opening = role == "condition" and pi == 0
            facts, names = reader.facts("there is " + said if cue == "should there be" else said)
            reader.own_it = reader.timed = reader.opening = False
            if role == "condition" and not facts and (mixed := reader.code_switched(text, thing)):
                # "If naka-on pa, pakipatay lang": a condition in another language's grammar
                # still asks what its English words say, of the item's topic
                facts, names = mixed, tuple(dict.fromkeys(f.subject for f in mixed))
            if role == "condition":
                facts = _parallel(said, facts, clauses, grammatical)
            if cue == "if available":
                facts = _where_taken_from(said, facts)
            if cue == "if available" and not any(f.kind in ("location", "exists") and not f.home for f in facts):
                facts += _available(reader, said)
            if role == "condition" and not facts and (elided := _elided(
                    reader, said, names, pieces[pi - 1].text if pi > 0 and pieces[pi - 1].role == "consequence"
                    else pieces[pi + 1].text if pi + 1 < len(pieces) else "")):
                # "close the microwave if it isn't already": the state its instruction sets
                facts, names = elided, tuple(dict.fromkeys(f.subject for f in elided))
            if role == "condition" and all(f.derived for f in facts) and pi + 1 < len(pieces) and (
                    undone := _undone(reader, said, pieces[pi + 1].text)):
                # "if they've been drawn, open them right up": a condition the reader cannot read,
                # answered by an instruction that sets a state of the same thing, says that the
                # thing is not yet in that state
                facts = undone
            if role == "condition" and not facts and (done := _done_before(clauses, grammatical, said, names)):
                # "the bin bag goes in the bin, unless Maya already took it down": an action some
                # agent has already done to the thing moved asks whether it is already there
                facts = done
            low = expand(said).lower() if role == "condition" else ""
            # "if it's there", "if it turns up", "if it isn't there": a condition that asks only
            # whether its thing is there at all (True: that it is not)
            # (a question's tag dropped: "the mug is there, isn't it? Then ..." asks what "is the
            # mug there?" does, `_unbiased`)
            low_words = WORD.findall(_unbiased(low))
            present = presence_asked(low_words) if role == "condition" else None
            if role == "condition" and present is None:
                present = _conjunct_presence(low_words)
            if role == "condition":
                facts = _absence_of_asked(facts, said, lex, clauses, grammatical)
            if present is not None and _pronoun_question(low_words) and any(
                    f.kind == "location" and (f.subject in names or cl.sentence >= grammatical - 2)
                    for cl in clauses for f in cl.facts):
                # "I forgot my glasses on the coffee table. ... Are they there?": a pronoun's
                # question after a place said of its thing, or of any thing just before (the
                # pronoun may be that thing's, however it is resolved), asks that place, not
                # whether the thing is there at all (left to the reading of "there" as it was)
                present = None
            if role == "condition" and _anaphoric(said, facts):
                # (a finding in the room itself, "if you find any in the media room", asks whether
                # the thing is there at all, whatever the clause before said of it: `_come_upon`)
                facts, names = ([], ()) if _THIS_ROOM.search(said) else _antecedent(clauses, grammatical, pointing)
                if not facts:
                    facts, names = _come_upon(clauses, grammatical, said)
                pointing.add(len(clauses))
                if "not" in {w for w, _, _ in tokens(expand(said))}:
                    # "the drawer might already be open, and if it isn't, open it": the opposite
                    facts = [replace(f, negated=not f.negated) for f in facts]
            elif role == "condition" and names and present is not None \
                    and (asked := _presence_asked(clauses, grammatical, names)):
                # "If you find a credit card anywhere in the office, put it on the desk ... If it
                # isn't there, nothing to do": after a condition asking whether the thing is there
                # at all, "there" is that presence, not the place the instruction put it
                facts = [Fact(r, f"exists({r})", "exists", negated=present) for r in asked]
            elif role == "condition" and all(f.derived for f in facts) and names and (
                    present is False or present is True and bool(set(low_words[:1]) & PRESENCE_DETERMINERS)
                    or present is True and not _place_before(clauses, grammatical, names)):
                # "If it turns up, put it on the desk", "it'll be on the floor if it's anywhere",
                # "Wallet. If it's there, lost property basket": a thing spoken of that may turn
                # up, or be there at all, may be absent (with no place named before to point to,
                # "it is there" asks whether the thing is there at all); so does "the mug is not
                # there" with the thing named in the condition itself (a pronoun, "if it is not
                # there", points back to a place the sentence before may have named); an attribute
                # only guessed from a modifier ("right" of "Is the right remote there?") is no reading
                facts = [Fact(r, f"exists({r})", "exists", negated=bool(present)) for r in names[:1]]
            elif role == "condition" and names and facts and all(
                    f.kind == "exists" and not f.negated for f in facts) and (
                    placed := _there_before(clauses, grammatical, names, low_words)):
                # "One always gets left on the floor by the door. If there's a bin bag down there,
                # ...": a thing said to be there, "there" the place the sentence before put it, asks
                # whether it is at that place, not whether such a thing exists at all
                facts = placed
            elif role == "condition" and names and not any(not f.goal for f in facts) \
                    and _FIND_NAMED.match(low):
                # "If you find a wallet, put it on the side table", "If you find a credit card
                # anywhere in the office, ...": coming upon a thing named, nowhere in particular
                facts = [Fact(r, f"exists({r})", "exists") for r in names[:1]]
            elif role == "uncertain" and names and all(f.derived for f in facts) and _doubted_presence(said) \
                    and not _place_before(clauses, grammatical, names):
                # "Maybe the mug is there. If that's the case, ...", "The remote will probably be
                # here": a guess that the thing is there at all, as the condition "if it is there"
                # asks (with a place said before, "there" may be that place: left as it was)
                facts = [Fact(r, f"exists({r})", "exists") for r in names[:1]]
            elif role == "statement" and (_elaborates(clauses, grammatical, said) or _verbless_request(said)):
                # "anything on the floor should go where it belongs - the book on the couch, a toy
                # in the toy box": a verbless list after a clause that moves things says where each
                # goes, not where it is; so does a request with no verb ("Boots on the racks please,
                # not on the pipes", "Cups in the dishwasher pls")
                facts = [replace(f, goal=True) if f.kind == "location" else f for f in facts]
            elif (role == "condition" or role == "uncertain" and "been" in {w for w, _, _ in tokens(said)}) \
                    and facts and all(f.goal for f in facts) and not set(w for w, _, _ in tokens(said)) & AGENTS:
                # "if it has been thrown on the floor", "whenever the jacket ends up on the
                # floor": in a condition a moved object's place is the situation, not a goal; so
                # in a guess at what has happened ("wet wipes may have been put on the table")
                facts = [replace(f, goal=False) for f in facts]
            if role == "uncertain" and _habit_of_state(said):
                # "The TV on the TV stand is frequently left running", "Printer on desk often left
                # on": the habit is the thing's state; the subject's place is where it is (the
                # placement reader states it), not what the doubt asks
                facts = [f for f in facts if f.kind != "location" or f.goal]
            if spread[0] == grammatical:
                facts = list(_distributed(tuple(facts), spread[1]))
            before_relative = facts
            if role == "condition" and text.strip() in found_in_text[si]:
                # (a condition the writer wrote, not one `implied` spelled out: "Examine the mug on
                # the coffee table" is "examine the mug if it is on the coffee table")
                reader.doubted |= _asked_again(said, facts, reader.lex)
            elif role in _HEDGED_ROLES and {w for w, _, _ in tokens(said)} & _HEDGES:
                # "IMPACT - Phone on the bed at 0% on waking. ... ACTIONS 1. Phone. It may be lying
                # on the bed.": a writer who says a thing may be somewhere does not know it, as one
                # who asks does not, whatever a report said before (`_asked_again`); so when the
                # guess is a main clause before a condition of its own ("The pillow might be on
                # the armchair when you arrive - if so, ...": the cut reads it as the time
                # clause's consequence)
                reader.doubted |= _asked_again(said, facts, reader.lex)
            facts = _already_relative(said, facts)
            if facts is not before_relative:
                # (which no statement settles: `_settle_stated`)
                reader.doubted |= _placed_where(facts)
            if role == "condition" and re.search(re.escape(text.strip().rstrip(":")) + r"\s*:", sent):
                colon_closed.add(len(clauses))
                if re.search(re.escape(text.strip().rstrip(":")) + r"\s*:[ \t]*\n", described):
                    colon_ends_line.add(len(clauses))
            if role == "condition" and (paired := _second_case(reader, clauses, text, facts)) != facts:
                facts, names = paired, tuple(dict.fromkeys(f.subject for f in paired))
            clauses.append(Clause(text, grammatical, cue, role, tuple(facts), names))
        if bullets[si] is not None and si + 1 < len(sentences) and bullets[si + 1] == bullets[si]:
            continue  # "* Bedroom: table lamp on? -> off. Wardrobe doors open? -> close.": one item
        if bullets[si] is None and si + 1 < len(sentences) and sent.rstrip().endswith(_TRAILING) \
                and sentences[si + 1].lstrip()[:1].islower():
            # "if it's dirty straight into the washing machine... unless the machine's already
            # running, then into the hamper...": a trailing ellipsis before a lower-case word is a
            # pause, not a sentence end; the conditions go on
            continue
        if bullets[si] is not None or sent.rstrip().endswith((".", "!", "?")) or si + 1 == len(sentences) or (
                _turn_starts(reader, cut[si + 1], speakers)):
            # (a bullet item ends its unit, full stop or not: "- racket too if its lying on the floor")
            grammatical += 1

    contrasted = _contrasted(clauses, plain)
    # collect condition facts per (subject, kind, key)
    found: dict[tuple[str, str, str], dict[str, Any]] = {}
    last_key: tuple[str, str, str] | None = None
    slot: tuple[str, str, str]
    #: conditions met earlier in the sentence: a factor first mentioned under them depends on them
    context: list[tuple[tuple[str, str, str], bool, str]] = []
    current_sentence = -1
    #: a sentence that opens with an instruction continues the previous one's conditions
    #: ("Clean the mirror if it is dirty. Use the cloth if we still have one; if there is no
    #: cloth, ..."): an absence stated there is only asked under those conditions
    carried: list[tuple[tuple[str, str, str], bool, str]] = []
    #: the tool a sentence opening with a verbless "with" phrase names (`_with_tool`): any
    #: condition of its sentence on it is asked under the conditions carried on
    with_tool: set[str] = set()
    #: whether the last condition said of each slot is its fact holding (see `Factor.under`)
    holds: dict[tuple[str, str, str], bool] = {}
    #: the sentence opens with "Then" after a sentence that was only a condition ("Suppose the
    #: lamp is on. Then switch it off."): its instructions are that condition's consequences
    answers_premise = False
    #: the conditions a framing sentence sets over the sentences after it (`_frame`), and the
    #: sentences it covers
    frame: list[tuple[tuple[str, str, str], bool, str]] = []
    framed: set[int] = set()
    roles_of: dict[int, set[str]] = {}
    for cl in clauses:
        roles_of.setdefault(cl.sentence, set()).add(cl.role)
    for ci, cl in enumerate(clauses):
        if cl.sentence != current_sentence:
            frame_answered = False
            if cl.sentence == current_sentence + 1 and (
                    scope := _frame(clauses, current_sentence, colon_closed, colon_ends_line, line_of)):
                # "Only if there are eggs in the fridge. Open the fridge, get the pan onto the stove
                # unless it is there already", "If it is on the vanity: put it away. The cabinet may
                # be open or shut; ...", "Bread on the counter? Onto the plate with it, and see that
                # the toaster is on - it may be on already": the conditions of a sentence that frames
                # the ones after it hold over those (`_frame`)
                # (the frame is the framing condition's own: "If there is:\n- put it in the cabinet if
                # it's clean" frames the list by the plate's being there, not by its first item's)
                asked_first = {(f.subject, f.kind, f.key if f.kind in ("state", "attr") else "")
                               for f in clauses[_framing(clauses, current_sentence)].facts}
                frame, framed = [c for c in context if c[0] in asked_first], scope
                # (a sentence of conditions only is answered by the first sentence it frames, as
                # by one opening with "Then" below; a colon frame has its own instruction)
                frame_answered = not roles_of.get(current_sentence, set()) & {"consequence", "else"} and not any(
                    c in colon_closed for c, x in enumerate(clauses) if x.sentence == current_sentence)
            elif cl.sentence not in framed:
                frame, framed = [], set()
            # "EGGS are conditional: only if there are eggs in the fridge. Then the sequence is:
            # ... put the frying pan on the stove, unless it is already there": a sentence of a
            # condition with no consequence of its own, answered by a sentence opening with
            # "Then", is that sentence's condition; its factors are asked under it
            premise = cl.sentence == current_sentence + 1 and _THEN_OPENS.match(cl.text) is not None and (
                "condition" in roles_of.get(current_sentence, set())
                and not roles_of.get(current_sentence, set()) & {"consequence", "else"})
            # ... unless it speaks of a situation of its own ("Finally, a dirty mirror is cleaned:")
            # ("Mirror dirty? Clean it. Use the cloth if we still have one.": an instruction
            # standing alone after a question passes its conditions on)
            # ("Wipe the table if it's dirty. Use the sponge to wipe it, if there is one.": a tool
            # sentence whose purpose takes up the instruction before is that instruction, `_takes_up`)
            carried = (context or carried) if cl.role in ("statement", "consequence") and not any(
                not f.goal and not f.derived and not f.home for f in cl.facts) or _takes_up(
                    cl, clauses, current_sentence) or (
                # "Wipe it if it's dirty. Use the sponge, then leave it on the counter. If there is no
                # sponge, ...": a condition on the thing the instruction carried on used is that
                # instruction's alternative, under the same conditions
                cl.role == "condition" and carried and not context and bool(
                    {f.subject for f in cl.facts if not f.goal} & {
                        m for c in clauses if c.sentence == current_sentence for m in c.mentions})) else []
            answers_premise = premise or frame_answered
            current_sentence, context, with_tool = cl.sentence, (context if premise else list(frame)), set()
        elif (cl.role == "condition" and ci >= 2 and clauses[ci - 1].role == "consequence"
              and clauses[ci - 2].role == "condition" and clauses[ci - 2].sentence == cl.sentence
              and (clauses[ci - 1].cue != cl.cue or (
                  ci >= 3 and clauses[ci - 3].role == "consequence"
                  and clauses[ci - 3].sentence == cl.sentence)
                  # "should the wardrobe be open, close it; should the lamp be on, ...": a condition
                  # on something the previous instruction never spoke of
                  or not ({f.subject for f in cl.facts if not f.goal}
                          & (set(clauses[ci - 1].mentions) | set(clauses[ci - 2].mentions)))
                  and bool(cl.facts))):
            # "switch off the lamp in case it is on, and shut the wardrobe if it is open": a new
            # instruction with its own postposed condition, not nested under the previous one (but
            # still under a sentence that frames it)
            context = list(frame)
        if _with_tool(cl) and all(c.role == "statement" and not c.facts for c in clauses[:ci]
                                  if c.sentence == cl.sentence):
            # ("With the sponge, if the sponge is on the counter!", after a speaker's name at most:
            # a verbless tool phrase goes on with the instruction before, whatever its condition
            # asks of the tool, `_with_tool`)
            with_tool = set(cl.mentions)
        if cl.role == "else" and context and WORD.search(cl.text):
            # (an `else` clause with no words is "instead" closing the instruction before it: "but
            # if the machine is running it goes into the hamper instead; and if the hamper is
            # full, ...": what follows is asked under that condition, not its opposite)
            slot0, neg0, key0 = context[-1]
            context[-1] = (slot0, not neg0, key0)
        # "put it in the fridge - the fridge door may already be open": an uncertain remark
        # ("NO (it is somewhere else, or we are out of it):": an answer's gloss says what it covers)
        conditional = cl.role in ("condition", "uncertain") or _label(cl) is not None or (
            cl.role == "consequence" and bool(uncertain_words(re.findall(r"[a-z]+", cl.text.lower()))))
        added: list[tuple[tuple[str, str, str], bool, str]] = []
        if cl.role == "condition":
            # "when it is dirty, ...; when it is clean and wet, ...": a condition restating an
            # earlier one of the sentence is its sibling alternative, not nested under it
            restated = {((f.subject, f.kind, f.key if f.kind in ("state", "attr") else ""), not f.negated)
                        for f in cl.facts if not f.goal}
            context = [c for c in context if (c[0], c[1]) not in restated]
        for f in cl.facts:
            if f.derived and (f.subject, f.key) not in contrasted or f.home and cl.role in (
                    "condition", "consequence", "else", "uncertain"):
                # "if there is one (it is kept in the vanity)", "(spares are kept there)": where a
                # thing is kept, said in a condition or an instruction, asks nothing (a stated home
                # is weighed against the rest of the text by `_settle_stated`)
                continue
            if cl.role == "uncertain" and _identifying_place(f, cl):
                # "The lamp on the nightstand may be on": the doubt is whether it is on; the
                # place names which lamp is meant
                continue
            if f.goal or not (conditional or (f.modifier and cl.role not in ("scene",)
                                              # "The tablet is lying on the chair.": stated, kept
                                              and not ((f.definite or _norm(cl)) and cl.role == "statement")
                                              # "Take a spare fuse from the drawer and ...": a
                                              # plain instruction takes its source for granted
                                              and not (f.presupposed and cl.role == "statement")
                                              # "A dirty mug is sitting on the desk": a thing the
                                              # statement places outright is as it describes it
                                              and not (cl.role == "statement" and not f.home
                                                       and f.subject in _placed_outright(brief, catalog, cl.text)
                                                       # "Take it to the kitchen: a dirty mug in the
                                                       # sink, a clean one on the counter": a list
                                                       # saying where each goes places nothing
                                                       and not _moved(cl, f.subject)))
                              or (cl.role == "else" and f.kind != "location")):
                continue
            if conditional and f.kind == "location" and not f.goal and f.condition.startswith("in_room(") \
                    and list(brief.get("rooms") or []) == [f.key]:
                if _holds_another(f.subject, cl.facts):
                    # "The lamp on the nightstand in the bedroom may be on": the room says which
                    # holder is meant; the doubt is the lamp's, not whether the nightstand is there
                    continue
                if _state_asked(f.subject, cl.facts):
                    # "If the lamp in the bedroom is on", "Kettle in the kitchen still on?": in a
                    # task of one room, the room says nothing of which thing or whether it is
                    # there; the condition asks its state
                    continue
                # "I believe I may have left my wristwatch in the flatlet. If it is there, ...": in a
                # task of one room, being in that room is being there at all
                f = Fact(f.subject, f"exists({f.subject})", "exists", negated=f.negated)
            if conditional and f.kind == "location" and not f.goal and f.condition == f"on({f.subject}, floor)" \
                    and _floor_bound(kinds.get(f.subject)):
                # "in case there's a puddle on the floor": a thing that can be nowhere but on the
                # floor and is never carried (a puddle, a stain, a rug) is there if it is at all
                f = Fact(f.subject, f"exists({f.subject})", "exists", negated=f.negated)
            slot = (f.subject, f.kind, f.key if f.kind in ("state", "attr") else "")
            entry = found.setdefault(slot, {"order": ci, "sentence": cl.sentence, "clause": ci,
                                           "targets": [], "values": [],
                                           "context": [c for c in context if c[0] != slot and not (
                                               f.kind == "exists" and c[0][0] == f.subject)]
                                           or [c for c in carried if c[0] != slot and (
                                               f.kind == "exists" or f.subject in with_tool)]})
            entry.setdefault("places", set()).add((cl.sentence, ci))
            entry["home"] = entry.get("home", True) and f.home and cl.role == "statement" and _home_said(
                cl.text, opens=ci == 0 or clauses[ci - 1].sentence != cl.sentence)
            if cl.role == "condition":
                value = f.condition.rsplit(", ", 1)[1][:-1] if f.kind == "attr" else f.key
                # "unless it is already in the box, put it in: open the box first if ...": what
                # follows a leading "unless" happens when its condition does not hold (a trailing
                # one, "the pillow, unless there is a pan - in that case ...", ends its instruction)
                leading = ci == 0 or clauses[ci - 1].sentence != cl.sentence or clauses[ci - 1].role != "consequence"
                added.append((slot, f.negated != (cl.cue == "unless" and leading), value))
                holds[slot] = not added[-1][1]
            elif conditional:
                holds[slot] = not f.negated
            if f.kind == "location" and cl.role == "condition" and (
                    cl.cue == "unless" or re.search(r"\balready\b", cl.text.lower()) is not None):
                entry["reached"] = True  # where the instruction puts it: see `Factor.stops`
            if f.kind == "location" and f.key not in entry["targets"]:
                entry["targets"].append(f.key)
                entry.setdefault("conds", {})[f.key] = f.condition
            if f.kind == "attr":
                value = f.condition.rsplit(", ", 1)[1][:-1]
                if value not in entry["values"]:
                    entry["values"].append(value)
            entry.setdefault("condition", f.condition)
            last_key = slot
            if cl.role == "condition" and cl.cue not in _ASKING_CUES and ci > 0 \
                    and clauses[ci - 1].role == "consequence" \
                    and clauses[ci - 1].sentence == cl.sentence and all(
                        c.role == "statement" and not c.facts for c in clauses[:ci - 1] if c.sentence == cl.sentence):
                # "Switch it off if it is on", "Empty it only if it is full", "The sock - pick it
                # up if it is on the floor": an instruction opening the sentence (after a topic
                # at most), its condition put after it, is the condition's branch; before a
                # trailing "unless" ("Close the curtains unless they're shut already", "fold up
                # the brolly unless it's still wet") it is the branch where the condition does
                # not hold, as after a leading one (the clauses after it, "- in that case ...",
                # stay under the condition holding); a forbidden instruction before it ("dont
                # turn my lamp on unless it's off", "I never clean the fridge unless it's dirty")
                # is done only where the condition holds
                forbidden = bool(set(re.findall(r"[a-z]+", expand(clauses[ci - 1].text).lower())) & NEGATIONS)
                entry.setdefault("consequences", []).append(clauses[ci - 1].text)
                entry.setdefault("under", []).append(holds[slot] != (cl.cue == "unless" and not forbidden))
        context += added
        if (cl.role in ("consequence", "else") or answers_premise and cl.role == "statement") \
                and last_key is not None:
            found[last_key].setdefault("consequences", []).append(cl.text)
            found[last_key].setdefault("under", []).append(holds.get(last_key, True) == (cl.role != "else"))
            found[last_key].setdefault("roles", set()).update(cl.mentions)
    for (role, attr_key), classes in reader.attribute_classes(plain).items():
        entry = found.setdefault((role, "attr", attr_key), {"order": len(clauses), "sentence": -1,
                                                            "clause": -1, "targets": [], "values": []})
        entry["values"] += [v for v in classes if v not in entry["values"]]

    factors: list[Factor] = []
    slot_factor: dict[tuple[str, str, str], Factor] = {}
    # (where a thing is kept is no place it is expected now: "Use the cloth if we still have one.
    # The cloth lives in the vanity." still asks whether there is one)
    subjects_with_location = {s for (s, k, _), e in found.items() if k == "location" and not e.get("home")}
    absence_stated = {f.subject for cl in clauses if cl.role in ("condition", "uncertain") or _label(cl) is not None
                      for f in cl.facts
                      if f.kind == "exists" and not f.goal and (
                          f.negated and cl.role == "uncertain"
                          # "if it is elsewhere, or we have none": two alternatives, not "no plate on the counter"
                          or f.negated and re.search(r"\bor\b", cl.text) is not None and any(
                              g.subject == f.subject and g.kind == "location" and g.negated for g in cl.facts)
                          # "there may be a loaf of bread." said on its own, before where it is
                          or cl.role == "uncertain" and not any(g.subject == f.subject and g.kind == "location"
                                                                for g in cl.facts))}
    for (subject, kind, key), e in found.items():
        values: dict[str, str]
        if kind == "exists" and subject in subjects_with_location - absence_stated:
            # `if there are no wipes` refers to where the wipes are expected; only an absence
            # stated as its own alternative (`if it is elsewhere or we have none`, `there may or
            # may not be a loaf`) is a separate question
            continue
        if kind == "location":
            targets = e["targets"]
            if len(targets) == 1:
                values = {"yes": e["conds"][targets[0]], "no": f"not {e['conds'][targets[0]]}"}
                fid = f"{subject}_{e['conds'][targets[0]].split('(')[0]}_{targets[0]}"
            else:
                values = {t: e["conds"][t] for t in targets}
                values["elsewhere"] = " and ".join(f"not {e['conds'][t]}" for t in targets)
                fid = f"{subject}_location"
        elif kind == "attr":
            # a class the text names (`attribute_classes`) is bound by the kind's catalog domain
            # as a stated value is (`_Reader._offered`)
            cat = kinds.get(subject)
            domain = dict(cat.attributes or {}) if cat is not None else {}
            real = [v for v in e["values"] if v != "other" and (key not in domain or v in domain[key])]
            if not real:
                continue
            values = {v: f"attr({subject}, {key}, {v})" for v in real}
            values["other"] = " and ".join(f"not attr({subject}, {key}, {v})" for v in real)
            fid = f"{subject}_{key}"
        else:
            cond = e["condition"]
            values = {"yes": cond, "no": f"not {cond}"}
            fid = f"{subject}_{key or 'present'}"
        factor = Factor(fid, subject, _question(subject, kind, key, e["targets"]), values, kind,
                        e["order"], e["sentence"], e["clause"], e.get("consequences", []),
                        set(e.get("roles", set())))
        factor.raw_context = e.get("context", [])
        factor.places = set(e.get("places", set()))
        factor.stops = not e.get("reached", False)
        factor.under = list(e.get("under", []))
        slot_factor[(subject, kind, key)] = factor
        factors.append(factor)
    homes = {f.condition for cl in clauses if cl.role == "statement" and {w for w, _, _ in tokens(cl.text)} & HOMES
             for f in cl.facts if f.kind == "location" and not f.goal}
    factors = _settle_stated(factors, brief, catalog, slot_factor, homes, reader.asked_already, reader.doubted)
    for factor in factors:
        for slot_c, negated, value in factor.raw_context:
            dep = slot_factor.get(slot_c)
            if dep is not None and dep is not factor:
                factor.context.append((dep.id, _allowed(dep, negated, value)))
        factor.context = _consistent(factor.context)
    _answered(factors, clauses, line_of, described.split("\n"))
    _taken_up_under(factors, clauses)
    factors += _alternatives_put_back(factors, clauses)
    factors.sort(key=lambda f: (f.order, _RANK[f.kind], f.id))
    groups, group_roles = _group(factors, _moves_into(factors, clauses) + _answers(factors, clauses))
    covered = set().union(*group_roles) if group_roles else set()
    return TaskAnalysis(sentences, clauses, factors, groups, group_roles, set(lex.roles) - covered)


#: words by which a sentence takes up the thing of the sentence before it ("Only if the cereal box is
#: in the cupboard. Take it out, ...")
_TAKING_UP = frozenset({"it", "them", "they", "there", "its", "their"})
#: words that may be cut off before a framing condition as a clause of their own ("only when ...")
_FRAME_LEADS = frozenset({"only", "just", "but", "and", "so"})


def _frame(clauses: list[Clause], sentence: int, colon_closed: set[int], colon_ends_line: set[int],
           line_of: Mapping[int, tuple[int, int]]) -> set[int]:
    """The sentences after `sentence` that its conditions frame (empty when it frames none).

    A sentence frames the ones after it when it opens (after a fact-less heading: "EGGS -", "Q.")
    with a condition and either closes that condition with a colon ("If the laptop is on the
    desk: put it on the shelf. The cabinet may be open; ...") or says nothing but conditions
    ("Only if there are apples in the bowl.", "Laptop on the bed?"), and the sentence after it
    takes up a thing of its conditions (names it or its place, or points back: "it", "there").
    A colon frame covers the rest of its line (the sentences up to one opening with a condition
    of its own), or, where the colon ends the line, its paragraph (the list under "If X:"); a
    sentence of conditions only covers the rest of its line the same way, and a question only
    the sentence after it, an instruction answering it ("... ? Onto the plate with it")."""
    own = [ci for ci, c in enumerate(clauses) if c.sentence == sentence]
    first = _framing(clauses, sentence)
    own = own[own.index(first):] if first in own else []
    after = [ci for ci, c in enumerate(clauses) if c.sentence == sentence + 1]
    if not own or not after or clauses[first].role != "condition" or _label(clauses[after[0]]) is not None:
        # (a sentence opening with an answer's label, "Is the mug on the desk?\nNo: then ...",
        # is answered by that label, `_answered`)
        return set()
    if first in colon_closed:
        return _framed(clauses, sentence, line_of, by_paragraph=first in colon_ends_line)
    if not all(clauses[ci].role == "condition" for ci in own) or not _takes_up_frame(clauses, first, after):
        return set()
    if _asks(clauses[first]):
        # (a question put to the reader asks for a deed, not whether the scene is so: "The kids
        # dropped their coat and bag in the hallway - could you sort them out?")
        addressed = set(re.findall(r"[a-z]+", clauses[first].text.lower())) & AGENTS
        return {sentence + 1} if clauses[after[0]].role != "condition" and not addressed else set()
    return _framed(clauses, sentence, line_of, by_paragraph=False)


def _framing(clauses: list[Clause], sentence: int) -> int:
    """The clause a sentence opens with after a fact-less heading or lead ("EGGS - Only if ...",
    "only when ...", its "only" cut off as a clause of its own); -1 for a sentence with none."""
    own = [ci for ci, c in enumerate(clauses) if c.sentence == sentence]
    while own and not clauses[own[0]].facts and (clauses[own[0]].role == "statement" or set(
            re.findall(r"[a-z]+", clauses[own[0]].text.lower())) <= _FRAME_LEADS):
        own = own[1:]
    return own[0] if own else -1


def _takes_up_frame(clauses: list[Clause], first: int, after: list[int]) -> bool:
    """Whether the sentence of clauses `after` takes up a thing of the condition `first`: names
    the thing or its place, or points back to it ("it", "there") before it names anything else
    ("Is the mug on the desk? Switch the lamp off if it is on" takes up the lamp, not the mug)."""
    things = {x for f in clauses[first].facts for x in (f.subject, f.key if f.kind == "location" else "")} - {""}
    named = False
    for ci in after:
        if set(clauses[ci].mentions) & things or not named and set(
                re.findall(r"[a-z]+", clauses[ci].text.lower())) & _TAKING_UP:
            return True
        named = named or bool(clauses[ci].mentions)
    return False


def _framed(clauses: list[Clause], sentence: int, line_of: Mapping[int, tuple[int, int]], *,
            by_paragraph: bool) -> set[int]:
    """The sentences after `sentence` on its line, up to one opening with a condition of its own
    (or, `by_paragraph`, every sentence of its paragraph)."""
    line, paragraph = line_of.get(sentence, (-1, -1))
    covered: set[int] = set()
    for s in sorted({c.sentence for c in clauses if c.sentence > sentence}):
        at = line_of.get(s, (-1, -1))
        opening = next((c for c in clauses if c.sentence == s and (c.role != "statement" or c.facts)), None)
        if (at[1] != paragraph if by_paragraph else at[0] != line) or (
                not by_paragraph and opening is not None and opening.role == "condition" and s != sentence + 1):
            break
        covered.add(s)
    return covered


#: a label answering the question before it ("> YES: ...", "NO (or not sure): ...", "Yes ->"): what
#: follows, up to the next label, question or capitalised heading, holds under that answer
_ANSWER_LABEL = re.compile(r"^\W*(yes|no)\b\s*(?:\([^()]*\))?\W*$", re.I)


def _label(clause: Clause) -> str | None:
    """The answer ("yes", "no") a clause is the label of, if it is one (`_ANSWER_LABEL`): a bare
    "yes"/"no" (a bracket may gloss it) before a colon, a dash or an arrow."""
    m = _ANSWER_LABEL.match(clause.text)
    if m is None or not (clause.cue in (":", "-", "->") or re.search(r"[:>-]\s*$", clause.text)):
        return None
    return m.group(1).lower()


def _asks(clause: Clause) -> bool:
    """Whether a clause is a question about the scene (a condition asked with "?")."""
    return clause.cue == "?" or ends_asking(clause.text)


def _lines(text: str) -> list[tuple[int, int]]:
    """(line, paragraph) of the text each of its sentences (`split_sentences`) starts on, found by
    its first words in order (a sentence not found verbatim, a line joined to the next, takes the
    place of the one before)."""
    out: list[tuple[int, int]] = []
    pos = 0
    for sent in split_sentences(text):
        k = text.find(sent[:24], pos)
        pos = k if k >= 0 else pos
        out.append((text.count("\n", 0, pos), len(re.findall(r"\n[ \t]*\n", text[:pos]))))
    return out


def _opening_indent(texts: list[str], line: int, answer: str) -> int:
    """The indentation (`_indent_of`) of a text's line that opens with the answer label `answer`
    ("         NO -> ..."), or -1 when the line is not indented or opens with something else."""
    if not 0 <= line < len(texts) or not texts[line].lstrip(" \t").lower().startswith(answer):
        return -1
    return _indent_of(texts, line) or -1


def _answered(factors: list[Factor], clauses: list[Clause], line_of: Mapping[int, tuple[int, int]],
              texts: list[str]) -> None:
    """A call script's, flowchart's or FAQ's labelled answers ("Ask: 'Is there bread on the
    counter?' > YES: put it on the plate, and switch the toaster on if it is off. > NO: skip the
    toast."): a factor first raised after a "yes" or "no" label, in the rest of its line (or, for
    a label alone on its line, of its paragraph) and before the next label, question or capitalised
    heading, is asked only under that answer to the question before the label (the yes/no factors
    the question raised), and so in its subtask. A line after the answer's own is a step of its own
    ("NO: leave it. / If the lamp is on, switch it off."). In a text flowchart, where a label
    opens an indented line ("Clean? YES -> ... / NO -> Machine running? / YES -> ..."), the label
    answers the nearest question before it on a line indented less than the label: its answers
    stand one indentation deeper than the question, so a question within an answer has answers
    of its own (`texts`: the text's lines)."""
    answering: set[int] = set()  # clauses within an answer (a question there asks within it)
    for li, label in enumerate(clauses):
        answer = _label(label)
        if answer is None:
            continue
        line, paragraph = line_of.get(label.sentence, (-1, -1))
        indent = _opening_indent(texts, line, answer)
        if indent > 0:
            asked = next((ci for ci in range(li - 1, -1, -1) if _asks(clauses[ci]) and _indent_of(
                texts, line_of.get(clauses[ci].sentence, (-1, -1))[0]) < indent), None)
        else:
            asked = next((ci for ci in range(li - 1, -1, -1) if _asks(clauses[ci]) and ci not in answering), None)
            if asked is not None and any(_label(c) is None and _asks(c) and ci not in answering
                                         for ci, c in enumerate(clauses[asked + 1:li], asked + 1)):
                asked = None
        if asked is None:
            continue
        alone = li + 1 < len(clauses) and line_of.get(clauses[li + 1].sentence, (-1, -1))[0] != line
        # (on the label's own line a question asks within the answer: "YES: Is the toaster on? ...")
        end = next((ci for ci in range(li + 1, len(clauses)) if _label(clauses[ci]) is not None
                    or alone and _asks(clauses[ci]) or _capitalised(clauses[ci].text)
                    or line_of.get(clauses[ci].sentence, (-1, -1))[1 if alone else 0] != (paragraph if alone else line)),
                   len(clauses))
        answering |= set(range(li + 1, end))
        questions = [a for a in factors if (clauses[asked].sentence, asked) in a.places
                     and set(a.values) == {"yes", "no"}]
        for b in factors:
            first = min((ci for _, ci in b.places), default=-1)
            if not li < first < end:
                continue
            for a in questions:
                if a.subject != b.subject and all(dep != a.id for dep, _ in b.context):
                    b.context.append((a.id, frozenset({_answer_value(a, clauses[asked], answer)})))


#: sentences of asides (a speaker's name with a remark that asks and moves nothing, a stage
#: direction) that may stand between an instruction and the condition that takes up its thing
_ASIDE_REACH = 2


def _taken_up_under(factors: list[Factor], clauses: list[Clause]) -> None:
    """A condition asked alone in its sentence on a thing that the instruction just before brings,
    sends or puts something into, under a branch of its own ("If there's a pan in the kitchen, bring
    me the desk lamp. If it's on, switch it off first"; "Any other book goes into the nightstand
    drawer. - It sticks. - Then open it, unless it's already open"): the thing is only dealt with on
    that branch, so its condition is asked only there, not across every situation. Asides with no
    fact between the two sentences (a listener's remark, a stage direction) do not part them
    (`_ASIDE_REACH`). A condition on a thing the instruction before never names ("If the bed is
    unmade, make it. If the lamp is on, ...") or an instruction with no branch ("Bring me the lamp.
    If it's on, ...") sets no such scope (`_branch_of`)."""
    by_sentence: dict[int, list[tuple[int, Clause]]] = {}
    for ci, c in enumerate(clauses):
        by_sentence.setdefault(c.sentence, []).append((ci, c))
    for b in factors:
        if b.context or b.sentence < 1 or any(a.sentence == b.sentence and a.subject != b.subject for a in factors) \
                or not any(s == b.sentence and clauses[ci].role == "condition" for s, ci in b.places):
            continue
        previous = b.sentence - 1
        for _ in range(_ASIDE_REACH):
            if previous < 1 or any(c.facts or c.role != "statement" or _opens_with_action(c.text)
                                   for _, c in by_sentence.get(previous, [])):
                break
            previous -= 1
        own = by_sentence.get(previous, [])
        naming = [k for k, (_, c) in enumerate(own) if c.role in ("consequence", "statement") and (
            b.subject in c.mentions or any(f.goal and f.key == b.subject for f in c.facts))]
        if naming and _only_where_sent(b, own[naming[-1]][1]) and not (
                any(v.startswith(f"state({b.subject}, open)") for v in b.values.values())
                or _relates(b.sentence, clauses)):
            # "If the mug is dirty, put it in the dishwasher. If the dishwasher is full, run it.":
            # where a thing is sent has cases of its own; only its opening for the thing, or an
            # instruction that replaces or prepares the move (`_relates`), is the move's
            continue
        if naming:
            branch = _branch_of(factors, clauses, own, naming[-1], b.subject)
            # (a branch asked under this very condition, read from elsewhere, would make a circle
            # no path meets: the reading already nests them the other way)
            if not _asked_under(b.id, [dep for dep, _ in branch], factors):
                b.context = branch


def _opens_with_action(text: str) -> bool:
    """Whether a clause opens with a verb of acting (after an instruction's lead-ins): an
    instruction, even one whose object a label left out ("Any other kind of book: place in the
    nightstand drawer. To do so, pull the drawer out unless it is already open"), is never an aside
    between an instruction and the condition that takes up its thing ("- It sticks. -" is)."""
    words = re.findall(r"[a-z']+", text.lower())
    k = next((i for i, w in enumerate(words) if w not in _INSTRUCTION_LEADS), len(words))
    return k < len(words) and words[k] in ACTIONS


def _only_where_sent(b: Factor, instruction: Clause) -> bool:
    """Whether the instruction names b's thing only as where another thing goes (a goal's place),
    not as a thing it brings, acts on or uses."""
    goals = [f for f in instruction.facts if f.goal and f.kind == "location"]
    return any(f.key == b.subject for f in goals) and not any(f.subject == b.subject for f in goals)


def _asked_under(target: str, deps: list[str], factors: list[Factor]) -> bool:
    """Whether any of `deps` is asked under `target`, directly or through the factors it is asked
    under."""
    context = {f.id: [d for d, _ in f.context] for f in factors}
    seen: set[str] = set()
    todo = list(deps)
    while todo:
        dep = todo.pop()
        if dep == target:
            return True
        if dep not in seen:
            seen.add(dep)
            todo += context.get(dep, [])
    return False


def _branch_of(factors: list[Factor], clauses: list[Clause], own: list[tuple[int, Clause]], said: int,
               thing: str) -> list[tuple[str, frozenset[str]]]:
    """The branch the instruction `own[said]` of a sentence is given under (`_taken_up_under`): the
    nearest condition before it in its sentence, the instructions between at most (or, with none
    before, the condition put right after it: "Bring me the lamp if there's a pan"), the values it
    asks of the factors on other things; where the thing has a place and a state asked together
    ("Shirt on the floor and not dirty: hang it up"), the place says which thing and the state is
    the case; a sentence that says the condition's fact both ways ("if they are not clean, ...
    - dusty leaves ...", or a misread negation) names no one branch, and the condition stays
    asked everywhere. A list's case with no condition of its own ("a novel -> the shelf; any other book ->
    the drawer") is the value of the moved thing's kind its words name ("other"); none, or an
    instruction with no branch, gives no scope."""
    k = said - 1
    while k >= 0 and own[k][1].role == "consequence":
        k -= 1
    if k >= 0 and own[k][1].role == "statement" and not own[k][1].facts:
        return _case_named(factors, [own[k][1], own[said][1]], thing)
    if k < 0 and said + 1 < len(own) and own[said + 1][1].role == "condition":
        k = said + 1
    if not 0 <= k < len(own) or own[k][1].role != "condition":
        return _case_named(factors, [own[said][1]], thing) if k < 0 else []
    ci, c = own[k]
    facts = [f for f in c.facts if not f.goal and f.subject != thing]
    cases = [f for f in facts if f.kind not in ("location", "exists")]
    branch: list[tuple[str, frozenset[str]]] = []
    for f in facts:
        if f.kind in ("location", "exists") and any(g.subject == f.subject for g in cases):
            continue
        if any(g.condition == f.condition and g.negated != f.negated and not g.goal for _, o in own for g in o.facts):
            # (a sentence saying the condition's fact both ways names no one branch)
            return []
        for a in factors:
            if a.subject == f.subject and (c.sentence, ci) in a.places and f.condition in {
                    v.removeprefix("not ") for v in a.values.values()}:
                value = f.condition.rsplit(", ", 1)[1][:-1] if f.kind == "attr" else f.key
                # (the instruction before "unless ..." is given when its condition does not hold)
                branch.append((a.id, _allowed(a, f.negated != (c.cue == "unless"), value)))
                break
    return _consistent(branch)


def _case_named(factors: list[Factor], said: list[Clause], thing: str) -> list[tuple[str, frozenset[str]]]:
    """The one value of a moved thing's kind that a case's words name ("Any other book goes into
    the drawer": the kind's `other`; "Novels go on the shelf": `novel`), as the case's branch."""
    words = {w for c in said for w in re.findall(r"[a-z]+", c.text.lower())}
    moved = {f.subject for c in said for f in c.facts if f.goal and f.kind == "location"} | {
        m for c in said for m in c.mentions}
    for a in factors:
        if a.kind == "attr" and a.subject in moved and a.subject != thing:
            named = [v for v in a.values if ({v} | set(noun_plurals(v))) & words]
            if len(named) == 1:
                return [(a.id, frozenset(named))]
    return []


def _indent_of(texts: list[str], line: int) -> int:
    """The indentation of a text's line (a large number for a line not found)."""
    if not 0 <= line < len(texts):
        return 1 << 16
    return len(texts[line]) - len(texts[line].lstrip(" \t"))


def _answer_value(factor: Factor, question: Clause, answer: str) -> str:
    """The factor's value a "yes" or "no" answer to the question gives: the answer itself, or
    the other one where the question asks the factor's state in its opposite word ("Clean? NO ->
    ..." answers the mug's dirtiness "yes", "Kettle empty? YES -> ..." its fill "no"), as the
    question's fact is the negation of the factor's "yes"."""
    said = [x.negated for x in question.facts if x.condition == factor.values["yes"]]
    return {"yes": "no", "no": "yes"}[answer] if said and all(said) else answer


#: a tool sentence whose purpose is an instruction's verb with a pronoun object ("Use the sponge
#: to wipe it", "grab a cloth to dry them", "take the brush to do so"): the verb is the group
_PURPOSE_TOOL = re.compile(r"^\W*(?:(?:just|then|and|so|please|now)\W+)*(?:use|take|grab|get|fetch|pick\s+up)\s+"
                           r"[^,;:.!?]*?\bto\s+([a-z]+)\s+(?:it|them|this|that|so|those|these)\b", re.I)
#: verbs that stand for any instruction before them ("to do it", "to do so")
_PRO_VERBS = frozenset({"do"})
#: a sentence that is only a tool phrase ("With the sponge, if ...", "And with the dish cloth!"):
#: "with", a determiner at most, and a name of up to three words, nothing after it
_WITH_ONLY = re.compile(r"^\W*(?:(?:and|then|but|so|or|now)\W+)*with\s+(?:(?:the|a|an|your|our|my|some|that|this)\s+)?"
                        r"[a-z]+(?:[ -][a-z]+){0,2}\W*$", re.I)


def _takes_up(cl: Clause, clauses: list[Clause], previous: int) -> bool:
    """A tool sentence whose purpose takes up the verb of the instruction before ("You only need to
    wipe the table if it is dirty. Use the sponge to wipe it, if there is one."): it says how that
    instruction is done, so its tool is asked under that instruction's conditions. A tool sentence
    with a verb of its own ("Use the cloth to dust the shelf") or an object of its own ("to wipe
    the counter") is an instruction of its own."""
    m = _PURPOSE_TOOL.match(cl.text)
    if m is None or cl.role not in ("uncertain", "consequence", "statement"):
        return False
    verbs = set(getAllLemmas(m.group(1).lower()).get("VERB", ()))
    if verbs & _PRO_VERBS:
        return any(c.sentence == previous and c.role == "consequence" for c in clauses)
    said = {lemma for c in clauses if c.sentence == previous and c.role in ("consequence", "statement")
            for w in re.findall(r"[a-z]+", c.text.lower()) for lemma in getAllLemmas(w).get("VERB", ())}
    return bool(verbs & said)


def _with_tool(cl: Clause) -> bool:
    """A sentence opening with a verbless "with" phrase ("With the sponge, if the sponge is lying
    on the counter!"): the tool of the instruction before, so a condition on the tool, of any kind,
    is asked under that instruction's conditions. A "with" phrase opening an instruction of its
    own ("With the sponge, wipe the shelf") has a verb and is not this."""
    return cl.role in ("consequence", "statement") and _WITH_ONLY.match(cl.text) is not None


def _capitalised(text: str) -> bool:
    """Whether a clause is a heading written in capitals ("STEP 2", "CLOSING")."""
    letters = re.sub(r"[^A-Za-z]", "", text)
    return len(letters) >= 3 and letters.isupper() and _ANSWER_LABEL.match(text) is None


def _consistent(context: list[tuple[str, frozenset[str]]]) -> list[tuple[str, frozenset[str]]]:
    """A factor's context with each factor it depends on once: the values allowed by every
    condition on it, or, when those conditions exclude each other, the values any of them allows
    ("where it goes depends on whether it's dirty or clean: a dirty white one goes ...": both
    answers of the question before the cases, which no path meets, so the factor under them would
    never be asked)."""
    merged: dict[str, frozenset[str]] = {}
    for dep, allowed in context:
        both = merged.get(dep, allowed) & allowed
        merged[dep] = both or merged[dep] | allowed
    return list(merged.items())


#: words by which a later instruction speaks of whichever of two alternatives was used ("put
#: whichever you used back on the counter", "whatever was used goes back in the drawer",
#: "whichever you used must be returned to the counter", "return whichever you used to the shelf")
_EITHER = r"\b(?:whichever|whatever|either one|either of them)\b"
_RETURNED = r"\b(?:back|return|returns|returned|replace|replaced)\b"
_EITHER_USED = re.compile(rf"{_EITHER}.*{_RETURNED}|{_RETURNED}.*{_EITHER}")


#: the sentences after a condition within which its absence may be asked and answered ("With the
#: sponge, if the sponge is on the counter! - And if it is not? - Then with the dish cloth!")
_ABSENCE_REACH = 4


def _answered_absence(clauses: list[Clause], ci: int, condition: str) -> int | None:
    """The clause that answers a later condition of the absence of `condition` in its own
    sentence ("And if it is not?" then "Then with the dish cloth!", a dialogue's turns or a Q&A):
    the first clause after that condition, in the sentences that follow it, that names a thing,
    whatever speaker labels come between; None when no such condition follows."""
    sentence = clauses[ci].sentence
    for j in range(ci + 1, len(clauses)):
        cl = clauses[j]
        if cl.sentence > sentence + _ABSENCE_REACH:
            return None
        if cl.sentence > sentence and cl.role == "condition" and any(
                x.negated and x.condition == condition for x in cl.facts):
            return next((k for k in range(j + 1, len(clauses)) if clauses[k].sentence > cl.sentence
                         and clauses[k].sentence <= cl.sentence + 2 and clauses[k].mentions
                         and clauses[k].role in ("statement", "consequence")), None)
    return None


def _alternatives_put_back(factors: list[Factor], clauses: list[Clause]) -> list[Factor]:
    """An alternative used when a thing is not at a place, later put back there with the thing
    ("wipe it with the sponge if the sponge is on the counter; otherwise use the cloth. Put
    whichever you used back on the counter"): "back" says the alternative was there too, as far as
    the thing was, so whether it is there is asked where the thing is not (a factor under the
    thing's "no"), as a reader asks what else lies on the counter."""
    out: list[Factor] = []
    asked = {(f.subject, v) for f in factors for v in f.values.values()}
    for f in factors:
        at = _at(f.values.get("yes", "")) if f.kind == "location" and set(f.values) == {"yes", "no"} else None
        if at is None:
            continue
        thing, holder = at
        for sentence, ci in sorted(f.places):
            rest = [j for j in range(ci + 1, len(clauses)) if clauses[j].sentence == sentence]
            # "otherwise use the cloth", "and if it's not, use the cloth": the instruction for the
            # thing's absence
            alternative = next((j for j in rest if clauses[j].role == "else" or (
                clauses[j].role == "consequence" and clauses[j - 1].role == "condition" and any(
                    x.negated and x.condition == f.values["yes"] for x in clauses[j - 1].facts))), None)
            if alternative is None:
                alternative = _answered_absence(clauses, ci, f.values["yes"])
            end = sentence if alternative is None else clauses[alternative].sentence
            # the next two sentences, each read whole ("whichever u used -> back on counter": cut
            # at the arrow)
            later: dict[int, tuple[str, set[str]]] = {}
            for cl in clauses[ci + 1:]:
                if sentence < cl.sentence <= end + 2 or cl.sentence == sentence:
                    text, mentions = later.get(cl.sentence, ("", set()))
                    later[cl.sentence] = (f"{text} {cl.text.lower()}", mentions | set(cl.mentions))
            back = any(_EITHER_USED.search(text) and holder in mentions for text, mentions in later.values())
            if alternative is None or not back:
                continue
            for other in clauses[alternative].mentions:
                cond = f.values["yes"].replace(f"({thing},", f"({other},", 1)
                if other in (thing, holder) or (other, cond) in asked:
                    continue
                asked.add((other, cond))
                g = Factor(f"{other}_{cond.split('(')[0]}_{holder}", other, _question(other, "location", "", [holder]),
                           {"yes": cond, "no": f"not {cond}"}, "location", alternative, sentence, alternative,
                           [clauses[alternative].text], set(clauses[alternative].mentions))
                g.context = [*f.context, (f.id, frozenset({"no"}))]
                out.append(g)
    return out


#: the pronouns that take up a definite thing: "have it in my bag" (not "have one", any thing)
_DEFINITE_PRONOUNS = frozenset({"it", "them"})


def _had_somewhere(words: list[str], m: Mention) -> bool:
    """Whether a thing "had" (`_WE_HAVE`) is a definite pronoun with a place right after it
    ("I think I have it in my bag", "we might have them on the desk"): the place it is had in,
    an alternative to the place the text doubts, not a doubt that it is there at all."""
    return m.kind == "pronoun" and words[m.start] in _DEFINITE_PRONOUNS and m.end < len(words) \
        and words[m.end] in PREP_IN | PREP_ON


#: the words a clause's predicate opens with (a copula, a perfect, a modal, a verb of resting):
#: a place said before one is in the subject's phrase ("the lamp on the nightstand may be on")
_PREDICATE_OPENERS = frozenset({
    "is", "are", "was", "were", "be", "been", "has", "have", "had", "may", "might", "could", "can",
    "will", "would", "should", "must", "seems", "seem", "looks", "appears", "gets", "got", "stays",
    "remains", "keeps", "sits", "lies", "stands", "hangs"})


def _identifying_place(f: Fact, cl: Clause) -> bool:
    """Whether `f` is the place a thing is named by ("the lamp on the nightstand", "the desktop
    computer on the desk"), said before the predicate, in a doubt whose predicate is the thing's
    state ("... may be on", "... is left running more often than not"): the doubt is the
    state's, the place says which thing is meant, as it would in a plain statement. A place in
    the predicate ("the towel might be on the floor and wet") is still doubted."""
    if f.kind != "location" or f.goal or not _state_asked(f.subject, cl.facts):
        return False
    words = re.findall(r"[a-z']+", cl.text.lower())
    verb = next((k for k, w in enumerate(words) if w in _PREDICATE_OPENERS), None)
    # (no predicate opener, no subject phrase to name the thing by: "Maybe I forgot my glasses
    # on the table" doubts the place itself)
    return verb is not None and any(w in PREP_ON | PREP_IN for w in words[1:verb])


def _state_asked(role: str, facts: Iterable[Fact]) -> bool:
    """Whether the clause asks a state of `role` (not one it is to be brought to)."""
    return any(g.subject == role and g.kind == "state" and not g.goal for g in facts)


def _holds_another(role: str, facts: Iterable[Fact]) -> bool:
    """Whether the clause places another thing on or in `role` ("the lamp on the nightstand in
    the bedroom"): then a room said after `role` names which holder is meant, no doubt of it."""
    return any(g.kind == "location" and not g.goal and g.key == role and g.subject != role for g in facts)


def _floor_bound(cat: Category | None) -> bool:
    """Whether a role's kind can be nowhere but on the floor and is neither carried nor a holder
    (a puddle, a stain, a rug: no furniture, which a location never moves): where it is not on the
    floor, it is not at all."""
    return cat is not None and not cat.pickable and set(cat.placement) == {"floor"} and not (
        cat.surface or cat.container)


def _moved(clause: Clause, subject: str) -> bool:
    """Whether the clause says where `subject` goes (a location goal of it): a verbless list
    after an instruction that moves things (`_elaborates`) reads its places as goals."""
    return any(f.goal and f.kind == "location" and f.subject == subject for f in clause.facts)


#: relative pronouns: a noun phrase with a relative clause ("a plate that is wet") names a class
#: the sentence gives a rule for, not a thing it places
RESTRICTIVE = frozenset({"that", "which", "who", "whichever", "whatever"})


def _placed_outright(brief: Mapping[str, Any], catalog: Catalog, text: str) -> set[str]:
    """The roles a plain statement places outright (`offline.placement`'s settled placements:
    "A dirty mug is sitting on the desk", "There's a wet towel on the floor"; not "A dirty plate
    on the table goes into the dishwasher", whose verb moves it): the statement asserts the
    thing as it describes it, so the states its noun phrase gives it are facts, not factors. A
    sentence with a relative clause (`RESTRICTIVE`) gives a rule for a class, and places nothing."""
    if {w for w, _, _ in tokens(text)} & RESTRICTIVE:
        return set()  # "A clean plate that is wet stays on the table": a relative clause restricts, a rule
    told = described_placements({**brief, "description": text}, catalog, kinds=frozenset({"settled"}))
    return {f.split("(", 1)[1].split(",", 1)[0] for f in told if f.startswith(("on(", "inside(", "in_room("))}


def _settle_stated(factors: list[Factor], brief: Mapping[str, Any], catalog: Catalog,
                   slot_factor: dict[tuple[str, str, str], Factor], homes: set[str],
                   asked: frozenset[str] | set[str] = frozenset(),
                   doubted: frozenset[str] | set[str] = frozenset()) -> list[Factor]:
    """A placement the description states (`offline.placement`: "a coffee table with a mug on it", "a
    kitchen with a stove") is no uncertain location: its yes/no factor is dropped. So is where an
    object is kept ("it's kept in the vanity, unless someone stuffed it into the medicine
    cabinet"): a factor listing the places it may be asks about the others (`_drop_home`) —
    unless the text speaks of somewhere else ("wherever else it may be lying"). A home asked with
    "already" (`asked`: "Your doll sleeps on the bed. Put her there, unless she's already on it")
    is doubted: its factor stays; so is a placement a later condition asks by "there" (`doubted`:
    "There's a plate on the counter ... and no plate there at all?")."""

    cued = _elsewhere_cued(as_read(str(brief.get("description", ""))))
    settled = set(described_placements(brief, catalog, kinds=frozenset({"settled"})))
    settled |= {f for f in described_placements(brief, catalog, kinds=frozenset({"settled", "kept"}))
                if not cued(f.split("(", 1)[1].split(",", 1)[0])}
    # where the placement reader or this reader ("The shampoo and the soap are kept in the wall
    # cabinet") finds a thing kept
    kept = set(described_placements(brief, catalog, kinds=frozenset({"kept"}))) | homes
    # an object the text places outright ("On the floor: a dirty mark") is nowhere else in question
    placed = {f.split("(", 1)[1].split(",", 1)[0] for f in described_placements(
        brief, catalog, kinds=frozenset({"settled"})) if f.startswith(("on(", "inside("))}
    # "fetch a spare from the dresser (that's where the spares are kept)": a thing the text places
    # on or in a holder that is both (a dresser, a cabinet) is asked neither on it nor in it
    held = {_at(x) for x in settled} - {None}
    proper = set(described_placements(brief, catalog, kinds=frozenset({"settled"})))  # stated, not a home
    out: list[Factor] = []
    for f in factors:
        values = set(f.values.values())
        if f.kind == "location" and set(f.values) == {"yes", "no"} and (
                settled & values or f.subject in placed or {_at(v) for v in values} & held) and not (
                    values & set(asked) and not values & proper or values & set(doubted)):
            for slot, g in list(slot_factor.items()):
                if g is f:
                    del slot_factor[slot]
            continue
        if f.kind == "location" and "elsewhere" in f.values and kept & values and not cued(f.subject):
            _drop_home(f, kept)
        out.append(f)
    return out


_AT = re.compile(r"^(?:on|inside)\((\w+), (\w+)\)$")


def _at(fact: str) -> tuple[str, str] | None:
    """(thing, holder) of an `on`/`inside` fact, whichever of the two it says."""
    m = _AT.match(fact)
    return (m.group(1), m.group(2)) if m else None


#: a line that opens a list item or a new paragraph: where a bulleted note moves on to its next thing
_BLOCK_BREAK = re.compile(r"\n\s*\n|\n(?=\s*(?:[-*\u2022\u2013]|\d+[.)])\s)")
#: where a sentence of a block ends, for the sentences a cue of somewhere else looks back over
_SENTENCE_BREAK = re.compile(r"(?<=[.!?])\s+|\n")


def _elsewhere_cued(description: str) -> Callable[[str], bool]:
    """Which things a cue of somewhere else (`ELSEWHERE`: "on the hook, or anywhere else, nothing
    to do") may speak of: in a text of one block, every thing; in a text of paragraphs or list
    items, the things named in the blocks that say a cue (`_BLOCK_BREAK`), so that one item's
    "anywhere else" leaves another item's home ("the water bottle lives on the bench") settled.
    A thing whose role's words no block says is taken as spoken of (the old, text-wide reading);
    one said by some of its words only ("the soap" of soap_bar) is found by them. A cue looks
    back: within its block it speaks of the things named up to the end of its sentence, never of
    one named only after it ("Torch on the desk? Hang it up. Anywhere else, leave it. The first aid
    kit is kept on the shelf." leaves the kit's home settled)."""
    # "There's always one left by the door, isn't there, Maureen.": a tag asks for agreement and
    # says nothing of anywhere else, so its "not there" is no cue of another place (`_TAG`)
    said = [[[w for w, _, _ in tokens(_TAG.sub(" ", expand(s)))] for s in _SENTENCE_BREAK.split(b)]
            for b in _BLOCK_BREAK.split(description) if b.strip()]
    blocks = [{w for ws in sents for w in ws} for sents in said]
    last = [max((i for i, ws in enumerate(sents) if _says_elsewhere(" ".join(ws))), default=-1) for sents in said]
    # per block, the words up to the end of its last cue's sentence (none where it says no cue)
    before = [{w for ws in sents[:i + 1] for w in ws} for sents, i in zip(said, last, strict=True)]
    any_cue = any(i >= 0 for i in last)

    def cued(role: str) -> bool:
        if not any_cue:
            return False
        words = set(words_of(role))
        # a role named by other words than its name ("the soap" for soap_bar) is found by any of them
        names: Callable[[set[str]], bool] = (lambda b: words <= b) if any(words <= b for b in blocks) \
            else (lambda b: bool(words & b))
        return not any(names(b) for b in blocks) or any(names(b) for b in before)

    return cued


def _says_elsewhere(text: str) -> bool:
    """Whether words joined by spaces say a cue of somewhere else (`ELSEWHERE`, "wherever")."""
    return any(re.search(rf"\b{cue}\b", text) for cue in ELSEWHERE + ("wherever",))


def _drop_home(f: Factor, kept: set[str]) -> None:
    """Where a thing is kept is its norm, not what is uncertain about it ("The soap is kept in
    the wall cabinet. There may be a bar of soap in the tub"): the factor asks about the other
    places, and stays exhaustive (a yes/no for one place, else the places and "elsewhere")."""
    rest = {k: v for k, v in f.values.items() if k != "elsewhere" and v not in kept}
    if not rest:
        return
    if len(rest) == 1:
        ((target, cond),) = rest.items()
        f.values = {"yes": cond, "no": f"not {cond}"}
        f.id = f"{f.subject}_{cond.split('(')[0]}_{target}"
    else:
        f.values = {**rest, "elsewhere": " and ".join(f"not {c}" for c in rest.values())}
    f.question = _question(f.subject, "location", "", list(rest))


def _contrasted(clauses: list[Clause], text: str) -> set[tuple[str, str]]:
    """(subject, key) of derived attributes the text contrasts, so that they decide something:
    an adjective said of the object both positively and negated (`a ripe one ..., one that is not
    ripe ...`, `ripe` / `unripe`, `if it's ripe, ...; otherwise ...`), a kind stated in a condition (`if it is a bill`) or set against
    `other` objects of its sort (`any other document`)."""
    polarity: dict[tuple[str, str], set[bool]] = {}
    out: set[tuple[str, str]] = set()
    low = " " + " ".join(w for w, _, _ in tokens(expand(text))) + " "
    for ci, cl in enumerate(clauses):
        # "if it's ripe, put it in the fridge; otherwise ...": an alternative answers the condition
        answered = cl.role == "condition" and bool(cl.facts) and all(f.derived for f in cl.facts) and any(
            c.role == "else" and c.sentence == cl.sentence for c in clauses[ci + 1:])
        for f in cl.facts:
            if not f.derived:
                continue
            polarity.setdefault((f.subject, f.key), set()).add(f.negated)
            if answered:
                polarity[(f.subject, f.key)].add(not f.negated)
            if f.key == "kind" and (cl.role == "condition" or f" other {f.subject.replace('_', ' ')} " in low):
                out.add((f.subject, f.key))
    return out | {s for s, pols in polarity.items() if len(pols) == 2}


def _moves_into(factors: list[Factor], clauses: list[Clause]) -> list[tuple[str, str]]:
    """(thing, container) for each container whose being open is asked alone in its sentence
    while that sentence or the one before moves a thing into it (a goal fact, or an instruction
    under a factor of the thing that names the container): "... it needs to go into the
    fridge. I can't remember whether I shut the fridge door, so you might have to open it", "Any
    other book goes in the nightstand drawer: open the drawer first unless it is already open".
    Whether the container is open is asked for that move, in the thing's subtask."""
    out: list[tuple[str, str]] = []
    for b in factors:
        if b.kind != "state" or not any(v.startswith(f"state({b.subject}, open)") for v in b.values.values()) \
                or any(a.sentence == b.sentence and a.subject != b.subject for a in factors):
            continue
        moved = [f.subject for c in clauses if c.sentence in (b.sentence - 1, b.sentence) for f in c.facts
                 if f.goal and f.kind == "location" and f.key == b.subject and f.subject != b.subject
                 and f.condition.startswith("inside(")]
        # or an instruction of the sentence before, under a factor of the thing, names the container
        moved = moved or [a.subject for a in factors if a.sentence == b.sentence - 1 >= 0
                          and a.subject != b.subject and b.subject in a.roles]
        if moved:
            out.append((moved[-1], b.subject))
    return out


#: Words by which an instruction replaces one given before ("..., the shirt goes on the rack
#: instead"; "instead" after the instruction is also split off as an `else` clause, clauses.py),
#: and words by which it prepares one ("If the can's empty, fill it at the sink first"; opening
#: its clause, "first" orders steps instead: "First, the plant."). The instruction it relates to
#: was given under a factor of the sentence before, so both are asked in one subtask (`_answers`)
REPLACING_WORDS = frozenset({"instead"})
PREPARING_WORDS = frozenset({"first", "beforehand"})
#: the marks after a label that opens a sentence ("Note: unless ...", "Caution - unless ...")
LABEL_CUES = frozenset({":", "-"})


def _relates(sentence: int, clauses: list[Clause]) -> bool:
    """Whether the sentence's instruction replaces or prepares an earlier one (`REPLACING_WORDS`,
    an empty `else` clause, or `PREPARING_WORDS` after its clause's first word), or opens with
    "unless": "If it is dirty, into the dishwasher it goes! Unless the dishwasher is already
    running: then into the sink" is the exception to the instruction before, as "instead" would
    say."""
    own = [c for c in clauses if c.sentence == sentence]
    while own and own[0].role == "statement" and own[0].cue in LABEL_CUES \
            and len(WORD.findall(own[0].text)) <= 2 and all(f.derived for f in own[0].facts):
        # "Note: unless the dishwasher is running, ...", "Caution - unless ...": a label before
        # the exception says nothing of it (its "noteness" is a guess, never asked)
        own = own[1:]
    if own and own[0].role == "condition" and own[0].cue == "unless":
        return True
    for c in own:
        words = re.findall(r"[a-z]+", c.text.lower())
        # (an `else` clause with no words of its own is "instead" closing the instruction before
        # it; one with words is the alternative of its own sentence's condition: "wipe w/ sponge
        # if sponge is on the counter, else dish cloth" replaces nothing said before)
        if c.role == "else" and not words or set(words) & REPLACING_WORDS or set(words[1:]) & PREPARING_WORDS:
            return True
    return False


def _answers(factors: list[Factor], clauses: list[Clause]) -> list[tuple[str, str]]:
    """(thing, other) for each factor on another object, asked alone in its sentence, whose
    instruction acts on a thing whose place or presence is asked in the sentence just before (not
    a place a thing goes to, whose state was asked there) ("Q: What about a towel in
    the dryer? A: Once the dryer has stopped, take the towel out ..."): the sentence answers the
    question about the thing, so its factor is asked in the thing's subtask."""
    out: list[tuple[str, str]] = []
    for b in factors:
        # the thing the sentence just before sends to b's subject, and b's instruction then acts
        # on that thing ("If it is dirty, it goes straight into the washing machine. Be advised:
        # when the machine is already running, the shirt goes into the hamper instead"): where the
        # thing goes depends on both, one subtask, as when one sentence says both
        # (one of the two named suffices when the instruction replaces or prepares one given
        # before: "Should it be wet, dry it there. Whilst the dryer is running, the shirt goes on
        # the rack instead" names no dryer in the first instruction)
        either = _relates(b.sentence, clauses)
        # (with one name enough, the thing b's instruction moves counts as named: "A dirty mug
        # goes in the dishwasher. Note: unless it is running - then leave it in the sink", the
        # mug's factor read from a modifier has no instruction of its own to name the dishwasher)
        moved = {f.subject for c in clauses if c.sentence == b.sentence for f in c.facts
                 if f.goal and f.kind == "location"} if either else set()
        sent = [a.subject for a in factors if b.sentence >= 1 and a.subject != b.subject
                and (a.sentence == b.sentence - 1 or any(at == b.sentence - 1 for at, _ in a.places))
                and ((b.subject in a.roles) + (a.subject in b.roles | moved) >= (1 if either else 2))]
        if sent:
            out.append((sent[-1], b.subject))
            continue
        if any(a.sentence == b.sentence and a.subject != b.subject for a in factors):
            continue
        asked = [a.subject for a in factors if a.sentence == b.sentence - 1 >= 0 and a.subject != b.subject
                 and a.kind in ("location", "exists") and a.subject in b.roles]
        if asked:
            out.append((asked[-1], b.subject))
    return out


def _group(factors: list[Factor],
           moves: Iterable[tuple[str, str]] = ()) -> tuple[list[list[str]], list[set[str]]]:
    """Independent subtasks: factors on one subject, joined with factors of other subjects that
    the same sentence makes depend on them (`a dirty plate goes into the dishwasher, but when the
    dishwasher is running ...`), and a container's being open with the thing moved into it
    (`_moves_into`), and a thing's place in a holder with the holder's state asked in the same
    clause ("if there's a towel inside and the dryer has stopped"). Subjects listed in one clause
    otherwise stay independent."""
    parent: dict[str, str] = {f.subject: f.subject for f in factors}

    def find(x: str) -> str:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a in factors:
        for b in factors:
            if a.subject != b.subject and a.sentence == b.sentence >= 0 and a.clause != b.clause:
                parent[find(b.subject)] = find(a.subject)
            elif a.subject != b.subject and any(sa == sb and ca != cb for sa, ca in a.places
                                                for sb, cb in b.places):
                # restated later in a sentence that makes them depend ("a dirty shirt goes into the
                # machine, unless the machine is running")
                parent[find(b.subject)] = find(a.subject)
    for a in factors:
        # "if there's a towel inside and the dryer has stopped": a thing's place in a holder and
        # the holder's own state, asked in one clause, are one subtask
        held = {x for v in a.values.values() for x in re.findall(r"\b(?:on|inside)\(\w+, (\w+)\)", v)}
        for b in factors:
            if a.kind == "location" and b.kind == "state" and b.subject in held and a.places & b.places:
                parent[find(b.subject)] = find(a.subject)
    for moved, container in moves:
        if moved in parent and container in parent:
            parent[find(container)] = find(moved)
    subject_of = {f.id: f.subject for f in factors}
    for f in factors:  # a factor asked only under another's value belongs to its subtask
        for dep, _ in f.context:
            if dep in subject_of and find(subject_of[dep]) != find(f.subject):
                parent[find(f.subject)] = find(subject_of[dep])
    order: dict[str, list[str]] = {}
    for f in factors:
        order.setdefault(find(f.subject), []).append(f.id)
    groups = list(order.values())
    by_id = {f.id: f for f in factors}
    roles = [set().union(*({by_id[i].subject} | by_id[i].roles for i in g)) for g in groups]
    return groups, roles


def _consequence_under(f: Factor, holding: bool) -> str:
    """The first instruction said for the branch where the factor's condition holds (or does
    not): "if the lamp is off, switch it on" plans its action under "no", and a branch nothing
    is said for leaves the thing as it is. A factor read without branches (one built from a
    reply, `Factor.under` empty) keeps its first instruction under the condition."""
    under = f.under or [True] * len(f.consequences)
    said = [c for c, u in zip(f.consequences, under, strict=False) if u == holding]
    return said[0] if said else "leave it as it is"


def _after_their_conditions(subjects: list[str], factors: list[Factor]) -> list[str]:
    """The subjects in asking order, each after the subjects of the factors it is asked under: a
    condition taken up on a branch ("Any other book goes into the drawer. Open it unless it is
    open") may be said before the branch's own factor is read (a kind read from a list of cases),
    and one asked before its branch's factor would be asked on every path. A circle of such
    conditions keeps the order said."""
    order = list(subjects)
    subject_of = {f.id: f.subject for f in factors}
    for _ in range(len(order)):
        moved = False
        for f in factors:
            for dep, _allowed_values in f.context:
                before = subject_of.get(dep)
                if before is not None and before != f.subject and order.index(before) > order.index(f.subject):
                    order.remove(f.subject)
                    order.insert(order.index(before) + 1, f.subject)
                    moved = True
        if not moved:
            break
    return order


def nest(factors: list[Factor]) -> dict[str, Any]:
    """A decision tree over one subtask's factors.

    Factors are asked subject by subject, where the object is (location/existence) first; when
    an object is not where the task handles it (a location's `no`/`elsewhere` branch, or absent),
    its remaining factors are not asked, but other subjects' factors still are.
    """
    subjects = _after_their_conditions(list(dict.fromkeys(f.subject for f in factors)), factors)
    ordered = sorted(factors, key=lambda f: (subjects.index(f.subject), _RANK[f.kind], f.order))

    # a factor asked only under another's value is not asked on a path that passed that other
    # by (its own context unmet: "Machine running? YES -> Hamper full?" is not asked where the
    # machine's question is not)
    rank = {f.id: k for k, f in enumerate(ordered)}

    def asked(f: Factor, skipped: frozenset[str], path: dict[str, str]) -> bool:
        return f.subject not in skipped and all(
            path[dep] in allowed if dep in path else rank.get(dep, len(ordered)) > rank[f.id]
            for dep, allowed in f.context)

    def build(i: int, skipped: frozenset[str], path: dict[str, str]) -> dict[str, Any]:
        while i < len(ordered) and not asked(ordered[i], skipped, path):
            i += 1
        if i == len(ordered):
            return {"plan": [], "goal": "true"}
        f = ordered[i]
        branches = {}
        for value in f.values:
            stop = f.kind in ("location", "exists") and value in ("no", "elsewhere") and f.stops
            branches[value] = build(i + 1, skipped | {f.subject} if stop else skipped, {**path, f.id: value})
            if not f.consequences:
                continue
            leaf = branches[value]
            if "plan" in leaf and not leaf["plan"]:
                leaf["plan"] = [_consequence_under(f, value not in ("no", "elsewhere", "other"))]
        return {"var": f.id, "query": f.question, "branches": branches}

    return build(0, frozenset(), {})

