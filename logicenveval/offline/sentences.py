"""Word tables and sentence splitting both readers of a description share: the factor reader
(`offline.analysis`) and the placement reader (`offline.placement`) read with the same states,
action verbs, prepositions, contractions and sentences."""

from __future__ import annotations

import re
from collections.abc import Callable

from lemminflect import getAllInflections, getAllLemmas, getInflection

from logicenveval.offline.lexicon import COLOR_WORDS, GREETINGS, singular, verb_form

#: adjective/participle -> (state flag, polarity)
STATE_WORDS: dict[str, tuple[str, bool]] = {
    "open": ("open", True), "opened": ("open", True), "ajar": ("open", True),
    "closed": ("open", False), "shut": ("open", False),
    "on": ("toggled_on", True), "lit": ("toggled_on", True), "lighted": ("toggled_on", True), "running": ("toggled_on", True),
    "burning": ("toggled_on", True), "glowing": ("toggled_on", True), "off": ("toggled_on", False),
    "dirty": ("dirty", True), "stained": ("dirty", True), "messy": ("dirty", True),
    "dusty": ("dirty", True), "muddy": ("dirty", True), "greasy": ("dirty", True),
    "sticky": ("dirty", True), "used": ("dirty", True), "clean": ("dirty", False),
    "spotless": ("dirty", False), "wet": ("wet", True), "damp": ("wet", True),
    "soaked": ("wet", True), "soggy": ("wet", True), "dry": ("wet", False),
    "full": ("filled", True), "filled": ("filled", True), "empty": ("filled", False),
    "cooked": ("cooked", True), "raw": ("cooked", False), "sliced": ("sliced", True),
    "out": ("toggled_on", False), "extinguished": ("toggled_on", False),
    "ringing": ("toggled_on", True), "beeping": ("toggled_on", True), "playing": ("toggled_on", True),
    "buzzing": ("toggled_on", True),
    "silent": ("toggled_on", False), "stopped": ("toggled_on", False), "idle": ("toggled_on", False),
    "broken": ("broken", True), "cracked": ("broken", True), "blown": ("broken", True),
    "busted": ("broken", True), "faulty": ("broken", True), "shattered": ("broken", True),
    "smashed": ("broken", True),
    "spinning": ("toggled_on", True), "whirring": ("toggled_on", True), "unlit": ("toggled_on", False),
    # the predicative adjective of burning, beside "lit" and "burning" ("if the candle is still
    # alight", "the fire was alight when I left")
    "alight": ("toggled_on", True),
    "grubby": ("dirty", True), "filthy": ("dirty", True), "soiled": ("dirty", True),
    "grimy": ("dirty", True), "smudged": ("dirty", True), "mucky": ("dirty", True),
}
#: general nouns that trade and service writing uses for a machine it has just named ("Air
#: conditioner. The unit is not to run overnight", "the dishwasher ... if the appliance is still
#: running"): after "the" / "this" / "that", and not as a place, they speak of that machine again
#: (`naming`'s `machine_again`: no shelving unit named; `analysis._Reader.machine_again`: "it")
MACHINE_EPITHETS = frozenset({"unit", "appliance", "device", "machine"})
#: the personal pronouns that can be a clause's subject; each reader adds the other subjects it
#: needs (`clauses.SUBJECTS`, `placement.SUBJECT_PRONOUNS`, `naming`'s relative-clause test)
PERSONAL_SUBJECTS = frozenset({"i", "we", "you", "he", "she", "they"})
#: verbs of a speaker's belief: after a subject pronoun ("I think", "we reckon", "I believe") they
#: hedge what follows, as "may" does (`clauses.uncertain_words`, `placement._believed`)
BELIEFS = frozenset({"think", "believe", "reckon", "suppose", "guess", "expect"})
#: verbs of taking a thing from where it is: an instruction "take a spare fuse from the drawer",
#: "grab a clean towel from the cupboard" presupposes the thing is in or on its source, a stated
#: fact and no question (`analysis.Fact.presupposed`, `placement._taken_from`)
TAKING_FROM = frozenset({"take", "grab", "fetch", "get", "pull", "pick", "collect", "retrieve", "remove"})
#: the words that may stand between such a verb and its thing ("take a spare one", "grab two new")
TAKEN_WORDS = frozenset({"a", "an", "the", "one", "some", "two", "three", "spare", "new", "fresh", "clean", "another",
                         "extra", "up", "out", "down", "of", "your", "my", "our"})


def taken_word(word: str) -> bool:
    """Whether `word` may stand between a verb of taking and its thing: one of `TAKEN_WORDS`, or a
    state the thing is taken in ("take a dry cloth"), but not "on"/"off" (where it is). The one
    test both readers of an instruction of taking use (`analysis._taken`, `placement._taken_from`)."""
    return word in TAKEN_WORDS or word in STATE_WORDS and word not in ("on", "off")


#: action verbs before an object: a location after the object is a goal
ACTIONS = frozenset(
    ["put", "place", "move", "take", "bring", "return", "carry", "drop", "set", "lay", "stand", "hang", "throw", "toss", "tuck", "store", "stow", "leave", "fold", "bin", "transfer", "slide", "shove", "push", "pour", "empty", "fill", "refill", "sort", "give", "file", "load", "unload", "shelve",
     "pack", "stack", "deliver",
     # informal verbs of putting, by their dictionary senses: "stick" (Oxford: "put (something)
     # somewhere in a quick or careless way": "then just stick it in the sink"), "biff"
     # (NZ/Australian English, to throw: Collins English Dictionary), "plonk" and "bung" (British
     # informal, to put down carelessly / to throw: Oxford Learner's Dictionaries); "chuck"
     # (informal, to throw carelessly), "pop" (British informal, to put somewhere quickly: "pop it
     # in the fridge") and "sling" (British informal, to throw or put carelessly), the same
     # dictionaries (thirty-first session)
     "stick", "biff", "plonk", "bung", "chuck", "pop", "sling"]
)
PREP_ON = frozenset({"on", "onto", "atop", "upon"})
#: what a carried thing comes in: "Tin foil: in case the roll has fallen", "Sunscreen - if the
#: bottle is empty": the thing spoken of, in its roll or bottle (`naming`, `analysis.mentions`)
FORMS = frozenset({"bag", "pack", "packet", "carton", "roll", "bottle", "tube", "jar", "tub", "can",
                   "container", "box", "spray"})
#: "the" and the persons' possessive determiners: they open a noun phrase of a thing taken as
#: known (a subject whose clause or place is said of it, a thing named again)
DEFINITE_OPENERS = frozenset({"the", "my", "your", "our", "his", "her", "their"})
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

def as_tokens(words: set[str]) -> frozenset[str]:
    """`words` as written and as `lexicon.tokens` gives them (its noun lemma, `singular`)."""
    return frozenset(words | {singular(w) for w in words})


#: habitual aspect: a statement of what keeps happening ("my ball keeps ending up on the floor",
#: "the scarf tends to slip off the hook", "the remote often lies on the rug", "the towel usually
#: gets left on the floor") says what may be so in a scene, not a fact of this one. Frequency
#: adverbs always make it; adverbs of a norm only with a verb of an event ("usually gets left"),
#: since with one of being they state the norm ("Normally a fresh diaper is lying on the table")
#: Each set holds its words as written and as `lexicon.tokens` gives them ("sometimes" ->
#: "sometime", "always" -> "alway": `as_tokens`), since both readers test them on tokens.
FREQUENCY = as_tokens({"often", "frequently", "regularly", "repeatedly", "constantly", "sometimes",
                        "occasionally", "forever"})
#: adverbs of a norm; said with a verb of resting they make a place a thing's usual one, a home
#: ("Upon the stove there commonly stands the saucepan", "On the hook usually hangs the key":
#: `placement`), with one of an event a habit (`habitual`)
NORM_ADVERBS = as_tokens({"usually", "normally", "generally", "typically", "always", "commonly", "ordinarily",
                           "customarily"})
EVENT_VERBS = frozenset({"get", "gets", "got", "getting", "end", "ends", "ended", "ending", "wind", "winds",
                         "wound", "fall", "falls", "roll", "rolls", "slip", "slips", "turn", "turns"})
#: "tends to <verb>"; "keeps <verb>-ing"
TEND = frozenset({"tend", "tends", "tended"})
KEEP = frozenset({"keep", "keeps", "kept"})
#: the words of a habitual form, which say nothing of the place or the state themselves
HABITUAL_WORDS = FREQUENCY | NORM_ADVERBS | TEND | KEEP | {"to"}


def habitual(words: list[str]) -> bool:
    """Whether a clause's words are in the habitual aspect (see `FREQUENCY`; an adverb of a norm
    with a participle of leaving a thing carelessly, "is always dropped on the floor", is one too)."""
    for k, w in enumerate(words):
        nxt = words[k + 1] if k + 1 < len(words) else ""
        if (w in FREQUENCY or w in TEND and nxt == "to" or w in KEEP and len(nxt) > 4 and nxt.endswith("ing")
                or w in NORM_ADVERBS and bool(set(words[k + 1:k + 3]) & (EVENT_VERBS | CARELESS))):
            return True
    return False
PREP_IN = frozenset({"in", "inside", "into", "within"})
#: participles that say where or how a thing was come upon; after a bare conditional they are the
#: condition's verb with its subject elided ("if found on the floor", "unless left open")
FOUND_PARTICIPLES = frozenset({"found", "left", "seen", "spotted", "discovered", "located", "noticed"})
#: participles of leaving a thing carelessly (`offline.placement`: "it gets dumped on the bench" places
#: it; before a place they are an elided condition's verb, "if dropped on the floor")
CARELESS = frozenset({"left", "dumped", "dropped", "thrown", "abandoned", "forgotten", "knocked", "flung",
                      "chucked", "tossed", "slung", "stuck"})

#: words after a noun's "'s" that make it the verb, not a possessive: "the door's shut", "the
#: pillow's been moved", "the dishwasher's already on" (but "the cat's ball")
_HAS_AFTER = ("been", "got", "gotten")
_IS_AFTER = tuple(STATE_WORDS) + ("already", "still", "not", "probably", "just", "now", "in", "on", "under",
                                  "lying", "sitting", "left", "gone", "missing", "there", "here")
_IS_BEFORE_PLACE = ("inside", "atop", "underneath", "beneath", "behind", "beside", "by")
_PLACE_OPENERS = ("the", "a", "an", "my", "your", "our", "his", "her", "their", "this", "that")
#: a thing's place named by a possessed noun and said with a preposition is where the thing lives
#: ("the laptop's position is on the desk", "the kettle's usual spot is on the worktop", "the
#: books' place is on the shelf"): the owner is the subject, as in "the laptop lives on the desk";
#: read with the possessive dropped, the noun of place would be the subject ("spot": a stain)
_HOME_NOUNS = ("place", "position", "spot", "location", "home", "station")
_HOME_QUALIFIERS = ("usual", "proper", "normal", "regular", "rightful", "right", "own", "designated", "allotted")
_HOME_PREPOSITIONS = _IS_BEFORE_PLACE + ("on", "in", "under", "near", "next", "at", "against", "upon", "above")
_HOME_OF = (rf"\s+(?:(?:{'|'.join(_HOME_QUALIFIERS)})\s+)?(?:{'|'.join(_HOME_NOUNS)})\s+(?:is|was)\s+"
            rf"(?=(?:{'|'.join(_HOME_PREPOSITIONS)})\b)")
_CONTRACTIONS = [
    (rf"\b(\w+)'s{_HOME_OF}", r"\1 lives "), (rf"\b(\w+)s'{_HOME_OF}", r"\1s live "),
    # "it's got" is "it has got" (possession: "unless it's got water in it"), as a noun's "'s" is
    (r"\b(it|that|there|what|where|who|how|here|he|she)'s\b(?!\s+got\b)", r"\1 is"),
    (r"\b(they|we|you)'re\b", r"\1 are"),
    (rf"\b(\w+)'s(?=\s+(?:{'|'.join(_HAS_AFTER)})\b)", r"\1 has"),
    (rf"\b(\w+)'s(?=\s+(?:{'|'.join(_IS_AFTER)})\b)", r"\1 is"),
    # a preposition of place that is also a noun ("the box's inside is dirty") is "is" before it
    # only where a place follows: "the wallet's inside the drawer", "the kettle's beside the sink"
    (rf"\b(\w+)'s(?=\s+(?:{'|'.join(_IS_BEFORE_PLACE)})\s+(?:{'|'.join(_PLACE_OPENERS)})\b)", r"\1 is"),
    # typed or dictated without the apostrophe ("if its not in there", "if its dirty"): "its",
    # "thats", "theres" before what follows "is" are "it is", never a possessive
    (rf"\b(it|that|there|what|where)s(?=\s+(?:{'|'.join(_IS_AFTER)})\b)", r"\1 is"),
    (r"(?<![\w'])'t(is|was)\b", r"it \1"),  # "'Tis only paper", "'twas left on": archaic "it is", "it was"
    # "ain't" (American, dialect): "have not" before "got" ("we ain't got one"), else the copula
    # its subject takes ("it ain't on", "they ain't there")
    (r"\b(he|she|it|that|this) ain't(?=\s+(?:got|gotten)\b)", r"\1 has not"),
    (r"\bain't(?=\s+(?:got|gotten)\b)", "have not"), (r"\b(we|you|they) ain't\b", r"\1 are not"),
    (r"\bi ain't\b", "i am not"), (r"\bain't\b", "is not"),
    (r"\bcan't\b", "can not"), (r"\bwon't\b", "will not"), (r"n't\b", " not"),
    (r"\b(i|you|we|they|might|must|should|could|would|may)'ve\b", r"\1 have"), (r"\b(i|you|we|they|it)'ll\b", r"\1 will"),
    (r"\b(\w+)s'(\s)", r"\1s\2"), (r"\b(\w+)'s\b", r"\1"),
    # the same contractions typed without their apostrophe ("theres a mark", "if there arent any"),
    # only where the form is no English word of its own ("were", "well", "its", "wed" are)
    (r"\b(there|that|what|where|who|here)s\b", r"\1 is"), (r"\b(they|you)re\b", r"\1 are"),
    (r"\b(is|are|was|were|do|does|did|has|have|had|should|could|would|must|need)nt\b", r"\1 not"),
    (r"\bcant\b", "can not"), (r"\bwont\b", "will not"), (r"\b(you|they|we)ve\b", r"\1 have"),
    # a dropped "g" written with an apostrophe, as slang is typed ("chillin' on the desk",
    # "sittin' there"): the "-ing" form
    (r"\b([a-z]{2,}in)'(?![\w'])", r"\1g"),
    # texting's "u" for "you" (not a letter of a name: "u-bend", "U-shaped")
    (r"(?<![\w'-])u(?![\w'-])", "you"),
]
#: an arrow as typed ("->", "=>", "\u2192"; the other typographic arrows become "->", `_ARROWS`):
#: one spelling for every reader that cuts or reads at an arrow
ARROW_MARK = r"(?:->|=>|\u2192)"
#: an arrow says "then": what follows it is the instruction of what came before ("Coffee machine:
#: still on? -> switch OFF.", "Lamp on => off"), never a sentence of its own
ARROW = re.compile(rf"\s*{ARROW_MARK}\s*")
#: a closing quotation mark after a question or exclamation mark ends the sentence with it ("Ask:
#: "Is the kettle on the counter?" If not, ..."): a question quoted in a script, a story or a
#: transcript asks as one does unquoted (a quoted statement's full stop may end a line of speech
#: that the narration after it goes on with: '"The cauldron." She pointed at it')
_SENT = re.compile(rf"(?:(?<=[.!?;:])|(?<=[!?][\"\u201d]))\s+(?!{ARROW_MARK})|\n+|(?<=\))\s+(?=[A-Z](?![A-Z]))")
_FULL_STOP = re.compile(r"(?:(?<=[.!])|(?<=[!?][\"\u201d]))\s+|\n+")
_ABBREV = re.compile(r"\b(e\.g|i\.e|etc|approx|vs)\.", re.I)


#: a slash between two words offers alternatives, as "or" does ("on the chair / on the floor",
#: "wet/dirty")
_SLASH = re.compile(r"(?<=[a-z])\s*/\s*(?=[a-z])", re.I)
#: "and/or" is one connective, the inclusive "or" (Merriam-Webster: "used as a function word to
#: indicate that two words or expressions are to be taken together or individually"): "A sofa
#: pillow and/or a toy may be on the floor" doubts each, as "or" does (not "and or or")
_AND_OR = re.compile(r"\band\s*/\s*or\b", re.I)
#: shorthand's "w/" is "with" ("wipe w/ sponge"), not "w or ..."
_WITH = re.compile(r"\bw/\s*", re.I)


#: an email's quoting: the attribution line above a quoted message ("On Monday, Jo wrote:") and
#: the ">" that opens each quoted line; neither says anything of the scene
_ATTRIBUTION = re.compile(r"^[ \t>]*On\b[^\n]{0,80}\bwrote:[ \t]*$", re.M)
_QUOTE_MARK = re.compile(r"^[ \t]*(?:>[ \t]?)+", re.M)
#: a quoted line that states something, answered by a reply opening with "Then" ("> Also the
#: curtains were open when I walked past this morning" / "Then could you close them?"): the
#: writer takes the other's report as the premise of the reply, not as a fact of their own, as
#: "Curtains open? Then ..." does; read as a question ("... this morning? Then could you ...")
#: a forum's quote of another member's post ("Quote from: nightowl_kat on November 29, ..." and the
#: ">" lines under it): what its writer says in the first person ("Mine keeps shoving my phone in
#: a drawer") speaks of their own home, not of the scene the reply describes, whose things the
#: reply names as its own ("My phone may be lying on the bed"); those sentences are dropped
_FORUM_QUOTE = re.compile(r"^[ \t]*Quote from:[^\n]*\n(?P<lines>(?:[ \t]*>[^\n]*(?:\n|$))+)", re.M | re.I)
_FIRST_PERSON = re.compile(r"\b(?:i|i'm|i've|i'd|me|my|mine|we|we're|we've|our|ours)\b", re.I)
#: the marks that close a quotation: one table for `_QUOTED_WHOLE` and `clauses.ends_asking`
CLOSING_QUOTES = "\"\u201d"
_QUOTED_SENTENCE = re.compile(r"[^.!?\n]+(?:[.!?]+|$)")
#: a whole question in double quotes, its question mark inside them (a call script's 'Ask: "Is the
#: kettle on the counter?" YES: ...', a story's '"Is the fridge open?" YES: ...'): the marks only
#: say who asks, and left in place they hide that the sentence is a question; it is read without
#: them. Quoted words that end no question ('the "good" towel') keep their marks, and so does a
#: quoted statement (a story's dialogue keeps its turns: '"The cauldron." She pointed at ...').
#: (Not `clauses.ends_asking`, which tells a clause a question by the same closing marks: a
#: quoted question this leaves in place, one opening in lower case or longer than a line, still asks)
_QUOTED_WHOLE = re.compile(rf"[\"\u201c]([A-Z][^\"\u201c\u201d\n]{{1,300}}?\?)[{CLOSING_QUOTES}]")


def _forum_quote(m: re.Match[str]) -> str:
    """The quoted lines of `_FORUM_QUOTE` without their sentences in the first person."""
    lines = []
    for line in m.group("lines").splitlines():
        body = _QUOTE_MARK.sub("", line)
        kept = "".join(x for x in _QUOTED_SENTENCE.findall(body) if not _FIRST_PERSON.search(x)).strip()
        if kept:
            lines.append(f"> {kept}")
    return "".join(f"{x}\n" for x in lines)


_QUOTED_PREMISE = re.compile(r"^(?P<q>[ \t]*>[^\n]*?[^\s?!.:>])[ \t]*\.?[ \t]*(?P<gap>\n(?:[ \t]*\n)*)"
                             r"(?=[ \t]*Then\b)", re.M)
#: a Markdown sub-heading ("### 3. Notebook on the floor", "## Kitchen"): a document's section
#: title, which names the situation or the thing its section deals with, as a checklist's heading
#: before a colon does ("Notebook on the floor: ..."); read so, not as a statement that the
#: notebook is on the floor. (One "#" also opens a comment in code and YAML, and is left alone.)
_MARKDOWN_HEADING = re.compile(r"^[ \t]*#{2,6}[ \t]+(?:\d+[.)][ \t]+)?(?P<title>[^\n]*?[^\s.:?!])[ \t]*$", re.M)
#: a reference work's marks after a word or a full stop (an encyclopedia article, a report: "shut
#: afterwards.[3] The bat ...", "is meant to be displayed.[citation needed]", "on the bar[a]"):
#: they say where a claim comes from, never what it claims, and hide the sentence's end
_CITATION = re.compile(r"(?<=\S)\[(?:\d+(?:\s*[,\u2013-]\s*\d+)*|[a-z]|(?:citation|clarification) needed"
                       r"|dubious(?: [^\]\n]{0,30})?|who\?|when\?|by whom\?|according to whom\?)\]", re.I)


#: the label of a lettered or numbered item at a line's start ("(b) Bedroom: ...", "c) ...",
#: "2. Check ...", "(iv) ..."; a sub-item's "3.2 ...", "1.2.1 ...", as a task card, a manual or a
#: procedure numbers its steps, one digit after each point, so that a clock time "7.10 ..." stays):
#: it orders the items and says nothing, and left in place it hides a heading after it ("(b)
#: Bedroom:" is no room heading) and is a word before the step's condition ("3.2 If muddy, ..."
#: is no instruction ending "... 3.2 if muddy")
#: a branch labelled by the case it is for, in a bracket before the colon ("PRIMARY TARGET (pan in the
#: kitchen): ...", "Plan B (no mug on the desk): ...", "Case 2 (no laptop on the desk): skip"): a
#: thing and its place with no verb, the thing said absent by "no"; read as the condition it is
#: ("PRIMARY TARGET: if there is a pan in the kitchen, ..."). A bracket that names a place alone
#: ("Step 2 (kitchen):"), holds a verb ("(the one I bought)") or opens with "in"/"on" is left alone
_CASE_LABEL = re.compile(r"[ \t]*\((?P<no>no[ \t]+)?(?P<thing>[a-z]+(?:[ \t][a-z]+)?)[ \t]+"
                         r"(?P<prep>in|on|inside|under)[ \t]+(?P<place>(?:the|my|your|our)[ \t]+[a-z]+(?:[ \t][a-z]+)?)"
                         r"\)[ \t]*:[ \t]*", re.I)
#: words that make the bracket's words before the place no thing ("(it is on the desk)", "(put
#: it on the desk)": a verb or a pronoun); an instruction's verb (`ACTIONS`) neither
_NO_CASE_THING = frozenset({"is", "are", "was", "were", "be", "has", "have", "had", "lies", "sits", "stands",
                            "it", "them", "they", "one", "ones", "this", "that"})
