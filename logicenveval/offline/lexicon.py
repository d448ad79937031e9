"""Grounding words of a task description to the task's roles, rooms and attribute values.

The lexicon is built from the brief alone (role names, their categories, the catalog's synonyms
and attribute domains), so it generalises to any task written with the same catalog.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from lemminflect import getAllLemmas, getLemma

from logicenveval.domain.catalog import Catalog, per_catalog
from logicenveval.domain.lemmas import noun_lemma
from logicenveval.offline.wordnet import is_wordnet_name

WORD = re.compile(r"[a-z0-9]+(?:'[a-z]+)?")

#: words that tell a spare from the one in use ("the spare roll", "an extra bag")
SPARE_WORDS = frozenset({"spare", "extra", "backup", "replacement"})
#: "a fresh bag": the spare where the kind was first named without it ("the full bag ... a fresh
#: bag"), the one in use where the text opens with it ("a fresh diaper is lying on the changing
#: table; if there isn't one, fetch a spare"): the naming step's rule (`offline.naming`)
FRESH_WORDS = frozenset({"fresh", "new"})
#: head nouns of a control named for what it controls ("light switch"): "the light is on" is said
#: of the switch, the one thing of the scene whose state it is (`Lexicon.build`, the naming step)
CONTROL_HEADS = frozenset({"switch"})

#: words that open a verb's object: a one-word name right before one is the verb ("stand it in
#: the umbrella stand", "if you spot it there", "water the plant", "wipe the mirror")
VERB_OBJECTS = frozenset({"it", "them", "the", "a", "an", "this", "these", "those", "its", "their", "my",
                          "your", "our"})
#: words after which a word is a verb, never a noun: a subject pronoun, "to" and the modals
#: ("if you spot it", "someone has to mop", "please vacuum")
VERB_LEADS = frozenset({"you", "we", "i", "they", "he", "she", "someone", "somebody", "to", "please", "can",
                        "could", "will", "would", "should", "must", "might", "don't", "let's"})
#: particles a verb may take before its object ("mop up the water", "wipe down the table")
VERB_PARTICLES = frozenset({"up", "down", "off", "out", "over", "away"})

#: determiners before "the salt and pepper shakers" (`Lexicon._shared_head`)
_SHARED_LEADS = frozenset({"the", "my", "our", "your", "their", "both", "a", "some", "any"})

COLOR_WORDS = frozenset(
    ["red", "blue", "green", "yellow", "white", "black", "grey", "gray", "brown", "pink", "purple", "orange", "beige", "silver", "gold"]
)


#: the noun lemma the reader compares words by: the judge's own (`domain.lemmas`), so that a
#: name the reader matches is a name the judge resolves
singular = noun_lemma


def verb_form(word: str) -> bool:
    """Whether `word` as written is a form of a verb (lemminflect): "spot", "wipes", "mopping"."""
    return bool(getAllLemmas(word, upos="VERB").get("VERB"))


def verb_at(word: str, prev: str, nxt: list[str]) -> bool:
    """Whether `word` (as written) is a verb where it stands, not the noun it is also the name
    of: after a subject, "to" or a modal (`VERB_LEADS`: "if you spot it there"); or in its base
    form right before its object, or a particle and its object (`VERB_OBJECTS`,
    `VERB_PARTICLES`: "mop up the water", "wipe it down"), unless a determiner, a preposition,
    a count or a state stands right before it ("the spot", "on a tape", "a dirty mop the ...").
    `prev` is the word before and `nxt` the (up to two) words after, as written; a caller
    leaves out those beyond punctuation (a list "a mop, the bucket" is two things)."""
    if not verb_form(word):
        return False
    if prev in VERB_LEADS:
        return True
    if not nxt or word not in getAllLemmas(word, upos="VERB").get("VERB", ()):
        return False
    if prev in VERB_OBJECTS or prev in NOT_BEFORE_VERBS:
        return False
    return nxt[0] in VERB_OBJECTS or nxt[0] in VERB_PARTICLES and nxt[1:2] != [] and nxt[1] in VERB_OBJECTS


def adjective_only(word: str) -> bool:
    """Whether `word` (as written) is an adjective and no other part of speech in the lemmatiser's
    dictionary ("acoustic", "wooden"; not "metal", "red" or "live", also nouns or verbs)."""
    lemmas = getAllLemmas(word)
    return set(lemmas) == {"ADJ"} and word in lemmas["ADJ"]


#: verbs (lemmas) after which a bare word that is also an adjective is their complement, no noun: a
#: verb of being or becoming ("is it safe", "stay safe", "keep safe", "feel fine") or a verb of
#: moving or doing that takes a flat adverb ("drive safe", "pack light", "travel light", "play fair")
#: (no verb a terse note puts before a thing: "turn light on", "get light bulb", "hold fan")
COMPLEMENT_VERBS = frozenset({"be", "stay", "remain", "keep", "seem", "look", "feel", "become", "go", "sound", "grow",
                              "drive", "ride", "travel", "pack", "play", "fly", "walk", "arrive"})
#: an object (or subject) pronoun: a bare adjective right after one is its complement ("keep it
#: safe", "is it safe", "hold them steady"); "her", also a possessive, is left out
OBJECT_PRONOUNS = frozenset({"it", "them", "me", "us", "him", "you", "everyone", "everybody", "everything"})

#: relative pronouns: a clause one opens says more of the thing before it ("the shelf, which is
#: by the door"; "on which", "in which": `placement`), no thing of its own (`naming`: "a blue box,
#: which is for dolls, and a white box")
RELATIVE = frozenset({"which", "that", "who"})

#: adverbs of place a verb of moving takes before its complement ("get home safe", "got back safe",
#: "made it there safe"); after a determiner they are nouns ("the back safe")
PLACE_ADVERBS = frozenset({"home", "back", "there", "here"})


def complement_adjective(word: str, prev: str, prev_lead: str) -> bool:
    """Whether `word` (as written), with `prev` right before it and `prev_lead` before that, is an
    adjective or adverb said of something, no noun: a word the lemmatiser's dictionary lists as an
    adjective or adverb standing with no determiner after a verb of being or a verb taking a flat
    adverb (`COMPLEMENT_VERBS`: "drive safe", "is safe", "pack light"), after an object pronoun
    ("keep it safe", "is it safe") or an adverb of place (`PLACE_ADVERBS`: "get home safe"), or after a plural noun its verb's object ("keeps the kids
    safe"); a singular noun after a determiner there is a compound's modifier ("the wall safe")."""
    lemmas = getAllLemmas(word)
    if not {"ADJ", "ADV"} & set(lemmas) or not prev.isalpha():
        return False
    if prev in OBJECT_PRONOUNS or prev in PLACE_ADVERBS and prev_lead not in VERB_OBJECTS:
        return True
    verbs = getAllLemmas(prev, upos="VERB").get("VERB", ())
    if COMPLEMENT_VERBS & set(verbs) and prev_lead not in NOT_BEFORE_VERBS and prev_lead not in VERB_OBJECTS:
        return True
    plural = noun_lemma(prev) != prev and "NOUN" in getAllLemmas(prev)
    return plural and prev_lead in {"the", "my", "our", "your", "their", "his", "her"}


