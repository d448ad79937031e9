"""Where the description says things are, read as a careful reader (an LLM) reads it.

A description states some placements outright, whatever the situation, in many grammatical
forms: a copular or locative clause ("the cardboard box is on the floor", "the bath mat lies on
the floor", "the dishwasher, the sink and a cabinet are in the kitchen"), a possessive ("the
kitchen has the dishwasher, ...", "the basket also holds a box of cereal", "a nightstand with a
lamp on it"), an existential ("there is a dirty mark on the floor"), a relative clause ("a
nightstand on which a lamp stands", "the bucket, which stands on the floor", "the kitchen, where
the fridge is"), a heading ("Bedroom: the table lamp, ...", "On the floor: a dirty mark"), a
framing phrase ("In the kitchen there are two pet bowls"), a room word before a noun ("the
bedroom wardrobe"). Where an object is *kept* ("the spares are kept in the vanity", "we store it
in the vanity", "it's where the flashlight lives") is its home, which the text may still doubt,
and is read apart from where it *is*; nothing is placed from a condition, a question, an
instruction (where a thing goes) or a doubted clause ("there might be a book on the floor").

The reader works on clauses (`_clauses`, cut by `offline.clauses.clause_spans`): a sentence is cut
at semicolons, dashes, brackets and before a subordinate clause, each clause gets its mood (a
statement, a condition, an instruction), and the subject of a statement is the noun-phrase list
before its verb, not the nearest noun. The words each form turns on are the data tables below. Like
the analyser, this reads only the brief (description, rooms, roles), never ground truth.
"""

from __future__ import annotations

import json
import re
import threading
from collections import OrderedDict
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from lemminflect import getAllLemmas

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.offline.clauses import (
    AGENT_TIMES,
    DOUBT,
    FRONT_LEADS,
    IMPERATIVES,
    LEAD_INS,
    NEGATIONS,
    PUNCT,
    SUBORDINATORS,
    Span,
    clause_spans,
    doubts,
    fronted_time,
    presence_asked,
)
from logicenveval.offline.lexicon import (
    COLOR_WORDS,
    FURNITURE_PARTS,
    PART_TIES,
    RELATIVE,
    Lexicon,
    Mention,
    singular,
    verb_form,
    without_modifiers,
)
from logicenveval.offline.sentences import (
    ACTIONS,
    ARROW_MARK,
    BELIEFS,
    CARELESS,
    DEFINITE_OPENERS,
    FREQUENCY,
    NORM_ADVERBS,
    PERSONAL_SUBJECTS,
    PREP_IN,
    PREP_ON,
    STATE_WORDS,
    TAKING_FROM,
    as_read,
    determiner,
    expand,
    foreign,
    habitual,
    split_sentences,
    taken_word,
)
from logicenveval.offline.vocabulary import reading_catalog

# ---------------------------------------------------------------------------------------------
# Reading rules (data tables). Each names a class of words, never a task's phrase or object.
# ---------------------------------------------------------------------------------------------

#: verbs that say where a thing belongs rather than where it is now ("it's kept in the vanity",
#: "we store the spares in the vanity", "the cloth lives in the vanity"; supplies "are stocked in
#: the hall cupboard", as a shop or a store room says it)
KEEP_VERBS = frozenset({"keep", "keeps", "kept", "store", "stores", "stored", "live", "lives", "lived",
                        "sleep", "sleeps", "stock", "stocks", "stocked"})
#: forms of "be" and of verbs of resting that state where a thing is ("is", "lies", "is lying",
#: "stands", "sits", "rests", "hangs", "stays")
BE = frozenset({"is", "are", "was", "were", "be", "been", "being", "am"})
#: words that rank the parts of a thing ("on the bottom shelf", "in the top drawer"): the part is
#: the thing's, so the place is the thing ("the top of the ..." is not: "of" follows)
RANKS = frozenset({"top", "bottom", "middle", "upper", "lower", "first", "second", "third"})
#: pronouns that take up a thing put first ("the mug on the desk, is it dirty?")
RESUMPTIVE = frozenset({"it", "they"})
STATIVE = frozenset({"lie", "lies", "lay", "lying", "sit", "sits", "sat", "sitting", "stand", "stands",
                     "stood", "standing", "rest", "rests", "resting", "hang", "hangs", "hanging",
                     "stay", "stays", "wait", "waits", "waiting", "leaning", "lean",
                     "leans", "propped",
                     # slang ("chilling on the desk")
                     "chill", "chills", "chilling"})
#: participles that state a result ("has been left on the floor", "are found in the kitchen"):
#: after a perfect ("has/have been") all of these state a place; after a plain "is/are" only the
#: `PASSIVE_STATIVE` ones do ("is put on the bed" is an instruction in the passive voice)
#: participles of placement in a formal register (patents, inventories, specifications: "a box
#: disposed on a stool", "the lamp is positioned on the desk", "a hook mounted on the door"): they
#: say where a thing is, as "located" does, never where it should go
PLACED = frozenset({"located", "situated", "disposed", "positioned", "arranged", "mounted", "received",
                    "housed", "seated", "perched", "stationed"})
#: participles of observing and recording: in a report's past or perfect passive ("a cup was noted
#: on the desk", "a towel was recorded on the bed during the inspection", "a book has been logged
#: on the sofa") they say where the thing was when it was seen, never where it should go; not
#: `PASSIVE_STATIVE`: a present one is a condition's ("where a cup is noted on the desk, wash it")
OBSERVED = frozenset({"noted", "observed", "recorded", "logged", "reported", "sighted", "photographed",
                      "spotted", "noticed"})
#: participles of putting a thing away (the nineteenth session): "the apple is tucked in the
#: fridge", "a spare key was stashed in the bowl", "the scarf is stowed in the basket". Like `kept`
#: they say where the thing now is, after a plain "is" too, so they join `PASSIVE_STATIVE`
STOWED = frozenset({"tucked", "stashed", "stowed", "hidden"})
RESULT = frozenset({"left", "dropped", "put", "placed", "thrown", "set", "found", "knocked",
                    "kept", "stored", "dumped", "abandoned", "forgotten", "parked", "stuck", "present",
                    "spread", "draped", "slung"}) | PLACED | OBSERVED | STOWED
PASSIVE_STATIVE = frozenset({"found", "kept", "stored",
                             # "leave" is "let stay": "the bowl is left at the head of the table"
                             # is where it stays ("is to be left", "should be left": a norm)
                             "left",
                             "present",  # "a dirty mark is present on the floor"
                             "spread", "draped", "slung"}) | PLACED | STOWED  # "the throw is draped over the sofa"
#: verbs of covering and hanging after which "over" names the thing under, which holds it ("the
#: blanket, spread over the bed", "a towel draped over the chair", "the coat hanging over the
#: banister"): there "over" is "on" (elsewhere "over" is a particle: "knocked over", "fell over")
COVERING = frozenset({"spread", "draped", "slung", "thrown", "hanging", "hangs", "hang"})
PERFECT = frozenset({"has", "have", "had"})
#: the past forms of "be": before a result participle they report a past event ("was left")
PAST_BE = frozenset({"was", "were"})
#: verbs whose subject holds what follows ("the kitchen has the dishwasher", "it contains a bed",
#: "the basket also holds a box of cereal")
HAVE_VERBS = frozenset({"has", "have", "had", "contains", "contain", "holds", "hold", "got", "includes",
                        "include", "houses",
                        # the formal register's verb of having ("said room comprising a desk, ...")
                        "comprises", "comprise", "comprising"})
#: verbs of motion and of belonging a terse clause may carry ("a newspaper on the floor goes in the bin")
MOTION = frozenset({"go", "goes", "went", "belong", "belongs", "get", "gets", "come", "comes", "need",
                    "needs", "should", "must", "want", "wants",
                    # a verb of going back ("a pillow on the floor returns to the bed")
                    "return", "returns"})
#: words that may stand inside a verb group without ending it ("is still lying", "has probably
#: been left", "are both kept")
ADVERBS = frozenset({"still", "already", "always", "usually", "normally", "often", "again", "also",
                     "just", "both", "all", "then", "now", "currently", "out", "over", "down", "up",
                     "back", "there", "here", "too", "each", "mostly", "generally", "typically",
                     # "tucked away in the drawer", "has been put away in the cupboard"
                     "away"})
#: participles of how a thing lies, not of putting it there ("left folded on the bench", "have
#: been left stacked on the chair", "found scrunched in the basket"): read as the verb group's
#: adverbs (`_verb_kind`: after a plain "is" alone they say what is done to things, a rule)
ARRANGED = frozenset({"folded", "stacked", "piled", "heaped", "crumpled", "scrunched", "rolled", "bundled",
                      "coiled", "balled"})
VERBS = BE | PERFECT | STATIVE | RESULT | KEEP_VERBS | HAVE_VERBS | MOTION
#: modal and semi-modal words before a verb group that make it a norm or a goal, not a fact
#: ("the shirt should be in the basket", "it needs to go on the desk", "is to be put away")
NORMATIVE = frozenset({"should", "must", "ought", "shall", "would", "will", "can", "to", "needs", "need",
                       "has", "have", "wants", "want"})
#: modals of a rule that, said with a time covering every moment (`STANDING_TIMES`), state where
#: a thing stays, so where it is when the task is done ("your phone should be on the bedside table
#: at all times", "the fire blanket must always be on its hook"); said with no such time ("should be
#: in the basket when you're done") they name a goal
STANDING_MODALS = frozenset({"should", "must"})
#: times that cover every moment (word sequences, after the modal anywhere in its clause)
STANDING_TIMES: tuple[tuple[str, ...], ...] = (
    ("at", "all", "times"), ("always",), ("permanently",), ("constantly",), ("day", "and", "night"),
    ("round", "the", "clock"), ("around", "the", "clock"), ("whatever", "happens"))
#: the predictive "will be" of a notice or a host's note: where the reader will find a thing when
#: they get there ("Where one was issued, the hair dryer will be on the desk", "your key will be in
#: the lockbox"), unless a time of completion follows (`COMPLETION_TIMES`: "will be on the desk once
#: you have finished" is a goal) or a condition of presence governs it (`_if_there`, read apart)
COMPLETION_TIMES: tuple[tuple[str, ...], ...] = (
    ("once",), ("after",), ("afterwards",), ("until",), ("till",), ("later",), ("done",), ("finished",), ("soon",),
    ("by", "then"), ("by", "the", "time"), ("by", "this"), ("by", "tonight"), ("by", "tomorrow"),
    ("tomorrow",), ("tonight",))
#: a time clause of the reader's arrival, which frames a description of what they will find
#: ("When you come in, the hair dryer will be on the desk", "When you get there, your key is in the
#: lockbox"): "when", a person (`ARRIVERS`), one of these verbs (`ARRIVING`) and its particle at
#: most, then a comma
ARRIVERS = frozenset({"you", "we", "they", "i", "guests", "guest", "visitors", "everyone"})
ARRIVING = frozenset({"arrive", "arrives", "come", "comes", "get", "gets", "walk", "walks", "check", "checks",
                      "wake", "wakes", "return", "returns"})
ARRIVING_PARTICLES = frozenset({"in", "back", "there", "here", "home", "up", "round", "over", "tonight",
                                "tomorrow", "later", "first"})
#: words of a speaker's hope or doubt about a clause that follows ("I doubt the mug is on the
#: counter", "hopefully the keys are in the drawer", "I wonder if ..."): a hedge, as `BELIEFS` are
HEDGES = frozenset({"doubt", "doubts", "doubtful", "hope", "hopes", "hopefully", "wonder", "wonders"})
#: the correlative negation of places ("the mug is neither on the counter nor in the car")
CORRELATIVE_NEGATIONS = frozenset({"neither", "nor"})
#: where a thing rests (not "into"/"onto", which say where it goes)
AT = frozenset({"on", "in", "inside", "atop", "upon"})
#: words after an article that are no modifier of a place ("on the top of", "in the middle of")
PREP_OF_PLACE = frozenset({"top", "middle", "side", "end", "edge", "back", "front", "corner", "bottom", "left",
                           "right", "same", "other", "one", "floor"})
#: the outer parts of a thing ("on the fridge door", "on the side of the bath", "on the desk corner"):
#: a thing on one is on that thing where it has a top to hold it, and never inside it (`_outer_part`)
OUTER_PARTS = frozenset({"door", "side", "edge", "rim", "lid", "front", "back", "handle", "corner", "end",
                         # a seat's arms ("on the arm of the sofa", "on the armrest of the chair")
                         "arm", "armrest"})
#: the preposition `_holder_after` gives a place on an outer part (`_contain`: on a surface, else none)
ON_PART = "on_part"
#: the parts of a holder an "at the <part> of" names, and the preposition a thing there is at the
#: holder by: at the end, head, edge or corner of a thing it rests on that thing's top ("the bowl is
#: at the head of the long table", "a lamp at the far end of the desk": `ON_PART`, never in it);
#: at the bottom or back of it, it is in it where it holds things ("at the bottom of the laundry
#: basket", "right at the back of the wardrobe"), else on it ("at the back of the shelf")
AT_PARTS = {"end": ON_PART, "head": ON_PART, "edge": ON_PART, "corner": ON_PART, "bottom": "in", "back": "in"}
#: words that make a place exact and say nothing of it ("right at the back of", "bang on the table")
PLACE_INTENSIFIERS = frozenset({"right", "bang", "smack", "slap"})
#: words that may stand before such a part ("at the far end of", "at the very bottom of")
AT_PART_MODIFIERS = frozenset({"far", "very", "near", "other", "top", "bottom", "back", "front", "left", "right"})
ARTICLES = frozenset({"a", "an", "the", "some", "its", "their", "our", "my", "your", "this", "that",
                      "his", "her", "these", "those", "two", "three", "four", "one", "both", "another"})
#: words that may stand between the nouns of a list ("the sink, the fridge and a cabinet")
LIST_GLUE = frozenset({",", "and", "or", "plus", "as", "well"}) | ARTICLES
#: words that point back to a place or a thing already named
PLACE_PRONOUNS = frozenset({"there", "here"})
THING_PRONOUNS = frozenset({"it", "that", "this", "they"})
#: prepositions that name where a thing comes from, not a place spoken of ("from the dining room")
SOURCE = frozenset({"from", "of", "off", "than"})
#: subjects of an active clause that name no object of the task ("someone left a mark on the floor")
SUBJECT_PRONOUNS = PERSONAL_SUBJECTS | frozenset({"someone", "somebody", "kids", "children", "everyone", "nobody"})
#: words before a room that let it frame the rest of its sentence ("In the kitchen, ...", "Over in
#: the living room there ...")
_LEADS = frozenset({"over", "out", "down", "up", "and", "then", "also", "back", "now", "next"})


#: what a phrase says of a place: `settled` (a statement: "a nightstand with a lamp", "the
#: kitchen has a stove", "the cardboard box is on the floor"), `kept` (where it belongs: "it's
#: kept in the vanity", which the text may still doubt: "wherever else it may be lying"),
#: `presumed` (a noun phrase takes it for granted: "check the towel on the drying rack")
KINDS = frozenset({"settled", "kept", "presumed"})
_ORDER = ("settled", "kept", "presumed")

#: `described_placements` per (catalog, brief, kinds), most recent last: the same brief is read
#: once per situation and per request of a task (measured: 367 readings of 25 briefs per run,
#: ~0.4 s of LogicEnvGen's generation), and the reading depends on nothing else
_READ: OrderedDict[tuple[int, str, frozenset[str]], tuple[Catalog, tuple[str, ...]]] = OrderedDict()
_READ_MAX = 64
_READ_LOCK = threading.Lock()


def described_placements(brief: Mapping[str, Any], catalog: Catalog | None = None, *,
                         kinds: frozenset[str] = KINDS) -> list[str]:
    """Facts (condition language) placing the brief's roles where its description says they are:
    `on(lamp, nightstand)`, `inside(old_towel, vanity)`, `on(mark, floor)`, `in_room(drying_rack,
    balcony)`, from the phrases of `kinds`. One on/inside per object, and one room for an object
    not on or in another role; a statement wins over a home, a home over a presumption, and
    within one kind the first phrase wins."""
    catalog = catalog or load_catalog()
    if not brief.get("roles"):
        return []
    try:
        text = json.dumps(brief, sort_keys=True)
    except (TypeError, ValueError):  # not plain JSON data: read, not remembered
        return _read(brief, catalog, kinds)
    key = (id(catalog), text, frozenset(kinds))
    with _READ_LOCK:
        hit = _READ.get(key)
        if hit is not None and hit[0] is catalog:  # the catalog object is kept: its id is not reused
            _READ.move_to_end(key)
            return list(hit[1])
    facts = _read(brief, catalog, kinds)
    with _READ_LOCK:
        _READ[key] = (catalog, tuple(facts))
        while len(_READ) > _READ_MAX:
            _READ.popitem(last=False)
    return facts


# ---------------------------------------------------------------------------------------------
# Tokens, mentions, clauses
# ---------------------------------------------------------------------------------------------

_TOKEN = re.compile(r"[a-z0-9]+(?:'[a-z]+)?|[,;:()?]|(?<=\s)-(?=\s)|\n")


@dataclass(frozen=True)
class _Token:
    word: str  # lower-case surface form
    lemma: str  # singular form, used to match names
    start: int
    end: int


@dataclass
class _Sentence:
    toks: list[_Token]
    mentions: list[Mention]  # role, room and floor mentions (token indices)
    new_line: bool = True  # whether a line break (or the text's start) comes before it

    @property
    def words(self) -> list[str]:
        return [t.word for t in self.toks]


@dataclass
class _Reading:
    """Facts found so far, per kind: `held[kind][role]` (on/inside/floor), `rooms[kind][role]`."""

    held: dict[str, dict[str, str]]
    rooms: dict[str, dict[str, str]]
    #: the room a dash heading set over its line ("3. STUDY - laptop. It belongs on the desk."):
    #: the things the line's later sentences name are in it (`_in_section`)
    section_room: str | None = None
    last_subject: Mention | None = None  # the subject of the last statement (for "it", "that")
    #: the sentence `last_subject` is a mention of: its token positions index that sentence only
    last_subject_sent: _Sentence | None = None
    last_holder: Mention | None = None  # the last place named (for "there")
    #: the first carried thing a statement last spoke of (for "it will be on the floor if it is
    #: anywhere": a thing that may be absent, not the bed it slipped behind)
    last_carried: Mention | None = None

    def place(self, kind: str, role: str, fact: str) -> None:
        self.held[kind].setdefault(role, fact)

    def room(self, kind: str, role: str, room: str) -> None:
        self.rooms[kind].setdefault(role, room)


#: an arrow after a part that asks no question: "then", the answer of what comes before it, cut
#: as a colon is ("Pillow on the floor -> back on the sofa" is a heading answered by an
#: instruction, a condition, as "Pillow on the floor: back on the sofa" is; after "?" it is dropped)
_THEN_ARROW = re.compile(rf"(?<![?:!])\s*{ARROW_MARK}\s*")


#: a ticked box and an unticked one, as checklists write them ("[x]", "[ ]", a check mark, a ballot
#: box)
_TICKED = r"\[[ \t]*[xX\u2713\u2714][ \t]*\]|[\u2713\u2714\u2611]"
_UNTICKED = r"\[[ \t]*\]|\u2610"
#: a checklist's box at a line's start, ticked or not ("[x] mug on the counter", "[ ] lights off",
#: "✓ keys in the bowl"): the nineteenth session reads it as the item's boundary, as a
#: semicolon, so the line is a list item of its own and not the tail of the line before
_TICK_BOX = re.compile(rf"^[ \t]*(?:{_TICKED}|{_UNTICKED})[ \t]*", re.M)
#: a box after an item's label mark, the checklist written item first ("Mug — [x] on the shelf",
#: "Laptop: [x] on the desk", "Lamp: [ ] on the desk"): a ticked box says the line holds, so it is
#: dropped and the label reads its place as "Mug — on the shelf" does; an unticked one says it
#: is not (yet) so, so it cuts the line as a full stop would, and the place after it is no one's
_LABELLED_TICK = re.compile(rf"(?<=[:\-\u2013\u2014])[ \t]*(?:{_TICKED})[ \t]*")
_LABELLED_UNTICKED = re.compile(rf"(?<=[:\-\u2013\u2014])[ \t]*(?:{_UNTICKED})[ \t]*")


#: an en or em dash set off by spaces is the dash a clause or a label ends at, as " - " is
#: ("Mug — on the counter", "Lamp – switch it off"): the clause cut (`clauses._HARD`) knows "-"
#: only, so the tokens read every such dash as "-"
_DASHES = re.compile(r"(?<=\s)[\u2013\u2014](?=\s)")


def _sentences(text: str, lex: Lexicon) -> list[_Sentence]:
    out = []
    boxed = expand(_LABELLED_UNTICKED.sub(". ", _LABELLED_TICK.sub(" ", _TICK_BOX.sub("; ", text))))
    at = 0
    for part in split_sentences(boxed, full_stops_only=True):
        found = boxed.find(part, at)
        new_line = at == 0 or found < 0 or "\n" in boxed[at:found]
        at = found + len(part) if found >= 0 else at
        low = _THEN_ARROW.sub(": ", part.lower())
        toks = [_Token(m.group(0), singular(m.group(0)) if m.group(0)[0].isalnum() else m.group(0),
                       m.start(), m.end()) for m in _TOKEN.finditer(_DASHES.sub("-", low))]
        toks = [t for t in toks if t.word != "\n"]
        mentions = lex.find_mentions([(t.lemma, t.start, t.end) for t in toks])
        for drop in (_without_asides, _held_in_aside):
            kept = drop(toks, mentions)
            if len(kept) < len(toks):  # an aside dropped: the mentions after it moved
                toks, mentions = kept, lex.find_mentions([(t.lemma, t.start, t.end) for t in kept])
        mentions = [m for m in mentions if not _verb_mention(toks, mentions, m)]
        mentions = without_modifiers(mentions, [(t.lemma, t.start, t.end) for t in toks], [t.word for t in toks])
        out.append(_Sentence(toks, _with_room_word(toks, mentions, lex), new_line))
    return _with_aliases(out)


def _with_aliases(sentences: list[_Sentence]) -> list[_Sentence]:
    """A word the text identifies as one of its things ("The bar is a kitchen counter salvaged from
    the refit") names that thing where it is later a place ("a wine bottle stands on the bar"):
    "the <word> is a/an [modifiers] <thing>" in a statement, the word naming nothing itself."""
    aliases: dict[str, Mention] = {}
    for sent in sentences:
        words = sent.words
        for i in range(len(words) - 3):
            if words[i] != "the" or not words[i + 1].isalpha() or words[i + 2] != "is" \
                    or words[i + 3] not in ("a", "an") or any(m.start <= i + 1 < m.end for m in sent.mentions) \
                    or i > 0 and words[i - 1] not in SUBJECT_LEADS:
                continue
            named = next((m for m in sent.mentions if m.kind == "role" and len(m.roles) == 1
                          and i + 4 <= m.start <= i + 6
                          and all(w.isalpha() and w not in VERBS for w in words[i + 4:m.start])), None)
            if named is not None and (named.end >= len(words) or not words[named.end].isalpha()
                                      or words[named.end] not in ("of", "for", "with")):
                aliases.setdefault(sent.toks[i + 1].lemma, named)
    if not aliases:
        return sentences
    out = []
    for sent in sentences:
        words = sent.words
        extra = [Mention(aliases[sent.toks[k].lemma].roles, k, k + 1, "role") for k in range(2, len(words))
                 if sent.toks[k].lemma in aliases and words[k - 1] == "the" and words[k - 2] in FALLBACK_AT
                 and not _named_word(sent.mentions, k)]
        out.append(_Sentence(sent.toks, sorted(sent.mentions + extra, key=lambda m: m.start)) if extra else sent)
    return out