#: the same with a clause in the bracket ("Option A (the mug is dirty): wash it", "Plain lead (the
#: shirt is clean): fold it away", a decision sheet's or a method sheet's cases): a label of at most
#: four words opening its line, then a bracket whose clause has a subject (a determiner's noun
#: phrase, "it", "they", "there") and a finite "be" or "have" before the colon: read as the
#: condition it is ("Option A: if the mug is dirty, wash it"). A bracket without such a verb
#: ("Step 2 (the kitchen):", "Mug (the blue one):") is a description and stays
_CASE_CLAUSE = re.compile(
    r"^(?P<label>[ \t]*(?:[\w'-]+[ \t]+){0,3}[\w'-]+)[ \t]*\((?P<clause>(?:the|my|your|our|his|her|their|its|it"
    r"|they|there)\b[^()\n:]*?\b(?:is|are|isn't|aren't|was|were|has|have|hasn't|haven't)\b[^()\n:]*)\)[ \t]*:[ \t]*",
    re.I | re.M)


def _case_label(m: re.Match[str]) -> str:
    """`_CASE_LABEL`'s bracket as the condition it labels its branch by."""
    said = m.group("thing").lower().split()
    if set(said) & _NO_CASE_THING or said[0] in ACTIONS:
        return m.group(0)
    said = "no" if m.group("no") else "a"
    return f": if there is {said} {m.group('thing')} {m.group('prep')} {m.group('place')}, "


_ITEM_LABEL = re.compile(r"^[ \t]*(?:\((?:[a-z]|[ivx]+|\d{1,2})\)|(?:[a-z]|[ivx]+|\d{1,2})\)|\d{1,2}\.|\d{1,2}(?:\.\d(?!\d))+\.?)"
                         r"[ \t]+",
                         re.M | re.I)


#: a semicolon (and a closing "and" / "or") at the end of a labelled item's line before the next
#: labelled item ("(a) ... switching said vacuum cleaner off;\n(b) where ... closing said box; and\n(c)
#: where ..."): the items are steps of their own, as numbered lines are, not one sentence
_ITEM_END = re.compile(r"[ \t]*;(?:[ \t]+(?:and|or))?[ \t]*\n(?=[ \t]*(?:\((?:[a-z]|[ivx]+|\d{1,2})\)"
                       r"|(?:[a-z]|[ivx]+|\d{1,2})\)|\d{1,2}\.)[ \t]+)", re.I)


#: participles of a thing at rest where it was put or fell ("lying", "standing", British "sat"):
#: they say no more than that it is there, so an elided condition's subject is the thing before
#: them (`_ELIDED_PLACE`) and, before "there", they ask its presence as "there" alone does
#: (`_RESTING_THERE`)
RESTING_PARTICIPLES = ("left", "lying", "sitting", "standing", "resting", "sat", "stood")
#: the same but "left", which before "there" is the verb of leaving a thing somewhere ("if it's
#: been left there", read by the factor reader with the place before it), not a thing at rest
AT_REST = tuple(w for w in RESTING_PARTICIPLES if w != "left")
#: a resting participle between a thing's copula (or "still") and "there" / "here" ("if it's
#: still lying there", "should it be sitting there still", "Still standing there?"): dropped, so
#: the presence is asked as "if it's still there" is
_RESTING_THERE = re.compile(
    rf"\b(is|are|be|been|'s|'re|still)\s+(?:{'|'.join(AT_REST)})\s+(?=(?:still\s+)?(?:there|here)\b)",
    re.I)


#: a participle of finding or leaving fronted before its main clause, as a clause of its own ("Found
#: on the floor, it goes back on its hook", "Left on the desk, the mug goes in the sink", "Found
#: dirty, ..."): the case the main clause acts in, as "if found on the floor, ..." (then read by
#: `_ELIDED_SUBJECT`); only a place or a state and a comma after the participle, then a main
#: clause's subject or verb ("My cup. Left on the desk, next to the scales, as ever." describes)
_FRONTED_FINDING = re.compile(
    r"(?:(?<=^)|(?<=[.!?;:]\s)|(?<=\n)|(?<=\s[-\u2013\u2014]\s))([ \t]*)(found|left|spotted|discovered|seen)"
    r"(?=\s+(?:still\s+|lying\s+|sitting\s+)?(?:(?:on|in|inside|under|behind|beside|by|near|upon)\s[^,.;:!?\n]{1,50}"
    rf"|(?:{'|'.join(w for w in STATE_WORDS if ' ' not in w)}))\s*,\s+"
    rf"(?:it|they|this|that|these|those|the|a|an|my|your|our|his|her|their|just|then|please|{'|'.join(sorted(ACTIONS))})\b)",
    re.I | re.M)
#: a condition with its subject and copula elided before a participle of finding or leaving (a
#: work order's "if found on the chair", a manual's "when left open"): "if it is found ..."; so
#: before one of careless leaving and a place (a checklist's "Pencil -> desk, only if dropped on
#: the floor", "into the hamper if thrown on the floor"), with no place a consequence ("if dropped,
#: sweep up the pieces")
_ELIDED_SUBJECT = re.compile(
    rf"\b(if|unless|when|whenever|once|while)\s+(?=(?:{'|'.join(sorted(FOUND_PARTICIPLES))})\b"
    rf"|(?:{'|'.join(sorted(CARELESS))})\s+(?:on|onto|in|into|under|behind|beside|by)\b)", re.I)
#: the same before a place ("the towel: if on the floor, pick it up", "grab the sock if still on
#: the rug", "if standing on the vanity, put it away"): a condition with no subject and no verb whose
#: predicate is a surface place, or a resting participle and that place, speaks of the thing just
#: named, "if it is on the floor"; a place the preposition "in" opens is left alone ("when in the
#: kitchen, ..." is where the listener is, not the thing), and so are "once" and "while" (a time:
#: "while on the phone")
_ELIDED_PLACE = re.compile(
    rf"\b(if|unless|when|whenever)\s+(?=(?:(?:still|already)\s+)?(?:(?:{'|'.join(RESTING_PARTICIPLES)})\s+)?"
    r"(?:on|upon)\s+(?:the|a|an|your|my|our|his|her|their)\s)", re.I)
#: the same as a question of its own, after the thing was named ("The towel. On the floor? Hang
#: it up.", "I took my hat off in a hurry. Still on the floor? ..."): a sentence that is only a
#: surface place and its question mark asks it of the thing spoken of, "Is it on the floor?"; a
#: place after a heading's colon or dash is the heading's (read there), and a question with a verb
#: or subject of its own ("On the sofa, is it?") or with "in" ("In the kitchen?": where the
#: listener is) is left alone, as is an idiom of "on" that is no place (`IDIOM_PLACES`: "On your
#: way out?", "On the phone?")
IDIOM_PLACES = ("way", "phone", "call", "whole", "list", "go", "own", "shift", "duty", "rota", "agenda")
#: a question of place whose writer kept the finite verb and dropped its subject, as a speaker of
#: a null-subject language does (Ukrainian, Russian, Spanish: "Lies on the floor?", "Is on the
#: sofa?", "Still lie on the rug?"): the verb "be" or of resting, and whether it is singular
_DROPPED_VERBS = {"is": True, "are": False, "lies": True, "lie": False, "sits": True, "sit": False,
                  "stands": True, "stand": False, "rests": True, "rest": False}
_ELIDED_PLACE_QUESTION = re.compile(
    r"(?:(?<=^)|(?<=[.!?;]\s)|(?<=\n))(?:(?:still|already|left|lying)\s+)?"
    rf"(?:(?:{'|'.join(_DROPPED_VERBS)})\s+(?:(?:still|already|now)\s+)?)?(?:on|upon|under|underneath|behind)\s+"
    rf"(?:the|a|an|your|my|our|his|her|their)\s+(?!(?:{'|'.join(IDIOM_PLACES)})\b)"
    r"(?:(?!(?:is|are|was|were|it|they)\b)[^\s?.!,;:]+\s*){1,4}\?",
    re.I | re.M)


def _asked_place(m: re.Match[str]) -> str:
    """`_ELIDED_PLACE_QUESTION`'s question with its subject and copula: "Is it on the floor?"; a
    finite verb of resting its writer kept, the subject dropped ("Lies on the floor?", "Still lie
    on the rug?"), gives way to the copula of its number ("Is it on the floor?", "Are they on the
    rug?")."""
    said = m.group(0)
    verb = re.match(rf"(?:(?:still|already)\s+)?({'|'.join(_DROPPED_VERBS)})\s+", said, re.I)
    if verb is None:
        return f"{_match_case(said, 'is it')} {said[:1].lower()}{said[1:]}"
    rest = said[:verb.start(1)] + said[verb.end():]
    asked = "is it" if _DROPPED_VERBS[verb.group(1).lower()] else "are they"
    return f"{_match_case(said, asked)} {rest[:1].lower()}{rest[1:]}"
#: a condition whose subject pronoun is dropped, as a speaker of a null-subject language drops it
#: (Spanish, Italian, Portuguese: "si está encendida"; a hasty text: "if is still on, turn it
#: off", "unless are dry"): "if" or "unless" then a finite "be" that no "there" follows, read with
#: its pronoun ("if it is", "unless they are"); a question's "is there" stays
_DROPPED_SUBJECT = re.compile(r"\b(if|unless)\s+(?=(is|are|was|were)\s+(?!there\b)[a-z])", re.I)
_DROPPED_PRONOUN = {"is": "it", "was": "it", "are": "they", "were": "they"}
#: a condition's second predicate joined by "and" with its subject left out ("if the mug had fallen
#: and was lying on the floor", "if they'd been knocked over and were lying about", "when the lamp
#: is old and is flickering"): the second predicate speaks of the condition's subject, read with
#: its pronoun ("and it was lying ...") so that it is a clause the reader reads; only after a
#: subject that is a thing (a pronoun of a thing or a noun phrase with its determiner), not "you"
#: or "we" ("if you are home and are tired" asks nothing of a thing); so a condition inverted with
#: "should", whose second predicate's "be" is the base form the modal governs ("Should it have
#: slipped off and be lying on the floor", "should the towels have fallen and be lying about"):
#: "and it be lying ...", with "they" after "they" (`_shared_pronoun`)
_SHARED_SUBJECT = re.compile(
    r"\b(?P<head>(?P<cue>if|when|whenever|unless|should)\s+(?P<subject>it|they|(?:the|my|your|our|his|her|its|their|a|an|any)\s+"
    r"[a-z-]+(?:\s+[a-z-]+)?)\b[^,.;:?!()\n]{1,60}?\s+and)\s+(?P<be>was|were|is|are|be)\s+(?=[a-z])", re.I)
_BE_PRONOUN = {"was": "it", "is": "it", "were": "they", "are": "they"}


#: when a question asks its thing ("Still there at six?", "... when you finish?", "... by
#: lunchtime?", "... tonight?"): a time, which says when to look and nothing of the thing
_TIME_ADJUNCT = (r"\s+(?:(?:at|by|when|after|before|until|till|once|on|around|come)\s[^?.!\n]{1,40}"
                 r"|tonight|today|later|this\s+(?:morning|afternoon|evening))")
#: the same of "there" after "still", as a question of its own ("The mug has been on the desk all
#: week. Still there? Wash it.", "Still lying there?"): the thing spoken of is asked whether it is
#: still where it was said to be, "Is it still there?" (a resting participle says no more,
#: `AT_REST`); without "still" a bare "There?" is left alone
_STILL_THERE_QUESTION = re.compile(
    r"(?:(?<=^)|(?<=[.!?;]\s)|(?<=\n))(?P<still>still)\s+"
    rf"(?:(?:{'|'.join(AT_REST)})\s+)?(?P<there>there|here)(?P<time>{_TIME_ADJUNCT})?\?", re.I | re.M)


def _still_there(m: re.Match[str]) -> str:
    """`_STILL_THERE_QUESTION`'s question with its subject and verb: "Is it still there?", its time
    kept ("Still there at six?": "Is it still there at six?")."""
    return f"{_match_case(m.group('still'), 'is')} it still {m.group('there').lower()}{m.group('time') or ''}?"


def _shared_pronoun(m: re.Match[str]) -> str:
    """`_SHARED_SUBJECT`'s second predicate with its pronoun: by the finite "be"'s number, or after
    an inverted "should" (whose "be" is the base form, of either number) by the subject's ("they"
    only after "they"); a finite "be" after "should" is a new clause, left as it is."""
    be = m.group("be")
    inverted = m.group("cue").lower() == "should"
    if inverted != (be.lower() == "be"):
        return m.group(0)
    pronoun = ("they" if m.group("subject").lower() == "they" else "it") if inverted else _BE_PRONOUN[be.lower()]
    return f"{m.group('head')} {pronoun} {be} "
#: a note's sentence of doubt with its subject dropped after the thing was named ("Toothbrush
#: (mine). May have fallen on the floor.", "The scarf - might be on the radiator", "Spare key:
#: could still be in the drawer"): a modal of doubt opening its sentence or the part after a
#: heading's colon or dash, before "have", "be" or "still"/"already", read with its pronoun ("It
#: may have fallen ..."), as the hedge it is when the subject is said; a request ("Could you ...")
#: has its subject
_DROPPED_DOUBT = re.compile(r"(?:(?<=^)|(?<=[.!?:;]\s)|(?<=\n)|(?<=\s[-\u2013\u2014]\s))([ \t]*)(may|might|could)"
                            r"(?=\s+(?:(?:well|not)\s+)?(?:have|be|still|already)\b)", re.I | re.M)
#: the same before a state word that ends its clause inside brackets or after an arrow's answer
#: ("alarm clock -> nightstand (silence it first if ringing)", "(wash it first if dirty)"): the
#: elided subject is the "it" the bracket's instruction acts on, not the place named last
_ELIDED_STATE = re.compile(
    rf"(\([^()]*?\b(?:if|unless|when|whenever|once|while))\s+(?=(?:{'|'.join(sorted(w for w in STATE_WORDS if ' ' not in w))})\s*\))",
    re.I)
#: the same after "not" where a sentence opens ("Check the cat bowl. If not full, fill it up", "Look
#: in the pot. If not full, fill it with cold water", "Feel the soil. If not wet, water it"): a
#: condition whose subject and copula are elided before a negated state speaks of the thing just
#: named, "if it is not full", not of the alternative "if not," opens (`clauses.ELSE_CUES`: "Is
#: it full? If not, fill it", where a comma follows "not")
_ELIDED_NOT_STATE = re.compile(
    rf"(?:(?<=^)|(?<=[.!?;:]\s)|(?<=\n))([ \t]*(?:if|unless|when|whenever))\s+(?=not\s+"
    rf"(?:{'|'.join(sorted(w for w in STATE_WORDS if ' ' not in w))})\s*,)",
    re.I | re.M)
#: the same at the end of an instruction's clause, after its verb ("Tablet on the plinth: power
#: off if still on.", "Heater by the door: switch off if running"): an instruction whose condition
#: is a bare state, with or without "still" / "already", speaks of the thing it acts on, "if it is
#: still on"; a bare state opening a sentence ("If dirty, ...") is read elsewhere. An aside in
#: brackets may close the clause ("kettle OFF if on (nearly had a fire Sat!!)")
_ELIDED_END_STATE = re.compile(
    rf"(?<=\w)(\s+(?:if|unless|when|whenever|once|while))\s+(?=(?:(?:still|already)\s+)?"
    rf"(?:{'|'.join(sorted(w for w in STATE_WORDS if ' ' not in w))})\s*(?:[.;!(]|$))",
    re.I | re.M)


#: an emphatic "do" before a verb of habit ("the folders do tend to end up on the floor", "the
#: ball does keep rolling under the sofa"): it stresses the habit and is no verb of its own, but
#: left in place it makes the remark a clause with a finite verb that the habit rules do not read
_EMPHATIC_DO = re.compile(rf"(?<=\w)\s+(?:do|does|did)(?=\s+(?:{'|'.join(sorted(TEND | KEEP))})\b)", re.I)


#: a speaker correcting a place as they say it ("throw it in the wardrobe, no wait, sorry, in the
#: hamper", "put it on the desk - I mean on the shelf"): the corrected place, with the words that
#: retract it, is dropped, so only the place meant is read
_PLACE_PREP = r"(?:in|on|into|onto|to|under|inside|next to|by)\b"
_RETRACT = r"(?:no,?\s+wait|wait,?\s+no|no,?\s+sorry|sorry|i mean|or rather|scratch that|actually|correction|no)"
#: "Unless Maya already took it down, the bag goes in the bin", "If it's not already in the
#: basket, put the towel there": a condition put first that asks, of a thing it names only by a
#: pronoun, whether it is already where or as its main clause makes it. The pronoun points forward
#: and "already" to a result not said yet, so the sentence is read in the usual order, the main
#: clause first ("The bag goes in the bin, unless Maya already took it down"), where "already"
#: takes up the place or state just given
_FRONTED_ALREADY = re.compile(
    r"(?P<lead>^|(?<=[.!?])[ \t]+)(?P<cue>Unless|If|unless|if)\s+"
    r"(?P<cond>(?=[^,.;:!?\n]*\b(?:it|they|them)\b)(?=[^,.;:!?\n]*\balready\b)[^,.;:!?\n]+),\s*"
    r"(?P<main>[^,.;:!?\n][^.;:!?\n]*?)(?P<end>[.;!?]|$)", re.M)


#: a thing taken up by a pronoun, in a main clause's first stretch or in what follows its comma
_TAKEN_UP = re.compile(r"\b(?:it|them)\b", re.I)


#: a learner's participle without its ending at a condition's end ("If curtain still close, open
#: it", "if bucket not fill yet", "if the door already close"): after the subject and "is"/"are",
#: "still", "already" or "not", a verb's plain form whose "-ed" form is a state (`STATE_WORDS`:
#: "closed", "filled", "cracked") and that ends its clause is that state; "close to the house" goes
#: on, "if you still use it" has a person for its subject and an object, and neither is read so
_BARE_PARTICIPLE = re.compile(
    r"\b(?P<head>(?:if|unless|when|whenever)\s+(?:(?:the|my|your|our|his|her|their|this|that)\s+)?"
    r"(?P<subj>[a-z]+)(?:\s+[a-z]+)?\s+(?P<marks>(?:(?:is|are|still|already|not)\s+)+))(?P<verb>[a-z]+)"
    r"(?=\s*(?:[,.;:!?)]|$)|\s+(?:already|yet|then|please|pls)\b)", re.I | re.M)


def _participle_state(m: re.Match[str]) -> str:
    """The `_BARE_PARTICIPLE` match with its verb as the state's participle, when it is one."""
    verb = m.group("verb").lower()
    done: str | None = next((str(f) for f in getInflection(verb, tag="VBN") if f in STATE_WORDS), None)
    if done is None or verb in STATE_WORDS or m.group("subj").lower() in PERSONAL_SUBJECTS:
        return m.group(0)
    return m.group("head") + done


def _postposed(m: re.Match[str]) -> str:
    """The sentence with its fronted condition after the main clause's instruction. When the main
    clause goes on after a comma with words that take up no thing by a pronoun ("Unless it's
    already full, fill it at the sink, ready for when we get back with our frames"), the condition
    goes before that tail, beside the instruction whose result "already" asks: after the tail its
    pronoun would take up the last thing the tail names."""
    main, cond = m.group("main"), f"{m.group('cue').lower()} {m.group('cond')}"
    head, comma, tail = main.partition(", ")
    if comma and _TAKEN_UP.search(head) and not _TAKEN_UP.search(tail):
        main, cond = head, f"{cond}, {tail}"
    return f"{m.group('lead')}{main[:1].upper()}{main[1:]}, {cond}{m.group('end')}"


#: what stands between the place taken back, the words that retract it and the place meant: a
#: comma, a dash, or suspension points ("put in the cabinet... no, on the cabinet")
_RETRACT_GAP = r"(?:[\s,\-\u2013\u2014\u2026]|\.{2,})+"
_SELF_CORRECTION = re.compile(rf"\b{_PLACE_PREP}[^,.;:!?()\u2026]{{1,40}}?{_RETRACT_GAP}"
                              rf"(?:{_RETRACT}{_RETRACT_GAP})+(?={_PLACE_PREP})", re.I)


#: a bare state word as the subject of a verb of going ("dirty goes in the hamper", "wet go on the
#: rack": a note or a speaker naming the thing by its state): the condition on the thing spoken of
_STATE_SUBJECT = re.compile(
    rf"(?:(?<=^)|(?<=[.!?;:\n]))(\s*)({'|'.join(w for w, (flag, _) in STATE_WORDS.items() if flag in ('dirty', 'wet'))})"
    r"\s+(goes|belongs|go|belong)\b", re.I | re.M)


def _state_subject(m: re.Match[str]) -> str:
    plural = m.group(3).lower() in ("go", "belong")
    return f"{m.group(1)}if {'they are' if plural else 'it is'} {m.group(2)}, {'they' if plural else 'it'} {m.group(3)}"


#: a bare state word and a comma before an instruction ("If there's an umbrella: wet, stand it in
#: the umbrella stand; dry, lay it on the console table"): the case of the thing spoken of, as
#: "if it is wet, ..." (the verb of putting after the comma, `ACTIONS`), or before a goal with no
#: verb, as `_VERBLESS_CASE`'s answers are ("Your cup is on the bench. Dirty, in the sink. Clean,
#: back on the shelf"); two states joined by "and" / "but" make one case ("clean but wet, hang it
#: on the towel rack... clean and dry, leave it where it is")
_CASE_STATES = "|".join(w for w, (flag, _) in STATE_WORDS.items() if flag in ("dirty", "wet"))
#: (a plain "in" or "on" only before "the": "Clean, in my opinion" is no goal)
_VERBLESS_GOAL = (r"(?:(?:back|straight)\s+(?:into|onto|to|in|on)|into|onto)\s+(?:the|my|your|our|its|their)\s"
                  r"|(?:in|on|to)\s+the\s")
_STATE_CASE = re.compile(
    rf"(?:(?<=^)|(?<=[.!?;:\n]))(\s*)((?:{_CASE_STATES})(?:\s+(?:and|but)\s+(?:still\s+)?(?:{_CASE_STATES}))?)"
    rf",\s+(?=(?:just\s+)?(?:{'|'.join(sorted(ACTIONS))})\b|{_VERBLESS_GOAL})", re.I | re.M)


#: every state word as a regular expression's alternatives, the longest first (so "opened" is
#: not read as "open" and a rest)
_STATE_ALTERNATION = "|".join(sorted(STATE_WORDS, key=len, reverse=True))
#: where a case opens: its text's, line's or sentence's start, with a list item's bullet if any
_ITEM_START = r"(?:(?<=^)|(?<=[.!?;\n]))([ \t]*(?:[-*\u2022][ \t]*)?)"


#: a bare "already" and a state, then a comma before a remark or an instruction, opening its
#: sentence ("Switch it off once she's asleep. Already off, great.", "Already shut, nothing to do",
#: "already empty, leave it"): the case of the thing spoken of, as "if it is already off, ..." (the
#: dash and question forms, "Already off - fine", "Already off? Great", were read already)
_ALREADY_CASE = re.compile(
    rf"(?:(?<=^)|(?<=[.!?;:\n]))(\s*)already\s+((?:{_STATE_ALTERNATION}))\s*,\s+",
    re.I | re.M)