#: quantifiers the lemmatiser's dictionary lists as nouns: after a noun one floats off its subject
#: ("the mugs both go", "the plates each need", "asleep on the couch all day"), never a head
QUANTIFIERS = frozenset({"all", "both", "each", "none", "many", "some", "any", "neither", "another"})
#: the indefinite pronouns of persons, which the dictionary lists as nouns too ("a someone"): after
#: a noun they open a relative clause's subject ("the plate someone put in the sink"), no compound
INDEFINITE_PERSONS = frozenset({"someone", "somebody", "anyone", "anybody", "everyone", "everybody", "nobody"})
#: closed-class words the lemmatiser's dictionary also lists as nouns ("or", a heraldic gold; "i",
#: the letter; the quantifiers): never the head of a noun compound (`compound_head`)
FUNCTION_WORDS = frozenset({"or", "and", "but", "nor", "i", "me", "it", "itself", "them", "themselves", "us",
                            "you", "he", "him", "she", "we", "they", "this", "that", "these", "those", "if",
                            "as", "than", "who", "which", "what"}) | QUANTIFIERS | INDEFINITE_PERSONS


def compound_head(word: str, after_plural: bool) -> bool:
    """Whether `word` (as written), right after a noun with nothing between, is the head noun of an
    English noun compound the noun before modifies ("car park", "food bank", "light bill"): a noun
    in the lemmatiser's dictionary and no auxiliary, adverb or adjective ("the lamp will", "the mug
    today", "the lights out"); a verb's form there is a finite verb of the noun before ("the towel
    stays", "the towels hang"), unless it is the bare form after a singular ("the car park").
    `FUNCTION_WORDS` are never one."""
    lemmas = getAllLemmas(word)
    if word in FUNCTION_WORDS or "NOUN" not in lemmas or {"AUX", "ADV", "ADJ"} & set(lemmas):
        return False
    verb = lemmas.get("VERB", ())
    return not verb or word in verb and not after_plural and word in lemmas["NOUN"]