def _verb_mention(toks: list[_Token], mentions: list[Mention], m: Mention) -> bool:
    """Whether a one-word mention is a verb of resting in the third person after its subject ("it
    stands on the TV stand": "stands" names no TV stand): a pronoun or a thing's name before it and
    a place or an adverb after it."""
    if m.end - m.start != 1 or m.start == 0 or m.end >= len(toks):
        return False
    word, prev, nxt = toks[m.start].word, toks[m.start - 1].word, toks[m.end].word
    subject = prev in THING_PRONOUNS | PERSONAL_SUBJECTS or any(x.end == m.start and x.kind == "role" for x in mentions)
    return word in STATIVE and word != toks[m.start].lemma and subject and nxt in AT | OVER | ADVERBS


def _without_asides(toks: list[_Token], mentions: list[Mention]) -> list[_Token]:
    """The tokens without a bracket right after a thing's name that names nothing and states no
    condition or doubt: an aside about the thing ("Mug (mine, the chipped one) lives on the bedside
    table", "The vase (a gift from Gran) is on the piano") stands between the subject and its verb
    and hides the statement; a bracket that names a place (`_identifying_aside`) or holds "if",
    "maybe" is kept."""
    out = list(toks)
    for m in sorted(mentions, key=lambda x: -x.start):
        if m.kind != "role" or m.end >= len(out) or out[m.end].word != "(":
            continue
        close = next((j for j in range(m.end + 1, len(out)) if out[j].word in (")", "(")), None)
        if close is None or out[close].word != ")":
            continue
        inside = {t.word for t in out[m.end + 1:close]}
        if any(m.end < x.start < close for x in mentions) or inside & (SUBORDINATORS | DOUBT | {"if", "unless"}):
            continue
        del out[m.end:close + 1]
    return out


#: the prepositions of an aside naming what holds the thing spoken of ("the photo, in the silver frame, ...")
_HELD_IN = frozenset({"in", "inside"})


def _held_in_aside(toks: list[_Token], mentions: list[Mention]) -> list[_Token]:
    """The tokens with the holder an aside names as the subject, where the sentence opens with a
    thing named by what it holds and naming nothing of the task ("The photo of me and Gran, in the
    silver frame, is on the sideboard", "The roses, in the blue vase, are on the windowsill"): a
    framed photo is its frame, flowers in a vase are the vase, so the statement places the holder
    ("the silver frame is on the sideboard"). Only a subject with no thing, room or verb of its own
    before the aside's comma, an aside of "in"/"inside" ending in one thing's name and the
    statement's verb right after it; the tokens unchanged otherwise."""
    words = [t.word for t in toks]
    first = next((k for k, w in enumerate(words) if w == ","), None)
    if first is None or first == 0 or first + 2 >= len(words) or words[first + 1] not in _HELD_IN \
            or any(w in VERBS for w in words[:first]) or any(m.start < first for m in mentions):
        return toks
    close = next((k for k in range(first + 2, min(len(words), first + 8)) if words[k] == ","), None)
    if close is None or close + 1 >= len(words) or words[close + 1] not in VERBS:
        return toks
    held = [m for m in mentions if first + 1 < m.start < close]
    if len(held) != 1 or held[0].kind != "role" or held[0].end != close or len(held[0].roles) != 1:
        return toks
    return toks[first + 2:close] + toks[close + 1:]


def _with_room_word(toks: list[_Token], mentions: list[Mention], lex: Lexicon) -> list[Mention]:
    """"the room" (or "the place") names the room the task is in when it has only one."""
    if len(lex.rooms) != 1:
        return mentions
    taken = {i for m in mentions for i in range(m.start, m.end)}
    extra = [Mention((lex.rooms[0],), i, i + 1, "room") for i, t in enumerate(toks)
             if t.word == "room" and i not in taken and i > 0 and toks[i - 1].word in ("the", "this")]
    return sorted(mentions + extra, key=lambda m: m.start)


def _clauses(words: list[str], lo: int, hi: int) -> list[Span]:
    """The clauses of words[lo:hi] (`clause_spans`), with this reader's verbs: a part with none of
    `VERBS` is verbless, and one of `MOTION` or `NORMATIVE` says where things go."""
    return clause_spans(words, lo, hi, verbs=VERBS, goal_words=MOTION | NORMATIVE)


# ---------------------------------------------------------------------------------------------
# The reading
# ---------------------------------------------------------------------------------------------


def _read(brief: Mapping[str, Any], catalog: Catalog, kinds: frozenset[str]) -> list[str]:
    lex = Lexicon.build(brief, reading_catalog(catalog))
    reading = _Reading({k: {} for k in _ORDER}, {k: {} for k in _ORDER})
    sentences = _sentences(as_read(str(brief.get("description", ""))), lex)
    goal_list = False
    for sent in sentences:
        _in_section(sent, reading)
        # the items of a list a goal's lead opens say where things go, not where they are
        goal_list = goal_list and _list_item(sent)
        if not goal_list:
            _read_sentence(sent, lex, catalog, reading)
        goal_list = goal_list or _goal_lead(sent)
    before = _Before()
    for sent in sentences:  # after every rule: a thing a rule placed keeps its place
        _fallback(sent, before, lex, catalog, reading)
        before.see(sent)
    held: dict[str, str] = {}
    rooms: dict[str, str] = {}
    for kind in _ORDER:
        if kind not in kinds:
            continue
        for role, fact in reading.held[kind].items():
            held.setdefault(role, fact)
        for role, room in reading.rooms[kind].items():
            rooms.setdefault(role, room)
    out = list(held.values())
    out += [f"in_room({role}, {room})" for role, room in rooms.items()
            if role not in held or held[role].endswith(", floor)")]
    return out


#: the verbs of a lead that sends things somewhere ("Anything left on it goes where it is kept:",
#: "Put things back as follows:", "Return these to their homes:"): the list after it gives
#: destinations, not places (`_goal_lead`)
_SENDING = MOTION | frozenset({"put", "return", "take", "move", "hang", "place", "store", "tidy", "clear", "sort"})


def _goal_lead(sent: _Sentence) -> bool:
    """Whether the sentence leads into a list of where things go: it ends at a colon and says
    where things go or tells the reader to put them somewhere ("Anything left on it goes where it
    is kept:", "Put things back as follows:", "Where everything belongs:"). The list's items
    ("- the alarm clock: on the nightstand") are then destinations: read as where the things
    are, they would settle what the text leaves open ("There may be a book, an alarm clock or a
    phone left on the bed"). A lead that sends nothing ("Here is what you will find:") leaves its
    items statements."""
    words = sent.words
    return bool(words) and words[-1] == ":" and bool(set(words) & _SENDING)


def _list_item(sent: _Sentence) -> bool:
    """Whether the sentence is a verbless item of a list: on a line of its own (its dash or
    number dropped by `as_read`), a thing and its place at a colon ("- the phone: on the desk",
    "2. mug: in the cupboard")."""
    return sent.new_line and ":" in sent.words


def _in_section(sent: _Sentence, reading: _Reading) -> None:
    """The things a sentence names are in the room a dash heading set over its line (`_heading`,
    `_room_dash`, as `section_room`): "3. STUDY - laptop. It belongs on the desk." puts the desk in
    the study too, as check sheets give each room a line. A line break or another room named ends
    it."""
    if sent.new_line or any(m.kind == "room" and m.roles != (reading.section_room,) for m in sent.mentions):
        reading.section_room = None
    if reading.section_room is None:
        return
    for m in sent.mentions:
        # (a noun opening its sentence is a noun phrase too: "Wardrobe: doors open = defect")
        if m.kind == "role" and not _indefinite_doubt(sent, m) and (m.start == 0 or _named(sent.words, m.start)):
            for role in _roles(m, sent):
                reading.room("settled", role, reading.section_room)


def _read_sentence(sent: _Sentence, lex: Lexicon, catalog: Catalog, reading: _Reading) -> None:
    words = sent.words
    body_start = _heading(sent, lex, catalog, reading)
    _frame(sent, reading, body_start)
    _room_words(sent, lex, reading)
    _identifying_aside(sent, lex, catalog, reading)
    spans = _clauses(words, body_start, len(words))
    # a condition or a doubt anywhere in the sentence governs what its instructions take for granted
    plain = not any(c.mood == "condition" or c.doubted for c in spans)
    for clause in spans:
        if clause.mood == "statement" and _ended_past(words, clause.start, clause.end):
            continue  # "the mug was on the counter until this morning": then, not now
        ms = [m for m in sent.mentions if clause.start <= m.start < clause.end]
        framed = _arrival_frame(words, clause.start, clause.end) if clause.mood == "condition" else None
        if framed is not None:  # "When you come in, the mug will be on the counter": what they will find
            _locative(sent, Span(framed, clause.end, "statement", clause.doubted), [m for m in ms if m.start >= framed],
                      lex, catalog, reading)
        if clause.mood == "instruction" and plain:
            _taken_from(sent, clause, ms, lex, catalog, reading)
        if clause.mood != "condition":
            _locative(sent, clause, ms, lex, catalog, reading)
        if clause.mood != "statement":
            _relative_place(sent, clause, ms, lex, catalog, reading)
        if clause.mood == "statement":  # a doubt in a list leaves out only what it covers
            _possessive(sent, clause, ms, lex, catalog, reading)
        if clause.mood == "statement" and not clause.doubted:
            _existential(sent, clause, ms, lex, catalog, reading)
            _perceived(sent, clause, ms, lex, catalog, reading)
        if clause.mood == "statement" and not clause.doubted or _epithet_heading(sent, clause):
            _inverted(sent, clause, ms, lex, catalog, reading)
        if clause.mood != "condition" and not clause.doubted:
            # in an instruction only a home: "take a spare roll from the vanity where spares are kept"
            _where(sent, clause, ms, lex, catalog, reading, homes_only=clause.mood == "instruction")
        if clause.mood != "condition" and not clause.doubted:
            _kept(sent, clause, ms, lex, catalog, reading)
        if clause.mood == "statement" and not clause.doubted:
            _with(sent, clause, ms, lex, catalog, reading)
        elif clause.mood == "instruction" and plain:
            _with(sent, clause, ms, lex, catalog, reading, kind="presumed")
        _in_room(sent, clause, ms, reading)
        _resting(sent, clause, ms, lex, catalog, reading)
        subjects = [m for m in ms if m.kind in ("role", "room")]
        if clause.mood == "statement" and subjects:
            reading.last_subject, reading.last_subject_sent = subjects[0], sent
            carried = [m for m in subjects if m.kind == "role" and len(m.roles) == 1
                       and (cat := catalog.get(str(lex.roles[m.roles[0]]["category"]))) is not None and cat.pickable]
            reading.last_carried = carried[0] if carried else reading.last_carried
        holders = [m for m in ms if _prep_before(words, m.start) in AT | {"from", "of"}]
        if holders:
            reading.last_holder = holders[-1]


def _relative_place(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
                    reading: _Reading) -> None:
    """"Used the bath towel that was hanging on the towel rail?", "if the mug which is sitting on
    the desk is dirty", "put it back in the cardboard box that lives on top of the piano": in a
    question, condition or instruction, a relative clause of being, resting or keeping said of a
    definite thing tells which one is meant by where it is, which the question or instruction
    takes for granted: a statement of its place, or its home for a verb of keeping ("that lives
    on", "which is kept in"); what the question asks is read by the factor reader."""
    words = sent.words
    for m in ms:
        k = _of_complement(words, ms, m.end, clause.end)  # "the photo frame of Nana that's on the shelf"
        if m.kind != "role" or len(m.roles) != 1 or k >= clause.end:
            continue
        reduced = words[k] in STATIVE and words[k].endswith("ing")
        if words[k] in RELATIVE and determiner(words, m.start) == "the":
            end, group = _verb_group(words, k + 1, clause.end)
        elif reduced and _the_before(words, m.start):
            end, group = k + 1, [words[k]]  # the relative reduced: "the towel hanging on the rack"
        else:
            continue
        kind = _verb_kind(group) if group else None
        if kind is None or group[0] not in BE | STATIVE | KEEP_VERBS or doubts(group):
            continue
        found = _holder_after(sent, ms, end, clause.end)
        if found is None:
            continue
        if reduced and (found[1].end >= clause.end or words[found[1].end] not in BE | PERFECT | _LINKING):
            continue  # "if you see the mug sitting on the desk": the place is what is seen, the condition
        _put(reading, kind, catalog, lex, m.roles[0], found[1], found[0])


#: verbs that link a subject to a state as "is" does ("the towel on the rack looks dirty")
_LINKING = frozenset({"look", "looks", "seem", "seems", "smell", "smells", "feel", "feels"})


def _the_before(words: list[str], start: int) -> bool:
    """A noun phrase opened by "the", right before the noun or before one noun modifier, which
    may be a verb's form as well ("the pool towel", "the tea cup"): not a participle."""
    if start > 0 and words[start - 1] == "the":
        return True
    return start > 1 and words[start - 2] == "the" and words[start - 1].isalpha() \
        and not words[start - 1].endswith(("ing", "ed")) and words[start - 1] not in STATE_WORDS


def _identifying_aside(sent: _Sentence, lex: Lexicon, catalog: Catalog, reading: _Reading) -> None:
    """"The desktop computer (the old one on the desk, ...)", "the lamp (the one on the
    nightstand)": a bracket right after a thing that tells which one it is by where it stands
    states where it is; so does a bracket that is only a place ("the storage box (bottom shelf of
    the metal rack)", "the first-aid kit (on the top shelf)": `_bracketed_place`)."""
    words = sent.words
    for m in sent.mentions:
        if m.kind != "role" or len(m.roles) != 1 or m.end + 1 >= len(words) or words[m.end] != "(":
            continue
        k = m.end + 1
        place = _bracketed_place(sent, lex, k)
        if place is not None and place[1].roles != m.roles:
            _put(reading, "settled", catalog, lex, m.roles[0], place[1], place[0])
            continue
        home = _bracketed_home(sent, k)
        if home is not None and home[1].roles != m.roles:
            _put(reading, "kept", catalog, lex, m.roles[0], home[1], home[0])
            continue
        if words[k] != "the":
            continue
        one = next((j for j in range(k + 1, min(k + 4, len(words))) if words[j] == "one"), None)
        if one is None or any(w in VERBS or w in ("(", ")", ",") for w in words[k + 1:one]):
            continue  # "(the one we use)": no place
        close = next((j for j in range(one, len(words)) if words[j] in (")", ",")), len(words))
        found = _holder_after(sent, [x for x in sent.mentions if one < x.start < close], one + 1, close)
        if found is not None and found[1].roles != m.roles:
            _put(reading, "settled", catalog, lex, m.roles[0], found[1], found[0])


#: the verbs of keeping that open a bracket of their own after a thing: a participle or a
#: present with the thing as subject ("(kept in the vanity)", "(lives in the drawer)")
_KEPT_ASIDE = frozenset({"kept", "stored", "lives", "sleeps"})


def _bracketed_home(sent: _Sentence, k: int) -> tuple[str, Mention] | None:
    """(preposition, place) when the bracket opening at word `k` says where the thing before it is
    kept, with a norm adverb or none: "the old towel (normally kept in the vanity, or sometimes
    stuffed into the medicine cabinet)", "the spare bulbs (stored in the hall cupboard)": its home,
    the first place said (an alternative after "or" leaves it the usual one)."""
    words = sent.words
    close = next((j for j in range(k, len(words)) if words[j] == ")"), None)
    if close is None:
        return None
    j = k + (words[k] in NORM_ADVERBS)
    if words[j] not in _KEPT_ASIDE:
        return None
    end = next((x for x in range(j + 1, close) if words[x] in (",", "or", "and")), close)
    found = _holder_after(sent, [x for x in sent.mentions if j < x.start < end], j + 1, end)
    return found if found is not None and found[1].end == end else None


def _bracketed_place(sent: _Sentence, lex: Lexicon, k: int) -> tuple[str, Mention] | None:
    """(preposition, place) when the bracket opening at word `k` holds only a place: "on/in the
    <place>", or a part of a piece of furniture named by its rank ("bottom shelf of the metal
    rack", "top drawer of the dresser": `FURNITURE_PARTS`), which puts the thing in that furniture,
    or on it when it has no inside (an open rack)."""
    words = sent.words
    close = next((j for j in range(k, len(words)) if words[j] == ")"), None)
    if close is None:
        return None
    ms = [x for x in sent.mentions if k <= x.start < close]
    if words[k] in AT:
        found = _holder_after(sent, ms, k, close)
        return found if found is not None and _place_closes(words, found[1].end, close) else None
    part = k + (words[k] in ARTICLES)
    part += words[part] in RANKS
    if part + 1 >= close or words[part] not in FURNITURE_PARTS or words[part + 1] != "of":
        return None
    # the furniture's name ends the bracket, with what describes it before ("the metal rack")
    m = next((x for x in ms if x.start >= part + 2 and x.end == close), None)
    return ("in", m) if m is not None and m.kind == "role" else None


#: prepositions that place a place by another thing ("the utility shelf above the sink"): said
#: after a bracket's place, they say which one it is, not a second place of the thing
_PLACE_MODIFIERS = frozenset({"by", "near", "next", "beside", "under", "at", "above", "below", "behind", "opposite", "over"})


def _place_closes(words: list[str], end: int, close: int) -> bool:
    """Whether the place ending at word `end` is all a bracket closing at `close` says of where
    the thing is: it ends the bracket, or what follows only tells the place apart ("(on the
    utility shelf above the sink)", "(in the cupboard by the door)") or the thing ("(on the
    workbench, the green one)": an apposition after a comma); never an alternative ("(on the
    shelf or in the drawer)") or a second clause."""
    if end == close:
        return True
    return words[end] in _PLACE_MODIFIERS or words[end] == "," and end + 1 < close and words[end + 1] in ARTICLES


def _roles(m: Mention, sent: _Sentence) -> tuple[str, ...]:
    """The roles a mention names: its one role, or all of them when the word is plural ("two pet
    bowls", "the toy boxes") and so names every one."""
    if m.kind != "role":
        return ()
    if len(m.roles) == 1:
        return m.roles
    last = sent.toks[m.end - 1]
    plural = last.word != last.lemma or (m.start > 0 and sent.toks[m.start - 1].word in ("two", "three", "both"))
    return m.roles if plural else ()


def _np_list(sent: _Sentence, ms: list[Mention], lo: int, hi: int) -> list[Mention]:
    """The role mentions of a noun-phrase list within tokens [lo, hi): nouns joined by commas,
    "and", articles and adjectives, each not the object of a preposition ("the pantry next to the
    kitchen": the pantry), and none after a doubt word ("a dirty mark, and possibly a book")."""
    out: list[Mention] = []
    doubt_from: int | None = None  # where a doubt began ("possibly a book, a clock or a phone")
    for m in ms:
        if not lo <= m.start < hi or m.end > hi:
            continue
        words = sent.words
        if doubt_from is None:
            doubt_from = next((k for k in range(lo, m.start) if doubts(words[k:k + 2])), None)
        if doubt_from is not None:
            # the doubt ends with the "or" chain it opens: at a comma after an "or" has been seen
            nxt = next((n.start for n in ms if n.start > m.start), hi)
            sep = words[m.end:min(nxt, hi)]
            if "or" in words[doubt_from:m.end] and "or" not in sep and "," in sep:
                doubt_from = None
                lo = m.end
            continue
        prep = _prep_before(sent.words, m.start)
        if prep is not None and prep not in ("of",) and lo <= _prep_index(sent.words, m.start):
            continue
        if _negated(words, lo, m.start):
            continue  # "the mug, not the cup, is on the table": the cup is contrasted away
        if prep == "of" and out and out[-1].end == _prep_index(sent.words, m.start):
            # "a box of cereal": one thing, the complement when it names the head too
            if _names_head(sent, out[-1], m):
                out[-1] = m
            continue
        out.append(m)
    return out


def _negated(words: list[str], lo: int, start: int) -> bool:
    """Whether the noun phrase at `start` is negated by the word before it or before its article
    ("not the cup", "never a plate", "no mug")."""
    k = start - 1
    if k > lo and words[k] in ARTICLES:
        k -= 1
    return k >= lo and words[k] in NEGATIONS


def _names_head(sent: _Sentence, head: Mention, complement: Mention) -> bool:
    """Whether the complement of "<head> of <complement>" names the head noun too ("a box of
    cereal" is the cereal box; "the bag of pet food" is a bag)."""
    word = sent.toks[head.end - 1].lemma
    return len(complement.roles) == 1 and word in complement.roles[0].split("_")


def _prep_index(words: list[str], start: int) -> int:
    """Where the word `_prep_before` looks at stands (articles and adjectives skipped)."""
    j = start - 1
    while j >= 0 and (words[j] in ARTICLES or words[j] in COLOR_WORDS or words[j] in STATE_WORDS
                      and words[j] not in ("on", "out", "off")):
        j -= 1
    return j


def _prep_before(words: list[str], start: int) -> str | None:
    """The preposition right before a mention, articles and adjectives skipped ("in the vanity",
    "next to the stool")."""
    j = _prep_index(words, start)
    if j < 0:
        return None
    w = words[j]
    if w == "with" and j > 0 and words[j - 1] in ("along", "together"):
        return None  # "along with a nightstand": a list goes on
    if w in PREP_IN | PREP_ON or w in ("to", "by", "from", "of", "near", "beside", "behind", "under",
                                       "at", "with", "for", "against", "into", "onto", "through", "off"):
        return w
    return None


#: the auxiliary of the passive with "get" ("it gets dumped on the bench", "the towel got thrown
#: on the floor"): where the thing ends up, a report in the past; in the present only with a verb
#: of leaving a thing carelessly (`CARELESS`), a habit: "dirty plates get put in the dishwasher" is
#: a rule of where they go, as a present passive with "is" may be ("the plate is put away")
GET_PASSIVE = frozenset({"get", "gets", "got", "gotten"})
PAST_GET = frozenset({"got", "gotten"})


def _get_passive(words: list[str], j: int, hi: int) -> bool:
    """Whether the word at `j` is a passive's "get" (`GET_PASSIVE`): a participle of putting or
    leaving (`RESULT`) follows it, perhaps after an adverb ("gets always left")."""
    k = j + 1
    while k < hi and (words[k] in ADVERBS or words[k].endswith("ly")):
        k += 1
    return words[j] in GET_PASSIVE and k < hi and words[k] in RESULT