#: a verbless case opened by "one" and a place, then a comma and an instruction told by "you" or
#: by a verb with "it"/"them" ("One on the floor, you pick it up", "one on the sofa, put it back"):
#: "if there is one on the floor, ..." (the question form, "One on the floor? Pick it up", was read
#: already); an inventory ("one on the floor, two on the sofa") tells nothing to do and is left
_ONE_CASE = re.compile(r"(?:(?<=^)|(?<=[.!?:;]\s)|(?<=\n)|(?<=\s[-\u2013\u2014]\s))([ \t]*)(one)\s+"
                       r"((?:on|in|inside|under|by)\s+(?:the|a|your|my|our|his|her|their)\s+[a-z]+(?:\s+[a-z]+)?)\s*,\s+"
                       r"(?=you\s|(?:just\s+|please\s+)?[a-z]+\s+(?:it|them)\b)", re.I | re.M)
#: a bare "No" and a thing opening its sentence, a comma, colon or dash after it ("No flowers
#: brought, nothing to do here", "No mug, nothing to do", "No tin out - fine"): the case of the
#: thing's absence, as "if there is no mug, ..." (the question form, "No mug? Nothing to do", was
#: read already); a place after the thing makes it a rule ("No shoes on the carpet, please"), left
_NO_CASE = re.compile(_ITEM_START + r"no\s+"
                      r"((?:(?!on\b|in\b|inside\b|at\b|under\b|by\b|near\b|onto\b|into\b)[a-z'-]+\s*){1,3}?)"
                      r"\s*(?:,|:|\s-\s)\s*", re.I | re.M)


#: a bare state word joined by "and" / "but" to a clause about another thing, before a colon or
#: a question mark, opening its line or sentence ("- Wet and the dryer is idle: load it into the
#: dryer", "Dirty but the dishwasher's running? Leave it in the sink"): the case of the thing spoken
#: of and that clause, as "if it is wet and the dryer is idle, ..."
_STATE_AND_CLAUSE = re.compile(
    _ITEM_START + rf"((?:already\s+)?(?:{_STATE_ALTERNATION}))"
    r"\s+(and|but)\s+((?:the|its|my|your|our|their|his|her)\s[^:?\n.;]+?)\s*[:?]\s*", re.I | re.M)


#: "any other kind of toy", "every other sort of book": the class itself ("any other toy")
_KIND_OF = re.compile(r"\b(other)\s+(?:kind|sort|type)s?\s+of\s+", re.I)


def _state_case(m: re.Match[str]) -> str:
    plural = re.match(r"\s*(?:just\s+)?[a-z]+\s+them\b", m.string[m.end():], re.I) is not None
    return f"{m.group(1)}if {'they are' if plural else 'it is'} {m.group(2)}, "


#: an indirect question about an action whose result is a state ("I can't remember whether I shut
#: the fridge door", "not sure if we switched the heater off"): the question is the state of the
#: thing acted on ("whether the fridge door is shut"), as a direct question would put it
_DOERS = ("i", "we", "you", "they", "he", "she", "someone", "somebody", "anyone", "anybody")
_DOER = f"(?:{'|'.join(_DOERS)})"
_THING = r"(?P<thing>(?:the|my|our|your)\s+[a-z]+(?:\s+[a-z]+){0,2}?)"
#: where the acted-on thing's phrase ends: a mark, or a conjunction or time word after it
_ACTED_END = r"(?=\s*(?:[,.;:!?)]|$|\s(?:or|and|so|but|when|before|after)\b))"
_ACTED_STATE = re.compile(
    rf"\b(?P<cue>whether|if)\s+{_DOER}\s+(?:(?:already|actually|even|ever)\s+)?(?:"
    rf"(?P<verb>{'|'.join(w for w, (flag, _) in STATE_WORDS.items() if flag == 'open' and w != 'ajar')})\s+{_THING}"
    rf"|(?:turned|switched)\s+(?P<pre>on|off)\s+{_THING.replace('thing', 'thing2')}"
    rf"|(?:turned|switched)\s+{_THING.replace('thing', 'thing3')}\s+(?P<post>on|off)){_ACTED_END}", re.I | re.M)


#: a condition whose verb phrase is elided after a doer, at its clause's end ("switch it off
#: unless someone already has", "put it in the dishwasher if no one has yet", "unless somebody's
#: done it already", "if somebody hasn't already", "if nobody's beaten you to it"): whether the
#: instruction's result holds already, as "unless it already is" asks of the thing the
#: instruction acts on; a doer with an object of its own ("unless someone has a key") is no such
#: clause, nor one whose doer is the one told ("if you haven't already" asks nothing of the
#: scene: the agent has done nothing yet). `analysis._DONE_BY_SOMEONE` reads the deed said in
#: full, with its object ("unless someone has emptied the bin").
_OTHER_DOER = f"(?:{'|'.join(d for d in _DOERS if d != 'you')})"
#: a doer named by a name or a noun phrase ("unless Priya has beaten you to it", "unless the night
#: porter has done it already", "unless Lee from the cafe has", "unless one of the cleaners has"),
#: with where they work after it: one only with the deed said ("done it", "beaten you to it"), since
#: "unless Lee has a key" has an object of its own
_NAMED_DOER = (r"(?:(?-i:(?:(?:Mr|Mrs|Ms|Miss|Dr)\.?\s+)?[A-Z][a-z]+)|the\s+[a-z]+(?:\s+[a-z]+)?|one\s+of\s+the\s+[a-z]+)"
               r"(?:\s+(?:from|on|in|at)\s+the\s+[a-z]+(?:\s+[a-z]+)?)?")
_DEED = r"(?:done\s+(?:it|so|that|this)|beaten\s+(?:you|me|us|them|him|her)\s+to\s+it)"
_DONE_ALREADY = re.compile(
    rf"\b(?:unless\s+{_NAMED_DOER}(?:\s+already)?(?:\s+(?:has|have|had)|'s|’s)(?:\s+already)?\s+{_DEED}"
    rf"|if\s+{_NAMED_DOER}\s+(?:has|have|had)(?:\s+not|n't|n’t)(?:\s+already)?\s+{_DEED}"
    rf"|unless\s+{_OTHER_DOER}(?:\s+else)?(?:\s+already)?(?:\s+(?:has|have|had|did)|'s|’s|'ve|’ve)"
    rf"|if\s+(?:no\s+one|no-one|nobody)(?:\s+else)?(?:\s+already)?(?:\s+(?:has|have|had|did)|'s|’s)"
    rf"|if\s+{_OTHER_DOER}(?:\s+else)?\s+(?:has|have|had|did)(?:\s+not|n't|n’t))"
    rf"(?:\s+(?:already|yet))?(?:\s+{_DEED})?"
    r"(?:\s+(?:already|yet))?(?=\s*(?:[,.;:!?)]|$)|\s+[-\u2013\u2014]\s)", re.I | re.M)
#: a condition that the one who should have done the deed forgot it, the deed elided ("switch it
#: off if I forgot to", "in case we forgot", "if the kids forgot - they usually do"): whether the
#: instruction's result is still to come about, as "unless it already is" asks; a forgetting with
#: an object of its own ("if you forgot the keys", "if I forgot anything") is no such clause
_FORGOT = re.compile(
    rf"\b(?:if|in\s+case)\s+(?:{_DOER}|{_NAMED_DOER})\s+(?:(?:might|may|must)\s+have\s+|has\s+|have\s+|had\s+)?"
    r"(?:forgot|forgotten)(?:\s+to)?(?=\s*(?:[,.;:!?)]|$)|\s+[-\u2013\u2014]\s)", re.I | re.M)


#: a heading that is a free relative, its verb ending it at a colon or a dash ("Where things are:
#: in the kitchen - the bin, the fridge", "Where everything lives -"): it names the topic of what
#: follows and asks nothing, so it is dropped; a "where" with a predicate after its verb ("Where
#: the bin is full: empty it") stays a condition
_WHERE_HEADING = re.compile(r"^([ \t]*)where\b[^?,:.\n]*?\b(?:is|are|was|were|lives?|goes|go|belongs?|sits?|stays?|kept)"
                            r"\s*(?::|\s[-\u2013\u2014])[ \t]*", re.I | re.M)
#: "where" of a case after "only", a bracket, a comma or a dash, before a clause of presence
#: ("UMBRELLA (only where one is present)", "Kettle, where there is one: ..."): a procedure's
#: "in a situation in which", read as "if"; "where" of a place ("put it where there is room")
#: follows a verb, not these
_CASE_WHERE = re.compile(r"(?:(?<=\()|(?<=,\s)|(?<=\s[-\u2013\u2014]\s)|(?<=\bonly\s))where"
                         r"(?=\s+(?:there\s+(?:is|are)|(?:one|it|they|any|some)\s+(?:is|are)\s+present)\b)", re.I)


#: what makes an "if" clause an indirect question ("not sure if", "can't remember if", "check if"),
#: not a condition on what the listener does ("if you open the fridge, close it after")
_ASKING = re.compile(r"\b(?:remember|recall|know|sure|certain|wonder|check|see|idea|forget|forgot)\W+$", re.I)


def _acted_state(m: re.Match[str]) -> str:
    if m.group("cue").lower() == "if" and not _ASKING.search(m.string[max(0, m.start() - 30):m.start()]):
        return m.group(0)
    thing = m.group("thing") or m.group("thing2") or m.group("thing3")
    state = m.group("verb") or m.group("pre") or m.group("post")
    return f"{m.group('cue')} {thing} is {state}"


#: a doubt about having got a thing at all ("I'm not sure I even got bread", "can't remember if we
#: bought any milk"): whether there is one, as "there may or may not be bread" says
_GOT_DOUBT = re.compile(
    r"\b(?:(?:i'?m|i am|we'?re|we are)\s+)?(?:not sure|unsure|not certain|can'?t remember|cannot remember|don'?t know|don'?t remember)\s+"
    rf"(?:(?:if|whether|that)\s+)?{_DOER}\s+(?:(?:even|actually|ever|really)\s+)?"
    r"(?:got|bought|picked up|brought|fetched|have|had)\s+(?:(?:any|some|a|an)\s+)?"
    r"(?P<thing>[a-z]+(?:\s+(?!(?:this|that|today|yesterday|at|in|on|for|when|or|and|but|too|either|again|"
    r"after|before|from)\b)[a-z]+)?)", re.I)


#: "bin it", "if empty bin it", "bin the wipe afterwards": "bin" as a verb (after a clause's start,
#: punctuation, an arrow or a word that leads an imperative, then its object) puts the thing in
#: a bin, which the text so names as an object of the scene as "put it in the bin" would (but
#: says nothing of where that bin stands, so only the naming reads it: `binned`)
_BIN_VERB = re.compile(
    r"(?P<lead>(?:^|[,.;:!?()\u2192>-]|\b(?:and|then|just|please|simply|or|so|empty|dirty|broken|used|old))\s*)"
    r"bin\s+(?P<obj>it|them|(?:the|this|that|these|those|my|your|our|his|her|their)\s[a-z ]+?)"
    r"(?=\s+(?:afterwards|after|then|and|when|if|unless|too|as well|straight away)\b|\s*[,.;:!?()\n]|\s*$)",
    re.I | re.M)


#: a note-taker's shorthand for ordinary words ("poss. w/ a book", "novels, essays & other books
#: resp.", "acc. to kind", "silence it 1st"), and "=" before a count as "has" ("Bookshelf = 3
#: levels: ..."): read as the words they stand for, so that the rules for those words apply and
#: an abbreviation's full stop ends no sentence
_SHORTHAND = (
    (re.compile(r"\bresp\.(?=\W|$)", re.I), "respectively"),
    (re.compile(r"\bposs\.(?=\W|$)", re.I), "possibly"),
    (re.compile(r"\bacc\.(?=\s+to\b)", re.I), "according"),
    (re.compile(r"(?<=\s)&(?=\s)"), "and"),
    (re.compile(r"\b1st\b", re.I), "first"), (re.compile(r"\b2nd\b", re.I), "second"),
    (re.compile(r"\b3rd\b", re.I), "third"),
    (re.compile(r"(?<=\w)\s*=\s*(?=(?:\d+|two|three|four|five|six)\s+[a-z])", re.I), " has "),
)


def _unabbreviated(text: str) -> str:
    """The text with a note-taker's shorthand spelled out (`_SHORTHAND`)."""
    for pattern, words in _SHORTHAND:
        text = pattern.sub(_spelled(words), text)
    return text


def _spelled(words: str) -> Callable[[re.Match[str]], str]:
    """The words for an abbreviation, with its full stop kept where it also ends the sentence
    (before a capital or a line's end)."""
    def spell(m: re.Match[str]) -> str:
        ends = m.group().endswith(".") and re.match(r"\s*(?:$|\n|[A-Z])", m.string[m.end():]) is not None
        return words + "." * ends
    return spell


def binned(text: str) -> str:
    """The text with "bin" as a verb spelled out as the move it stands for ("bin it": "put it in
    the bin", `_BIN_VERB`), for the reader that names the scene's objects."""
    return _BIN_VERB.sub(lambda m: f"{m.group('lead')}put {m.group('obj')} in the bin", text)


#: typographic arrows ("→", "⇒", "⟶", "➔", "➡️") are the typed "->": what follows is the
#: instruction for what came before, whichever arrow the keyboard or phone gave
_ARROWS = re.compile(r"\s*[\u2192\u21d2\u27f6\u27f9\u2794\u279c\u27a1\u21e8]\ufe0f?\s*")


#: a pictograph (an emoji, with its skin tone, variation selector and joiners): in a text message
#: it closes what was said ("dumped their bag in the hallway again 🙄 can u sort?", "fine 👍 if
#: yes, ..."), so between two words it is a sentence's end; elsewhere it says nothing
_EMOJI = re.compile(r"[ \t]*[\U0001F000-\U0001FAFF\u2764\u263a][\U0001F000-\U0001FAFF\ufe0f\u200d\u2600-\u27bf]*[ \t]*")


#: "clean -> kitchen cabinet, dirty -> dishwasher": a comma before a bare state word and an arrow
#: closes the answer before it, so the state is the case of the thing spoken of, not of the place
#: just named; read as the ";" between two cases. So for any one-word case, with "one" or "yet"
#: after it ("ripe one -> fridge, not ripe yet -> fruit bowl")
_CASE_AFTER_COMMA = re.compile(r",\s*(?=(?:not\s+)?[a-z]+(?:\s+(?:ones?|yet))?\s*->)", re.I)


#: "1. The plate on the counter, if there is one: ...": a thing at a place heading its clause,
#: followed by a doubt that there is one, asks whether there is one there, as "if there is a
#: plate on the counter" does; it states no placement
_IF_ANY = re.compile(
    r"(?P<lead>^[ \t]*(?:\d{1,2}[.)][ \t]*|[-*\u2022][ \t]*)?|[.;:!?][ \t]+)(?:the|a|an|any)\s+(?P<np>[a-z][a-z ]{0,30}?\s(?:on|in|inside|under|by|near)\s+(?:the|a|my|your|our)"
    r"\s+[a-z]+(?:\s[a-z]+)?)\s*,\s*if\s+(?:there\s+is|there's|there\s+are|any)(?:\s+one|\s+any)?(?=\s*:)",
    re.I | re.M)


def _if_any(m: re.Match[str]) -> str:
    said = f"if there is a {m.group('np')}"
    opens = m.group()[len(m.group("lead"))]
    return m.group("lead") + (said[0].upper() + said[1:] if opens.isupper() else said)


def _emoji(m: re.Match[str]) -> str:
    before, after = m.string[:m.start()], m.string[m.end():]
    return ". " if before[-1:].isalnum() and after[:1].isalpha() else " " * bool(before[-1:].isalnum() and after[:1].isalnum())


#: British and older spellings of function words, read as the common form every word table
#: holds ("Whilst the dryer is running" is "While the dryer is running")
VARIANTS = {"whilst": "while", "amongst": "among", "amidst": "amid", "unto": "to", "upon": "on"}
#: British spellings of the words the catalog spells the American way, its attribute values
#: among them ("the grey plastic one" is the catalog's `gray`; Merriam-Webster, "grey": chiefly
#: British spelling of gray)
SPELLINGS = {"grey": "gray"}
_SPELLED = {**VARIANTS, **SPELLINGS}
_VARIANT = re.compile(rf"\b(?:{'|'.join(_SPELLED)})\b", re.I)
#: "anywhere other than the counter", "somewhere other than in the drawer": the common "else than"
#: the elsewhere cues read ("anywhere else", `analysis.ELSEWHERE`), so that "other" is not read as
#: "any other <kind>", a class ("If the bread is anywhere other than the counter, or we have no
#: bread at all" lost its "no bread")
_OTHER_THAN = re.compile(r"\b(anywhere|somewhere|everywhere|nowhere)\s+other\s+than\b", re.I)
#: a proposition offered with its own negation by a lexical verb's "do" ("Either the magazine lies
#: on the floor or it does not.", "The remote either sits on the sofa or it doesn't."): the writer
#: leaves it open, as "maybe" does, so it is read "Maybe the magazine lies on the floor." (an open
#: statement the conditions after it take up: "If so", "If it does"), and a first case taken up
#: right after it ("In the first case, ...") as "If so"; only a whole sentence, its negation
#: ending it ("or it does not keep" is a consequence). "Either it is on the floor or not. In the
#: first case ..." is `analysis`'s own reading of "either", left to it
_OPEN_DISJUNCTION = re.compile(
    r"(?:(?<=^)|(?<=[.!?;]\s)|(?<=\n))(?:either\s+)?(?P<clause>[^.!?;:\n]{3,120}?),?\s+or\s+(?:it|they|he|she)\s+"
    r"(?:does|do|did)(?:\s+not|n't|n\u2019t)(?=\s*[.!;\n]|\s*$)(?P<gap>[.!;]?\s*)"
    r"(?P<case>in\s+the\s+(?:first|former)(?:\s+case)?(?=\s*,))?", re.I | re.M)


def _open_disjunction(m: re.Match[str]) -> str:
    """`_OPEN_DISJUNCTION`'s proposition as an open statement: "Maybe <clause>" ("either" in it
    dropped), and its first case after it as "If so"."""
    clause = re.sub(r"\s+either\b", "", m.group("clause"))
    first = clause.split()[0]
    # its first word loses the capital it had as the sentence's first, unless all of it is capitals
    # (a letter naming a thing, "M lies ...", or a notice in capitals)
    opened = clause if first.isupper() else clause[:1].lower() + clause[1:]
    case = _match_case(m.group("case"), "if so") if m.group("case") else ""
    return f"{_match_case(m.group(0), 'maybe')} {opened}{m.group('gap')}{case}"


#: "eventually" before or after a present-tense "is" / "are" of the scene ("Eventually my mug is
#: also on the desk", "If eventually there is a document on the desk", "The remote is eventually on
#: the sofa"): English says "in the end" only of an event to come or past, so a state said now with
#: it is the false friend of French "éventuellement", Spanish and Italian "eventualmente", German
#: "eventuell", Dutch "eventueel", Polish "ewentualnie": "possibly". Read as "perhaps" (before) and
#: "may be" (after the copula); not before a passive's participle ("Eventually the kettle is
#: switched off" is the end of a procedure), a future or a past ("eventually it will boil") nor
#: an instruction ("Eventually, put the mug in the sink") (the eighteenth session)
_NOT_PARTICIPLE = r"(?!\s+(?:also\s+|still\s+)?[a-z]+(?:ed|en)\b)"
_EVENTUAL_BEFORE = re.compile(
    r"\beventually\b,?(?=\s+(?:there\s+(?:is|are)\b|there's\b|(?:it|they|(?:my|the|your|our|his|her|this|that|a|an|some)"
    rf"(?:\s+[a-z]+){{1,3}}?)\s+(?:is|are)\b{_NOT_PARTICIPLE}))", re.I)
_EVENTUAL_AFTER = re.compile(rf"\b(?:is|are)\s+eventually\b{_NOT_PARTICIPLE}", re.I)


#: an enumeration of two or more things, each with "a"/"an", whose last item follows "or else" ("a
#: book, an alarm clock, or else a phone"; "a mug, a stapler, or else a pen on the desk"): "else"
#: only stresses the list's last alternative, so it reads as "or" and the item stays one of the list's
#: things (as a clause's "else" it would start an alternative instruction and drop the thing). After
#: one thing ("with the sponge, or else a towel") it is an alternative and stays
_LISTED_OR_ELSE = re.compile(r"\b(?P<items>(?:an?\s+[a-z-]+(?:\s+[a-z-]+)?,\s+){2,})or\s+else\s+(?=an?\s+[a-z])", re.I)


#: a verbless instruction, a thing and the place it goes, with "unless it's (already) there"
#: ("frying pan on the stove unless it's there already", "- Towels in the basket unless they're
#: already there"): a list's or a note's way of telling where a thing goes, whose condition asks
#: whether it is there; read with its verb of putting ("put frying pan on the stove unless ...") so
#: the place is an instruction's goal and the condition asks it. The thing is one or two words
#: after a clause's start, none a verb or "be" (`_NOT_A_THING`): "The pan is on the stove" states
_VERBLESS_UNLESS_THERE = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?;:,(])|(?<=[.!?;:,(]\s))[ \t]*(?:[-*\u2022][ \t]+)?)"
    r"(?P<thing>(?:(?:the|my|your|our|a|an|one|two)\s+)?[a-z][a-z-]*(?:\s+[a-z][a-z-]*)?)\s+"
    r"(?P<place>(?:on|in|into|onto|inside|under)\s+(?:the|my|your|our)\s+[a-z-]+(?:\s+[a-z-]+)?"
    r",?\s+unless\s+(?:it|they)(?:'s|'re|\u2019s|\u2019re|\s+is|\s+are)\s+(?:already\s+there|there\s+already)\b)",
    re.I | re.M)
_NOT_A_THING = ACTIONS | PERSONAL_SUBJECTS | {"is", "are", "was", "were", "be", "it", "keep", "get", "go", "goes",
                                             "check", "see", "make", "have", "has", "there", "that", "this"}


def _verbless_put(m: re.Match[str]) -> str:
    """`_VERBLESS_UNLESS_THERE`'s instruction with "put" before its thing (and "the" when it has no
    determiner: the reader takes a bare word after a verb for no thing), unless a word of the thing
    is a verb, "be" or a pronoun (then it has a verb or says where a thing is: left as it is) or
    it is a bare state ("clean onto the armchair": the state is the case, `_STATE_CASE`)."""
    thing = m.group("thing")
    if _NOT_A_THING & set(thing.lower().split()) or thing.lower() in STATE_WORDS:
        return m.group(0)
    said = thing if thing.split()[0].lower() in DETERMINERS else f"the {thing}"
    return f"{m.group('lead')}{_match_case(thing, 'put')} {said[:1].lower()}{said[1:]} {m.group('place')}"


