"""Word tables and sentence splitting both readers of a description share: the factor reader
(`offline.analysis`) and the placement reader (`offline.placement`) read with the same states,
action verbs, prepositions, contractions and sentences."""

from __future__ import annotations

import re

from logicenveval.offline.lexicon import COLOR_WORDS, verb_form

#: adjective/participle -> (state flag, polarity)
STATE_WORDS: dict[str, tuple[str, bool]] = {
    "open": ("open", True), "opened": ("open", True), "ajar": ("open", True),
    "closed": ("open", False), "shut": ("open", False),
    "on": ("toggled_on", True), "lit": ("toggled_on", True), "running": ("toggled_on", True),
    "burning": ("toggled_on", True), "off": ("toggled_on", False),
    "dirty": ("dirty", True), "stained": ("dirty", True), "messy": ("dirty", True),
    "dusty": ("dirty", True), "muddy": ("dirty", True), "greasy": ("dirty", True),
    "sticky": ("dirty", True), "used": ("dirty", True), "clean": ("dirty", False),
    "spotless": ("dirty", False), "wet": ("wet", True), "damp": ("wet", True),
    "soaked": ("wet", True), "soggy": ("wet", True), "dry": ("wet", False),
    "full": ("filled", True), "filled": ("filled", True), "empty": ("filled", False),
    "cooked": ("cooked", True), "raw": ("cooked", False), "sliced": ("sliced", True),
    "out": ("toggled_on", False), "extinguished": ("toggled_on", False),
    "ringing": ("toggled_on", True), "beeping": ("toggled_on", True), "playing": ("toggled_on", True),
    "silent": ("toggled_on", False), "stopped": ("toggled_on", False), "idle": ("toggled_on", False),
    "broken": ("broken", True), "cracked": ("broken", True), "blown": ("broken", True),
    "busted": ("broken", True), "faulty": ("broken", True), "shattered": ("broken", True),
    "smashed": ("broken", True),
    "spinning": ("toggled_on", True), "whirring": ("toggled_on", True), "unlit": ("toggled_on", False),
    "grubby": ("dirty", True), "filthy": ("dirty", True), "soiled": ("dirty", True),
    "grimy": ("dirty", True), "smudged": ("dirty", True), "mucky": ("dirty", True),
}
#: the personal pronouns that can be a clause's subject; each reader adds the other subjects it
#: needs (`clauses.SUBJECTS`, `placement.SUBJECT_PRONOUNS`, `naming`'s relative-clause test)
PERSONAL_SUBJECTS = frozenset({"i", "we", "you", "he", "she", "they"})
#: action verbs before an object: a location after the object is a goal
ACTIONS = frozenset(
    ["put", "place", "move", "take", "bring", "return", "carry", "drop", "set", "lay", "stand", "hang", "throw", "toss", "tuck", "store", "stow", "leave", "fold", "bin", "transfer", "slide", "shove", "push", "pour", "empty", "fill", "refill", "sort", "give", "file", "load", "unload", "shelve",
     "pack", "stack", "deliver"]
)
PREP_ON = frozenset({"on", "onto", "atop", "upon"})
#: what a carried thing comes in: "Tin foil: in case the roll has fallen", "Sunscreen - if the
#: bottle is empty": the thing spoken of, in its roll or bottle (`naming`, `analysis.mentions`)
FORMS = frozenset({"bag", "pack", "packet", "carton", "roll", "bottle", "tube", "jar", "tub", "can",
                   "container", "box", "spray"})
#: words that open a noun phrase and say which one is meant (`determiner`)
DETERMINERS = frozenset({"the", "a", "an", "my", "our", "your", "his", "her", "its", "their", "this",
                         "that", "these", "those", "any", "every", "each", "some", "no"})