def _verb_group(words: list[str], i: int, hi: int) -> tuple[int, list[str]]:
    """The verb group starting at token i (auxiliaries, adverbs, verbs), as (end, its words)."""
    j = i
    while j < hi and (words[j] in BE | PERFECT | STATIVE | RESULT | KEEP_VERBS | ADVERBS | DOUBT | ARRANGED
                      or words[j] in ("not", "never", "usually", "often") or words[j].endswith("ly")
                      or _get_passive(words, j, hi)):
        j += 1
    return j, words[i:j]


def _verb_kind(group: list[str]) -> str | None:
    """What a verb group says of a place: `settled` ("is", "lies", "has been left", "are found"),
    `kept` ("are kept", "lives", "we store"), None for a goal ("is put", "goes") or no verb."""
    verbs = [w for w in group if w not in ADVERBS | ARRANGED]
    if not verbs or set(verbs) & {"not", "never"}:
        return None
    if set(group) & ARRANGED and all(w in BE for w in verbs):
        return None  # "Books are stacked on the shelf by colour": what is done to them, a rule
    if set(verbs) & KEEP_VERBS:
        return "kept"
    last = verbs[-1]
    if last in BE or last in STATIVE:
        return "settled"
    if last in RESULT and set(verbs[:-1]) & GET_PASSIVE:
        # "it gets dumped on the bench", "the towel got thrown on the floor" (not "plates get put
        # in the dishwasher": a rule)
        return "settled" if set(verbs[:-1]) & PAST_GET or last in CARELESS else None
    if last in RESULT:
        perfect = bool(set(verbs) & PERFECT) and "been" in verbs
        # "someone left a mark on the floor", "we had put the box on the stool" (with its subject)
        active_past = len(verbs) == 1 or _active_perfect(verbs)
        # a past passive reports what was done, where a present one may instruct ("two cups were
        # left on the trolley", "the keys were dropped on the mat"; not "the plate is put away")
        past = len(verbs) == 2 and verbs[0] in PAST_BE
        return "settled" if perfect or last in PASSIVE_STATIVE or active_past or past else None
    return None


#: words that set a sentence on an earlier occasion of what the text asks for now ("last time the
#: headset sat on that table for a fortnight", "the time before, the mug stood on the desk"): where
#: a thing was then is an anecdote, not where it is; a clause that says "now", "today" or
#: "currently" speaks of the present again ("last time the lamp was on the shelf; now it is on
#: the desk")
EARLIER_OCCASION = (("last", "time"), ("the", "time", "before"), ("previous", "time"), ("previous", "occasion"))
_PRESENT_AGAIN = frozenset({"now", "today", "currently", "tonight"})


def _earlier_occasion(words: list[str], clause: Span) -> bool:
    """Whether a statement's clause tells of an earlier occasion (`EARLIER_OCCASION` in its
    sentence, no word of the present in the clause)."""
    if set(words[clause.start:clause.end]) & _PRESENT_AGAIN:
        return False
    return any(tuple(words[k:k + len(p)]) == p for p in EARLIER_OCCASION for k in range(len(words)))


#: the nineteenth session's ended past: a past placement the sentence itself says has ended is
#: no current one ("the mug was on the counter until this morning", "the rug was formerly kept in
#: the hall", "the lamp sat on the desk yesterday, but Sam moved it"). Past forms of a verb of
#: being or resting; adverbs of a former state; words that bound a past state; verbs (after "but")
#: that undo it
ENDED_PAST_VERBS = PAST_BE | frozenset({"had", "sat", "lay", "stood", "hung", "stayed", "remained", "lived"})
FORMER = frozenset({"formerly", "previously", "originally"})
BOUNDS = frozenset({"until", "till", "til"})
UNDOING = frozenset({"moved", "took", "taken", "removed", "cleared", "shifted", "gone", "emptied", "tidied"})
_UNDO_REACH = 4
_UNDONE = frozenset({"it", "them", "they"})


def _ended_past(words: list[str], lo: int, hi: int) -> bool:
    """Whether the statement in words[lo:hi] tells of a past placement its sentence ends: a past
    verb of being or resting (`ENDED_PAST_VERBS`) with a former-state adverb in it, a bound
    ("until ...") in it or opening the next part, or "but" later in the sentence followed within a
    few words by a verb that undoes it and "it"/"them" ("but Sam moved it", "but it's gone")."""
    if not set(words[lo:hi]) & ENDED_PAST_VERBS:
        return False
    # (the clause ends before a bound's subordinate clause: "until" may be its first word)
    if set(words[lo:hi]) & FORMER or set(words[lo:hi + 1]) & BOUNDS:
        return True
    return any(set(near) & UNDOING and set(near) & _UNDONE
               for near in (words[k + 1:k + 1 + _UNDO_REACH] for k in range(lo, len(words)) if words[k] == "but"))


#: prepositions that may go on an apposed place as its own modifier ("the desk by the window")
_APPOSED_MODIFIERS = frozenset({"by", "near", "next", "beside", "under", "at"})


def _apposed(sent: _Sentence, ms: list[Mention], j: int, hi: int) -> Mention | None:
    """The thing an apposition after a place no name of the task names says the place is ("on
    the taburete, the little stool", "in the armoire, the big wardrobe", "on the whatsit, the
    sideboard"): from `j`, a definite noun phrase (the article, adjectives) naming one role that
    ends the clause or is followed by a comma or its own modifier ("the desk by the window"); else
    None ("on the way, the mug fell" goes on)."""
    words = sent.words
    if j >= hi or words[j] != "the":
        return None
    m = next((t for t in ms if t.start > j and t.kind == "role"), None)
    if m is None or len(m.roles) != 1 or not all(w.isalpha() and w not in VERBS | AT for w in words[j + 1:m.start]) \
            or m.start - j > 3:
        return None
    return m if m.end >= hi or words[m.end] in PUNCT | _APPOSED_MODIFIERS else None


#: the words a gloss's bracket may hold after its name and a comma, which say which one it is
#: ("pufyk (the ottoman, small soft one)", "the komoda (the dresser, left of the door)")
_GLOSS_TAIL = 6


def _bracket_gloss(sent: _Sentence, j: int) -> Mention | None:
    """The thing a bracket right after a place no name of the task names glosses it as ("on
    wersalka (sofa)", "in the kufer (the trunk)", "on the chabudai (the coffee table)"): the
    bracket holds only a name of one role, its article and modifiers at most, and after a comma
    at most a few words that tell it apart ("on pufyk (the ottoman, small soft one)"). The bracket
    is a clause of its own (`clause_spans` cuts at brackets), so it is read past the clause's end."""
    words = sent.words
    close = next((c for c in range(j, min(j + 6 + _GLOSS_TAIL, len(words))) if words[c] == ")"), None)
    if close is None:
        return None
    named = min([c for c in range(j, close) if words[c] == ","] + [close])
    if close - named > _GLOSS_TAIL + 1 or named - j > 5 or "(" in words[j:close]:
        return None
    m = next((t for t in sent.mentions if j <= t.start and t.end == named and t.kind == "role"), None)
    if m is None or len(m.roles) != 1 or not all(w.isalpha() and w not in VERBS | AT for w in words[j:m.start]):
        return None
    return m


def _glossed_place(sent: _Sentence, a: int, b: int) -> list[Mention]:
    """The thing a bracket right after the part [a, b) glosses its last word as, when that word is
    a place no name of the task names, after a preposition of place ("it stands on pufyk (the
    ottoman, small soft one)"): the part's holder, though the bracket is a part of its own; none
    otherwise."""
    words = sent.words
    if b + 1 >= len(words) or words[b] != "(" or b - a < 2 or any(m.start <= b - 1 < m.end for m in sent.mentions) \
            or not (words[b - 2] in FALLBACK_AT or words[b - 3:b - 2] and words[b - 3] in FALLBACK_AT
                    and words[b - 2] in ARTICLES):
        return []
    gloss = _bracket_gloss(sent, b + 1)
    return [gloss] if gloss is not None else []


def _active_perfect(group: list[str]) -> bool:
    """An active perfect of a verb of result ("had put", "have left", "has dropped"): a past act
    with its object after it, as the simple past is ("put", "left"); not a passive ("has been left")."""
    verbs = [w for w in group if w not in ADVERBS]
    return len(verbs) == 2 and verbs[0] in PERFECT and verbs[1] in RESULT


def _holder_after(sent: _Sentence, ms: list[Mention], j: int, hi: int) -> tuple[str, Mention] | None:
    """(preposition, place) when tokens from j read "on/in [the ...] <place>"."""
    words = sent.words
    if j < hi and _covers(words, j):
        words = [*words[:j], "on", *words[j + 1:]]  # "spread over the bed": on the bed
    if j + 1 < hi and words[j] in PLACE_INTENSIFIERS and (words[j + 1] in AT or words[j + 1] == "at"):
        j += 1  # "right at the back of the wardrobe", "bang in the middle of the table"
    if j < hi and words[j] == "at":
        return _at_part(sent, ms, j, hi)
    if j >= hi or words[j] not in AT:
        return None
    k = j + 1
    # (a modifier that begins a name is the name's: "on the open shelves" is a shelving unit)
    while k < hi and not any(m.start == k for m in ms) and (
            words[k] in ARTICLES or words[k] in COLOR_WORDS or words[k] in STATE_WORDS
            or words[k] in RANKS and k + 1 < hi and words[k + 1] not in ("of", ",")):
        k += 1
    outer = _outer_part(sent, ms, j, k, hi)
    if outer is not None:
        return ON_PART, outer
    whole = _part_of(sent, ms, k, hi)
    if whole is not None:
        # "on the lower shelf of the metal rack": on the rack; "on the top shelf of the wardrobe":
        # in it (a part is inside a container, on an open piece: `_contain`, as in a bracket)
        return "in", whole
    tied = _tied_whole(sent, ms, j, k, hi)
    if tied is not None:
        return ON_PART, tied
    m = next((m for m in ms if m.start == k), None)
    if m is None and k > j + 1 and words[k - 1] in ARTICLES:
        m = _modified_holder(words, ms, k, hi)
    elif m is None and k == j + 1:
        m = _owned_holder(words, ms, k, hi)
    # a place the text names by a word no name of the task holds, said again after it
    unknown = m is None and k + 2 < len(words) and words[k].isalpha() and words[k] not in PREP_OF_PLACE | VERBS \
        and not any(t.start <= k < t.end for t in sent.mentions)
    if unknown and k + 2 < hi and words[k + 1] == ",":
        m = _apposed(sent, ms, k + 2, hi)  # "on the taburete, the little stool"
    if unknown and m is None and words[k + 1] == "(":
        m = _bracket_gloss(sent, k + 2)  # "on wersalka (sofa)", "in the kufer (the trunk)"
    if m is not None and m.kind == "room":
        # "sits on the cloakroom counter", "on the bedroom dresser": a room's name before a thing's
        # names which one (`_room_words`); the place is the thing
        m = next((t for t in ms if t.start == m.end and t.kind == "role"), m)
    return (words[j], m) if m is not None else None


#: how many modifiers naming nothing may stand between a place's article and its head: "on the
#: props table" (one), "on the steel cage trolley", "on the old oak desk" (two: a material or a
#: make and what the thing is, as shops and notes name furniture)
_HOLDER_MODIFIERS = 2


#: words of `PREP_OF_PLACE` that are a modifier right before a holder's name, telling which side
#: of a room or a row it is ("on the front desk", "the back counter", "the left shelf"); before
#: "of" they name a part of the holder ("on the front of the desk": on the desk all the same)
SIDE_MODIFIERS = frozenset({"front", "back", "left", "right", "middle", "end", "corner", "side", "other", "same"})


def _modified_holder(words: list[str], ms: list[Mention], k: int, hi: int) -> Mention | None:
    """The holder after one or two modifiers from token `k` that name nothing, are words and are
    no verb or preposition ("lives on the props table", "kept on the steel cage trolley", "on the
    old oak desk"): the noun phrase's head is the place, as the naming step reads one modifier
    (`naming.modified`). Why two: a place named with a material and a kind before its head ("wire
    cage trolley", "glass top coffee table") is as common as one with a single modifier. A
    preposition among them ("on its way to the cart", "on the shelf next to the table") ends the
    phrase: the place is another."""
    for n in range(1, _HOLDER_MODIFIERS + 1):
        mods = range(k, k + n)
        # (one modifier may be a verb's form too, "the drying rack"; of two, neither is)
        if k + n >= hi or not all(words[i].isalpha() and words[i] not in AT | PREP_OF_PLACE - SIDE_MODIFIERS
                                  and (n == 1 or words[i] not in VERBS)
                                  and not any(t.start <= i < t.end for t in ms) for i in mods):
            return None
        m = next((t for t in ms if t.start == k + n and t.kind == "role"), None)
        if m is not None:
            return m
    return None


def _owned_holder(words: list[str], ms: list[Mention], k: int, hi: int) -> Mention | None:
    """The holder after one word naming nothing with no article before it: a person's possessive,
    whose "'s" `expand` has dropped ("on Sam's desk" reads "on sam desk", "in Grandma's wardrobe",
    "under Dad's bed"), or a terse note's modifier ("in wooden box"). The word stands where "my"
    would, so the place is the head after it; two such words are no place (`_modified_holder`
    reads two only after an article)."""
    m = _modified_holder(words, ms, k, hi)
    return m if m is not None and m.start == k + 1 else None


def _at_part(sent: _Sentence, ms: list[Mention], j: int, hi: int) -> tuple[str, Mention] | None:
    """(preposition, holder) of "at the [far] <part> of [the ...] <holder>" (`AT_PARTS`): "at the
    head of the long table" is on the table, "at the bottom of the basket" in it; "at the side of"
    or "at the foot of" a thing is beside it, no place on or in it."""
    words = sent.words
    k = j + 1
    if k >= hi or words[k] not in ("the", "its", "their"):
        return None
    k += 1
    while k < hi and words[k] in AT_PART_MODIFIERS and words[k + 1:k + 2] != ["of"]:
        k += 1
    if k + 2 >= hi or words[k] not in AT_PARTS or words[k + 1] != "of" or any(t.start <= k < t.end for t in ms):
        return None
    n = k + 2
    while n < hi and words[n] in ARTICLES:
        n += 1
    m = next((t for t in ms if t.start == n and t.kind == "role" and len(t.roles) == 1), None)
    if m is None and n + 1 < hi and words[n].isalpha() and words[n] not in VERBS | AT \
            and not any(t.start <= n < t.end for t in ms):
        m = next((t for t in ms if t.start == n + 1 and t.kind == "role" and len(t.roles) == 1), None)  # "the long table"
    return (AT_PARTS[words[k]], m) if m is not None else None


def _tied_whole(sent: _Sentence, ms: list[Mention], j: int, k: int, hi: int) -> Mention | None:
    """The thing of "on the <part> above/of/over the <thing>" when the part names no role (a part
    the catalog has no kind for, which the naming step names no object: "On the mantelpiece above
    the fireplace sits the candle", "the vase is on the mantel of the fireplace"): a thing on the
    part is on the thing it is part of where it has a top (as on an outer part, `ON_PART`: never in
    it). A part that names a role is that role ("on the shelf above the desk")."""
    words = sent.words
    if words[j] not in ("on", "upon") or k + 2 >= hi or not words[k].isalpha() or words[k + 1] not in PART_TIES \
            or any(t.start <= k < t.end for t in ms):
        return None
    n = k + 2
    while n < hi and words[n] in ARTICLES:
        n += 1
    return next((m for m in ms if m.start == n and m.kind == "role" and len(m.roles) == 1), None)


#: prepositions that, after a verb of covering or of resting, name the thing under ("draped over
#: the chair", "spread across the bed", "a blanket lies across the ottoman")
OVER = frozenset({"over", "across"})


def _covers(words: list[str], j: int) -> bool:
    """Whether words[j] is an "over" or "across" that names what a covering verb's thing lies on
    (`COVERING`, `OVER`), or an outer part of a holder it hangs on, whatever the verb
    (`_over_a_part`: "the towel is over the back of the chair")."""
    return words[j] in OVER and (j > 0 and words[j - 1] in COVERING or _over_a_part(words, j, len(words)))


def _outer_part(sent: _Sentence, ms: list[Mention], j: int, k: int, hi: int) -> Mention | None:
    """The thing whose outer part (`OUTER_PARTS`) a place "on" names: "on the fridge door", "on the
    side of the bath", "on the corner of the desk". A thing there is on the outside of that thing, not
    in it, whatever a container said "on" otherwise means (`_contain`); "in the fridge door" is in it."""
    words = sent.words
    if words[j] not in ("on", "upon") and not _covers(words, j):
        return None
    if k + 2 < hi and words[k] in OUTER_PARTS and words[k + 1] == "of":
        n = k + 2
        while n < hi and words[n] in ARTICLES:
            n += 1
        return next((m for m in ms if m.start == n and m.kind == "role" and len(m.roles) == 1), None)
    m = next((m for m in ms if m.start == k and m.kind == "role" and len(m.roles) == 1), None)
    if m is not None and m.end < hi and words[m.end] in OUTER_PARTS and words[m.end + 1:m.end + 2] != ["of"]:
        return m
    return None


def _part_of(sent: _Sentence, ms: list[Mention], k: int, hi: int) -> Mention | None:
    """The thing of "<part> of the <thing>" when word `k` is a part of a piece of furniture
    (`FURNITURE_PARTS`: "the lower shelf of the metal rack", "the top drawer of the dresser"): a
    thing on or in the part is on or in the thing (`_contain` tells which by the thing); the name
    of the thing may follow one modifier that names nothing ("the metal rack")."""
    words = sent.words
    if k + 2 >= hi or words[k] not in FURNITURE_PARTS and sent.toks[k].lemma not in FURNITURE_PARTS \
            or words[k + 1] != "of":
        return None
    j = k + 2
    while j < hi and words[j] in ARTICLES:
        j += 1
    m = next((x for x in ms if x.start in (j, j + 1) and x.kind == "role" and len(x.roles) == 1), None)
    if m is None or m.start == j + 1 and (j == k + 2 or any(x.start <= j < x.end for x in ms) or not words[j].isalpha()):
        return None
    return m


def _put(reading: _Reading, kind: str, catalog: Catalog, lex: Lexicon, item: str, holder: Mention,
         prep: str) -> None:
    """Record `item` at `holder` (a role, a room or the floor) under `kind`."""
    if holder.kind == "room":
        if item not in lex.rooms:
            reading.room(kind, item, holder.roles[0])
        return
    if holder.kind == "floor":
        cat = catalog.get(str(lex.roles[item]["category"]))
        if cat is not None and "floor" in cat.placement or cat is not None and cat.pickable:
            reading.place(kind, item, f"on({item}, floor)")
            room = _floor_room(holder, lex)
            if room is not None:
                reading.room(kind, item, room)
        return
    if len(holder.roles) != 1:
        return
    fact = _contain(catalog, lex, item, holder.roles[0], prep)
    if fact is not None:
        reading.place(kind, item, fact)


def _floor_room(floor: Mention, lex: Lexicon) -> str | None:
    """The room of "the kitchen floor" (a floor mention longer than one word), if any."""
    if floor.end - floor.start < 2:
        return None
    return next((r for r in lex.rooms if floor.end - floor.start - 1 == len(r.split("_"))), None)


def _contain(catalog: Catalog, lex: Lexicon, item: str, holder: str, prep: str) -> str | None:
    """`inside(...)` for a container said "in" (or one that is no surface), `on(...)` for a
    surface; None when the item is furniture (it stands on the floor) or the holder holds nothing."""
    cat = catalog.get(str(lex.roles[holder]["category"]))
    item_cat = catalog.get(str(lex.roles[item]["category"]))
    if item == holder or cat is None or not (cat.container or cat.surface):
        return None
    if item_cat is not None and not item_cat.pickable and (item_cat.surface or item_cat.container):
        return None  # furniture rests on the floor, not on another piece
    if prep == ON_PART:  # "on the fridge door": on a thing with a top, never in it
        return f"on({item}, {holder})" if cat.surface else None
    inside = cat.container and (prep in PREP_IN or not cat.surface)
    return f"{'inside' if inside else 'on'}({item}, {holder})"


# --- the forms -------------------------------------------------------------------------------


def _heading_mark(words: list[str]) -> int | None:
    """Where a heading ends: its colon, or (the nineteenth session) a dash after a heading that
    opens with a preposition of place, as inventories and notes write a place before its list
    ("On the counter - 1 mug", "In the top drawer – socks, a belt"); a dash after any other
    opening is a label's or an aside's (`_label`)."""
    if ":" in words:
        return words.index(":")
    if words[:1] and words[0] in AT:
        return next((k for k, w in enumerate(words) if w in _LABEL_MARKS), None)
    return None


def _heading(sent: _Sentence, lex: Lexicon, catalog: Catalog, reading: _Reading) -> int:
    """"Bedroom: the table lamp, ...", "Kitchen: two pet bowls", "On the floor: a dirty mark, and
    possibly a book", "In the room: a sofa; a table": a heading naming a room or a place before a
    colon, and the list after it. Returns where the body starts (0 without a heading)."""
    words = sent.words
    colon = _heading_mark(words)
    dash = _room_dash(sent)
    if dash is not None and (colon is None or dash < colon):
        colon = dash
    if colon is None:
        return 0
    head = [m for m in sent.mentions if m.end <= colon]
    if len(head) != 1 or head[0].kind == "role" and len(head[0].roles) != 1:
        return 0
    place = head[0]
    lo = _label_before(words, place.start)
    filler = [words[i] for i in range(lo, colon) if not place.start <= i < place.end]
    if not all(w in AT | ARTICLES | _LEADS or _heading_lead(filler, k) for k, w in enumerate(filler)):
        return 0
    prep = next((w for w in reversed(words[lo:place.start]) if w in AT), "in")  # "On display in the case"
    if place.kind == "role" and prep not in AT:
        return 0
    if place.kind == "role" and not set(filler) & AT:
        if not _holder_over_list(sent, place, colon, catalog, lex):
            return 0  # "Plate: ...", "Two toy boxes: ...": the thing spoken of, not a place
        prep = "on"  # "DESK: laptop": on a surface, in a container that is none (`_contain`)
    body = [m for m in sent.mentions if m.start > colon]
    for clause in _clauses(words, colon + 1, len(words)):
        if clause.mood == "condition" and place.kind != "room":
            continue
        for m in _np_list(sent, [b for b in body if clause.start <= b.start < clause.end],
                          clause.start, clause.end) if place.kind != "room" else [
                b for b in body if clause.start <= b.start < clause.end and not _indefinite_doubt(sent, b)]:
            for role in _roles(m, sent):
                if role != place.roles[0]:
                    _put(reading, "settled", catalog, lex, role, place, prep)
        if place.kind != "room" and clause.doubted:
            break
    if place.kind == "room" and colon == dash:
        # (a room's colon heading covers its own sentence only: carried over its line as well, it
        # cost a held-out rewording, `docs/reader.md`)
        reading.section_room = place.roles[0]
    return colon + 1