def gerund_of(word: str) -> str | None:
    """The verb whose -ing form `word` is, when it is one ("drying": "dry"; "ceiling", "pudding"
    are no verb's), else None."""
    if not word.endswith("ing"):
        return None
    lemma = getLemma(word, upos="VERB", lemmatize_oov=False)
    return lemma[0] if lemma and lemma[0] != word else None


#: words before a noun, never before an imperative: determiners, counts, prepositions
NOT_BEFORE_VERBS = frozenset({"a", "an", "any", "some", "no", "each", "every", "one", "two", "three", "of",
                              "on", "onto", "in", "into", "inside", "from", "by", "near", "under", "at",
                              "with", "for", "dirty", "clean", "wet", "dry", "full", "empty", "spare", "new",
                              "fresh", "old", "extra"})


def tokens(text: str) -> list[tuple[str, int, int]]:
    """(normalised word, start, end) with words singularised for matching."""
    return [(singular(m.group(0)), m.start(), m.end()) for m in WORD.finditer(text.lower())]


def _spare(role: str) -> bool:
    """A role named as the spare of its kind ("spare_roll", "spare_bag")."""
    told = words_of(role)
    return len(told) > 1 and told[0] in SPARE_WORDS


#: parts of a piece of furniture that holds things ("the bottom shelf of the metal rack", "the top
#: drawer of the dresser"): said "of" a thing, the part names that thing, no object of its own
#: (`offline.naming`), and a thing put on or in the part is on or in the thing (`offline.placement`)
FURNITURE_PARTS = frozenset({"shelf", "level", "tier", "drawer", "compartment"})
#: what ties a part the catalog has no kind of its own for to the piece of furniture it is part of
#: ("the mantelpiece above the fireplace", "the mantel of the fireplace", "the ledge over the
#: sink"): the part names no object (`offline.naming`), a thing on it is on the furniture
#: (`offline.placement`)
PART_TIES = frozenset({"of", "above", "over"})

#: nouns of time that make the name before them a time ("on bin day", "on trash day", "at bath
#: time", "laundry day"): a noun modifying its head, which names no object
TIME_HEADS = frozenset({"day", "night", "week", "morning", "evening", "time", "weekend"})

#: the ordinal words, said of an order or a time ("first thing", "the second shelf", "next time",
#: "last night") far more often than as a modifier of a thing's name: alone they hint no kind
#: whose name holds them (`offline.naming`: "first" elsewhere is no first aid box)
ORDER_WORDS = frozenset({"first", "second", "third", "next", "last"})


def words_of(name: str) -> tuple[str, ...]:
    return tuple(singular(w) for w in WORD.findall(name.lower().replace("_", " ")))


@dataclass(frozen=True)
class Mention:
    roles: tuple[str, ...]  # one role, or several when the phrase is ambiguous (two toy boxes)
    start: int  # token index
    end: int  # token index (exclusive)
    kind: str = "role"  # "role" | "room" | "floor"


#: a word of two or three capitals ("DW", "WM"): an initialism, when it abbreviates one role's name
_INITIALISM = re.compile(r"\b[A-Z]{2,3}\b")
#: English function words a writer puts in capitals for stress ("put it ON the shelf", "do NOT
#: open", "NO pens on the desk", "SO put it away"): the word itself, never an initialism, though
#: its letters may spell one ("ON" the ottoman's or the oven's, "NO" the notebook's)
_STRESSED_WORDS = frozenset({"on", "in", "at", "to", "by", "up", "off", "out", "no", "not", "so", "do", "did", "or",
                             "and", "but", "it", "is", "am", "are", "was", "the", "all", "any", "me", "my",
                             "we", "us", "you", "now", "too", "yes", "can", "may", "for"})


def _abbreviates(short: str, category: str) -> bool:
    """Whether `short` ("dw") is an initialism of a name ("dishwasher", "washing_machine"): the
    initials of its words, or for a one-word compound its first letter and then, in order, the
    first letters of its parts ("dish|washer"; a part starts at any later letter)."""
    words = category.lower().split("_")
    if len(words) > 1:
        return short == "".join(w[0] for w in words)
    word = words[0]
    if len(short) < 2 or word[:1] != short[0]:
        return False
    at = 1
    for letter in short[1:]:
        at = word.find(letter, at + 1)
        if at < 0:
            return False
    return True


