"""Word tables and sentence splitting both readers of a description share: the factor reader
(`offline.analysis`) and the placement reader (`offline.placement`) read with the same states,
action verbs, prepositions, contractions and sentences."""

from __future__ import annotations

import re

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
    "broken": ("broken", True), "cracked": ("broken", True),
    "spinning": ("toggled_on", True), "whirring": ("toggled_on", True), "unlit": ("toggled_on", False),
    "grubby": ("dirty", True), "filthy": ("dirty", True), "soiled": ("dirty", True),
    "grimy": ("dirty", True), "smudged": ("dirty", True), "mucky": ("dirty", True),
}
#: action verbs before an object: a location after the object is a goal
ACTIONS = frozenset(
    ["put", "place", "move", "take", "bring", "return", "carry", "drop", "set", "lay", "stand", "hang", "throw", "toss", "tuck", "store", "stow", "leave", "fold", "bin", "transfer", "slide", "shove", "push", "pour", "empty", "fill", "refill", "sort", "give", "file", "load", "unload", "shelve",
     "pack", "stack", "deliver"]
)
PREP_ON = frozenset({"on", "onto", "atop", "upon"})

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
    (r"\bcan't\b", "can not"), (r"\bwon't\b", "will not"), (r"n't\b", " not"),
    (r"\b(i|you|we|they)'ve\b", r"\1 have"), (r"\b(i|you|we|they|it)'ll\b", r"\1 will"),
    (r"\b(\w+)s'(\s)", r"\1s\2"), (r"\b(\w+)'s\b", r"\1"),
    # the texting register's contractions without an apostrophe ("theres a mark", "if there arent
    # any", "dont"), and "u" for "you"; words that are also words ("its", "were", "wont", "ill")
    # are left alone
    (r"\b(there|that|what|where|here)s\b", r"\1 is"), (r"\b(you|they)re\b", r"\1 are"),
    (r"\b(is|are|was|were|do|does|did|has|have|had|could|should|would|must)nt\b", r"\1 not"),
    (r"\bdont\b", "do not"), (r"\bcant\b", "can not"), (r"\bu\b", "you"),
    # a slash between words offers alternatives ("on the office chair / on the floor")
    (r"(?<=[a-z])\s*/\s*(?=[a-z])", " or "),
]
#: an arrow says "then": what follows it is the instruction of what came before ("Coffee machine:
#: still on? -> switch OFF.", "Lamp on => off"), never a sentence of its own
ARROW = re.compile(r"\s*(?:->|=>|\u2192)\s*")
_SENT = re.compile(r"(?<=[.!?;:])\s+(?!->|=>|\u2192)|\n+|(?<=\))\s+(?=[A-Z])")
_FULL_STOP = re.compile(r"(?<=[.!])\s+|\n+")
_ABBREV = re.compile(r"\b(e\.g|i\.e|etc|approx|vs)\.", re.I)


def expand(text: str) -> str:
    """The text with contractions spelled out ("it's" -> "it is") and possessives dropped."""
    out = text.replace("\u2019", "'")
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