def _room_dash(sent: _Sentence) -> int | None:
    """Where a room's heading ends at a dash: a room's name alone before it, after an item's number
    at most ("BEDROOM - table lamp: on = defect", "2) Bathroom - towel on the floor?", "Kitchen -
    kettle: if it's on, ..."), as check sheets and notes head each room's part; what follows is in
    that room (`_heading`). None when a thing's name or a word stands before the dash."""
    words = sent.words
    dash = next((k for k, w in enumerate(words) if w == "-"), None)
    if dash is None:
        return None
    head = [m for m in sent.mentions if m.end <= dash]
    after = next((m for m in sent.mentions if m.start > dash), None)
    if len(head) != 1 or head[0].kind != "room" or head[0].end != dash or after is not None and after.kind == "room":
        return None  # (not a list of rooms: "Hall - Kitchen - Lounge: lights off")
    return dash if all(w.isdigit() or w in (")", ".") or w in ARTICLES for w in words[:head[0].start]) else None


#: nouns of being shown that "on" makes a state of place before a heading's own preposition ("On
#: display in the cabinet: a vase", "on show on the shelf", "on view in the case"): a museum
#: label's, a shop window's or an exhibition list's way of saying where the things are
ON_SHOW = frozenset({"display", "show", "view"})


def _heading_lead(filler: list[str], k: int) -> bool:
    """Whether the heading word `filler[k]` leads into its place and leaves it a place where things
    are: a participle that states where a thing is (`PASSIVE_STATIVE`, `OBSERVED`: "Found on the
    floor: a sock, a mug", "Left on the bed: a towel", "Noted on the desk: a cup") opening the
    heading right before its preposition, or "on display" / "on show" before one. Why: lost-property
    lists, inventories, museum labels and inspection notes put the participle first; a base form
    ("Put on the counter: ...", "Set on the counter: ...") may be an instruction, and a participle
    of wanting ("Wanted on the desk: a lamp") says no thing is there, so neither is read; "Kept in
    the drawer:" (`KEEP_VERBS`) says where things belong, not where they are now."""
    before_place = k + 1 < len(filler) and filler[k + 1] in AT
    if k == 0:
        return before_place and filler[k] in (PASSIVE_STATIVE | OBSERVED) - KEEP_VERBS
    return filler[k] in ON_SHOW and filler[k - 1] == "on" and before_place


def _label_before(words: list[str], start: int) -> int:
    """Where a heading's place phrase begins, after a label that names nothing: a document's field
    or entry ("Contents, counter: 2 x mugs", "Room 12 - Nightstand: phone", "Shelf 3, on the left
    - ...") set off by a comma or a dash before the place. A label with a condition, a doubt or a
    negation ("If dirty, sink: ...") is no label: the heading is read as before (from its start)."""
    mark = max((k for k in range(start) if words[k] in _HEADING_LABEL_MARKS), default=-1)
    if mark < 0 or set(words[:mark]) & (SUBORDINATORS | DOUBT | NEGATIONS | {"if", "unless"}):
        return 0
    return mark + 1


def _holder_over_list(sent: _Sentence, place: Mention, colon: int, catalog: Catalog, lex: Lexicon) -> bool:
    """Whether a heading that is a holder's bare name heads a list of the things it holds ("DESK:
    laptop, lamp", "Fridge: two apples", "Counter: 2 x mugs, the kettle"): an inventory's,
    a packing list's, a stage plot's or a note's way of writing "on the desk: ...". Only a holder
    (a surface or a container) and a body that is nothing but a list of things (names, articles,
    colours, counts and the list's commas): a word of its own after the colon ("Plate: clean - into
    the cabinet", "Lamp: switch it off", "Bed: pillow on the floor?") makes the heading the thing
    spoken of, as before."""
    cat = catalog.get(str(lex.roles[place.roles[0]]["category"])) if len(place.roles) == 1 else None
    if cat is None or not (cat.surface or cat.container):
        return False
    words = sent.words
    end = len(words) - (words[-1:] in ([","], ["."], [";"], ["!"]))
    covered = {k for m in sent.mentions if m.start > colon for k in range(m.start, m.end)}
    things = [m for m in sent.mentions if m.start > colon and m.kind == "role" and m.roles != place.roles]
    return bool(things) and all(m.kind == "role" for m in sent.mentions if m.start > colon) and all(
        k in covered or words[k] in LIST_GLUE or words[k] in COLOR_WORDS or _quantity(words, k)
        for k in range(colon + 1, end))


def _indefinite_doubt(sent: _Sentence, m: Mention) -> bool:
    """"there might be a shirt", "possibly a pack of wipes", "if there is a pan": an object whose
    presence is in doubt (an indefinite under a modal or a condition a few words before)."""
    before = sent.words[max(0, m.start - 5):m.start]
    return bool(set(before) & (DOUBT | SUBORDINATORS | {"case"})) and (
        "a" in before or "an" in before or "any" in before or "there" in before or "some" in before)


def _frame(sent: _Sentence, reading: _Reading, lo: int) -> None:
    """"In the kitchen there are two pet bowls", "In the bedroom, turn off the table lamp", "Over
    in the living room, clean the pet bed": a room opening its sentence frames every object the
    sentence names, but an object only possibly there ("there might be a pan")."""
    words = sent.words
    rooms = [m for m in sent.mentions if m.kind == "room" and m.start >= lo]
    if not rooms:
        return
    first = rooms[0]
    lead = words[lo:first.start]
    if not (lead[-2:] == ["in", "the"] and all(w in _LEADS for w in lead[:-2])):
        framed = next((m for m in rooms if _clause_frame(words, lo, m.start)), None)
        if framed is None:
            return
        first = framed
    # (a question mark ends the sentence the room frames: "... the sink, right? Now you clear the
    # dining table", which this reader reads as one sentence, `_sentences`)
    end = next((k for k in range(first.end, len(words)) if words[k] == "?"), len(words))
    for later in sent.mentions:
        if later.start < first.end:
            continue
        if later.kind == "room" and later.roles != first.roles or later.start > end:
            break  # (the room named again goes on framing: "the study, where in the study ...")
        if later.kind == "role" and not _indefinite_doubt(sent, later) and _named(words, later.start):
            for role in _roles(later, sent):
                reading.room("settled", role, first.roles[0])


def _clause_frame(words: list[str], lo: int, start: int) -> bool:
    """Whether the room at `start` opens a clause of its own after a comma or a semicolon, as
    `_frame` reads a room opening its sentence: "The dining room opens onto the kitchen, and there
    in the kitchen you have the dishwasher, the sink ...", "The hall leads to the kitchen; in the
    kitchen you will find a fridge and a sink"; or a room a relative "where" follows ("Go on to the
    study, where (in the study) the laptop belongs on the desk")."""
    if words[start + 1:start + 3] == [",", "where"] and start + 1 < len(words):
        # "Sashay to the study, where the laptop belongs on the desk": a relative "where" after
        # the room speaks of what is there
        return True
    if words[max(lo, start - 2):start] != ["in", "the"]:
        return False
    k = start - 3
    # (", where in the study the laptop belongs on the desk": the relative's own fronted room)
    while k >= lo and words[k] in _LEADS | {"there", "where"}:
        k -= 1
    return k >= lo and words[k] in (",", ";")


def _named(words: list[str], start: int) -> bool:
    """A noun phrase with its determiner ("the wardrobe", "two pet bowls"), not a verb ("bin the wipe")."""
    return any(w in ARTICLES for w in words[max(0, start - 2):start])


def _room_words(sent: _Sentence, lex: Lexicon, reading: _Reading) -> None:
    """"the bedroom wardrobe", "the kitchen sink", "the kitchen counter": a room's name before a
    noun (or starting the object's own name) says which room it is in."""
    for a, b in zip(sent.mentions, sent.mentions[1:], strict=False):
        if a.kind == "room" and b.kind == "role" and b.start == a.end and len(b.roles) == 1:
            reading.room("settled", b.roles[0], a.roles[0])
    for m in sent.mentions:
        if m.kind != "role" or len(m.roles) != 1:
            continue
        for room in lex.rooms:
            parts = room.split("_")
            if m.end - m.start > len(parts) and [t.lemma for t in sent.toks[m.start:m.start + len(parts)]] == parts:
                reading.room("settled", m.roles[0], room)


#: conjunctions that may open a clause before its subject ("so it'll be on the floor")
_CLAUSE_LEADS = frozenset({"so", "and", "then", "but"})


#: what a condition asks when it asks whether an agent left the thing there ("if she did leave
#: it", "if you forgot them"): then "it will be on the armchair" is where it is, if it is
LEAVING = frozenset({"leave", "left", "forget", "forgot", "forgotten", "drop", "dropped", "lose", "lost"})


def _if_there(words: list[str], clause: Span) -> bool:
    """Whether a condition right after the clause ("it will be on the floor if it is anywhere")
    or before it ("If it is there, it will be on the armchair", "If she did leave it, it'll be on
    the armchair") only asks whether the thing is there (`clauses.presence_asked`, or an agent
    leaving it, `LEAVING`): then "it will be on the floor" is the speaker's guess where the
    thing is, if it is there (a stated place of a thing that may be absent), not a goal."""
    after = [w for w in words[clause.end:clause.end + 7] if w[0].isalnum()]
    if after[:1] == ["if"] and presence_asked(after[1:]) is False:
        return True
    cue = max((n for n in range(clause.start) if words[n] == "if"), default=None)
    if cue is None:
        return False
    asked = [w for w in words[cue + 1:clause.start] if w[0].isalnum() and w != "still"]
    return presence_asked(asked) is False or 2 <= len(asked) <= 4 and not set(asked) & NEGATIONS \
        and asked[-1] in ("it", "them") and bool(set(asked) & LEAVING)


def _locative(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
              reading: _Reading) -> None:
    """"The cardboard box is on the floor next to the stool", "the dishwasher, the sink and a
    cabinet are in the kitchen", "The bath mat lies on the floor", "A dirty mark has been left on
    the floor", "Two pet bowls are kept in the kitchen": the noun-phrase list before a verb of
    being, resting or result is at the place after it; later ", <list> in <place>" parts share the
    verb ("..., a sofa and a coffee table in the living room")."""
    words = sent.words
    i = lo = clause.start
    while i < clause.end:
        if words[i] not in BE | PERFECT | STATIVE | RESULT | KEEP_VERBS and not _get_passive(words, i, clause.end):
            i += 1
            continue
        end, group = _verb_group(words, i, clause.end)
        if end > i + 1 and _covers(words, end - 1):
            end, group = end - 1, group[:-1]  # "draped over the chair": "over" is the place's, not a particle
        start, i = i, end
        kind = _verb_kind(group)
        k = start - 1
        while k > clause.start and words[k] in ADVERBS:
            k -= 1
        # (a name's last word is no auxiliary: "the watering can is on the bench", "the trash can
        # stands by the door": "can" ends the subject's name, `_named_word`)
        before = words[k] if k >= clause.start and not _named_word(ms, k) else ""
        reported = _reported(before, group, words[clause.start:k])
        guessed = before == "will" and _if_there(words, clause)
        standing = _standing(words, clause, before, group, end)
        ruled = standing or _predicted(words, clause, before, group, end)
        if before in NORMATIVE and not (before in PERFECT and group[:1] == ["been"]) and not guessed and not ruled \
                or before in ("you", "we", "i") and not set(group) & KEEP_VERBS and not reported:
            continue  # a norm or a goal ("should be in"), or what someone does ("which you hang on")
        if kind is None or clause.mood == "instruction" and _finite(group):
            continue  # an instruction places only through its noun phrases ("the coat the kids dumped ...")
        if kind == "settled" and _earlier_occasion(words, clause):
            continue  # "last time the headset sat on that table for a fortnight": then, not now
        named_end = max((m.end for m in ms if lo <= m.start and m.end <= start), default=lo)
        if set(words[named_end:start]) & NEGATIONS:
            continue  # "the mug never ever stands on the table", "does not sit on": no place stated
        if kind == "settled" and group[-1] in STATIVE and (
                (set(group) | set(words[k + 1:start])) & NORM_ADVERBS or _timed_rest(words, clause, group)):
            kind = "kept"  # "flowers that normally sit on the bench": where they belong, not where they are
        subjects = _np_list(sent, ms, lo, start)
        said = [w for w in words[lo:k + 1] if not (guessed or standing) or w not in _CLAUSE_LEADS and w != before]
        last = reading.last_carried if guessed else reading.last_subject
        # "wipe the puddle with the old towel - it's kept in the vanity": "it" is a thing its own
        # sentence named (`_kept` reads that), not the last statement's subject
        earlier = any(m.end <= clause.start and m.kind == "role" for m in sent.mentions)
        # (after a time put first, "After a job it gets dumped on the bench", the same "it")
        timed = said[-1:] == ["it"] and fronted_time(said, VERBS) == len(said) - 1
        if not subjects and (_finite(group) or guessed or standing) and (said == ["it"] or timed) \
                and last is not None and last.kind == "role" and len(last.roles) == 1 and (guessed or not earlier):
            subjects = [last]  # "Broom. ... Not agreed; it stays standing on the floor"
        if ruled:
            if not subjects:
                continue  # the rule's subject is the noun phrase before its modal, or a standing rule's "it"
        elif not _finite(group) or _active_perfect(group):
            who = start - 1
            while who > lo and words[who] in ADVERBS:
                who -= 1
            if subjects and subjects[-1].end == start:  # "the keys lying on the floor": a modifier
                if _definite(sent.words, subjects[-1].start) or _named_possessor(words, clause.start, subjects[-1].start):
                    kind = "presumed"
                elif clause.mood == "statement" and _headline(sent, clause, subjects, start, end):
                    kind = "presumed"  # a report ("Torch found on the bunk again"): a later "if on bunk" asks it
                elif not (clause.mood == "statement" and _held_list(words, clause, subjects[-1].start)):
                    kind = ""
                subjects = subjects[-1:]
            elif who >= lo and _agent(sent, ms, lo, who) and group[-1] in RESULT \
                    and not set(words[who + 1:start]) & (NORM_ADVERBS | FREQUENCY):
                # (not a habit: "my husband always puts it on the floor" says where it tends to be)
                at = next((k for k in range(end, clause.end) if words[k] in AT), clause.end)
                after = _np_list(sent, ms, end, at)
                if not after and words[end:at] == ["it"]:
                    # "My jacket. I left it on the sofa.", "My jacket: I left it on the sofa": the
                    # object "it" is the thing the text last spoke of, as a subject "it" is ("The
                    # jacket. It is on the sofa.")
                    after = _object_it(sent, clause, last, earlier)
                elif not after and end == at:
                    after = _gapped_topic(sent, clause, at)
                # "someone left a mark on the floor"; "the coat the kids dumped in the hallway"
                subjects, end = (after, at) if after else (_np_list(sent, ms, lo, who), end)
                # (a speaker's report of their own act is presumed: a later "if it is still on
                # the floor" asks again, `_reported`)
                kind = kind if clause.mood == "statement" and not reported else "presumed"
            elif clause.mood == "statement" and words[who:who + 1] == [","] and (
                    _resting_participle(group) or _result_participle(group) and not set(words[lo:who]) & (BE | PERFECT)):
                subjects = _adjunct_subject(sent, ms, lo, who)  # "the telly's on, sitting on the stand"
            elif start == 0 and clause.mood == "statement" and _headed_participle(sent, ms, group, end, reading):
                # "b) My cup. Left on the desk, next to the scales.": the heading's one thing
                subjects, kind = [last] if last is not None else [], "presumed"
            else:
                continue
            if not kind:
                continue
        found = _holder_after(sent, ms, end, clause.end) or _pronoun_holder(sent, clause, end, lex, reading)
        if found is None and kind == "settled" and group[-1] in PLACE_PRONOUNS and subjects:
            found = _place_back(sent, subjects[0].start)
        if found is None:
            continue
        if words[clause.start] in RELATIVE and not subjects:
            back = _antecedent(sent, clause)
            subjects = [back] if back is not None else []
        if not subjects and _finite(group) and _code_switched(sent) and words[lo:k + 1] \
                and words[lo] in ARTICLES and all(foreign(w) for w in words[lo + 1:k + 1]):
            subjects = _gloss(sent, ms, found[1].end, clause.end)  # "The kaldero is on the stove, yung big pot"
        first = subjects[0].start if subjects else start
        said = words[max(lo, first - 3):found[1].end]
        # (a speaker's belief before the subject doubts it too: "I think I left the torch on the shelf")
        believed = _believed(words[clause.start:first])
        if not subjects or words[clause.start] == "there" or doubts(said) or habitual(said) or believed \
                or _alternative_place(words, found[1].end, len(words)):
            lo = found[1].end
            continue  # no subject, an existential (`_existential`), a doubt ("may have been put") or a habit
        prep, holder = found
        for m in subjects:
            for role in _roles(m, sent):
                _put(reading, kind, catalog, lex, role, holder, prep)
        lo = _gapped(sent, clause, ms, holder.end, kind, lex, catalog, reading)
    if clause.mood == "statement":
        _fragment(sent, clause, ms, lex, catalog, reading)


def _timed_rest(words: list[str], clause: Span, group: list[str]) -> bool:
    """Whether a present verb of resting is bounded by a time clause of its own sentence
    (`clauses.AGENT_TIMES`, the twenty-first session): "It hangs on the hook when nobody's
    gathering", "The kettle sits on the stove when it's not in use", "the mop stands in the
    bucket while not in use" say where the thing is at such times, its home, as "usually hangs" does,
    not where it is now; a later "Found it lying on the floor?" asks. A past ("the coat hung on
    the hook when I left"), a participle, and a time of the reader's arrival ("when you come in":
    what they will find, `_arrival_time`) are none, and so is a condition set off after a comma
    or "and" ("The lamp sits on the desk, and when it's on, ..." asks of the lamp, no time of its
    resting)."""
    verb = group[-1]
    if verb in ENDED_PAST_VERBS or verb.endswith("ing") or not _finite(group) or set(group) & (BE | PERFECT):
        return False
    # (the time clause right after the place; one put first makes the whole a condition, read there)
    return clause.end < len(words) and words[clause.end] in AGENT_TIMES \
        and _arrival_time(words, clause.end, len(words)) is None


def _said_after(words: list[str], lo: int, hi: int, phrases: tuple[tuple[str, ...], ...]) -> bool:
    """Whether one of `phrases` (word sequences) stands in words[lo:hi]."""
    return any(tuple(words[k:k + len(p)]) == p for k in range(lo, hi) for p in phrases if k + len(p) <= hi)


def _only_be(group: list[str]) -> bool:
    """A verb group of "be" and a verb of resting at most ("be", "be sitting", "always be")."""
    verbs = [w for w in group if w not in ADVERBS]
    return verbs[:1] == ["be"] and all(w in STATIVE for w in verbs[1:])


def _standing(words: list[str], clause: Span, before: str, group: list[str], end: int) -> bool:
    """A standing rule (`STANDING_MODALS` with one of `STANDING_TIMES`, no negation and no time of
    completion in the clause): "the phone should be on the bedside table at all times"."""
    tail = _tail(words, clause.end)  # the time may follow a comma: "on the sofa, day and night"
    return before in STANDING_MODALS and _only_be(group) and not set(words[clause.start:clause.end]) & NEGATIONS \
        and _said_after(words, clause.start, tail, STANDING_TIMES) \
        and not _said_after(words, end, tail, COMPLETION_TIMES)


def _tail(words: list[str], end: int) -> int:
    """Where an adverbial set off by a comma after a clause ends: four words on at most, up to the
    sentence's next full stop, semicolon or question mark."""
    k = end
    while k < min(len(words), end + 4) and words[k] not in (".", ";", "?"):
        k += 1
    return k


def _predicted(words: list[str], clause: Span, before: str, group: list[str], end: int) -> bool:
    """The predictive "will be" of what the reader will find (`COMPLETION_TIMES`): framed by their
    arrival, before it ("When you come in, the mug will be on the counter", `_arrival_frame`) or
    after it ("... will be on the desk when you get there"), or by a case the sentence opens with
    ("Where one was issued, the hair dryer will be on the desk"). Said alone ("The mug will be on
    the desk. Wash it.") or under a condition ("... if it is dirty") it stays a goal."""
    if before != "will" or not _only_be(group) or clause.mood != "statement" \
            or set(words[clause.start:clause.end]) & NEGATIONS:
        return False
    tail = _tail(words, clause.end)
    stop = next((x for x in range(end, len(words)) if words[x] in (".", ";", "?")), len(words))
    if _said_after(words, end, tail, COMPLETION_TIMES) or set(words[end:stop]) & {"if", "unless"}:
        return False
    framed = _arrival_frame(words, 0, clause.end) == clause.start
    arriving = any(_arrival_time(words, x, tail) is not None for x in range(end, tail))
    case = words[clause.start] == "where" and "," in words[clause.start:end]
    return framed or arriving or case or _habit_where(words, end, stop)


#: object pronouns a habitual relative takes the thing up by ("where Dad always leaves it")
_HABIT_OBJECTS = frozenset({"it", "them", "one"})


def _habit_where(words: list[str], end: int, stop: int) -> bool:
    """Whether, after the place of a predictive "will be" (from `end` to the sentence's `stop`), a
    relative "where" says the habit that puts the thing there: an adverb of norm or frequency
    (`NORM_ADVERBS`, `FREQUENCY`) and the thing taken up by a pronoun ("The remote will be on the
    sofa, where Dad always leaves it", "your keys will be in the bowl where you usually drop
    them"). The habit is why the writer expects the thing there, so the reader will find it there.
    "where it belongs" or "where the porter will collect it" says no habit: the "will be" stays
    a goal."""
    x = next((k for k in range(end, stop) if words[k] == "where"), stop)
    rel = set(words[x + 1:stop])
    return x < stop and bool(rel & (NORM_ADVERBS | FREQUENCY)) and bool(rel & _HABIT_OBJECTS)


def _arrival_time(words: list[str], lo: int, hi: int) -> int | None:
    """The end of a time clause of the reader's arrival at `lo` ("when you come in", "when the
    guests arrive": "when", a person, `ARRIVING` and its particles), else None."""
    if hi - lo < 3 or words[lo] != "when":
        return None
    k = lo + 1
    if words[k] == "the":
        k += 1
    if k >= hi or words[k] not in ARRIVERS:
        return None
    k += 1
    if k >= hi or words[k] not in ARRIVING:
        return None
    k += 1
    while k < hi and words[k] in ARRIVING_PARTICLES:
        k += 1
    return k


def _arrival_frame(words: list[str], lo: int, hi: int) -> int | None:
    """Where the main clause after a time clause of arrival (`_arrival_time`) and its comma starts,
    else None."""
    k = _arrival_time(words, lo, hi)
    return k + 1 if k is not None and k + 1 < hi and words[k] == "," else None


def _alternative_place(words: list[str], j: int, hi: int) -> bool:
    """Whether a place is followed by another offered in its stead ("on the counter or in the
    car", "in the drawer, or else on the shelf"): a choice, no place stated."""
    k = j
    while k < hi and words[k] in (",", "or", "else", "maybe", "perhaps", "possibly"):
        k += 1
    return "or" in words[j:k] and k < hi and (words[k] in AT or words[k] in ("under", "behind", "at", "by", "near"))