#: titles a given name may open with ("Lady Rosabel", "Mr Snuggles", "Captain Fluff"): with one,
#: a name may open its sentence
TITLES = frozenset({"mr", "mrs", "ms", "miss", "lady", "lord", "sir", "dame", "captain", "doctor", "dr", "prince",
                    "princess", "king", "queen", "aunt", "auntie", "uncle", "professor", "sergeant"})
#: a greeting's first word: "Hi Sam, your mug ..." names the reader, not the mug (and a letter's
#: or a message's salutation ends its own line: `sentences._SALUTATION`)
GREETINGS = frozenset({"hi", "hey", "hello", "dear", "morning", "evening", "thanks", "cheers", "love", "yo"})
_NAME = r"[A-Z][a-z]+\.?(?:\s+[A-Z][a-z]+){0,2}"
_NOUN = r"[a-z]+(?:\s+[a-z]+){0,2}?"
_NOUN_END = r"(?=\s*(?:[,.;:!?)]|$)|\s+(?:who|which|that|is|was|has|had|sat|sits|lay|lies)\b)"
#: a given name set beside a noun that names the thing, in apposition: "Lady Rosabel, her doll",
#: "her doll, Lady Rosabel", "Mr Snuggles the teddy bear" (`_named_things`)
_NAMED_BEFORE = re.compile(rf"(?P<name>{_NAME})(?:,\s+(?:her|his|my|our|their|your|the)|\s+the)\s+(?P<noun>{_NOUN}){_NOUN_END}")
_NAMED_AFTER = re.compile(rf"\b(?:her|his|my|our|their|your|the)\s+(?P<noun>{_NOUN}),\s+(?P<name>{_NAME})(?=\s*[,.;:!?)]|$)")
#: prepositions of place and motion before which a noun phrase ending its clause is where a thing
#: goes or is: a name after it is the listener's, a vocative ("Take it to the sink, Tom, and put it
#: in", "Hang it on the hook, Anna."), not the place's given name (`_named_things`)
_VOCATIVE_PREPS = frozenset({"to", "into", "onto", "on", "in", "at", "under", "by", "off", "from", "inside",
                             "beside", "behind", "over", "next"})


#: the words that name the room a task of one room is in, after a determiner of `_THIS_ROOM`
#: ("the room", "this room", "each room")
_ROOM_WORDS = frozenset({"room"})
_THIS_ROOM = frozenset({"the", "this", "each", "every"})
#: a list item's label ending the text before a word ("a) On the desk ...", "2. Blanket", "(iii)
#: Lamp"): the word opens its item as it would open a sentence
_ITEM_LABEL_END = re.compile(r"(?:^|\n)[ \t]*\(?(?:[a-z]|[0-9]{1,2}|[ivx]{1,4})[).]$", re.I)


def _named_things(text: str, phrases: Mapping[tuple[str, ...], set[str]]) -> dict[tuple[str, ...], set[str]]:
    """The given names a text calls one role by: a capitalised name in apposition with a noun
    phrase that names exactly one role ("First, the princess had to find Lady Rosabel, her doll.
    If Lady Rosabel had fallen on the floor ..."; "Captain Fluff, my teddy bear"), so that the
    name, said alone later, is that role. A name opening its sentence counts only after a title or
    as two capitalised words that are no greeting ("Old Faithful, his kettle"; "Then, the dog bed"
    and "Hi Sam, your mug" name nothing); a name that is already a phrase is left as it is."""
    out: dict[tuple[str, ...], set[str]] = {}
    for m in (*_NAMED_BEFORE.finditer(text), *_NAMED_AFTER.finditer(text)):
        name = m.group("name")
        lead = text[:m.start("name")].rstrip(" \t")
        opens = not lead or lead[-1] in ".!?:\n\"'(-*" or bool(_ITEM_LABEL_END.search(lead))
        first = name.split()[0].lower().rstrip(".")
        if opens and first not in TITLES and (len(name.split()) < 2 or first in GREETINGS):
            continue
        if m.re is _NAMED_AFTER and (text[: m.start()].split()[-1:] or [""])[0].lower() in _VOCATIVE_PREPS:
            continue  # "to the sink, Tom": the listener, called by name
        meant = phrases.get(words_of(m.group("noun")))
        key = words_of(name)
        if meant and len(meant) == 1 and key and key not in phrases:
            out.setdefault(key, set()).update(meant)
    return {k: v for k, v in out.items() if len(v) == 1}