#: a verbless case and its verbless answer ("SOCK ON THE FLOOR, INTO THE BASKET", "shirt not in the
#: basket, no action", "- samples on the bench, back into the fridge"): a broadcast's, a
#: checklist's or a protocol's way of telling what to do with a thing where it is found, a case
#: as "if the sock is on the floor, ..." says it, no statement of where it is. Only a thing of one
#: or two words opening its clause, a place of up to three words, and after the comma a goal with
#: no verb ("into", "onto", "to", "back in/on") or no action at all (after a list's mark or an item's
#: number at most: "7.1 Bottle on the floor, onto the shelf"): "mug in the sink, plate on the rack"
#: (a second thing), "towel on the rail, please" and "the kettle on the worktop, to the left of the
#: hob" (where it stands beside another, "to the ... of") stay as they are
_VERBLESS_CASE = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?;:(])|(?<=[.!?;:(]\s))[ \t]*(?:[-*\u2022][ \t]+|\d{1,2}(?:[.)]|(?:\.\d{1,2})+[.)]?)[ \t]+)?)"
    r"(?P<thing>(?:(?:the|my|your|our|a|an|any)\s+)?[a-z][a-z-]*(?:\s+(?!not\b)[a-z][a-z-]*)?)\s+(?P<neg>not\s+)?"
    r"(?P<place>(?:on|in|inside|under)\s+(?:the|my|your|our)\s+[a-z-]+(?:\s+[a-z-]+){0,2}),\s+"
    r"(?P<answer>(?:(?:back|straight)\s+)?(?:into|onto|to)\s+(?:the|my|your|our|its|their)\s(?![a-z]+\s+of\b)"
    r"|back\s+(?:in|on)\s"
    r"|no\s+action\b|nothing\s+to\s+do\b)",
    re.I | re.M)


def _verbless_case(m: re.Match[str]) -> str:
    """`_VERBLESS_CASE` as a condition ("If the sock is on the floor, put it into the basket"),
    unless a word of the thing is a verb, "be" or a pronoun (`_NOT_A_THING`: "put mug in the
    sink, into ..." has its verb) or it is a bare state ("clean on the rack, ..." is a case of a
    state, `_STATE_CASE`)."""
    thing = m.group("thing")
    if _NOT_A_THING & set(thing.lower().split()) or thing.lower() in STATE_WORDS:
        return m.group(0)
    said = thing if thing.split()[0].lower() in DETERMINERS else f"the {thing}"
    answer = m.group("answer")
    head = thing.split()[-1].lower()
    plural = singular(head) != head  # "samples on the bench, ...": "if the samples are ..., put them ..."
    put = "" if answer[:1].lower() == "n" else f"put {'them' if plural else 'it'} "
    return (f"{m.group('lead')}{_match_case(thing, 'if')} {said[:1].lower()}{said[1:]} {'are' if plural else 'is'} "
            f"{m.group('neg') or ''}{m.group('place')}, {put}{answer}")


#: a place said to be checked or confirmed ("1 towel, to be checked on the drying rack", "the
#: spare key, still to be confirmed in the drawer") is left open, as "may be" leaves it: the
#: writer does not know yet (read as "1 towel may be on the drying rack")
_TO_BE_CHECKED = re.compile(r",?\s+(?:still\s+|yet\s+)?to\s+be\s+(?:checked|confirmed|verified|double-checked)"
                            r"\s+(?=(?:on|in|inside|under|by|near|at)\s)", re.I)


#: a modal doubt said with its own negation after a thing ("A tape roll may or may not be on the
#: cart", "the mug might or might not lie on the floor", "the lamp may, or may not, still be on"):
#: the negation only says the doubt runs both ways, which a modal alone already says, so it is
#: read as the modal ("may be on the cart") and a following "If so" / "If present" / "If it
#: does" takes up the clause as after "may be". After an existential "there" the doubt is
#: whether there is one at all ("there may or may not be bread"), which the readers of presence
#: read as such, so it is kept
_MODAL_DOUBT = re.compile(r"(?<!there )\b(may|might|could)\s*,?\s+or\s+(?:may|might|could)\s+not\s*,?(?=\s)", re.I)


#: a bracketed appositive of "one" between a thing and its place ("left a mug (the blue one) on
#: the desk", "a towel (the big white ones) in the hamper"): it only tells the thing apart, as the
#: same words between commas do, but a bracket cuts the clause (`clauses.clause_spans`) and
#: parts the thing from its place; it is read between commas. Only "one"/"ones" after a
#: determiner: a bracketed noun is a gloss or a fuller name (`naming.glossed`), kept as it is
_ONE_APPOSITIVE = re.compile(r"\s*\(((?:the|my|your|his|her|our|their|that|this)\s+(?:[A-Za-z'-]+\s+){0,3}ones?)\)"
                             r"(?=\s+(?:on|in|inside|under|by|near|next to|beside|behind|at|onto|into)\s)", re.I)


#: a formula of politeness before an instruction's verb ("be good enough to examine the towel",
#: "be so kind as to shut it"): it asks the listener to act, as the bare verb does, and is dropped
_POLITE = re.compile(r"\bbe (?:so )?(?:good|kind)(?: enough to| as to)\s+", re.I)


#: state words that are states only as a predicate, after a form of "be" at a clause's end: "the
#: dishwasher's already going", "if it's still going" (Merriam-Webster, "going" adj.: "running,
#: working"); elsewhere they are verbs ("it's going in the bin", "going to bed")
#: "in operation" (Merriam-Webster: "functioning, in use"; "the dryer is still in operation"), its
#: article kept by a translated text ("if the air conditioner is still in the operation"); and
#: the progressive of opening and closing said as the state it leaves, as learners and translated
#: texts say it ("When the mouth of the bag is opening, please close it", "if the window is
#: opening, shut it"): only as a predicate at a clause's end, where a thing's state is asked
PREDICATE_STATES = {"going": "running", "in operation": "running", "opening": "open", "closing": "closed",
                    # the participle of a verb whose result is a state, said of the thing ("if the
                    # bowl has been washed" is clean, "if the bucket was emptied" is empty), and a
                    # verb of the state in progress ("if the towel is still dripping" is wet); only
                    # as a predicate: "1 washed shirt" describes the thing and asks nothing
                    "washed": "clean", "rinsed": "clean", "scrubbed": "clean", "emptied": "empty",
                    "dried": "dry", "dripping": "wet"}
#: a predicate state's "in" may take an article (`PREDICATE_STATES`)
_ARTICLE_OPTIONAL = re.compile(r"^in ")
_IN_ARTICLE = r"in\\s+(?:the\\s+)?"
_ARTICLE_IN = re.compile(r"in\s+(?:the\s+)?")
#: adverbials of time or of the place already spoken of that may follow a predicate state before
#: its clause ends ("if the bucket was emptied overnight", "if the mug has been taken again", "the
#: lamp: if off right now, ..."): they say when, not what, so the state is still its clause's
#: predicate; a place or a direction after the participle ("emptied into the sink", "taken to the
#: kitchen") is no such adverbial and leaves the verb a verb
TRAILING_ADVERBIALS = ("already", "still", "now", "again", "overnight", "earlier", "yesterday", "today",
                       "tonight", "lately", "recently", "this morning", "this afternoon", "this evening",
                       "last night", "all night", "all day", "at the moment", "right now", "by now",
                       "for now", "in there", "in here")
#: words after a predicate state that go on to another clause ("if it's still going, then ...")
GOING_ON = ("then", "and", "or", "but", "so")
#: the times of a day a state may be said to have held since, after, from or during ("was it left
#: going after the last nap?", "if the heater is still going since lunch", "still going from last
#: night"): a preposition of time before one of these says when, as `TRAILING_ADVERBIALS` do, so
#: the state is still its clause's predicate; "going after the cat" or "going in the cupboard
#: after lunch" name no such time straight after "going" and leave the verb a verb
TIMES_OF_DAY = ("nap", "naps", "sleep", "breakfast", "lunch", "dinner", "supper", "tea", "meal", "film",
                "movie", "meeting", "shift", "party", "class", "lesson", "service", "session", "night",
                "morning", "afternoon", "evening", "weekend", "bath", "visit", "match", "game", "show")
_TIME_PREPOSITIONS = ("after", "since", "from", "before", "during", "through", "over")
_TIME_AFTER = (rf"(?:{'|'.join(_TIME_PREPOSITIONS)})\s+(?:(?:the|this|that|last|her|his|their|our|my|your)\s+){{0,2}}"
               rf"(?:{'|'.join(TIMES_OF_DAY)})(?![\w-])")
_SPACED = re.compile(" ")
_ADVERBIALS = "|".join([_SPACED.sub(r"\\s+", a) for a in TRAILING_ADVERBIALS] + [_TIME_AFTER])
_CLAUSE_END = r"(?=\s*(?:[,.;:!?)]|$|\s(?:" + "|".join(GOING_ON) + "|" + _ADVERBIALS + r")\b))"
#: participles and phrases that say a thing is not where it should be at all, as a predicate at a
#: clause's end: "if the mug has been taken", "if the lamp was removed", "when it has
#: disappeared", "if the remote is nowhere to be seen" (read as "missing", `analysis.ABSENT`).
#: Only as a predicate: "taken to the kitchen", "taken out", "removed from the shelf" say where it
#: went, and "has taken the mug" is an act of someone's
ABSENCE_PREDICATES = ("taken away", "taken", "removed", "disappeared", "vanished", "gone missing",
                      "nowhere to be seen", "nowhere to be found", "not anywhere to be seen")
_PREDICATE_WORDS = "|".join([_ARTICLE_OPTIONAL.sub(_IN_ARTICLE, k) for k in PREDICATE_STATES]
                            + [_SPACED.sub(r"\\s+", a) for a in ABSENCE_PREDICATES])
_PREDICATE_STATE = re.compile(
    rf"((?:\b(?:is|are|was|were|be|been)|'s|\u2019s)(?:\s+(?:still|already|just|now))*\s+|\b(?:still|already)\s+"
    # an intransitive verb of going says its absence in the perfect: "if the mug has disappeared"
    rf"|\b(?:has|have|had)(?:\s+(?:just|now|already))*\s+(?=(?:disappeared|vanished|gone\s+missing)\b))"
    rf"({_PREDICATE_WORDS}){_CLAUSE_END}", re.I | re.M)
#: the same participle in a question that puts its auxiliary first ("Was the bowl washed?", "Has
#: my mug been taken?"): the participle before the question mark is the predicate of the subject
#: between them, read as its state
_QUESTION_PREDICATE = re.compile(
    rf"((?:^|(?<=[.!?:;]\s)|(?<=\n)|(?<=\s-\s))[ \t]*(?:was|were|is|are|has|have|had)\s+(?:it|they|the|my|your"
    rf"|our|his|her|their|this|that|these|those)\b[^.?!,;:\n]{{0,40}}?\s)({_PREDICATE_WORDS})"
    rf"(?=(?:\s+(?:{_ADVERBIALS}))?\s*\?)", re.I | re.M)
#: a case put as what a state means, opening a clause ("Check it: still burning means it gets blown
#: out", "Kettle. Empty means fill it", "Already off means no problem"): "if it is <state>, ..." of
#: the thing just spoken of (`STATE_WORDS` only: "No kettle on the counter means no tea" and a
#: definition, "'tidy' means put away", are left as they are)
_MEANS_LEAD = r"((?:^|(?<=[.!?:;,]\s)|(?<=\n)|(?<=\s[-\u2013\u2014]\s))[ \t]*)"  # where such a case opens
_MEANS_CASE = re.compile(
    rf"{_MEANS_LEAD}((?:(?:still|already)\s+)?"
    rf"(?:{'|'.join(sorted(w for w in STATE_WORDS if ' ' not in w))}))\s+means\s+", re.I | re.M)
#: the same case put as what a thing's contents mean ("no water in it means fill it up", "water
#: left in it means tip it away"): "if there is (no) water in it, ..." (what "there is ... in it"
#: says of the container is the factor reader's, `offline.analysis`)
_MEANS_THERE = re.compile(
    rf"{_MEANS_LEAD}((?:(?:no|some|any|still)\s+)?[a-z]+(?:\s+left)?"
    r"\s+(?:in|inside)\s+(?:it|them))\s+means\s+", re.I | re.M)
#: a condition with its subject and verb elided before such a predicate ("the mug: if washed, put it
#: away", "the remote - if missing, tell me", "if taken, let me know"), read "if it is ...";
#: not after "once" ("wash the mug and once washed, ..." is a step after the washing, not a question)
_ELIDED_PREDICATE = re.compile(
    rf"\b(if|unless|when|whenever)\s+(?=(?:(?:still|already)\s+)?(?:{_PREDICATE_WORDS}|missing|gone){_CLAUSE_END})",
    re.I | re.M)


def _predicate(word: str) -> str:
    """The state word a predicate of `PREDICATE_STATES` or `ABSENCE_PREDICATES` says."""
    said = " ".join(_ARTICLE_IN.sub("in ", word.lower()).split())
    return PREDICATE_STATES.get(said, "missing")


def predicate_state(clause: str) -> str:
    """The clause with a predicate of `PREDICATE_STATES` or `ABSENCE_PREDICATES` at its end read
    as its state word, as `unquote` reads it before a mark: for a condition cut from its
    instruction where the writer typed no comma ("if my mug hasn't been washed wash it", "if the
    towel is still dripping hang it up", `clauses._imperative_cut`), whose predicate no mark
    ended when the text was normalised (the thirteenth session)."""
    return _PREDICATE_STATE.sub(lambda m: m.group(1) + _predicate(m.group(2)), clause)


#: a device's sound or activity said as the finite verb of a condition ("if the alarm clock rings,
#: silence it", "when the timer beeps", "if the candle still burns, blow it out", "if the fan
#: still runs", "if it ring" in verse or a learner's English): the device is going, as "is
#: ringing" / "is burning" says (`STATE_WORDS`); only right after a condition's cue and a short
#: subject, so "the phone that rings" or "ring the bell" asks nothing. A subject holds no copula
#: and the verb no object: "if the lamp is on ring me", "if the fridge is open buzz us" end their
#: condition at an instruction to call the speaker (the eighteenth session). An adverb of time
#: ("still", "already") and a negation ("no longer", "doesn't", a learner's "not burns") may
#: stand before the verb, as before "is burning"; a particle after it makes another verb ("runs
#: out", "burns down", "plays up": stock run out, a thing broken), never the thing's activity (the
#: nineteenth session)
SOUNDS = {"ring": "ringing", "rings": "ringing", "beep": "beeping", "beeps": "beeping",
          "buzz": "buzzing", "buzzes": "buzzing", "bleep": "beeping", "bleeps": "beeping",
          "burn": "burning", "burns": "burning", "run": "running", "runs": "running",
          "glow": "glowing", "glows": "glowing", "spin": "spinning", "spins": "spinning",
          "whirr": "whirring", "whirrs": "whirring", "play": "playing", "plays": "playing"} | {
    # (the twenty-first session) a thing's steady activity while it is going, said of a machine
    # or a light: "if the fan still hums", "if the lamp still shines", "when the kettle
    # whistles"; their forms by the lemmatiser, the "-ing" form read as a word of operation
    # (`analysis.OPERATION_WORDS`), so only of a thing that switches on
    form: str(getInflection(verb, "VBG")[0]) for verb in ("hum", "shine", "whistle")
    for form in (verb, str(getInflection(verb, "VBZ")[0]))}
#: the adverbs of time and the negations that may stand between the subject and the verb
_SOUNDING_BEFORE = {"still": "still", "already": "already", "no longer": "no longer", "not": "not",
                    "doesn't": "not", "does not": "not", "don't": "not", "do not": "not",
                    "still not": "still not", "already not": "already not", "never": "not"}
_SOUNDING = re.compile(r"\b(if|when|whenever|unless|once|in\s+case)\s+((?:it|they|(?:the|my|your|our|his|her|this|that)"
                       r"(?:\s+(?!(?:is|are|was|were|be|been|being|still|already|not|no|never|doesn't|does|don't|do)\b)"
                       r"[a-z]+){1,3}?))\s+"
                       rf"(?:({'|'.join(sorted(_SOUNDING_BEFORE, key=len, reverse=True))})\s+)?"
                       rf"({'|'.join(SOUNDS)})\b(?!\s+(?:the|a|an|my|your|it|them|me|us|out|down|up|over|off|low|short"
                       r"|dry|away|into|through)\b)", re.I)


def _sounding(m: re.Match[str]) -> str:
    """"if the alarm rings" as "if the alarm is ringing", "if it no longer burns" as "if it is no
    longer burning" (`_SOUNDING`)."""
    be = "are" if m.group(2).lower() == "they" else "is"
    before = f"{_SOUNDING_BEFORE[' '.join(m.group(3).lower().split())]} " if m.group(3) else ""
    return f"{m.group(1)} {m.group(2)} {be} {before}{SOUNDS[m.group(4).lower()]}"


#: "In the case the heater is on", "in the event that the tap is running": a condition opened by
#: a noun of occasion ("in the case (that)", "in the event (that)"; Merriam-Webster, "in the event
#: that": "if it happens that"), read as "if"; only where a clause starts (its sentence's or item's
#: start, a comma or a conjunction before it) and not before "of" ("in the case of fire" is no
#: clause; "put it in the case the optician gave you" puts it in a case)
_OCCASION_IF = re.compile(r"(?:(?<=^)|(?<=[.!?;:,)\n])|(?<=[.!?;:,)]\s)|(?<=\band\s)|(?<=\bbut\s))[ \t]*\b"
                          r"in\s+the\s+(?:case|event)(?:\s+that)?\b(?!\s+of\b)", re.I | re.M)


#: a supposition put as an imperative or a participle ("Suppose the lamp is on. Then switch it
#: off", "Supposing the bin is full, empty it", "Assuming that the kettle is cold, ...": a proof's,
#: a puzzle's or a lawyer's "if"), read as "if" (`_occasion_if`); only where a sentence or a clause
#: starts, so a belief with its subject ("I suppose the lamp is on") stays a hedge
#: (`clauses.DOUBT`), and not before "so" or "not" ("Suppose so.")
_SUPPOSED_IF = re.compile(r"(?:(?<=^)|(?<=[.!?;:)\n])|(?<=[.!?;:)]\s)|(?<=\s-\s))[ \t]*\b(?:suppose|supposing|assume|assuming"
                          r"|let(?:'s|\s+us)\s+(?:say|suppose|assume))(?:\s+(?:instead|now))?(?:\s+that)?\b"
                          r"(?!\s+(?:so|not)\b)", re.I | re.M)


#: a proviso opened by a cue the reader's list (`clauses.CONDITIONAL`) does not hold: "providing
#: (that)", a bare "provided", "on (the) condition that" (read as "provided that") and "so long
#: as" (read as "as long as"; Merriam-Webster, "provided": "on condition that: if"). "provided" and
#: "providing" only before a clause, a subject (a determiner of `DETERMINERS` but "that", "any"
#: and "some", which open a clause or a quantity more often than a subject, and up to four words,
#: or a pronoun)
#: and its finite verb, so the participle ("the towels provided by the hotel", "the soap provided
#: is ...") and the gerund ("for providing the towels") stay
_PROVISO = re.compile(
    r"\b(?:(?P<given>provided|providing)(?:\s+that)?|on\s+(?:the\s+)?condition\s+that|(?P<long>so\s+long\s+as))\b"
    rf"(?=(?:\s+that)?\s+(?:(?:{'|'.join(sorted(DETERMINERS - {'that', 'any', 'some'}))})"
    r"(?:\s+(?!(?:that|which|who|with|for|to|and|or|but)\b)[a-z][\w-]*){1,4}"
    r"|it|they|there|he|she|we|you|u|nobody|no\s+one|someone|somebody|everyone|everybody)"
    r"(?:'s|'re|\s+(?:is|are|isn't|aren't|was|were|has|have|hasn't|haven't|does|do|doesn't|don't|can|will|looks|look"
    r"|seems|seem|stays|stay|remains|remain|still|already|not))\b)", re.I)


def _proviso(m: re.Match[str]) -> str:
    """A proviso's cue as the one the reader reads (`_PROVISO`); "provided" / "providing" after an
    auxiliary or a preposition is a verb's form ("we are providing the kids ...", "for providing
    the towels"), kept as written."""
    before = m.string[:m.start()].split()
    if m.group("given") and before and before[-1].lower() in _VERB_BEFORE_PROVISO:
        return m.group(0)
    return _match_case(m.group(0), "as long as" if m.group("long") else "provided that")


#: words after which "provided" / "providing" is a verb's participle or gerund, not a proviso
_VERB_BEFORE_PROVISO = frozenset({"am", "is", "are", "was", "were", "be", "been", "being", "has", "have", "had",
                                  "for", "by", "of", "about", "from", "not", "without"})


#: a thing gone missing said with the inchoative "go" in a simple tense ("If the remote goes
#: missing", "Should the keys go missing", "if the scissors went missing again"): read as the
#: state it comes to, "missing" after the copula of the same tense (`ABSENCE_PREDICATES` reads
#: the perfect, "has gone missing", and the copula); the base form after a modal, "to" or "let"
#: is "be"
GOES_MISSING = {"goes": "is", "go": "are", "went": "was"}
_GOES_MISSING = re.compile(r"\b(?P<before>\w+)(?P<gap>\s+(?:ever\s+|again\s+|suddenly\s+)?)(?P<go>goes|go|went)\s+missing\b",
                           re.I)
_BASE_BEFORE = frozenset({"should", "shall", "will", "would", "may", "might", "can", "could", "must", "to", "let"})


def _goes_missing(m: re.Match[str]) -> str:
    """"goes missing" as "is missing" (`GOES_MISSING`), an adverb of time between dropped ("ever goes
    missing", "went missing again": it says when, not what); "go" after a modal, "to" or "let" as
    "be"."""
    go = m.group("go").lower()
    be = "be" if go == "go" and m.group("before").lower() in _BASE_BEFORE else GOES_MISSING[go]
    return f"{m.group('before')} {be} missing"


#: a left-dislocated noun phrase taken up by a pronoun after a dash ("The PC on the desk - it's
#: a desktop computer, so ...", "My mug on the desk - it's dirty", "The towels - they're wet"), a
#: sentence's opening in speech and notes: the noun phrase is the clause's subject, read as
#: "The PC on the desk is a desktop computer". Only a noun phrase that opens its sentence (or a
#: numbered or bulleted item) with a determiner and holds no finite verb or conjunction of its
#: own (`_NOT_DISLOCATED`: "The mug is on the desk - it's dirty" is a clause and its comment); a
#: comma's "That said, it's ..." is no noun phrase, so the comma is left alone
_LEFT_DISLOCATED = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?])[ \t]+)[ \t]*(?:\d{1,2}[.)][ \t]+|[-*\u2022][ \t]+)?)"
    rf"(?P<np>(?:{'|'.join(sorted(DEFINITE_OPENERS | {'this', 'these', 'those'}))})[ \t]+(?:[\w'-]+[ \t]+){{0,5}}?[\w'-]+)"
    r"[ \t]+[-\u2013\u2014][ \t]+(?P<pron>it|they)(?P<be>'s|'re|[ \t]+is|[ \t]+are)(?P<after>[ \t]+\w+)",
    re.I | re.M)