def _object_it(sent: _Sentence, clause: Span, last: Mention | None, earlier: bool) -> list[Mention]:
    """The thing an object "it" of a statement's placing verb takes up: the topic its clause
    follows after a colon or dash ("My jacket: I left it on the sofa"), else, when its sentence
    names no thing before it, the last statement's subject ("My jacket. I left it on the sofa")."""
    if earlier:
        if clause.start == 0 or sent.words[clause.start - 1] not in (":", "-"):
            return []
        topic = [m for m in sent.mentions if m.end < clause.start and m.kind == "role"]
        return topic[-1:] if len(topic) == 1 and len(topic[0].roles) == 1 else []
    return [last] if last is not None and last.kind == "role" and len(last.roles) == 1 else []


#: marks that close off a fronted topic before the clause that says what was done with it
_TOPIC_MARKS = frozenset({":", "-", ",", ")"})


def _gapped_topic(sent: _Sentence, clause: Span, at: int) -> list[Mention]:
    """The object a placing verb leaves unsaid ("I have put on the chair", no "it") when a topic is
    fronted before its clause and set off by a dash, colon, comma or bracket: "Your gamchha - the
    towel - I have put on the chair for you", "The spare keys, we have hung on the key hook", "My
    dupatta (the scarf) I left on the sofa". A topic-first order learners of English bring from
    Bengali, Hindi or Chinese, and a speaker's afterthought in any register. Only a topic that
    names one thing and has no verb of its own ("The kettle is boiling, I have put on the radio"
    is two statements), under no condition, and a clause that names nothing but the place after
    the verb ("I have put on the chair the coat": the coat is the object)."""
    words = sent.words
    if clause.start == 0 or words[clause.start - 1] not in _TOPIC_MARKS:
        return []
    lead = words[:clause.start]
    if set(lead) & (VERBS | CONDITION_CUES):
        return []
    topic = [m for m in sent.mentions if m.end < clause.start and m.kind == "role"]
    after = [m for m in sent.mentions if at <= m.start < clause.end and m.kind == "role"]
    if len(topic) != 1 or len(topic[0].roles) != 1 or len(after) > 1:
        return []
    return topic


def _believed(lead: list[str]) -> bool:
    """Whether the words before a statement's subject are a speaker's belief (`BELIEFS` after a
    subject pronoun: "I think", "we reckon", "I'm not sure"), which hedges what follows."""
    return any(w in BELIEFS and k > 0 and lead[k - 1] in PERSONAL_SUBJECTS for k, w in enumerate(lead)) or (
        "sure" in lead and "not" in lead) or bool(set(lead) & HEDGES)


def _headline(sent: _Sentence, clause: Span, subjects: list[Mention], start: int, end: int) -> bool:
    """Whether a clause is only a noun-phrase list, a participle and its place, the terse
    register's statement (a claim form's "Old bath towel put down on the floor", a log's "Sock
    left in the drawer", a headline's "Laptop found on desk"), as a verbless "Bath mat on the
    floor" is (`_fragment`): the list opens the clause, its place is no "it", and no verb, no
    subordinate clause and no question follow the place in its sentence ("a towel left on the
    floor gets mouldy" says what happens to any; "Milk left in it -> ..." is a case of a list)."""
    words = sent.words
    covered = {k for m in subjects for k in range(m.start, m.end)}
    lo = clause.start + 1 if _possessor(words, clause.start, subjects[0].start) else clause.start
    opening = all(k in covered or w in LIST_GLUE or w in COLOR_WORDS or w in STATE_WORDS
                  for k, w in enumerate(words[lo:start], lo))
    # (a purpose "to soak up the leak" is no finite verb; a verb after a comma or in a clause of
    # its own is this noun phrase's: "A bottle left upon the table, if it be empty, goes ...")
    rest = words[end:]
    return opening and rest[1:2] != ["it"] and not any(
        w in VERBS or w in NORMATIVE - {"to"} or w in SUBORDINATORS or w == "?" for w in rest)


def _held_list(words: list[str], clause: Span, start: int) -> bool:
    """Whether the thing at `start` is listed as what a statement's subject holds ("The shed holds a
    mower and a rake leaning on the wall", "said mezzanine comprising ..., a box disposed on a
    stool, ..."): a verb of having (`HAVE_VERBS`) stands before it in its clause. There a
    participle of resting or placement after an indefinite thing states where it is, as a list of
    the scene's things does; elsewhere it describes one that may not be there ("pick up a toy
    lying on the floor")."""
    return any(w in HAVE_VERBS for w in words[clause.start:start])


def _code_switched(sent: _Sentence) -> bool:
    """Whether a sentence mixes English with another language: two words or more that are no
    English words (`sentences.foreign`)."""
    return sum(foreign(w) for w in sent.words) >= 2


def _segments(words: list[str], lo: int, hi: int) -> list[tuple[int, int]]:
    """The comma-delimited stretches of words[lo:hi], as (start, end)."""
    cuts = [lo - 1, *(k for k in range(lo, hi) if words[k] == ","), hi]
    return [(a + 1, b) for a, b in zip(cuts, cuts[1:], strict=False) if b > a + 1]


def _gloss(sent: _Sentence, ms: list[Mention], lo: int, hi: int) -> list[Mention]:
    """The thing an English noun phrase glosses in a code-switched sentence, when a subject said
    in the other language names none ("The kaldero is still on the stove, yung big pot na ginamit
    ko": the pot; "The sandok is in the drawer, the big ladle"): the one thing named in the first
    stretch after the place, with only articles, adjectives and words of the other language before
    it, and no verb in that stretch."""
    words = sent.words
    if lo >= hi or words[lo] != ",":
        return []
    end = next((k for k in range(lo + 1, hi) if words[k] == ","), hi)
    found = [m for m in ms if lo < m.start and m.end <= end and m.kind == "role" and len(m.roles) == 1]
    if len(found) != 1 or _prep_before(words, found[0].start) is not None \
            or any(w in VERBS for w in words[lo + 1:end]):
        return []  # a clause of its own ("..., the pot is in the sink"), or a place
    return found if all(w in ARTICLES or foreign(w) or w in COLOR_WORDS or getAllLemmas(w).get("ADJ")
                        for w in words[lo + 1:found[0].start]) else []


def _fragment(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
              reading: _Reading) -> None:
    """"Dirty mark on the floor.", "Bath mat on the floor, by the tub": a verbless statement (the
    terse register), a noun-phrase list and its place."""
    words = sent.words
    j = next((k for k in range(clause.start, clause.end) if words[k] in AT), None)
    if j is None:
        return
    subjects = _np_list(sent, ms, clause.start, j)
    found = _holder_after(sent, ms, j, clause.end)
    if found is None and words[j + 1:j + 2] == ["it"] and clause.start > 0 and words[clause.start - 1] in (":", "-"):
        # "The kitchen has a counter: a kettle and a toaster on it": "it" is the holder the clause
        # before the colon or dash last named
        held = [m for m in sent.mentions if m.end <= clause.start and m.kind == "role" and len(m.roles) == 1
                and m.roles[0] in lex.holders]
        found = (words[j], held[-1]) if held else None
    body = set(words[clause.start:clause.end])
    lo = clause.start
    if not subjects and j == clause.start and found is not None:
        lo, subjects = _label(sent, clause.start)  # "Torch: on the bench", "Keys - in the drawer"
    if not subjects or found is None or body & (DOUBT | VERBS | {"or"}):
        return  # doubted, a choice of places ("on the floor or on the sofa"), or it has a verb
    covered = {k for m in subjects for k in range(m.start, m.end)}
    if _code_switched(sent):
        # "Papa ka kurta, the white shirt, kursi pe pada hai, on the chair": a stretch in the other
        # language says, in its words, what the English ones say; the English ones are read. Only
        # a stretch a comma closes before the place: one running into the place holds its verb
        # ("then hoy the towel in the hamper", a dialect's instruction, is no statement)
        covered |= {k for a, b in _segments(words, clause.start, j) if b < j and any(foreign(w) for w in words[a:b])
                    for k in range(a, b)}
    covered |= _premodifiers(words, clause.start, min(m.start for m in subjects))
    if not all(k in covered or w in LIST_GLUE or w in COLOR_WORDS or w in STATE_WORDS or _quantity(words, k)
               for k, w in enumerate(words[lo:j], lo) if lo == clause.start or k < clause.start - 1):
        return
    for m in subjects:
        if _generic(sent, m):
            continue  # "Toys on the floor!": a heading about a class, no statement of where one is
        for role in _roles(m, sent):
            _put(reading, "settled", catalog, lex, role, found[1], found[0])


#: the multiplication sign of a manifest's or packing list's count ("2 x mugs"; a "×" is no token)
_TIMES = frozenset({"x"})


def _quantity(words: list[str], k: int) -> bool:
    """Whether the word at `k` is a count before a list item's thing (the nineteenth session): a
    number ("1 mug", "2x mugs") or the sign after or before one ("1 x mug", "x2"). Manifests,
    packing lists and inventories count the thing where prose says "a" or "two"."""
    w = words[k]
    if re.fullmatch(r"\d+x?|x\d+", w):
        return True
    return w in _TIMES and (k > 0 and words[k - 1].isdigit() or k + 1 < len(words) and words[k + 1].isdigit())


#: how many words a verbless statement's subject may carry before its name that the names do not
#: cover: a possessor and a modifier ("Biscuit's water bowl, on the floor by the door")
_PREMODIFIERS = 2


def _premodifiers(words: list[str], start: int, first: int) -> set[int]:
    """The tokens between a verbless clause's start and its first subject's name that only modify
    that name: after an article, or opening the sentence or a labelled item ("Item 3 - Biscuit's
    water bowl, on the floor": the possessive's "'s" is gone from the words), at most
    `_PREMODIFIERS` words that are nouns and no verb of place ("water" of "the water bowl"), all
    of them, or none. A clause opened by a verb ("fill Biscuit's bowl, on the floor") is no noun
    phrase."""
    if first <= start:
        return set()
    article = words[start] in ARTICLES
    opens = start == 0 or words[start - 1] in _LABEL_MARKS
    if not article and not (opens and not verb_form(words[start])):
        return set()
    loose = list(range(start + 1 if article else start, first))
    if len(loose) > _PREMODIFIERS or any(not words[k].isalpha() or words[k] in VERBS
                                         or "NOUN" not in getAllLemmas(words[k]) for k in loose):
        return set()
    return set(range(start, first))


#: the marks after a label in a record, a list or a form ("Torch: on the bench", "Keys - in the drawer")
_LABEL_MARKS = frozenset({":", "-"})  # (an en or em dash is read as "-": `_DASHES`)
#: what closes a document's label before a heading's place ("Contents, counter: ...", "Room 12 -
#: Nightstand: ...")
_HEADING_LABEL_MARKS = frozenset({","}) | _LABEL_MARKS - {":"}
#: what ends the stretch before a label
_LABEL_STOPS = frozenset({".", ";", ",", "(", ")", "\n", "?"}) | _LABEL_MARKS


def _label(sent: _Sentence, start: int) -> tuple[int, list[Mention]]:
    """(where the label starts, its things) when the clause at `start` follows a label and its
    mark, the record's or list's way of saying a thing's place ("Torch: on the bench by the
    window", "- Keys - in the key bowl", "Laptop: on the desk, charging"): the label is the
    stretch before the mark back to the sentence's start or a stop; (start, []) when there is none."""
    words = sent.words
    if start == 0 or words[start - 1] not in _LABEL_MARKS:
        return start, []
    lo = start - 1
    while lo > 0 and words[lo - 1] not in _LABEL_STOPS:
        lo -= 1
    things = [m for m in sent.mentions if lo <= m.start and m.end < start and m.kind == "role"]
    if things and _possessor(words, lo, things[0].start):
        lo += 1  # "Sam's jacket: in the wardrobe"
    return lo, things


def _possessor(words: list[str], k: int, first: int) -> bool:
    """Whether the word at `k`, right before the first thing of a list opening at `first`, is a
    possessor whose "'s" the text normalising dropped ("Sam's jacket" read "sam jacket")."""
    return first == k + 1 and words[k].isalpha() and words[k] not in _NO_AGENT


#: words before a noun that quantify it, no possessor ("every mug left on the counter gets in the way")
QUANTIFIERS = frozenset({"every", "each", "any", "all", "no", "most", "many", "few", "several", "some"})


def _named_possessor(words: list[str], lo: int, start: int) -> bool:
    """Whether the thing at `start` opens its clause after a possessor whose "'s" was dropped ("Sam's
    mug left on the counter needs a wipe", read "sam mug ..."): a definite noun phrase, as "the mug"
    and "my mug" are, which takes the reduced relative's place for granted; not a quantifier, a
    colour or a state ("every mug left ...", "dirty mug left ...")."""
    k = start - 1
    return k == lo and _possessor(words, k, start) and words[k] not in QUANTIFIERS \
        and words[k] not in COLOR_WORDS and words[k] not in STATE_WORDS


def _pronoun_holder(sent: _Sentence, clause: Span, j: int, lex: Lexicon,
                    reading: _Reading) -> tuple[str, Mention] | None:
    """(preposition, place) for "on it" / "in it" after a verb of resting: "a nightstand (the lamp
    stands on it)", "There is a shelf by the door. The keys lie on it.": the nearest thing before
    the clause that can hold things (in its sentence, else the last statement's subject)."""
    words = sent.words
    if j + 1 >= clause.end or words[j] not in AT or words[j + 1] != "it":
        return None
    before = [m for m in sent.mentions if m.end <= clause.start and m.kind == "role"]
    for m in (*reversed(before), reading.last_subject):
        if m is not None and m.kind == "role" and len(m.roles) == 1 and m.roles[0] in lex.holders:
            return words[j], Mention(m.roles, j + 1, j + 2, m.kind)  # where "it" stands
    return None


def _place_back(sent: _Sentence, before: int) -> tuple[str, Mention] | None:
    """("in", room) for a statement ending in "there": "Back of house is the kitchen, straight
    through from the dining room: the sink, a cabinet and the bin are all back there", "The
    garage is behind the hallway; the bike and the mower are out there": the nearest room named
    before the statement's subject in its sentence, but one named as a source ("from the dining
    room")."""
    for m in reversed([m for m in sent.mentions if m.end <= before and m.kind == "room"]):
        if _prep_before(sent.words, m.start) not in SOURCE:
            return "in", m
    return None


def _resting_participle(group: list[str]) -> bool:
    """A bare participle of resting or covering ("sitting", "lying up there", "spread")."""
    verbs = [w for w in group if w not in ADVERBS]
    return len(verbs) == 1 and (verbs[0] in STATIVE and verbs[0].endswith("ing") or verbs[0] in COVERING)


def _result_participle(group: list[str]) -> bool:
    """A bare participle of a result (`RESULT`: "left", "kept", "tucked", "placed", "dropped"),
    after a verbless noun phrase and a comma (the nineteenth session): "The mug, left on the
    counter by Sam.", "My scarf, tucked in the basket, is still damp", a museum label's "the
    candle, placed on the dresser by the maid" say the thing is there, as "sitting" does after a
    comma (an "it" after "put" is an instruction's object, and no place follows the verb)."""
    verbs = [w for w in group if w not in ADVERBS]
    return len(verbs) == 1 and verbs[0] in RESULT


def _headed_participle(sent: _Sentence, ms: list[Mention], group: list[str], end: int, reading: _Reading) -> bool:
    """Whether a sentence that opens with a bare participle of a result or of resting and names
    no subject ("Left on the desk, next to the scales, as ever.", "Kept in the nightstand, like
    always.", "Sitting on the stove, as usual.") speaks of the one thing a verbless heading just
    before it named ("b) My cup.", "Item 4: Umbrella.", "- Kettle."): the terse register of
    context sheets, handover notes and logs, which name a thing once as the item's heading and
    then say where it is with the subject left out, as "My jacket. I left it on the sofa" leaves
    it to "it" (`_object_it`). Only when the heading has no verb of its own (a statement before
    it may be of another matter), its subject is one thing, and after the place nothing says the
    participle is a condition, a question or the modifier of another clause's subject ("My cup.
    If left on the desk, ...", "Left on the desk?", "Left on the desk overnight, coffee goes
    mouldy"). Presumed, as a headline's report is (`_headline`): a later condition may ask it."""
    last, heading = reading.last_subject, reading.last_subject_sent
    if last is None or heading is None or heading is sent or last.kind != "role" or len(last.roles) != 1:
        return False
    if not (_result_participle(group) or _resting_participle(group)) or any(
            w in VERBS | BE | PERFECT | STATIVE | RESULT | KEEP_VERBS for w in heading.words):
        return False
    found = _holder_after(sent, ms, end, len(sent.words))
    return found is not None and not any(
        w in VERBS or w in CONDITION_CUES or w == "?" for w in sent.words[found[1].end:])


def _adjunct_subject(sent: _Sentence, ms: list[Mention], lo: int, comma: int) -> list[Mention]:
    """The subject of a participle set off by a comma after a finished clause (a free adjunct: "The
    telly's been on since kick-off, sitting up there on the TV stand", "The kettle is still warm,
    standing on the hob"): English gives it the clause's subject, the noun-phrase list before the
    clause's first finite verb; a verbless noun-phrase list is the subject itself; none when the
    clause has neither."""
    words = sent.words
    for f in range(lo, comma):
        if words[f] in BE | PERFECT or words[f] in STATIVE and _finite([words[f]]):
            return _np_list(sent, ms, lo, f) if f > lo and words[f - 1] not in PLACE_PRONOUNS else []
    # no verb: a list's item, a noun phrase alone before the comma ("1 wicker basket, sitting on
    # the ironing board", "A spare towel, lying on the shelf"): the item is where it rests, as a
    # verbless "Bath mat on the floor" is (`_fragment`)
    subjects = _np_list(sent, ms, lo, comma)
    covered = {k for m in subjects for k in range(m.start, m.end)}
    for m in subjects:  # "your trusty water bottle, lying on ...": a plain adjective after the determiner
        k = m.start - 1
        while k >= lo and words[k].isalpha() and words[k] not in VERBS | AT | LIST_GLUE and not verb_form(words[k]) \
                and m.start - k <= 2:
            k -= 1
        if lo <= k < m.start - 1 and words[k] in ARTICLES:
            covered |= set(range(k + 1, m.start))
    if subjects and all(k in covered or w in LIST_GLUE or w in COLOR_WORDS or w in STATE_WORDS or w.isdigit()
                        for k, w in enumerate(words[lo:comma], lo)):
        return subjects
    return []


def _named_word(ms: list[Mention], k: int) -> bool:
    """Whether token `k` is a word of a thing's name (a mention), not a word of the clause's own."""
    return any(m.start <= k < m.end for m in ms)


#: the speakers whose own past act of putting says where a thing is now ("I put the basket on the
#: dresser", "we set the box on the stool"); "you put ..." is as often an instruction or a
#: generic "you" ("you put the mug on the rack"), so it is no report
_REPORTERS = frozenset({"i", "we"})


def _reported(subject: str, group: list[str], lead: list[str]) -> bool:
    """Whether a first-person subject and a lone verb of result ("I put", "we set", "I placed",
    `RESULT`) report where the speaker left a thing: a past act, read as a statement of place
    (`_verb_kind`: an active past), presumed only, so that a later condition ("I left her
    blanket on the floor. If it is still on the floor, ...") asks it again. Not when the words
    before the subject doubt it ("Maybe I left one on the table": the task's question)."""
    return subject in _REPORTERS and (len(group) == 1 and group[0] in RESULT or _active_perfect(group)) \
        and not doubts(lead)


#: words that never stand in a person's name before a verb of result (`_agent`)
_NO_AGENT = VERBS | NORMATIVE | AT | SOURCE | NEGATIONS | SUBORDINATORS | DOUBT | ARTICLES | RELATIVE \
    | THING_PRONOUNS | PLACE_PRONOUNS | frozenset({"please", "then", "and", "or", "but", "so", "if"})


def _agent(sent: _Sentence, ms: list[Mention], lo: int, who: int) -> bool:
    """Whether words [lo, who] are the subject of an active verb of result that is no thing of
    the task: a personal pronoun ("someone left ...", `SUBJECT_PRONOUNS`) or a person's name or
    title of one or two words naming no role ("Tom left my mug on the counter", "Mum had put the
    towels in the basket", "the cleaner left the wallet on ..."): its object is the thing placed."""
    if sent.words[who] in SUBJECT_PRONOUNS:
        return True
    span = sent.words[lo:who + 1]
    if span[:1] and span[0] in DEFINITE_OPENERS:
        span = span[1:]  # "the cleaner", "my sister": a person's title
    return 1 <= len(span) <= 2 and not any(lo <= m.start <= who for m in ms) \
        and all(w.isalpha() and w not in _NO_AGENT for w in span)


def _finite(group: list[str]) -> bool:
    """A verb group with a finite verb ("is lying", "lies", "has been left", "are kept"), not a
    bare participle ("lying", "left", "found") that modifies the noun before it."""
    verbs = [w for w in group if w not in ADVERBS and w not in DOUBT]
    return bool(set(verbs) & (BE | PERFECT | GET_PASSIVE)) or any(
        (w in STATIVE or w in KEEP_VERBS) and not w.endswith(("ing", "ed")) and w not in RESULT for w in verbs)


def _definite(words: list[str], start: int) -> bool:
    """A noun phrase opened by "the" or a possessive ("the keys", "my phone")."""
    j = start - 1
    while j >= 0 and (words[j] in COLOR_WORDS or words[j] in STATE_WORDS):
        j -= 1
    return j >= 0 and (words[j] in DEFINITE_OPENERS or words[j] == "its")


#: prepositions whose noun completes the noun before it (what it is for, what it holds): a
#: relative clause after the phrase speaks of the head noun (`_antecedent`)
COMPLEMENT_PREPOSITIONS = frozenset({"for", "of"})


def _antecedent(sent: _Sentence, clause: Span) -> Mention | None:
    """The noun a relative clause ("..., which stands on the floor") speaks of: the last mention
    before it in its sentence, or the head of the noun phrase that mention completes ("the
    wicker basket for journals, which stands on the floor", "the jar of buttons, which sits on
    the shelf": the basket, the jar; `COMPLEMENT_PREPOSITIONS`)."""
    before = [m for m in sent.mentions if m.end <= clause.start and m.kind == "role"]
    if len(before) >= 2:
        words, head, last = sent.words, before[-2], before[-1]
        between = [w for w in words[head.end:last.start] if w not in ARTICLES]
        if between and between[0] in COMPLEMENT_PREPOSITIONS and len(between) == 1:
            return head
    return before[-1] if before else None


def _gapped(sent: _Sentence, clause: Span, ms: list[Mention], after: int, kind: str, lex: Lexicon,
            catalog: Catalog, reading: _Reading) -> int:
    """", a sofa and a coffee table in the living room, and the front door at the end of the
    hallway": a list and a place after the place of a locative clause, its verb left out."""
    words = sent.words
    i = after
    while i < clause.end:
        if words[i] != ",":
            i += 1
            continue
        j = i + 1
        while j < clause.end and words[j] not in AT and words[j] != ",":
            j += 1
        found = _holder_after(sent, ms, j, clause.end)
        subjects = _np_list(sent, ms, i + 1, j)
        if found is not None and subjects and all(w in LIST_GLUE or w in COLOR_WORDS
                                                  or _named_word(subjects, k)
                                                  for k, w in enumerate(words[i + 1:j], i + 1)):
            for m in subjects:
                for role in _roles(m, sent):
                    _put(reading, kind, catalog, lex, role, found[1], found[0])
            i = found[1].end
            after = i
        else:
            i = j
    return after


