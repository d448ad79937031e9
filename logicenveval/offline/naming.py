"""The offline model's answer to `name_objects`: the objects a description names, read as a
careful reader would list them (the request every method asks first under `--brief description`,
`generators.brief`).

It reads structure, not phrases: noun phrases (longest catalog name or synonym, a bare head noun
resolved by the kind last named, by an adjacent modifier, by its exact name, then by context);
a compound of two names as one object ("the vanity cabinet", "the pet food bag"); a group of
objects of one kind told apart by an enumeration ("two bowls: a food bowl and a water bowl",
"three levels - novels on one, essays on the next", "two toy boxes: red for dolls, white for
toys", "three levels hold novels, essays and other books respectively"); a spare told from the
one in use ("the full bag ... a fresh bag ... no spare bag" is two bags, "a fresh diaper ... if
there isn't one, fetch a spare" is two diapers); "another lamp" after a lamp is a second lamp;
coordinated colours ("a red and a white toy box") one object each. Its word lists are the data
tables below, beside the code that applies them; tests/test_offline_naming.py tries each rule on
sentences of several texts."""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

from lemminflect import getAllLemmas

from logicenveval.domain.catalog import Catalog, Category, load_catalog, per_catalog
from logicenveval.llm.base import ChatRequest
from logicenveval.model.rooms import known_room_type, room_type_of
from logicenveval.offline.clauses import SUBORDINATORS
from logicenveval.offline.handlers import handler
from logicenveval.offline.lexicon import (
    COLOR_WORDS,
    CONTROL_HEADS,
    FUNCTION_WORDS,
    FURNITURE_PARTS,
    ORDER_WORDS,
    PART_TIES,
    RELATIVE,
    SPARE_WORDS,
    TIME_HEADS,
    WORD,
    adjective_only,
    complement_adjective,
    compound_head,
    gerund_of,
    singular,
    tokens,
    verb_at,
    verb_form,
    words_of,
)
from logicenveval.offline.sentences import (
    ARROW,
    DEFINITE_OPENERS,
    FORMS,
    MACHINE_EPITHETS,
    PERSONAL_SUBJECTS,
    RUN_ON_WORDS,
    STATE_WORDS,
    binned,
    expand,
    unquote,
)
from logicenveval.offline.vocabulary import reading_catalog
from logicenveval.offline.wordnet import contents_names, is_wordnet_name, room_words
from logicenveval.scene.compat import can_hold