def determiner(words: list[str], start: int) -> str:
    """The word that determines the noun phrase whose noun starts at `start`: the word before
    it, or the determiner before one plain adjective ("the little statue", "my old lamp"): not a
    state word ("a dirty plate": the state may be the condition itself), a colour, a preposition
    or a verb form."""
    before = words[start - 1] if start > 0 else ""
    if start > 1 and words[start - 2] in DETERMINERS and before.isalpha() and before not in (
            DETERMINERS | PREP_ON | PREP_IN | STATE_WORDS.keys() | COLOR_WORDS) and not verb_form(before):
        return words[start - 2]
    return before

#: habitual aspect: a statement of what keeps happening ("my ball keeps ending up on the floor",
#: "the scarf tends to slip off the hook", "the remote often lies on the rug", "the towel usually
#: gets left on the floor") says what may be so in a scene, not a fact of this one. Frequency
#: adverbs always make it; adverbs of a norm only with a verb of an event ("usually gets left"),
#: since with one of being they state the norm ("Normally a fresh diaper is lying on the table")
FREQUENCY = frozenset({"often", "frequently", "regularly", "repeatedly", "constantly", "sometimes",
                       "occasionally", "forever"})
NORM_ADVERBS = frozenset({"usually", "normally", "generally", "typically", "always"})
EVENT_VERBS = frozenset({"get", "gets", "got", "getting", "end", "ends", "ended", "ending", "wind", "winds",
                         "wound", "fall", "falls", "roll", "rolls", "slip", "slips", "turn", "turns"})
#: "tends to <verb>"; "keeps <verb>-ing"
TEND = frozenset({"tend", "tends", "tended"})
KEEP = frozenset({"keep", "keeps", "kept"})
#: the words of a habitual form, which say nothing of the place or the state themselves
HABITUAL_WORDS = FREQUENCY | NORM_ADVERBS | TEND | KEEP | {"to"}


def habitual(words: list[str]) -> bool:
    """Whether a clause's words are in the habitual aspect (see `FREQUENCY`)."""
    for k, w in enumerate(words):
        nxt = words[k + 1] if k + 1 < len(words) else ""
        if (w in FREQUENCY or w in TEND and nxt == "to" or w in KEEP and len(nxt) > 4 and nxt.endswith("ing")
                or w in NORM_ADVERBS and bool(set(words[k + 1:k + 3]) & EVENT_VERBS)):
            return True
    return False
PREP_IN = frozenset({"in", "inside", "into", "within"})

#: words after a noun's "'s" that make it the verb, not a possessive: "the door's shut", "the
#: pillow's been moved", "the dishwasher's already on" (but "the cat's ball")
_HAS_AFTER = ("been", "got", "gotten")
_IS_AFTER = tuple(STATE_WORDS) + ("already", "still", "not", "probably", "just", "now", "in", "on", "under",
                                  "lying", "sitting", "left", "gone", "missing", "there", "here")