#: words that may open a clause before its fronted place, its commas included (`FRONT_LEADS`)
_FRONT_LEADS = FRONT_LEADS | {","}
#: determiners that open an epithet after a colon ("the blanket: his nest"), which says whose the
#: thing is or what it is to someone, never where it goes
_EPITHET = frozenset({"his", "her", "their", "its", "my", "our", "your"})


def _inverted(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
              reading: _Reading) -> None:
    """Locative inversion, the place put first and the thing after it: "On the utility shelf lies the
    flashlight", "In the fridge are the milk and the eggs" (a finite verb of being, resting or
    keeping between them), and a fronted participle of resting or covering with its place, the thing
    after a comma: "Draped across the sofa, the blanket", "Lying on the doormat, the newspaper". The
    thing must follow at once (articles and adjectives only) and, after a participle, end the clause;
    `_locative` reads the subject before its verb and so found none here."""
    words = sent.words
    j = clause.start
    while j < clause.end and words[j] in _FRONT_LEADS:
        j += 1
    participle = j + 1 < clause.end and _resting_participle([words[j]])
    found = _holder_after(sent, ms, j + 1 if participle else j, clause.end)
    if found is None:
        return
    prep, holder = found
    k = holder.end
    kind = "settled"
    if participle:
        if k >= clause.end or words[k] != ",":
            return
        k += 1
    else:
        end, group = _verb_group(words, k, clause.end)
        said = _verb_kind(group) if end > k and _finite(group) else None
        if said is None:
            return
        kind, k = said, end
    stop = next((n for n in range(k, clause.end) if words[n] == ","), clause.end)
    subjects = _np_list(sent, ms, k, stop)
    if not subjects or doubts(words[clause.start:stop]) or habitual(words[clause.start:stop]):
        return
    covered = {n for m in subjects for n in range(m.start, m.end)}
    tail = stop if participle else subjects[0].start
    # (an adjective with its article left out, as learners' English does: "On piano is standing
    # small lamp")
    if not all(n in covered or w in LIST_GLUE or w in COLOR_WORDS or w in STATE_WORDS
               or n + 1 == tail and "ADJ" in getAllLemmas(w) for n, w in enumerate(words[k:tail], k)):
        return  # "On the shelf lies a note about the torch": the thing is not what follows the verb
    if kind == "settled" and set(words[holder.end:subjects[0].start]) & NORM_ADVERBS:
        kind = "kept"  # "On the stove usually sits the old pot": where it belongs, as `_locative` reads it
    for m in subjects:
        for role in _roles(m, sent):
            _put(reading, kind, catalog, lex, role, holder, prep)


def _epithet_heading(sent: _Sentence, clause: Span) -> bool:
    """Whether a verbless part before a colon (a heading, which the clause cut reads as the situation
    its instruction answers) is instead answered by an epithet, a noun phrase opened by a possessive
    and naming no thing or place ("And here, draped across the sofa, the blanket: his nest"): then
    nothing is asked and the part states what it describes."""
    words = sent.words
    if clause.mood != "condition" or clause.end >= len(words) or words[clause.end] != ":" \
            or next((w for w in words[clause.start:clause.end] if w not in _FRONT_LEADS), "") in SUBORDINATORS:
        return False
    rest = words[clause.end + 1:]
    stop = next((n for n, w in enumerate(rest) if w in PUNCT), len(rest))
    body = rest[:stop]
    return bool(body) and body[0] in _EPITHET and not any(
        clause.end < m.start for m in sent.mentions) and all(
        w.isalpha() and w not in VERBS and w not in AT and w not in IMPERATIVES for w in body)


def _possessive(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
                reading: _Reading) -> None:
    """"The kitchen, next door to the dining room, has the dishwasher, the sink ...", "It contains a
    bed, a wardrobe ...", "The basket also holds a box of cereal", "The pantry has two shelves":
    the clause's subject (its first noun not after a preposition; "it" for the room or thing last
    spoken of) holds the list after the verb."""
    words = sent.words
    lo = clause.start
    for i in range(clause.start, clause.end):
        if i < lo or words[i] not in HAVE_VERBS or words[i + 1: i + 2] == ["been"] or words[i + 1: i + 2] == ["to"]:
            continue
        if set(words[max(lo, i - 1):i + 2]) & NEGATIONS:
            return  # "the shelf has no book on it", "has not got", "does not have": it holds none
        lo = _joined_clause(words, ms, lo, i)
        before = _np_list(sent, [m for m in ms if m.kind in ("role", "room")], lo, i)
        owner: Mention | None = before[0] if before else None
        if owner is None and set(words[lo:i]) & THING_PRONOUNS:
            owner = reading.last_subject
        if owner is None or owner.kind == "role" and len(owner.roles) != 1:
            return
        if before and before[0].start > lo and words[before[0].start - 1] in ("we", "i", "you"):
            return
        if before and not _modifies(words[owner.end:i]):
            return  # "the bookshelf's three levels hold ...": the subject is another noun
        stop = _next_owner(sent, ms, i + 1, clause.end)
        items = _np_list(sent, ms, i + 1, stop)
        prep = _taken_up(words, items[-1].end, stop) if items else "in"
        for m in items:
            if _generic(sent, m):
                continue  # "hold novels, essays and other books": kinds, not things
            for role in _roles(m, sent):
                if role != owner.roles[0]:
                    _put(reading, "settled", catalog, lex, role, owner, prep)
        if stop == clause.end:
            return
        lo = stop


#: words that join a second clause to a first ("the hall is tiny but the bedroom has a bed")
_CLAUSE_JOINS = frozenset({"and", "but", "so", "while", "whereas"})


def _joined_clause(words: list[str], ms: list[Mention], lo: int, i: int) -> int:
    """Where the clause of the verb at i begins when a joining word (`_CLAUSE_JOINS`) after a verb
    of its own starts it: "your dining room opens onto the kitchen, and the kitchen has a sink"
    (the kitchen has it, not the dining room); "the kitchen and the pantry have a shelf" has no
    verb before its "and", so both are the subject. lo when none does."""
    named = {k for m in ms for k in range(m.start, m.end)}
    for c in range(i - 1, lo, -1):
        if words[c] in _CLAUSE_JOINS and any(
                k not in named and words[k].isalpha() and words[k] not in ARTICLES | AT and verb_form(words[k])
                for k in range(lo, c)):
            return c + 1
    return lo


def _taken_up(words: list[str], j: int, hi: int) -> str:
    """The preposition a possessive's place is said with: "on" when the list is followed by "on it"
    ("The dresser has the hair dryer on it": on the dresser, not in it), else "in" (what a thing
    has, it holds)."""
    if j + 1 < hi and words[j] in FALLBACK_AT and words[j + 1] in RESUMPTIVE | {"them"}:
        return FALLBACK_AT[words[j]]
    return "in"


def _next_owner(sent: _Sentence, ms: list[Mention], lo: int, hi: int) -> int:
    """Where the list after a possessive verb ends: at a comma or "and" before another subject
    and its own possessive verb ("the kitchen holds the bin and the fridge, the living room has a
    sofa"); `hi` when none follows."""
    words = sent.words
    for m in ms:
        if m.start < lo or m.kind not in ("room", "role"):
            continue
        j = m.end
        while j < hi and words[j] in ADVERBS:
            j += 1
        k = m.start - 1
        while k >= lo and words[k] in ARTICLES:
            k -= 1
        if j < hi and words[j] in HAVE_VERBS and k >= lo and words[k] in (",", "and", ";"):
            return k
    return hi


#: words that open a modifier after a noun ("the pantry next to the kitchen", "the kitchen, …, has")
MODIFIER_OPENERS = frozenset({",", "next", "near", "beside", "behind", "by", "opposite", "off", "through",
                              "just", "right"}) | AT | PREP_IN | PREP_ON


def _modifies(gap: list[str]) -> bool:
    """Whether the words between a noun and its verb only modify the noun: none, adverbs, an
    apposition between commas, or a prepositional phrase; not a head noun of their own."""
    rest = [w for w in gap if w not in ADVERBS]
    return not rest or rest[0] in MODIFIER_OPENERS


def _generic(sent: _Sentence, m: Mention) -> bool:
    """A bare plural ("novels", "other books"): a kind of thing, not the things of the scene; a
    counted plural ("2 mugs", "3 x mugs") is the scene's, as "two mugs" is."""
    last = sent.toks[m.end - 1]
    j = m.start - 1
    while j >= 0 and (sent.words[j] in COLOR_WORDS or sent.words[j] in STATE_WORDS or sent.words[j] in ("other",)):
        j -= 1
    return last.word != last.lemma and not (j >= 0 and (sent.words[j] in ARTICLES or _quantity(sent.words, j)))


def _existential(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
                 reading: _Reading) -> None:
    """"There is a dirty mark on the floor", "There are a pan and a pot on the stove": the listed
    objects are at the place that ends the list."""
    words = sent.words
    for i in range(clause.start, clause.end - 1):
        if words[i] != "there" or words[i + 1] not in BE:
            continue
        j = i + 2
        while j < clause.end and words[j] not in AT and not _covers(words, j):
            j += 1
        found = _holder_after(sent, ms, j, clause.end)
        if found is None:
            return
        for m in _np_list(sent, ms, i + 2, j):
            for role in _roles(m, sent):
                _put(reading, "settled", catalog, lex, role, found[1], found[0])
        return


#: verbs of finding and seeing whose object is then at the place after it ("you will find the keys
#: in the drawer", "I saw a mug sitting on the desk"), and the words that make them a statement of
#: what is there: a subject "you"/"I"/"we" with "will"/"can" or a past form
PERCEIVING = frozenset({"find", "see", "spot", "notice", "saw", "spotted", "noticed", "found"})
_PERCEIVED_PAST = frozenset({"saw", "spotted", "noticed", "found"})
_PERCEIVERS = frozenset({"you", "i", "we"})


def _perceived(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
               reading: _Reading) -> None:
    """"You will find my mug on the counter", "you can see a mug lying on the desk", "I spotted the
    towel in the basket": what a perceiver finds or sees is at the place after it, a resting
    participle between ("lying", "sitting") or not; an object "it" is the thing last spoken of
    (`_object_it`). Presumed, as a speaker's report is
    (`_reported`): a later condition may ask it again. Not "you might find" (a doubt: the clause
    is doubted), not "if you see" (a condition: not a statement), not "find the mug" (an
    instruction, no perceiver)."""
    words = sent.words
    for i in range(clause.start + 1, clause.end):
        if words[i] not in PERCEIVING:
            continue
        if words[i] in _PERCEIVED_PAST:
            ok = words[i - 1] in _PERCEIVERS
        else:
            ok = words[i - 1] in ("will", "can") and i - 2 >= clause.start and words[i - 2] in _PERCEIVERS
        if not ok:
            continue
        j = i + 1
        while j < clause.end and words[j] not in AT:
            j += 1
        k = j - 1
        while k > i and (words[k] in STATIVE or words[k] in RESULT or words[k] in ADVERBS):
            k -= 1  # "lying", "left", "still sitting": the object's participle, before the place
        found = _holder_after(sent, ms, j, clause.end)
        if found is None:
            continue
        objects = _np_list(sent, ms, i + 1, k + 1)
        if not objects and words[i + 1:k + 1] == ["it"]:  # "The mug? You will find it on the counter."
            earlier = any(m.end <= clause.start and m.kind == "role" for m in sent.mentions)
            objects = _object_it(sent, clause, reading.last_subject, earlier)
        for m in objects:
            for role in _roles(m, sent):
                _put(reading, "presumed", catalog, lex, role, found[1], found[0])


def _where(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
           reading: _Reading, *, homes_only: bool = False) -> None:
    """"the kitchen, where the dishwasher, the sink ... are", "a nightstand on which a lamp
    stands", "that's where the dishwasher ... are", "it's where the flashlight lives", "the
    vanity, where the spares are kept": the list of the relative clause is at its antecedent (the
    noun before it, or what "that"/"it" points back to); a keeping verb makes it a home."""
    words = sent.words
    for i in range(clause.start, clause.end):
        rel = words[i] == "where" or (words[i] in RELATIVE and i > 0 and words[i - 1] in AT)
        if not rel:
            continue
        lead = i - 1 if words[i] in RELATIVE else i  # "on which": the preposition
        prep = words[lead] if words[i] in RELATIVE else "in"
        before = [m for m in sent.mentions if m.end <= lead and m.kind in ("role", "room")]
        antecedent: Mention | None = None
        gap = words[before[-1].end:lead] if before else []
        if before and _noun_tail(gap):
            antecedent = before[-1]
        elif set(words[max(clause.start, lead - 3):lead]) & THING_PRONOUNS:
            pronoun = next(w for w in words[max(clause.start, lead - 3):lead] if w in THING_PRONOUNS)
            antecedent = _pointed(sent, clause, lex, catalog, reading, pronoun)
        if antecedent is None or antecedent.kind == "role" and len(antecedent.roles) != 1:
            continue
        stop = next((k for k in range(i + 1, clause.end) if words[k] in (",",) and k + 1 < clause.end
                     and words[k + 1] in IMPERATIVES), clause.end)
        if doubts(words[i + 1:stop]) or not set(words[i + 1:stop]) & (BE | STATIVE | KEEP_VERBS):
            continue  # "where a pan may be"; "where a dirty mug goes" (a goal)
        kind = "kept" if set(words[i + 1:stop]) & KEEP_VERBS else "settled"
        if homes_only and kind != "kept":
            continue
        items = _np_list(sent, ms, i + 1, stop)
        for m in items:
            for role in _roles(m, sent):
                if role != antecedent.roles[0]:
                    _put(reading, kind, catalog, lex, role, antecedent, prep)
        if not items and kind == "kept":
            item = _unnamed_item(sent, lex, i + 1, stop, exclude=antecedent.roles[0])
            if item is not None:
                _put(reading, kind, catalog, lex, item, antecedent, prep)
        return


def _noun_tail(gap: list[str]) -> bool:
    """Words between a mention and its relative pronoun that still end its noun phrase: a comma,
    or a word or two of a longer name than the one matched ("the vanity cabinet, where ...")."""
    tail = gap[:-1] if gap[-1:] == [","] else gap
    return len(tail) <= 2 and not set(tail) & (BE | PERFECT | STATIVE | RESULT | KEEP_VERBS | AT | ARTICLES
                                                | PUNCT | DOUBT | SUBORDINATORS | THING_PRONOUNS)


def _pointed(sent: _Sentence, clause: Span, lex: Lexicon, catalog: Catalog, reading: _Reading,
             pronoun: str) -> Mention | None:
    """What the pronoun of "it's where ..." / "that's where ..." points back to, the first of these
    that can hold things (a room, a surface or a container): for "it", the subject of the last
    statement, then the nearest noun before it; for "that" / "this", the nearest noun, unless it
    is named as a source ("through from the dining room"): then that subject first."""
    near = [m for m in sent.mentions if m.end <= clause.start and m.kind in ("role", "room")]
    nearest = near[-1] if near else None
    source = nearest is not None and _prep_before(sent.words, nearest.start) in SOURCE
    first_subject = pronoun == "it" or source
    order = (reading.last_subject, nearest) if first_subject else (nearest, reading.last_subject)
    for m in (*order, reading.last_holder):
        if m is None or m.kind == "floor":
            continue
        if m.kind == "room" or len(m.roles) == 1 and m.roles[0] in lex.holders:
            return m
    return None


def _unnamed_item(sent: _Sentence, lex: Lexicon, lo: int, hi: int, exclude: str) -> str | None:
    """The role a noun no name matches stands for ("the spares" for the spare roll): a word of
    exactly one role's name."""
    for t in sent.toks[lo:hi]:
        if t.lemma in ARTICLES or t.lemma in PUNCT or len(t.lemma) < 3:
            continue
        owners = [r for r in lex.roles if r != exclude and t.lemma in r.split("_")]
        if len(owners) == 1:
            return owners[0]
    return None


def _kept(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
          reading: _Reading) -> None:
    """"it's kept in the vanity", "we store the spares in the vanity cabinet", "the cloth lives in
    the vanity", "(spares are kept there)": the object (named after the verb, else the clause's
    subject, else what "it" points back to) has its home at the place after the preposition (or
    at the place last named, for "there")."""
    words = sent.words
    for i in range(clause.start, clause.end):
        if words[i] not in KEEP_VERBS and not _provided(words, i, clause):
            continue
        if clause.mood == "instruction" and words[clause.start:i + 1][-1] == words[clause.start]:
            return  # "keep the door shut": an instruction
        j = i + 1
        while j < clause.end and words[j] not in AT | PLACE_PRONOUNS:
            j += 1
        if j >= clause.end:
            return
        holder: Mention | None
        prep = "in"
        if words[j] in PLACE_PRONOUNS:
            holder = reading.last_holder
        else:
            found = _holder_after(sent, ms, j, clause.end)
            if found is None:
                return
            prep, holder = found
        if holder is None or holder.kind == "role" and len(holder.roles) != 1:
            return
        named = [r for m in _np_list(sent, ms, i + 1, j) for r in _roles(m, sent)]
        subject = [r for m in _np_list(sent, ms, clause.start, i) for r in _roles(m, sent)]
        if holder.roles[0] in named + subject:
            # "Developer kept in the brown bottle on the lower shelf": the thing's own vessel (a
            # word naming the thing itself) is passed through to the place after it
            nxt = next((n for n in range(holder.end, clause.end) if words[n] in AT), None)
            found = _holder_after(sent, ms, nxt, clause.end) if nxt is not None else None
            if found is None:
                return
            prep, holder = found
        rel = i - 1
        while rel > clause.start and (words[rel] in BE or words[rel] in ADVERBS):
            rel -= 1
        if words[rel] in RELATIVE:
            # "into the basket which is kept on the shelf": the relative clause's subject is the
            # thing right before it, not the instruction's object
            subject = [r for m in ms if m.end == rel for r in _roles(m, sent)]
        items = named or subject
        if not items:
            unnamed = _unnamed_item(sent, lex, clause.start, j, exclude=holder.roles[0])
            if unnamed is not None:
                items = [unnamed]
        if not items and set(words[clause.start:j]) & THING_PRONOUNS:
            back = [m for m in sent.mentions if m.end <= clause.start and m.kind == "role"
                    and len(m.roles) == 1 and m.roles[0] != holder.roles[0]]
            if back:
                items = [back[-1].roles[0]]
            elif reading.last_subject is not None and reading.last_subject.kind == "role":
                items = list(_roles(reading.last_subject, reading.last_subject_sent or sent)
                             or reading.last_subject.roles[:1])
        for role in items:
            if role in lex.roles and role != holder.roles[0]:
                _put(reading, "kept", catalog, lex, role, holder, prep)
        return


#: verbs of letting a thing stay whose present said by the writer of their own doing is a
#: provision, where the thing is kept for the reader (the twenty-first session): "I leave a towel
#: on the chair for drying your hands", "We leave a spare blanket in the wardrobe", as "we keep
#: ..." is (`_provided`)
PROVIDING = frozenset({"leave"})


def _provided(words: list[str], i: int, clause: Span) -> bool:
    """Whether the verb at `i` is a writer's provision: a verb of `PROVIDING` in its plain present
    ("leave", not "left", a past report read as such; not "leaves", a third person's habit, which
    says where a thing tends to go, `_habitually_put`), whose subject "I" or "we" opens its
    statement, with at most adverbs of a norm or manner between ("I always leave", "we leave";
    the learner's "I leave always" too). A frequency ("Sometimes I leave the mug on the desk"), a
    negation, a modal ("I'll leave", "I will leave"), a question's auxiliary ("Do I leave") or a
    condition ("If I leave") leaves the place open: those are no clause opened by the subject, or
    no statement."""
    if clause.mood != "statement" or words[i] not in PROVIDING \
            or words[i] not in getAllLemmas(words[i]).get("VERB", ()):
        return False
    k = i - 1
    while k >= clause.start and words[k] in ADVERBS | NORM_ADVERBS and words[k] not in FREQUENCY:
        k -= 1
    return k >= clause.start and words[k] in ("i", "we") and all(w in _LEADS for w in words[clause.start:k]) \
        and "?" not in words[clause.end:clause.end + 1]


def _with(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
          reading: _Reading, kind: str = "settled") -> None:
    """"a nightstand with a lamp", "the nightstand with a lamp on it", "nightstand with lamp": a
    carried thing on (or in) the piece it is said to come with (not "a table with a mop leaning
    against it", which says where the mop stands; not "wipe it with the sponge", an instrument).
    In an instruction (`kind` "presumed": "dust the shelf with the vase on it", "look in the
    drawer with my socks in it") only the phrase that ends "on it"/"in it" places: a bare "with"
    there names an instrument ("wipe the counter with a cloth")."""
    words = sent.words
    for a in ms:
        # (a room "with" in an instruction says what is carried there: "go to the kitchen with the mug")
        if kind == "settled" and a.kind == "room" and a.end < clause.end and words[a.end] == "with":
            stop = next((m.start for m in ms if m.start > a.end and m.kind == "room"), clause.end)
            for m in _np_list(sent, ms, a.end + 1, stop):
                for role in _roles(m, sent):
                    reading.room("settled", role, a.roles[0])
    for a, b in zip(ms, ms[1:], strict=False):
        if a.kind != "role" or b.kind != "role" or len(a.roles) != 1 or len(b.roles) != 1:
            continue
        between = words[a.end:b.start]
        tied = words[b.end:b.end + 2] in (["on", "it"], ["in", "it"])
        if not between or between[0] != "with" or not _determined(between[1:], tied):
            continue
        cat = catalog.get(str(lex.roles[b.roles[0]]["category"]))
        if cat is None or not cat.pickable:
            continue
        after = words[b.end:b.end + 2]
        if b.end < clause.end and not (tied or words[b.end] in PUNCT | {"and"}) or kind != "settled" and not tied:
            continue
        if b.end < len(words) and words[b.end] in STATIVE | {"leaning", "propped"}:
            continue
        fact = _contain(catalog, lex, b.roles[0], a.roles[0], "in" if after == ["in", "it"] else "on")
        if fact is not None:
            reading.place(kind, b.roles[0], fact)


def _determined(words: list[str], tied: bool) -> bool:
    """Words that may open a noun phrase after "with": articles, and where "on it"/"in it" ties
    the thing to the holder (`tied`) one more word, a possessor whose "'s" the text normalising
    dropped ("with Sam's mug on it") or an adjective ("with dirty socks in it"); never a negation
    ("with no mug on it"), a verb or a preposition. Untied, "the vanity with the other spares"
    says what else is there, not that this thing is."""
    extra = [w for w in words if w not in ARTICLES]
    return not extra or tied and len(extra) == 1 and extra[0].isalpha() \
        and extra[0] not in VERBS | AT | NEGATIONS | SOURCE | {"other", "same"}