_NOT_DISLOCATED = frozenset({"is", "are", "was", "were", "has", "have", "had", "be", "been", "do", "does", "did",
                             "can", "will", "should", "must", "may", "might", "if", "when", "unless", "once",
                             "while", "because", "so", "then", "it", "they", "you", "we", "i"})


def _left_dislocated(m: re.Match[str]) -> str:
    """`_LEFT_DISLOCATED`'s noun phrase as the subject of the pronoun's verb ("'s been" as "has
    been")."""
    if set(w.lower() for w in m.group("np").split()) & _NOT_DISLOCATED:
        return m.group(0)
    be = m.group("be").strip().lower()
    after = m.group("after")
    perfect = after.strip().lower() in ("been", "got", "gotten")
    verb = {"'s": "has" if perfect else "is", "'re": "have" if perfect else "are"}.get(be, be)
    return f"{m.group('lead')}{m.group('np')} {verb}{after}"


#: the subjects of a relative clause `_CONTACT_RELATIVE` drops: the pronouns and a household's
#: people (not its pets: "if the bowl the cat eats from is empty" is left as it is written)
RELATIVE_SUBJECTS = ("i", "you", "we", "they", "he", "she", "someone", "somebody", "the kids", "the children",
                     "the guests", "the cleaner")
_RELATIVE_SUBJECT = "|".join(w.replace(" ", r"\s+") for w in RELATIVE_SUBJECTS)
#: a subject with a relative clause whose own subject is a pronoun or a household's people, "that"
#: or "which" said or left out ("the old towel I use to dry legs is over the chair", "If the mug
#: you left on the desk is dirty", "when the towel the kids used is wet"): the clause
#: says which thing is meant, the predicate after it is the thing's, so the clause is dropped and
#: a place it ends with is kept as the thing's place ("the mug on the desk is dirty": where it was
#: left is where it is). Only a clause of one to eight words with no comma, opened by a verb (the
#: lemmatiser's) and holding no pronoun, contraction or conjunction of a clause of its own, after a noun phrase
#: with none either (`_NOT_RELATIVE`: "if you find the key you know it is in the bowl" and "wash the
#: plate and we make sure our toaster is off" are two clauses)
_CONTACT_RELATIVE = re.compile(
    rf"\b(?P<np>(?:{'|'.join(sorted(DEFINITE_OPENERS))})\s+(?:[a-z-]+\s+){{0,2}}?[a-z-]+)\s+(?:(?:that|which)\s+)?"
    rf"(?P<subject>{_RELATIVE_SUBJECT})\s+"
    r"(?P<clause>(?:[a-z'-]+\s+){1,8}?)(?P<be>is|are|isn't|aren't|was|were|looks|seems)\b", re.I)
_NOT_RELATIVE = frozenset({"it", "they", "them", "he", "she", "him", "her", "there", "that", "which", "if", "when",
                           "and", "but", "or", "because", "so", "is", "are", "was", "were", "i", "you", "we",
                           "this", "these", "those", "how", "what", "where", "who", "why",
                           # a verb of thinking or saying whose clause the "be" is ("the mug I think is dirty")
                           "think", "thought", "believe", "reckon", "guess", "suppose", "know", "say", "said"})
#: the prepositions of place a dropped relative clause's place may open with, and the one kept
_RELATIVE_PLACE = {"on": "on", "onto": "on", "in": "in", "into": "in", "inside": "inside", "under": "under",
                   "by": "by", "beside": "beside", "over": "over"}


def _contact_relative(m: re.Match[str]) -> str:
    """`_CONTACT_RELATIVE`'s subject without its relative clause, with the place the clause ends
    with."""
    clause = m.group("clause").split()
    said = [w.lower() for w in clause + m.group("np").split()[1:]]
    if set(said) & _NOT_RELATIVE or any("'" in w for w in said) or "VERB" not in getAllLemmas(clause[0].lower()):
        return m.group(0)
    at = next((k for k in range(len(clause) - 2, -1, -1) if clause[k].lower() in _RELATIVE_PLACE
               and clause[k + 1].lower() in DETERMINERS), None)
    place = f" {_RELATIVE_PLACE[clause[at].lower()]} {' '.join(clause[at + 1:])}" if at is not None and at > 0 else ""
    return f"{m.group('np')}{place} {m.group('be')}"


#: the putative "should" of a condition ("If the kettle should be empty, fill it", "in case the
#: towels should still be damp"; Quirk et al., the putative "should" in a conditional clause):
#: what is, not what ought to be, so its verb is read finite ("If the kettle is empty"). Only
#: right after the cue's subject (a determiner of `DETERMINERS` short of "that" and the
#: quantifiers but "any", and up to four words, or "it" / "they"), so a
#: consequence's "should" ("If it is empty, it should be filled") and a subject that is a clause
#: ("if you need the pan it should be clean") stay; "you should find" is read as it is
_PUTATIVE_SHOULD = re.compile(
    r"\b(?P<cue>if|in\s+case|unless|provided\s+that|as\s+long\s+as)\s+"
    rf"(?P<subject>(?:{'|'.join(sorted(DETERMINERS - {'that', 'every', 'each', 'some', 'no'}))})"
    r"(?:\s+[a-z][\w-]*){1,4}|it|they)\s+should\s+(?P<adverbs>(?:(?:still|ever|also|really"
    r"|not|by\s+(?:any\s+)?chance)\s+)*)(?P<verb>[a-z]+)\b", re.I)
_PUTATIVE_SUBJECT_STOPS = frozenset({"it", "they", "you", "we", "i", "u", "should", "is", "are"})


def _putative_should(m: re.Match[str]) -> str:
    """A condition's "should" + verb as the finite verb (`_PUTATIVE_SHOULD`): "is" / "are" for
    "be", the third person singular or the base form by the subject's number, "does not" / "do
    not" before a negated verb other than "be"; kept as written where the subject holds a
    pronoun or a verb (a clause)."""
    subject = m.group("subject").split()
    if len(subject) > 1 and set(w.lower() for w in subject[1:]) & _PUTATIVE_SUBJECT_STOPS:
        return m.group(0)
    head = subject[-1].lower()
    plural = head == "they" or (len(subject) > 1 and singular(head) != head)
    verb = m.group("verb").lower()
    adverbs = m.group("adverbs").split()
    negated = [w for w in adverbs if w.lower() == "not"]
    others = " ".join(w for w in adverbs if w.lower() != "not")
    if verb == "be":
        finite = f"{'are' if plural else 'is'}{' not' if negated else ''}"
        said = " ".join(x for x in (finite, others) if x)
    elif negated:
        said = " ".join(x for x in ("do not" if plural else "does not", others, verb) if x)
    else:
        form = verb if plural else (getInflection(verb, "VBZ") or (verb + "s",))[0]
        said = " ".join(x for x in (others, form) if x)
    return f"{m.group('cue')} {m.group('subject')} {said}"


#: comment adverbials a writer sets off with commas inside a clause ("The remote, as ever, belongs
#: on the stand", "the kettle, of course, lives on the counter", "the mat is, as usual, on the
#: floor"): they say what the writer thinks of the clause, nothing of the scene, and between a
#: subject and its verb they hide the statement; dropped with their commas. (Not
#: `analysis._Reader._aside_end`, which passes over any short aside but only before a place: a
#: named list may drop its asides everywhere, an open one only where it hides no condition)
COMMENT_ASIDES = ("as ever", "as always", "as usual", "of course", "naturally", "by the way",
                  "incidentally", "as you know", "as you'll know", "needless to say", "as it happens")
_COMMENT_ASIDE = re.compile(rf"(?<=\w),\s+(?:{'|'.join(re.escape(a) for a in COMMENT_ASIDES)}),\s+(?=\w)", re.I)


#: the subjects an alternative condition opens with after its "or" ("or we have none at all", "or
#: it's on the floor", "or if there isn't one", "or should it be on"): a clause, not a second thing
#: or an alternative instruction ("- or put it in the basket", "- or on the desk")
_ALTERNATIVE_SUBJECTS = ("we", "you", "they", "it", "there", "i", "he", "she", "someone", "somebody", "nobody",
                         "no one")
_DASH_MARK = r"(?:-|--|\u2013|\u2014)"
#: an alternative condition set off by dashes or a bracket, or closed by a colon or an arrow ("If
#: it is anywhere else - or we have none at all - leave it", "If the book is on the sofa (or it's
#: on the floor), ...", "If it's anywhere else, or we have none: leave it", "The detergent is
#: anywhere else - or we have none at all.", or a quiz's case turned into a condition, "If it is
#: anywhere else - or we have none at all, leave it"): written with commas ("If it is anywhere else, or we
#: have none at all, leave it"), as the condition reader reads two alternatives; the dash, the
#: bracket or the colon otherwise cut the alternative off as an aside or an instruction
_SET_OFF_ALTERNATIVE = re.compile(
    rf"(?P<open>[ \t]+{_DASH_MARK}[ \t]+|[ \t]*\(|,[ \t]*)"
    rf"(?P<alt>or[ \t]+(?:(?:if|should|when)[ \t]+)?(?:{'|'.join(s.replace(' ', '[ ]') for s in _ALTERNATIVE_SUBJECTS)})"
    r"\b[^,.?!;:\n()\u2013\u2014-]*?)"
    rf"(?P<end>[ \t]+{_DASH_MARK}[ \t]+|[ \t]*\)[ \t]*,?[ \t]*|[ \t]*(?::|->|\u2192)[ \t]*|(?=[ \t]*[.?!])|(?<=[^,])(?=,))",
    re.I)


def _set_off_alternative(m: re.Match[str]) -> str:
    """`_SET_OFF_ALTERNATIVE`'s alternative between commas (a comma after it only where something
    follows in the sentence). A bracket is one only with both its marks: in "> NO (the bread is
    somewhere else, or we are out of bread): skip the toast" the bracket is an answer's gloss, and
    its alternative after a comma is read within it already."""
    if (m.group("open").strip() == "(") != (m.group("end").strip().startswith(")")):
        return m.group(0)
    return f", {m.group('alt')}" + (", " if m.group("end") and not m.string.startswith(",", m.end()) else "")


#: connectives a writer may break off after, an aside between dashes before the clause they open
#: ("If - and it does happen - the lamp is on, ...", "Unless - ah, unless! - the dishwasher is
#: already running: ...", "When - not if - the bin is full, ..."): the aside says how the writer
#: feels about the case, nothing of it, and hides the condition from its cue; dropped with its
#: dashes. Only straight after the connective and up to `_DASHED_ASIDE_WORDS` words, so a dash
#: after a condition ("if it's dirty - sink") and a dashed list are left alone
DASHED_ASIDE_CONNECTIVES = ("if", "unless", "when", "whenever", "once", "should", "provided that", "as long as",
                            "in case")
_DASHED_ASIDE_WORDS = 6
_DASHED_ASIDE = re.compile(
    rf"\b(?P<cue>{'|'.join(re.escape(c) for c in DASHED_ASIDE_CONNECTIVES)})[ \t]+{_DASH_MARK}[ \t]+"
    rf"(?:[^\s.?\n\u2013\u2014-]+[ \t]+){{1,{_DASHED_ASIDE_WORDS}}}{_DASH_MARK}[ \t]+(?=\w)", re.I)


#: an exception put as a condition ("fold up the brolly except when it's still wet", "Baste the
#: chicken every twenty minutes except when the oven is off", "Open it except if it is open
#: already"; Merriam-Webster, "except" as a conjunction: "unless"): read as "unless", so that the
#: instruction before it falls where the condition does not hold; "except where" is a statement's
#: exception (`clauses._EXCEPT_WHERE`)
EXCEPTIVE_CUES = ("except when", "except if")
_EXCEPTIVE = re.compile(r"\b(?:" + "|".join(c.replace(" ", r"\s+") for c in EXCEPTIVE_CUES) + r")\b", re.I)

#: a letter's or a message's salutation before a comma at the text's start ("Dear Ms Ames, if my
#: spectacles are on the sofa, please put them in their case", "Dear colleague, got a dirty cup
#: ...?", "Hi Sam, ..."): the greeting (`lexicon.GREETINGS`) and the name or title after it are a line
#: of their own, as a letter sets them, not the instruction a condition after them is said of; the
#: letter's first sentence opens with a capital (a line in small letters goes on the line before's
#: sentence: `_BROKEN_LINE`)
_SALUTATION = re.compile(r"\A(?P<greeting>[ \t]*(?i:" + "|".join(sorted(GREETINGS)) + r")(?:[ \t]+[A-Za-z][\w.'-]*){0,3})"
                         r"[ \t]*,[ \t]*(?P<first>\S)")

#: where a clause starts: a text's or line's start, after a sentence's or clause's mark (a comma
#: too: "Dear Jo, the oven, if on, ..."), or after
#: a log line's number ("2254 Were the microwave on, ...", "3.19 Desk lamps, if on, ...")
_CLAUSE_START = r"(?:(?<=^)|(?<=[.!?;:,)\n])|(?<=[.!?;:,)]\s))(?P<lead>[ \t]*(?:\d+(?:\.\d+)*[ \t]+)?)"

#: a condition by inversion with "were" ("Were the oven on when you get in, switch it off", "Were
#: the washing machine to be left open, the Resident shall close it"; Quirk et al., the inverted
#: conditional of "were", "had" and "should"), read as "if" with its verb after the subject ("If the
#: oven were on ..."), as the reader reads "should" (`clauses.CONDITIONAL`). Only where a clause
#: starts with a determiner after "were" and the clause ends in a comma: a question ("Were the
#: lights on?") ends in its mark
_INVERTED_WERE = re.compile(
    _CLAUSE_START + rf"(?P<were>were)\s+(?P<clause>(?:{'|'.join(sorted(DETERMINERS))})\s+[^,.;:!?\n]{{1,80}}?)(?=\s*,)",
    re.I | re.M)
#: the words that end the subject of an inverted "were" and open what is said of it: a state, an
#: adverb before one, "to be", or a place
_WERE_PREDICATE = frozenset(STATE_WORDS) | {"still", "not", "already", "to", "left", "found", "switched",
                                            "turned"} | PREP_ON | PREP_IN


def _inverted_were(m: re.Match[str]) -> str:
    """"Were the X on, ..." as "If the X were on, ..." (`_INVERTED_WERE`), "to be" dropped ("Were
    the machine to be left open": "If the machine were left open"); kept as written when nothing
    in the clause is said of its subject (`_WERE_PREDICATE`)."""
    words = m.group("clause").split()
    at = next((i for i, w in enumerate(words) if i > 1 and w.lower() in _WERE_PREDICATE), None)
    if at is None:
        return m.group(0)
    said = words[at:]
    if [w.lower() for w in said[:2]] == ["to", "be"]:
        said = said[2:]
    return f"{m.group('lead')}{_match_case(m.group('were'), 'if')} {' '.join(words[:at])} were {' '.join(said)}"


#: a condition set inside the sentence after its topic ("The fan, if on, switch it off", "Alarm
#: clock in bedroom one, if on, silence it", "The television, if on, shall be switched off by the
#: last guest"): the topic is the condition's subject and the instruction after the second comma
#: its branch, read as "If the fan is on, switch it off" ("If the television is on, it shall be
#: ..."). The topic is a noun phrase of a few words, its determiner first if it has one, and the
#: condition a state (`STATE_WORDS`) after "not", "still" or "already" at most
_TOPIC_IF = re.compile(
    _CLAUSE_START + r"(?P<topic>[A-Za-z][\w'-]*(?:[ \t]+[A-Za-z][\w'-]*){0,5}?)[ \t]*,[ \t]*if[ \t]+"
    rf"(?P<state>(?:(?:not|still|already)\s+)?(?:{_STATE_ALTERNATION}))"
    r"\s*,\s*(?=(?P<rest>[A-Za-z]+))", re.I | re.M)
#: words that make a "topic" a clause: a pronoun object ("Switch it off, if on"), a verb's particle
#: ("Turn the heater down, if on") or a subject
_NOT_TOPIC = frozenset({"it", "them", "him", "her", "you", "we", "they", "i", "u", "off", "on", "up", "down", "out",
                        "away", "over", "back", "is", "are", "was", "were"})
#: the finite words an instruction said of its topic opens with ("..., shall be switched off"): the
#: topic is taken up by a pronoun before them
_TOPIC_FINITE = frozenset({"shall", "should", "must", "is", "are", "will", "can", "may", "need", "needs", "has",
                           "have"})


def _topic_if(m: re.Match[str]) -> str:
    """"The X, if on, ..." as "If the X is on, ..." (`_TOPIC_IF`); kept as written when the topic
    is a clause (`_NOT_TOPIC`, a verb of putting first, a determiner inside it)."""
    words = m.group("topic").split()
    low = [w.lower() for w in words]
    if set(low) & _NOT_TOPIC or low[0] in ACTIONS or any(w in DETERMINERS for w in low[1:]) and not (
            set(low) & (PREP_ON | PREP_IN)):
        return m.group(0)
    head = next((w for w in reversed(low[:next((i for i, w in enumerate(low) if w in PREP_ON | PREP_IN), len(low))])),
                low[-1])
    plural = singular(head) != head
    taken_up = f"{'they' if plural else 'it'} " if m.group("rest").lower() in _TOPIC_FINITE else ""
    topic = m.group("topic")[0].lower() + m.group("topic")[1:]
    return f"{m.group('lead')}If {topic} {'are' if plural else 'is'} {m.group('state')}, {taken_up}"


#: a condition put as an imperative and "and you" ("Find the fridge open and you close it", "find
#: the curtains open at 9 and u draw them": the conditional imperative, Quirk et al.'s "Do that
#: and you'll regret it"), read as "If you find the fridge open, close it": the verbs of coming
#: upon a thing (`DISCOVERY`, in their base form), a state or a place the thing is found in, and
#: "and you" after it make it a condition; without "you" ("Find the keys on the hook and bring
#: them") it is two instructions
DISCOVERY = frozenset({"find", "found", "spot", "spotted", "see", "saw", "seen", "notice", "noticed", "discover",
                       "discovered", "come", "came", "across", "upon"})
_FINDING = sorted(w for w in DISCOVERY if getAllLemmas(w, upos="VERB").get("VERB", ("",))[0] == w)
_FOUND_AND = re.compile(
    _CLAUSE_START + rf"(?P<verb>{'|'.join(_FINDING)})\s+(?P<found>(?:{'|'.join(sorted(DETERMINERS))})\s+"
    r"[^,.;:!?\n]{1,80}?)\s*,?\s+and\s+(?:you|u)\s+(?:(?:will|'ll|must|shall|should|then)\s+)?(?=[a-z])",
    re.I | re.M)


def _found_and(m: re.Match[str]) -> str:
    """"Find the X open and you close it" as "If you find the X open, close it" (`_FOUND_AND`),
    where the thing is found in a state or at a place; "Find the remote and you can watch" stays."""
    if not set(m.group("found").lower().split()[1:]) & (set(STATE_WORDS) | PREP_ON | PREP_IN | {"under"}):
        return m.group(0)
    return f"{m.group('lead')}{_match_case(m.group('verb'), 'if')} you {m.group('verb').lower()} {m.group('found')}, "


def _occasion_if(m: re.Match[str]) -> str:
    lead = m.group(0)[:len(m.group(0)) - len(m.group(0).lstrip(" \t"))]
    return lead + ("If" if m.group(0).lstrip(" \t")[0].isupper() else "if")


#: a telegram's words for its punctuation (Oxford: stop, "(in telegrams) a full stop"; query,
#: "a question mark"), read only in a text that ends two sentences or more with "STOP" in capitals
TELEGRAM_MARKS = {"STOP": ".", "QUERY": "?"}
_TELEGRAM_MARK = re.compile(rf"\s+\b({'|'.join(TELEGRAM_MARKS)})\b(?=\s|$)")


def _telegram(text: str) -> str:
    """A telegram's "STOP" and "QUERY" as the full stop and question mark they stand for."""
    if len(re.findall(r"\bSTOP\b", text)) < 2:
        return text
    return _TELEGRAM_MARK.sub(lambda m: TELEGRAM_MARKS[m.group(1)], text)


#: voice typing's spoken punctuation (the words a dictation app turns into marks: "comma", "full
#: stop", "new paragraph"), read only in a text that speaks two kinds of mark or more
#: (`_dictated`): there a sentence ends at "full stop", not at the next written mark
DICTATED_MARKS = {"full stop": ".", "period": ".", "comma": ",", "question mark": "?",
                  "exclamation mark": "!", "exclamation point": "!", "new paragraph": ".\n\n",
                  "new line": ".\n", "semicolon": ";", "colon": ":"}
_DICTATED_MARK = re.compile(r"\s*\b(" + "|".join(sorted(DICTATED_MARKS, key=len, reverse=True)).replace(" ", r"\s+")
                            + r")\b[ \t]*", re.I)


#: a line that ends on a word no clause ends on (a conjunction, an article, a preposition that is no
#: particle or state: not "on", "in", "off", "to", "so": "if: the kettle is still on"), then a
#: line that opens in lower case: verse or a wrapped field ("hold novels, essays, and / all other
#: books"), one sentence running on. A line ending on any other word may end its message (a chat's
#: lines, a YAML file's keys): it stays a line
RUN_ON_WORDS = frozenset({"and", "or", "but", "nor", "the", "a", "an", "of", "with", "from", "into", "onto",
                          "my", "your", "our", "their", "its"})
_RUN_ON_LINE = re.compile(r"(?im)\b(" + "|".join(sorted(RUN_ON_WORDS)) + r")[ \t]*\n[ \t]*(?=[a-z])")


#: the marks a line of verse or of wrapped prose ends its line with when the line ends its clause
_LINE_END_MARKS = tuple(".,;:!?)-\u2013\u2014")
#: a line with no mark at its end, or with a mark inside a sentence (a comma, a semicolon, a colon:
#: "the alarm clock on the nightstand - but, if it ring, / first silence it"; "put each thing where
#: it should go: / a book on its level; / the phone on the desk"), then a line that opens in lower
#: case (`_punctuated_lines`)
_UNMARKED_BREAK = re.compile(r"(?m)(?<=[a-z,;:])[ \t]*\n[ \t]*(?=[a-z])")


def _punctuated_lines(text: str) -> bool:
    """Whether the text marks the end of its lines' clauses: of its lines of three words or more,
    at least two in three end on a mark (`_LINE_END_MARKS`), as verse and wrapped prose do; a
    chat's or a list's lines, most of them unmarked, each end a message or an item."""
    lines = [line.strip() for line in text.splitlines() if len(line.split()) >= 3]
    return len(lines) >= 4 and 3 * sum(line.endswith(_LINE_END_MARKS) for line in lines) >= 2 * len(lines)