_CONTRACTIONS = [
    (r"\b(it|that|there|what|where|who|how|here|he|she)'s\b", r"\1 is"), (r"\b(they|we|you)'re\b", r"\1 are"),
    (rf"\b(\w+)'s(?=\s+(?:{'|'.join(_HAS_AFTER)})\b)", r"\1 has"),
    (rf"\b(\w+)'s(?=\s+(?:{'|'.join(_IS_AFTER)})\b)", r"\1 is"),
    # typed or dictated without the apostrophe ("if its not in there", "if its dirty"): "its",
    # "thats", "theres" before what follows "is" are "it is", never a possessive
    (rf"\b(it|that|there|what|where)s(?=\s+(?:{'|'.join(_IS_AFTER)})\b)", r"\1 is"),
    (r"\bcan't\b", "can not"), (r"\bwon't\b", "will not"), (r"n't\b", " not"),
    (r"\b(i|you|we|they)'ve\b", r"\1 have"), (r"\b(i|you|we|they|it)'ll\b", r"\1 will"),
    (r"\b(\w+)s'(\s)", r"\1s\2"), (r"\b(\w+)'s\b", r"\1"),
    # the same contractions typed without their apostrophe ("theres a mark", "if there arent any"),
    # only where the form is no English word of its own ("were", "well", "its", "wed" are)
    (r"\b(there|that|what|where|who|here)s\b", r"\1 is"), (r"\b(they|you)re\b", r"\1 are"),
    (r"\b(is|are|was|were|do|does|did|has|have|had|should|could|would|must|need)nt\b", r"\1 not"),
    (r"\bcant\b", "can not"), (r"\bwont\b", "will not"), (r"\b(you|they|we)ve\b", r"\1 have"),
    # texting's "u" for "you" (not a letter of a name: "u-bend", "U-shaped")
    (r"(?<![\w'-])u(?![\w'-])", "you"),
]
#: an arrow says "then": what follows it is the instruction of what came before ("Coffee machine:
#: still on? -> switch OFF.", "Lamp on => off"), never a sentence of its own
ARROW = re.compile(r"\s*(?:->|=>|\u2192)\s*")
_SENT = re.compile(r"(?<=[.!?;:])\s+(?!->|=>|\u2192)|\n+|(?<=\))\s+(?=[A-Z])")
_FULL_STOP = re.compile(r"(?<=[.!])\s+|\n+")
_ABBREV = re.compile(r"\b(e\.g|i\.e|etc|approx|vs)\.", re.I)


#: a slash between two words offers alternatives, as "or" does ("on the chair / on the floor",
#: "wet/dirty"; "and/or" is "and or")
_SLASH = re.compile(r"(?<=[a-z])\s*/\s*(?=[a-z])", re.I)


#: an email's quoting: the attribution line above a quoted message ("On Monday, Jo wrote:") and
#: the ">" that opens each quoted line; neither says anything of the scene
_ATTRIBUTION = re.compile(r"^[ \t>]*On\b[^\n]{0,80}\bwrote:[ \t]*$", re.M)
_QUOTE_MARK = re.compile(r"^[ \t]*(?:>[ \t]?)+", re.M)


def unquote(text: str) -> str:
    """The text without an email's quoting marks: a reply above a quoted message reads as one
    text ("> On Monday, Jo wrote:" is no sentence; "> Could you tidy ..." is "Could you tidy ...");
    a table of items and places as its sentences (`detable`); a heading answered by a verb with no
    subject of its own with the heading as that subject (`_SUBJECTLESS`)."""
    return _SUBJECTLESS.sub(r"\1\2\3the \2 \4", detable(_QUOTE_MARK.sub("", _ATTRIBUTION.sub("", text))))


#: "Desk lamp: stays on the desk.", "- Sunscreen - lives in the cabinet": a line's heading of a few
#: words, answered by a verb of where a thing is or goes with no subject of its own and a place
#: after it, is said of the heading's thing ("the desk lamp stays on the desk"), so every reader
#: reads the place as in a sentence
_SUBJECTLESS = re.compile(r"(^[ \t]*(?:[-*\u2022]|\d+[.)])?[ \t]*)([A-Za-z][A-Za-z']*(?: [A-Za-z][A-Za-z']*){0,3})"
                          r"(\s*(?::|[-\u2013\u2014])\s*)(stays|lives|sits|stands|lies|belongs|goes|hangs|remains)"
                          r"(?=\s+(?:on|in|inside|into|onto|under|by|near|next|beside|behind|at|back|there|here)\b)",
                          re.I | re.M)


