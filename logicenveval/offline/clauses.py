"""Sentences into clauses, for both readers of a description: the factor reader
(`offline.analysis`) and the placement reader (`offline.placement`).

A clause comes with its *mood* and its *link* to the clauses around it. Two cuts of one sentence
are given, one per reader, with the same cue words:

- `split_clauses` cuts the text of a sentence into `Piece`s (text, cue, role). The role is the
  mood the factor reader needs: a `condition` (what the text is unsure of: "if the bin is full",
  a question, a heading "Mirror dirty?"), a `consequence` (what follows under it), an `else` (the
  alternative: "otherwise ..."), an `uncertain` statement ("a book may be on the floor", "the ball
  often ends up there"), a `scene` ("there is a sink", "the box has two drawers") or a plain
  `statement`. The cue is the link: the word that opened the condition a consequence or an
  alternative depends on ("if", "unless", "otherwise", "?", ":"), so chained conditionals read
  in order.
- `clause_spans` cuts a sentence's tokens into `Span`s (token range, mood, doubt, link) for the
  placement reader, whose moods are `statement`, `condition` (a subordinate clause, a question, a
  verbless heading) and `instruction` (the imperative mood, a polite request, a verbless part
  going on with an instruction before it: its `goal` link).

The word tables are the data below; one table of cues (`CONDITIONAL`, `ELSE_CUES`, `TIME_CUES`)
opens a condition in both cuts (`SUBORDINATORS` is its one-word part). What a clause then says of
the scene is each reader's own business.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import NamedTuple

from lemminflect import getAllLemmas

from logicenveval.offline.lexicon import WORD, singular, tokens
from logicenveval.offline.sentences import (
    ACTIONS,
    ARROW,
    BELIEFS,
    CLOSING_QUOTES,
    PERSONAL_SUBJECTS,
    STATE_WORDS,
    TRAILING_ADVERBIALS,
    expand,
    habitual,
)

# ---------------------------------------------------------------------------------------------
# Word tables (data). Each names a class of words, never a task's phrase or object.
# ---------------------------------------------------------------------------------------------

#: determiners and the like before a noun (after a base-form verb they open its object: `OBJECT_STARTS`)
ARTICLES = frozenset({"the", "a", "an", "any", "some", "one", "of", "its", "their", "this", "that",
                      "these", "those", "every", "each", "your", "my", "our"})
#: prepositions before a place or a goal: an object after them is not what a clause speaks of
PLACE_PREPS = frozenset({"on", "onto", "in", "into", "inside", "to", "from", "by", "near", "under"})
#: words that negate what a clause says ("if there is no roll", "the lamp is not on")
NEGATIONS = frozenset({"not", "no", "none", "never", "without", "nothing", "nobody", "nowhere"})
#: words that make a statement uncertain (an `uncertain` piece, not a fact)
UNCERTAIN = frozenset({"may", "might", "possibly", "possible", "perhaps", "maybe", "could", "sometimes",
                       "occasionally", "potentially", "probably", "likely"})
#: cues that open a condition (the earliest in a sentence wins, the longest at one place: `_first_cue`)
CONDITIONAL = ("depending on whether", "depending on if", "in case", "as long as", "provided that",
               "only if", "if not", "if so", "whether", "if", "unless", "whenever", "when", "while", "once",
               "should there be", "should")
#: cues that are a whole condition by themselves, pointing back ("if so")
POINTING_CUES = frozenset({"if so"})
#: time cues that, before what the reader does ("when you're done", "once you leave"), only say
#: when a question is asked of the scene ("Is the light on when you're done for the day? Then
#: switch it off"): the question is the condition, the time clause none
AGENT_TIMES = frozenset({"when", "whenever", "once", "while"})
#: who acts in such a time clause, and for the factor reader in any condition: one about what
#: they do ("when you put it away", "if u find it there") is no situation (`analysis`)
AGENTS = frozenset({"you", "we", "i", "u"})
#: other people a question's time clause may be told by ("Is the lamp still on when they have
#: gone?", "... once everyone has left?", "... when the last of them has gone?"): as the agent's,
#: the time says when the question is asked, not a condition of its own; "they" and "them" only
#: after a question naming no thing in the plural ("Are the towels dry when they come out?")
PEOPLE = frozenset({"everyone", "everybody", "he", "she", "they", "all of them", "the last of them",
                    "the rest of them"})
_PLURAL_PEOPLE = frozenset({"they", "all of them", "the last of them", "the rest of them"})
#: words that open a sentence without saying anything of the scene ("Then, if ...", "Oh, and
#: should ...")
DISCOURSE = frozenset({"then", "and", "also", "so", "first", "second", "third", "next", "finally", "last",
                       "lastly", "oh", "but", "now", "plus", "afterwards", "after", "that", "right", "okay",
                       "ok", "well"})
#: cues that open the alternative of the condition before ("otherwise", "if not")
ELSE_CUES = ("or else", "otherwise", "else", "failing that", "if not", "if there is not", "if there are not")
#: the cues of `ELSE_CUES` that open an alternative wherever a clause starts (not "if not ...")
ALTERNATIVES = ELSE_CUES[:4]
#: words after "if" that make it a condition of availability ("if there are any")
AVAILABILITY = frozenset({"available", "any", "present", "possible", "exist", "exists", "there"})
#: pronouns of a thing: "if it's there" asks where that thing is, not whether there are any
_THING_PRONOUNS = frozenset({"it", "they", "she", "he"})
#: how a sentence that sets the scene opens ("there is ...", "you are in ..."); a doubt before it
#: ("maybe there are some wipes ...") makes the piece uncertain instead (`_split`). A "there"
#: after a preposition is a place, not the existential "there": "the ceiling fan in there is
#: broken", "the mop out there is wet" state something of their subject
SCENE_START = re.compile(r"^\W*([a-z' ,]{0,50}?(?<!\bin )(?<!\bout )(?<!\bup )(?<!\bdown )(?<!\bover )(?<!\bunder )"
                         r"(?<!\bback )(?<!\bfrom )\bthere(?: is| are|['\u2019]?s|['\u2019]re)\b(?! (no|not|maybe|possibly))"
                         r"|you are\b|we are\b|you['\u2019]re\b|we['\u2019]re\b)", re.I)

#: subordinators that open a clause of time or concession, not a condition on the scene (for the
#: placement reader: nothing in them is placed)
TIME_CUES = frozenset({"until", "before", "after", "though", "although"})
#: words that open a subordinate clause: a condition or a time, not a statement about the scene
#: (the one-word cues of `CONDITIONAL` and `ELSE_CUES`, and `TIME_CUES`)
SUBORDINATORS = frozenset(c for c in CONDITIONAL + ELSE_CUES if " " not in c) | TIME_CUES
#: subordinators that are modal verbs elsewhere ("the shirt should be in the basket")
MODAL_SUBORDINATORS = frozenset({"should"})
#: subject pronouns ("u": the texting register's "you"): after "and" they open a clause of its own in both cuts
SUBJECTS = PERSONAL_SUBJECTS | frozenset({"u", "someone", "somebody"})
#: words that open a new clause after a comma or "and" (a subject pronoun or a sentence adverb)
CLAUSE_OPENERS = SUBJECTS | frozenset({"it", "then", "but", "so", "or", "which", "that", "where", "this"})
#: verbs that open an instruction (the imperative mood): a place after its object is a goal
IMPERATIVES = ACTIONS | frozenset({
    "check", "clean", "wipe", "close", "open", "shut", "switch", "turn", "grab", "fetch", "use", "pop",
    "chuck", "get", "look", "mop", "scrub", "rinse", "wash", "dry", "hang", "make", "go", "find",
    "pick", "lock", "tidy", "clear", "collect", "gather", "do", "keep", "see", "water", "mist", "spray",
    "feed", "lay", "replace", "swap", "dump", "stash", "pull", "remove", "straighten", "fix", "don't",
    "let", "try", "give", "pour", "empty", "toss", "please", "examine", "inspect"})
#: words that make a clause (or the rest of a list) doubtful: nothing after them is placed
DOUBT = frozenset({"may", "might", "could", "maybe", "perhaps", "possibly", "probably", "likely",
                   "sometimes", "whether", "any", "think", "guess", "somewhere",
                   # a speaker's belief is a hedge too: "I believe I left my watch in the flat",
                   # "I reckon the torch is in the shed", "I'm unsure it is on the shelf"
                   "believe", "reckon", "suppose", "unsure"})
#: how a polite request opens ("Could you sort out the coat ...?", "might you wipe it ..."): a
#: question that is an instruction; the modal before "you" is no doubt about the scene
REQUESTS = frozenset({"could", "can", "would", "will", "might"})
#: punctuation tokens; the hard ones always end a clause (a comma only before a new clause)
PUNCT = frozenset({",", ";", ":", "(", ")", "-", "?"})
_HARD = frozenset({";", "(", ")", "-", "?", ":"})
#: words before a clause's first word that say nothing of its mood ("and then put ...")
LEAD_INS = frozenset({"and", "then", "please", "just", "also", "so", "now", "first", "last", "oh", "right",
                       "but", "or"})
#: words that may open a clause before its fronted place, in both readers ("And here, draped across
#: the sofa, the blanket", "Meanwhile, on the shelf lies the torch")
FRONT_LEADS = frozenset({"and", "here", "there", "then", "now", "meanwhile", "somewhere", "so"})


# ---------------------------------------------------------------------------------------------
# The factor reader's cut: text pieces with their role and cue
# ---------------------------------------------------------------------------------------------


class Piece(NamedTuple):
    """A clause of a sentence as the factor reader reads it (see the module's docstring)."""

    text: str
    cue: str | None
    role: str  # "condition" | "consequence" | "else" | "uncertain" | "statement" | "scene" | "heading"


def split_clauses(sentence: str) -> list[Piece]:
    """The clauses of one sentence (as `split_sentences` gives it), in order, with their role and
    cue: a listed apposition and a fronted "without" rewritten first (`_apposition`), then the
    sentence cut at its cues (`_split`), then a condition cut where an action follows (`_subsplit`)."""
    masked = _BRACKETED_LIST.sub(_mask_commas, sentence)
    return [Piece(t.replace(_MASK, ","), c, r) for t, c, r in _subsplit(_split(_apposition(masked)))]


#: a bracketed aside holding commas ("If you've been in today (training swim, a rescue, whatever)
#: and it's wet", "When the kettle (the old one, not the new one) is on"): its commas are the
#: aside's own, so they cut no clause around it; an aside with a cue of its own ("(if it rings,
#: silence it first)") is a clause and keeps them
_BRACKETED_LIST = re.compile(r"\([^()]*,[^()]*\)")
_MASK = "\u201a"


def _mask_commas(m: re.Match[str]) -> str:
    aside = m.group(0)
    if _first_cue(aside.lower(), CONDITIONAL + ELSE_CUES) is not None:
        return aside
    return aside.replace(",", _MASK)


_GENERIC = (r"whatever|anything|everything|something|all|(?:any|the|all the)\s+(?:items?|things?|objects?|stuff)"
            r"|items|things|objects|stuff")
_APPOSITION = re.compile(rf"^(?P<lead>\W*)(?:{_GENERIC})\s+(?:that\s+|which\s+)?(?P<pred>[^:\u2013-]+?)\s*(?:\s-|\u2013|:)\s+"
                         r"(?P<list>[^:\u2013-]+?(?:,|\bor\b|\band\b)[^:\u2013-]+?)\s+(?:-|\u2013)\s+(?P<rest>.+)$", re.I)
_WITHOUT = re.compile(r"^(\W*)(?:without|with no|in the absence of|absent|failing|lacking)\s+(?:a|an|any|the)?\s*(?=\w[^,]*,)",
                      re.I)
#: legal drafting's conditions, as plain ones: "Subject to the table being dirty, ..." (if the
#: table is dirty; so "in the event of" / "on condition of" X being Y), "Where the carton remains
#: on the table, ..." (a clause-opening "where" is "if": a relative "where" follows its noun),
#: "provided that, where ..." (the proviso is its condition)
_SUBJECT_TO = re.compile(r"^(\W*)(?:subject to|in the event of|on condition of)\s+((?:the|a|an|its|their|your|my|our)\s+[^,;]+?)\s+being\b", re.I)
_WHERE = re.compile(r"^(\W*)where\b(?=[^?]*,[^?]*$)", re.I)
_PROVISO = re.compile(r"\bprovided that,?\s+(?:where|if|when|in case)\b", re.I)
#: an exception's connective after a comma before a clause-opening "where" ("..., save that where
#: the machine is already running it shall go into the hamper", "..., except where the window is
#: already closed", "..., but where the projector is already off, ..."): the exception's
#: condition, read "but if" as the proviso's is; with no comma before it the connective takes a
#: place ("anywhere except where the lamp is", "not on the shelf but where the plates are kept")
_EXCEPT_WHERE = re.compile(r",\s*(?:(?:save|except)(?:\s+that)?|but),?\s+where\b(?!\s+(?:is|are|was|were|do|does|did|should|shall|can|could|would|will)\b)", re.I)
#: "A plate left on the table shall, if clean, be placed in the cabinet": a condition put between
#: a modal and its verb is the condition of the whole clause
_INTERPOSED = re.compile(r"^(?P<head>.+?\b(?:shall|must|will|should|is to|are to|has to|have to|needs to|need to))"
                         r"\s*,\s*(?P<cue>if|unless|when|where|once)\s+(?P<cond>[^,;]+?)\s*,\s*(?P<rest>[^,;]+?)"
                         r"(?P<end>[;.!]?\s*)$", re.I)

#: a rule's quantified subject described by its state, then a modal passive ("Any umbrella still
#: open when the last four-ball is in must be closed", "Every lamp left on at close should be
#: switched off"; a relative "that is still on" is read already and spreads over every member
#: the text enumerated, so it is left as written): club rules, notices and
#: procedures state a condition so, as "if the umbrella is still open ..., it must be closed";
#: the state word is read only before a time clause or the modal, so a place ("any plate still
#: on the table") is not a state
_STATE_WORD = "|".join(sorted((re.escape(w) for w in STATE_WORDS), key=len, reverse=True))
_QUANTIFIED_STATE = re.compile(
    r"^(?P<lead>\W*)(?:any|every|each)\s+(?P<noun>[a-z]+(?:\s+(?!still\b|left\b|found\b|that\b|which\b)[a-z]+)?)\s+"
    rf"(?P<state>(?:(?:still|left|found)\s+)?(?:{_STATE_WORD}))"
    r"(?P<rest>(?:\s+(?:when|at|after|before|by|overnight|during|once|until)\b[^,;]*?)?)\s*,?\s+"
    r"(?P<modal>must|should|shall|is\s+to|has\s+to|needs\s+to)\s+be\s+(?P<done>\S.*)$", re.I)


def _quantified_state(sentence: str) -> str:
    """`_QUANTIFIED_STATE`'s rule as a plain condition: "If the umbrella is still open when ...,
    it must be closed" (the subject's state is the condition, the modal passive its action)."""
    m = _QUANTIFIED_STATE.match(sentence)
    if m is None:
        return sentence
    return (f"{m.group('lead')}If the {m.group('noun')} is {m.group('state')}{m.group('rest')}, "
            f"it {m.group('modal')} be {m.group('done')}")


def _apposition(sentence: str) -> str:
    """`Whatever is lying on it - a book, a clock, a phone - goes ...`: the listed objects are the
    subject of the generic word's predicate (`a book, a clock, a phone is lying on it - goes ...`);
    a fronted `without a sponge, ...` is the condition `if there is no sponge, ...`, and so is a
    rule's quantified subject with a state (`_quantified_state`)."""
    sentence = _WITHOUT.sub(r"\1if there is no ", sentence)  # "without a sponge, use ...": a condition
    sentence = _quantified_state(sentence)  # "Any umbrella still open ... must be closed"
    sentence = _SUBJECT_TO.sub(r"\1if \2 is", sentence)
    sentence = _EXCEPT_WHERE.sub(", but if", _PROVISO.sub("but if", _WHERE.sub(r"\1if", sentence)))
    interposed = _INTERPOSED.match(sentence)
    if interposed is not None:
        cond = interposed.group("cond")
        if set(cond.lower().split()) <= set(STATE_WORDS) | {"not", "still", "already"}:
            cond = f"it is {cond}"  # "if clean": the clause's subject is
        sentence = (f"{interposed.group('head')} {interposed.group('rest')} {interposed.group('cue')} {cond}"
                    f"{interposed.group('end')}")
    m = _APPOSITION.match(sentence)
    if m is None:
        return sentence
    return f"{m.group('lead')}{m.group('list')} {m.group('pred')} - {m.group('rest')}"


#: what may follow an inverted "should" ("should the hamper be full", "should its doors be open")
_INVERTING = ("the|there|a|an|it|they|any|one|your|my|our|its|their|his|her|this|that|these|those|some|no|you|we|"
              "either|neither|each|both|anyone|someone|somebody|anybody")
#: an inverted "should" after its main clause with no comma ("close the wardrobe should its doors
#: be open", "put the cover back on should the rain start"): its subject, then "be" or a verb
#: within a few words; a question asked with a wh-word ("where should the box go?") is none
_LATE_SHOULD = re.compile(rf"(?<![a-z])should(?=\s+(?:{_INVERTING})(?:\s+[a-z'-]+){{0,3}}?\s+(?:be|have|ever)\b)")
_WH = re.compile(r"\b(?:what|where|which|who|whom|whose|why|how|when)\b")


def late_should(words: list[str], i: int) -> bool:
    """Whether `words[i]` ("should") opens an inverted condition after its main clause with no
    comma before it (`_LATE_SHOULD`), for the placement reader's cut."""
    return bool(_LATE_SHOULD.match(" ".join(words[i:i + 6]))) and not _WH.search(" ".join(words[:i]))


def _timed_by_people(question: str, time: str) -> bool:
    """Whether a question's time clause (`time`, after its cue) is told by what people do: its
    subject is the agent (`AGENTS`) or other people (`PEOPLE`), "they" only where the question
    (`question`, before the cue) names nothing in the plural, which "they" would take up."""
    subject = next((p for p in sorted(AGENTS | PEOPLE, key=len, reverse=True)
                    if re.match(rf"\W*{p}\b", time)), None)
    if subject is None:
        return False
    return subject not in _PLURAL_PEOPLE or not any(
        w.endswith("s") and w not in getAllLemmas(w).get("NOUN", (w,)) for w in re.findall(r"[a-z]+", question))


def _first_cue(low: str, cues: tuple[str, ...]) -> tuple[int, str] | None:
    best: tuple[int, str] | None = None
    for cue in cues:
        pattern = rf"(?<![a-z]){re.escape(cue)}\b"
        if cue in ("once", "while"):  # a conjunction only before its clause: not "a once-over"
            pattern = rf"(?<![a-z-]){cue}(?=\s+[a-z])"
        if cue == "should":  # only the inverted conditional: "should the hamper be full, ..."
            pattern = rf"(?:^|[,;:(-]\s*|\b(?:and|or|but)\s+)should\b(?=\s+(?:{_INVERTING})\b)"
        m = re.search(pattern, low)
        if m is None and cue == "should":
            m = next((x for x in _LATE_SHOULD.finditer(low) if not _WH.search(low[: x.start()])), None)
        if m is None:
            continue
        start = m.end() - len(cue)
        if best is None or start < best[0] or (start == best[0] and len(cue) > len(best[1])):
            best = (start, cue)
    return best


#: words that make a segment a clause of its own (a finite verb, its subject, an existential),
#: so that it is no verbless heading: "Lamp left on:" is a heading, "the box has two drawers:" not
#: ("can" is left out: "Trash can full:" is a heading; "can you ...?" has its subject)
CLAUSE_WORDS = frozenset({
    "is", "are", "was", "were", "am", "be", "been", "has", "have", "had", "do", "does", "did",
    "will", "would", "could", "shall", "should", "may", "might", "must", "need", "needs",
    "keep", "keeps", "i", "you", "we", "he", "she", "it", "they", "someone", "somebody", "everyone",
    "there", "please", "let", "make", "get"})
#: finite forms of the verbs of resting, moving, belonging and holding ("Towel lies on the floor:"
#: is a clause, "Towel lying on the floor:" a heading): a participle is no finite verb
FINITE_VERBS = frozenset({"lies", "lay", "sits", "sat", "stands", "stood", "rests", "hangs", "stays", "waits",
                          "leans", "goes", "went", "belongs", "comes", "gets", "got", "contains", "holds",
                          "includes", "houses", "lives", "sleeps", "stores", "keeps"})


#: the bare forms of `FINITE_VERBS`' verbs of resting and holding: finite after a plural subject
#: ("Two cups sit on the desk: a tea cup and a coffee cup", "the drawers hold ..."), where the
#: same word opening a segment is an imperative ("Hang the towels on the rail:")
PLURAL_FINITE = frozenset({"lie", "sit", "stand", "rest", "hang", "stay", "wait", "lean", "belong", "live", "hold",
                           "contain"})


#: what a condition asks when it asks only whether its thing is there at all: "if it is there",
#: "if they are here at all", "if it's anywhere" (`presence_asked`)
PRESENT = frozenset({"there", "here", "anywhere", "around", "about"})
#: verb groups of a thing coming to be there: "if it turns up", "if the key shows up", "if they
#: are found", "if it reappears" (`presence_asked`)
APPEARING = frozenset({("turn", "up"), ("turns", "up"), ("turned", "up"), ("show", "up"), ("shows", "up"),
                       ("showed", "up"), ("is", "found"), ("are", "found"), ("appear",), ("appears",),
                       ("appeared",), ("reappear",), ("reappears",), ("reappeared",)})
#: a subject's determiners in a presence condition that names its thing ("if your wallet turns up")
PRESENCE_DETERMINERS = frozenset({"the", "a", "an", "your", "my", "our", "his", "her", "their", "its"})
#: words a presence condition's verb group may carry that ask nothing more ("if it ever turns up",
#: "if they're still there", "if it does show up")
_PRESENCE_FILLERS = frozenset({"ever", "still", "do", "does", "did"})


#: the finite words a presence question opens with ("Is the mug there?", "Isn't the remote here?",
#: and a modal of likelihood, the nineteenth session: "Might it still be there?", "Could the keys
#: be here?"; not "should", "must" or "can", which ask what ought to or may be, not what is)
PRESENCE_QUESTION = frozenset({"is", "are", "was", "were", "might", "may", "could", "will", "would"})
#: modals before "be" in a presence condition ("if the mug might still be there", "should the
#: towel be here", "if it will be there"); a bare "be" after an inverted "should" too
_PRESENCE_MODALS = frozenset({"might", "may", "could", "should", "will", "would", "must", "can"})

def presence_asked(words: list[str]) -> bool | None:
    """`_presence` of the condition's words, also in the forms writers ask it in (the thirteenth
    session): a modal before "be" ("if the mug might still be there", "should the towel be here")
    and a question with its finite
    word first ("Is the mug there?"; a negative question, "Isn't the mug there?", asks the same
    as the positive one, `analysis._unbiased`). Why: a presence was read only as "X is there"."""
    if words[:1] and words[0] in PRESENCE_QUESTION:
        # the subject is the thing's noun phrase, or since the nineteenth session "it"/"they"
        # as in the statement: "Is it there? If so, ..." asks what "If it is there, ..." asks
        lead = 2 if words[1:2] == ["not"] else 1
        for n in (1, 2, 3):
            said = _presence(words[lead:lead + n] + words[:1] + words[lead + n:])
            if said is not None:
                return said
        return None
    return _presence(words)


def _presence(words: list[str]) -> bool | None:
    """Whether a condition's words (after its "if", contractions spelled out, no punctuation) ask
    only whether its thing is there at all, and if so whether they ask that it is *not* there
    (True) or that it is (False); None when they ask more. The subject is "it", "they" or the
    thing's noun phrase ("your wallet"), or left out ("if anywhere", "if there at all"); then a
    verb of appearing (`APPEARING`: "turns up", "is found") or "is" with a word of presence
    (`PRESENT`: "if it's there", "if they are not here"), that word's "at all" ("if it is here
    at all"), or "anywhere" and whatever place follows, never "anywhere else" (a place of its
    own). Both readers ask it: the condition reader makes such a condition the thing's
    existence (`analysis`), and the placement reader takes "it will be on the floor" beside it
    as where the thing is if it is there, not a goal (`placement`). One definition, so that
    what one reads as a question of presence the other does too."""
    for n in (0, 1, 2, 3, 4):
        if n == 1 and words[:1] not in (["it"], ["they"]) or n > 1 and (
                not words or words[0] not in PRESENCE_DETERMINERS):
            continue
        rest = [w for w in words[n:] if w not in _PRESENCE_FILLERS]
        if tuple(rest) in APPEARING:
            return False
        if n:  # a subject's presence is said by "is" ("if its flame yet gutters there" asks more)
            if rest[:1] and rest[0] in _PRESENCE_MODALS and rest[1:2] == ["be"]:
                rest = rest[1:]
            if rest[:1] not in (["is"], ["are"], ["be"]):
                continue
            rest = rest[1:]
        negated = rest[:1] == ["not"]
        rest = rest[negated:]
        if rest[:1] == ["anywhere"] and rest[1:2] != ["else"] or rest[:1] and rest[0] in PRESENT \
                and rest[1:] in ([], ["at", "all"]):
            return negated
    return None


#: the prepositions a fronted place opens with before an inverted verb ("On the counter sit two mugs")
_FRONTED_PLACE = frozenset({"on", "in", "inside", "under", "by", "beside", "upon", "atop", "over", "behind"})


def _plural_finite(words: list[str]) -> bool:
    """Whether a bare verb of `PLURAL_FINITE` follows a plural noun ("cups sit", "towels hang":
    a word the lemmatiser gives another noun lemma, `lexicon.singular`) or, after a fronted
    place, comes before its subject ("On the counter sit two mugs")."""
    return any(w in PLURAL_FINITE and k > 0 and (
        singular(words[k - 1]) != words[k - 1]
        or words[0] in _FRONTED_PLACE and k > 2) for k, w in enumerate(words))


def verbless(words: list[str]) -> bool:
    """Whether a segment has no finite verb, no subject and no imperative (`CLAUSE_WORDS`,
    `FINITE_VERBS`, `PLURAL_FINITE` after a plural, `imperative`): "Lamp left on", "Towel lying
    on the floor", "Dog bowl empty" are verbless; "The pantry has two shelves", "Towel lies on
    the floor", "Two cups sit on the desk", "Put it away" are not. Both readers tell a heading
    before a colon by it."""
    return not set(words) & (CLAUSE_WORDS | FINITE_VERBS) and not _plural_finite(words) and not imperative(words)


#: words after a base-form verb that make it an imperative with its object ("clean it", "put
#: the", "pick up"), not an adjective or noun opening a heading ("clean - ...", "water bowl ...")
OBJECT_STARTS = ARTICLES | frozenset({"it", "them", "up", "out", "back", "away", "down", "off", "over",
                                      "with", "at", "from", "onto", "into",
                                      # a doll or a teddy spoken of as a person ("put her there")
                                      "her", "him",
                                      # the speaker as the object: an instruction to report back
                                      # ("let me know", "tell us", "text me", "give me a shout")
                                      "me", "us"})
#: a heading ends where its instruction starts: at a colon, a question mark or a spaced dash
_HEADING = re.compile(r"^(?P<head>[^:?\u2013]+?)(?P<mark>\?|:|\s+(?:-|\u2013)\s+)(?P<rest>.*)$", re.S)


#: adverbs that may open an instruction before its verb ("just stick it in the sink")
SOFTENERS = frozenset({"just", "simply"})


#: verbs of sending a message that the lemma table knows only as nouns ("text me", "whatsapp us",
#: "msg me", "dm me"): before the speaker they are an instruction to report back, as "call me"
MESSAGING = frozenset({"text", "txt", "whatsapp", "msg", "dm", "sms"})
#: the speaker as a verb's object
SPEAKER_OBJECTS = frozenset({"me", "us"})


def imperative(words: list[str]) -> bool:
    """The segment opens with a verb in its base form followed by its object or particle."""
    if words[:1] and words[0] in SOFTENERS:
        words = words[1:]  # "just chuck it in the sink", "simply hang it up"
    if len(words) < 2:
        return False
    if words[0] in MESSAGING:
        return words[1] in SPEAKER_OBJECTS
    lemmas = getAllLemmas(words[0]).get("VERB", ())
    return words[0] in lemmas and words[1] in OBJECT_STARTS


#: after a spaced dash, a noun phrase that names again the thing before the dash ("The tablet on
#: the workbench - the one we use for photos", "Kettle on the hob - the old whistling one", "The
#: lamp by the sofa - that's the one with the dimmer"): an apposition telling which thing is meant,
#: neither an instruction nor a case's answer, so the part before the dash is no heading asking
#: where the thing is; "the one" and "the <one or two words> one", or "that is the one"
_RENAMING = re.compile(r"^(?:(?:that|this|it) is\s+)?(?:the|that|this)\s+(?:[a-z'-]+\s+){0,2}?ones?\b(?!\s+(?:of|more)\b)",
                       re.I)


def _heading(sentence: str) -> tuple[str, str, str] | None:
    """A verbless heading and its instruction: "Pillow on the floor: back on the bed", "Mirror
    dirty? Clean it", "dirty - into the hamper", "Table dirty:" (the instruction in the next piece).
    Returns (heading, mark, rest), or None when the first segment is a clause of its own (it has a
    finite verb, a subject, a conditional cue) or an instruction (an imperative)."""
    m = _HEADING.match(sentence.strip())
    if m is None:
        return None
    head, rest = m.group("head").strip(" ,"), m.group("rest").strip()
    words = [w for w, _, _ in tokens(expand(head))]
    if not words or len(words) > 10 or not verbless(WORD.findall(expand(head).lower())):
        return None  # (the words as written: "lies" is a verb, its noun lemma "lie" is not)
    if _first_cue(head.lower(), CONDITIONAL) or any(w in UNCERTAIN for w in words) and words[0] not in PLACE_PREPS:
        return None  # (a place may carry a doubt: "On the bed, maybe: a book, a phone")
    mark = m.group("mark").strip()
    if mark == "-" and (not rest or _RENAMING.match(rest)):
        return None
    return head, mark, rest


def _state_places(instruction: str) -> list[tuple[str, str | None, str]]:
    """An instruction listing a place per state of the thing spoken of ("wet to the laundry
    basket, dry to the towel rack", "dirty into the hamper, clean back in the wardrobe"): each
    state is a subjectless heading (a condition on that thing) and its place the instruction.
    Empty unless every comma-separated item (two or more) opens with a state word and a place."""
    items = [i.strip(" .!") for i in re.split(r",\s*(?:and\s+)?|;\s*", instruction) if i.strip(" .!")]
    out: list[tuple[str, str | None, str]] = []
    for item in items:
        words = item.split()
        if len(words) < 3 or words[0].lower() not in STATE_WORDS or words[1].lower() not in PLACE_PREPS | {"back"}:
            return []
        out += [(words[0], ":", "heading"), (" ".join(words[1:]), None, "consequence")]
    return out if len(items) > 1 else []


#: "put it in the sink, if not in the cupboard": after an instruction, "if not" and a place that
#: ends the sentence is the alternative, its verb elided ("Knife - if not in the dish rack, put it
#: in" asks where the knife is: an instruction follows its comma)
_IF_NOT_PLACE = re.compile(r",\s*if not\s+(?=(?:on|in|into|onto|inside|under)\s+(?:the|a|an|my|your|our|his|her|their)\b"
                           r"(?![^,;]*\b(?:already|yet|still)\b)[^,;]*$)", re.I)


#: a clause after a condition's comma that instructs in the passive, with a subject of its own
#: and a modal ("the full bag will be taken out", "the lamp is to be switched off", "any spare
#: should then be put back"): the condition's main clause, as an imperative after the comma is
_PASSIVE_INSTRUCTION = (r",\s*(?:the|a|an|any|its|their|this|that|each|every)\s+(?:[a-z'-]+\s+){0,3}?"
                        r"(?:will|shall|must|should|is\s+to|are\s+to)\s+(?:then\s+|also\s+|now\s+)?be\s+[a-z]+(?:ed|en|t)\b")


#: "Either the mug is dirty or it is not.", "Either M lies on the floor or not": a proposition
#: and its bare negation offered as two cases asks the proposition, as a question does
_EITHER_OR_NOT = re.compile(r"^\W*either\s+(?P<asked>.+?),?\s+or\s+(?:(?:it|they|he|she|there|that|this|we|you|i)\s+"
                            r"(?:is|are|was|were|does|do|did|has|have|had|can|will)(?:\s+not|n't)|not)\W*$", re.I)
#: the cases of such a question named by their order, opening a clause ("In the first case,
#: wash it; in the second, put it away", "If the former, ...; if the latter, ..."): the first is
#: the case the proposition holds, as "if so" says, the second the other, as "if not"
_BY_ORDER = re.compile(r"(^\W*|[;,:]\s*)(?:(?:in|for)\s+the\s+(first|former|second|latter)(?:\s+case\b|(?=\s*[,:]))"
                       r"|if\s+the\s+(former|latter)\b)", re.I)
_ORDER_CUES = {"first": "if so", "former": "if so", "second": "if not", "latter": "if not"}


def _by_order(sentence: str) -> str:
    """The cases named by order said as the pointing cues they stand for (`_BY_ORDER`)."""
    return _BY_ORDER.sub(lambda m: m.group(1) + _ORDER_CUES[(m.group(2) or m.group(3)).lower()], sentence)


def ends_asking(text: str) -> bool:
    """Whether `text` ends with a question mark, inside closing quotation marks or not: a question
    quoted in a script or a story asks as one does without them ('"Is the kettle on the counter?"').
    One test for the clause splitter (`_split`) and the analyser's answer labels (`analysis._asks`).
    Not `sentences._QUOTED_WHOLE`, which takes the marks off a capitalised whole question in the
    text once; this sees each clause (lower-cased, or quoted in ways that leaves) and reads past
    the same closing marks (`sentences.CLOSING_QUOTES`)."""
    return text.rstrip().rstrip(CLOSING_QUOTES).rstrip().endswith("?")


#: a parenthesised aside ending the words after a cue, dropped before they are read as a
#: condition of availability (`AVAILABILITY`)
_AFTER_ASIDE = re.compile(r"\s*\([^()]*\)")


def _split(sentence: str) -> list[tuple[str, str | None, str]]:
    """(text, cue, role) pieces of a sentence, recursively for chained conditionals; a verbless
    heading (`_heading`) is a `heading` piece, its instruction read after it."""
    # "still on? -> switch OFF.", "Laptop on the floor -> put it on the desk": the arrow is "then"
    sentence = ARROW.sub(" - ", re.sub(rf"([?:!]){ARROW.pattern}", r"\1 ", sentence))
    sentence = _by_order(_IF_NOT_PLACE.sub(", otherwise ", sentence))
    either = _EITHER_OR_NOT.match(sentence)
    if either is not None:
        return [(either.group("asked") + "?", "?", "condition")]
    states = _state_places(sentence)
    if states:
        return states  # "Bath towel on the floor: wet to the basket, dry to the rack"
    heading = _heading(sentence)
    if heading is not None:
        label, mark, instruction = heading
        answer = [(t, c, "consequence" if r in ("statement", "scene") else r)
                  for t, c, r in _split(instruction)] if instruction.strip(" .!") else []
        return [(label, mark, "heading"), *answer]
    low = sentence.lower()
    for cue in ELSE_CUES:
        m = re.match(rf"^\W*{re.escape(cue)}\b", low)
        if m:
            if cue.startswith("if there"):
                return [(sentence, cue, "condition")]
            if cue == "if not" and re.match(r"\s*(?:already\s+|yet\s+)?(?:on|in(?!\s+case\b)|inside|at|by|under|near)\b",
                                              low[m.end():]):  # ("if not in case ...": a cue, no place)
                # "Knife - if not in the dish rack, put it in": a negated place of the thing spoken
                # of, elliptic for "if it is not in the dish rack" (a bare "if not," is the else)
                return _split(f"if it is not{sentence[m.end():]}")
            return [(sentence[m.end():].strip(" ,"), cue, "else")]
    best = _first_cue(low, CONDITIONAL)
    asks = ends_asking(low)
    if best is not None and best[1] in AGENT_TIMES and asks and best[0] > 0 \
            and _timed_by_people(low[:best[0]], expand(low[best[0] + len(best[1]):])):
        best = None  # "is it on when you're done for the day?": asked of the scene at a time of the agent's
    if best is None and asks:
        return [(sentence, "?", "condition")]  # "Are the keys on the floor?" asks about the situation
    if best is None:
        # (as `clause_spans` does: "and" before a subject pronoun starts a clause of its own, "there's
        # a mark on the floor and you may find wipes on the table")
        parts: list[str] = [str(p) for p in re.split(
            r",\s*(?:and|but|while)\s+|\s+but\s+|;\s*|:\s+|\s+-\s+|\s+while\s+"
            rf"|\s+and\s+(?=(?:{'|'.join(sorted(SUBJECTS))})\b)", sentence) if p and p.strip()]
        out: list[tuple[str, str | None, str]] = []
        for p in parts:
            alternative = re.match(rf"^\W*({'|'.join(re.escape(c) for c in ALTERNATIVES)})\b", p.lower())
            if alternative is not None and out:
                # "return it, close the vanity - else with the hand towel": a later part may be the
                # alternative of what came before
                out.append((p[alternative.end():].strip(" ,"), alternative.group(1), "else"))
                continue
            scene = SCENE_START.match(p)
            if scene and not uncertain_words(re.findall(r"[a-z]+", scene.group(0).lower())) or re.search(r"\b(has|have|contains)\b(?!\s+(?:been|\w+(?:ed|en))\b)",
                                                 p.lower()) and not (
                    re.search(r"\bif\b", p.lower()) or set(re.findall(r"[a-z]+", p.lower())) & UNCERTAIN):
                out.append((p, None, "scene"))
            else:
                said = re.findall(r"[a-z]+", p.lower())
                # "The ball often ends up on the floor": a habitual statement says what may be so
                out.append((p, None, "uncertain" if uncertain_words(said) or habitual(said) or either_state(said)
                            else "statement"))
        return out
    start, cue = best
    # (an aside after it is no part of the condition: "if there are any (they are not always
    # restocked); ...", "if there is one (Gran borrows it), ...")
    after = re.match(r"\W*([a-z' ]{0,30}?)\W*(?:$|[,;]|\s-\s)", _AFTER_ASIDE.sub("", expand(low[start + len(cue):])))
    if cue in ("if", "in case") and after and set(after.group(1).split()) & AVAILABILITY \
            and len(after.group(1).split()) <= 3 and not set(after.group(1).split()) & NEGATIONS \
            and after.group(1).split()[0] not in _THING_PRONOUNS and not (
                ELIDED_EXISTENTIAL.match(after.group(1).strip())
                and set(re.findall(r"[a-z]+", low[:start])) <= DISCOURSE):
        # (an elided existential opening its sentence, "Is there a towel inside? If there is,
        # ...", has no instruction before it to give a tool: it points back, `points_back`)
        # "with the wipes if there are any, else with the mop": the alternative is its own piece
        sentence = sentence[:start] + _AFTER_ASIDE.sub("", sentence[start:], count=1)
        other = re.search(r"[,;]\s*(?:otherwise|else|or else|failing that)\b", sentence[start:], re.I)
        if other is not None:
            cut = start + other.start()
            return [(sentence[:cut], "if available", "uncertain"),
                    (sentence[start + other.end():].strip(" ,"), "otherwise", "else")]
        return [(sentence, "if available", "uncertain")]
    head = sentence[:start].strip(" ,-")
    if set(re.findall(r"[a-z]+", head.lower())) <= DISCOURSE:
        head = ""  # "Then, unless it is in the box, put it in": the condition opens the sentence
    tail = sentence[start + len(cue):]
    pieces: list[tuple[str, str | None, str]] = []
    coordinated = re.search(r"[,;]?\s*\b(?:but|and|so)$", head, re.I)
    own = _split(head[:coordinated.start()]) if coordinated and head[:coordinated.start()].strip() \
        and re.search(r",\s*\S", tail) and not _first_cue(head.lower(), CONDITIONAL) else []
    if not own and head and not _first_cue(head.lower(), CONDITIONAL) and not re.search(r",\s*$", sentence[:start]):
        # "and theres a coffee mug on the table - if its dirty put it in the sink": a thing the
        # scene has, said before a condition, is no instruction of it (a dash or a full stop apart)
        remark = _split(head)
        own = remark if remark and all(r == "scene" for _, _, r in remark) else []
    if own and all(r in ("uncertain", "scene") for _, _, r in own):
        # "There may or may not be bread, but if there is a loaf on the counter, put it away": a
        # remark on the scene joined to a condition that has its own instruction is no
        # instruction of it
        pieces += own
        head = ""
    if head:
        step = _last_step(head) if not _first_cue(head.lower(), CONDITIONAL) else None
        if step is not None:  # "Open the fridge, get the pan onto the stove unless ...": the last step's
            pieces += _split(head[:step])
            head = head[step:].lstrip(" ,")
        pieces += _split(head) if _first_cue(head.lower(), CONDITIONAL) else [(head, cue, "consequence")]
        if pieces and pieces[-1][2] in ("statement", "scene"):
            pieces[-1] = (pieces[-1][0], cue, "consequence")
    m = re.search(r",\s*(then\s+)?|\bthen\b|\s+-\s+|:\s*", tail)
    # "he always does - if so, off please": a condition that only points back has nothing before
    # its comma, so what follows is its instruction, however short
    pointer = m is not None and not tail[:m.start()].strip() and cue in POINTING_CUES
    # (after its comma, a verb and a pronoun or a request opens the condition's instruction: "...
    # - if you find one there, put it back", "... - if you find one there, would you put it back?";
    # so does an instruction in the passive with a subject of its own: "Under the plan, if the
    # trash can is full, the full bag will be taken out", `_PASSIVE_INSTRUCTION`)
    if head and not pointer and not (m and re.match(
            rf"\s*(then\b|,\s*[a-z]+ (it|them)\b|,\s*(?:{'|'.join(sorted(REQUESTS))}) you\b|{_PASSIVE_INSTRUCTION})",
            tail[m.start():].lower())):
        other = re.search(r"[,;]?\s*\b(otherwise|(?<!where )(?<!thing )else|or else|instead)\b", tail)
        cond = tail[: other.start()] if other else tail
        nested = _first_cue(cond.lower()[1:], CONDITIONAL)
        if nested:
            cut = nested[0] + 1
            main = _imperative_cut(cond[:cut], subjects_only=True)
            pieces.append((cond[:cut] if main is None else cond[:main], cue, "condition"))
            if main is not None:  # "if it is off the helper switches it on - unless ...": its main clause
                pieces.append((cond[main:cut], cue, "consequence"))
            pieces += _split(cond[cut:])
        else:
            imp = _imperative_cut(cond)
            step = _next_step(cond) if imp is None else None
            end = imp if imp is not None else step
            pieces.append((cond if end is None else cond[:end], cue, "condition"))
            if imp is not None:  # "the towel, if dirty wash it": the instruction follows
                pieces.append((cond[imp:], cue, "consequence"))
            if step is not None:  # "..., take an egg and put it in the pan": the list's next step
                pieces += _split(cond[step:].lstrip(" ,"))
        if other:
            pieces.append((tail[other.end():], "otherwise", "else"))
        return pieces
    cond, cons = (tail[: m.start()], tail[m.end():]) if m else (tail, "")
    if cue in POINTING_CUES and cond.strip(" ."):
        # "If so wash it.", "if so just leave it": a cue that is a whole condition by itself
        # needs no comma; what follows it is its instruction, comma and all (no alternative after
        # the comma joins the condition: "if so or the bin is full," kept no word twice)
        cond, cons, m = "", tail.lstrip(), None
    # "if its not in there put it in there": no comma; or before the comma of an alternative ("if
    # its dirty put it in the sink, otherwise in the cupboard": the instruction came before it)
    before_else = m is not None and re.match(
        rf",\s*(?:{'|'.join(re.escape(c) for c in ALTERNATIVES)})\b", tail[m.start():], re.I) is not None
    # ("so if it is off the helper switches it on - unless ...": before the condition's dash or
    # comma, a main clause with a subject of its own still ends it, see `_main_clause`)
    imp = _imperative_cut(cond) if m is None or before_else else _imperative_cut(cond, subjects_only=True)
    if imp is not None:
        cond, cons = cond[:imp], cond[imp:] + (tail[m.start():] if m else "")
    alt = re.match(r"\s*or\s+[^,;]*,\s*", cons, re.I) if m and tail[m.start()] == "," else None
    if alt and m:  # "if it is elsewhere, or we are out of it, skip it": one condition with two alternatives
        cond, cons = tail[: m.start() + 1] + " " + cons[: alt.end()].rstrip(" ,"), cons[alt.end():]
    pieces.append((cond, cue, "condition"))
    if cons.strip():
        rest = _split(cons)
        pieces += [(t, c or cue, "consequence" if r in ("statement", "scene") else r) for t, c, r in rest]
    return pieces


#: words after which a verb's base form is no imperative: its subject, a modal, "to", a copula
#: ("if you put it back", "if it is set aside", "if we can leave it")
_NO_IMPERATIVE_AFTER = frozenset({
    "i", "you", "we", "they", "he", "she", "it", "someone", "somebody", "kids", "to", "will", "would",
    "can", "could", "should", "shall", "must", "may", "might", "not", "do", "does", "did", "let", "is",
    "are", "was", "were", "be", "been", "being", "am", "has", "have", "had", "and", "or", "please",
    # a determiner or a preposition: the word is a noun ("on the floor it goes", "no sponge a ..."),
    # but for "on", as often the state ("if the lamp is still on turn it off")
    "the", "a", "an", "no", "any", "some", "each", "every", "my", "your", "his", "her", "our", "their",
    "its", "this", "that", "these", "those", "in", "into", "onto", "at", "by", "of", "for", "from",
    "with", "under", "near", "behind", "beside", "next"})
#: what makes the words before a cut a condition of their own: a copula, "there", a state word
#: prepositions of motion that open an instruction whose verb is dropped ("into the basket")
DIRECTIONS = frozenset({"into", "onto"})
#: (and "be" after a modal, the nineteenth session: "if the mug might still be missing let me
#: know" ends its condition where "if the mug is missing let me know" does)
_PREDICATES = frozenset({"is", "are", "was", "were", "be", "has", "have", "had", "there"}) | frozenset(STATE_WORDS)


#: subjects that open a main clause of their own after a condition typed without its comma
MAIN_SUBJECTS = frozenset({"you", "we", "i", "they", "he", "she"})
#: the thing a condition spoke of, as the subject of its main clause with the comma left out
#: (`_main_clause`); never after a state word that is also a preposition ("if the lamp is on it
#: ...", "if a mug is in it ...": "on it", "in it" are places)
THING_SUBJECTS = frozenset({"it", "they"})
PLACE_STATES = frozenset({"on", "off", "in", "out", "up", "down"})


def _main_clause(ws: list[str], k: int) -> bool:
    """A main clause with a subject of its own right after a condition's state word, the comma
    left out ("if it is off the helper switches it on", "if the window is open you close it"):
    a subject pronoun, or "the" and one or two words, then a verb and its object. The state
    word must end the condition: "if the cup is off the table the helper ..." has a place after
    "off", and "the table" is followed by no verb; "if it is off the shelf put it back" has an
    imperative, no verb agreeing with "the shelf"."""
    if ws[k] in THING_SUBJECTS and k + 1 < len(ws) and (
            ws[k - 1] in STATE_WORDS and ws[k - 1] not in PLACE_STATES or ws[k - 1] in ("there", "here")):
        # "if it's dirty it goes in the dishwasher", "if it's still there it belongs in the box": the
        # thing itself, then a verb agreeing with it ("it goes", "they go"; no noun, no copula)
        verb = ws[k + 1]
        lemmas = getAllLemmas(verb).get("VERB", ())
        if ws[k] == "they":  # "they go", "they need": the base form
            return verb in lemmas and verb not in ("be", "have", "are", "were")
        return verb.endswith("s") and bool(lemmas) and verb not in lemmas and verb not in ("is", "was", "has")
    if ws[k - 1] not in STATE_WORDS:
        return False
    if ws[k] in MAIN_SUBJECTS:
        return imperative(ws[k + 1:k + 3])
    # (the verb agrees with its subject: "the helper switches it", not "off the shelf put it back")
    return ws[k] == "the" and any(
        ws[k + n].endswith("s") and ws[k + n] not in getAllLemmas(ws[k + n]).get("VERB", (ws[k + n],))
        and ws[k + n + 1] in OBJECT_STARTS for n in (2, 3) if k + n + 1 < len(ws))


def _opens_step(text: str) -> bool:
    """Whether `text` opens with an imperative (`imperative`: a verb's base form and its object),
    a step of a list of steps."""
    return imperative(re.findall(r"[a-z']+", expand(text).lower())[:2])


def _next_step(cond: str) -> int | None:
    """Where a condition put after its instruction in a list of steps ends at a comma before the
    list's next step ("Open the fridge, get the pan onto the stove unless it's there already,
    take an egg and put it in the pan", "wipe the desk if it is dusty, lock the drawer and ..."):
    a comma, then an imperative (`imperative`: a verb's base form and its object). None when no
    step follows: the condition runs to its end ("... if it is on the desk, the shelf or the
    floor")."""
    return next((c.start() for c in re.finditer(r",\s*(?:and\s+)?", cond) if _opens_step(cond[c.end():])), None)


def _last_step(head: str) -> int | None:
    """Where the last step of a list of steps before a condition put after it starts ("Open the
    fridge, get the pan onto the stove unless it's there already": the condition is the pan's
    step's, the fridge is opened whatever): the last comma before an imperative that opens
    neither the list (its first step) nor a bare "and" list of things. None with one step."""
    if not _opens_step(head):
        return None
    steps = [c for c in re.finditer(r",\s*(?:and\s+|then\s+)?", head) if _opens_step(head[c.end():])]
    return steps[-1].start() if steps else None


def _subjectless_request(words: list[str], k: int) -> bool:
    """A request with its "you" dropped right after a condition's state word, the comma left out
    ("if the fan still on can help me off it", "if the laptop open can close it pls", "if still
    on could switch off for me"): the English of speakers whose languages drop a known subject
    (Singapore and Malaysian English, Chinese, Indonesian, Thai, Vietnamese, Korean) asks with the
    modal alone. Only after a state word (`STATE_WORDS`) ending the condition and before an
    imperative (`imperative`); "if it can be moved", "if the lamp is on it can overheat" have a
    subject before the modal or no imperative after it."""
    return words[k] in REQUESTS and words[k - 1] in STATE_WORDS and imperative(words[k + 1:k + 3])


def _imperative_cut(cond: str, subjects_only: bool = False) -> int | None:
    """Where a condition typed without a comma runs into its instruction ("if its not in there
    put it in there", "if the lamp is still on turn it off", "if empty bin it"): before the first
    imperative (a base-form verb and its object or particle, `imperative`) that follows a
    predicate (a copula, "there" or a state word), not its subject or a modal, or before a
    request ("if it still is can you shut it"). None if there is no such verb (the whole text is
    the condition). Before the condition's own comma or dash (`subjects_only`) only a main clause
    with a subject of its own ends it: an imperative there is the condition's ("if you find it
    off the shelf put back, ...") as often as not; so does a request with its "you" dropped
    (`_subjectless_request`: "if still on can help me off it, the switch is on the left")."""
    said = expand(cond).lower()
    ws = list(re.finditer(r"[a-z]+", said))
    plain = [w.group() for w in ws]
    for k in range(1, len(ws) - 1):
        gap = said[ws[k - 1].end():ws[k].start()]
        # "if it still is can you shut it": a request ("can you", "could you") opens the
        # instruction even after a copula
        request = ws[k].group() in REQUESTS and ws[k + 1].group() == "you" and k + 2 < len(ws) \
            and imperative([w.group() for w in ws[k + 2:k + 4]])
        if gap.strip() or ws[k - 1].group() in _NO_IMPERATIVE_AFTER and not request:
            continue
        if said[ws[k].end():ws[k + 1].start()].strip():
            continue  # "if it was left open (the cleaner ...)": a verb's object follows it directly, not past a bracket
        if not {w.group() for w in ws[:k]} & _PREDICATES:
            continue
        if " ".join(said[ws[k].end():].strip(" .,;:!?").split()) in TRAILING_ADVERBIALS:
            continue  # "if it was left open this morning": a state, then when; no verb and its object
        if ws[k].group() in STATE_WORDS and any(
                " ".join(w.group() for w in ws[k + 1:k + 1 + len(a.split())]) == a and k + len(a.split()) + 1 < len(ws)
                for a in TRAILING_ADVERBIALS):
            continue  # "if the fridge was left open this morning close it": the state, when, then the verb
        # a terse instruction with its verb dropped after a bare state ("if wet into laundry
        # basket", "IF DIRTY ONTO THE PILE"): the direction starts it (`DIRECTIONS`)
        bare = ws[k].group() in DIRECTIONS and ws[k - 1].group() in STATE_WORDS
        # (a main clause's subject and verb are never parted by a bracket: "if it's lying on the
        # floor (he flings it at tea), hang it" has an aside with a subject and verb of its own)
        aside = "(" in said[ws[k].start():ws[min(k + 3, len(ws) - 1)].start()]
        if not subjects_only and (request or bare or imperative(plain[k:k + 2])) \
                or _main_clause(plain, k) and not aside or _subjectless_request(plain, k):
            # the same words in the text as written (the expansion only lengthens what is before)
            rest = said[ws[k].start():]
            at = cond.lower().rfind(rest)
            return at if at > 0 else None
    return None


def _subsplit(pieces: list[tuple[str, str | None, str]]) -> list[tuple[str, str | None, str]]:
    """`it is on, and close the wardrobe`: a condition ends at `, and`; what follows is an action."""
    out: list[tuple[str, str | None, str]] = []
    for text, cue, role in _more_conditions(pieces):
        # ", otherwise ..." ends a consequence as it ends a clause span: the alternative is its own piece
        splitter = r",\s*(?:and|but|then)\s+|,\s*(?=(?:otherwise|else|or else|failing that)\b)" + (
            r"|,\s*(?=the\s)" if role == "consequence" else "")
        parts = [p for p in re.split(splitter, text) if p.strip()] or ([text] if role == "condition" else [])
        for i, part in enumerate(parts):
            alternative = re.match(rf"^\W*({'|'.join(re.escape(c) for c in ALTERNATIVES)})\b", part.lower())
            if i > 0 and alternative is not None:  # "... if there are some, and otherwise the mop"
                out.append((part[alternative.end():].strip(" ,"), alternative.group(1), "else"))
                continue
            out.append((part, cue, role if i == 0 or role != "condition" else "consequence"))
    return out


#: "If you find the mug on the desk, and it's empty, ...": after a condition's ", and", a
#: clause with a subject of its own and a copula (a pronoun or a definite noun, then "is", "are",
#: "has", "was") says more of the situation; an imperative there ("..., and close the door") is
#: the action
_MORE_CONDITION = re.compile(r"^\W*(?:it|they|he|she|the\s+[a-z]+(?:\s+[a-z]+)?)\s+"
                             r"(?:is|are|was|were|has|have|had|looks?|seems?)\b", re.I)


def _more_conditions(pieces: list[tuple[str, str | None, str]]) -> list[tuple[str, str | None, str]]:
    """A consequence that opens with "and" or "but" and a clause of the situation up to its comma
    (`_MORE_CONDITION`: "..., and it's dirty, bin it") is that clause as more of the condition,
    then the rest as the consequence."""
    out: list[tuple[str, str | None, str]] = []
    for text, cue, role in pieces:
        joined = re.match(r"^\W*(?:and|but)\s+([^,;]+),\s*(\S.*)$", text, re.I | re.S)
        if (role == "consequence" and out and out[-1][2] == "condition" and joined is not None
                and _MORE_CONDITION.match(expand(joined.group(1))) is not None):
            out += [(joined.group(1), cue, "condition"), (joined.group(2), cue, "consequence")]
            continue
        out.append((text, cue, role))
    return out


#: the words of a condition that only points back ("if so", "if it has", "should that be the
#: case", "when that happens", "if they are"): its content is the clause before it
ANAPHORIC = frozenset({"so", "that", "this", "it", "they", "them", "is", "are", "was", "were", "has",
                       "have", "had", "do", "does", "did", "be", "been", "being", "the", "case",
                       "happen", "happens", "happened", "true", "indeed", "still", "again", "really"})


def either_state(words: list[str]) -> bool:
    """Whether the words offer a state and its opposite ("DW door open or shut, doesn't matter",
    "the lamp may be on or off"): the speaker does not know which, so the remark is uncertain."""
    for k in range(1, len(words) - 1):
        a, b = STATE_WORDS.get(words[k - 1]), STATE_WORDS.get(words[k + 1])
        if words[k] == "or" and a is not None and b is not None and a[0] == b[0] and a[1] != b[1]:
            return True
    return False


#: an existential said without its noun ("Is there a towel inside the dryer? If there is, ...",
#: "if there aren't"): the question's "there is a towel" elided, as "if so" leaves it out
ELIDED_EXISTENTIAL = re.compile(r"^there (?:is|are|was|were)(?: not)?$")


def points_back(text: str) -> bool:
    """Whether a condition's words only point back to a clause before it ("if so", "if it is not",
    "should that be the case", "when that happens", "if there is": `ELIDED_EXISTENTIAL`): its
    content is that clause's, which the reader links it to (an empty condition, the text of "if
    so", points back too)."""
    words = [w for w, _, _ in tokens(expand(text))]
    return all(w in ANAPHORIC | {"not"} for w in words) or ELIDED_EXISTENTIAL.match(" ".join(words)) is not None


# ---------------------------------------------------------------------------------------------
# The placement reader's cut: token spans with their mood
# ---------------------------------------------------------------------------------------------


@dataclass
class Span:
    """A clause of a sentence as the placement reader reads it (see the module's docstring)."""

    start: int  # token range of the sentence
    end: int
    mood: str  # "statement" | "condition" | "instruction"
    doubted: bool
    goal: bool = False  # a verbless part going on with a goal ("- the book on the couch")


#: prepositions of time that are subordinators too: "after the guests leave" is a clause, "after
#: lunch the blanket was dumped on the bench" a phrase before the statement's subject
TIME_PREPOSITIONS = frozenset({"after", "before", "until", "till", "since"})
#: words that open a clause's subject after such a phrase: a personal pronoun, "it", or a
#: determiner of a noun phrase
_SUBJECT_OPENERS = PERSONAL_SUBJECTS | frozenset({"it", "the", "a", "an", "my", "your", "his", "her", "our", "their",
                                                  "this", "these", "those"})


def fronted_time(words: list[str], verbs: frozenset[str]) -> int | None:
    """Where the subject starts after a time phrase put first with a preposition that is also a
    subordinator (`TIME_PREPOSITIONS`): "after a job it gets dumped", "after lunch the blanket
    was dumped", "since Monday the laptop has been ...": a noun phrase with no verb (`verbs`) of
    its own, then a subject's first word. None for a clause ("after the guests leave", "after
    you've used it": a verb before any second subject) or no such preposition."""
    if not words or words[0] not in TIME_PREPOSITIONS:
        return None
    for j in range(2, min(len(words), 6)):
        if words[j] in verbs or words[j] in PUNCT:
            return None
        if words[j] in _SUBJECT_OPENERS and words[j - 1] not in ARTICLES:
            return j
    return None


def clause_spans(words: list[str], lo: int, hi: int, *, verbs: frozenset[str],
                 goal_words: frozenset[str]) -> list[Span]:
    """The clauses of words[lo:hi]: cut at hard punctuation (`;`, a dash, brackets, `?`), before a
    subordinator, and at a comma or "and" that a clause opener or an imperative verb follows. A
    clause opened by a subordinator runs to its comma; a clause ending in "?" is a question.
    `verbs` are the reader's verbs (a part without one is verbless: a heading, or the goal of the
    instruction before it) and `goal_words` the words that make a clause say where things go."""
    cuts = [lo]
    for i in range(lo, hi):
        w = words[i]
        nxt = words[i + 1] if i + 1 < hi else ""
        if w in _HARD:
            cuts += [i, i + 1]
        elif w in SUBORDINATORS and i > lo and words[i - 1] not in ("in", "case") and (
                w not in MODAL_SUBORDINATORS or words[i - 1] in PUNCT | {"and", "but", "or", "then"}
                or late_should(words[lo:hi], i - lo)):
            cuts.append(i)  # "should" opens a condition only inverted: "..., should the bin be full"
        elif w == "case" and i > lo and words[i - 1] == "in":
            cuts.append(i - 1)
        elif w in (",", "and") and (nxt in CLAUSE_OPENERS or nxt in SUBORDINATORS or nxt in IMPERATIVES
                                    or (nxt in ("in",) and i + 2 < hi and words[i + 2] == "case")):
            cuts.append(i + 1 if w == "," else i)
        elif w == "," and any(c > lo and words[c] in SUBORDINATORS | {"in"} for c in cuts[-1:]):
            cuts.append(i + 1)  # the end of a fronted condition: "If the pan is hot, ..."
        elif w == "," and nxt in ("the", "a", "an") and _finite_after(words, i + 1, hi, verbs) and next(
                (x for x in words[cuts[-1]:i] if x not in LEAD_INS and x not in PUNCT), "") in IMPERATIVES:
            # "empty it, the bag is in the cupboard": after an instruction, a comma before a subject
            # and its verb ends a clause, as the text cut ends a consequence there (a verbless ", the
            # pen on the desk" goes on with its verb; a list "the sink, the fridge ... are" is one)
            cuts.append(i + 1)
    cuts.append(hi)
    out: list[Span] = []
    bounds = sorted(set(cuts))
    for a, b in zip(bounds, bounds[1:], strict=False):
        body = [w for w in words[a:b] if w not in PUNCT]
        if not body:
            continue
        question = (b < len(words) and words[b] == "?" or (b - 1 >= a and words[b - 1] == "?")) and not (
            body[0] in REQUESTS and body[1:2] == ["you"])
        # "Plate on the table: ..." (a verbless checklist item), not "The pantry has two shelves: ..."
        heading = b < len(words) and words[b] == ":" and verbless(body) and not set(body) & HOLDING
        # "... should go where it belongs - the book on the couch": a verbless part after a dash or a
        # colon goes on with the clause before it (here a goal), not a statement of its own
        follows_goal = (a > 0 and words[a - 1] in ("-", ":") and not set(body) & verbs and bool(out)
                        and (out[-1].mood == "instruction" or _says_goal(words[out[-1].start:out[-1].end],
                                                                           goal_words)))
        # "... in its place: the book on the shelf; the alarm clock on the nightstand (if it rings,
        # silence it first); the phone on the desk": a list of such goals goes on after a semicolon,
        # past an item's own condition and instruction
        follows_goal = follows_goal or (a > 0 and words[a - 1] == ";" and not set(body) & verbs
                                        and any(o.goal for o in out))
        first = next((w for w in body if w not in LEAD_INS), "")
        if first in SUBORDINATORS and fronted_time(body, verbs) is None or body[:2] == ["in", "case"] or question:
            mood = "condition"
        elif first in IMPERATIVES or body[0] in REQUESTS and body[1:2] == ["you"] or follows_goal:
            mood = "instruction"
        elif heading and not _conditional_after(words, b + 1, hi):
            mood = "condition"
        else:
            mood = "statement"
        # a habitual statement ("the ball keeps ending up on the floor") is doubted like "may"
        out.append(Span(a, b, mood, doubts(body) or habitual(body), follows_goal))
    return out


#: the participles of having that make a part before a colon a description of what a thing holds,
#: not a checklist heading ("said mezzanine comprising a stool and a box disposed on it, the method
#: comprising the steps of:", "A shelf holding two mugs and a jar: ...")
HOLDING = frozenset({"comprising", "containing", "having", "holding", "housing"})


#: verbs that say where a thing must go only before "to" ("it has to go on the desk", "the
#: kettle needs to go on the counter"); before an object they are possessive or say a want ("the
#: kitchen has a counter: a kettle on it" states where the kettle is)
SEMI_MODALS = frozenset({"has", "have", "need", "needs", "want", "wants"})


def _says_goal(words: list[str], goal_words: frozenset[str]) -> bool:
    """Whether a clause's words say where things must go (`goal_words`, a semi-modal only
    before "to": `SEMI_MODALS`)."""
    return any(w in goal_words and (w not in SEMI_MODALS or words[k + 1:k + 2] == ["to"])
               for k, w in enumerate(words))


def _conditional_after(words: list[str], start: int, hi: int) -> bool:
    """Whether the clause from `start` opens with a conditional ("towel on the shelves: if it's
    dirty -> ..."): the heading before it then only says what is spoken of and where it is."""
    body = [w for w in words[start:hi] if w not in PUNCT and w not in LEAD_INS]
    return bool(body) and (body[0] in SUBORDINATORS or body[:2] == ["in", "case"])


def _finite_after(words: list[str], start: int, hi: int, verbs: frozenset[str]) -> bool:
    """Whether the words from `start` to the next punctuation hold a finite verb of `verbs`
    (`FINITE_VERBS` or a form of "be")."""
    for w in words[start:hi]:
        if w in PUNCT:
            return False
        if w in verbs and (w in FINITE_VERBS or w in ("is", "are", "was", "were")):
            return True
    return False


def uncertain_words(words: list[str]) -> set[str]:
    """The words of `UNCERTAIN` that make a clause doubtful: a modal that opens a polite request
    ("might you scrub it", "could you wipe it") asks the listener to act, it doubts nothing of
    the scene ("the bowl might be dirty" still does)."""
    return {w for k, w in enumerate(words) if w in UNCERTAIN and not request_modal(words, k)
            and not permission(words, k)
            # a speaker's belief ("I think I left it on the shelf", "we reckon", "I'm not sure")
            or w in BELIEFS and k > 0 and words[k - 1] in PERSONAL_SUBJECTS
            or w == "sure" and words[k - 1:k] == ["not"]}


#: who a rule or a notice lets do something ("Guests may use the kettle", "A member may open a
#: wet umbrella"): people, never a thing of the scene
PERMITTED = PERSONAL_SUBJECTS | frozenset({
    "guest", "guests", "member", "members", "visitor", "visitors", "resident", "residents", "staff",
    "pupil", "pupils", "student", "students", "player", "players", "tenant", "tenants", "user", "users",
    "children", "kids", "everyone", "anyone", "customers", "campers", "volunteers"})
#: what a person "may" do that still doubts the scene: "may have left it", "may be using it",
#: "you may find it on the floor", "may well", "may need to"
_EPISTEMIC_AFTER = frozenset({"be", "have", "well", "also", "still", "already", "find", "see", "spot",
                              "notice", "discover", "come", "need", "want", "wish", "forget"})


def permission(words: list[str], k: int) -> bool:
    """Whether `words[k]` is the "may" of a permission: a person (`PERMITTED`) lets do an act
    ("Guests may use the kettle in the kitchenette", "you may open the window"): it grants, it
    doubts nothing of the scene. After a thing ("the kettle may be on"), or before a perfect, a
    "be" or a verb of finding (`_EPISTEMIC_AFTER`), "may" still doubts."""
    if words[k] != "may" or k == 0 or words[k - 1] not in PERMITTED:
        return False
    nxt = words[k + 2:k + 3] if words[k + 1:k + 2] == ["not"] else words[k + 1:k + 2]
    return bool(nxt) and nxt[0] not in _EPISTEMIC_AFTER


def request_modal(words: list[str], k: int) -> bool:
    """Whether `words[k]` is the modal of a polite request: one of `REQUESTS` right before "you"."""
    return words[k] in REQUESTS and words[k + 1:k + 2] == ["you"]


def doubts(words: list[str]) -> bool:
    """Whether the words carry a doubt ("may", "possibly", "probably"); "could you" opens a request."""
    return any(w in DOUBT and not request_modal(words, k) or w == "sure" and words[k - 1:k] == ["not"]
               for k, w in enumerate(words))  # "I'm not sure": a hedge ("make sure" is none)