def _runs_on(text: str) -> str:
    """The text with a line that runs on into the next (`_RUN_ON_LINE`) joined to it: a line break
    there ends no sentence; in a text that marks its lines' ends (`_punctuated_lines`: "My bedroom
    has a bed, where there may lie / a book, an alarm clock, or else a phone;") an unmarked line
    before one in lower case runs on too, and so does a line ending on a comma, a semicolon or a
    colon: such a text opens its sentences in capitals, so a line in lower case goes on with the
    sentence before it (a list after "put each thing where it goes:" stays that instruction's, its
    items no statements of where things are)."""
    joined = _RUN_ON_LINE.sub(r"\1 ", text)
    return _UNMARKED_BREAK.sub(" ", joined) if _punctuated_lines(joined) else joined


def _spoken_mark(m: re.Match[str]) -> str:
    """The spoken mark a `_DICTATED_MARK` match says, as `DICTATED_MARKS` keys it ("Full  stop")."""
    return " ".join(m.group(1).lower().split())


def _dictated(text: str) -> str:
    """A dictated text's spoken marks as the marks they stand for ("the can is on the bench full
    stop if it's empty fill it" is "the can is on the bench. If it's empty fill it"), when it
    speaks at least two kinds of them, three times or more: "put a comma after the date" or
    "the period after lunch" alone is the text's own word."""
    spoken = [_spoken_mark(m) for m in _DICTATED_MARK.finditer(text)]
    if len(set(spoken)) < 2 or len(spoken) < 3:
        return text
    out = _DICTATED_MARK.sub(lambda m: DICTATED_MARKS[_spoken_mark(m)] + " ", text)
    out = re.sub(r"([.?!;:,])(?:\s*[.,;:])+", r"\1", out)  # "... new paragraph" after a full stop: one mark
    out = re.sub(r"\n[ \t]+", "\n", out)
    return re.sub(r"([.?!]\s+)([a-z])", lambda m: m.group(1) + m.group(2).upper(), out).strip()


#: "No roll by the toilet then take a spare", "no bag in the bin then fetch one": a sentence that
#: opens with "no" and a noun phrase, then "then" and an instruction, asks whether there is one
#: (as "No roll by the toilet? Then take a spare" does)
_NO_THEN = re.compile(r"(^|[.!?;:]\s+|\n\s*)(no\s+[a-z]+(?:\s+[a-z]+){0,5}?)\s+then\s+(?=[a-z])", re.I)


#: "Is the mug on the coffee table dirty, then bring it to the sink", "Are the lights still on,
#: then switch them off": a yes/no question whose answer opens the instruction after "then" (the
#: conditional of a verb-first clause, as in Dutch and German, "Is er geen pan, dan ..."; older
#: English "Is it raining, then take a coat") is the question "Is the mug ... dirty? Then ...", as
#: `_NO_THEN` reads "No roll by the toilet then ...". Only a clause that opens its sentence (or
#: follows a colon or semicolon) with a finite "be" and a subject, a comma before "then", and a
#: word after it: "Is the mug dirty, then?" asks, and "is the mug dirty" in a clause stays
_BE_THEN = re.compile(r"(^|[.!?;:]\s+|\n\s*)((?:is|are|was|were)\s+(?:the|a|an|there|your|my|our|his|her|their|its|it|they)"
                      r"\b[^.!?;:,\n]{1,80}?)\s*,\s*then\s+(?=[a-z])", re.I)


#: "connected" / "disconnected" for a machine's on and off, the calque of the Portuguese
#: "ligado/desligado" and the Spanish "conectado/desconectado" ("if the air conditioner is
#: connected, please disconnect it", "if is still connected, disconnect"): as a state after a
#: copula, "still", "already", "stays" or "remains", and as the verb before its pronoun, when no
#: "to", "from", "with", "by", "into" or "up" says what it is linked to ("if the printer is
#: connected to the laptop" is a link, and stays)
_CONNECTED = re.compile(r"\b(?P<before>(?:is|are|was|were|be|still|already|stays|remains)\s+)(?P<dis>dis)?connected\b"
                        r"(?!\s+(?:to|from|with|by|into|up)\b)", re.I)
_CONNECT_IT = re.compile(r"\b(?P<dis>dis)?connect\s+(?P<obj>it|them)\b(?!\s+(?:to|from|with|into|up)\b)", re.I)


def connected_as_on(text: str) -> str:
    """The text with `_CONNECTED` states said "on"/"off" and `_CONNECT_IT` verbs "switch ... on/off"."""
    text = _CONNECTED.sub(lambda m: m.group("before") + ("off" if m.group("dis") else "on"), text)
    return _CONNECT_IT.sub(lambda m: f"switch {m.group('obj')} {'off' if m.group('dis') else 'on'}", text)


#: a word of that thing: no state word or adverb ("when in the kitchen is the kettle still on," asks
#: a state of the kettle, no existential)
_THING_WORD = rf"(?!(?:{'|'.join(sorted(STATE_WORDS))}|still|already|not|again)\b)[a-z]+"
#: a condition that puts the place before an existential, the order of Chinese, Russian, Polish,
#: Hungarian, Turkish and Korean ("If on the desk there is a mug,", "when on the sofa is a
#: blanket,", "if on the table got a mug,", "if on the floor have towels,"; English allows the
#: first two too): read "if there is a mug on the desk," so that the place is no state of the thing
#: ("on" after "if") and the thing is asked there; only up to the condition's comma, with a thing
#: of one to three words after its determiner or none (`_THING_WORD`)
_PLACE_FIRST_EXISTENTIAL = re.compile(
    r"(?P<lead>\b(?:if|when|whenever|unless|in case)\s+)(?P<place>(?:on|in|inside|under|by|near|beside|behind)\s+"
    r"(?:the|my|your|our|his|her|their)\s+(?:(?!(?:there|is|are|has|have|got)\b)[a-z]+\s+){1,2})"
    r"(?P<verb>there\s+is|there\s+are|there's|is|are|has|have|got)\s+"
    rf"(?P<thing>(?:(?:a|an|some|any|the)\s+)?{_THING_WORD}(?:\s+{_THING_WORD}){{0,2}}?)(?P<end>\s*,)", re.I)


def _place_first_existential(m: re.Match[str]) -> str:
    """The `_PLACE_FIRST_EXISTENTIAL` condition as "there is/are <thing> <place>"."""
    plural = m.group("verb").lower() in ("are", "have", "there are") or m.group("thing").lower().startswith("some ")
    return f"{m.group('lead')}there {'are' if plural else 'is'} {m.group('thing')} {m.group('place').strip()}{m.group('end')}"


#: a yes/no question that puts its subject after its predicate, the order of the asker's own
#: language (Greek, Spanish, Italian, Portuguese, Romanian, Arabic: "Is on the floor again the
#: board game?", "Is still open the laptop?", "Are dirty the cups?"): a copula opening its
#: sentence, then a place or a state word, then the subject with its determiner before the
#: question mark; read in English order ("Is the board game on the floor again?")
_SUBJECT_LAST = re.compile(r"(?P<lead>^|[.!?;:]\s+|\n\s*)(?P<be>is|are|was|were)\s+(?P<rest>[a-z][a-z' ]{2,80}?)\s*\?",
                           re.I | re.M)
#: the same order in a condition ("If is open the laptop, close it", "in case are on the floor the
#: towels, ...") or a doubt ("Maybe is still on the lamp."), up to its comma or full stop
_SUBJECT_LAST_IF = re.compile(r"(?P<lead>\b(?:if|when|unless|in case|maybe|perhaps)\s+)(?P<be>is|are|was|were)\s+"
                              r"(?P<rest>[a-z][a-z' ]{2,80}?)(?P<end>\s*[,.])", re.I)
#: adverbs that may stand on either side of the fronted predicate
_SUBJECT_LAST_ADVERBS = frozenset({"still", "again", "already", "now", "maybe", "perhaps", "really", "also"})
#: what a postposed subject opens with, and the determiner of a fronted place
_SUBJECT_LAST_DETERMINERS = frozenset({"the", "my", "your", "our", "his", "her", "their", "this", "that", "these",
                                       "those", "a", "an"})
_SUBJECT_LAST_PLACES = frozenset({"on", "in", "inside", "under", "by", "near", "behind", "beside", "onto", "into"})


def _subject_last(m: re.Match[str]) -> str:
    """The `_SUBJECT_LAST` question in English order, when its words after the copula are
    adverbs, a place (a preposition, a determiner and one or two nouns) or a state word
    (`STATE_WORDS`), adverbs, and a subject with its determiner; any other question ("Is the lamp
    on?", "Is there a mug?", "Is on the floor?") stays as it is."""
    words = m.group("rest").split()
    order = _subject_last_order(words, place=True) or _subject_last_order(words, place=False)
    return m.group(0) if order is None else f"{m.group('lead')}{m.group('be')} {order[0]} {order[1]}?"


def _subject_last_if(m: re.Match[str]) -> str:
    """The `_SUBJECT_LAST_IF` condition in English order ("if the laptop is open,"), as
    `_subject_last` reads the question; a condition with no subject after its predicate ("if is
    on, close it") stays as it is."""
    words = m.group("rest").split()
    order = _subject_last_order(words, place=True) or _subject_last_order(words, place=False)
    return m.group(0) if order is None else f"{m.group('lead')}{order[0]} {m.group('be')} {order[1]}{m.group('end')}"


def _subject_last_order(words: list[str], place: bool) -> tuple[str, str] | None:
    """`_subject_last` with the predicate read as a place (`place`) or as a state word: "on" is
    either ("Is on the desk my mug?", "Is still on the lamp?"). None when the words do not fit."""
    i = 0
    while i < len(words) and words[i].lower() in _SUBJECT_LAST_ADVERBS:
        i += 1
    start = i
    if not place and i < len(words) and words[i].lower() in STATE_WORDS and (
            words[i].lower() not in _SUBJECT_LAST_PLACES or {w.lower() for w in words[:i]} & {"still", "already"}):
        i += 1  # ("on" as a state only after "still"/"already": "Is on the floor?" asks of no floor)
    elif place and i + 2 < len(words) and words[i].lower() in _SUBJECT_LAST_PLACES \
            and words[i + 1].lower() in _SUBJECT_LAST_DETERMINERS:
        i += 3
        if i < len(words) and words[i].lower() not in _SUBJECT_LAST_ADVERBS | _SUBJECT_LAST_DETERMINERS \
                | _SUBJECT_LAST_PLACES:
            i += 1  # a place of two words ("on the coffee table")
    else:
        return None
    predicate = words[start:i]
    while i < len(words) and words[i].lower() in _SUBJECT_LAST_ADVERBS:
        i += 1
    subject = words[i:]
    if not 2 <= len(subject) <= 4 or subject[0].lower() not in _SUBJECT_LAST_DETERMINERS \
            or set(w.lower() for w in subject) & (_SUBJECT_LAST_PLACES | set(STATE_WORDS)):
        return None
    adverbs = [w for w in words[:i] if w.lower() in _SUBJECT_LAST_ADVERBS and w not in predicate]
    # (a state after its adverbs, "is the laptop still open"; a place before them, "... on the floor again")
    said = adverbs + predicate if len(predicate) == 1 else predicate + adverbs
    return " ".join(subject), " ".join(said)


def _no_then(m: re.Match[str]) -> str:
    words = m.group(2).lower().split()
    if set(words[1:]) & (ACTIONS | {"is", "are", "was", "were", "need", "needs", "one", "way", "matter"}):
        return m.group(0)  # "No need to ... then", "no matter then": no noun phrase
    return f"{m.group(1)}{m.group(2)}? {_match_case(m.group(0)[len(m.group(1)):], 'then')} "


def _match_case(said: str, word: str) -> str:
    """`word` with the first letter's case of `said` (a sentence's opening word stays capitalised)."""
    return word.capitalize() if said[:1].isupper() else word


#: a chat or log line's time stamp ("[08:02] Dana: ...", "[9:15 pm]", "14:02 Sam: ..."): when, not
#: what, so the line reads from its speaker on
_TIME_STAMP = re.compile(r"^([ \t]*)(?:\[\d{1,2}[:.]\d{2}(?:[:.]\d{2})?(?:\s*[ap]\.?m\.?)?\]|\d{1,2}:\d{2}(?=\s+[A-Z][\w.' ]{0,30}:))[ \t]*",
                         re.M | re.I)
#: a chat line (after its time stamp and speaker) that corrects the line before, as chat writers
#: do: a star right before a word ("*sink not dishwasher, dishwasher's broken", "*the fridge door")
_STARRED = re.compile(r"^(?P<lead>\s*(?:\[[^\]\n]*\]\s*)?(?:[A-Z][\w.' ]{0,30}:\s*)?)\*(?=\w)(?P<fix>[^\n]*)$", re.M)
#: "X not Y": the word meant, then the word it replaces, and the reason after a comma
_INSTEAD = re.compile(r"^(?P<meant>[^,;]+?)\s+not\s+(?P<wrong>[^,;]+?)\s*(?:[,;]\s*(?P<why>.*))?$", re.I)


def starred(text: str) -> str:
    """Each chat correction made in the line before it and dropped: "*sink not dishwasher" puts
    "sink" for the last "dishwasher" there (its reason after a comma stays, as a line of its own);
    "*the fridge door" puts the correction for the longest run of its first words the line before
    says ("the fridge" -> "the fridge door"). A correction that matches nothing stays as it is."""
    lines: list[str | None] = list(text.split("\n"))
    for n in range(1, len(lines)):
        m = _STARRED.match(lines[n] or "")
        if m is None:
            continue
        prev = next((k for k in range(n - 1, -1, -1) if (lines[k] or "").strip()), None)
        if prev is None:
            continue
        before = str(lines[prev])
        fix = m.group("fix").strip().rstrip(".!")
        instead = _INSTEAD.match(fix)
        if instead is not None:
            wrong = re.escape(instead.group("wrong"))
            found = list(re.finditer(rf"\b{wrong}\b", before, re.I))
            if not found:
                continue
            at = found[-1]
            lines[prev] = before[:at.start()] + instead.group("meant") + before[at.end():]
            why = instead.group("why")
            lines[n] = f"{m.group('lead')}{why}." if why else None
            continue
        words = fix.split()
        for k in range(len(words) - 1, 0, -1):
            said = re.search(rf"\b{re.escape(' '.join(words[:k]))}\b", before, re.I)
            if said is not None and any(w.lower() not in ("the", "a", "an", "my", "your", "that") for w in words[:k]):
                lines[prev] = before[:said.start()] + fix + before[said.end():]
                lines[n] = None
                break
    return "\n".join(line for line in lines if line is not None)


#: Scots spellings of English words that English spells otherwise and uses in no other sense
#: (Dictionary of the Scots Language, dsl.ac.uk: "oot" out, "doon" down, "aboot" about, "efter"
#: after, "hoose" house, "yin" one): in a text with two of them or more, each reads as its English
#: word ("the drawer might be pulled oot already" is pulled out, open; "shut it doon" shut down)
SCOTS = {"oot": "out", "doon": "down", "aboot": "about", "efter": "after", "hoose": "house", "yin": "one"}
_SCOTS = re.compile(rf"\b(?:{'|'.join(SCOTS)})\b", re.I)


def _scots(text: str) -> str:
    """`text` with its Scots spellings (`SCOTS`) as English, when it has two of them or more."""
    if len({m.group(0).lower() for m in _SCOTS.finditer(text)}) < 2:
        return text
    return _SCOTS.sub(lambda m: _match_case(m.group(0), SCOTS[m.group(0).lower()]), text)


#: English's closed-class words (articles, pronouns, prepositions, conjunctions, auxiliaries),
#: which lemminflect, a lexicon of open-class words, does not list: with it, what tells an
#: English word from a word of another language in a code-switched text (`foreign`)
ENGLISH_CLOSED = frozenset({
    "a", "an", "the", "this", "that", "these", "those", "my", "your", "his", "her", "its", "our", "their",
    "i", "you", "he", "she", "it", "we", "they", "me", "him", "us", "them", "if", "of", "and", "or", "but",
    "nor", "so", "then", "than", "as", "at", "by", "for", "from", "in", "into", "on", "onto", "to", "with",
    "without", "under", "over", "up", "down", "off", "out", "not", "no", "yes", "when", "while", "until",
    "unless", "whether", "because", "is", "am", "are", "was", "were", "be", "been", "being", "do", "does",
    "did", "has", "have", "had", "will", "would", "shall", "should", "can", "could", "may", "might", "must",
    "ok", "okay", "pls", "please", "s", "t", "re", "ll", "ve", "d", "m",
    # words of place, quantity and reference lemminflect does not list
    "here", "there", "inside", "atop", "upon", "what", "where", "which", "who", "whose", "one", "two",
    "three", "four", "both", "some", "another", "someone", "somebody", "everyone", "nobody", "kids",
    "children",
})


def foreign(word: str) -> bool:
    """Whether a lower-case word is of no English: neither a closed-class word (`ENGLISH_CLOSED`)
    nor a form lemminflect lists ("abhi", "naka", "deh" are foreign; "on", "floor", "dirty" are
    not). Only words of two letters or more count: a number, a name or a letter of an
    abbreviation ("o/e", on examination) is neither."""
    return len(word) > 1 and word.isalpha() and word.islower() and word not in ENGLISH_CLOSED \
        and not getAllLemmas(word)


def code_switched(words: list[str]) -> bool:
    """Whether a clause's words are of another language in good part: a third of them or more
    `foreign` ("abhi bhi on hai", "naka on pa", "it deh pon di floor"), not the odd word
    lemminflect does not list in an English clause ("shut the fridge and turn on the stove")."""
    return 3 * sum(foreign(w) for w in words) >= len(words) > 0 and any(foreign(w) for w in words)


#: The conditional conjunctions of languages English is often mixed with in writing, each with
#: the word that may answer it as "then" ("" when it has none): Hindi-Urdu "agar ... toh"
#: ("Agar abhi bhi on hai toh band kar dena"), Spanish and French "si" ("si no, you open it",
#: "si no está maduro todavía"; "entonces", "alors"), Tagalog "kung" and "kapag", German "wenn ...
#: dann", Malay and Indonesian "kalau" and "jika" ("maka"). A word English also has ("se", "als",
#: "falls", "pag") is left out; "agar", an English noun too, opens a condition only in a clause
#: in good part of another language (`_native_if`, `code_switched`). The conjunction opens its
#: clause after a sentence's or a clause's mark, a dash too ("Die Stehlampe, the floor lamp -
#: wenn sie noch an ist, ...": the English gloss, then the condition).
NATIVE_IF = {"agar": ("toh",), "si": ("entonces", "alors"), "kung": (), "kapag": (), "wenn": ("dann",),
             "kalau": ("maka",), "jika": ("maka",)}
_NATIVE_THEN = frozenset(w for thens in NATIVE_IF.values() for w in thens)
_NATIVE_IF = re.compile(rf"(?:^|(?<=[.!?,;:(\n])|(?<=[.!?,;:(\-\u2013\u2014]\s))[ \t]*({'|'.join(NATIVE_IF)})\b"
                        r"(?P<rest>[^.!?\n]*)",
                        re.I | re.M)
_THEN_WORD = re.compile(rf"\s*,?\s+\b({'|'.join(sorted(_NATIVE_THEN))})\b", re.I)


def _native_if(m: re.Match[str]) -> str:
    """A clause opened by another language's conditional conjunction (`NATIVE_IF`) as one opened
    by "if", its "then" word as ", then"; kept as written when the conjunction is an English word
    too and the rest of its sentence is not in good part of another language (`code_switched`:
    "Agar plates go in the fridge")."""
    cue, rest = m.group(1), m.group("rest")
    if not foreign(cue.lower()) and not code_switched(re.findall(r"[A-Za-z]+", rest)):
        return m.group(0)
    rest = _THEN_WORD.sub(", then", rest, count=1)
    # "si no, you open it", "si no está maduro": the conjunction's "no" is "if not", English's
    # "if no" asking a thing's absence only before a noun of its own
    rest = re.sub(r"^(\s+)no\b(?=\s*,|\s+(\w+))", lambda n: n.group(1) + (
        "not" if n.group(2) is None or foreign(n.group(2)) else "no"), rest)
    lead = m.group(0)[: m.start(1) - m.start(0)]
    return f"{lead}{'If' if cue[0].isupper() else 'if'}{rest}"


#: Early Modern English's third person ("the plant needeth water", "a novel goeth onto the
#: shelf", "a lamp doth sit", "it hath fallen"): "-eth" on a verb's stem for "-s", and its two
#: irregular forms; a word is so read only when what is left is a verb lemminflect knows
#: ("goeth": go; "maketh": make; "sitteth": sit) and the word is none of today's English, so
#: "teeth" and "beneath" stay
ARCHAIC_VERBS = {"doth": "does", "hath": "has"}
_ETH = re.compile(r"\b([A-Za-z]{2,})eth\b")


def _archaic(m: re.Match[str]) -> str:
    """An "-eth" verb as its present third person (`ARCHAIC_VERBS`, `_ETH`)."""
    stem = m.group(1).lower()
    if getAllLemmas(m.group(0).lower()):
        return m.group(0)  # a word of today's English ("teeth")
    for base in (stem, stem + "e", stem[:-1] if len(stem) > 2 and stem[-1] == stem[-2] else ""):
        if base and "VERB" in getAllLemmas(base) and (third := getInflection(base, "VBZ")):
            return _match_case(m.group(0), third[0])
    return m.group(0)


#: the legal register's anaphoric determiner ("a jacket draped over said stool", "closing said box",
#: "the aforesaid lamp"): "said" or "aforesaid" as a determiner is "the". Only where no verb "said"
#: can stand: after a preposition, a verb's -ing form, a comma or a sentence's start, and before a
#: bare word ("Mum said the mug ...", "as I said, the mug", "having said that" keep theirs)
_LEGAL_SAID = re.compile(r"(^[ \t]*|[.;:,(]\s+|\b(?:on|in|over|of|to|into|onto|from|under|by|with|inside|upon|at|"
                         r"for)\s+|\b[a-z]+ing\s+)((?:afore)?said)\s+(?!(?:the|a|an|that|this|it|so|to|yes|no|"
                         r"nothing|something|hello|goodbye|and|or|he|she|they|we|you|i)\b)(?-i:(?=[a-z]))", re.I | re.M)


def _modern(text: str) -> str:
    """`text` with its Early Modern English verb forms as today's (`ARCHAIC_VERBS`, `_ETH`), and the
    legal register's determiner "said" as "the" (`_LEGAL_SAID`)."""
    text = _LEGAL_SAID.sub(lambda m: m.group(1) + _match_case(m.group(2), "the "), text)
    text = re.sub(rf"\b(?:{'|'.join(ARCHAIC_VERBS)})\b", lambda m: _match_case(
        m.group(0), ARCHAIC_VERBS[m.group(0).lower()]), text, flags=re.I)
    return _ETH.sub(_archaic, text)