#: letters that stand for one another between English and the languages a loanword or cognate
#: comes from ("telewizor" / "television": Polish w and z; "telefon": f for ph; "kamera":
#: k for c), compared after this spelling is evened out (`_cognates`)
_COGNATE_SPELLING = (("ph", "f"), ("w", "v"), ("z", "s"), ("k", "c"), ("y", "i"))
#: how alike (difflib's ratio) an unknown word and a kind's one-word name must be, once spelt
#: alike, to be that word in the writer's own language: "televisor", "telewizor", "televisi"
#: against "television" (0.84 to 0.89), "kamera" against "camera" (1.0); a name, a place or a
#: word of another sense stays far below ("Tomek", "Kraków", "komoda": 0.3 at most)
_COGNATE_LIKENESS = 0.8


def _spelt_alike(word: str) -> str:
    for letters, same in _COGNATE_SPELLING:
        word = word.replace(letters, same)
    return word


def _cognates(text: str, roles: Mapping[str, Mapping[str, Any]], catalog: Catalog,
              phrases: Mapping[tuple[str, ...], set[str]]) -> dict[tuple[str, ...], set[str]]:
    """Words of no English a text calls one role by, because they are that role's kind's word in
    the writer's language or a slip of its spelling: "Telewizor stands on the chest of drawers"
    in a Polish speaker's note, "the televisor is on the cabinet" in a Spanish speaker's,
    "televisi" in an Indonesian one's, "the televsion" typed in haste. A word lemminflect does not
    know, of five letters or more, not already a phrase, as like one role's one-word kind name or
    synonym (`_COGNATE_LIKENESS`, after `_COGNATE_SPELLING`) and no other role's, with the same
    first letter, is that role wherever it is said. A known English word is never taken so (it
    has a sense of its own), nor a word two roles' names are equally like."""
    names: dict[str, set[str]] = {}
    for name, role in roles.items():
        cat = catalog.get(role["category"])
        for n in {role["category"], *(cat.synonyms if cat else ())}:
            if len(words_of(n)) == 1 and not is_wordnet_name(n):
                names.setdefault(_spelt_alike(words_of(n)[0]), set()).add(name)
    out: dict[tuple[str, ...], set[str]] = {}
    for word in {w for w, _, _ in tokens(text)}:
        if len(word) < 5 or not word.isalpha() or (word,) in phrases or getAllLemmas(word):
            continue
        alike = _spelt_alike(word)
        meant = {r for n, rs in names.items() if n[:1] == alike[:1]
                 and difflib.SequenceMatcher(None, alike, n).ratio() >= _COGNATE_LIKENESS for r in rs}
        if len(meant) == 1:
            out[(word,)] = meant
    return out


def _modifier_synonyms(roles: Mapping[str, Mapping[str, Any]], catalog: Catalog) -> dict[tuple[str, ...], set[str]]:
    """"<modifier> <head>" phrases for a role whose kind is named by a two-word compound whose
    modifier is another kind's name, with that modifier said by one of its kind's own one-word
    synonyms: "the boot rack" and "the sneaker rack" are the shoe rack ("boot", "sneaker": a
    shoe), "the couch pillow" the sofa pillow, "the brolly stand" the umbrella stand. English
    builds such a compound from any name of its first kind, the catalog lists one; the naming
    reader names the object so (`naming._Reader.named_holder`), and the other readers find the
    role by the same words. WordNet names lend no modifier."""
    one_word = {words_of(c)[0]: c for c in catalog.categories if len(words_of(c)) == 1}
    out: dict[tuple[str, ...], set[str]] = {}
    for name, role in roles.items():
        cat = catalog.get(role["category"])
        for n in {role["category"], *(cat.synonyms if cat else ())}:
            phrase = words_of(n)
            if len(phrase) != 2 or is_wordnet_name(n) or phrase[0] not in one_word:
                continue
            modifier = catalog.categories[one_word[phrase[0]]]
            for other in modifier.synonyms:
                if len(words_of(other)) == 1 and not is_wordnet_name(other):
                    out.setdefault((words_of(other)[0], phrase[1]), set()).add(name)
    return out


@per_catalog
def _one_word_names(catalog: Catalog) -> frozenset[tuple[str, ...]]:
    """Every catalog name and synonym of one word ("bench", "chair")."""
    return frozenset(words_of(n) for name, cat in catalog.categories.items() for n in (name, *cat.synonyms)
                     if len(words_of(n)) == 1)