def _in_room(sent: _Sentence, clause: Span, ms: list[Mention], reading: _Reading) -> None:
    """"the drying rack out on the balcony", "the table lamp in the bedroom", "the nearest sink is
    in the kitchen": a definite object named right before "in/on <room>" (a noun modifier),
    unless an instruction moves it there ("put the mug in the kitchen") or it is only possibly
    there ("if there is a pan in the kitchen")."""
    words = sent.words
    for a, b in zip(ms, ms[1:], strict=False):
        if a.kind != "role" or b.kind != "room" or len(a.roles) != 1:
            continue
        between = [w for w in words[a.end:b.start] if w != "the"]
        if not between or between[-1] not in AT or not all(w in BE | ADVERBS for w in between[:-1]):
            continue
        if _moved(words, a.start, clause) or _indefinite_doubt(sent, a) or _room_asked(words, clause, a.start, b.end):
            continue
        if determiner(words, a.start) in NEGATIONS:
            continue  # "No pan in the kitchen?", "no towel in the bathroom": the thing is denied there
        if clause.mood == "condition" and set(between) & BE:
            continue  # "If the book is in the bedroom, bring it": the room is what the condition asks
        if clause.doubted and clause.mood == "statement":
            continue  # "I believe I may have left my watch in the flat": a hedged place is open
        reading.room("settled", a.roles[0], b.roles[0])  # a noun phrase's own place, whatever the mood


def _room_asked(words: list[str], clause: Span, thing: int, after_room: int) -> bool:
    """"Is there a towel in the bathroom?", "Is the laptop in the study?", "Are the keys still in
    the hall?": a yes/no question (opening with a form of "be") whose room ends it asks whether the
    thing is in that room, which the factor reader reads; the room of a question that goes on to
    ask something else ("Is the lamp in the bedroom on?") still says which thing is meant. So does
    a question with no verb before its thing (the thing at word `thing`): a verbless one ("Book in
    the bedroom? If so, ...", "Pan in the kitchen? Then ...", "Any towels in the bathroom?", a
    checklist's "Mug in the study? -> ...") or one in a statement's order ("The book is in the
    bedroom?"), as a checklist, a note or a broadcast asks it."""
    lead = next((w for w in words[clause.start:after_room] if w not in LEAD_INS), "")
    verbless = all(w in LEAD_INS or w in ARTICLES or w in NEGATIONS or not w.isalnum()
                   for w in words[clause.start:thing])
    rest = words[after_room:clause.end + 1]
    return (lead in BE or verbless) and "?" in rest and all(
        w in ADVERBS or w in {"now", "right", "?"} for w in rest[:rest.index("?") + 1])


def _moved(words: list[str], start: int, clause: Span) -> bool:
    """The object at `start` follows an instruction verb ("put the clean mug ...") or its -ing
    form, the action named as a step ("the step comprises hanging the jacket on the hook",
    "finish by putting the mug in the sink")."""
    j = start - 1
    while j >= clause.start and (words[j] in ARTICLES or words[j] in STATE_WORDS or words[j] in COLOR_WORDS
                                 or re.fullmatch(r"[a-z]+(ed|est)", words[j])):
        j -= 1
    return j >= clause.start and (words[j] in ACTIONS or words[j].endswith("ing") and any(
        lemma in ACTIONS for lemma in getAllLemmas(words[j]).get("VERB", ())))


#: verbs of wanting and imagining that take a thing and a place as one complement (the
#: nineteenth session): "Sam wants the mug on the counter", "imagine the lamp on the desk", "I'd
#: prefer the rug in the hall" say where it should be or might be, not where it is (`_wished`)
WISHING = frozenset({"want", "wants", "wanted", "need", "needs", "needed", "imagine", "imagines", "imagined",
                     "picture", "pictures", "prefer", "prefers", "preferred", "envisage", "envision"})


def _wished(words: list[str], start: int, end: int, clause: Span) -> bool:
    """The object at `start`, with its place ending at `end`, follows a verb of wanting or
    imagining (`WISHING`): its place is a wish, no place the thing rests in. A state after the
    place ("Sam wants the mug on the counter washed") makes the place the thing's own, a definite
    noun phrase's, and the wish the state."""
    j = start - 1
    while j >= clause.start and (words[j] in ARTICLES or words[j] in STATE_WORDS or words[j] in COLOR_WORDS):
        j -= 1
    stated = end < clause.end and (words[end] in STATE_WORDS or re.fullmatch(r"[a-z]+ed", words[end]) is not None)
    return j >= clause.start and words[j] in WISHING and not stated


#: verbs of putting whose habitual present ("Tom leaves his keys in the bowl", "she always puts the
#: mug on the desk") says where a thing tends to go, not where it is (`_habitually_put`)
_PUTTING = frozenset({"leave", "put", "drop", "throw", "set", "place", "dump", "stick", "park", "stuff"})


def _habitually_put(words: list[str], start: int, clause: Span) -> bool:
    """The noun phrase at `start` is the object of a verb of putting in the habitual present (a
    third person's "-s" form, or a frequency or norm adverb before it: "my husband always puts the
    jacket on the sofa", "Tom leaves the wallet in the drawer", "they often throw a sock in
    there"): the place after it is where the habit takes it, which a later condition asks."""
    j = start - 1
    while j >= clause.start and (words[j] in ARTICLES or words[j] in STATE_WORDS or words[j] in COLOR_WORDS):
        j -= 1
    if j < clause.start or not set(getAllLemmas(words[j]).get("VERB", ())) & _PUTTING:
        return False
    present = words[j].endswith("s") and words[j] not in _PUTTING
    return present or j > clause.start and words[j - 1] in NORM_ADVERBS | FREQUENCY


def _unfound(words: list[str], start: int, clause: Span) -> bool:
    """The noun phrase at `start` is the object of a doubted or negated verb of finding or seeing
    (`PERCEIVING`: "you might find the mug on the desk", "you won't see the apple in the fridge"):
    the place after it is the verb's complement, which the doubt or negation leaves open, not a
    modifier that takes the place for granted."""
    j = start - 1
    while j >= clause.start and (words[j] in ARTICLES or words[j] in STATE_WORDS or words[j] in COLOR_WORDS):
        j -= 1
    if j < clause.start or words[j] not in PERCEIVING:
        return False
    return clause.doubted or bool(set(words[max(clause.start, j - 3):j]) & NEGATIONS)


def _resting(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
             reading: _Reading) -> None:
    """"check the towel on the drying rack", "if the mug on the coffee table is dirty": a definite
    carried thing named right before "on/in <holder>" is presumed to rest there, unless an
    instruction moves it ("hang the shirt on the rack") or the clause asks where it is ("is the
    mug on the table?", "if there is a mug on the table")."""
    words = sent.words
    for a, b in zip(ms, ms[1:], strict=False):
        if a.kind != "role" or b.kind != "role" or len(a.roles) != 1 or len(b.roles) != 1:
            continue
        between = words[a.end:b.start]
        part = a.end + 1
        while part < clause.end and (words[part] in ARTICLES or words[part] in RANKS):
            part += 1
        whole = _part_of(sent, ms, part, clause.end) if between[:1] in ([w] for w in AT) else None
        if whole is not None:
            b = whole  # "the brown bottle on the lower shelf of the metal rack": on the rack
        elif not between or between[0] not in AT or not all(w in ARTICLES or w in RANKS for w in between[1:]) \
                and _modified_holder(words, ms, part, clause.end) is not b:
            continue  # ("the basket on the enquiry desk", "on the heated rail": the head after a modifier)
        cat = catalog.get(str(lex.roles[a.roles[0]]["category"]))
        pointed = _pointed_out(words, a.start, clause)
        # "the work boots", "the garden hose": a noun modifier that is a verb's form too
        # (`_the_before`) still opens a definite phrase, which starts at the modifier
        start = a.start - (determiner(words, a.start) != "the" and _the_before(words, a.start))
        if cat is None or not cat.pickable or determiner(words, start) != "the" and not pointed:
            continue
        if _moved(words, start, clause) or clause.goal or _unfound(words, start, clause) \
                or _habitually_put(words, start, clause) or _wished(words, start, b.end, clause):
            continue
        described = clause.mood == "condition" and (_described_subject(words, a.start, b.end, clause) or pointed)
        if clause.mood == "condition" and not described:
            continue
        fact = _contain(catalog, lex, a.roles[0], b.roles[0], "in" if whole is not None else between[0])
        if fact is not None:  # a condition on its state takes its place for granted: a statement
            reading.place("settled" if described else "presumed", a.roles[0], fact)


def _taken_from(sent: _Sentence, clause: Span, ms: list[Mention], lex: Lexicon, catalog: Catalog,
                reading: _Reading) -> None:
    """"Take a spare fuse from the drawer", "grab a clean towel out of the cupboard": an
    instruction of taking (`TAKING_FROM`, its verb opening the clause) presupposes the thing is
    in or on its source, so the scene puts it there (`presumed`). Called only for a sentence with
    no condition and no doubt ("if there's one in the drawer, take it", "take one from the drawer
    if you can find one" leave it open)."""
    words = sent.words
    lead = clause.start
    while lead < clause.end and (words[lead] in LEAD_INS or words[lead] in (",", "just", "simply")):
        lead += 1
    if lead >= clause.end or words[lead] not in TAKING_FROM:
        return
    for a, b in zip(ms, ms[1:], strict=False):
        if a.kind != "role" or b.kind != "role" or len(a.roles) != 1 or len(b.roles) != 1:
            continue
        if not all(taken_word(w) for w in words[lead + 1:a.start]):
            continue  # the verb's own object only: "take the towel to the shelf from ..." is no source
        between = [w for w in words[a.end:b.start] if w not in ARTICLES]
        if between not in (["from"], ["out", "of"], ["off"]):
            continue
        cat = catalog.get(str(lex.roles[a.roles[0]]["category"]))
        if cat is None or not cat.pickable:
            continue
        fact = _contain(catalog, lex, a.roles[0], b.roles[0], "on" if between == ["off"] else "in")
        if fact is not None:
            reading.place("presumed", a.roles[0], fact)
        return


#: verbs of seeing that point a thing out to the listener ("see that bottle on the bench?")
PERCEIVE = frozenset({"see", "notice", "spot", "seen", "noticed", "spotted"})
#: the words a question that points a thing out may open with ("do you see", "can you spot")
_ASKED_SEEING = frozenset({"do", "did", "can", "you", "u", "ya", "see", "notice", "spot", "seen", "noticed",
                           "spotted", "have", "just"})


def _pointed_out(words: list[str], start: int, clause: Span) -> bool:
    """"see that water bottle on the bench?", "Do you see the mug on the desk?": a question that
    asks whether the listener sees a definite or demonstrative thing takes for granted that it is
    there; only where a verb of seeing and its auxiliaries come before the thing ("Is there a mug
    on the desk?" and "see a mug?" still ask)."""
    lead = [w for w in words[clause.start:start] if w not in ("the", "that", "this", "those", "these")]
    det = words[start - 1] if start > 0 else ""
    return det in ("the", "that", "this", "those", "these") and bool(set(lead) & PERCEIVE) and all(
        w in _ASKED_SEEING for w in lead)


#: verbs of becoming, the predicate of a state a thing comes to be in ("if the towel on the rail
#: gets wet", "has got dirty", "when the cloth in the bucket goes dry", "has become soiled")
#: (the analysis reads the state after one too: "if the cloth gets wet", "once the bowl goes empty")
GOING = frozenset({"go", "goes", "going", "gone", "went"})
BECOMING = GOING | GET_PASSIVE | frozenset({"getting", "become", "becomes", "became", "turn", "turns", "turned",
                                            "grow", "grows", "grown", "grew"})


def _described_subject(words: list[str], start: int, end: int, clause: Span) -> bool:
    """"if the mug on the coffee table is dirty", "Is the lamp on the nightstand still on?": a
    definite object whose state (not place) is in question: a state word follows its place, after
    a verb of being, a perfect ("if the bath towel on the rail has been used", "should the mug on
    the desk have got dirty", "has been left wet") or of becoming (`BECOMING`: "goes dry")."""
    j = end
    put_first = j < clause.end and words[j] == ","
    j += put_first
    while j < clause.end and (words[j] in ADVERBS or words[j] in BE or words[j] in PERFECT or words[j] in BECOMING
                              or words[j] == "left" and words[j - 1] in BE):
        j += 1
    if put_first and j < clause.end and words[j - 1] in BE and words[j] in RESUMPTIVE:
        # "the wine bottle on the table, is it empty?": the thing put first, then asked of by
        # a pronoun after the inverted verb
        j += 1
        while j < clause.end and words[j] in ADVERBS:
            j += 1
    return start - 1 >= clause.start and j < clause.end and words[j] in STATE_WORDS


# ---------------------------------------------------------------------------------------------
# A structural fallback for stated placements
# ---------------------------------------------------------------------------------------------

#: the prepositions of place the fallback reads, and the one each stands for ("into"/"onto" say
#: where a thing goes; "under", "behind", "beside" name no holder)
FALLBACK_AT = {"on": "on", "upon": "on", "atop": "on", "in": "in", "inside": "inside", "within": "in"}
#: relative words of place of the formal and archaic registers ("a desk whereon a lamp sits")
WHERE_PREPS = {"whereon": "on", "whereupon": "on", "wherein": "in"}
#: words that keep a clause from stating a fact: negation, modality, a goal, a hedge, a condition
UNSTATED = frozenset({"not", "never", "no", "nothing", "should", "must", "ought", "shall", "would", "will",
                      "can", "could", "might", "may", "to", "need", "needs", "want", "wants", "if", "unless",
                      "whether", "anywhere", "somewhere", "when", "whenever", "once", "until", "let"}) | DOUBT \
    | HEDGES | CORRELATIVE_NEGATIONS
#: words that may stand before a subject at the head of a clause ("and whereas on the piano ...")
SUBJECT_LEADS = LEAD_INS | FRONT_LEADS | frozenset({",", "whereas", "while", "meanwhile", "as", "yes", "also",
                                                    # interjections ("Uh-oh, the floor is stained!")
                                                    "uh", "oh", "ah", "oops", "whoops", "alas", "hey"})
#: words before "to" that make it part of a place ("on the shelf next to the boiler"), not a goal
PLACE_BEFORE_TO = frozenset({"next", "close", "adjacent", "beside"})
#: words opening a clause that make it a condition or a relative, not a statement of its own
_WHERE_LEADS = frozenset({"where", "wherever", "whenever", "once", "should", "what", "which", "who"})
#: words of a verb gap that say where a thing goes or what someone does to it, not where it is
_GAP_STOPS = (RESULT - PASSIVE_STATIVE) | MOTION | HAVE_VERBS | SUBJECT_PRONOUNS | frozenset(
    {"you", "we", "i", "they", "he", "she", "moved", "move", "moves", "goes", "go"})


@dataclass
class _Before:
    """What the fallback knows of the text before the sentence it reads: the last sentence (a
    pronoun or an elided subject whose own sentence names no fitting thing before it takes up the
    nearest fitting mention there) and the thing that last spoke of itself ("I am the sideboard.
    On top of me sits the table lamp": a label's "me")."""

    last: _Sentence | None = None
    speaker: Mention | None = None

    def see(self, sent: _Sentence) -> None:
        words = sent.words
        for i in range(len(words) - 2):
            if words[i] == "i" and words[i + 1] == "am" and words[i + 2] in ARTICLES:
                named = next((m for m in sent.mentions if m.kind == "role" and len(m.roles) == 1
                              and i + 3 <= m.start <= i + 5 and m.end == len(words)
                              and all(w.isalpha() and w not in VERBS for w in words[i + 3:m.start])), None)
                self.speaker = named or self.speaker
        self.last = sent


def _fallback(sent: _Sentence, before: _Before, lex: Lexicon, catalog: Catalog, reading: _Reading) -> None:
    """Where no rule read a placement, a declarative part of a statement that names a thing and a
    holder joined by a preposition of place (`FALLBACK_AT`) states that the thing is there,
    whatever its verb ("stands", "lies open", "does sit"), word order (a fronted place, "there"
    insertion), relative clause ("that's on", "whereon"), possessive ("the floor has a stain on
    it"), identification ("the basket is the wicker one on the bench") or a bracketed "it" after
    the thing. A thing some rule already placed keeps that place; a part with a negation, a modal,
    a hedge or a condition (`UNSTATED`) states nothing; conditions, questions and instructions
    are never read (the clause moods)."""
    words = sent.words
    for clause in _clauses(words, 0, len(words)):
        if clause.mood == "condition" and clause.end < len(words) and words[clause.end] == "?":
            for kind, item, prep, holder in _asked_activity(sent, clause):
                _put_new(reading, kind, catalog, lex, item, holder, prep)
        if clause.mood != "statement" or _earlier_occasion(words, clause) \
                or _ended_past(words, clause.start, clause.end):
            continue  # (an anecdote of an earlier occasion, a state since ended, places nothing now)
        for a, b in _parts(words, clause):
            ms = [m for m in sent.mentions if a <= m.start and m.end <= b] + _glossed_place(sent, a, b)
            lead = next((w for w in words[a:b] if w not in SUBJECT_LEADS), "")
            habit = habitual(words[a:b])
            if ms and habit and lead not in SUBORDINATORS | _WHERE_LEADS:
                for item, prep, holder in _habit_subject(sent, ms, a, b):
                    _put_new(reading, "presumed", catalog, lex, item, holder, prep)
            if not ms or habit or lead in SUBORDINATORS | _WHERE_LEADS:
                continue  # "where the carton remains on the table, ...": a condition's register
            # the "to" of "has moved to" is where the thing went, of "next to" where it is: no goal
            stated = not {w for k, w in enumerate(words[a:b], a)
                          if (w != "to" or words[k - 1] not in MOVED | PLACE_BEFORE_TO)
                          and not _corrective_not(words, a, k)} & UNSTATED \
                and not any(_alternative_place(words, k, len(words)) for k in range(a, min(b + 2, len(words)))
                            if words[k] == "or")
            for kind, item, prep, holder in _fallback_forms(sent, ms, a, b, lex, stated) \
                    + (_structures(sent, before, ms, a, b, lex) if stated else []):
                _put_new(reading, kind, catalog, lex, item, holder, prep)


#: finite forms of "be" that end a subject before its predicate (`_habit_subject`)
_SUBJECT_END_BE = frozenset({"is", "are", "was", "were"})


def _habit_subject(sent: _Sentence, ms: list[Mention], a: int, b: int) -> list[tuple[str, str, Mention]]:
    """(thing, preposition, holder) of a habitual statement part (from `a` to `b`) whose definite
    subject names a thing with its place ("The desktop computer on the desk is left running more
    often than not", "the printer on the desk is often left on"): the habit speaks of what
    happens to the thing, while the definite subject's place is where the thing is now. The
    subject ends at the first finite "be", before any word of the habit, and is "the", the thing
    and its place, nothing else. A generic subject ("Printers on the desk are often left on", "A
    computer on the desk ...") and a habit of place ("The mug is often on the desk", "the mug
    often ends up on the desk") are no such subject. A notice's telegraphic line drops "the" and
    "is" ("TV on TV stand frequently left running"): a bare singular thing opening the part, with
    its place, ends at the habit's adverb when a participle of leaving or switching follows it."""
    words = sent.words
    v = next((k for k in range(a + 1, b) if words[k] in _SUBJECT_END_BE), b)
    thing = next((m for m in ms if m.kind == "role" and len(m.roles) == 1), None)
    if v == b and thing is not None and thing.start == a and sent.toks[thing.end - 1].word == sent.toks[thing.end - 1].lemma:
        # (the telegraphic line: the subject ends where the habit's adverb starts)
        v = next((k for k in range(thing.end, b) if words[k] in FREQUENCY | NORM_ADVERBS), b)
        if v == b or not _participle_after(words, v + 1, b):
            return []
    elif words[a] != "the" or v == b or habitual(words[a:v + 1]):
        return []
    if thing is None or thing.end >= v or not _subject_at(words, thing.start, a):
        return []
    found = _place_at(sent, ms, thing.end, v, False)
    # (the holder's room may follow it: "the computer on the desk in the study is ...")
    if found is None or found[1].end != v and not _room_after(sent, found[1].end, v):
        return []
    return [(thing.roles[0], found[0], found[1])]


#: participles of a thing left as it is, or switched so ("often left running", "regularly switched
#: on", "frequently forgotten"): a habit of the thing's state (`_participle_after`; the factor
#: reader's `analysis._habit_of_state`)
LEFT_PASSIVES = frozenset({"left", "switched", "turned", "forgotten"})


def _participle_after(words: list[str], k: int, end: int) -> bool:
    """Whether the word at `k` (before `end`) is a past participle ("left", "switched"): a
    telegraphic line's passive with its "is" dropped ("... often left running"), not a verb of
    place ("... often ends up on the desk": a habit of place, which places nothing)."""
    return k < end and words[k] in LEFT_PASSIVES


def _room_after(sent: _Sentence, k: int, end: int) -> bool:
    """Whether the tokens from `k` to `end` are "in the <room>" (a room the brief names), which
    says where the holder before them is, not another place."""
    words = sent.words
    j = k + 1
    while j < end and words[j] in ARTICLES:
        j += 1
    return k < end and words[k] == "in" and any(m.kind == "room" and m.start == j and m.end == end
                                                 for m in sent.mentions)


def _corrective_not(words: list[str], a: int, k: int) -> bool:
    """Whether the "not" at token `k` opens a corrective tail after a place its part (from `a`)
    has already stated: "it was left on the filing cabinet, not on the desk", "it's on the shelf,
    not the desk". The tail denies another place, not the statement; a "not" before the place
    ("left, not on the cabinet, but ...") or on the verb ("was not left on ...") still does."""
    return words[k] == "not" and k > a and words[k - 1] == "," and k + 1 < len(words) \
        and (words[k + 1] in FALLBACK_AT or words[k + 1] in ARTICLES) \
        and any(w in FALLBACK_AT for w in words[a:k - 1])


def _parts(words: list[str], clause: Span) -> list[tuple[int, int]]:
    """A statement clause cut where a new clause is joined on (", and", ", but", "and there"), so
    that a doubt in one ("... and there may be a toy on it") leaves the other standing."""
    cuts = [clause.start]
    for i in range(clause.start + 1, clause.end - 1):
        if words[i] == "," and words[i + 1] in ("and", "but", "while", "whereas") \
                or words[i] == "and" and words[i + 1] == "there" and words[i - 1] != ",":
            cuts.append(i + 1 if words[i] == "," else i)
    cuts.append(clause.end)
    return [(x, y) for x, y in zip(cuts, cuts[1:], strict=False) if y > x]


def _put_new(reading: _Reading, kind: str, catalog: Catalog, lex: Lexicon, item: str, holder: Mention,
             prep: str) -> None:
    """`_put`, for a thing no rule has placed yet (in any kind, on a holder or in a room). A thing
    only said to be in the one room of a one-room task ("the desktop computer on the reception
    desk" also names the reception) may still be put on a holder there: that narrows its place."""
    if any(item in held for held in reading.held.values()):
        return
    if any(item in rooms for rooms in reading.rooms.values()) and (len(lex.rooms) != 1 or holder.kind != "role"):
        return
    _put(reading, kind, catalog, lex, item, holder, prep)