#: function words that the English-lexified creoles of the Caribbean spell apart from English
#: (Jamaican Patois and its neighbours: Cassidy & Le Page, Dictionary of Jamaican English; "di" the,
#: "pon" upon, "inna" in, "wid" with) and their locative copula "deh" / "dey" (is, before a place):
#: in a text with two of them or more, each reads as its English word ("Mi handbag deh pon di
#: chair" is "Mi handbag is on the chair"); "deh" not before a place is "there" ("lef it right deh")
CREOLE = {"di": "the", "pon": "on", "inna": "in", "wid": "with"}
_CREOLE = re.compile(rf"\b(?:{'|'.join(CREOLE)}|deh|dey)\b", re.I)
#: the locative copula before its place ("deh pon di chair", "dey inna di box")
_CREOLE_BE = re.compile(rf"\b(deh|dey)(?=\s+(?:{'|'.join(CREOLE)}|on|in|under)\b)", re.I)


def _creole(text: str) -> str:
    """`text` with a Caribbean creole's function words (`CREOLE`) as English, when it has two
    different ones or more."""
    if len({m.group(0).lower() for m in _CREOLE.finditer(text)}) < 2:
        return text
    text = _CREOLE_BE.sub(lambda m: _match_case(m.group(0), "is"), text)
    text = re.sub(r"\b(?:deh|dey)\b", lambda m: _match_case(m.group(0), "there"), text, flags=re.I)
    return re.sub(rf"\b(?:{'|'.join(CREOLE)})\b", lambda m: _match_case(m.group(0), CREOLE[m.group(0).lower()]),
                  text, flags=re.I)


#: a question's or an answer's label in a question-and-answer layout: a catechism's "Q. 5." and
#: "A.", an FAQ's "Q:" / "A:", a quiz's "Question 3:" / "Answer:" (a label needs its mark or its
#: number, so that "A mug ..." is no answer)
_QA_LABEL = re.compile(r"^[ \t]*(?P<kind>q|question|a|answer)[ \t]*(?:[.:)\-][ \t]*(?:\d{1,3}[ \t]*[.:)]?[ \t]*)?"
                       r"|\d{1,3}[ \t]*[.:)\-][ \t]*)", re.I)
#: a question that states a case and asks what to do in it: "What must you do if X?", "And if
#: X?", "But what if X?", "What should the robot do when X?" (not "Do you know if X?": an
#: indirect question asks no case)
_CASE_QUESTION = re.compile(r"^(?P<follow>(?:and|but|or|so|now)\b[ \t,]*)?(?:(?P<what>what|how)\b[^?]*?\b)?"
                            r"(?:if|when|in case)\s+(?P<case>[^?]+?)\s*\?\s*$", re.I)
#: a condition an answer asks of its own ("If the mop is standing on the floor, ...")
_OWN_CASE = re.compile(r"\b(?:if|when|unless)\s+(?P<case>[^,;:.]+)", re.I)
#: the words two conditions may share without speaking of the same thing
_CASE_FUNCTION_WORDS = frozenset({"the", "a", "an", "it", "its", "is", "are", "not", "there", "this", "that", "they",
                                  "them", "was", "were", "be", "been", "still", "any", "some", "one", "no"})
_THEN = re.compile(r"^then\b[ \t,]*", re.I)


def _case_words(case: str) -> set[str]:
    return {w for w in re.findall(r"[a-z]+", case.lower()) if w not in _CASE_FUNCTION_WORDS}


def answered_questions(text: str) -> str:
    """A question-and-answer layout (a catechism, an FAQ, a quiz sheet) whose question states a
    case ("Q. What must you do if there is a mug on the desk?" / "A. If it is dirty, I take it to
    the sink.") as the conditional it stands for, the question's case framing its answer: "If
    there is a mug on the desk: If it is dirty, I take it to the sink." A reader asks the answer's
    own conditions under the question's case; read apart, the question is no instruction and the
    answer's conditions would be asked in a subtask of their own. A follow-up question on the
    answer's own condition ("But what if it is not dirty?" / "A. Then I put it away") is that
    condition's other branch in the same frame: it is joined to the answer before ("...; if it is
    not dirty, then I put it away"). A question that states no case, an answer with no question
    before it and every other line stay as they are."""
    lines = text.split("\n")
    out: list[str] = []
    last: int | None = None  # the index in `out` of the last answer read, and its own case
    last_case = ""
    i = 0
    while i < len(lines):
        q = _QA_LABEL.match(lines[i])
        if q is None or q.group("kind").lower() not in ("q", "question"):
            out.append(lines[i])
            i += 1
            continue
        j = i + 1
        while j < len(lines) and not lines[j].strip():
            j += 1
        a = _QA_LABEL.match(lines[j]) if j < len(lines) else None
        case = _CASE_QUESTION.match(lines[i][q.end():].strip())
        if a is None or a.group("kind").lower() not in ("a", "answer") or case is None:
            out.append(lines[i])
            last = None
            i += 1
            continue
        answer = lines[j][a.end():].strip()
        said = case.group("case").strip()
        own = _OWN_CASE.search(answer)
        if (last is not None and (case.group("follow") or case.group("what"))
                and _case_words(said) & _case_words(last_case)):
            # the other branch of the answer before's own condition: joined to that answer
            out[last] = f"{out[last].rstrip().rstrip('.')}; if {said}, {_THEN.sub('then ', answer)}"
            last = None
        else:
            out.append(f"If {said}: {_THEN.sub('', answer)}")
            last, last_case = (len(out) - 1, own.group("case")) if own is not None else (None, "")
        i = j + 1
    return "\n".join(out)


#: an answer key ("ANSWER KEY: 1 b, 2 a, 3 c", "Answers: 1-c; 2-a", "Key: 1) b 2) d"): a question's
#: number and the letter of its right option, at least two of them on one line
_KEY_LINE = re.compile(r"^[ \t]*(?:the[ \t]+)?(?:answer[ \t]+key|answers|key|solutions?)[ \t]*[:\-][ \t]*(?P<pairs>.+)$",
                       re.I | re.M)
_KEY_PAIR = re.compile(r"\b(?P<n>\d{1,2})[ \t]*[.:)=\-]?[ \t]*(?P<letter>[a-e])\b", re.I)
#: a quiz's numbered question ("Q1.", "Question 3:", "2)") opening its line
_QUIZ_QUESTION = re.compile(r"^[ \t]*(?:q(?:uestion)?[ \t]*)?(?P<n>\d{1,2})[ \t]*[.:)][ \t]+(?P<body>\S.*)$", re.I)
#: a lettered option ("a) Put it ...", "(b) Leave it", "c. Fold it ..."), several to a line
_QUIZ_OPTION = re.compile(r"(?:^|(?<=\s))\(?(?P<letter>[a-e])[).][ \t]+(?P<said>.+?)(?=\s+\(?[a-e][).][ \t]|\s*$)", re.I)
#: the question a scenario ends with, asking what to do in it ("What do you do with it?", "What
#: should you do?", "How do you handle this?")
_WHAT_TO_DO = re.compile(r"\s*\b(?:what|how)\b[^.?!]*\?\s*$", re.I)


def keyed_answers(text: str) -> str:
    """A quiz whose answer key is given apart (the eighteenth session: dev 14 laundry_sorting_d14's
    "Q1. There's a dirty white shirt on the floor. What do you do with it? a) ... b) ..." and
    "ANSWER KEY: 1 b, 2 a, ..." at the bottom): each numbered question that states a case and asks
    what to do, with lettered options, becomes "If <case>, <the keyed option>." and the key line
    goes, so the case is read as the condition of the action the key names. Training quizzes,
    safety drills and onboarding tests write rules so. A quiz without a key, or a question whose
    number the key does not give, is left as it is (which option is right is not said)."""
    keys = list(_KEY_LINE.finditer(text))
    key = {int(p.group("n")): p.group("letter").lower() for k in keys for p in _KEY_PAIR.finditer(k.group("pairs"))}
    if len(key) < 2:
        return text
    lines = text.split("\n")
    out: list[str] = []
    i = 0
    while i < len(lines):
        q = _QUIZ_QUESTION.match(lines[i])
        if q is None or int(q.group("n")) not in key:
            out.append(lines[i])
            i += 1
            continue
        # the question's own lines: up to the next question, the key or a blank line
        j = i + 1
        while j < len(lines) and lines[j].strip() and not _QUIZ_QUESTION.match(lines[j]) \
                and not _KEY_LINE.match(lines[j]):
            j += 1
        block = " ".join([q.group("body"), *(ln.strip() for ln in lines[i + 1:j])])
        first = re.search(r"(?:^|\s)\(?[a-e][).][ \t]", block, re.I)
        options = {o.group("letter").lower(): o.group("said").strip() for o in
                   _QUIZ_OPTION.finditer(block[first.start():] if first else "")}
        case = _WHAT_TO_DO.sub("", block[:first.start()] if first else "").strip().rstrip(".")
        chosen = options.get(key[int(q.group("n"))])
        if not chosen or not case or case == block.strip():
            out.extend(lines[i:j])
        else:
            out.append(f"{q.group('n')}. If {case[:1].lower() + case[1:]}, {chosen[:1].lower() + chosen[1:]}")
        i = j
    return "\n".join(line for line in out if not _KEY_LINE.match(line) or len(list(_KEY_PAIR.finditer(line))) < 2)


#: a capital letter that names the thing before it, the way a proof, a puzzle or a specification
#: names its objects ("a floor lamp L, a coffee table T and a cup C", "the storage box B;"): an
#: article and up to four words in small letters (no article among them), then a capital letter standing alone before a
#: mark, "and" or the line's end. "A" and "I" are words, never such names; a letter with a word
#: after it is part of a name or a size ("a size M towel", "Plan B") and names nothing
_LETTER_ALIAS = re.compile(r"\b(?P<det>[Aa]n?|[Tt]he)\s+(?P<np>(?!(?:an?|the)\b)[a-z][a-z-]*"
                           r"(?:\s+(?!(?:an?|the)\b)[a-z][a-z-]*){0,3}?)"
                           r"\s+(?P<letter>[B-HJ-Z])(?=\s*(?:[,;:.)]|\band\b|$))", re.M)
#: the letter's later uses: standing alone, not an initial inside a name ("F. Okoye") nor part of
#: a word or a code ("3B", "D-day")
_LETTER_USE = r"(?<![\w.'\u2019/-]){}(?![\w'\u2019/-]|\.\w)"


#: a letter defined by a sentence of its own, the way a proof or a puzzle does ("Let D denote the
#: drawing room.", "Let C be the cup on the desk", "Write B for the book", "... a towel on the
#: floor - call it T"): the letter, then the thing it names (an article and up to four words in
#: small letters), or the thing (and up to five words of where it is), then "call it" and the
#: letter
_LETTER_DEFINED = re.compile(
    r"\b(?:[Ll]et\s+(?P<letter>[B-HJ-Z])\s+(?:denote|be|stand\s+for|mean|name)|[Ww]rite\s+(?P<letter2>[B-HJ-Z])\s+for)"
    r"\s+(?P<det>an?|the)\s+(?P<np>(?!(?:an?|the)\b)[a-z][a-z-]*(?:\s+(?!(?:an?|the|on|in|by|at)\b)[a-z][a-z-]*){0,3}?)"
    r"(?=\s*(?:[,;:.)]|\s(?:on|in|by|at|under|inside)\s|\band\b|$))"
    r"|(?P<det3>\b[Aa]n?|\b[Tt]he)\s+(?P<np3>(?!(?:an?|the)\b)[a-z][a-z-]*(?:\s+(?!(?:an?|the)\b)[a-z][a-z-]*){0,3}?)"
    r"(?P<rest>(?:\s+[a-z][a-z'-]*){0,5}?)"
    r"\s*(?:[,;(]|\s-+|\s\u2013|\s\u2014)\s*(?:(?:we(?:'ll)?|I(?:'ll)?|let's)\s+)?call\s+it\s+(?P<letter3>[B-HJ-Z])\b\)?",
    re.M)


def _defined_letters(text: str) -> dict[str, str]:
    """The letters `text` defines by a sentence of their own (`_LETTER_DEFINED`): letter -> the
    words of the thing it names."""
    out: dict[str, str] = {}
    for m in _LETTER_DEFINED.finditer(text):
        letter = m.group("letter") or m.group("letter2") or m.group("letter3")
        name = m.group("np") or m.group("np3")
        out[letter] = name if out.get(letter, name) == name else ""
    return out


def _defined_as(m: re.Match[str]) -> str:
    """A letter's definition said as the thing it names: "Let C be the cup" -> "The cup",
    "a towel on the floor - call it T" -> "a towel on the floor"."""
    if m.group("letter3"):
        return f"{m.group('det3')} {m.group('np3')}{m.group('rest')}"
    return f"{m.group('det').capitalize()} {m.group('np')}"


def dealias(text: str) -> str:
    """A text that names its things by letters ("In D there are a floor lamp L and a magazine M.
    Suppose L is on. Then switch it off. Either M lies on the floor or it does not.") with each
    letter as the thing it names ("Suppose the floor lamp is on ... Either the magazine lies on
    the floor ..."): a reader takes "L" as the lamp for the rest of the text, as the apposition
    said. The letter is dropped where it is given (`_LETTER_ALIAS`); a letter given twice, for
    two things, is left alone, since which one a later use means is not known, and so is one
    never used again (it ends a name: "the end of row C")."""
    given: dict[str, str] = {}
    twice: set[str] = set()
    for m in _LETTER_ALIAS.finditer(text):
        letter, name = m.group("letter"), m.group("np")
        if given.get(letter, name) != name:
            twice.add(letter)
        given[letter] = name
    # (a letter used nowhere else is part of the name it ends, "at the end of row C", no alias)
    given = {k: v for k, v in given.items()
             if k not in twice and len(re.findall(_LETTER_USE.format(k), text)) > text.count(f"{v} {k}")}
    # a letter defined apart ("Let D denote the drawing room"), used after its definition; one
    # defined twice, or also given in apposition to another thing, is left alone
    defined = {k: v for k, v in _defined_letters(text).items()
               if v and given.get(k, v) == v and k not in twice and len(re.findall(_LETTER_USE.format(k), text)) > 1}
    if not given and not defined:
        return text
    text = _LETTER_ALIAS.sub(lambda m: m.group(0) if m.group("letter") not in given
                             else f"{m.group('det')} {m.group('np')}", text)
    # the definition says the thing is there, as a mention of it does: "the drawing room." (and
    # where it is, "the cup on the desk."); the letter's later uses are the thing
    text = _LETTER_DEFINED.sub(lambda m: m.group(0) if (m.group("letter") or m.group("letter2") or m.group("letter3"))
                               not in defined else _defined_as(m), text)
    given = {**defined, **given}
    for letter, name in given.items():
        text = re.sub(_LETTER_USE.format(letter), f"the {name}", text)
    return text


def unquote(text: str) -> str:
    """The text with British and older spellings of function words in their common form
    (`VARIANTS`) and British spellings of catalog words in the catalog's (`SPELLINGS`) and without a formula of politeness before a verb (`_POLITE`), with a typographic
    arrow as "->" (`_ARROWS`), an emoji between words as a
    sentence's end (`_EMOJI`), a comma before the next "state ->" case as ";"
    (`_CASE_AFTER_COMMA`), "the X on the Y, if there is one" as "if there is an X on the Y"
    (`_IF_ANY`), a condition put first whose pronoun points forward to a result not said yet after
    its main clause (`_FRONTED_ALREADY`), without an email's quoting marks (a forum quote's sentences in the first person dropped: `_FORUM_QUOTE`; a quoted statement a reply answers with "Then" as a question: `_QUOTED_PREMISE`): a reply above a quoted message reads as one
    text ("> On Monday, Jo wrote:" is no sentence; "> Could you tidy ..." is "Could you tidy ...");
    without the labels of lettered or numbered items (an item's closing semicolon a full stop:
    `_ITEM_END`); a place the speaker corrects dropped for the
    one meant ("in the wardrobe, no wait, in the hamper"); a bare state as a subject read as the
    condition it is ("dirty goes in the hamper": "if it is dirty, it goes ..."); an indirect
    question about an action as the state it leaves ("whether I shut the fridge door": "whether
    the fridge door is shut"), a note-taker's shorthand spelled out ("resp.", "&", `_SHORTHAND`), and a doubt about having got a thing as one about whether there is
    one ("not sure I even got bread": "there may or may not be bread"); a condition's elided
    subject spelled out
    ("if found on" -> "if it is found on"), and a dropped subject pronoun ("if is lighted" -> "if
    it is lighted": `_DROPPED_SUBJECT`), and a note's "May have fallen ..." after a topic as "It may
    have fallen ..." (`_DROPPED_DOUBT`); a telegram's "STOP" and "QUERY" as "." and "?"
    (`TELEGRAM_MARKS`); a dictated text's spoken marks as marks (`DICTATED_MARKS`); a line running on into the next as one
    line (`_runs_on`); "No X by the Y then ..." as the question "No X by the Y? Then ..."
    (`_NO_THEN`); a bare state and a comma before an instruction as its condition ("wet, stand
    it in the stand": `_STATE_CASE`); "other kind of toy" as "other toy" (`_KIND_OF`); a state word said only as a predicate in its state's
    common word ("the dishwasher's already going": "running", `PREDICATE_STATES`); a table of items and places as its sentences
    (`detable`); a rule written as a record of keyed lines as its conditional (`derecord`); a heading answered by a verb with no subject of its own with the heading as that
    subject (`_SUBJECTLESS`); a chat message's `*`-correction made in the message it corrects
    (`starred`), a verbless directive as its imperative ("Into the fridge with it": "Put it into the
    fridge", `_DIRECTIVE_WITH`, `_DIRECTIVE_AFTER_QUESTION`), a place "to be checked" as one that "may be" (`_TO_BE_CHECKED`), without a chat line's time stamp (`_TIME_STAMP`), without a reference work's
    citation marks (`_CITATION`), with a Markdown sub-heading as a heading before a colon
    (`_MARKDOWN_HEADING`); a supposition as "if" (`_SUPPOSED_IF`), a comment aside between
    commas dropped (`COMMENT_ASIDES`), an aside between dashes after a connective dropped
    (`DASHED_ASIDE_CONNECTIVES`), a whole question in quotes without them (`_QUOTED_WHOLE`), a
    thing gone said as "missing" (`ABSENCE_PREDICATES`), a predicate state's elided subject, a
    second predicate's shared subject and a note's dropped subject of doubt spelled out
    (`_ELIDED_PREDICATE`, `_SHARED_SUBJECT`, `_DROPPED_DOUBT`), and an inverted question's
    participle read as its state (`_QUESTION_PREDICATE`), and a learner's participle without its
    ending at a condition's end as the state ("if curtain still close": `_BARE_PARTICIPLE`); a
    question-and-answer layout's answer framed by the case its question states, first
    (`answered_questions`), and before it a quiz's keyed option framed so (`keyed_answers`), and
    before all a thing named by a letter as the thing (`dealias`); a learner's subject after its
    predicate in a question, condition or doubt in English order (`_SUBJECT_LAST`,
    `_SUBJECT_LAST_IF`), "connected" for on (`connected_as_on`) and a place put before an
    existential after it (`_PLACE_FIRST_EXISTENTIAL`); a proviso's cue as "provided that" or "as
    long as" (`_PROVISO`), a condition's putative "should" as its finite verb
    (`_PUTATIVE_SHOULD`) and a thing that "goes missing" as one that "is missing" (`_GOES_MISSING`);
    a noun phrase put first before a dash as its pronoun's subject (`_LEFT_DISLOCATED`), a case
    label's bracketed clause as its condition (`_CASE_CLAUSE`), a resting participle before
    "there" dropped (`_RESTING_THERE`) and "Still there?" as "Is it still there?"
    (`_STILL_THERE_QUESTION`), and a thing's contents that "mean" a step as the case they state
    (`_MEANS_THERE`), "One on the floor, you pick it up" as its case (`_ONE_CASE`). A subject's
    relative clause is dropped by `as_read`, not here."""
    text = _SALUTATION.sub(lambda m: f"{m.group('greeting')}\n{m.group('first').upper()}", _VERSE_LINE.sub(lambda m: _VERSE_SLASH.sub("\n", m.group(0)), text))
    text = _DASHED_ASIDE.sub(r"\g<cue> ", answered_questions(keyed_answers(dealias(text))))
    text = _SET_OFF_ALTERNATIVE.sub(_set_off_alternative, text)
    text = _SUPPOSED_IF.sub(_occasion_if, _OCCASION_IF.sub(_occasion_if, _COMMENT_ASIDE.sub(" ", _QUOTED_WHOLE.sub(r"\1", text))))
    text = _EXCEPTIVE.sub(lambda m: _match_case(m.group(0), "unless"), text)
    text = _PUTATIVE_SHOULD.sub(_putative_should, _PROVISO.sub(_proviso, text))
    text = _LEFT_DISLOCATED.sub(_left_dislocated, _GOES_MISSING.sub(_goes_missing, text))
    text = _FOUND_AND.sub(_found_and, _TOPIC_IF.sub(_topic_if, _INVERTED_WERE.sub(_inverted_were, text)))
    text = _SUBJECT_LAST_IF.sub(_subject_last_if, _SUBJECT_LAST.sub(_subject_last, connected_as_on(text)))
    text = _PLACE_FIRST_EXISTENTIAL.sub(_place_first_existential, text)
    text = _BE_THEN.sub(lambda m: f"{m.group(1)}{m.group(2)}? {_match_case(m.group(2), 'then')} ", text)
    text = _NO_THEN.sub(_no_then, _creole(_scots(_telegram(_dictated(_runs_on(_modern(_NATIVE_IF.sub(_native_if, text))))))))
    text = _TO_BE_CHECKED.sub(" may be ", _OTHER_THAN.sub(r"\1 else than", text))
    text = _EVENTUAL_AFTER.sub("may be", _EVENTUAL_BEFORE.sub(lambda m: _match_case(m.group(0), "perhaps"), text))
    text = _LISTED_OR_ELSE.sub(r"\g<items>or ", text)
    text = _VERBLESS_UNLESS_THERE.sub(_verbless_put, text)
    text = _VERBLESS_CASE.sub(_verbless_case, text)
    text = _ONE_APPOSITIVE.sub(r", \1,", _MODAL_DOUBT.sub(r"\1", text))
    text = _OPEN_DISJUNCTION.sub(_open_disjunction, text)
    text = _POLITE.sub("", _VARIANT.sub(lambda m: _match_case(m.group(0), _SPELLED[m.group(0).lower()]), text))
    text = starred(_TIME_STAMP.sub(r"\1", _CITATION.sub("", _MARKDOWN_HEADING.sub(r"\g<title>:", text))))
    plain = _CASE_AFTER_COMMA.sub("; ", _EMOJI.sub(_emoji, _ARROWS.sub(" -> ", text)))
    plain = _IF_ANY.sub(_if_any, plain)
    plain = _CASE_LABEL.sub(_case_label, _FRONTED_ALREADY.sub(_postposed, plain))
    plain = _CASE_CLAUSE.sub(r"\g<label>: if \g<clause>, ", plain)
    plain = _SELF_CORRECTION.sub("", _ITEM_LABEL.sub("", _ITEM_END.sub(".\n", _QUOTE_MARK.sub("", _QUOTED_PREMISE.sub(
        r"\g<q>?\g<gap>", _FORUM_QUOTE.sub(_forum_quote, _ATTRIBUTION.sub("", plain)))))))
    plain = _unabbreviated(plain)
    plain = _MEANS_CASE.sub(lambda m: f"{m.group(1)}{_match_case(m.group(2), 'if')} it is {m.group(2).lower()}, ",
                            plain)
    plain = _MEANS_THERE.sub(lambda m: f"{m.group(1)}{_match_case(m.group(2), 'if')} there is {m.group(2).lower()}, ",
                             plain)
    plain = _ELIDED_PREDICATE.sub(r"\1 it is ", _RESTING_THERE.sub(r"\1 ", plain))
    plain = _PREDICATE_STATE.sub(lambda m: m.group(1) + _predicate(m.group(2)), _SOUNDING.sub(_sounding, plain))
    plain = _QUESTION_PREDICATE.sub(lambda m: m.group(1) + _predicate(m.group(2)), plain)
    plain = _BARE_PARTICIPLE.sub(_participle_state, plain)
    plain = _EMPHATIC_DO.sub("", plain)
    plain = _ELIDED_NOT_STATE.sub(r"\1 it is ", plain)
    plain = _FRONTED_FINDING.sub(lambda m: f"{m.group(1)}{_match_case(m.group(2), 'if')} {m.group(2).lower()}", plain)
    plain = _ELIDED_END_STATE.sub(r"\1 it is ", _ELIDED_STATE.sub(r"\1 it is ", _ELIDED_SUBJECT.sub(r"\1 it is ", _ELIDED_PLACE.sub(r"\1 it is ", plain))))
    plain = _STILL_THERE_QUESTION.sub(_still_there, _ELIDED_PLACE_QUESTION.sub(_asked_place, plain))
    plain = _DROPPED_SUBJECT.sub(lambda m: f"{m.group(1)} {_DROPPED_PRONOUN[m.group(2).lower()]} ", plain)
    plain = _SHARED_SUBJECT.sub(_shared_pronoun, plain)
    plain = _DROPPED_DOUBT.sub(lambda m: f"{m.group(1)}{_match_case(m.group(2), 'it')} {m.group(2).lower()}", plain)
    plain = _CASE_WHERE.sub(lambda m: _match_case(m.group(0), "if"), _WHERE_HEADING.sub(r"\1", plain))
    for elided in (_DONE_ALREADY, _FORGOT):  # the deed elided: does its result hold already?
        plain = elided.sub(lambda m: _match_case(m.group(0), "unless it already is"), plain)
    plain = _ACTED_STATE.sub(_acted_state, plain)
    plain = _GOT_DOUBT.sub(lambda m: f"there may or may not be {m.group('thing')}", plain)
    plain = _KIND_OF.sub(r"\1 ", _STATE_CASE.sub(_state_case, plain))
    plain = _STATE_AND_CLAUSE.sub(lambda m: f"{m.group(1)}if it is {m.group(2).lower()} {m.group(3).lower()} {m.group(4)}, ",
                                  plain)
    plain = _NO_CASE.sub(lambda m: f"{m.group(1)}if there is no {m.group(2).strip()}, ", plain)
    plain = _ONE_CASE.sub(lambda m: f"{m.group(1)}{_match_case(m.group(2), 'if')} there is one {m.group(3)}, ", plain)
    plain = _ALREADY_CASE.sub(lambda m: f"{m.group(1)}if it is already {m.group(2).lower()}, ", plain)
    plain = _DIRECTIVE_AFTER_QUESTION.sub(_directive, _DIRECTIVE_WITH.sub(_directive, plain))
    return _SUBJECTLESS.sub(r"\1\2\3the \2 \4", detable(derecord(_STATE_SUBJECT.sub(_state_subject, plain))))