@handler("name_objects")
def _offline_name_objects(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """The objects the description names, as a careful reader would list them (`name_objects`)."""
    task = payload["task"]
    return {"objects": name_objects(task["description"], load_catalog(), rooms=task.get("rooms", ()))}


#: head nouns that name a part of the thing before them, or the place right by it ("the fridge door",
#: "the lamp cord", "the sink area"): such a compound still names that thing (`modifies_other`)
PART_HEADS = frozenset({"door", "lid", "edge", "side", "top", "bottom", "back", "front", "handle", "cord",
                        "cable", "plug", "shade", "leg", "seat", "arm", "base", "corner", "knob", "button",
                        "screen", "cover", "cap", "strap", "wheel", "rim", "sill", "ledge", "panel", "hinge",
                        "latch", "lock", "filter", "end", "surface", "area", "space", "zone", "inside",
                        "outside", "wall", "floor"})
#: words before a noun that say which one, not what it is like
_ARTICLES = frozenset({"a", "an", "the", "any", "some", "its", "their", "our", "my", "your", "this",
                       "that", "each", "every", "all", "both", "his", "her"})
_DETERMINERS = _ARTICLES | {"no", "one", "other"}
#: the determiners that point back to a thing spoken of
_DEMONSTRATIVE = frozenset({"the", "this", "that"})
#: words after which a bare noun starts a noun phrase as after a determiner ("a nightstand with
#: lamp", "bed, wardrobe and lamp")
_NOUN_LEADS = frozenset({"with", "and", "or", "plus"})
#: prepositions: an item holding one is a clause, not a noun phrase ("are in the kitchen")
_PREPOSITIONS = frozenset({"on", "onto", "in", "into", "inside", "from", "by", "near", "under", "of",
                           "to", "at", "beside", "behind", "with"})
#: prepositions whose object is a noun phrase, with no subject in it (`_Reader.prepositional_object`)
_OBJECT_PREPOSITIONS = _PREPOSITIONS | {"for", "about"}
#: the words of a phrase that says where a thing is, by what it is near ("by the door", "next to
#: the sink", "in front of the fire"): a definite head so placed tells which thing it is
_LOCATING = frozenset({"by", "near", "beside", "behind", "under", "underneath", "beneath", "above", "below",
                       "opposite", "next", "in", "nearest", "closest", "close"})
#: the words that go on such a phrase's first word ("next to", "in front of", "close to")
_LOCATING_LINKS = frozenset({"to", "front", "of"})
#: prepositions of company: "with the spares" after a place says whom a thing joins there
_COMPANY = frozenset({"with", "beside", "among", "amongst", "alongside"})
#: prepositions that put a thing in or on a place ("goes on the shelf", "put it in the drawer")
_PUT_PLACES = frozenset({"on", "onto", "in", "into", "inside"})
#: prepositions of place a dictionary also lists as nouns ("above", "below"): after a part word
#: ("the gable end above the river") they end its noun phrase (`_Text.part_of_other`)
_PLACE_ADVERBS = frozenset({"above", "below", "beneath", "across", "along", "beyond", "opposite", "past"})
#: the linking words and particles of a name made as a phrase ("bag of trash", "chest of drawers",
#: "drying rack for dishes", "washing-up liquid"): no word of what the kind is, so no clue to it in
#: a sentence ("if either of them has ended up on the floor" says nothing of a bag or a washing-up
#: liquid: `_Reader.bare_noun`)
_NAME_LINKS = _PREPOSITIONS | {"for", "up", "down", "out", "off", "over"}
#: words that make a noun phrase indefinite: a thing of its own, not a part of one named
_INDEFINITE = frozenset({"a", "an", "another", "some", "any"})
_COUNTS = {"two": 2, "three": 3, "four": 4, "five": 5, "both": 2, "2": 2, "3": 3, "4": 4, "5": 5}
#: what follows a list item's number ("2. ", "3) "): the number labels the item, it counts nothing
_ITEM_NUMBER = re.compile(r"^[.)]")
#: "a fresh bag": the spare when the kind was already named in use ("the full bag"), else the
#: one in use ("a fresh diaper is lying on the changing table")
_FRESH = frozenset({"fresh", "new"})
#: "a lamp on the desk and another lamp by the bed": a second object of a kind already named
_ANOTHER = frozenset({"another", "second"})
#: words for what a trash bag holds ("a bag of rubbish" is one: `_Reader.other_contents`)
_RUBBISH = frozenset({"trash", "rubbish", "garbage", "refuse", "waste", "litter"})
#: "a bag of pet food", "a pack of wipes", "the pet food bag": the contents are the object
_PACKAGING = frozenset({"bag", "pack", "packet", "carton"})
#: nouns of a group or a quantity that, before "of", name no thing of their own: "a spare set of
#: keys", "a pair of socks", "a bunch of keys" are the keys and the socks ("set" alone is also a
#: television set's last word)
_COLLECTIVES = frozenset({"set", "pair", "bunch", "bundle", "pile", "stack", "heap", "couple"})
#: vessels: a thing one picks up named before one is what it holds, the object as the catalog
#: keeps it ("the detergent bottle" is the detergent, "the soap dish" the soap's): no noun
#: compound whose head names the object (`modifies_next`)
_VESSELS = _PACKAGING | {"bottle", "jar", "tub", "tin", "can", "box", "jug", "tube", "pot", "dish", "sachet"}
#: nouns that are verbs as often ("you can use", "switch it off"): objects only after a determiner
_ALSO_VERBS = frozenset({"can", "throw", "stand", "switch", "set", "press", "iron", "watch", "hook"})
#: verbs of writing something down: a book one does so in ("the log book ... he is to write in
#: it", "a record book", "jot it down in the book") is a book of blank pages for notes, the kind
#: whose own name holds one of them ("notebook", "notepad": `_Reader.written_in`), not a book one
#: reads
_WRITING = frozenset({"write", "jot", "note", "record", "log", "scribble"})
#: words whose count sense the catalog names ("the paper", "today's paper": a newspaper) and whose
#: mass sense is a material (WordNet's first sense of "paper": "a material made of cellulose
#: pulp"): said without a determiner ("'Tis only paper", "Paper: into the recycling") or as the
#: material of a plural noun that names no kind ("the paper drawings", "paper copies"), the thing
#: is a sheet of it, the kind given here (`_Reader.material`)
_MATERIAL_SENSES = {"paper": "document"}
#: nouns that are also a thing's usual place ("put each item in its designated spot", "back in
#: their spot"): after a possessive, with at most one word between, they name a place, no object
_PLACE_SENSES = frozenset({"spot"})
_POSSESSIVES = frozenset({"its", "their", "his", "her", "your", "my", "our"})
#: words that may stand before a colour in a list's item ("one small red scarf", "a large blue
#: towel"): skipped back over to find the colon that opens the list (`_Reader.restates_plain`)
_RESTATING_LEADS = frozenset({"same", "small", "big", "large", "little", "old", "new", "one"})
#: attributes whose values say what a thing is (a toy's kind: doll, car, ball): a bare plural
#: of such a value after the thing is named is a class of it (`_Reader.kind_value`)
KIND_ATTRIBUTES = ("kind",)
#: the openers of a run of parallel sentences that sort things by kind, one kind each ("A novel
#: goes ... A textbook goes ... Any other book goes ..."), and how many sentences a run may take
_RUN_OPENERS = frozenset({"a", "an", "any", "every", "each"})
#: determiners of a singular that may stand for its whole class ("a doll", "every doll goes into
#: the red box")
_GENERIC_ONE = frozenset({"a", "an", "every", "each"})
_RUN = 4
#: the prepositions before which a room word that also names its fixture (WordNet's room sense of
#: the toilet: "lavatory", "washroom", "loo"; `offline.wordnet.room_words`) is the room: a place
#: something is in, goes into or to, or comes from ("in the lavatory", "go to the loo")
ROOM_PLACE_LINKS = frozenset({"in", "into", "inside", "to", "from", "at", "through"})
#: head nouns a speaker puts in place of a thing's name they do not reach for ("the drying thing",
#: "the ironing whatsit"): after the -ing form that opens one kind's two-word name they stand for
#: that name's head (`_Reader.placeholder`)
PLACEHOLDER_HEADS = frozenset({"thing", "thingy", "thingie", "whatsit", "gadget", "contraption", "doodah",
                               "thingamajig", "thingummy"})
#: what follows "the <word> thing" when it is a matter, not a thing ("the drying thing is that it
#: takes a week", "the ironing thing about Sundays")
_MATTER_AFTER = frozenset({"about", "that", "is", "was", "with"})
#: words whose sense in a regional variety of English is another catalog kind than the one they
#: name elsewhere, with the words that mark a text as written in that variety (each found in
#: that variety only): (marks, {word: kind}). Dictionary senses: in Australian and New Zealand
#: English "bench" is a kitchen worktop (Oxford English Dictionary; Macquarie Dictionary); the
#: marks "arvo" (afternoon), "jandal" (flip-flop), "chilly bin" (cool box), "servo" (petrol
#: station), "chur" (thanks), "kia ora" (hello) are Australian or New Zealand words (Oxford
#: Dictionary of New Zealand English; Macquarie Dictionary)
REGIONAL_SENSES: tuple[tuple[frozenset[str], dict[str, str]], ...] = (
    (frozenset({"arvo", "jandal", "chilly bin", "servo", "chur", "kia ora"}),
     {"bench": "kitchen_counter"}),
)
#: a head noun several kinds share, with no kind of its own name, and the kind it names in general
#: use (a dictionary's first sense): a "table" is "a piece of furniture with a flat top ... used for
#: such purposes as eating, writing, working, or playing games" (Oxford), the catalog's dining
#: table; a bedside, coffee, console, side or changing table is named for a use or place of its
#: own. A "box" is "a container with a flat base and sides ... for holding or storing things"
#: (Oxford): the catalog's storage box, where a cardboard box is named for its material and a toy
#: box for its use. Read when the text names its own sort by a modifier no kind's name holds ("the
#: card table", "a trestle table", "the folding table", "the lost property box", "the props box":
#: `_Reader.bare_noun`)
HEAD_SENSES = {"table": "dining_table", "box": "storage_box"}
#: the sort an adjective describes a `HEAD_SENSES` head as, as the dictionary defines the catalog's
#: other sorts ("side table: a small table", "coffee table: a low table", "occasional table: a small
#: table"; Oxford): a head so described is that sort where the task's rooms do not tell
#: (`_Reader.bare_noun`)
SORT_SENSES = {("small", "table"): "side_table", ("little", "table"): "side_table",
               ("tiny", "table"): "side_table", ("occasional", "table"): "side_table",
               ("low", "table"): "coffee_table"}
#: those adjectives: a head described by one ("the small table by the bed") is no more the general
#: sense than a bare one, where one described by another ("a sturdy table", "the long table") is
SORT_ADJECTIVES = frozenset(adjective for adjective, _ in SORT_SENSES)
#: words that open or shut a thing, or name what does: a sort the catalog cannot open is not the
#: thing they are said of (`_Reader.bare_noun`)
_OPENING = frozenset({"open", "opened", "close", "closed", "shut", "lid", "flap"})

#: fixed expressions of general English in which a catalog kind's word names no thing (idioms a
#: dictionary of idioms lists, and compounds of another sense): as the text writes them, each word
#: singular, a verb by its lemma. Their words name nothing (`_Reader.fixed`): "bar none", "threw in
#: the towel", "outside the box", "a box-office hit", "a sink or swim moment". Only expressions a
#: room's text cannot mean literally are listed: "under the table", "by the book", "in my book",
#: "an open book", "on the clock", "turn the table", "have a ball", "drop the ball" also say where a
#: real thing is or what is done with it ("the dog is asleep under the table", "the key is by the
#: book on the shelf", "the cat is on the ball"), so they are not
FIXED_EXPRESSIONS: tuple[tuple[str, ...], ...] = (
    ("bar", "none"), ("raise", "the", "bar"), ("set", "the", "bar"),
    ("hit", "the", "book"), ("cook", "the", "book"),
    ("outside", "the", "box"), ("box", "office"), ("tick", "the", "box"), ("tick", "a", "box"),
    ("sink", "or", "swim"), ("but", "the", "kitchen", "sink"),
    ("throw", "in", "the", "towel"),
    ("get", "the", "ball", "rolling"), ("start", "the", "ball", "rolling"), ("keep", "the", "ball", "rolling"),
    ("glass", "ceiling"),
    ("on", "the", "safe", "side"), ("safe", "bet"), ("safe", "and", "sound"),
    ("in", "light", "of"), ("shed", "light", "on"), ("come", "to", "light"), ("green", "light"),
    ("make", "light", "of"),
    ("around", "the", "clock"), ("round", "the", "clock"), ("against", "the", "clock"),
    ("cup", "final"), ("world", "cup"), ("cup", "tie"),
    ("kettle", "of", "fish"), ("go", "to", "pot"), ("pot", "luck"),
    ("mirror", "image"), ("bed", "of", "rose"),
    ("a", "fan", "of"), ("big", "fan", "of"), ("huge", "fan", "of"),
)
#: words naming an animal kept at home, as the catalog's kinds for one are named ("pet bowl",
#: "dog bowl", "cat bed") and as a text names the animal ("the cat flap", "walk the dog")
ANIMAL_WORDS = frozenset({"pet", "dog", "cat", "puppy", "kitten", "rabbit", "hamster", "guinea",
                          "budgie", "parrot", "tortoise", "ferret"})
#: what an animal's bowl holds ("the water bowl", "a bowl of food": `animal_kind`)
FEED_WORDS = frozenset({"water", "food", "feed", "drinking", "feeding", "kibble", "biscuit"})
#: the words that open a clause or phrase saying what the thing before them is for ("the towel
#: you dry your hands on", "the towel wherewith the brethren dry their hands", "a bottle for the
#: pills"): relative words, the subject pronouns of a contact clause, "for" (`_Reader.use_clause`)
USE_OPENERS = frozenset({"that", "which", "wherewith", "wherein", "whereon", "where", "for",
                         "you", "we", "they", "i", "he", "she", "people", "everyone"})
#: how many words of such a clause are read: a clause of use is short
_USE_SPAN = 8

#: the words that may stand between a noun and "on the floor" in its own phrase, saying where the
#: thing stands ("the bowl, which sits on the floor", "a lamp that stands on the floor"): a
#: relative word and a verb of standing, never a verb of action ("put the bowl on the table and
#: mop the floor", "the bowl fell on the floor" say where it went, not what kind it is)
FLOOR_LINKS = frozenset({"which", "that", "is", "sits", "sit", "stands", "stand", "lives", "live", "stays", "stay",
                         "lies", "lie"})
#: deeds only people do to a thing, as written: leaving it somewhere or so, forgetting it (a thing
#: "drops", "is lost", "comes on" or "says" a time too, so those are none); with the thing after
#: them (`_DEED_OBJECTS`), their subject is a person (`_Reader.person_subject`)
PERSON_DEEDS = frozenset({"leave", "leaves", "left", "forget", "forgets", "forgot"})
#: what such a deed's object opens with ("left it on", "forgot to switch", "leaves the door open"):
#: without one, "left" is a participle of the thing ("Was the lamp left on?")
_DEED_OBJECTS = frozenset({"it", "them", "the", "a", "an", "his", "her", "their", "my", "our", "your", "this",
                           "that", "to"})
#: what may stand between such a subject and its deed ("the cleaners have always left it on")
_PERSON_DEED_LINKS = frozenset({"have", "has", "had", "always", "never", "often", "usually", "sometimes",
                                "will", "may", "might", "did", "do", "does"})
#: the nouns of the floor said as the place a thing stands on
FLOOR_WORDS = frozenset({"floor", "ground"})
#: verbs of being and of standing, as written, after which a learner's English may leave out the
#: article of the thing that is or stands ("On piano is standing small lamp": `_Reader.modified`)
_BEING = frozenset({"is", "are", "was", "were", "stands", "standing", "sits", "sitting", "lies", "lying",
                    "hangs", "hanging"})
#: the floor as `_Reader.stood_on` gives it: the support every room has, no catalog kind
FLOOR = "floor"
#: words too common to say which of several categories a bare noun means
_NOT_CONTEXT = frozenset({"floor", "wall", "ceiling", "room"})
#: "that is a ...", "it was a ...": a predicate noun of a thing already named (`predicate_noun`)
#: words before an indefinite subject that still open its clause ("Then a drawer slams")
_OPENING_ADVERBS = frozenset({"then", "later", "suddenly", "now", "meanwhile", "somewhere", "again"})
_POINTERS = frozenset({"that", "it", "this", "which"})
_COPULAS = frozenset({"is", "was"})
#: the pronouns that take up a thing named before (`_Reader.heading_spare`)
_THING_PRONOUNS = frozenset({"it", "its", "they", "them", "their"})
#: words that open a clause of their own inside a sentence: where the kinds said near a head
#: stop (`_Reader.kinds_said_near`)
_CLAUSE_LINKS = SUBORDINATORS | {"and", "but", "or", "so", "then", "because", "while"}
#: verbs that, right after a noun phrase, make it the subject of a clause of its own
#: (`_Reader.renamed_fuller`)
_CLAUSE_VERBS = frozenset({"is", "was", "are", "were", "has", "had", "goes", "lives", "sits", "stands", "lies",
                           "stays", "belongs", "needs", "should", "must", "will", "can", "may", "might"})
#: verbs after a subject that say where it is or what it is ("The treasure map be on the table",
#: "The rota is on the fridge door", "The card lives in the drawer": `unnamed_subject`)
_SUBJECT_VERBS = frozenset({"is", "was", "be", "are", "lives", "sits", "stands", "lies", "stays"})
#: words naming a part of a piece of furniture that holds things, and the kind each part is
_PARTS = {"level": "shelf", "tier": "shelf", "shelf": "shelf"}
#: words that rank parts or say which one ("on the next", "the top one")
_ORDINALS = frozenset({"first", "second", "third", "fourth", "next", "last", "top", "middle", "bottom",
                       "upper", "lower", "left", "right", "other", "one", "front", "back"})
#: ordinals of a series of events or rounds: "the last game", "the next game" (`_Reader.head_alone`)
_SERIES = frozenset({"first", "second", "third", "next", "last", "final", "previous"})
#: prepositions placing a person at a place: "behind the bar", "at the bar" (`_Reader.head_alone`)
_STANDING_AT = frozenset({"behind", "at"})
#: verbs that lead a list of what each part holds ("three levels hold novels, essays and ...")
_HOLDING = frozenset({"hold", "keep", "store", "contain", "take", "carry", "be", "are", "is", "for"})
#: words of an item that say nothing of which one it is
_FILLER = frozenset({"respectively", "one", "and", "or", "then", "also", "each", "s", "is", "are",
                     "kept", "stored", "go", "goes", "put", "placed", "shelved"})
#: what separates the items of an enumeration
_ITEM_BREAK = re.compile(r"[,;:(]|\s-+\s|\u2013|\u2014")
#: what ends a heading a list follows ("Bookshelf levels: top for novels, ...")
_HEADING = re.compile(r":|\s-+\s|\u2013|\u2014")
_SENTENCE_END = re.compile(r"[.!?]|\n")
#: a person's name as a possessive before a noun ("Marco's glass", "Priya's cup"): capitalised,
#: since "the dog's bowl" or "the lamp's switch" own nothing
_POSSESSOR = re.compile(r"\b([A-Z][a-z]+)'s\s+[a-z]")
#: a word and its possessive ending before the next word ("Dad's", "the dogs'"): a possessive
#: where `expand` drops the ending, a contraction where it reads "is" or "has" (`_possessives`)
_POSSESSIVE = re.compile(r"\b([A-Za-z]+?)(?:'s|s')\s+[A-Za-z]+")
#: a number as written, and what may end the reading a label and a number make ("bar 1016,")
_NUMBER = re.compile(r"\d+")
_READING_END = re.compile(r"\s*(?:[,;.]|\n|$)")
#: what may stand between the two halves of one word written as two (`_Reader.closed_match`): a
#: hyphen ("piano-forte") or one space ("tooth brush"), never a line break or other punctuation
COMPOUND_JOINS = frozenset({"-", " "})
#: punctuation no name runs across (a hyphen inside a word does not count: "toy-box")
_BREAK = re.compile(r"[,;:.!?()\u2013\u2014\n]|\s-|-\s")


@dataclass
class _Kind:
    """What the description says of one category: generic mentions and told-apart instances."""

    generic: bool = False
    count: int = 0
    #: (name, attributes) of each instance, in order of first mention
    instances: dict[str, dict[str, str]] = field(default_factory=dict)


@dataclass
class _Text:
    """The description as words: singular forms, the words as written, and what stands between
    a word and the one before it (punctuation tells items and sentences apart)."""

    words: list[str]
    raw: list[str]
    gaps: list[str]

    @cached_property
    def said(self) -> frozenset[str]:
        """Every word of the text (singular forms), once: what the rules asking whether the text
        says a word anywhere (`_Reader.marked`, `_Reader.animal_kind`) look in."""
        return frozenset(self.words)

    def part_of_other(self, k: int) -> bool:
        """Whether word `k` names a part of another thing: of what follows it ("at the end of the
        night", "the top of the fridge") or of what its own modifier names ("the gable end", "the
        north side", "the far end", a noun phrase the part word heads): no word of a thing's name
        there ("end table", "side table"), as `_Reader.bare_noun` reads the text's words for hints.
        A part word after a determiner alone ("at the side", "the end table") may still be one."""
        if self.words[k] not in PART_HEADS:
            return False
        if self.words[k + 1:k + 2] == ["of"]:
            return True
        before = self.words[k - 1] if k > 0 and self.gaps[k] == " " else ""
        modified = before.isalpha() and before not in _DETERMINERS and before not in _NAME_LINKS
        # the phrase ends at the part word: a break or a word no noun after it, not a noun it
        # modifies ("the gable end above the river", not "a low end table")
        ends = k + 1 == len(self.words) or self.gaps[k + 1] != " " or self.words[k + 1] in _NAME_LINKS \
            or self.words[k + 1] in _PLACE_ADVERBS or "NOUN" not in getAllLemmas(self.raw[k + 1])
        return modified and ends

    def sentence_end(self, i: int) -> int:
        """Index of the first word of the next sentence after word `i`."""
        j = i + 1
        while j < len(self.words) and not _SENTENCE_END.search(self.gaps[j]):
            j += 1
        return j

    def sentence_start(self, i: int) -> int:
        j = i
        while j > 0 and not _SENTENCE_END.search(self.gaps[j]):
            j -= 1
        return j

    def items(self, start: int, end: int) -> list[tuple[int, int]]:
        """Word spans of the items of a list between `start` and `end` (split at commas,
        semicolons, colons, dashes, "and" and "or")."""
        out: list[tuple[int, int]] = []
        a = start
        for j in range(start, end + 1):
            if j == end or j > a and (_ITEM_BREAK.search(self.gaps[j]) or self.words[j] in ("and", "or")):
                if j > a:
                    out.append((a, j))
                a = j + 1 if j < end and self.words[j] in ("and", "or") else j
        return out


@per_catalog
def _control_kinds(catalog: Catalog) -> dict[str, tuple[str, ...]]:
    """The two-word control kinds by the thing they work ("light" -> ("light_switch",)): a head
    in `CONTROL_HEADS` after the word."""
    out: dict[str, tuple[str, ...]] = {}
    for c in catalog.categories:
        w = words_of(c)
        if len(w) == 2 and w[1] in CONTROL_HEADS:
            out[w[0]] = (*out.get(w[0], ()), c)
    return out


def _plural_kind_name(category: str, word: str) -> bool:
    """Whether the kind's own name is the plural of `word` ("glasses" of "glass", "scissors"): a
    plurale tantum, never meant by the singular (a kind only a synonym names in the plural, the
    document's "papers", is still "paper")."""
    head = category.split("_")[-1]
    return head != word and singular(head) == word


@per_catalog
def _phrase_tables(catalog: Catalog) -> tuple[dict[tuple[str, ...], str], dict[str, list[str]], int]:
    """Each category name and synonym as words -> its category; head noun -> the categories it
    heads; the longest phrase's length: ~500 names, the same for every description the process
    reads. Callers only read them."""
    phrases: dict[tuple[str, ...], str] = {}
    heads: dict[str, list[str]] = {}
    # a name written as its words' lemmas ("glass") wins its phrase over a name singularised
    # into it ("glasses", the spectacles): "Marco's glass" is a drinking glass
    for name, cat in catalog.categories.items():
        for text in (name, *cat.synonyms):
            if _lemma_named(text):
                phrases.setdefault(words_of(text), name)
    for name, cat in catalog.categories.items():
        for text in (name, *cat.synonyms):
            phrase = words_of(text)
            phrases.setdefault(phrase, name)
            if is_wordnet_name(text):
                continue  # a last-resort name: matched whole, lends no head noun
            # the head noun: the last word, or the one before "of" ("chest of drawers" is a chest)
            heads.setdefault(phrase[phrase.index("of") - 1] if "of" in phrase[1:] else phrase[-1], []).append(name)
    # an English compound is written open, hyphenated or closed ("air con", "air-con", "aircon";
    # "log book", "logbook"): a two-word catalog name (not a WordNet name) is also its closed
    # form, after every name of its own, so a closed form that is a name keeps its kind
    for name, cat in catalog.categories.items():
        for text in (name, *_own(cat)):
            phrase = words_of(text)
            if len(phrase) == 2 and "of" not in phrase:
                closed = singular("".join(phrase))
                if (closed,) not in phrases and closed not in heads:
                    phrases[(closed,)] = name
    return phrases, heads, max(len(p) for p in phrases)



@per_catalog
def _use_kinds(catalog: Catalog) -> dict[str, set[str]]:
    """First word -> the kinds whose name (the catalog's own, of two words) it opens, for a verb's
    -ing form that is no name of its own: the use the name says ("drying": the drying rack;
    "ironing": the ironing board). An adjective ("the easy thing") or a noun ("the room thing")
    before a placeholder says no use; a synonym's participle often says how the thing is, not
    what it is for ("floating shelf", "standing lamp": "the floating thing" is no shelf), so only
    the kind's own name is taken.
    Built once per catalog; callers only read it."""
    phrases = _phrase_tables(catalog)[0]
    out: dict[str, set[str]] = {}
    for name in catalog.categories:
        phrase = words_of(name)
        if len(phrase) == 2 and (phrase[0],) not in phrases and gerund_of(phrase[0]):
            out.setdefault(phrase[0], set()).add(name)
    return out


#: the determiners that open a phrase renaming the thing just named (`_Reader.appositive`): "the"
#: after a comma or a bracket, a possessive too between dashes
_RENAMING_DETERMINERS = DEFINITE_OPENERS
#: the words that name the complement of a colour as a class ("a coloured shirt", `color_class`)
_COMPLEMENT_COLORS = frozenset({"coloured", "colored"})
#: the nouns of colour after "other" ("a towel of any other colour")
_COLOR_NOUNS = frozenset({"colour", "colours", "color", "colors"})
#: a dash set between words, as a gap holds it (" - ", " – ", " — ")
_DASH_GAP = re.compile(r"\s[-\u2013\u2014]\s|[\u2013\u2014]")


def _same_sort(a: Category, b: Category) -> bool:
    """Whether two kinds are things of one sort, as the catalog describes them: where they stand
    and whether they hold things on or in them (a desk and a dining table; not a desk and a lamp)."""
    return (tuple(a.placement), a.surface, a.container) == (tuple(b.placement), b.surface, b.container)


class _Reader:
    """One reading of one description (the state `name_objects` builds up word by word)."""

    def __init__(self, description: str, catalog: Catalog, rooms: Iterable[str]) -> None:
        self.catalog = catalog
        self.phrases, self.heads, self.longest = _phrase_tables(catalog)
        self.controls = _control_kinds(catalog)
        text = expand(binned(unquote(description)))
        toks = tokens(text)
        raw = [text[a:b].lower() for _, a, b in toks]
        gaps = [text[toks[k - 1][2] if k else 0:toks[k][1]] for k in range(len(toks))]
        # a line that ends on a word that cannot end a clause (verse, a form's wrapped field:
        # "hold novels, essays, and / all other books") goes on on the next line: no sentence end
        gaps = [" " if k and "\n" in g and not g.strip() and raw[k - 1] in RUN_ON_WORDS else g for k, g in enumerate(gaps)]
        self.text = _Text([w for w, _, _ in toks], raw, gaps)
        #: the words written with a capital first letter (`line_of_its_own`: a new line's sentence)
        self.capitalised = frozenset(k for k, (_, a, _) in enumerate(toks) if text[a:a + 1].isupper())
        #: every word written as a possessive before another ("Today's brew sheet", "the chef's
        #: prep sheet"; not "the kettle's still on", which `expand` reads as "is"): it stands where
        #: an article does (`modified`, `leads_noun`)
        self.possessives = _possessives(description)
        self.fixed = self._fixed_expressions()
        self.named: set[str] = set()  # kinds named outright (by a full name or synonym)
        self.context = self._context()
        self.room_types = {room_type_of(r) for r in rooms}
        #: the room types the room ids name (not the fallback of an id naming none, "fitness_room"):
        #: what tells a bare noun's kinds apart by the rooms they belong in (`bare_noun`)
        self.known_room_types = {t for t in map(known_room_type, rooms) if t is not None}
        #: the head words of the task's room ids ("home_bar": "bar"): a bare noun that names no
        #: kind by itself and is one of them names the room ("tidy the home bar", "Re: the bar")
        self.room_heads = {words_of(r)[-1] for r in rooms if words_of(r)}
        #: the words of the task's room ids ("laundry_room": laundry, room): said in full they name
        #: the room, not the kind their first words name ("the laundry room" holds no laundry)
        self.room_ids = {words_of(r) for r in rooms if len(words_of(r)) > 1}
        self.kinds: dict[str, _Kind] = {}
        self.recent: list[str] = []  # kinds in order of their last mention
        #: kind -> the head nouns the text named it by ("the box" then means the red toy box)
        self.used: dict[str, set[str]] = {}
        self.consumed: set[int] = set()  # words an enumeration has read
        self.first_at: dict[str, int] = {}  # kind -> the word its first plain reading starts at
        #: people named as owners ("Marco's glass": `expand` drops the "'s", so they are read
        #: off the text as written) and, per kind, the owners of its mentions in order
        self.possessors = {m.group(1).lower() for m in _POSSESSOR.finditer(description.replace("\u2019", "'"))}
        self.owners: dict[str, list[str]] = {}
        #: kinds named at least once as a particular thing (after a determiner or a count, or in
        #: the singular), not only by a bare plural (`class_of_named`)
        self.particular: set[str] = set()
        #: word -> kind, for the words a regional variety the text is written in gives another
        #: sense (`REGIONAL_SENSES`); such a kind's object is named by the word ("bench")
        said = " " + " ".join(self.text.words) + " "
        self.senses = {word: kind for marks, senses in REGIONAL_SENSES
                       if any(f" {mark} " in said for mark in marks) for word, kind in senses.items()
                       if kind in catalog.categories}
        self.said_as: dict[str, str] = {}
        #: the kinds whose `said_as` a bracket gave (`glossed`: "the chart table (the little desk ...)")
        self.glossed_as: set[str] = set()
        #: kind -> the colour "it is the red one" gives its one object
        self.colors: dict[str, str] = {}
        #: the head word of "the <part> of the <N>" -> the part ("the lower shelf of the metal
        #: rack": a rack with shelves, `part_said_of`)
        self.part_for: dict[int, str] = {}
        #: kind -> whether every plain mention of it so far was a heading of its own ("3. The
        #: folder.", "Mug:"), which a later coloured mention names again (`heading_mention`)
        self.headed: dict[str, bool] = {}
        #: kinds whose one coloured instance restates a plain mention made before it (`restates_plain`)
        self.restated: set[str] = set()
        #: part kind -> the furniture the text named it as a part of ("the nightstand drawer"),
        #: whose part a later "the drawer" is (`part_said_again`)
        self.part_holders: dict[str, set[str]] = {}

    def _fixed_expressions(self) -> frozenset[int]:
        """The words of the text's fixed expressions (`FIXED_EXPRESSIONS`), within one stretch of
        words without punctuation but a hyphen ("a box-office hit"): they name no thing."""
        words, raw, gaps = self.text.words, self.text.raw, self.text.gaps
        lemmas: dict[int, tuple[str, ...]] = {}

        def fits(k: int, word: str) -> bool:
            if words[k] == word:
                return True
            if k not in lemmas:
                lemmas[k] = getAllLemmas(raw[k], upos="VERB").get("VERB", ())
            return word in lemmas[k]

        out: set[int] = set()
        for i in range(len(words)):
            for expression in FIXED_EXPRESSIONS:
                n = len(expression)
                if i + n <= len(words) and all(fits(i + k, w) and (k == 0 or gaps[i + k] in COMPOUND_JOINS)
                                               for k, w in enumerate(expression)):
                    out.update(range(i, i + n))
        return frozenset(out)

    # -- noun phrases ----------------------------------------------------------------------

    def names_kind(self, k: int) -> bool:
        """Whether word `k` is the head of a kind's name ("towel", "box") or opens a catalog name
        there ("coffee table"): a noun of the task's world, no modifier or verb."""
        return self.text.words[k] in self.heads or self.match(k)[1] is not None

    def match(self, i: int) -> tuple[int, str | None]:
        """(length, category) of the longest catalog name starting at word `i`, within one
        stretch of words without punctuation ("the floor is wet, mop it" names no wet mop)."""
        words, gaps = self.text.words, self.text.gaps
        if i in self.fixed:  # "bar none", "threw in the towel": no thing
            return 1, None
        stretch = next((k for k in range(i + 1, len(words)) if _BREAK.search(gaps[k])), len(words)) - i
        found = next(((n, self.phrases[tuple(words[i:i + n])])
                      for n in range(min(self.longest, len(words) - i, stretch), 0, -1)
                      if tuple(words[i:i + n]) in self.phrases), (1, None))
        closed = self.closed_match(i, stretch) or self.vessel_of(i, stretch) or self.contents_vessel(i, stretch)
        found = closed if closed is not None and closed[0] > found[0] else found
        if found[0] < 2 and stretch >= 2 and (by_synonym := self.head_by_synonym(i)) is not None:
            found = by_synonym
        if found[1] is None:
            return self.placeholder(i, stretch) or found
        return (found[0], None) if self.room_as_place(i, found[0]) else found

    def head_by_synonym(self, i: int) -> tuple[int, str] | None:
        """(2, kind) when word `i` and the next make a kind's two-word name with the next said by a
        synonym of its head: "the wall cupboard" is the wall cabinet, "the TV cupboard" the TV
        cabinet, "the bedside cupboard" the bedside cabinet, as "cupboard" is a name of the
        cabinet, "the medicine cupboard" the medicine cabinet; the synonym must name its kind
        outright, and the modifier must make a name with that kind's own head ("the kitchen
        cupboard" is a cupboard)."""
        words = self.text.words
        synonym = self.phrases.get((words[i + 1],))
        kind = self.named_with(words[i], synonym) if synonym is not None else None
        return None if kind is None else (2, kind)

    def named_with(self, modifier: str, category: str, placement: str | None = None) -> str | None:
        """The kind other than `category` whose two-word name is `modifier` and the head of one of
        `category`'s own names ("wall" and "cabinet": the wall cabinet), and, with `placement`,
        that the catalog places there (`head_by_synonym`, `wall_sibling`)."""
        for text in (category, *_own(self.catalog.categories[category])):
            kind = self.phrases.get((modifier, words_of(text)[-1]))
            if kind is not None and kind != category and (
                    placement is None or placement in self.catalog.categories[kind].placement):
                return kind
        return None

    def wall_sibling(self, k: int, category: str) -> str | None:
        """The kind hung on a wall that `category`'s thing is when its own phrase, from word `k`,
        says it hangs there: "on the wall", or "over" / "above" another thing ("the cupboard over
        the kettle", "the cabinet on the wall by the door"): the kind whose name is "wall" and
        the name's head (`Category.placement` "wall": the wall cabinet), where the catalog has one;
        a cupboard under or by something stays a cupboard."""
        words, gaps = self.text.words, self.text.gaps
        if k + 2 >= len(words) or any(gaps[j] != " " for j in (k, k + 1, k + 2)):
            return None
        if not (words[k:k + 3] == ["on", "the", "wall"] or words[k] in ("over", "above") and words[k + 1] in _ARTICLES):
            return None
        return self.named_with("wall", category, placement="wall")

    def placeholder(self, i: int, stretch: int) -> tuple[int, str] | None:
        """(2, kind) when word `i`, naming no kind itself, opens the two-word own name of one kind
        only and a placeholder head follows it (`PLACEHOLDER_HEADS`): "the drying thing" is the
        drying rack, "the ironing whatsit" the ironing board, "the watering thingy" the can.
        A speaker names the thing by its use and leaves the head out; the use word opening a
        name of several kinds ("the washing thing": a machine or a powder) says none, and a
        matter ("the drying thing is that it takes a week") is no thing."""
        words = self.text.words
        if stretch < 2 or words[i + 1] not in PLACEHOLDER_HEADS or self.text.gaps[i + 1] != " ":
            return None
        if i + 2 < len(words) and words[i + 2] in _MATTER_AFTER:
            return None
        kinds = _use_kinds(self.catalog).get(words[i], set())
        return (2, next(iter(kinds))) if len(kinds) == 1 else None

    def room_as_place(self, i: int, n: int) -> bool:
        """Whether the `n` words at `i` are a room word of a fixture's (`ROOM_PLACE_LINKS`'s
        note: "the lavatory", "the washroom") said as the place something is in or goes to ("the
        soap is in the lavatory", "go to the loo"): the room, no thing; "the lav is blocked",
        "clean the washroom's lavatory" and "sat on the loo" name the fixture."""
        if " ".join(self.text.words[i:i + n]) not in room_words():
            return False
        k = i - 1
        while k >= 0 and self.text.words[k] in _DETERMINERS | _POSSESSIVES:
            k -= 1
        return k >= 0 and self.text.words[k] in ROOM_PLACE_LINKS

    def vessel_of(self, i: int, stretch: int) -> tuple[int, str] | None:
        """(length, category) of "<vessel> of <contents>" at word `i` when "<contents> <vessel>" is
        a catalog name: "a bottle of water" is a water bottle, "the bottle of wine" a wine bottle,
        "a box of tissues" a tissue box, "a bottle of pills" a pill bottle. English writes
        the compound either way round; the catalog lists one. The contents are the words after
        "of" (and an article) up to the stretch's end, read whole: "a bottle of dish soap" is no
        soap bottle. Contents that name a kind one of whose names is "<X> <vessel>" are that
        kind too: "a bottle of red wine", "a bottle of vermouth" (WordNet names of the wine bottle,
        "wine bottle"), one object, where "a bottle of milk" (a milk carton) and "a box of books"
        stay a vessel and its contents."""
        words = self.text.words
        if stretch < 3 or words[i] not in _VESSELS or words[i + 1] != "of":
            return None
        j = i + 2 + (words[i + 2] in _ARTICLES)
        if j >= i + stretch:
            return None
        whole = next(((j + n - i, self.phrases[(*words[j:j + n], words[i])])
                      for n in range(min(self.longest - 1, i + stretch - j), 0, -1)
                      if (*words[j:j + n], words[i]) in self.phrases), None)
        if whole is not None:
            return whole
        n, kind = self.match(j)
        if kind is None:
            held = self.held_by(j, words[i], i + stretch)
            return None if held is None else (held[0] + j - i, held[1])
        if not any(words_of(text)[-1] == words[i] for text in (kind, *_own(self.catalog.categories[kind]))):
            return None
        return j + n - i, kind

    def of_its_place(self, i: int, category: str | None) -> str | None:
        """The kind named "<place> <thing>" when the one-word name at word `i` (of `category`, or of
        several kinds: "the lamp") is
        followed by "from" or "of" and a definite one-word place ("the pillow from the sofa" is a
        sofa pillow, "the mat from the bathroom" a bathroom mat, "the lamp of the desk" a desk
        lamp): English says a compound's modifier after its head as a place the thing comes from,
        as `vessel_of` reads "a bottle of water" a water bottle, and the catalog lists the
        compound. The place stays a thing of its own (the sofa is named too); a place that is no
        compound's modifier ("the pillow from the bed": a bed pillow is a pillow), a longer place
        ("from the sofa bed") or an owner ("the pillow of my sister") names the thing's own kind."""
        words, gaps = self.text.words, self.text.gaps
        j = i + 3
        if j >= len(words) or words[i + 1] not in ("from", "of") or words[i + 2] not in ("the", "this", "that") \
                or any(_BREAK.search(gaps[k]) for k in range(i + 1, j + 1)):
            return None
        if j + 1 < len(words) and not _BREAK.search(gaps[j + 1]) and (words[j + 1] in self.heads or self.match(j)[0] > 1):
            return None  # "from the sofa bed", "of the coffee table": the place goes on
        # the place as written ("the bathroom") or by its kind's own name ("the couch": a sofa)
        place = self.match(j)[1]
        said = [words[j], *([place] if place is not None and len(words_of(place)) == 1 else [])]
        kind = next((self.phrases[(w, words[i])] for w in said if (w, words[i]) in self.phrases), None)
        return kind if kind is not None and kind != category else None

    def held_by(self, j: int, vessel: str, end: int) -> tuple[int, str] | None:
        """(length, kind) of the WordNet contents word at word `j` (`contents_names`: "claret",
        "champagne", "pinot noir") when `vessel` heads a name of the kind that holds it: "a
        bottle of claret" and "the merlot bottle" are wine bottles, where "a glass of claret"
        names no bottle and "claret" alone names nothing."""
        words = self.text.words
        for n in range(min(3, end - j), 0, -1):
            kind = contents_names().get(" ".join(words[j:j + n]))
            if kind is not None and kind in self.catalog.categories and any(
                    words_of(text)[-1] == vessel for text in (kind, *_own(self.catalog.categories[kind]))):
                return n, kind
        return None

    def contents_vessel(self, i: int, stretch: int) -> tuple[int, str] | None:
        """(length, kind) of "<contents> <vessel>" at word `i` for WordNet contents
        (`held_by`): "the merlot bottle", "a champagne bottle" are wine bottles."""
        words = self.text.words
        for n in range(min(3, stretch - 1), 0, -1):
            if self.text.gaps[i + n] == " " and words[i + n] in _VESSELS:
                held = self.held_by(i, words[i + n], i + n)
                if held is not None and held[0] == n:
                    return n + 1, held[1]
        return None

    def closed_match(self, i: int, stretch: int) -> tuple[int, str] | None:
        """(length, category) of the longest catalog name starting at word `i` when words `i` and
        `i + 1` are one word written hyphenated or open (`COMPOUND_JOINS`) where the catalog
        writes it closed: "the piano-forte" (the pianoforte), "the tooth brush", "the bed-side
        table" (the bedside table). An English compound is written all three ways; the catalog
        lists one. Only a longer reading than the words as written give is taken (`match`)."""
        words, gaps, raw = self.text.words, self.text.gaps, self.text.raw
        if stretch < 2 or gaps[i + 1] not in COMPOUND_JOINS or not raw[i].isalpha() or not raw[i + 1].isalpha():
            return None
        joined = singular(raw[i] + raw[i + 1])
        return next(((n + 1, self.phrases[(joined, *words[i + 2:i + 1 + n])])
                     for n in range(min(self.longest, len(words) - i - 1, stretch - 1), 0, -1)
                     if (joined, *words[i + 2:i + 1 + n]) in self.phrases), None)

    def leads_noun(self, i: int, strict: bool = False) -> bool:
        """Whether word `i` stands where a noun phrase starts: after a determiner (a possessive
        too), a colour or a count, or (unless `strict`: a word that is as often a verb) at the start of a sentence or
        list item or after "with", "and"."""
        lead = self.compound_start(i)
        prev = self.text.words[lead - 1] if lead > 0 else ""
        # (a possessive whose "'s" `expand` dropped is a determiner: "Sam's throw", "the kids' throw")
        if prev in _DETERMINERS or prev in COLOR_WORDS or prev in _COUNTS or prev in self.possessives:
            return True
        return not strict and (i == 0 or prev in _NOUN_LEADS or bool(
            _ITEM_BREAK.search(self.text.gaps[i]) or _SENTENCE_END.search(self.text.gaps[i])))

    def compound_start(self, i: int) -> int:
        """The first word of a hyphenated modifier right before word `i` ("the check-in
        computer", "the lost-property cart", "an end-of-day list"), else `i`: such a modifier
        stands between a determiner and its noun as one adjective does."""
        gaps = self.text.gaps
        k = i - 1
        if k < 1 or gaps[i].strip() or gaps[k] != "-":
            return i
        while k > 0 and gaps[k] == "-":
            k -= 1
        return k

    def kind_at(self, i: int) -> tuple[int, str | None]:
        """The kind the noun phrase at word `i` names, and its length in words."""
        words = self.text.words
        n, category = self.match(i)
        if n > 1:
            return n, category
        if words[i].isalpha() and (of_place := self.of_its_place(i, category)) is not None:
            return 1, of_place  # "the pillow from the sofa": a sofa pillow, the sofa named apart
        word = words[i]
        nxt = words[i + 1] if i + 1 < len(words) else ""
        if word in _PACKAGING and nxt == "of" and self.contents_named(i + 2):
            return 1, None  # "a bag of pet food": the food is the object
        if word in _PACKAGING and nxt == "of" and self.other_contents(i, category):
            return 1, None  # "a whole bag of crisps": no trash bag
        if self.verb(i) or self.place_sense(i) or self.reading_label(i) or self.adjective_sense(i):
            return 1, None
        if (laundry := self.laundry_heading(i)) is not None:
            self.said_as[laundry] = word  # "Used scrubs - ... into the laundry hamper": laundry
            return 1, laundry
        if self.material(i):  # "'Tis only paper", "the paper drawings": sheets of it, no newspaper
            return 1, _MATERIAL_SENSES[word]
        if word in self.senses:  # "left it out on the bench" in a New Zealand note: the worktop
            self.said_as[self.senses[word]] = word
            return 1, self.senses[word]
        return 1, self.bare_noun(i, category)

    def other_contents(self, i: int, category: str | None) -> bool:
        """Whether "<packaging> of <X>" at word `i` holds something other than what the kind its
        packaging word names is named for: the catalog's bags are a trash bag and a garbage bag,
        named for their contents, and "a whole bag of crisps", "a bag of old clothes" are neither
        (a kind's name is "<contents> <packaging>" or "<packaging> of <contents>", and the word
        after "of" is none of its contents). Such a bag names no object; "a bag of rubbish" (the
        synonym "bag of trash") still does, and a bag of an owner ("the bag of my wife", "the bag
        of her sister") is the owner's bag, whatever kind its word names."""
        words = self.text.words
        if i + 2 >= len(words) or words[i + 2] in _POSSESSIVES:
            return False  # "the bag of my wife": the owner's bag
        # a kind named in this very form ("bag of trash"): the words after "of" are its contents
        phrased = [words_of(t) for c in dict.fromkeys(self.heads.get(words[i], []))
                   for t in (c, *_own(self.catalog.categories[c])) if words_of(t)[:2] == (words[i], "of")]
        if phrased:
            return words[i + 2] not in {w for name in phrased for w in name[2:]} | _RUBBISH
        kind = self.bare_noun(i, category)
        if kind is None:
            return False
        name = words_of(kind)
        if len(name) < 2 or name[-1] != words[i]:
            return False
        return words[i + 2] not in {*name[:-1], *_RUBBISH}

    def contents_named(self, i: int) -> bool:
        """Whether the words from `i`, after "<packaging> of", name a kind within three words
        ("a bag of pet food", "a pack of the baby wipes"): then the contents are the object, as
        the catalog keeps them; else the packaging is ("my carton of NS things", "a bag of old
        clothes to give away": the carton, the bag)."""
        words = self.text.words
        end = next((k for k in range(i, min(i + 3, len(words))) if _BREAK.search(self.text.gaps[k]) and k > i),
                   min(i + 3, len(words)))
        return any(self.match(k)[1] is not None for k in range(i, end))

    def reading_label(self, i: int) -> bool:
        """Whether the one-word noun at word `i` labels a reading, no object: it opens its item
        (no determiner, preposition or verb before it) and a measured value alone follows it up to
        a comma, full stop or the line's end ("Wind SW 3, bar 1016, vis good": the barometer;
        "clock 0815"). A value is a number of three digits or more, or with a decimal point: a
        small whole number numbers the thing ("Make up tonight: bed 2, bed 5"); a number before a colon
        heads what is said of a thing ("Shelf 2: novels"), and "in drawer 3" names one."""
        words, gaps = self.text.words, self.text.gaps
        k = i + 1
        if k >= len(words) or gaps[k].strip() or not _NUMBER.fullmatch(self.text.raw[k]):
            return False
        measured = len(self.text.raw[k]) >= 3
        while k + 1 < len(words) and gaps[k + 1] == "." and _NUMBER.fullmatch(self.text.raw[k + 1]):
            k += 1  # "4.2": one number
            measured = True
        if not measured:
            return False
        ends = k + 1 == len(words) or bool(_READING_END.match(gaps[k + 1]))
        return ends and (i == 0 or bool(_ITEM_BREAK.search(gaps[i]) or _SENTENCE_END.search(gaps[i])))

    def laundry_heading(self, i: int) -> str | None:
        """The kind the word "laundry" names (the catalog's dirty clothes), when word `i` is the plural
        head of a heading that names no kind ("2. Used scrubs - if found on floor, into the laundry
        hamper", "Muddy kits: into the laundry basket") and its sentence puts it in or into a thing
        named for laundry: what goes in the laundry hamper is laundry, whatever the garment."""
        words, raw, gaps = self.text.words, self.text.raw, self.text.gaps
        laundry = self.phrases.get(("laundry",))
        if laundry is None or raw[i] == words[i] or self.names_kind(i) \
                or i + 1 >= len(words) or not _HEADING.search(gaps[i + 1]):
            return None
        start = self.text.sentence_start(i)
        if i - start > 2 or any(self.match(k)[1] is not None or words[k] in _DETERMINERS or not words[k].isalpha()
                                for k in range(start, i)):
            return None
        end = self.text.sentence_end(i)
        for k in range(i + 1, end):
            if words[k] not in ("in", "into"):
                continue
            j = k + 1
            while j < end and words[j] in _ARTICLES:
                j += 1
            n, kind = self.match(j) if j < end else (1, None)
            if kind is not None and kind != laundry and "laundry" in words[j:j + n]:
                return laundry
        return None

    def material(self, i: int) -> bool:
        """Whether the singular word at `i` is a material (`_MATERIAL_SENSES`) where it stands: with
        no determiner, count or owner before it ("'Tis only paper"), or right before a plural noun
        that names no kind ("The paper drawings for Plot 7": drawings on paper). "The paper is on
        the mat", "Dad's paper" are newspapers."""
        words, raw, gaps = self.text.words, self.text.raw, self.text.gaps
        word = words[i]
        if word not in _MATERIAL_SENSES or _MATERIAL_SENSES[word] not in self.catalog.categories or raw[i] != word:
            return False
        j = i + 1
        if j < len(words) and not gaps[j].strip() and raw[j].isalpha() and raw[j] != words[j] \
                and not self.names_kind(j) and not getAllLemmas(raw[j], upos="VERB"):
            return True  # a plural noun naming no kind (and no verb's form) after it: what the paper is made into
        prev = words[i - 1] if i > 0 and not _SENTENCE_END.search(gaps[i]) else ""
        return prev not in _DETERMINERS and prev not in _COUNTS and prev not in self.possessors \
            and not (j < len(words) and not gaps[j].strip() and self.names_kind(j))

    def adjective_sense(self, i: int) -> bool:
        """Whether the one-word name at word `i` is an adjective or adverb where it stands, no
        thing: the complement of a verb of being, a flat adverb or an object's complement with no
        determiner (`lexicon.complement_adjective`: "drive safe", "is it safe", "keeps the kids
        safe", "pack light"), or a degree before a colour word ("the light blue mug", "a light
        grey coat"). A heading or list item's first word ("Safe: code 1234") stays a noun."""
        raw, gaps = self.text.raw, self.text.gaps
        nxt = raw[i + 1] if i + 1 < len(raw) and not gaps[i + 1].strip() else ""
        if nxt in COLOR_WORDS and "ADJ" in getAllLemmas(raw[i]):
            return True
        if i == 0 or gaps[i].strip():
            return False
        lead = raw[i - 2] if i > 1 and not gaps[i - 1].strip() else ""
        return complement_adjective(raw[i], raw[i - 1], lead)

    def place_sense(self, i: int) -> bool:
        """Whether the one-word name at word `i` is a thing's usual place ("its designated spot",
        `_PLACE_SENSES`), not an object."""
        return self.text.words[i] in _PLACE_SENSES and bool(_POSSESSIVES & set(self.text.words[max(0, i - 2):i]))

    def verb(self, i: int) -> bool:
        """Whether the one-word name at word `i` is a verb where it stands ("if you spot it",
        "mop up the water", "you can use", "switch it off": `lexicon.verb_at`; a word of
        `_ALSO_VERBS` names a thing only after a determiner)."""
        if self.text.words[i] in _ALSO_VERBS and not self.leads_noun(i, strict=True):
            return True
        raw, gaps = self.text.raw, self.text.gaps
        if self.adjective_before(i):
            return False  # "the acoustic curtain over the window": a noun after an article and adjective
        if self.line_of_its_own(i):
            return False  # "MUG\nIt is on the desk.", "QUENCH BUCKET\nIt stands ...": a heading's noun
        if self.compound_object(i):
            return False  # "in the wheelie bin out the back": a compound's head, in an object's phrase
        prev = raw[i - 1] if i > 0 and not gaps[i].strip() else ""
        nxt: list[str] = []
        for k in (i + 1, i + 2):  # the next words up to punctuation
            if k >= len(raw) or gaps[k].strip():
                break
            nxt.append(raw[k])
        if ARROW.search(gaps[i]) and nxt[:1] == ["with"] and verb_at(raw[i], "to", nxt):
            return True  # "counter dirty? -> wipe w/ sponge": after an arrow, an instruction's verb
        return verb_at(raw[i], prev, nxt)

    def line_of_its_own(self, i: int) -> bool:
        """Whether word `i` ends a line of at most two words with no mark after it, the next line
        opening a sentence with a capital ("MUG", "QUENCH BUCKET", then "It is on the desk."): a
        heading's noun, which the next line's first words do not make a verb with an object ("mug
        it", "bucket it"); a next line in lower case may go on with it ("Mop\nthe floor")."""
        gaps = self.text.gaps
        ends = i + 1 == len(gaps) or gaps[i + 1].strip() == "" and "\n" in gaps[i + 1] and i + 1 in self.capitalised
        starts = next((j for j in (i, i - 1) if j == 0 or "\n" in gaps[j]), None)
        return ends and starts is not None and all(not gaps[j].strip() for j in range(starts + 1, i + 1))

    def animal_kind(self, i: int, options: list[str]) -> str | None:
        """The kind among `options` named for an animal (`ANIMAL_WORDS`: "pet bowl", "dog bowl",
        "cat bowl") that the head noun at word `i` means when it holds an animal's food or water
        (`FEED_WORDS` right before it, "the water bowl", or "of" one after it, "a bowl of food")
        and the text names an animal kept at home ("the cat flap", "for the kitten") or a pet: a
        water bowl where a cat lives is its bowl, a water bowl in a text naming none a plain bowl."""
        words = self.text.words
        fed = i > 0 and words[i - 1] in FEED_WORDS and not self.text.gaps[i].strip() or \
            i + 2 < len(words) and words[i + 1] == "of" and words[i + 2] in FEED_WORDS
        if not fed:
            return None
        if not ANIMAL_WORDS & self.text.said:
            return None
        animal = [c for c in options
                  if {w for text in (c, *_own(self.catalog.categories[c])) for w in words_of(text)} & ANIMAL_WORDS]
        return animal[0] if len(set(animal)) == 1 else None

    def adjective_before(self, i: int) -> bool:
        """Whether word `i` follows an article and one adjective (a word whose only part of speech
        is an adjective, `lexicon.adjective_only`) with nothing between: "the acoustic curtain over
        the window", "a wooden spoon in the drawer" are noun phrases, where a verb and its particle
        ("curtain over the ...") would read the noun as an instruction. No imperative follows an
        article and an adjective; a plural noun there may be a subject ("the kids mop up") and is
        no adjective."""
        words, gaps = self.text.words, self.text.gaps
        return i >= 2 and words[i - 2] in _ARTICLES and not gaps[i].strip() and not gaps[i - 1].strip() \
            and adjective_only(self.text.raw[i - 1])

    def compound_object(self, i: int) -> bool:
        """Whether word `i`, in its base form, heads a compound noun in an object's phrase rather than
        being a verb: it follows an article and one word in the singular, and that article follows a
        verb or a preposition of the same clause ("chuck it in the wheelie bin out the back", "wheel
        the kitchen bin out the side gate", "take the recycling box down the drive"): the bare form
        after a singular noun is a compound's head (`lexicon.compound_head`: a verb there would need
        that noun as its subject, and a singular subject takes "bins", "boxes"), and an object's
        phrase holds no subject at all. An article that opens its clause ("The family bin out the
        old papers", "when the team mop up", a collective noun taking a plural verb) or a plural
        before the word ("the kids mop up") leaves the verb."""
        words, raw, gaps = self.text.words, self.text.raw, self.text.gaps
        if i < 3 or any(gaps[k].strip() for k in (i - 2, i - 1, i)) or words[i - 2] not in _ARTICLES:
            return False
        lead = raw[i - 3]
        return raw[i - 1].isalpha() and compound_head(raw[i], singular(raw[i - 1]) != raw[i - 1]) \
            and (lead in _PREPOSITIONS or verb_form(lead) and lead not in FUNCTION_WORDS)

    def bare_noun(self, i: int, exact: str | None) -> str | None:
        """The kind a one-word noun means: the kind last named that it ends; else the kind whose
        name holds the word before it ("the full bag": a full trash bag); else the kind it is the
        name of ("the chair", "the stool"); else the kind whose other name words its sentence holds
        most ("the pantry has two shelves": pantry shelves); else the kind it is a synonym of ("the
        bin"); else the kind whose other name words the names of the kinds named hold most ("a
        nightstand (bedside table) with a lamp": a bedside lamp); then the kind most specific to the
        task's rooms (the rooms whose ids name a known type: a guessed type says nothing); then the
        kind whose name (not a synonym) it heads. A noun that names no kind itself must start a
        noun phrase. A sort the text names by a noun no kind's name holds ("the card table") is the
        head's sense in general use (`sort_named`, `HEAD_SENSES`) before its sentence is asked; the
        words that hint a kind are the modifiers its names drop (`dropped_modifiers`)."""
        word = self.text.words[i]
        options = list(dict.fromkeys(self.heads.get(word, [])))
        part = self.part_for.get(i)
        if part is not None:  # "the lower shelf of the metal rack": a rack with shelves, for no use unsaid
            having = [c for c in options if self.has_part(c, part)]
            options = [c for c in having if not self.marked(c, word)] or having or options
        # (never a plurale tantum named before for a singular: "my glasses ... the glass on the
        # desk" is a drinking glass, as it is with no spectacles named first)
        singular_said = self.text.raw[i] == word
        named = [c for c in reversed(self.recent) if c in options and word in self.used.get(c, ())
                 and not (singular_said and _plural_kind_name(c, word))]
        if named and not self.placed_apart(i, named[0]):
            return named[0]
        fed = self.animal_kind(i, options)
        if fed is not None:
            return fed  # "Biscuit's water bowl ... he comes in through the cat flap": the pet's bowl
        # the tail of a closed compound named before ("the workbench ... the bench", "the
        # armchair ... the chair"): the same thing, said short
        tail = [c for c in reversed(self.recent) if word in self.heads
                and any(len(h) > len(word) + 2 and h.endswith(word) for h in self.used.get(c, ()))]
        if tail and self.leads_noun(i) and not self.placed_apart(i, tail[0]):
            return tail[0]
        if self.machine_again(i):
            return None  # "Air conditioner. The unit is not to run overnight": the air conditioner
        headed = self.heading_vessel(i)
        if headed is not None:
            return headed  # "Wine. The bottle's on the desk": the wine bottle the heading named
        if exact is None:
            control = [c for c in self.recent if c in self.controls.get(word, ())]
            if control:
                return control[-1]  # "Light switch: if the light is on": the light the switch works
            ahead = self.controls_ahead(i)
            if ahead is not None:
                return ahead  # "And the light - is it on? Then flick off the switch": one thing
        if exact is None and (not options or not (self.leads_noun(i) or self.modified(i)) or word in self.room_heads):
            return None
        if exact is None and len(set(options)) == 1 and self.head_alone(i, options[0]):
            return None  # "behind the bar", "the last game" (no soap, no board said): no soap bar, no board game
        if exact is None and self.person_subject(i):
            return None  # "If the cleaners have left it on": the people who clean, no vacuum cleaner
        prev = self.text.words[i - 1] if i > 0 else ""
        candidates = options if options else [exact]
        written = self.text.raw[i]
        if written == word:  # a singular never names a plural-only kind: "Marco's glass" is no spectacles
            candidates = [c for c in candidates if c is None or not self.plural_only(c, word)] or candidates
        said = self.sentence_context(i)
        # (read only where there is a choice: with one candidate no score is compared)
        near = self.kinds_said_near(i) if len(candidates) > 1 else set()

        writing = self.written_in(i)
        unlisted = self.sort_named(i, [c for c in candidates if c is not None])
        use = self.use_clause(i) or self.use_said_later(i)
        described = i > 0 and self.text.gaps[i] == " " and self.text.words[i - 1] not in _DETERMINERS \
            and self.text.words[i - 1] not in SORT_ADJECTIVES and "ADJ" in getAllLemmas(self.text.raw[i - 1])

        support = self.stood_on(i)
        opened = bool({self.text.words[k] for k in range(self.text.sentence_start(i), self.text.sentence_end(i))}
                      & _OPENING)

        def score(category: str | None) -> tuple[bool, bool, bool, bool, bool, bool, int, int, bool, bool, bool, bool, int, bool, int,
                                                 bool, bool]:
            assert category is not None
            cat = self.catalog.categories[category]
            # the other words of its names that say what it is: not a preposition of a name made
            # as a phrase ("bag of trash", "drying rack for dishes"), which says nothing of the kind
            # ("the mouth of the bag" is no bag of trash), nor a word of order ("the first box" on
            # the trolley is no first aid box)
            others = {w for text in (category, *_own(cat)) for w in words_of(text)} - {word} - _NAME_LINKS - ORDER_WORDS
            rooms = set(cat.rooms)
            # its own name: written as the text writes it ("glasses"), or the word's lemma ("chairs")
            # when the name is a lemma (not "glasses" for "glass", a drinking glass)
            own = category.replace("_", " ") == self.text.raw[i] or words_of(category) == (word,) and _lemma_named(category)
            # a book one writes in: the kind named for writing ("notebook") before the head's own
            for_writing = writing and any(w.startswith(tuple(_WRITING)) for w in others)
            hints = self.dropped_modifiers(category, word)
            fits = bool(rooms & self.known_room_types) or not self.known_room_types
            return (for_writing, prev in others,
                    # what the noun's own clause says it is for ("the towel you dry your hands on",
                    # "a bottle for the pills") names its sort before the head's own name does
                    bool(hints & use),
                    # the floor its own phrase stands it on names the kind the catalog stands on
                    # the floor ("the bowl on the floor by the door": a pet's bowl, no cereal bowl),
                    # a thing's top the kind the catalog stands on one ("the lamp lives on the
                    # shelf": a desk or table lamp, no floor or ceiling lamp)
                    support is not None and ("floor" if support == FLOOR else "surface") in cat.placement,
                    own,
                    # a sort named by its own modifier is that sort, whatever else its sentence says
                    # (not where its sentence opens or shuts it and the sort cannot be: "an open
                    # craft box", "open the flaps" are a cardboard box's, no storage box's)
                    unlisted and HEAD_SENSES.get(word) == category and (cat.openable or not opened),
                    # a word of its sentence hints only a kind of the task's own rooms ("there's
                    # coffee in the jar; the post is on the table" in a kitchen: no coffee table,
                    # a living room's), any kind where no room id names a type
                    len(hints & said) if fits else 0,
                    # the kinds said beside it, in a kind the word heads the own name of ("a boot
                    # goes back on the racks": the shoe rack; "put the boots on the shelf" is no
                    # shoe rack, whose "shoe shelf" is only a synonym)
                    len(set(words_of(category)) & near) if words_of(category)[-1] == word else 0,
                    written != word and self.plural_named(category, word),
                    category == exact,
                    # the sort the dictionary describes by the head's adjective ("the small table
                    # near his chair": a side table), before the kinds of the task's known rooms
                    SORT_SENSES.get((self.text.words[i - 1] if i > 0 else "", word)) == category,
                    # a kind of the task's own rooms before one a word said elsewhere hints ("tea
                    # and coffee are in the tin" in a kitchen)
                    fits,
                    # the text's words elsewhere, as the modifier a short name dropped ("bedside"
                    # said, then "the table"): a modifier of a name the word heads, never a time
                    # ("last night" is no night table) or another name's head ("cabinet" of
                    # "bedside cabinet" names a cabinet, no bedside table)
                    len(hints & self.context),
                    # a head described by an adjective ("a sturdy table", "the long table") is its
                    # sense in general use, where nothing the text says tells its sorts apart:
                    # before the rooms the kinds it names outright suggest (a guess: bunk beds make
                    # no bothy a bedroom) and before the catalog's order; the task's own rooms
                    # still come first
                    described and not self.known_room_types and HEAD_SENSES.get(word) == category,
                    -len(rooms) if rooms & self.room_evidence() else -1000,
                    # then a kind whose name says no use the text does not ("keep it on the rack,
                    # the metal one" with no shoes, coats or drying said: the storage rack)
                    not self.marked(category, word),
                    # last, the kind the word heads the name of, not only a synonym ("computer":
                    # a desktop computer, not a laptop's "notebook computer")
                    words_of(category)[-1] == word)

        return max(candidates, key=score)

    def placed_apart(self, i: int, named: str) -> bool:
        """Whether the head alone at word `i`, which would take up the compound `named` said
        before ("the step stool ... the stool"), is a thing of its own: the word is a kind's own
        name, and its phrase places it by a landmark (`_LOCATING`: "the stool by the door", "the
        basket under the sink") that the compound's sentence, up to this word, does not say ("the
        step stool next to the sink"). A definite noun restricted by another place than the one
        its compound was said at tells a second thing apart, as English does for things of one
        kind. The phrase must be a place itself or a subject (after a preposition or opening its
        sentence: "on the stool by the door", "The stool by the door is ..."): after a verb ("put
        the stool by the door") the place is where it goes, not which one it is."""
        words, gaps = self.text.words, self.text.gaps
        word = words[i]
        if word not in self.catalog.categories or word == named or i < 1 or words[i - 1] != "the":
            return False
        start = self.text.sentence_start(i)
        if i - 1 != start and (i < 2 or words[i - 2] not in _PREPOSITIONS | _PLACE_ADVERBS or gaps[i - 1] != " "):
            return False
        k = i + 1
        if k < len(words) and gaps[k] == " " and words[k] in _LOCATING:
            k += 1
            while k < len(words) and gaps[k] == " " and words[k] in _LOCATING_LINKS:
                k += 1
        if k == i + 1 or k >= len(words) or gaps[k] != " ":
            return False
        while k < len(words) and gaps[k] == " " and (words[k] in _ARTICLES or words[k] in _POSSESSIVES):
            k += 1
        if k >= len(words):
            return False
        at = self.first_at.get(named)
        if at is None:
            return False
        first = self.text.sentence_start(at)
        said = set(words[first:min(self.text.sentence_end(at), i)])
        return words[k] not in said

    def stood_on(self, i: int) -> str | None:
        """What the noun at word `i` is stood on by its own phrase: "on the" right after it, after
        a comma or a relative word and a verb of standing (`FLOOR_LINKS`), then the floor
        (`FLOOR_WORDS`, one modifier allowed: "the kitchen floor"; `FLOOR`) or a kind with a top
        that holds things (`Category.surface`: "the lamp lives on the shelf", "a clock on the
        bookshelf": the kind's name). None when its phrase stands it on neither."""
        words, gaps = self.text.words, self.text.gaps
        fronted = self.fronted_support(i)
        if fronted is not None:
            return fronted
        k = i + 1
        # (as written: the singular of "lives" is "life")
        while k < len(words) and self.text.raw[k] in FLOOR_LINKS and gaps[k] in (" ", ", "):
            k += 1
        if k + 2 >= len(words) or words[k] != "on" or gaps[k] not in (" ", ", ") or words[k + 1] != "the" \
                or gaps[k + 2] != " ":
            return None
        if words[k + 2] in FLOOR_WORDS or k + 3 < len(words) and words[k + 3] in FLOOR_WORDS and gaps[k + 3] == " ":
            return FLOOR
        support = self.match(k + 2)[1]
        return support if support is not None and self.catalog.categories[support].surface else None

    def fronted_support(self, i: int) -> str | None:
        """What the noun at word `i` stands on by a place its sentence opens with, before a verb of
        being or standing and the noun's own phrase ("On the piano stands a small lamp", "On piano
        is standing small lamp", "On the desk is a lamp"): a kind with a top that holds things,
        as `stood_on` reads "on the" after the noun."""
        words = self.text.words
        start = self.text.sentence_start(i)
        if words[start] != "on" or start + 1 >= i:
            return None
        at = start + 1 + (words[start + 1] in _ARTICLES)
        n, support = self.match(at)
        k = at + n
        if support is None or not self.catalog.categories[support].surface or k >= i \
                or self.text.raw[k] not in _BEING:
            return None
        k += 1 + (k + 1 < i and self.text.raw[k + 1] in _BEING)  # "is standing"
        # then the noun's own phrase: an article, and an adjective at most
        return support if i - k <= 2 and all(w in _ARTICLES or "ADJ" in getAllLemmas(self.text.raw[j])
                                              for j, w in enumerate(words[k:i], k)) else None

    def use_clause(self, i: int) -> set[str]:
        """The words of the clause or phrase right after the noun at word `i` that says what it is
        for (`USE_OPENERS`: a relative word, a subject pronoun, "for"): "the towel wherewith the
        brethren dry their hands", "the bottle we keep the pills in", "a basket for the clothes"),
        to the next break; none when another word follows the noun. A word there that a kind's
        name adds to the head ("hand" of "hand towel") says the thing is of that kind."""
        words, gaps = self.text.words, self.text.gaps
        if i + 1 >= len(words) or gaps[i + 1] != " " or words[i + 1] not in USE_OPENERS:
            return set()
        out: set[str] = set()
        for k in range(i + 2, min(i + 2 + _USE_SPAN, len(words))):
            if gaps[k] != " ":
                break
            out.add(words[k])
        return out - _NOT_CONTEXT

    def use_said_later(self, i: int) -> set[str]:
        """The use clause (`use_clause`) of the next mention of the noun at word `i` by "the" or
        "this" ("OF THE TOWEL. The towel wherewith the brethren dry their hands ..."): a later
        mention of a head named before is read as that thing (`bare_noun`'s first step), so what
        it says the thing is for tells the first mention's kind too."""
        words = self.text.words
        for k in range(i + 1, len(words)):
            if words[k] == words[i] and words[k - 1] in {"the", "this"}:
                return self.use_clause(k)
        return set()

    def machine_again(self, i: int) -> bool:
        """Whether the word at `i` is a general noun for the machine named last (`MACHINE_EPITHETS`:
        "Air conditioner. The unit is not to run overnight"), so no thing of the kind whose name it
        heads (a shelving unit): after a demonstrative or "the", not after a preposition ("put the
        books on the unit" is a place), with the kind named last one that switches on and off."""
        words = self.text.words
        return words[i] in MACHINE_EPITHETS and i > 0 and words[i - 1] in _DEMONSTRATIVE \
            and (i < 2 or words[i - 2] not in _PREPOSITIONS | _PLACE_ADVERBS) \
            and bool(self.recent) and self.catalog.categories[self.recent[-1]].toggleable

    def head_alone(self, i: int, category: str) -> bool:
        """Whether the word at `i`, no kind's name by itself and the head of names of `category`
        only ("bar" of "soap bar" and "bar of soap", "game" of "board game"), stands where its
        other senses do: after a series ordinal (`_SERIES`: "the last game", "the next game", a
        game of a series, a match) or as the place a person stands behind or at (`_STANDING_AT`:
        "behind the bar", "at the bar"), of a kind one picks up (no one stands behind a bar of
        soap) - with no word those names add ("soap", "board": `dropped_modifiers`) said anywhere
        in the text. Elsewhere a head alone names its one kind, as everyday speech does ("put the
        racket on the shelf", "my controller", "my bat"); a kind named before is read by
        `bare_noun`'s earlier steps."""
        words = self.text.words
        if self.dropped_modifiers(category, words[i]) & self.text.said or i < 2 or words[i - 1] not in _ARTICLES \
                and words[i - 1] not in _SERIES:
            return False
        if words[i - 1] in _SERIES:
            return words[i - 2] in _ARTICLES
        return words[i - 2] in _STANDING_AT and self.catalog.categories[category].pickable

    def person_subject(self, i: int) -> bool:
        """Whether the word at `i`, no kind's name by itself (the head of a longer name: "cleaner"
        of "vacuum cleaner"), is the subject of a deed only people do to a thing (`PERSON_DEEDS`
        and its object, `_DEED_OBJECTS`: "the cleaners have left it on", "the cleaner always
        leaves the blind open"), with an auxiliary or an adverb of frequency between at most
        (`_PERSON_DEED_LINKS`): it names the people the word also means, no thing."""
        raw, gaps = self.text.raw, self.text.gaps
        k = i + 1
        while k < len(raw) and not gaps[k].strip() and raw[k] in _PERSON_DEED_LINKS:
            k += 1
        return k + 1 < len(raw) and not gaps[k].strip() and raw[k] in PERSON_DEEDS \
            and not gaps[k + 1].strip() and raw[k + 1] in _DEED_OBJECTS

    def sort_named(self, i: int, options: list[str]) -> bool:
        """Whether the text names its own sort of the thing at word `i` by a noun before it that no
        option's name holds ("the card table", "the trestle table", "a folding table", "the
        mahjong table"): a compound's modifier that says what sort it is, not what it is like (a
        word the lemmatiser knows as an adjective, "the small table", "the round table", or a value
        of an option's attribute, "the metal table"). Such a thing is the head's sense in general
        use (`HEAD_SENSES`), whatever the catalog's other sorts are named for. The modifier may be
        a compound of two words ("the lost property box")."""
        if not (self.modified(i) or self.compound_modified(i)):
            return False
        prev = self.text.raw[i - 1]
        if "ADJ" in getAllLemmas(prev):
            return False
        for c in options:
            cat = self.catalog.categories[c]
            if any(prev in words_of(text) for text in (c, *_own(cat))) or \
                    any(prev in values for values in cat.attributes.values()):
                return False
        return True

    def compound_modified(self, i: int) -> bool:
        """Whether word `i` follows a determiner and a compound of two words that name no kind,
        the second no verb ("the lost property box", "a big comics box"): a noun phrase, as
        `modified` reads one modifier."""
        words, gaps = self.text.words, self.text.gaps
        return i >= 3 and words[i - 3] in _ARTICLES and all(g == " " for g in gaps[i - 2:i + 1]) \
            and all(words[k].isalpha() and self.match(k)[1] is None and words[k] not in _PREPOSITIONS
                    for k in (i - 2, i - 1)) and not self.verb(i - 1)

    def dropped_modifiers(self, category: str, word: str) -> set[str]:
        """The words a short name `word` may have dropped from a name of `category` it heads
        ("bedside", "night" of "bedside table", "night table" for "table"), else, for a kind the
        word does not head, the other words of its names; no noun of time (`TIME_HEADS`): the text
        says "night" of a time ("at night", "troop night") far more often than of a thing; no word
        of order (`ORDER_WORDS`): "first" said alone is an order or a time ("first thing", "do that
        first"), and in a name it says what aid a first aid box holds, not what box it is."""
        names = [words_of(text) for text in (category, *_own(self.catalog.categories[category]))]
        headed = {w for n in names if len(n) > 1 and n[-1] == word for w in n[:-1]}
        others = {w for n in names for w in n} - {word}
        return (headed or others) - _NAME_LINKS - TIME_HEADS - ORDER_WORDS

    def written_in(self, i: int) -> bool:
        """Whether the thing the noun at word `i` names is written in: a verb of writing
        (`_WRITING`) before it as its modifier ("the log book", "a record book"), or in its sentence
        or the next with "in" and the noun or "it" after ("he is to write in it", "note it down in
        the book")."""
        words, raw, gaps = self.text.words, self.text.raw, self.text.gaps

        def writes(k: int) -> bool:
            return bool(_WRITING & {raw[k], *getAllLemmas(raw[k], upos="VERB").get("VERB", ())})

        if i > 0 and not gaps[i].strip() and writes(i - 1):
            return True
        start, end = self.text.sentence_start(i), self.text.sentence_end(self.text.sentence_end(i))
        for k in range(start, min(end, len(words))):
            if k != i - 1 and writes(k):
                after = words[k + 1:k + 7]
                if "in" in after and (after[after.index("in") + 1:after.index("in") + 2] == ["it"]
                                      or words[i] in after[after.index("in") + 1:]):
                    return True
        return False

    def modified(self, i: int) -> bool:
        """Whether word `i` follows a determiner (or a possessive: "Today's brew sheet") and one
        modifier that names no kind and is no verb ("on the props table", "the wooden box"), or
        such a modifier opening its sentence or
        list item ("* fly spray lives on that shelf"): a noun phrase, as after the determiner
        alone (a head noun of several kinds is then one of them, `bare_noun`)."""
        words, gaps = self.text.words, self.text.gaps
        if i < 1 or gaps[i].strip():
            return False
        # the modifier after an article, or opening its sentence or list item ("* fly spray lives
        # on that shelf": a noun phrase as "the fly spray" is)
        opens = i == 1 or bool(_SENTENCE_END.search(gaps[i - 1]) or _ITEM_BREAK.search(gaps[i - 1]))
        # (the article left out after a preposition or a verb of being or standing, as learners'
        # English and notes do: "on small table near his chair", "in big basket", "On piano is
        # standing small lamp": an adjective alone then stands for it)
        dropped = i >= 2 and (words[i - 2] in _PREPOSITIONS - {"of"} or self.text.raw[i - 2] in _BEING) \
            and not gaps[i - 1].strip() and "ADJ" in getAllLemmas(self.text.raw[i - 1])
        # (a possessive stands where an article does: "Today's brew sheet", "the chef's prep sheet")
        article = i >= 2 and (words[i - 2] in _ARTICLES or words[i - 2] in self.possessives)
        if not (article and not gaps[i - 1].strip() or opens or dropped):
            return False
        return self.match(i - 1)[1] is None and not self.verb(i - 1) and words[i - 1].isalpha() \
            and words[i - 1] not in _PREPOSITIONS and words[i - 1] not in _DETERMINERS

    def controls_ahead(self, i: int) -> str | None:
        """The control kind named for the word at `i` ("light switch" for "light") when its
        sentence or the next says its head ("the switch", or the control's whole name: "If the
        lights are still on, flick the light switch off", the name written as one, not "the
        light. Switch off the fan"): the thing the text switches, the switch, as when it is named
        first (`CONTROL_HEADS`). Only the head as a noun: after the thing's word ("the light
        switch") or a determiner, with one word between at most ("the switch", "the main
        switch"); the head said as a verb ("If the light is on, switch it off") switches the
        thing itself."""
        word = self.text.words[i]
        kinds = self.controls.get(word, ())
        if len(kinds) != 1:
            return None
        end = self.text.sentence_end(self.text.sentence_end(i))
        head = words_of(kinds[0])[1]
        words, gaps = self.text.words, self.text.gaps
        return kinds[0] if any(words[k] == head and (
            words[k - 1] == word and gaps[k] == " " or words[k - 1] in _DETERMINERS
            or k >= 2 and words[k - 2] in _DETERMINERS and not gaps[k - 1].strip() and not gaps[k].strip())
            for k in range(i + 1, min(end, len(words)))) else None

    def room_evidence(self) -> set[str]:
        """The room types that tell a bare noun's kinds apart: those the task's room ids name; for
        ids naming none ("staff_room"), the room type most of the kinds the text names outright
        belong in (a microwave, a toaster, a fridge: a kitchen), when one leads."""
        if self.known_room_types or not self.named:
            return self.known_room_types
        votes = Counter(r for c in self.named for r in self.catalog.categories[c].rooms)
        ranked = votes.most_common(2)
        if not ranked or len(ranked) > 1 and ranked[1][1] == ranked[0][1]:
            return set()
        return {ranked[0][0]}

    def sentence_context(self, i: int) -> set[str]:
        """The words of word `i`'s sentence that may tell its kinds apart: not the words of another
        thing's name written there in full ("stand it on the dish rack; otherwise it goes up on
        the shelf": "rack" is the dish rack's, no hint of a shoe rack)."""
        words = self.text.words
        start, end = self.text.sentence_start(i), self.text.sentence_end(i)
        taken: set[int] = set()
        k = start
        while k < end:
            n, category = self.match(k)
            if n > 1 and category is not None and not k <= i < k + n:
                taken.update(range(k, k + n))
            k += n
        taken.update(k for k in range(start, end) if self.text.part_of_other(k))
        return {words[k] for k in range(start, end) if k not in taken} - _NOT_CONTEXT

    def kinds_said_near(self, i: int) -> set[str]:
        """The words of the own names of the kinds that word `i`'s clause names outright (a
        head of several kinds names none), and those from the sentence before when the clause
        refers back by a pronoun: what the thing is for, said by what goes on it ("a boot left on
        the floor goes back on the racks": a shoe, so the shoe rack; "Sneakers by the door? Line
        them up on the rack"), where the head alone is no hint ("boot" is no word of "shoe rack").
        The clause, not the sentence: "I've left the torch on the shelf charging; if it's still
        on, ..." says nothing of boots a sentence before."""
        words, gaps = self.text.words, self.text.gaps
        start, end = i, i + 1
        while start > 0 and not _BREAK.search(gaps[start]) and words[start - 1] not in _CLAUSE_LINKS:
            start -= 1
        while end < len(words) and not _BREAK.search(gaps[end]) and words[end] not in _CLAUSE_LINKS:
            end += 1
        if any(words[k] in _THING_PRONOUNS for k in range(start, end)):
            sentence = self.text.sentence_start(i)
            start = self.text.sentence_start(sentence - 1) if sentence > 0 else sentence
        out: set[str] = set()
        k = start
        while k < end:
            n, category = self.match(k)
            if category is not None and not k <= i < k + n and (n > 1 or len(set(self.heads.get(words[k], []))) <= 1):
                # the kind's own name, not the words written ("stand it on the dish rack;
                # otherwise it goes up on the shelf": "rack" hints no rack of shelves)
                out.update(set(words_of(category)) - set(words[k:k + n]))
            k += n
        return out - {words[i]}

    def plural_names(self, category: str, word: str) -> list[bool]:
        """For each name of `category` headed by `word` (singular), whether it is written in the
        plural ("glasses", "open shelves", "headphones")."""
        out = []
        for text in (category, *_own(self.catalog.categories[category])):
            written = re.findall(r"[a-z0-9]+", text.lower().replace("_", " "))
            head = written[written.index("of") - 1] if "of" in written[1:] else written[-1]
            if singular(head) == word:
                out.append(head != word)
        return out

    def plural_only(self, category: str, word: str) -> bool:
        """Whether every name of `category` headed by `word` is a plural (a plurale tantum such as
        "glasses", "scissors"): a singular "glass" names a drinking glass, never spectacles."""
        names = self.plural_names(category, word)
        return bool(names) and all(names)

    def plural_named(self, category: str, word: str) -> bool:
        """Whether a name of `category` is the plural of `word`: a plural bare noun ("put it on
        the shelves") fits best the kind the catalog names in the plural (a shelving unit, "open
        shelves"), where no other word of the sentence or a modifier tells the kinds apart."""
        return any(self.plural_names(category, word))

    def _context(self) -> set[str]:
        """The description's words and the words of every name of the kinds it names outright
        (by a name that is not the head noun of several kinds: "shelf" names no kind outright)."""
        words = self.text.words
        out = {words[k] for k in range(len(words)) if not self.text.part_of_other(k)}
        for i in range(len(words)):
            n, category = self.match(i)
            if category is None or n == 1 and (self.verb(i) or self.place_sense(i)):
                continue
            if n > 1 or len(set(self.heads.get(words[i], []))) == 1:
                self.named.add(category)
                for text in (category, *_own(self.catalog.categories[category])):
                    out.update(words_of(text))
        return out - _NOT_CONTEXT

    # -- instances -------------------------------------------------------------------------

    def instance(self, category: str, name: str, attrs: dict[str, str]) -> None:
        self.kinds.setdefault(category, _Kind()).instances.setdefault(_snake(name), attrs)

    def mention(self, category: str, head: str) -> None:
        """`category` was just named, by a noun phrase ending in `head`."""
        self.recent = [c for c in self.recent if c != category] + [category]
        self.used.setdefault(category, set()).add(head)

    def glossed(self, i: int, n: int, category: str) -> str | None:
        """The kind a bracket opening at word `i` names again by a fuller name of its own kind:
        "Cupboard on wall (wall cabinet, over sink)", "the rack (the towel rack)". The bracket
        opens within three words of the thing's first and only reading, in its sentence, and its
        first noun is a kind whose name ends in the head of that thing's kind and says more
        ("wall cabinet" after "cupboard", a cabinet), or is written as one word that ends in the
        word the thing was called by ("the field book (yellow notebook)", "the chair (the
        armchair)", "the pan (saucepan)": English closes many compounds): one object, of the
        fuller kind."""
        opens = i - (i > 0 and self.text.words[i - 1] in COLOR_WORDS and "(" not in self.text.gaps[i])
        opens -= opens > 0 and self.text.words[opens - 1] in _ARTICLES and "(" not in self.text.gaps[opens]
        if "(" not in self.text.gaps[opens]:
            # (an article and up to two words before the kind's noun: "(the little desk ...")
            described = next((k for k in range(i - 1, max(i - 4, -1), -1) if "(" in self.text.gaps[k]
                              and self.text.words[k] in _ARTICLES
                              and all(not g.strip() for g in self.text.gaps[k + 1:i + 1])), None)
            if described is None:
                return None
            opens = described
        if not self.recent or self.recent[-1] == category:
            return None
        before = self.recent[-1]
        kind, at = self.kinds.get(before), self.first_at.get(before)
        if kind is None or kind.instances or kind.count > 1 or at is None or not kind.generic:
            return None
        if at < self.text.sentence_start(i) or i - at > 4 or len(self.used.get(before, ())) != 1:
            return None
        head, fuller = words_of(before), words_of(category)
        if len(fuller) > len(head) and fuller[-len(head):] == head:
            return before
        # "the small table (the side table)", "the lamp (the floor lamp)": the thing was called by
        # its head alone, which the first reading took for one of the head's kinds (a guess the
        # bracket corrects), and the bracket's kind has that head too
        (said,) = self.used[before]
        words, end = self.text.words, i + n
        # a bracket that goes on with a verb of its own is a clause about another thing ("the
        # chair is wet (the armchair is dry)")
        goes_on = end < len(words) and not _BREAK.search(self.text.gaps[end]) and words[end] in _CLAUSE_VERBS
        if len(words[end - 1]) > len(said) + 2 and words[end - 1].endswith(said) and not goes_on:
            return before
        if self.text.words[at] == said and len(fuller) > 1 and fuller[-1] == said:
            return before
        # "the chart table (the little desk at the bottom of the steps)": the thing was called by
        # a phrase whose head alone was read (a guess), and the bracket opens with an article
        # and names a kind of the same sort (`_same_sort`) as its head noun: it says what the
        # thing is ("(the desk one)" only tells which, and keeps the guess)
        bracket = self.text.words[opens:end]
        if self.text.words[at] == said and at > 0 and self.text.words[at - 1] not in _ARTICLES \
                and bracket[:1] and bracket[0] in _ARTICLES and not goes_on \
                and not (end < len(words) and words[end] == "one") \
                and _same_sort(self.catalog.categories[before], self.catalog.categories[category]):
            # the thing keeps the text's own name ("chart_table", a desk), so that the text's
            # later "on the chart table" is read as that desk
            self.said_as.setdefault(category, f"{self.text.words[at - 1]} {said}")
            self.glossed_as.add(category)
            return before
        return None

    def one_glossed(self, i: int) -> tuple[str, str, str] | None:
        """(the kind named before, its fuller kind, the word it was called by) when word `i` opens
        "the <modifier> one" in a bracket or after a comma right after a thing is named (within six
        words), and the modifier with that word is a catalog name of another kind ("the lost
        property box (the cardboard one under the table)": a cardboard box, "the bin, the pedal
        one": a pedal bin): the gloss says which sort the thing is, as `glossed` reads "(the
        cardboard box)". A modifier that names no sort with the word ("(the red one)") keeps it."""
        words, gaps = self.text.words, self.text.gaps
        if i < 1 or i + 1 >= len(words) or words[i + 1] != "one" or words[i - 1] not in _ARTICLES \
                or not ("(" in gaps[i - 1] or "," in gaps[i - 1]) or not self.recent:
            return None
        before = self.recent[-1]
        kind = self.kinds.get(before)
        said = next((words[k] for k in range(i - 2, max(i - 7, -1), -1) if words[k] in self.used.get(before, ())), None)
        if kind is None or kind.instances or kind.count > 1 or said is None:
            return None
        category = self.phrases.get((words[i], said))
        if category is None or category == before or words_of(category)[-1] != said:
            return None
        return before, category, said

    def said_as_gloss(self, i: int) -> str | None:
        """The kind a bracket said a two-word phrase is (`glossed`: "the chart table (the little
        desk ...)"), when word `i` is that phrase's head again, after the same modifier."""
        if i == 0:
            return None
        said = f"{self.text.words[i - 1]} {self.text.words[i]}"
        return next((c for c, w in self.said_as.items() if w == said and c in self.kinds and c in self.glossed_as), None)

    def glossed_spare(self, i: int, n: int, category: str) -> tuple[str, str] | None:
        """The kind of a spare named right before a bracket that names it again by a compound
        written as one word ending in the word it was called by ("The spare field book (yellow
        notebook)", "the spare pan (the saucepan)"): the spare is a thing of the bracket's kind,
        the kind's other mentions ("2) Field book." as a heading) stay as they were."""
        opens = i - (i > 0 and self.text.words[i - 1] in COLOR_WORDS and "(" not in self.text.gaps[i])
        opens -= opens > 0 and self.text.words[opens - 1] in _ARTICLES and "(" not in self.text.gaps[opens]
        if "(" not in self.text.gaps[opens] or opens < 2 or not self.recent or self.recent[-1] == category:
            return None
        words, before = self.text.words, self.recent[-1]
        said, spare = words[opens - 1], f"spare_{words[opens - 1]}"
        kind = self.kinds.get(before)
        if kind is None or spare not in kind.instances or not any(
                w in SPARE_WORDS for w in words[max(0, opens - 4):opens - 1]):
            return None
        end = i + n
        goes_on = end < len(words) and not _BREAK.search(self.text.gaps[end]) and words[end] in _CLAUSE_VERBS
        closed = len(words[end - 1]) > len(said) + 2 and words[end - 1].endswith(said)
        return (before, spare) if closed and not goes_on else None

    def renamed_fuller(self, i: int, n: int, category: str) -> str | None:
        """The kind of the thing named last, when the noun phrase at words [i, i + n) names it
        again by a fuller name that ends in the word it was called by: as the predicate of an
        identifying "is" right after that word ("the bunny lamp is the little table lamp shaped
        like a rabbit", "the box is the blue toy box") or set off by a comma after the clause
        that named it ("Somebody's reading book has ended up on the floor again, the novel with
        the dragon on the front": the novel's name "fiction book"). The thing was only ever called
        by that one word, a head several kinds share, and no other kind was named since: one
        object, of the fuller kind. A phrase after a comma that goes on with a verb of its own is
        a clause of its own ("the book is on the desk, the novel is on the shelf")."""
        words, gaps = self.text.words, self.text.gaps
        the = i - 1
        while the >= 0 and i - the <= 3 and words[the] != "the":
            the -= 1
        if the < 1 or words[the] != "the" or not self.recent or self.recent[-1] == category:
            return None
        before = self.recent[-1]
        kind, said = self.kinds.get(before), self.used.get(before, set())
        if kind is None or kind.instances or kind.count > 1 or len(said) != 1:
            return None
        (head,) = said
        if any(self.match(k)[1] is not None for k in range(the + 1, i)):
            return None
        # the thing's word right before the identifying "is", or before a place said with it ("the
        # cupboard in the bathroom is the medicine cabinet")
        subject = next((k for k in range(the - 2, max(the - 7, 0) - 1, -1) if words[k] == head), None)
        copular = the >= 2 and words[the - 1] in _COPULAS and subject is not None and (
            subject == the - 2 or words[subject + 1] in _PREPOSITIONS
            and not any(_BREAK.search(gaps[k]) or words[k] in _COPULAS for k in range(subject + 1, the - 1)))
        # "the key cupboard is the little wall cabinet": a thing named outright by another word
        # (a cupboard is a cabinet) and identified by a fuller kind whose name ends in its
        # kind's name (a wall cabinet is a cabinet) is one object of the fuller kind
        narrower = copular and len(words_of(category)) > 1 and words_of(category)[-1] == words_of(before)[-1]
        if before in self.named and not narrower:
            return None
        end = i + n
        goes_on = end < len(words) and not _BREAK.search(gaps[end]) and words[end] in _CLAUSE_VERBS
        apposed = "," in gaps[the] and not goes_on and (self.first_at.get(before, -1) >= self.text.sentence_start(i))
        if not (copular or apposed):
            return None
        names = (category, *_own(self.catalog.categories[category]))
        return before if narrower or any(len(words_of(t)) > 1 and words_of(t)[-1] == head for t in names) else None

    def headed_fuller(self, i: int, n: int, category: str) -> str | None:
        """The kind a heading line named, when the noun phrase at words [i, i + n) names its thing
        again by a narrower kind right under it: a line that is only the thing's name, with its
        place or not ("Towel on the bench", a rota app's task title; "Cabinet:"), then, within the
        next three sentences and with no other thing of that head named between, a definite
        mention of a kind whose name ends in the heading kind's name ("Notes: The hand towel's
        been left on the bench by the back door again"). A heading names its topic by the bare
        word, as `heading_mention` reads for a colour; the item's fuller name is the same object."""
        words, gaps = self.text.words, self.text.gaps
        head = words_of(category)[-1]
        if len(words_of(category)) < 2 or i < 1 or words[i - 1] not in _RENAMING_DETERMINERS:
            return None
        before = next((c for c in reversed(self.recent) if c != category and tuple(words_of(c)) == (head,)), None)
        kind = self.kinds.get(before) if before is not None else None
        if before is None or kind is None or kind.instances or kind.count > 1:
            return None
        at = self.first_at[before]
        line_end = self.text.sentence_end(at)
        if not self.heading_line(at) or line_end >= i or "\n" not in gaps[line_end] \
                or any(self.match(k)[1] in (before, category) for k in range(at + 1, i)):
            return None
        sentences, k = 0, line_end
        while k <= i:
            k = self.text.sentence_end(k)
            sentences += 1
        return before if sentences <= 3 else None

    def heading_line(self, at: int) -> bool:
        """Whether the mention starting at word `at` is a line of its own with at most its article
        before it and a place after it ("Towel on the bench", "- The mug on the desk", "Cabinet:")."""
        words, gaps = self.text.words, self.text.gaps
        if at < 0:
            return False
        start = self.text.sentence_start(at)
        if start > 0 and "\n" not in gaps[start] or any(w not in _ARTICLES for w in words[start:at]):
            return False
        n, _ = self.match(at)
        end = self.text.sentence_end(at)
        rest = words[at + n:end]
        return not rest or rest[0] in _PREPOSITIONS and len(rest) <= 5 and not any(
            getAllLemmas(w).get("VERB") and not getAllLemmas(w).get("NOUN") for w in rest)

    def names_the_colored_one(self, i: int, n: int, kind: _Kind, prev: str, category: str) -> bool:
        """Whether a plain singular mention of a kind is the one thing of it the text has already
        named by its colour ("The blue cup is on the table. If the cup is dirty ...", "My blue cup
        ... If cup is dirty"): a definite or bare mention after exactly one coloured instance and
        no plain mention before it names that instance again, not a second thing. An indefinite
        or counted mention ("a cup", "another cup", "two cups") or a plural one still names things
        of its own. A plain mention before it that was only a heading (`heading_mention`: "3. The
        folder. ... the blue folder ...") was of the same thing."""
        if kind.generic and not self.headed.get(category) or kind.count > 1 or len(kind.instances) != 1:
            return False
        (attrs,) = kind.instances.values()
        if set(attrs) != {"color"} or prev in _INDEFINITE | _ANOTHER | _COUNTS.keys() | {"no", "one", "other"}:
            return False
        return self.text.raw[i + n - 1].lower() == self.text.words[i + n - 1]

    def restates_plain(self, told: int, category: str) -> bool:
        """Whether a coloured mention starting at word `told` (its colour) names again the thing a
        plain mention before it named: an item of a list after a label's colon in its sentence
        ("The magician waves a scarf. PROPS: one red scarf, a hat", "A towel hangs by the sink.
        Props: a blue towel, a bucket"), a later sentence of its own: a list says again, more
        fully, what the prose named. A mention in prose, definite or not ("A cup is on the desk.
        The blue cup is on the shelf.", "a mug on the desk and a blue mug on the shelf"), may set
        another thing against the first, so it restates nothing."""
        gaps = self.text.gaps
        first = self.text.sentence_start(told)
        start = told
        while start > 0 and self.text.words[start - 1] in _RESTATING_LEADS | _ARTICLES:
            start -= 1
        return self.first_at.get(category, first) < first and any(":" in gaps[k] for k in range(first + 1, start + 1))

    def heading_mention(self, i: int, n: int) -> bool:
        """Whether the mention at words [i, i + n) is a heading of its own: its sentence or line
        holds only it and its article, and a full stop, colon, dash or line break ends it ("3. The
        folder.", "Mug:", "TOWEL - the green towel ..."). A heading names the topic of what
        follows by its bare kind, so the thing the item then names by its colour ("the blue
        folder has slipped off the desk") is the heading's one thing, not a second one; so does
        an owner's name before it ("Umpire's hat.")."""
        words, gaps = self.text.words, self.text.gaps
        start = self.text.sentence_start(i)
        # (an owner's name may stand for the article, the twenty-first session: "Umpire's hat.
        # Stan's white cap ought to be on the hook" is one cap; "Dad's mug.", "Rex's bowl.")
        if any(w not in _ARTICLES and w not in self.possessors for w in words[start:i]):
            return False
        end = i + n
        return end == len(words) or bool(_SENTENCE_END.search(gaps[end]) or _HEADING.search(gaps[end]))

    def compound(self, i: int, n: int, category: str) -> tuple[int, str]:
        """"the vanity cabinet", "the pet food bag": a name followed at once by a head noun of
        several kinds (or a packaging word) is one object, of the kind named first; a head
        noun of one kind after it ("the sofa cushion") is the object."""
        words = self.text.words
        j = i + n
        if j >= len(words) or self.text.gaps[j].strip():
            return n, category
        holder = self.named_holder(i, n, category)
        if holder is not None:
            return n + 1, holder
        m, second = self.match(j)
        if second is None or m > 1:
            return n, category
        kinds = set(self.heads.get(words[j], []))
        if words[j] in _PACKAGING or len(kinds) > 1:
            return n + 1, category
        return n, category

    def named_holder(self, i: int, n: int, category: str) -> str | None:
        """The kind named "<a name of `category`> <head>" when the name of `category` at word `i`
        (`n` words) is followed at once by a one-word head of other kinds: a modifier naming a
        kind by another of its names ("boot", "sneaker": a shoe; "brolly": an umbrella; "couch":
        a sofa) names the holder or companion of that kind ("the boot rack", "the sneaker shelf":
        a shoe rack; "the brolly stand": an umbrella stand; "the couch pillow": a sofa pillow), as
        the catalog's name would; English builds such a compound from any name of its first
        kind, the catalog lists one."""
        words = self.text.words
        j = i + n
        if j >= len(words) or self.text.gaps[j].strip() or self.match(j)[0] > 1:
            return None
        head = words[j]
        # the compound may be built from any name of the modifier's kind, its own first ("the
        # plate rack": a dish rack, "dish" a name of the plate; "the tub mat": a bath mat)
        mine = [words_of(text) for text in (category, *_own(self.catalog.categories[category]))]
        kinds = set(self.heads.get(head, []))
        return next((kind for name in mine for kind in sorted(kinds) if kind != category
                     and any(words_of(text) == (*name, head)
                             for text in (kind, *_own(self.catalog.categories[kind])))), None)

    def modifies_other(self, i: int, n: int) -> bool:
        """Whether the one-word name at word `i` only modifies the noun right after it, a noun that
        names no kind ("Car park gate open", "for the food bank pick-up", "this month light bill",
        "lights-out list"): the compound is a park, a bank, a bill, so the first noun names no object
        of its kind. Joined by a hyphen, any word that names no kind makes one word with it; a part of
        the thing or a place right by it ("the fridge door", "the sink area": `PART_HEADS`) keeps it."""
        words, raw, gaps = self.text.words, self.text.raw, self.text.gaps
        j = i + n
        if n != 1 or j >= len(words) or gaps[j] not in (" ", "-"):
            return False
        nxt = words[j]
        if self.names_kind(j) or nxt in PART_HEADS or nxt in FURNITURE_PARTS \
                or nxt in TIME_HEADS or not raw[j].isalpha():
            return False
        # a placeholder head names the thing its modifier names ("the scarf thing", "that kettle
        # thingy", "the fan contraption"), unless it is a matter ("the scarf thing about ...")
        if nxt in PLACEHOLDER_HEADS and words[j + 1:j + 2] not in (["about"], ["that"]):
            return False
        if gaps[j] == "-":
            return True
        if self.material(i) or not compound_head(raw[j], raw[i] != words[i]) or self.verb(j):
            return False
        # a verb's bare form followed by its complement is the verb of a subject ("my bat and my
        # racket go in the ..."), not a compound's head ("Car park gate open"); a preposition's
        # object holds no subject ("for the bar staff on nights": the staff, no bar)
        after = words[j + 1] if j + 1 < len(words) and gaps[j + 1] == " " else ""
        if getAllLemmas(raw[j]).get("VERB") and after in _PREPOSITIONS:
            return self.prepositional_object(i)
        return not (getAllLemmas(raw[j]).get("VERB") and (after in _DETERMINERS or after in FUNCTION_WORDS))

    def prepositional_object(self, i: int) -> bool:
        """Whether the singular noun at word `i` opens the object of a preposition, bare or after
        an article ("Notes for bar staff", "for the bar staff on nights", `_OBJECT_PREPOSITIONS`):
        a word after it in its base form is then a compound's head, never a verb of it as subject
        (a verb's object is no such phrase: "let the cloth soak", "leave the mug drain")."""
        words, gaps = self.text.words, self.text.gaps
        k = i - 1 if i > 0 and words[i - 1] in _ARTICLES and not gaps[i].strip() else i
        return k > 0 and not gaps[k].strip() and words[k - 1] in _OBJECT_PREPOSITIONS \
            and singular(self.text.raw[i]) == self.text.raw[i]

    def modifies_next(self, i: int, n: int) -> bool:
        """Whether the one-word noun at word `i` modifies the noun right after it, the head of an
        English noun compound ("the collection basket" is a basket, "the chart table drawer" a
        drawer): it names no kind by a name of its own (its kind was only a guess among the longer
        names it heads: "collection" of "essay collection", "table" of "bedside table"), and the next
        word, with nothing between, is a kind's own name used as a noun. A name of its own before
        a generic head stays the object ("the vanity cabinet", `compound`), unless it names a thing
        one picks up ("the bread knife": a knife for bread, no bread)."""
        words = self.text.words
        j = i + n
        if n != 1 or j >= len(words) or self.text.gaps[j].strip():
            return False
        if words[j] in _PACKAGING or words[j] in TIME_HEADS:
            return False
        m, second = self.match(j)
        if second is None or m == 1 and (self.verb(j) or self.place_sense(j)):
            return False
        first = self.match(i)[1]
        # a thing one picks up, named by its own name, before a head noun of several kinds says
        # what the head is for ("the bread knife" is a knife, no bread), where a
        # piece of furniture before one is the thing ("the vanity cabinet", `compound`) and so is
        # the contents before a vessel ("the detergent bottle", `_VESSELS`)
        return first is None or m == 1 and words[j] not in _VESSELS \
            and self.catalog.categories[first].pickable and self.text.raw[i] == words[i]

    def color_before(self, i: int) -> int | None:
        """Where the colour of the noun phrase whose head is word `i` stands: right before it, or
        before one modifier that names no kind ("the black music folders", "a red plastic
        bucket": the colour is the head's, the modifier says more of it)."""
        words, gaps = self.text.words, self.text.gaps
        if i > 0 and words[i - 1] in COLOR_WORDS and not _SENTENCE_END.search(gaps[i]):
            return i - 1
        if i > 1 and words[i - 2] in COLOR_WORDS and not gaps[i].strip() and not gaps[i - 1].strip() \
                and words[i - 1].isalpha() and self.match(i - 1)[1] is None and not self.verb(i - 1) \
                and words[i - 1] not in _PREPOSITIONS and words[i - 1] not in _DETERMINERS:
            return i - 2
        return None

    def appositive(self, i: int, n: int, category: str) -> bool:
        """Whether the noun phrase at words [i, i + n) renames the thing named right before it, set
        off by commas or brackets ("Papa ka kurta, the white shirt, ...", "My jumper, the blue
        jumper, is on the chair", "ITEM: cloth (the blue rag)"): a definite phrase of the same
        kind, after a comma or an opening bracket that follows that thing's name, closed by a
        comma, the bracket or the sentence's end; one object, told by the fuller name. Between
        dashes, the phrase may open with a possessive too ("a campaign cap - my red hat - lying on
        the chair", "a beaker – your green cup – on the bench"): the dashes close it on both sides."""
        words, gaps = self.text.words, self.text.gaps
        start = self.color_before(i + n - 1)
        the = (start if start is not None else i) - 1
        dashed = the >= 1 and bool(_DASH_GAP.search(gaps[the]))
        if the < 1 or words[the] not in _RENAMING_DETERMINERS or words[the] != "the" and not dashed \
                or not ("," in gaps[the] or "(" in gaps[the] or dashed) or not self.recent \
                or self.recent[-1] != category:
            return False
        kind = self.kinds.get(category)
        if kind is None or kind.instances or words[the - 1] not in self.used.get(category, set()):
            return False
        end = i + n
        if end == len(words) or _SENTENCE_END.search(gaps[end]) or "(" in gaps[the] and ")" in gaps[end] \
                or dashed and _DASH_GAP.search(gaps[end]):
            return True
        if dashed:
            return False
        if "(" in gaps[the]:
            return False  # "The mugs (the red mug and the blue mug)": a list in the bracket
        nxt = end
        while nxt < len(words) and (words[nxt] in _DETERMINERS or words[nxt] in COLOR_WORDS):
            nxt += 1
        # a list goes on after the comma ("the mug, the red mug, the blue mug and a cup"): no renaming
        return "," in gaps[end] and words[end] not in _NOUN_LEADS and (
            nxt == len(words) or self.match(nxt)[1] != category)

    def subject_renamed(self, i: int, n: int, category: str) -> bool:
        """Whether the noun phrase at words [i, i + n) is an afterthought renaming the subject of
        its sentence ("The table lamp is on the desk - my reading lamp", "The laundry basket sits
        on the floor – the wicker basket", "the floor lamp is by the bed — her reading lamp"), or
        between two dashes right after the subject's name ("The table lamp - my reading lamp - is on
        the desk", "the laundry basket – the wicker basket – stands by the door"):
        set off by a dash, opened by "the" or a possessive with at most two words before the
        name, ending its sentence, and of a kind whose head noun is the head noun of the thing the
        sentence opens with, named before. A writer adds the name they use for the thing they have
        just placed; after a dash, the last thing named (the desk) is no antecedent of a lamp."""
        words, gaps = self.text.words, self.text.gaps
        end = i + n
        final = end == len(words) or bool(_SENTENCE_END.search(gaps[end]))
        if not final and not _DASH_GAP.search(gaps[end]):
            return False
        the = next((k for k in range(i - 1, max(i - 4, 0) - 1, -1) if words[k] in _RENAMING_DETERMINERS), None)
        if the is None or the < 1 or not _DASH_GAP.search(gaps[the]) or any(
                _DASH_GAP.search(gaps[k]) or self.match(k)[1] is not None for k in range(the + 1, i)):
            return False
        start = self.text.sentence_start(the)
        while start < the and words[start] in _DETERMINERS:
            start += 1
        length, subject = self.match(start)
        # between two dashes mid-sentence, the renaming stands right after the subject's name
        # ("The table lamp - my reading lamp - is on the desk"), never after a later thing
        return subject is not None and subject in self.kinds and start < the \
            and (final or start + length == the) and words_of(subject)[-1] == words_of(category)[-1]

    def color_class(self, told: int, category: str) -> bool:
        """Whether the colour at word `told` sorts things of `category` into classes rather than
        naming one of them: an indefinite phrase ("a white shirt goes in the washing machine", "a
        dirty white mug", a state word or two between the article and the colour) of a kind the
        text also names by the complement of a colour ("a coloured shirt goes in the hamper", "a
        towel of any other colour goes on the rail"). What is sorted is any one thing of the kind,
        its colour a condition, as laundry is sorted into whites and coloureds; "a white mug and a
        blue mug" name two mugs."""
        words = self.text.words
        k = told - 1
        while k >= 0 and told - k <= 3 and words[k] in STATE_WORDS:
            k -= 1
        if k < 0 or words[k] not in ("a", "an"):
            return False
        for j, w in enumerate(words):
            if w in _COMPLEMENT_COLORS and any(self.match(x)[1] == category for x in range(j + 1, min(j + 3, len(words)))):
                return True  # "a coloured shirt", "a dirty colored sock"
            if w in _COLOR_NOUNS and j > 0 and words[j - 1] in ("other", "another") and any(
                    self.match(x)[1] == category for x in range(max(0, j - 7), j - 1)):
                return True  # "a towel of any other colour", "shirts in another colour"
        return False

    def which_one_color(self, i: int) -> str | None:
        """The colour "the <colour> one" at word `i` ("one") gives the thing named last, when it
        says which one that thing is: as a predicate ("It's the red one by the slider") or as a
        bracket right after it ("the collection basket by the door (the grey plastic one)"), with
        at most one more word that names no kind between "the" and "one" ("plastic", "big"), and
        the thing's kind comes in that colour with no instances told apart."""
        words, gaps = self.text.words, self.text.gaps
        if words[i] != "one" or not self.recent or self.kinds.get(self.recent[-1], _Kind()).instances:
            return None
        the = next((k for k in (i - 2, i - 3) if k > 0 and words[k] == "the"), None)
        if the is None or any(gaps[k].strip() for k in range(the + 1, i + 1)):
            return None
        said = words[the + 1:i]
        color = next((w for w in said if w in COLOR_WORDS), None)
        allowed = self.catalog.categories[self.recent[-1]].attributes.get("color", [])
        if color is None or color not in allowed or any(
                w != color and (self.match(k)[1] is not None or w in _DETERMINERS)
                for k, w in zip(range(the + 1, i), said, strict=True)):
            return None
        predicate = words[the - 1] in _COPULAS and not gaps[the].strip()
        # a bracket that only tells which one: it closes after "one" or goes on with a place ("(the
        # red one by the window)"), not a clause of its own ("(the red one is mine)")
        closes = i + 1 == len(words) or ")" in gaps[i + 1] or words[i + 1] in _PREPOSITIONS
        return color if predicate or "(" in gaps[the] and closes else None

    def class_of_named(self, category: str) -> bool:
        """Whether `category` was named only by a bare plural ("Toys are kept in the toy box")
        and the text names things of kinds of its own that are values of its kind attribute (a
        doll, a toy car: a toy's kinds are doll, car ...): the class those things belong to, no
        object of its own."""
        if category in self.particular:
            return False
        values = {v for key in KIND_ATTRIBUTES for v in self.catalog.categories[category].attributes.get(key, ())}
        return any(c != category and set(words_of(c)) & values for c in self.kinds)

    def part_said_of(self, i: int) -> bool:
        """Whether word `i` is a part of a piece of furniture said "of" it ("the lower shelf of the
        metal rack", "the top drawer of the dresser", `FURNITURE_PARTS`): the part names no object
        of its own; the phrase after "of" names the furniture, of a kind that has such parts
        (`has_part`, read by `bare_noun` through `part_for`)."""
        whole = self.whole_said_after(i)
        if whole is not None:
            self.part_for[whole] = self.text.words[i]
        return whole is not None

    def whole_said_after(self, i: int) -> int | None:
        """The last word of the furniture a part at word `i` is said "of" ("the top drawer of the
        dresser": "dresser"), or None when word `i` is no part so said (`part_said_of`)."""
        words, gaps = self.text.words, self.text.gaps
        if words[i] not in FURNITURE_PARTS or i + 2 >= len(words) or words[i + 1] != "of" \
                or any(gaps[k].strip() for k in (i + 1, i + 2)) or words[i + 2] not in _ARTICLES:
            return None
        k = i + 3
        while k < min(i + 6, len(words)) and not gaps[k].strip():
            n, category = self.match(k)
            if category is not None or words[k] in self.heads:
                return k + n - 1
            k += 1
        return None

    def part_by_other_name(self, i: int, n: int, category: str) -> bool:
        """Whether the `n` words at `i` name a piece of furniture by none of its catalog's own
        names (a WordNet name only: "mantelpiece", a wall shelf) and are tied by "of", "above" or
        "over" (`PART_TIES`) to a piece of furniture named by its own name: "the mantelpiece above
        the fireplace" is part of the fireplace, which the catalog has no kind for, no object of
        its own. "The shelf above the desk" (the catalog's own word) is a shelf."""
        words, gaps = self.text.words, self.text.gaps
        cat = self.catalog.categories[category]
        end = i + n
        if cat.pickable or any(words_of(t) == tuple(words[i:end]) for t in (category, *_own(cat))) \
                or end + 1 >= len(words) or words[end] not in PART_TIES or gaps[end].strip():
            return False
        k = end + 1
        while k < len(words) and words[k] in _ARTICLES and not gaps[k].strip():
            k += 1
        m, whole = self.match(k)
        if whole is None or whole == category or gaps[k].strip() or self.catalog.categories[whole].pickable:
            return False
        own = self.catalog.categories[whole]
        return any(words_of(t) == tuple(words[k:k + m]) for t in (whole, *_own(own)))

    def has_part(self, category: str, part: str) -> bool:
        """Whether a kind of furniture has parts of the kind `part` names: shelves (levels, tiers)
        when one of its names says so ("storage rack" is the utility shelf's, "shoe shelf" the shoe
        rack's), drawers when a drawer fits in it as a part (`holds_as_part`)."""
        cat = self.catalog.categories[category]
        if _PARTS.get(part) == "shelf":
            return any("shelf" in words_of(text) or words_of(text)[-1].endswith("shelf")
                       for text in (category, *_own(cat)))
        drawer = self.catalog.categories.get("drawer")
        return drawer is not None and self.holds_as_part(drawer, category)

    def marked(self, category: str, word: str) -> bool:
        """Whether every name of `category` that `word` heads says a use the text does not: a
        room's ("pantry rack": a pantry's) or another kind's, what it holds ("shoe rack"), or an
        activity ("drying rack": drying, `lexicon.gerund_of`), with that word nowhere in the text.
        A bare "rack" with shelves is then the unmarked one, the "storage rack" (a utility shelf);
        so is a bare "rack" nothing else tells apart (`bare_noun`)."""
        said = self.text.said
        names = [words_of(text) for text in (category, *_own(self.catalog.categories[category]))]
        headed = [n for n in names if len(n) > 1 and n[-1] == word]

        def use(w: str) -> bool:
            """A room, a kind, or an activity ("drying": a verb's -ing form) the text does not say."""
            doing = gerund_of(w)
            if doing is not None:
                return doing not in said and w not in said
            return (known_room_type(w) is not None or (w,) in self.phrases) and w not in said

        return bool(headed) and all(any(use(w) for w in n[:-1]) for n in headed)

    def part_of_named(self, i: int, prev: str) -> bool:
        """Whether word `i` is a ranked part ("the bottom shelf", "the top level") of a piece of
        furniture already named whose names say it has such parts (a shelving unit, "open
        shelves"; a bookshelf): a part of it, no object of its own."""
        part = _PARTS.get(self.text.words[i])
        if part is None or prev not in _ORDINALS - {"one", "other", "next", "last"}:
            return False
        return any(part in {w for text in (c, *_own(self.catalog.categories[c])) for w in words_of(text)}
                   and not self.catalog.categories[c].pickable for c in self.recent)

    def part_of_its_furniture(self, i: int, n: int, category: str, prev: str) -> bool:
        """Whether the kind at words `i`..`i+n` is a part of a piece of furniture (a kind the
        catalog places only inside one: a drawer) said without a count or "a",
        of an openable piece of furniture it fits in that its sentence or the one before names ("file
        it in the filing cabinet - the drawer may be pulled out", "stick it in the filing cabinet.
        the drawer might already be pulled out", "goes into the nightstand drawer", "should the
        dresser drawers be open, close them"):
        that furniture's own drawer, whose opening is the furniture's (the catalog's nightstand
        is openable for its drawer), no object of its own. "Two drawers", "a drawer" or a drawer
        no furniture is named with are drawers of their own."""
        cat = self.catalog.categories[category]
        last = i + n - 1
        if cat.placement != ["inside"] or prev in _COUNTS:
            return False
        if self.part_said_again(i, n, category, prev):
            return True
        if prev in _INDEFINITE:
            return False
        start = self.text.sentence_start(i)
        start = self.text.sentence_start(start - 1) if start > 0 else start  # or the one before
        # the kinds named before it, also as a modifier of a name the catalog gives the drawer as
        # a whole ("the dresser drawers")
        named = [self.match(j)[1] for j in range(start, i)]
        # (a word that names a kind by no name of its own, "the chart table drawer", names no piece
        # of furniture: `modifies_next`), or the thing such a word named before ("the nightstand
        # ... the table drawer")
        named += [h for k in range(start, last) if k >= i or self.match(k)[1] is not None
                  for h in self.heads.get(self.text.words[k], [])]
        if i > start:
            before = self.text.words[i - 1]
            named += [c for c in self.recent if before in self.used.get(c, ())]
        holders = {other for other in named if other not in (None, category) and self.holds_as_part(cat, other)}
        self.part_holders.setdefault(category, set()).update(h for h in holders if h in self.kinds)
        return bool(holders)

    def part_said_again(self, i: int, n: int, category: str, prev: str) -> bool:
        """Whether a part of furniture (a drawer) said again, anywhere after the text named it as
        one piece of furniture's own ("goes into the nightstand drawer", "keep them in the desk
        drawer"), is that part: "the drawer" (as far back as it was named), or "a drawer" as the
        subject that opens its clause, a sound or a sight of the part ("SFX: A DRAWER SLIDES
        SHUT", "Later a drawer bangs"). Not when a second piece of furniture that holds such a
        part is named, nor "a drawer" after a verb or preposition ("put the pens in a drawer",
        "there is a drawer"), nor one a place or "of" follows ("a drawer in the hall"): a drawer
        of its own."""
        holders = self.part_holders.get(category, set())
        if len(holders) != 1 or prev not in _DEMONSTRATIVE | _INDEFINITE:
            return False
        cat = self.catalog.categories[category]
        if any(self.holds_as_part(cat, other) for other in self.kinds if other not in holders):
            return False
        if prev in _DEMONSTRATIVE:
            return True
        words, gaps, end = self.text.words, self.text.gaps, i + n
        opens = i == 1 or i > 1 and (_SENTENCE_END.search(gaps[i - 1]) is not None or ":" in gaps[i - 1]
                                     or words[i - 2] in _OPENING_ADVERBS)
        placed = end < len(words) and (words[end] in _PREPOSITIONS or words[end] in _LOCATING)
        return opens and not placed

    def holder_in_name(self, i: int, n: int, category: str) -> str | None:
        """The piece of furniture a part's own name starts with ("the dresser drawers", a name the
        catalog gives the drawer as a whole): what the text names is that furniture, whose
        opening is its drawers' (as "the nightstand drawer" names the nightstand)."""
        cat = self.catalog.categories[category]
        if cat.placement != ["inside"] or n < 2:
            return None
        return next((h for h in self.heads.get(self.text.words[i], []) if h != category and self.holds_as_part(cat, h)),
                    None)

    def holds_as_part(self, part: Category, holder_kind: str | None) -> bool:
        """Whether a kind is an openable piece of furniture `part` (a drawer) fits in."""
        holder = self.catalog.categories.get(holder_kind) if holder_kind is not None else None
        return holder is not None and holder.container and holder.openable and not holder.pickable \
            and can_hold(part, holder, "inside")

    def packaging_of_topic(self, i: int) -> bool:
        """Whether word `i` is "the <form>" (`sentences.FORMS`: roll, bottle, tube ...) said of the
        carried thing named in the heading its clause answers ("Tin foil: in case the roll has
        fallen on the floor", "Shampoo - if the bottle is empty, ..."): the thing's own roll or
        bottle, not a thing of another kind. Not after a preposition ("put them in the box": a
        place), nor a word a kind was already named by, nor without a heading ("Take the mug; if
        the bag is full, ...": a bag of its own)."""
        words = self.text.words
        if words[i] not in FORMS or i < 2 or words[i - 1] != "the" or words[i - 2] in _PREPOSITIONS:
            return False
        if any(words[i] in used for used in self.used.values()) or not self.recent:
            return False
        topic = self.recent[-1]
        start = self.text.sentence_start(i)
        # named in the heading the clause answers: before a colon or dash between it and the word
        headed = any(self.match(k)[1] == topic and any(_HEADING.search(self.text.gaps[j]) for j in range(k + 1, i))
                     for k in range(start, i))
        return headed and self.catalog.categories[topic].pickable

    def shared_head(self, i: int) -> str | None:
        """The kind word `i` names with the head noun of the next name: "the salt and pepper
        shakers" are a salt shaker and a pepper shaker, "the tea or coffee cups" a tea cup and a
        coffee cup, "the desk and floor lamps" a desk lamp and a floor lamp (a determiner, the
        modifier before "and"/"or", then a name of two or more words whose head is written in
        the plural, all within one stretch without punctuation)."""
        words, gaps = self.text.words, self.text.gaps
        if i < 1 or words[i - 1] not in _DETERMINERS or i + 3 >= len(words) or words[i + 1] not in ("and", "or") or any(
                gaps[k].strip() for k in (i + 1, i + 2)):
            return None
        n, category = self.match(i + 2)
        end = i + 2 + n
        if category is None or n < 2 or self.text.raw[end - 1] == words[end - 1]:
            return None
        return self.phrases.get((words[i], *words[i + 3:end]))

    # -- enumerations ----------------------------------------------------------------------

    def enumerations(self) -> None:
        """Objects of one kind told apart by a list: "two bowls: a food bowl and a water bowl",
        "two coat hooks: one for the jacket and one for the hat", "two toy boxes: red for dolls,
        white for other toys", "bookshelf levels: top for novels, middle for essays", "three
        levels - novels on one, essays on the next", "novels are kept on the first level,
        essays on the second", "three levels hold novels, essays and other books respectively"."""
        words = self.text.words
        i = 0
        while i < len(words):
            # "2. Cardboard box + contents (photos)": a list item's number is its label, no count
            count = 0 if _ITEM_NUMBER.match(self.text.gaps[i + 1] if i + 1 < len(words) else "") \
                and words[i].isdigit() else _COUNTS.get(words[i], 0)
            j = i + 1 if count else i
            n, category = self.group_kind(j)
            if category is not None and count and self.numbered_heading(i):
                i += 1  # "Finding 2 - Filing cabinet (risk rating: high)": the finding's number
                continue
            if category is None and count and words[i] != "both":
                n, category = 0, self.counted_before(i)  # "Tea towels. There are two, a green one and ..."
            if category is None:
                i += 1
                continue
            k = j + n  # the word after the noun phrase
            plural = n > 0 and self.text.raw[k - 1] != words[k - 1]
            listed = plural and k < len(words) and bool(_HEADING.search(self.text.gaps[k]))
            # (a ranked part said "of" a piece of furniture, "the bottom shelf of the bookcase", is
            # that furniture's part and heads no list: `part_said_of`)
            ordinal_part = words[k - 1] in _PARTS and i > 0 and words[i - 1] in _ORDINALS \
                and self.whole_said_after(k - 1) is None
            if not (count or listed or ordinal_part):
                i += 1
                continue
            if ordinal_part:
                start, end = self.text.sentence_start(i), self.text.sentence_end(i)
            else:
                start, end = j + n, self.text.sentence_end(j + n - 1)
                if count:
                    start = self.after_heading(start, end)
            # "Bookshelf levels: novels, essays, other books respectively": a list closed by
            # "respectively" pairs each item with one of the things it follows, as a count would
            paired = count or (len(self.text.items(start, end)) if "respectively" in words[start:end] else 0)
            found = self.read_items(category, start, end, paired)
            if len(found) >= max(2, count):
                self.kinds.setdefault(category, _Kind()).generic = True
                for name, attrs, span in found[:count or None]:
                    self.instance(category, name, attrs)
                    self.consumed.update(span)
                i = end
                continue
            i += 1

    def numbered_heading(self, i: int) -> bool:
        """Whether the number at word `i` numbers a heading rather than counting the things after
        it: a numeral followed by a colon or a dash and then a name ("Finding 2 - Filing cabinet
        (risk rating: high)", "Task 2 — Wardrobe (deadline: tonight)", "Action 7: Laptop"), as
        reports, tickets and checklists number their entries. A count runs straight into its noun
        ("2 mugs: a red one and a blue one"); what follows such a heading's name in brackets says
        more of the one thing, no list of several."""
        gaps = self.text.gaps
        return self.text.words[i].isdigit() and i + 1 < len(gaps) and bool(_HEADING.search(gaps[i + 1]))

    def counted_before(self, i: int) -> str | None:
        """The kind a count standing alone counts ("Tea towels. There are two, a green one and a
        white one", "Mugs: we have three - ..."): a count with no noun after it, before a comma,
        colon or dash, counts the things the text just named in the plural (in its sentence or
        the one before)."""
        words, gaps = self.text.words, self.text.gaps
        if i + 1 >= len(words) or not _ITEM_BREAK.search(gaps[i + 1]):
            return None
        start = self.text.sentence_start(i)
        start = self.text.sentence_start(start - 1) if start > 0 else start
        found: str | None = None
        k = start
        while k < i:
            n, category = self.match(k)
            if category is not None and k + n <= i and self.text.raw[k + n - 1] != words[k + n - 1]:
                found = category  # the last plural name before the count, read in full
            k += n
        return found

    def after_heading(self, start: int, end: int) -> int:
        """Where the items of a counted list start: after the colon or dash that ends its heading
        ("2 cups left out today: Dave's cup and Priya's cup", "three bins by the back door - one
        for paper, ..."): what stands between the counted noun and the colon says more of the
        whole group, no item of it. Without such a break, right after the noun; a dash inside a
        bracket is the aside's own ("the two CDs I lent Ben (the jazz one and the folk one - the
        folk one has the cracked case)"), so the search stops at an opening bracket."""
        opening = next((k for k in range(start, end) if "(" in self.text.gaps[k]), end)
        colon = next((k for k in range(start, opening) if _HEADING.search(self.text.gaps[k])), None)
        if colon is not None and any("," in self.text.gaps[k] for k in range(start + 1, colon)):
            return start  # "three levels hold novels, essays, and other books - top, middle, bottom": the list came first
        return start if colon is None or colon == start else colon

    def group_kind(self, j: int) -> tuple[int, str | None]:
        """The kind of the noun phrase at word `j` that may head a list: a catalog kind, or a part
        word ("levels", "tiers") of the kind of shelf the context fits best, never the piece of
        furniture named just before, of which they are the parts."""
        words = self.text.words
        if j >= len(words):
            return 1, None
        part = _PARTS.get(words[j])
        if part is not None and words[j] != part:
            # kinds that are shelves by their own name (a wall shelf, a pantry shelf), never a
            # piece of furniture named in the text (the bookshelf the levels are of)
            options = [c for c in dict.fromkeys(self.heads.get(part, []))
                       if c not in self.named and words_of(c)[-1] == part]
            return 1, self.part_kind(options, self.phrases.get((part,)))
        n, category = self.kind_at(j)
        if category is not None:
            self.mention(category, words[j + n - 1])
        return n, category

    def part_kind(self, options: list[str], exact: str | None) -> str | None:
        """Of the shelf kinds, the one that fits most of the task's rooms, then the context (the
        exact word wins ties): a pantry's levels are pantry shelves, a bedroom's wall shelves."""
        def score(c: str) -> tuple[int, int, bool]:
            cat = self.catalog.categories[c]
            others = {w for t in (c, *_own(cat)) for w in words_of(t)} - {"shelf"}
            return len(set(cat.rooms) & self.room_types), len(others & self.context), c == exact

        return max(options, key=score, default=None)

    def read_items(self, category: str, start: int, end: int,
                   count: int) -> list[tuple[str, dict[str, str], list[int]]]:
        """(name, attributes, words read) of each item of the list between `start` and `end`
        that tells one object apart: a colour, "for X", "X on the next", a modifier before
        "one" or before the kind's head noun, or a bare word."""
        words = self.text.words
        head = words_of(category)[-1]
        allowed = self.catalog.categories[category].attributes.get("color", [])
        out: list[tuple[str, dict[str, str], list[int]]] = []
        for a, b in self.without_relative_items(self.text.items(start, end)):
            item = words[a:b]
            if item[0] in _HOLDING and len(item) > 1 and not out:
                item, a = item[1:], a + 1  # "hold novels, essays and ..."
            color = next((w for w in item if w in COLOR_WORDS and w in allowed), None)
            ranked = self.ranked_holding(item, self.text.raw[a:b], head)
            if ranked is not None and "for" not in item and color is None:
                rank, held = ranked
                read = list(range(a, a + held))
                if self.text.raw[a + held] != item[held]:
                    read.append(a + held)  # a class of things ("my novels"), no object of its own
                out.append((f"{item[rank]}_{item[held]}_{head}", {}, read))
                continue
            at: int | None = None  # the purpose's word in the item
            if "for" in item:
                at = next((k for k in range(item.index("for") + 1, len(item)) if item[k] not in _ARTICLES), None)
            ordinal_at = next((k for k, w in enumerate(item) if w in _ORDINALS and k > 0
                               and item[k - 1] in ("on", "in", "the")), None)
            if at is None and ordinal_at is not None:
                at = next((k for k in range(ordinal_at) if item[k] not in _ARTICLES
                           and item[k] not in _FILLER and item[k] not in _PREPOSITIONS), None)
            purpose = None if at is None else item[at]
            before = item[:item.index("for")] if "for" in item else item
            # the item's own word for the kind ("a red bin" for a trash can) ends its modifiers
            # and names it ("red_bin"), as the catalog's head word would
            stop = next((k for k, w in enumerate(before) if w == "one" or w == head
                         or k > 0 and self.match(a + k) == (1, category)), len(before))
            said_head = before[stop] if stop < len(before) and before[stop] not in ("one", head) else head
            # (a colour the kind has no attribute for tells the item apart as any modifier does:
            # "two boxes: a red box and a blue box" are a red_box and a blue_box)
            modifiers = [w for w in before[:stop] if w not in _ARTICLES and w not in _FILLER
                         and (w not in COLOR_WORDS or color is None) and w != head and w not in _PREPOSITIONS
                         and (w != "other" or purpose is None)]  # "the other for the umbrella"
            if purpose is None and (not modifiers or not count) and color is None:
                continue  # without a count, a list tells objects apart by colour or purpose only
            if self.own_kind(a, a + len(before), head):
                continue  # "two toys: a doll and a ball" names a doll and a ball
            if ordinal_at is None and "for" not in item and color is None and (
                    len(item) > 4 or any(w in _PREPOSITIONS or w in _HOLDING or w in STATE_WORDS
                                         or w in PERSONAL_SUBJECTS for w in item)):
                continue  # a clause, not an item ("are in the kitchen", "the two CDs I lent Ben")
            # the words read: the item's up to "for", and the purpose when it is a class of things
            # (a bare plural: "for dolls", "novels on one"), not when it is an object ("one for
            # the jacket")
            read = [] if ordinal_at is not None else list(range(a, a + len(before)))
            if at is not None and self.text.raw[a + at] != purpose and (at == 0 or item[at - 1] not in _ARTICLES):
                read.append(a + at)
            if color is not None:
                out.append((f"{color}_{category}", {"color": color}, read))
                continue
            # named for its position and its purpose ("upper_tin_shelf"), a ranked item for its
            # purpose only ("novels on the first level": the rank says only which comes next)
            parts = [] if ordinal_at is not None else modifiers[:1]
            parts += [purpose] if purpose and purpose not in parts else []
            out.append(("_".join([*parts, said_head]), {}, read))
        return out

    def without_relative_items(self, spans: list[tuple[int, int]]) -> list[tuple[int, int]]:
        """The list's item spans without an item that is a relative clause on the item before it:
        "two toy boxes - a blue box, which is for dolls, and a white box", "a green bin, that
        takes the garden waste, and ...", "a tall mug, which we keep for tea": set off by commas
        (which `_Text.items` splits at), a clause that says more of the item before (its purpose,
        what it holds), no item of its own. It opens with a relative pronoun (`lexicon.RELATIVE`)
        and then a verb or a subject pronoun; "that" before a noun or "one" is a determiner ("this
        hook for coats, that one for hats", "that box for books"), and such an item names its
        thing as before."""
        words, raw = self.text.words, self.text.raw
        return [(a, b) for a, b in spans
                if not (b - a >= 2 and words[a] in RELATIVE and self.match(a + 1)[1] is None
                        and words[a + 1] != "one"
                        and (words[a + 1] in PERSONAL_SUBJECTS or verb_form(raw[a + 1])))]

    @staticmethod
    def ranked_holding(item: list[str], raw: list[str], head: str) -> tuple[int, int] | None:
        """(rank, purpose) word positions when an item names a part by its rank, then what it
        holds: "its top level holds my novels", "the middle one my essays" (the verb said once
        for the list), "the bottom shelf every other book", "the top one holds forks": the rank
        opens the item (after a determiner at most), the part's word or "one" follows it, then a
        verb of holding or keeping at most and determiners, then the class held, a plural as
        written ("other" when it is the rest). None for any other item ("the top shelf of the
        fridge", "the middle one is empty")."""
        k = 1 if item and item[0] in _ARTICLES else 0
        if k + 2 >= len(item) or item[k] not in _ORDINALS - {"one", "other"} or \
                item[k + 1] not in {*_PARTS, head, "one"}:
            return None
        m = k + 2
        while m < len(item) and (item[m] in _HOLDING - {"for"} or item[m] in _ARTICLES):
            m += 1
        if m >= len(item) or not item[m].isalpha() or raw[m] == item[m] and item[m] != "other":
            return None
        return k, m

    def predicate_noun(self, i: int) -> bool:
        """Whether the noun phrase at word `i` is the predicate of "that is a ...", "it is a ...",
        "this was a ..." said of a thing the sentence already named ("The essay collection is on
        the desk, that's a library book"), or with a possessive for its article ("the bunny lamp
        is the little table lamp, it's her night light"): it says what that thing is, it names no
        other object."""
        words = self.text.words
        leads = {"a", "an", *_POSSESSIVES}
        k = i - 1
        while k >= 0 and i - k <= 3 and words[k] not in leads:
            k -= 1
        if k < 2 or words[k] not in leads or words[k - 1] not in _COPULAS or words[k - 2] not in _POINTERS:
            return False
        start = self.text.sentence_start(i)
        return any(self.kind_at(j)[1] is not None for j in range(start, k - 2))

    def unnamed_subject(self, i: int) -> str | None:
        """The noun a thing was first called by, when the noun phrase at word `i` is the predicate of
        "it is (only) <a kind>" opening its sentence and the sentence before has as its subject a
        noun that names no kind ("The treasure map be on the little side table. 'Tis only paper":
        the map is the paper; "The rota is on the fridge door. It's a sheet of paper"): the thing
        keeps its first name, so that what the text said of it by that name is said of the object."""
        words = self.text.words
        k = i - 1
        while k > 0 and words[k] in _ARTICLES | {"only", "just"}:
            k -= 1
        start = self.text.sentence_start(i)
        if k < 1 or words[k] not in _COPULAS or words[k - 1] not in _POINTERS or k - 1 != start or start == 0:
            return None
        before = self.text.sentence_start(start - 1)
        verb = next((v for v in range(before, start) if words[v] in _SUBJECT_VERBS), None)
        if verb is None or verb - before < 2 or words[before] not in _ARTICLES:
            return None
        head = words[verb - 1]
        if not head.isalpha() or head in self.heads or any(self.match(v)[1] is not None for v in range(before, verb)):
            return None
        return head

    def says_which(self, i: int) -> bool:
        """Whether word `i` ("spare") is the predicate of "it is the spare", "that's a spare one"
        said right after a thing: it says which one that thing is (the spare, not the one in use),
        no second object of its kind. "Take a spare from the drawer" still names one."""
        words = self.text.words
        if i < 3 or words[i - 2] not in _COPULAS or words[i - 3] not in _POINTERS:
            return False
        return i + 1 == len(words) or words[i + 1] == "one" or self.match(i + 1)[1] is None

    def spare_word_before(self, i: int) -> int | None:
        """Where the spare word of the noun at `i` stands: right before it ("a spare roll"), or
        before a modifier that names no kind (`spare_before_head`: "the spare club towel")."""
        words = self.text.words
        if i >= 1 and words[i - 1] in SPARE_WORDS:
            return i - 1
        return i - 2 if i >= 2 and words[i - 2] in SPARE_WORDS and self.spare_before_head(i - 2) else None

    def spare_before_head(self, i: int) -> bool:
        """Whether word `i` ("spare") is an adjective before a modifier and a noun that names a kind
        ("the spare club towel", "a spare guest pillow", "the spare staff mug"): the modifier
        names no kind, so "spare" is no noun taking up the thing named before it ("fetch a spare
        from the drawer" is)."""
        words, gaps = self.text.words, self.text.gaps
        return i + 2 < len(words) and gaps[i + 1] == " " and gaps[i + 2] == " " and words[i + 1].isalpha() \
            and words[i + 1] not in _PREPOSITIONS and not self.verb(i + 1) \
            and self.names_kind(i + 2)

    def spare_of_unnamed(self, i: int) -> bool:
        """Whether a plural "spares" at word `i` takes up a plural noun that names no kind, said
        nearer before it in its sentence than any thing named ("Switch the torch off, batteries
        cost a fortune and the spares are flat": spare batteries, no second torch; "the remote's
        batteries are dead, the spares are in the drawer"). A noun phrase's number tells what an
        elided head takes up: a plural "spares" the nearest plural noun. A plural that may be a
        verb ("keys", "bags") counts after a determiner only ("the torch bulbs ... the spares").
        Why: the nearest *named* thing was taken, a second object of a kind the text has one of."""
        words, raw = self.text.words, self.text.raw
        if "spare" not in getAllLemmas(raw[i]).get("NOUN", ()) or raw[i] == "spare":
            return False
        for k in range(i - 1, self.text.sentence_start(i) - 1, -1):
            if self.match(k)[1] is not None:
                return False
            lemmas = getAllLemmas(raw[k])
            nouns = lemmas.get("NOUN", ())
            if raw[k].isalpha() and nouns and raw[k] not in nouns \
                    and ("VERB" not in lemmas or k > 0 and words[k - 1] in _DETERMINERS | _POSSESSIVES):
                return True
        return False

    def company_at_place(self, i: int) -> bool:
        """Whether a plural "the spares" at word `i` is the company a thing is put with: after a
        preposition of company (`_COMPANY`: "with", "beside", "among") in a sentence that puts
        something in or on a place before it ("it goes on the shelf, bin 3, with the spares", "put
        it in the drawer with the spares"). Those spares are where the thing joins others of its
        kind, as "with the others" is; no second object the task needs. A spare used ("replace
        the batteries with the spares": no place) or fetched ("fetch a spare") is still one."""
        words, raw = self.text.words, self.text.raw
        if raw[i] == "spare" or i < 3 or words[i - 1] != "the" or words[i - 2] not in _COMPANY:
            return False
        return any(w in _PUT_PLACES for w in words[self.text.sentence_start(i):i - 2])

    def contents_modifier(self, i: int) -> bool:
        """Whether word `i`, a spare word before a noun, is written plural ("the spares box", "an
        extras drawer", "the replacements bin"): an attributive plural noun says what the thing
        holds, as "a parts bin" or "the sales team" do, so the box is the one the text names again
        ("The cardboard box of spare track"), no spare box beside it. The adjective ("a spare
        box") still names a spare."""
        raw = self.text.raw[i]
        return raw != self.text.words[i] and raw.endswith("s")

    def heading_vessel(self, i: int) -> str | None:
        """The kind an item's heading named by its contents ("- Wine.", "Milk.", "DETERGENT.": the
        catalog's wine bottle, milk carton and laundry detergent, by their synonyms) when the next
        sentence opens with the article and the word of its vessel, after a subordinator at most
        ("The bottle's on the desk as well", "The carton is on the counter", "If the bottle has
        ended up on the floor"): the same thing, said by its vessel, as "Wine: the bottle ..." (one
        sentence) was read already; not a second, plain bottle. Its vessel is the word its name
        ends in, or the last word of its AI2-THOR type (a laundry detergent is a "SoapBottle", a
        board game a "Box": `vessel_word`). The heading is a sentence of that name alone."""
        words = self.text.words
        start = self.text.sentence_start(i)
        led = start + (words[start] in SUBORDINATORS)
        if start < 1 or i != led + 1 or words[led] not in _ARTICLES:
            return None
        head = self.text.sentence_start(start - 1)
        at = head + (words[head] in _ARTICLES)
        n, category = self.match(at)
        if category is None or at + n != start or category not in self.kinds \
                or words[i] not in (words_of(category)[-1], self.vessel_word(category)) or words[i] in words[at:at + n]:
            return None
        return category

    def vessel_word(self, category: str) -> str:
        """The last word of the kind's AI2-THOR type, lower case ("SoapBottle": "bottle"; "" when
        it has none): what the simulator's own object is, so what a text may call it by."""
        parts = re.findall(r"[A-Z][a-z]*", self.catalog.categories[category].ai2thor_type or "")
        return parts[-1].lower() if parts else ""

    def heading_spare(self, i: int) -> bool:
        """Whether word `i` ("spare"), definite or owned ("my spare one", "the spare"), is the thing
        the heading right before its sentence names: an item's heading ("- Torch.", "Phone
        charger.") is a sentence of that name alone, its thing named nowhere before, and the body's
        first word for it is the spare, no pronoun for the heading's thing before it ("Torch. Left
        my spare one behind, it's on the shelf": one torch, the spare). "Bulb. If it's blown, fetch
        the spare" (the bulb in use, then the spare) and "a spare" (indefinite) still name a
        spare of their own."""
        words = self.text.words
        start = self.text.sentence_start(i)
        if start < 1:
            return False
        head = self.text.sentence_start(start - 1)
        at = head + (words[head] in _ARTICLES)
        n, category = self.match(at)
        kind = self.kinds.get(category) if category is not None else None
        if category is None or kind is None or kind.instances or kind.count > 1 or self.first_at.get(category) != at \
                or at + n != start or not self.catalog.categories[category].pickable:
            return False
        return not any(w in _THING_PRONOUNS for w in words[start:i])

    def kind_value(self, i: int, n: int, prev: str) -> bool:
        """Whether the bare plural at word `i` (`n` words: "dolls", "toy cars"), or an indefinite
        singular set against "any other <kind>", is a class of a kind named before it, one of the values of its `kind` attribute (`KIND_ATTRIBUTES`; a toy
        is a doll, a car, a ball ...): what a distribution sorts ("dolls in the red box, toy cars
        in the blue box, everything else in the green one"), not an object of its own."""
        words = self.text.words
        head = words[i + n - 1]
        kinds = [c for c in self.recent for key in KIND_ATTRIBUTES
                 if head in self.catalog.categories[c].attributes.get(key, ())]
        if (prev in _GENERIC_ONE or self.bare_heading(i, n)) and self.text.raw[i + n - 1] == head:
            # "a doll into the red toy box; ... any other toy into the green one": an indefinite
            # one set against "other <kind>" in its sentence is a class of that kind too, or in a
            # run of sentences that each open with one ("A novel goes on the bookshelf. A
            # textbook goes on the desk. Any other book goes in the drawer."), or with a bare
            # singular heading ("Novel: to the bookshelf. Textbook: to the desk. Any other book: ...")
            end = self.text.sentence_end(i)
            for _ in range(_RUN):
                if end >= len(words) or words[end] not in _RUN_OPENERS and not self.bare_heading(end, 1):
                    break
                end = self.text.sentence_end(end)
            said = words[self.text.sentence_start(i):end]
            return any(w == "other" and set(said[k + 1:k + 3]) & set(words_of(c))
                       for c in kinds for k, w in enumerate(said))
        if self.text.raw[i + n - 1] == head or prev in _DETERMINERS or prev in _COUNTS:
            return False
        return bool(kinds)

    def purpose_class(self, i: int, n: int, prev: str) -> bool:
        """Whether the bare plural at word `i` (`n` words) after "for" is a class a holder is for,
        set against "other <kind>" in its sentence, of whose `kind` values it is one: "a red toy box
        for dolls and a white toy box for other toys", "a top shelf for novels, a lower one for
        other books". The kind may be named only after it (`kind_value` asks for one named
        before), so the class is known by the contrast; a plural after "for" with no "other" of its
        kind ("a basket for the towels", "a hook for keys") stays an object."""
        words = self.text.words
        head = words[i + n - 1]
        if prev != "for" or self.text.raw[i + n - 1] == head:
            return False
        said = words[self.text.sentence_start(i):self.text.sentence_end(i)]
        others = {said[k + 1] for k, w in enumerate(said[:-1]) if w == "other"}
        return any(words_of(c)[-1] in others and head in cat.attributes.get(key, ())
                   for c, cat in self.catalog.categories.items() for key in KIND_ATTRIBUTES)

    def bare_heading(self, i: int, n: int) -> bool:
        """Whether the `n` words at `i` are a heading of their own: a bare singular noun opening its
        sentence, right before a colon ("Novel: to the bookshelf", "Textbook: to the desk"), said
        of what is of that kind, as "a novel" is."""
        words, gaps = self.text.words, self.text.gaps
        end = i + n
        return (i == 0 or bool(_SENTENCE_END.search(gaps[i]))) and end < len(words) and ":" in gaps[end] \
            and self.text.raw[end - 1] == words[end - 1]

    def own_kind(self, a: int, b: int, head: str) -> bool:
        """Whether words `a`..`b` of an item name one thing of a kind of its own, with another
        head noun ("a doll" in "two toys: a doll and a ball"; not "a tea cup" in "two cups: ...",
        nor the class of things a part holds: "three levels hold novels, essays, ...")."""
        words = self.text.words
        k = next((k for k in range(a, b) if words[k] not in _DETERMINERS and words[k] not in COLOR_WORDS), None)
        if k is None or k == a or words[k - 1] not in _ARTICLES or self.text.raw[b - 1] != words[b - 1]:
            return False
        n, category = self.match(k)
        return category is not None and k + n == b and words[b - 1] != head

    def coordinated(self, j: int, allowed: list[str]) -> list[str]:
        """The colour at word `j` and those coordinated before it, in order ("a red and a white
        toy box", "the red, blue and green boxes")."""
        words, gaps = self.text.words, self.text.gaps
        out = [words[j]]
        joined = False  # a comma joins colours only before an "and" ("red, blue and green")
        while True:
            k = j - 1
            while k >= 0 and words[k] in _ARTICLES:
                k -= 1
            if k >= 0 and words[k] in ("and", "or"):
                joined = True
                k -= 1
                while k >= 0 and words[k] in _ARTICLES:
                    k -= 1
            elif not (joined and k + 1 < len(words) and "," in gaps[k + 1]):
                break
            if k < 0 or words[k] not in allowed:
                break
            out.insert(0, words[k])
            j = k
        # the first colour of the list must describe a noun phrase: "the sofa is red and the
        # blue toy box" is one box
        if len(out) > 1 and (j == 0 or words[j - 1] not in _DETERMINERS and words[j - 1] not in _COUNTS):
            return out[-1:]
        return out

    # -- the whole text --------------------------------------------------------------------

    def read(self) -> list[dict[str, Any]]:
        self.enumerations()
        self.recent, self.used = [], {}
        words = self.text.words
        last_colored: str | None = None
        i = 0
        while i < len(words):
            # (a word of the sentence before is no determiner: "... the right one. Dolls go in ...")
            prev = words[i - 1] if i > 0 and not _SENTENCE_END.search(self.text.gaps[i]) else ""
            if i in self.fixed:
                i += 1  # "bar none", "threw in the towel": a fixed expression names no thing
                continue
            if i in self.consumed:
                n, category = self.match(i)
                if category is not None:
                    self.mention(category, words[i + n - 1])
                i += 1
                continue
            if words[i] == "one" and prev in COLOR_WORDS and last_colored is not None:
                self.instance(last_colored, f"{prev}_{last_colored}", {"color": prev})
                i += 1
                continue
            color = self.which_one_color(i)
            if color is not None:
                # "Biff them in the bucket. It's the red one by the slider", "into the basket by the
                # door (the grey plastic one)": saying which one the thing named last is gives its colour
                self.colors[self.recent[-1]] = color
                i += 1
                continue
            if words[i] in SPARE_WORDS and prev in _DETERMINERS and self.says_which(i):
                i += 1  # "a hard hat on the floor (it's the spare, not his)": which one it is, no other
                continue
            if words[i] in SPARE_WORDS and (prev in _POSSESSIVES or prev == "the") and self.heading_spare(i):
                i += 1  # "- Torch. Left my spare one behind, it's on the shelf": the heading's torch
                continue
            if words[i] in SPARE_WORDS and prev in _DETERMINERS and (
                    i + 1 == len(words) or not self.names_kind(i + 1)) \
                    and not self.spare_before_head(i):
                # "a spare" as a noun: "fetch a spare from the dresser", "we store the spares"
                spare = None if self.spare_of_unnamed(i) or self.company_at_place(i) else next(
                    (c for c in reversed(self.recent) if self.catalog.categories[c].pickable), None)
                if spare is not None:
                    kind = self.kinds.setdefault(spare, _Kind())
                    if not any(name.startswith("spare_") for name in kind.instances):
                        self.instance(spare, f"spare_{words_of(spare)[-1]}", {})
                i += 1
                continue
            if (reglossed := self.one_glossed(i)) is not None:
                # "the lost property box (the cardboard one under the table)": the box is cardboard
                before, category, said = reglossed
                if self.first_at.get(before, i) >= i - 6:  # (its only naming: else the others keep it)
                    del self.kinds[before]
                    self.recent.remove(before)
                    self.particular.discard(before)
                self.kinds.setdefault(category, _Kind()).generic = True
                self.first_at.setdefault(category, i)
                self.particular.add(category)
                self.mention(category, said)
                i += 2
                continue
            if self.part_said_of(i):
                i += 1  # "the lower shelf of the metal rack": the rack's shelf, no object
                continue
            if words[i] in _COLLECTIVES and words[i + 1:i + 2] == ["of"]:
                i += 1  # "a spare set of keys": the keys, no television set
                continue
            if self.part_of_named(i, prev):
                i += 1  # "Shelving unit - the storage box lives on the bottom shelf": its shelf
                continue
            if self.packaging_of_topic(i):
                i += 1  # "Tin foil: in case the roll has fallen ...": the foil's roll, no toilet roll
                continue
            shared = self.shared_head(i)
            n, category = (1, shared) if shared is not None else self.kind_at(i)
            if shared is None and (glossed_as := self.said_as_gloss(i)) is not None:
                # "the chart table (the little desk ...). ... on the chart table": the desk again
                n, category = 1, glossed_as
            if category is None:
                i += 1
                continue
            if shared is None and self.part_by_other_name(i, n, category):
                i += n  # "the mantelpiece above the fireplace": the fireplace's, no wall shelf
                continue
            if shared is None and self.modifies_other(i, n):
                i += n  # "Car park gate open", "the food bank pick-up": a park, a bank, no car or food
                continue
            if shared is None and self.modifies_next(i, n) and self.named_holder(i, n, category) is None:
                i += n  # "the collection basket", "the chart table drawer": the last noun is the head
                continue
            if shared is None:
                n, category = self.compound(i, n, category)
            if (on_wall := self.wall_sibling(i + n, category)) is not None:
                category = on_wall  # "the cupboard over the kettle": the wall cabinet
            room = next((len(r) for r in self.room_ids if tuple(words[i:i + len(r)]) == r and len(r) > n), 0)
            if room:
                i += room  # "Laundry room - FAQ": the task's room, no laundry in it
                continue
            if (holder := self.holder_in_name(i, n, category)) is not None:
                # "the dresser drawers": the dresser (whose drawer a later "the drawer" is)
                self.part_holders.setdefault(category, set()).add(holder)
                category = holder
            elif self.part_of_its_furniture(i, n, category, prev):
                i += n  # "file it in the filing cabinet - the drawer may be pulled out": its drawer
                continue
            if self.predicate_noun(i):
                i += n  # "The essay collection is on the desk, that's a library book"
                continue
            if self.kind_value(i, n, prev) or self.purpose_class(i, n, prev):
                i += n  # "a toy on the floor ... dolls in the red box, toy cars in the blue box"
                continue
            if shared is None and self.subject_renamed(i, n, category):
                i += n  # "The table lamp is on the desk - my reading lamp": the lamp said again
                continue
            if shared is None and self.appositive(i, n, category):
                # "Papa ka kurta, the white shirt, ...": the shirt named again, its colour said
                told = self.color_before(i + n - 1)
                if told is not None and words[told] in self.catalog.categories[category].attributes.get("color", []):
                    self.colors[category] = words[told]
                i += n
                continue
            if shared is None and (glossed := self.glossed(i, n, category) or self.renamed_fuller(i, n, category)
                                   or self.headed_fuller(i, n, category)) is not None:
                # "Cupboard on wall (wall cabinet, over sink)": one thing, named by the fuller name
                del self.kinds[glossed]
                self.recent.remove(glossed)
                self.particular.discard(glossed)
            if shared is None and (spare_of := self.glossed_spare(i, n, category)) is not None:
                # "The spare field book (yellow notebook)": the spare is the notebook
                before, spare = spare_of
                del self.kinds[before].instances[spare]
                if not self.kinds[before].instances and not self.kinds[before].generic:
                    del self.kinds[before]
                    self.recent.remove(before)
            kind = self.kinds.setdefault(category, _Kind())
            self.first_at.setdefault(category, i)
            if (subject := self.unnamed_subject(i)) is not None:
                self.said_as.setdefault(category, subject)  # "The treasure map be on ... 'Tis only paper"
            known = category in self.recent
            self.mention(category, words[i + n - 1])
            allowed = self.catalog.categories[category].attributes.get("color", [])
            last = words[i + n - 1] if words[i + n - 1] not in _PACKAGING else words_of(category)[-1]
            told = self.color_before(i)
            if told is not None and words[told] in allowed and not self.color_class(told, category):
                if kind.generic and not kind.instances and self.restates_plain(told, category):
                    self.restated.add(category)  # "a silk scarf ... PROPS: one red silk scarf"
                for color in self.coordinated(told, allowed):
                    self.instance(category, f"{color}_{category}", {"color": color})
                last_colored = category
            elif (spare_at := self.spare_word_before(i)) is not None and not self.contents_modifier(spare_at) \
                    or prev in _FRESH and known and kind.generic:
                if not any(name.startswith("spare_") for name in kind.instances):
                    self.instance(category, f"spare_{last}", {})
            elif prev in _ANOTHER and known and kind.generic:
                self.instance(category, f"other_{last}", {})  # "a lamp on the desk and another lamp"
            elif self.names_the_colored_one(i, n, kind, prev, category):
                pass  # "My blue cup is standing on kitchen table. If cup is dirty": the blue cup again
            else:
                self.headed[category] = self.headed.get(category, True) and not kind.instances \
                    and self.heading_mention(i, n)
                kind.generic = True
                if prev in _DETERMINERS or prev in _COUNTS or self.text.raw[i + n - 1] == words[i + n - 1]:
                    self.particular.add(category)
                if prev in self.possessors and self.match(i - 1)[1] is None:
                    self.owners.setdefault(category, []).append(prev)
                if prev in _COUNTS:
                    kind.count = max(kind.count, _COUNTS[prev])
                    if allowed:
                        last_colored = category
            i += n
        for category, owners in self.owners.items():
            if len(set(owners)) >= 2 and not self.kinds[category].instances:
                # "Marco's glass and Lena's glass": one object per owner, told apart by whose it is
                for owner in dict.fromkeys(owners):
                    self.instance(category, f"{owner}_{words_of(category)[-1]}", {"owner": owner})
        found: list[dict[str, Any]] = []
        for category, kind in self.kinds.items():
            told_apart = len(kind.instances) >= max(2, kind.count)
            if kind.generic and not told_apart and not kind.instances and self.class_of_named(category):
                continue  # "Toys are kept in the toy box. Should the doll or the toy car ...": the class
            if kind.generic and not told_apart and kind.instances and category not in self.particular \
                    and all(name.startswith("spare_") for name in kind.instances):
                generic = False  # "THE SPARE BULB ... BROKEN BULBS GO IN THE BIN": a rule for the spare
            elif kind.generic and self.headed.get(category) and kind.count <= 1 and len(kind.instances) == 1 \
                    and all(set(attrs) == {"color"} for attrs in kind.instances.values()):
                generic = False  # "3. The folder. ... the blue folder has slipped off the desk": one folder
            elif kind.generic and category in self.restated and kind.count <= 1 and len(kind.instances) == 1 \
                    and all(set(attrs) == {"color"} for attrs in kind.instances.values()):
                generic = False  # "a silk scarf ... PROPS: one red silk scarf": one scarf, now told fully
            else:
                generic = kind.generic and not told_apart
            if generic:
                found.append({"name": _snake(self.said_as.get(category, category)), "category": category,
                              "attributes": {"color": self.colors[category]} if category in self.colors else {}})
            found += [{"name": name, "category": category, "attributes": attrs}
                      for name, attrs in kind.instances.items()]
        return list({o["name"]: o for o in found}.values())


def name_objects(description: str, catalog: Catalog, rooms: Iterable[str] = ()) -> list[dict[str, Any]]:
    """Catalog categories and synonyms named in the description, read as a careful reader would
    (the module docstring): one object per kind named, or one per instance where the text tells
    several apart, named for what tells them apart, with the colour as attribute."""
    return _Reader(description, reading_catalog(catalog), rooms).read()


def _own(cat: Category) -> list[str]:
    """A kind's catalog synonyms without the WordNet names the reading catalog appends: those name
    a thing as a whole phrase only, and lend no words to the context that tells kinds apart ("low"
    of "low-fat milk" must not make "the table" the coffee table, "low table")."""
    return [s for s in cat.synonyms if not is_wordnet_name(s)]


def _lemma_named(name: str) -> bool:
    """Whether a name is written as its words' lemmas ("glass", "chair"; not "glasses", the
    spectacles, whose lemma is another kind's name): only such a name is a word's own kind."""
    return words_of(name) == tuple(re.findall(r"[a-z0-9]+", name.lower().replace("_", " ")))


def _possessives(description: str) -> frozenset[str]:
    """The words (singular, lower case) the description writes as possessives: those whose "'s"
    `expand` drops (not "the kettle's still on": "is")."""
    text = description.replace("\u2019", "'")
    return frozenset(singular(m.group(1).lower()) for m in _POSSESSIVE.finditer(text)
                     if len(WORD.findall(expand(m.group(0)).lower())) == 2)


def _snake(name: str) -> str:
    return re.sub(r"[^a-z0-9_]", "_", name)