def without_modifiers(found: list[Mention], toks: list[tuple[str, int, int]], surface: list[str]) -> list[Mention]:
    """The mentions with a compound's modifier made part of its head's: in "Bread knife, on the
    counter ...: if it's dirty" a one-word name of a thing right before another's, with only a
    space between, is the compound's modifier and the thing is the head (the knife, not the
    bread), for the condition reader (`offline.analysis`) and the placement reader alike, so that
    neither reads the bread as a thing said to be there; the head's mention starts at the
    modifier, so "the bread knife" is one noun phrase after its article. A name of two words
    keeps its own reading: in "Air con unit" the "unit" is the air conditioner's, no shelving
    unit; and a word that is no compound's head as written (`surface`, `compound_head`) is none
    ("a lamp stands on it": the lamp stands, no lamp stand)."""
    modifiers = {m.end: m.start for m in found if m.kind == "role" and m.end - m.start == 1 and m.end < len(toks)
                 and toks[m.end][1] - toks[m.end - 1][2] == 1
                 and compound_head(surface[m.end], surface[m.start] != toks[m.start][0]) and any(
                     x.start == m.end and x.kind == "role" and set(x.roles) != set(m.roles) for x in found)}
    return [replace(m, start=modifiers[m.start]) if m.kind == "role" and m.start in modifiers else m
            for m in found if m.start + 1 not in modifiers or m.kind != "role" or m.end != m.start + 1]