def as_read(text: str) -> str:
    """The description as the factor and placement readers read it: `unquote`'s text with a
    subject's relative clause dropped (`_CONTACT_RELATIVE`). The namer reads `unquote`'s own, where
    the clause may say what the thing is for ("the towel we wipe our hands with" is a hand towel,
    "the bowl the cat eats from" a pet bowl)."""
    return _CONTACT_RELATIVE.sub(_contact_relative, unquote(text))


#: a verbless directive, a place and the thing sent there ("Into the fridge with it.", "Straight
#: back on the shelf with them!"), or after a question a place a thing is sent into ("Milk still
#: out? Straight into the fridge."): an imperative whose verb of putting is elided, read with it
#: ("Put it into the fridge.") so its thing and place are read as an instruction's goal. A bare
#: "on"/"in" after a question may answer where a thing is ("Where is the towel? On the rack."),
#: so after a question only a preposition of motion ("into", "onto") counts
_DIRECTIVE_WITH = re.compile(
    r"(?:(?<=^)|(?<=[.!?:;]\s)|(?<=\n))[ \t]*(?P<adv>(?:straight|right|directly|back)\s+)?"
    r"(?P<place>(?:into|onto|in|on|to)\s+(?:the|a|an|my|our|your|its|their)\s+[A-Za-z][A-Za-z' -]{0,40}?)"
    r"\s+with\s+(?P<thing>it|them)(?=\s*[.!])", re.I | re.M)
_DIRECTIVE_AFTER_QUESTION = re.compile(
    r"(?<=\?)(?P<gap>\s+)(?P<adv>(?:straight|right|directly|back)\s+)?"
    r"(?P<place>(?:into|onto)\s+(?:the|a|an|my|our|your|its|their)\s+[A-Za-z][A-Za-z' -]{0,40}?)(?=\s*[.!])",
    re.I)


def _directive(m: re.Match[str]) -> str:
    """"Put it into the fridge" for "Into the fridge with it" (`_DIRECTIVE_WITH`)."""
    thing = m.groupdict().get("thing") or "it"
    place = m.group("place")
    return f"{m.groupdict().get('gap') or ''}Put {thing.lower()} {(m.group('adv') or '').lower()}{place[0].lower()}{place[1:]}"


#: "Desk lamp: stays on the desk.", "- Sunscreen - lives in the cabinet", "Washing powder. Stays on
#: the shelf": a line's heading of a few words, answered by a verb of where a thing is or goes
#: with no subject of its own and a place after it, is said of the heading's thing ("the desk
#: lamp stays on the desk"), so every reader reads the place as in a sentence
_SUBJECTLESS = re.compile(r"(^[ \t]*(?:[-*\u2022]|\d+[.)])?[ \t]*)([A-Za-z][A-Za-z']*(?: [A-Za-z][A-Za-z']*){0,3})"
                          r"(\s*(?::|\.|[-\u2013\u2014])\s*)(stays|lives|sits|stands|lies|belongs|goes|hangs|remains)"
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
#: a decision table's condition column: its header opens a condition ("If you find...", "When")
#: or names one ("Condition", "Situation", "Case")
_CONDITION_HEAD = re.compile(r"^(?:(?P<cue>(?:if|when|whenever|in case)\b[^|]*?)|condition|situation|case)\W*$", re.I)


#: the fields of a rule written as a record of keyed lines (YAML, a config file, a form: "when:
#: ..." / "do: ..." / "else: ..."), by what each says: its condition, its action, what to do
#: otherwise and a note; the other fields ("name:", "id:") only label the record (`derecord`)
#: A troubleshooting table, a fault card or a maintenance log writes its rules the same way: the
#: fault it supposes ("Possible cause: kettle left on.", "Problem: towel on the floor.") is the
#: condition, its remedy ("Remedy:", "Fix:", "Solution:") the action; the symptom, what is seen,
#: only labels the record (the cause says the thing's state).
RECORD_FIELDS = {
    "condition": frozenset({"when", "if", "condition", "trigger", "case", "situation",
                            "cause", "fault", "problem", "issue"}),
    "action": frozenset({"do", "then", "action", "actions", "task", "run", "remedy", "fix", "solution"}),
    "else": frozenset({"else", "otherwise", "if_not", "elif_not"}),
    "note": frozenset({"note", "notes", "comment"}),
}
#: the hedges a field's label may carry ("Possible cause:", "Likely cause:", "Corrective action:"):
#: the label is the field it hedges; no other word opens a label of two words ("Kitchen door:" is
#: a heading, not a field)
FIELD_HEDGES = ("possible", "probable", "likely", "suspected", "corrective", "recommended")
_KEYED = re.compile(r"^(?P<indent>[ \t]*)(?P<dash>-[ \t]+)?(?:(?:" + "|".join(FIELD_HEDGES) + r")[ \t]+)?"
                    r"(?P<key>[A-Za-z_]+)[ \t]*:(?:[ \t]+(?P<value>.*?))?[ \t]*$", re.I)
_FIELD_COMMENT = re.compile(r"\s+#.*$")


def _field(value: str) -> str:
    """A field's value without a trailing comment or the quotes around it."""
    return _FIELD_COMMENT.sub("", value).strip().strip("\"'").strip()


def _record_sentences(fields: dict[str, str]) -> str | None:
    """The sentences a record of fields stands for, or None when it is no rule (no condition or
    no action): "If <condition>, <action>. Otherwise, <else>. <note>."."""
    said = {kind: next((fields[k] for k in fields if k in keys and fields[k]), "") for kind, keys in RECORD_FIELDS.items()}
    if not said["condition"] or not said["action"]:
        return None
    condition = re.sub(r"^(?:if|when)\s+", "", said["condition"], flags=re.I)
    out = f"If {condition.rstrip('.')}, {said['action'].rstrip('.')}."
    if said["else"]:
        out += f" Otherwise, {said['else'].rstrip('.')}."
    if said["note"]:
        out += f" {said['note'][0].upper()}{said['note'][1:].rstrip('.')}."
    return out


def derecord(text: str) -> str:
    """A rule written as a record of keyed lines, the way a YAML file or a config lists its
    items ("- name: headphones" / "when: \"you find my headphones in here\"" / "do: put them on
    the bookshelf" / "else: nothing"), as the conditional it stands for: "If you find my
    headphones in here, put them on the bookshelf. Otherwise, nothing." A record is a run of
    keyed lines, the first opened by "- " or each at one indentation; its fields are read by
    `RECORD_FIELDS` (a label such as "name:" is dropped, a trailing "# comment" and quotes too).
    A record with no condition or no action, and every other line, stays as it is."""
    lines = text.split("\n")
    out: list[str] = []
    run: list[tuple[str, str, str]] = []  # (line, key, value) of the record being read
    indent = ""

    def flush() -> None:
        fields: dict[str, str] = {}
        for _, key, value in run:
            fields.setdefault(key.lower(), _field(value))
        sentence = _record_sentences(fields)
        out.extend([sentence] if sentence is not None else [line for line, _, _ in run])
        run.clear()

    for line in lines:
        m = _KEYED.match(line)
        if m is None or not m.group("value"):
            flush()
            out.append(line)
            continue
        here = m.group("indent") + " " * len(m.group("dash") or "")
        if m.group("dash") or here != indent:
            flush()
            indent = here
        run.append((line, m.group("key"), m.group("value")))
    flush()
    return "\n".join(out)


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.strip().strip("|").split("|")]


def detable(text: str) -> str:
    """A table of items and where they are ("No. | Item | Location | Notes" then "2 | First aid kit
    | on the shelving unit | To be kept closed.") as the sentences it stands for: "First aid kit is
    on the shelving unit. To be kept closed." A place cell without a preposition is on or by what
    it names ("back wall", "shelving unit, top shelf"); "As item 4." repeats row 4's notes. A
    decision table, whose first column's header opens or names a condition ("If you find... | Do
    this", "Situation | Action"), is its rows' conditionals ("If you find <cell>, <cell>."), as
    a table of cases is read by anyone. Text that holds no such table is returned as it is."""
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
            cue = _CONDITION_HEAD.match(cells[0].rstrip(".\u2026: "))
            if cue is not None and len(cells) >= 2:
                header = ["if " if cue.group("cue") is None else cue.group("cue").strip() + " "]
                continue
            out.append(line)
            continue
        if set(re.sub(r"[-:| ]", "", line)) <= {""}:
            continue  # a "---|---" rule under the header
        if len(header) == 1:
            # a decision table's row: "If you find <its condition>, <its action>."
            action = "; ".join(c for c in cells[1:] if c.lower() not in _EMPTY_CELL).rstrip(".")
            out.append(f"{header[0][0].upper()}{header[0][1:]}{cells[0].rstrip('.')}{', ' * bool(action)}{action}.")
            continue
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


#: "on top of" is the preposition "on" ("the cardboard box that lives on top of the piano", "the
#: basket that sits on top of the wardrobe"): read so once, for every reader, so that its "on" is
#: never the state (the box switched on) nor "top" a part or a thing
_ON_TOP = re.compile(r"\bon\s+top\s+of\b", re.I)
#: a verb of becoming in the perfect before a state word is the copula: "if it has run empty",
#: "if the vase has gone dry", "once the towel has got wet" say it is so now, as "has been" does
#: (not "gone" alone, which is absence, nor a particle: "has gone off", "has turned on")
#: "run dry" is said of a container or a spring, never of a towel: it has run empty ("has the vase
#: run dry?", "when the can runs dry"), whatever "dry" alone says (`_BECOME` then reads the perfect)
_RUN_DRY = re.compile(r"\b(run|runs|ran)\s+dry\b", re.I)
_BECOME = re.compile(r"\b(has|have|had)\s+(?:(just|already|now)\s+)?(?:run|gone|got|gotten|become|turned|grown)\s+(?=(?:"
                     + "|".join(w for w in STATE_WORDS if w not in ("on", "off", "out")) + r")\b)", re.I)


#: a word that may be an "-ing" form with its "g" dropped and no apostrophe ("if the mop's standin
#: on the floor", "it's lyin there"): `_g_restored` decides
_DROPPED_G = re.compile(r"\b([A-Za-z]{2,}in)\b(?!')")


def _g_restored(m: re.Match[str]) -> str:
    """A word ending in "in" that lemminflect does not know, whose form with a "g" is a verb's
    "-ing" form ("standin", "sittin", "goin"), is that form, as the apostrophe's "sittin'"
    already is; an English word ("cabin", "begin", "basin") and a name ("Kevin") stay."""
    word = m.group(1)
    low = word.lower()
    if getAllLemmas(low) or not getAllLemmas(low + "g").get("VERB"):
        return word
    return word + "g"


#: a past tense after "have" as its participle, as dialects and casual speech say it ("might've fell
#: on the floor", "it's went in the bin"): `_participle`
_PAST_AS_PARTICIPLE = re.compile(r"\b((?:have|has|had|'ve|'s)\s+(?:(?:already|just|probably|maybe|never)\s+)?)"
                                 r"([a-z]+)\b", re.I)


def _participle(m: re.Match[str]) -> str:
    """The participle of a verb whose simple past stands after "have" and is none of its
    participles ("fell" -> "fallen", "went" -> "gone", "took" -> "taken"); "have got" is standard
    British English (possession) and stays, as does every word that is a participle already."""
    word = m.group(2)
    low = word.lower()
    if low == "got":
        return m.group(0)
    for lemma in getAllLemmas(low).get("VERB", ()):
        forms = getAllInflections(lemma, "VERB")
        if low in forms.get("VBN", ()):
            return m.group(0)
    for lemma in getAllLemmas(low).get("VERB", ()):
        forms = getAllInflections(lemma, "VERB")
        if low in forms.get("VBD", ()) and forms.get("VBN"):
            return f"{m.group(1)}{forms['VBN'][0]}"
    return m.group(0)


def expand(text: str) -> str:
    """The text with contractions spelled out ("it's" -> "it is"), possessives dropped, "w/" read
    as "with", "and/or" as "or", a slash between words as "or", a dropped "g" restored
    (`_g_restored`), "run dry" as "run empty" (`_RUN_DRY`) and a verb of becoming in the perfect
    before a state as "been" (`_BECOME`), "on top of" as "on" (`_ON_TOP`)."""
    out = _SLASH.sub(" or ", _AND_OR.sub("or", _WITH.sub("with ", _ON_TOP.sub("on", text.replace("\u2019", "'")))))
    for pat, repl in _CONTRACTIONS:
        out = re.sub(pat, repl, out, flags=re.I)
    out = _RUN_DRY.sub(r"\1 empty", _PAST_AS_PARTICIPLE.sub(_participle, _DROPPED_G.sub(_g_restored, out)))
    return _BECOME.sub(lambda m: f"{m.group(1)} {m.group(2) + ' ' if m.group(2) else ''}been ", out)


#: a line break inside a sentence (verse, a wrapped line): after a word with no punctuation,
#: before a line that opens with a conjunction or a finite "be" and asks no question ("The
#: dishwasher door may be wide / or be shut", "if the sponge / is lying on the counter"); a
#: chat's lines ("... leave it there / toothpaste and soap - ...") open with a sentence's own words
_BROKEN_LINE = re.compile(r"(?<=[A-Za-z])[ \t]*\n[ \t]*(?=(?:or|and|but|nor|is|are|was|were|"
                          # the auxiliaries, modals and verbs of where a thing belongs that go on a
                          # subject the line before opened ("Should a sofa cushion / have ended up on
                          # the floor", "The TV remote / belongs on the TV stand", "the mug / should
                          # go in the sink"); a line that opens with its own verb ("close it") stays
                          r"has|have|had|should|must|will|would|can|could|may|might|shall|does|do|did|"
                          r"needs|wants|belongs|goes|lives|stays|sits|lies|stands|hangs|remains)\s[^?\n]*$)",
                          re.M)
#: a line that ends in a comma goes on in the next when that opens with a small letter (verse, a
#: wrapped line: "Should a cushion have ended up on the floor, / put it on the sofa."), and a
#: line that ends in a verb of resting goes on in a next that opens with its place ("A clean one
#: should lie / on the armchair"); a line that opens with a capital starts its own sentence, and
#: one that asks a question stays apart, as in `_BROKEN_LINE` ("Candle on the table, / still
#: burning?" asks of the candle, not of its place)
_CONTINUED_LINE = re.compile(r"(?:,|\b(?P<verb>lie|lies|sit|sits|stand|stands|hang|hangs|stay|stays|rest|rests|"
                             r"belong|belongs|live|lives|go|goes))[ \t]*\n[ \t]*(?P<next>[a-z]+)\b(?=[^?\n]*$)", re.M)
#: a line of verse that opens with a condition's cue and ends in a word, with no mark ("if the
#: candle's still burning / blow it out", "whenever a bowl is dirty / wash it / slowly"): the
#: condition goes on in the next line when that opens with a small letter, as after a comma, so
#: its instruction is its branch; the cues are the connectives of a condition
#: (`DASHED_ASIDE_CONNECTIVES`; "in the event that" is "if" by then, `_OCCASION_IF`)
_VERSE_CONDITION = re.compile(r"^(?P<line>[ \t]*(?:" + "|".join(c.replace(" ", r"\s+") for c in DASHED_ASIDE_CONNECTIVES)
                              + r")\b[^\n.,;:!?]*[A-Za-z'])[ \t]*\n[ \t]*(?=[a-z])", re.M | re.I)
#: verse written on one line, its line breaks as spaced slashes ("if the keys are not there / leave
#: the door on the latch / quietly"): two or more in a line are line breaks, not the alternatives
#: one slash offers (`_SLASH`: "on the chair / on the floor")
_VERSE_SLASH = re.compile(r"[ \t]+/[ \t]+")
_VERSE_LINE = re.compile(r"^[^\n]*?[ \t]/[ \t][^\n]*?[ \t]/[ \t][^\n]*$", re.M)


def _continued(m: re.Match[str]) -> str:
    """A line's break joined where `_CONTINUED_LINE` says the sentence goes on."""
    if m.group("verb") and m.group("next") not in _LINE_PLACES:
        return m.group(0)
    return m.group(0)[: m.end(0) - m.start(0) - len(m.group("next"))].rstrip(" \t\n") + " " + m.group("next")


#: the prepositions of place a line may open with to finish the line before's verb of resting
_LINE_PLACES = frozenset({"on", "in", "inside", "under", "by", "near", "beside", "behind", "at", "onto", "into",
                          "next", "against", "upon", "atop"})


#: words that open a clause of their own (a condition's cue, a conjunction, "then"): after a pause
#: they go on as a sentence of their own would, whose conditions the reader joins up itself ("Your
#: shirt... if it's clean fold it away in the wardrobe... if it's dirty ...": read as one sentence
#: with commas, the first condition would run on to "in the wardrobe in your bedroom")
PAUSE_CLAUSE_WORDS = ("if", "unless", "when", "whenever", "once", "should", "in case", "then", "and", "but",
                      "or", "otherwise", "else")
#: suspension points before a word in small letters ("A ripe one... goes into the fridge", "a wet
#: one… well, that goes in the hamper"): a speaker's pause between a thing and what is said of
#: it, not a sentence's end, so the sentence goes on as after a comma; before a capital they end it
#: ("Wait... Now the mug"), and before a word that opens a clause (`PAUSE_CLAUSE_WORDS`) they stay
_SUSPENSION = re.compile(r"(?<=\w)[ \t]*(?:\.{3,}|\u2026)[ \t]+(?=[a-z])(?!(?:"
                         + "|".join(w.replace(" ", r"\s+") for w in PAUSE_CLAUSE_WORDS) + r")\b)")


def split_sentences(text: str, *, full_stops_only: bool = False) -> list[str]:
    """The text's sentences (and `;`/`:`-separated parts), abbreviations kept whole, a line
    broken inside a sentence joined (`_BROKEN_LINE`, `_CONTINUED_LINE`), a pause inside one kept
    in it (`_SUSPENSION`). With `full_stops_only`, only at a full
    stop, "!" or a line break: for a reader that cuts the rest itself
    (`offline.clauses.clause_spans` cuts at ";", ":", "?" and brackets)."""
    # (a condition's line of verse after the lines a conjunction or a verb goes on: "If the towel is
    # on the floor / and wet, ..." is one clause)
    joined = _VERSE_CONDITION.sub(r"\g<line>, ", _BROKEN_LINE.sub(" ", _CONTINUED_LINE.sub(_continued, text)))
    protected = _ABBREV.sub(lambda m: m.group(0).replace(".", "\u2024"), _SUSPENSION.sub(", ", joined))
    parts = [p.strip().replace("\u2024", ".") for p in (_FULL_STOP if full_stops_only else _SENT).split(protected)]
    return [p for p in parts if p]