#: a table's column of item names and its column of places ("Item | Location | Notes"), and the
#: columns that only number the rows ("No.", "#")
_ITEM_HEADS = frozenset({"item", "items", "object", "thing", "what"})
_PLACE_HEADS = frozenset({"location", "place", "where", "position"})
_EMPTY_CELL = frozenset({"", "-", "\u2013", "\u2014", "n/a", "none"})
#: "As item 4.", "Same as 4": a row whose notes are another row's
_AS_ROW = re.compile(r"^(?:as|same as)\s+(?:item|no\.?|row|#)?\s*(\d+)\.?$", re.I)
_PLACE_DOUBT = re.compile(r"\b(?:if|unless|when|should)\b[^.;]*?\b(?:on|in|inside|under|at)\s+[a-z]", re.I)
_PLACE_START = re.compile(r"^(?:on|in|inside|under|by|near|next|beside|behind|at|against|above|below)\b", re.I)


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.strip().strip("|").split("|")]


def detable(text: str) -> str:
    """A table of items and where they are ("No. | Item | Location | Notes" then "2 | First aid kit
    | on the shelving unit | To be kept closed.") as the sentences it stands for: "First aid kit is
    on the shelving unit. To be kept closed." A place cell without a preposition is on or by what
    it names ("back wall", "shelving unit, top shelf"); "As item 4." repeats row 4's notes. Text
    that holds no such table is returned as it is."""
    lines = text.split("\n")
    out: list[str] = []
    header: list[str] | None = None
    notes_of: dict[str, str] = {}
    for line in lines:
        if line.count("|") < 2:
            header = None
            out.append(line)
            continue
        cells = _cells(line)
        heads = [c.lower().rstrip(".:") for c in cells]
        if header is None:
            if set(heads) & _ITEM_HEADS and set(heads) & _PLACE_HEADS:
                header = heads
                continue
            out.append(line)
            continue
        if set(re.sub(r"[-:| ]", "", line)) <= {""}:
            continue  # a "---|---" rule under the header
        row = dict(zip(header, cells, strict=False))
        item = next((row[h] for h in header if h in _ITEM_HEADS), "")
        place = next((row[h] for h in header if h in _PLACE_HEADS), "")
        number = next((row[h] for h in header if h in ("no", "#", "number")), "")
        note = " ".join(row[h] for h in header if h not in _ITEM_HEADS | _PLACE_HEADS | {"no", "#", "number"}
                        and row.get(h, "").lower() not in _EMPTY_CELL)
        again = _AS_ROW.match(note)
        if again is not None:
            note = notes_of.get(again.group(1), "")
        notes_of[number] = note
        sentence = ""
        if item and place.lower() not in _EMPTY_CELL:
            where = place if _PLACE_START.match(place) else (
                f"on the {place}" if not place.lower().endswith("wall") else f"against the {place}")
            # a row whose notes ask where the item is ("If not on the shelving unit, ...") lists
            # where it belongs, not where it is
            verb = "belongs" if _PLACE_DOUBT.search(note) else "is"
            sentence = f"The {item[0].lower()}{item[1:]} {verb} {where}."
        elif item:
            sentence = f"The {item[0].lower()}{item[1:]}."
        if note:
            sentence += " " + (note if note.endswith((".", "!", "?")) else note + ".")
        out.append(sentence.strip())
    return "\n".join(out)


def expand(text: str) -> str:
    """The text with contractions spelled out ("it's" -> "it is"), possessives dropped and a
    slash between words read as "or"."""
    out = _SLASH.sub(" or ", text.replace("\u2019", "'"))
    for pat, repl in _CONTRACTIONS:
        out = re.sub(pat, repl, out, flags=re.I)
    return out


def split_sentences(text: str, *, full_stops_only: bool = False) -> list[str]:
    """The text's sentences (and `;`/`:`-separated parts), abbreviations kept whole. With
    `full_stops_only`, only at a full stop, "!" or a line break: for a reader that cuts the rest
    itself (`offline.clauses.clause_spans` cuts at ";", ":", "?" and brackets)."""
    protected = _ABBREV.sub(lambda m: m.group(0).replace(".", "\u2024"), text)
    parts = [p.strip().replace("\u2024", ".") for p in (_FULL_STOP if full_stops_only else _SENT).split(protected)]
    return [p for p in parts if p]