@dataclass
class Lexicon:
    roles: dict[str, dict[str, Any]]
    rooms: list[str]
    #: phrase (tuple of singular words) -> roles it may denote
    phrases: dict[tuple[str, ...], set[str]] = field(default_factory=dict)
    room_phrases: dict[tuple[str, ...], str] = field(default_factory=dict)
    #: role -> attribute key -> allowed values (from the catalog)
    domains: dict[str, dict[str, list[str]]] = field(default_factory=dict)
    #: role -> fixed attributes given by the brief
    fixed: dict[str, dict[str, str]] = field(default_factory=dict)
    #: roles one puts things *in* rather than *on* (containers that are not surfaces)
    containers: set[str] = field(default_factory=set)
    #: roles things can rest on or in (surfaces and containers)
    holders: set[str] = field(default_factory=set)
    #: spare roles a "fresh" mention denotes (`FRESH_WORDS`)
    fresh_spares: set[str] = field(default_factory=set)

    @classmethod
    def build(cls, brief: Mapping[str, Any], catalog: Catalog) -> Lexicon:
        roles: dict[str, dict[str, Any]] = dict(brief["roles"])
        lex = cls(roles=roles, rooms=list(brief.get("rooms", [])))
        for name, role in roles.items():
            cat = catalog.get(role["category"])
            names = {name, role["category"]} | set(cat.synonyms if cat else ())
            if name.split("_")[-1].isdigit():
                names.add("_".join(name.split("_")[:-1]))
            for n in names:
                lex.phrases.setdefault(words_of(n), set()).add(name)
                # a role named after an attribute + noun ("red_box") is also found by its noun
                if len(words_of(n)) > 1 and words_of(n)[0] in COLOR_WORDS:
                    lex.phrases.setdefault(words_of(n)[1:], set()).add(name)
            # a role named by two words that tell it apart ("upper_tin_shelf": the upper one, for
            # tins) is found by either with its noun ("the upper shelf", "the tin shelf") and as
            # "the shelf for tins"
            # a spare is also named by its word alone ("take a spare", "where the spares are kept")
            if words_of(name)[0] in SPARE_WORDS and len(words_of(name)) > 1:
                lex.phrases.setdefault(words_of(name)[:1], set()).add(name)
            *told, noun = words_of(name)
            if cat is not None and len(told) > 1 and noun == words_of(role["category"])[-1]:
                for word in told:
                    lex.phrases.setdefault((word, noun), set()).add(name)
                    lex.phrases.setdefault((noun, "for", word), set()).add(name)
            lex.domains[name] = {k: [v.lower() for v in vs] for k, vs in (cat.attributes if cat else {}).items()}
            lex.fixed[name] = {k: str(v).lower() for k, v in role.get("attributes", {}).items()}
            if cat is not None and cat.container and not cat.surface:
                lex.containers.add(name)
            if cat is not None and (cat.container or cat.surface):
                lex.holders.add(name)
        for room in lex.rooms:
            lex.room_phrases[words_of(room)] = room
        # "the table" for the dining table, "the machine" for the washing machine: a head noun
        # refers to the roles whose names end with it, when no role is named exactly so
        heads: dict[tuple[str, ...], set[str]] = {}
        for name, role in roles.items():
            cat = catalog.get(role["category"])
            for n in {role["category"], *(cat.synonyms if cat else ())}:
                phrase = words_of(n)
                if len(phrase) > 1 and not is_wordnet_name(n):
                    heads.setdefault(phrase[-1:], set()).add(name)
        for head, names in heads.items():
            if head not in lex.phrases:
                lex.phrases[head] = set(names)  # ambiguous heads are resolved by recency
        # "the wall cupboard", "the cupboard" for the wall cabinet: a head said by a one-word
        # synonym of the kind the head names ("cupboard" of the cabinet), as `offline.naming` names
        # it (`_Reader.head_by_synonym`, `_Reader.wall_sibling`), when that word names no role of
        # its own
        by_synonym: dict[tuple[str, ...], set[str]] = {}
        for name, role in roles.items():
            cat = catalog.get(role["category"])
            for n in {role["category"], *(cat.synonyms if cat else ())}:
                phrase = words_of(n)
                head_kind = catalog.get(phrase[-1]) if len(phrase) > 1 and not is_wordnet_name(n) else None
                for synonym in head_kind.synonyms if head_kind is not None else ():
                    said = words_of(synonym)
                    for key in (said, (*phrase[:-1], *said)) if len(said) == 1 else ():
                        if key not in lex.phrases:
                            by_synonym.setdefault(key, set()).add(name)
        lex.phrases.update(by_synonym)
        # "the workbench ... the bench": a one-word name ending in another one-word catalog name is
        # also found by that tail, when no role is named so (`offline.naming` reads it alike)
        tails = {p[0] for p in _one_word_names(catalog)}
        closed: dict[tuple[str, ...], set[str]] = {}
        for name, role in roles.items():
            cat = catalog.get(role["category"])
            for n in {role["category"], *(cat.synonyms if cat else ())}:
                if len(words_of(n)) == 1 and not is_wordnet_name(n):
                    word = words_of(n)[0]
                    for tail in tails:
                        if len(word) > len(tail) + 2 and word.endswith(tail) and (tail,) not in lex.phrases:
                            closed.setdefault((tail,), set()).add(name)
        lex.phrases.update(closed)
        # an English compound is written open or closed ("air con", "aircon"; "dish rack",
        # "dishrack"): a two-word name of a role's kind is also its closed form, as
        # `offline.naming` names it, when that form names no role of its own
        for name, role in roles.items():
            cat = catalog.get(role["category"])
            for n in {role["category"], *(cat.synonyms if cat else ())}:
                phrase = words_of(n)
                if len(phrase) == 2 and "of" not in phrase and not is_wordnet_name(n):
                    lex.phrases.setdefault((singular("".join(phrase)),), {name})
        for key, meant in _modifier_synonyms(roles, catalog).items():
            lex.phrases.setdefault(key, meant)
        for name, role in roles.items():
            phrase = words_of(role["category"])
            if len(phrase) == 2 and phrase[1] in CONTROL_HEADS and phrase[:1] not in lex.phrases:
                lex.phrases[phrase[:1]] = {name}  # "the light" of a light switch
        for short in set(_INITIALISM.findall(str(brief.get("description", "")))):
            # "DW already running?", "WM door": a note's initialism of a role's name
            if (short.lower(),) not in lex.phrases and short.lower() not in _STRESSED_WORDS:
                meant = {name for name, role in roles.items() if _abbreviates(short.lower(), role["category"])}
                if len(meant) == 1:
                    lex.phrases[(short.lower(),)] = meant
        # "Telewizor stands on the chest of drawers": the kind's word in the writer's language
        for key, meant in _cognates(str(brief.get("description", "")), roles, catalog, lex.phrases).items():
            lex.phrases.setdefault(key, meant)
        # "Lady Rosabel, her doll": a given name of one role
        for key, meant in _named_things(str(brief.get("description", "")), lex.phrases).items():
            lex.phrases.setdefault(key, meant)
        text = [w for w, _, _ in tokens(str(brief.get("description", "")))]
        for spare in (r for r in roles if _spare(r)):
            kin = [p for p, names in lex.phrases.items() if spare in names and len(names) > 1]
            first = next((k for k in range(len(text)) for p in kin if tuple(text[k:k + len(p)]) == p), None)
            if first is None or text[first - 1:first] not in ([w] for w in FRESH_WORDS):
                lex.fresh_spares.add(spare)
        return lex

    def role_words(self) -> set[str]:
        return {w for p in self.phrases for w in p}

    def attribute_words(self) -> set[str]:
        """Every value of every attribute domain and fixed attribute (singular)."""
        return {singular(v) for d in self.domains.values() for vs in d.values() for v in vs} | {
            singular(v) for attrs in self.fixed.values() for v in attrs.values()}

    def find_mentions(self, toks: list[tuple[str, int, int]]) -> list[Mention]:
        """Longest-match role, room and `floor` mentions; attribute words disambiguate."""
        words = [t[0] for t in toks]
        out: list[Mention] = []
        i = 0
        longest = max((len(p) for p in self.phrases), default=1)
        while i < len(words):
            found: Mention | None = self._shared_head(words, i, longest)
            for n in range(min(longest, len(words) - i), 0, -1) if found is None else ():
                key = tuple(words[i : i + n])
                if key in self.room_phrases and n > 0:
                    if words[i + n : i + n + 1] == ["floor"]:  # "the laundry room floor"
                        found = Mention(("floor",), i, i + n + 1, "floor")
                    else:
                        found = Mention((self.room_phrases[key],), i, i + n, "room")
                    break
                if key in self.phrases:
                    found = Mention(self._disambiguate(self.phrases[key], words, i), i, i + n)
                    break
            if found is None and words[i] == "floor":
                found = Mention(("floor",), i, i + 1, "floor")
            if found is None and words[i] in _ROOM_WORDS and len(self.rooms) == 1 and i > 0 \
                    and words[i - 1] in _THIS_ROOM:
                # "if a hair dryer is found in the room": in a task of one room, "the room" is that
                # room (`offline.placement` reads it alike)
                found = Mention((self.rooms[0],), i, i + 1, "room")
            if found is not None and found.kind == "role" and words[found.end:found.end + 1] and \
                    words[found.end] in TIME_HEADS:
                i = found.end + 1  # "on trash day", "bath time": a time, not the thing
                continue
            if found is not None:
                out.append(found)
                i = found.end
            else:
                i += 1
        return out

    def _shared_head(self, words: list[str], i: int, longest: int) -> Mention | None:
        """"the salt and pepper shakers", "the desk and floor lamps": after a determiner, the
        modifier before "and"/"or" with the next name's head names a thing of its own (when the
        task has one of that name: `offline.naming` names it)."""
        if i < 1 or words[i - 1] not in _SHARED_LEADS or words[i + 1 : i + 2] not in (["and"], ["or"]):
            return None
        for n in range(min(longest, len(words) - i - 2), 1, -1):
            shared = (words[i], *words[i + 3 : i + 2 + n])
            if tuple(words[i + 2 : i + 2 + n]) in self.phrases and shared in self.phrases:
                return Mention(self._disambiguate(self.phrases[shared], words, i), i, i + 1)
        return None

    def _disambiguate(self, candidates: Iterable[str], words: list[str], i: int) -> tuple[str, ...]:
        cands = sorted(candidates)
        if len(cands) == 1:
            return tuple(cands)
        # "a spare roll", "a fresh diaper" (`FRESH_WORDS`): the spare or the one in use of a kind
        spares = [r for r in cands if _spare(r)]
        prev = words[i - 1] if i > 0 else ""
        if spares and len(spares) < len(cands) and (prev in SPARE_WORDS or prev in FRESH_WORDS):
            if prev in SPARE_WORDS or set(spares) <= self.fresh_spares:
                return tuple(spares)
            return tuple(r for r in cands if r not in spares)
        window = set(words[max(0, i - 3) : i])
        picked = [r for r in cands if set(self.fixed.get(r, {}).values()) & window]
        if not picked:
            # "no toilet roll by the toilet" is the roll in use, "the spare roll" the spare: a
            # role named a spare is meant only where a spare word says so
            spare = [r for r in cands if words_of(r)[0] in SPARE_WORDS]
            picked = spare if window & SPARE_WORDS else [r for r in cands if r not in spare]
        return tuple(picked or cands)

    def attribute_of(self, role: str, word: str) -> tuple[str, str] | None:
        """(key, value) when `word` is a value of an attribute domain of the role's category."""
        w = singular(word)
        for key, values in self.domains.get(role, {}).items():
            for v in values:
                if singular(v) == w:
                    return key, v
        return None