def _over_a_part(words: list[str], j: int, hi: int) -> bool:
    """Whether the "over" / "across" at j names an outer part of a holder ("over the back of the
    chair", "across the arm of the sofa", "over the end of the bed"): a thing said to be there
    hangs on it, whatever the verb (a copula too: "the towel is over the back of the chair"),
    where "over the table" alone may be above it (a lamp over the table rests on none)."""
    k = j + 1
    while k < hi and words[k] in ARTICLES:
        k += 1
    return k + 1 < hi and words[k] in OUTER_PARTS and words[k + 1] == "of"


def _place_at(sent: _Sentence, ms: list[Mention], j: int, hi: int, resting: bool,
              at: str | None = None) -> tuple[str, Mention] | None:
    """(preposition, holder) when token j is a preposition of place (`FALLBACK_AT`, or after a verb
    of resting "across"/"over"; or any, read as `at`) followed by a holder the brief names."""
    word = sent.words[j] if j < hi else ""
    at = at or FALLBACK_AT.get(word) or ("on" if word in OVER and (resting or _over_a_part(sent.words, j, hi))
                                         else None)
    if at is None:
        return None
    toks = list(sent.toks)
    toks[j] = _Token(at, at, toks[j].start, toks[j].end)
    return _holder_after(_Sentence(toks, sent.mentions), ms, j, hi)


def _subject_at(words: list[str], start: int, lo: int) -> bool:
    """Whether a noun phrase starting at `start` opens its part (after leads and its determiners and
    up to three modifiers that are no verb): a subject, not an object."""
    j, modifiers = start - 1, 0
    while j >= lo and (words[j] in ARTICLES or words[j] in COLOR_WORDS or words[j] in STATE_WORDS
                       or modifiers < 3 and words[j].isalpha() and not verb_form(words[j])
                       and words[j] not in SUBJECT_LEADS and words[j] not in UNSTATED):
        modifiers += words[j] not in ARTICLES
        j -= 1
    return j < lo or all(w in SUBJECT_LEADS for w in words[lo:j + 1])


def _verb_gap(words: list[str], ms: list[Mention], i: int, hi: int) -> int | None:
    """The end of a gap of one to four words from i that holds a verb of being or resting and names
    nothing, nor says where a thing goes or who did something (`_GAP_STOPS`)."""
    j = i
    while j < hi and j - i < 4 and words[j].isalpha() and words[j] not in FALLBACK_AT \
            and words[j] not in OVER and words[j] not in _GAP_STOPS \
            and not _named_word(ms, j):
        j += 1
    gap = words[i:j]
    if not any(_finite_word(w) for w in gap):
        return None  # "a book found on the floor is ...", "toys lying on the floor": a modifier
    passive = next((k for k, w in enumerate(gap) if w in BE), None)
    if passive is not None and any(w not in PASSIVE_STATIVE and (w in RESULT or w.endswith("ed"))
                                   for w in gap[passive + 1:]):
        return None  # "books are shelved on the bookshelf": what is done, a norm
    return j


#: finite forms of "be", of the auxiliaries and of verbs of resting in the past
_FINITE = (BE - {"be", "been", "being"}) | frozenset(
    {"does", "do", "did", "doth", "has", "have", "had", "sat", "stood", "lay", "rested", "hung", "stayed"})


def _finite_word(word: str) -> bool:
    """Whether `word` is a finite verb: "is", "does", "sat", an archaic "standeth", or a verb's
    present third person ("stands", "remains"), not a participle ("lying", "found")."""
    return word in _FINITE or word.endswith("eth") and len(word) > 4 or (
        word.endswith("s") and not word.endswith("ss") and verb_form(word))


#: a perfect of moving says where a thing is now ("has moved to", "have been moved into")
MOVED = frozenset({"moved", "gone", "migrated", "relocated"})
#: where a perfect of moving goes, and the preposition of place it leaves the thing at
MOVED_TO = {"to": "on", "onto": "on", "into": "in"}


def _moved_to(words: list[str], i: int, hi: int) -> tuple[int, str] | None:
    """(index of the place's preposition, the preposition it stands for) when words from i read
    "has/have [now] [been] moved/gone to|onto|into": the thing is there now (not "has to move",
    a norm, nor "had moved", a past that may have passed)."""
    j = i
    if j >= hi or words[j] not in ("has", "have"):
        return None
    j += 1
    while j < hi and words[j] in ADVERBS:
        j += 1
    if j < hi and words[j] == "been":
        j += 1
    if j + 1 >= hi or words[j] not in MOVED or words[j + 1] not in MOVED_TO:
        return None
    return j + 1, MOVED_TO[words[j + 1]]


def _gap_kind(gap: list[str]) -> str:
    return "kept" if set(gap) & KEEP_VERBS else "settled"


def _fallback_forms(sent: _Sentence, ms: list[Mention], a: int, b: int, lex: Lexicon,
                    stated: bool) -> list[tuple[str, str, str, Mention]]:
    """(kind, thing, preposition, holder) of each form the fallback reads in the part [a, b)."""
    words = sent.words
    out: list[tuple[str, str, str, Mention]] = []
    things = [m for m in ms if m.kind == "role" and len(m.roles) == 1]
    for m in things:
        item = m.roles[0]
        subject = _subject_at(words, m.start, a) or words[a - 1:a] == ["("] and m.start == a
        after = _of_complement(words, ms, m.end, b)  # "the photo frame of Nana that's on the shelf"
        relative = after < b and words[after] in RELATIVE
        # the thing, a verb of being or resting, the place: "a wine bottle stands on the bar",
        # "visitors' book lies open on the desk", "the mug that's on the desk"
        if stated and (subject or relative) and _prep_before(words, m.start) is None:
            end = _verb_gap(words, ms, after, b)
            found = _place_at(sent, ms, end, b, bool(set(words[after:end]) & STATIVE)) if end is not None else None
            if found is None and subject and _definite(words, m.start):
                end = _passive_state(sent, after, b)  # "The bag of my wife is put on the low table"
                found = _place_at(sent, ms, end, b, False) if end is not None else None
            if found is not None and end is not None:
                out.append((_gap_kind(words[after:end]), item, found[0], found[1]))
        # the thing, a perfect of moving, where to: "the coffee maker has moved to the island"
        if stated and subject and _prep_before(words, m.start) is None:
            to = _moved_to(words, m.end, b)
            if to is not None:
                found = _place_at(sent, ms, to[0], b, False, at=to[1])
                if found is not None:
                    out.append(("settled", item, found[0], found[1]))
        # "a desk, a desk lamp on it": a thing after its holder and a comma, its place "on it"
        if stated and m.start >= 2 and words[m.end:m.end + 2] in ([w, "it"] for w in FALLBACK_AT) \
                and (m.end + 2 >= b or words[m.end + 2] in PUNCT):
            k = _prep_index(words, m.start)
            holder = next((x for x in ms if x.end == k and x.kind == "role" and len(x.roles) == 1), None)
            if k >= a and words[k] == "," and holder is not None:
                out.append(("settled", item, FALLBACK_AT[words[m.end]], holder))
        # a holder, "whereon"/"wherein", the thing and its verb: "a desk whereon a lamp doth sit"
        if stated and m.start > a and any(x.end <= m.start for x in ms):
            k = _prep_index(words, m.start)
            if k >= a and words[k] in WHERE_PREPS and _verb_gap(words, ms, m.end, b) is not None:
                holder = next((x for x in ms if x.end == k and len(x.roles) == 1), None)
                if holder is not None:
                    out.append(("settled", item, WHERE_PREPS[words[k]], holder))
        # a definite subject with its place, then its predicate: "the coffee machine on the
        # worktop, to the left of the hob, takes a while", "my mug on the desk is dirty" (a
        # possessive is as definite as "the"): the place is taken for granted
        if subject and _definite(words, m.start) and m.end < b and words[m.end] in FALLBACK_AT:
            found = _place_at(sent, ms, m.end, b, False)
            if found is not None and any(w in BE | STATIVE or verb_form(w) for w in words[found[1].end:b]):
                out.append(("presumed", item, found[0], found[1]))
    if not stated:
        return out
    out += _identified(sent, ms, a, b) + _resumed(sent, ms, a, b)
    # "(it stays on the floor)" right after the thing's name: the bracket's "it" is that thing
    if a >= 2 and words[a - 1] == "(" and words[a] in RESUMPTIVE:
        before = next((x for x in sent.mentions if x.end == a - 1 and x.kind == "role" and len(x.roles) == 1), None)
        end = _verb_gap(words, ms, a + 1, b)
        if before is not None and end is not None:
            found = _place_at(sent, ms, end, b, bool(set(words[a + 1:end]) & STATIVE))
            if found is not None:
                out.append((_gap_kind(words[a + 1:end]), before.roles[0], found[0], found[1]))
    # "there is a stain on the floor" in a part its clause's doubt does not cover
    for i in range(a, b - 1):
        if words[i] == "there" and words[i + 1] in BE:
            j = next((k for k in range(i + 2, b) if words[k] in FALLBACK_AT), b)
            found = _place_at(sent, ms, j, b, False)
            if found is not None:
                out += [("settled", r, found[0], found[1]) for x in _np_list(sent, ms, i + 2, j) for r in _roles(x, sent)]
    return out




def _identified(sent: _Sentence, ms: list[Mention], a: int, b: int) -> list[tuple[str, str, str, Mention]]:
    """"The basket is the wicker one on the bench", "it's the big desktop on the desk": a thing
    identified, after "is", by a noun phrase its place ends."""
    words = sent.words
    out: list[tuple[str, str, str, Mention]] = []
    for i in range(a, b - 2):
        if not (words[i] in BE or words[i] == "its" and words[i + 1] in ARTICLES) or words[i + 1] not in ARTICLES:
            continue
        j = i + 2
        while j < b and j - i < 6 and words[j].isalpha() and words[j] != "one" and words[j] not in FALLBACK_AT \
                and not any(m.start == j for m in ms):
            j += 1
        named = next((m for m in ms if m.start == j and m.kind == "role" and len(m.roles) == 1), None)
        if named is not None:
            at = named.end
        elif j < b and words[j] == "one":
            before = [m for m in _np_list(sent, ms, a, i) if m.kind == "role" and len(m.roles) == 1]
            named = before[-1] if before and _subject_at(words, before[-1].start, a) else None
            at = j + 1
        if named is None:
            continue
        found = _place_at(sent, ms, at, b, False)
        if found is not None:
            out.append(("settled", named.roles[0], found[0], found[1]))
    return out


def _resumed(sent: _Sentence, ms: list[Mention], a: int, b: int) -> list[tuple[str, str, str, Mention]]:
    """"The floor has a stain on it", "the tray holds two cups in it": a holder, a verb of having,
    the things, and a place taken up by "it"."""
    words = sent.words
    out: list[tuple[str, str, str, Mention]] = []
    for holder in ms:
        if len(holder.roles) != 1 or holder.end >= b or words[holder.end] not in HAVE_VERBS \
                or not _subject_at(words, holder.start, a):
            continue
        j = next((k for k in range(holder.end + 1, b - 1) if words[k] in FALLBACK_AT), None)
        if j is None or words[j + 1] not in RESUMPTIVE | {"them"}:
            continue
        for x in _np_list(sent, ms, holder.end + 1, j):
            out += [("settled", r, FALLBACK_AT[words[j]], holder) for r in _roles(x, sent)]
    return out


# ---------------------------------------------------------------------------------------------
# Placements by structure (tenth session): the fallback's forms read wherever they occur
# ---------------------------------------------------------------------------------------------

#: participles of placing whose present passive, right before the place and said of a definite
#: thing, states where it is ("The bag of my wife is put on the low table"); "is put back in",
#: "is to be put", "is put on the shelf once it is dry" (a procedure) do not (`_passive_state`)
PUT_PASSIVES = frozenset({"put", "placed", "set", "laid", "stood", "left"})
#: words after a place that make a present passive a procedure: a time or condition clause, a habit
_PROCEDURE = SUBORDINATORS | _WHERE_LEADS | frozenset({"after", "before", "every", "each", "then", "until"})
#: words before a part that put it under a condition ("if you have had it out and it is still
#: standing on the floor"): a pronoun or elided subject there is no statement's
CONDITION_CUES = frozenset({"if", "unless", "when", "whenever", "once", "should", "until", "whether"})
#: a state adjective said of a holder that names a thing on it ("The floor is stained": a stain on
#: the floor), and the nouns it may name (the brief's roles decide which, if any, is meant)
MARKS = {"stained": ("stain",), "marked": ("mark", "stain"), "smudged": ("smudge", "mark"),
         "scuffed": ("scuff", "mark"), "splattered": ("splatter", "stain"), "spattered": ("spatter", "stain"),
         "muddied": ("mud",), "scratched": ("scratch",)}


def _structures(sent: _Sentence, before: _Before, ms: list[Mention], a: int, b: int,
                lex: Lexicon) -> list[tuple[str, str, str, Mention]]:
    """The stated part [a, b)'s placements by structure: a place put first ("On the shoe rack sits
    the Small One's hat"), a pronoun or an elided subject ("it stands on the TV stand", "- is on
    top of the bookshelf", "Has a tissue box on it"), a state adjective naming a thing on its
    holder ("The floor is stained")."""
    return _fronted(sent, before, ms, a, b) + _taken_up_subject(sent, before, ms, a, b, lex) \
        + _marked(sent, ms, a, b, lex)


#: words that cannot stand among the determiners and modifiers of a noun phrase: a preposition
#: opens another phrase ("On the shelf sits a note about the hat": the note sits there)
_NOT_MODIFIERS = frozenset(FALLBACK_AT) | SOURCE | UNSTATED | RELATIVE | MODIFIER_OPENERS | frozenset(
    {"about", "for", "with", "without", "like", "at", "to", "under", "above", "below", "over", "beneath"})


def _fronted(sent: _Sentence, before: _Before, ms: list[Mention], a: int,
             b: int) -> list[tuple[str, str, str, Mention]]:
    """Locative inversion: a place first, optional "there" and adverbs, one finite verb of being or
    resting, then the things after their determiners and modifiers ("And whereas on the piano
    stands our photo frame", "On the shoe rack sits the Small One's hat", "Upon the stove there
    commonly stands the copper saucepan": a usual place, a home). "On top of me" is the thing that
    last spoke of itself ("I am the sideboard")."""
    words = sent.words
    j = a
    while j < b and words[j] in SUBJECT_LEADS:
        j += 1
    found = _place_at(sent, ms, j, b, False)
    if found is None and j + 1 < b and words[j] in FALLBACK_AT and words[j + 1] == "me" \
            and before.speaker is not None:
        found = (FALLBACK_AT[words[j]], Mention(before.speaker.roles, j + 1, j + 2, "role"))
    if found is None:
        return []
    k, kind = found[1].end, "settled"
    while k < b and (words[k] in ADVERBS or words[k] in NORM_ADVERBS):
        kind = "kept" if words[k] in NORM_ADVERBS else kind
        k += 1
    if k >= b or not _finite_word(words[k]) or words[k] in _GAP_STOPS or _named_word(ms, k):
        return []
    kind = "kept" if words[k] in KEEP_VERBS else kind
    things = _np_list(sent, ms, k + 1, b)
    if not things:
        return []
    gap = words[k + 1:things[0].start]
    if len(gap) > 4 or any(not w.isalpha() or w in VERBS or w in _NOT_MODIFIERS for w in gap):
        return []  # "On the shelf sits a note about the torch": the thing is not what follows
    return [(kind, r, found[0], found[1]) for x in things for r in _roles(x, sent)]


def _taken_up_subject(sent: _Sentence, before: _Before, ms: list[Mention], a: int, b: int,
                      lex: Lexicon) -> list[tuple[str, str, str, Mention]]:
    """A part whose subject is "it" or elided takes up the nearest fitting mention before it (in
    its sentence, else, when its sentence names no thing before it, the last sentence): "It is my
    television, it stands on the TV stand", "It's the red one by the slider, it stays on the floor
    there" (the bucket of the sentence before), "The class tablet - the iPad - is on top of the
    bookshelf"; an elided possessive its holder: "5. Side table: pine. Has a tissue box on it".
    A clause spliced on by a comma ("..., it stays on ...") is read as its own part."""
    words = sent.words
    if set(words[:a]) & CONDITION_CUES:
        return []  # "if there is one and it is on the counter": "it" under the condition
    j = a
    while j < b and words[j] in SUBJECT_LEADS:
        j += 1
    starts = [j] + [p for p in range(j + 1, b - 1) if words[p] == "it" and words[p - 1] == ","]
    for k in starts:
        if k >= b:
            continue
        found = _taken_up_at(sent, before, ms, k, b, lex, elided=k == j and words[k] != "it")
        if found:
            return found
    return []


def _taken_up_at(sent: _Sentence, before: _Before, ms: list[Mention], j: int, b: int, lex: Lexicon, *,
                 elided: bool) -> list[tuple[str, str, str, Mention]]:
    """`_taken_up_subject` for the clause from token j ("it ..." or, `elided`, its verb)."""
    words = sent.words
    start = j if elided else j + 1
    if elided and (j == 0 and before.last is None or not _finite_word(words[j])):
        return []
    if elided and words[start] in HAVE_VERBS:
        k = next((n for n in range(start + 1, b - 1) if words[n] in FALLBACK_AT), None)
        if k is None or words[k + 1] not in RESUMPTIVE | {"them"}:
            return []
        roles = [r for x in _np_list(sent, ms, start + 1, k) for r in _roles(x, sent)]
        holder = _nearest(sent, before, j, lex, holder=True, exclude=set(roles))
        if holder is None:
            return []
        return [("settled", r, FALLBACK_AT[words[k]], holder) for r in roles]
    end = _verb_gap(words, ms, start, b)
    if end is None or any(w in HAVE_VERBS for w in words[start:end]):
        return []
    found = _place_at(sent, ms, end, b, bool(set(words[start:end]) & STATIVE))
    if found is None:
        return []
    thing = _nearest(sent, before, j, lex, holder=False, exclude=set(found[1].roles))
    if thing is None:
        return []
    return [(_gap_kind(words[start:end]), thing.roles[0], found[0], found[1])]


def _nearest(sent: _Sentence, before: _Before, pos: int, lex: Lexicon, *, holder: bool,
             exclude: set[str]) -> Mention | None:
    """The nearest mention before token `pos` that fits: one role, not `exclude`, one thing (its
    word singular, for "it"), or a holder when a holder is wanted; in the sentence, else, when the
    sentence names no thing before `pos`, in the last sentence."""
    own = [(m, sent) for m in sent.mentions if m.end <= pos and m.kind == "role"]
    pool = own or ([(m, before.last) for m in before.last.mentions if m.kind == "role"]
                   if before.last is not None else [])
    for m, where in reversed(pool):
        if len(m.roles) != 1 or m.roles[0] in exclude:
            continue
        last = where.toks[m.end - 1]
        if m.roles[0] in lex.holders if holder else last.word == last.lemma:
            return m
    return None


def _of_complement(words: list[str], ms: list[Mention], j: int, hi: int) -> int:
    """Where a thing's noun phrase ends after an "of" complement naming no thing ("the photo frame
    of Nana", "the bag of my wife"): up to three words; `j` when there is none."""
    if j >= hi or words[j] != "of":
        return j
    k = j + 1
    while k < hi and k - j <= 3 and words[k].isalpha() and words[k] not in VERBS and words[k] not in RELATIVE \
            and not _named_word(ms, k):
        k += 1
    return k if k > j + 1 and k < hi and (words[k] in RELATIVE or words[k] in BE) else j


def _passive_state(sent: _Sentence, i: int, hi: int) -> int | None:
    """The place's index when words from i read "is/are <put/placed/left ...> on|in": a present
    passive of placing stated of a definite thing ("The bag of my wife is put on the low table"),
    unless its sentence has a time or condition clause or a habit ("is put on the shelf once it
    is dry", "after being silenced", "every evening"): a procedure, no fact."""
    words = sent.words
    if i + 2 >= hi or words[i] not in ("is", "are") or words[i + 1] not in PUT_PASSIVES \
            or words[i + 2] not in FALLBACK_AT:
        return None
    if set(words) & _PROCEDURE:
        return None
    return i + 2


def _marked(sent: _Sentence, ms: list[Mention], a: int, b: int, lex: Lexicon) -> list[tuple[str, str, str, Mention]]:
    """"The floor is stained", "the table is badly marked": a holder, a form of "be" and a state
    adjective (`MARKS`) that names a thing on it, when the brief names that thing (its noun as the
    lexicon reads it)."""
    words = sent.words
    out: list[tuple[str, str, str, Mention]] = []
    for holder in ms:
        if holder.kind not in ("role", "floor") or len(holder.roles) != 1 or holder.end >= b \
                or words[holder.end] not in BE or not _subject_at(words, holder.start, a):
            continue
        k = holder.end + 1
        while k < b and (words[k] in ADVERBS or words[k].endswith("ly")):
            k += 1
        if k >= b or words[k] not in MARKS or k + 1 < b and words[k + 1] in ("with", "by"):
            continue  # "stained with ink" names what stains, "marked by" who
        for noun in MARKS[words[k]]:
            named = [m for m in lex.find_mentions([(noun, 0, 1)]) if m.kind == "role" and len(m.roles) == 1]
            if named:
                out.append(("settled", named[0].roles[0], "on", holder))
                break
    return out


#: particles that may follow a verb of activity before its place ("still perking away on the counter")
_ACTIVITY_PARTICLES = frozenset({"away", "along", "quietly", "loudly"})


def _asked_activity(sent: _Sentence, clause: Span) -> list[tuple[str, str, str, Mention]]:
    """A yes/no question about what a thing is doing where it is ("Is the Perk-O-Matic (that's your
    trusty coffee maker!) still perking away on the counter?", "Is the fan still whirring on the
    desk?") asks about the activity and takes the place for granted: `presumed`. Not a verb of
    resting, keeping or placing ("Is the mug sitting on the desk?" asks where it is), nor a person
    ("Are you working on the desk?"), nor a doubt or condition."""
    words = sent.words
    if words[0] not in ("is", "are", "was", "were") or set(words[:clause.end]) & (CONDITION_CUES | DOUBT):
        return []
    ms = [m for m in sent.mentions if clause.start <= m.start and m.end <= clause.end]
    for i in range(clause.start, clause.end):
        w = words[i]
        if not w.endswith("ing") or not verb_form(w) or w in STATIVE | KEEP_VERBS | RESULT | PERCEIVE \
                or _named_word(sent.mentions, i):
            continue
        k = i + 1
        while k < clause.end and (words[k] in _ACTIVITY_PARTICLES or words[k] in ADVERBS):
            k += 1
        found = _place_at(sent, ms, k, clause.end, False)
        if found is None or found[1].kind != "role":
            return []
        before = [m for m in sent.mentions if m.end <= i and m.kind == "role" and len(m.roles) == 1
                  and m.roles[0] not in found[1].roles]
        if not before or set(words[before[-1].end:i]) & (SUBJECT_PRONOUNS | {"you", "we", "i", "they", "he", "she"}):
            return []
        return [("presumed", before[-1].roles[0], found[0], found[1])]
    return []
