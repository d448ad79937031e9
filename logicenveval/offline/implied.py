"""Conditions a sentence implies without a conditional cue, spelled out for the factor reader.

People rarely write "if the torch is on, switch it off". They write that it *has to be* off,
that the instruction holds *if need be*, or that *any on the floor* go in the box; each says the
situation is in doubt as plainly as an "if" does. Each rewrite here turns one such grammatical
form into the conditional the analyser already reads (as `analysis._ensured` does for "make sure
it is off"), so the form gets a factor and no new reading path. Only the factor reader reads
these rewrites: the placement reader and the naming see the text as written.
"""

from __future__ import annotations

import re

from logicenveval.offline.sentences import ARROW_MARK

#: the verbs of obligation before "be" that say a state must hold: "has to be", "must be",
#: "needs to be" ("should be" is a norm the text often answers itself: "should be on - if it's
#: off, ..."; "is not to be left" is a negative norm the analyser reads already)
OBLIGATIONS = ("has to", "have to", "must", "needs to", "need to", "ought to")
#: "The torch has to be turned off when you go", "The lamp must be switched off before you
#: leave": a definite subject obliged to a state, with no condition of its own after it, reads as
#: "if the torch is not turned off, make the torch turned off". A verb participle with its "e"
#: dropped ("turnd", as a child or a fast typist writes it) is the participle.
_OBLIGED = re.compile(
    r"(?P<lead>^\W*|[;:,]\s*|\s[-\u2013\u2014]\s+|\b(?:and|but|so)\s+)"
    r"(?P<subj>it|they|(?:the|your|my|our|his|her|their)\s+[a-z][a-z ]*?)\s+"
    r"(?P<must>" + "|".join(o.replace(" ", r"\s+") for o in OBLIGATIONS) + r")\s+(?:always\s+)?be\s+"
    r"(?P<state>(?:switch|turn|power)e?d\s+(?:off|on|down)|shut\s+(?:off|down)|off|on|open|closed|shut|locked|unlocked)\b"
    r"(?!\s+(?:the|a|an|its|their|your|my|top|to|of|in|into|on|onto)\b)"
    r"(?![^.;!?]*\b(?:if|unless|otherwise)\b)[^.;!?]*",
    re.I)
_PLURAL_OBLIGATIONS = frozenset({"have to", "need to"})


def _obliged(m: re.Match[str]) -> str:
    subj, must = m.group("subj"), " ".join(m.group("must").lower().split())
    be = "are" if subj.lower() == "they" or must in _PLURAL_OBLIGATIONS else "is"
    state = re.sub(r"^(switch|turn|power)e?d", r"\1ed", m.group("state"), flags=re.I)
    return f"{m.group('lead')}if {subj} {be} not {state}, make {subj} {state}"


#: the words that make an instruction hold only when it is needed: "switch it off at the wall if
#: need be", "close it if necessary", "turn the heater off if needed", "if required"
NEED_WORDS = ("need be", "needs be", "necessary", "needed", "required", "need")
#: an instruction that sets a state and then says "if need be": the condition is that the state it
#: sets does not hold yet ("switch it off at the wall if need be": if it is not off)
_IF_NEED_BE = re.compile(
    r"\b(?:(?P<verb>switch|turn|power|flick|shut)\s+(?P<obj>it|them|(?:the|your|my|our)\s+[a-z][a-z ]*?)\s+(?P<part>off|on|down)"
    r"|(?P<bare>close|open|shut|lock|unlock)\s+(?P<bobj>it|them|(?:the|your|my|our)\s+[a-z][a-z ]*?))\b"
    r"(?P<mid>[^.;!?]*?)\s*,?\s+if\s+(?:" + "|".join(w.replace(" ", r"\s+") for w in NEED_WORDS) + r")\b",
    re.I)
#: what each bare verb of "close it if necessary" leaves the thing
_BARE_RESULT = {"close": "closed", "open": "open", "shut": "shut", "lock": "locked", "unlock": "unlocked"}


def _if_needed(m: re.Match[str]) -> str:
    if m.group("verb"):
        obj, state = m.group("obj"), m.group("part").lower()
        state = "off" if state == "down" else state
    else:
        obj, state = m.group("bobj"), _BARE_RESULT[m.group("bare").lower()]
    be = "are" if obj.lower() == "them" else "is"
    subj = "they" if obj.lower() == "them" else obj
    return f"{m.group(0)[:m.start('mid') - m.start()]}{m.group('mid')} if {subj} {be} not {state}"


#: "Tennis rackets: any on the floor go in the storage box", "Books - any left on the floor go
#: back on the shelf": a plural heading and "any" with a place after it is a condition on each
#: of the heading's things ("any tennis rackets on the floor go ..." is read as a thing in doubt
#: at that place, as "a tennis racket on the floor goes ..." is)
_ANY_AT = re.compile(
    r"(?P<lead>^[ \t]*(?:[-*\u2022]\s*)?)(?P<head>[A-Za-z][A-Za-z' ]{1,40}?s)(?P<sep>\s*(?::|\s[-\u2013\u2014])\s*)"
    r"(?P<any>any)\s+(?=(?:(?:left|lying|found|sitting|still)\s+)?(?:on|in|under|inside|by|near)\s)",
    re.I | re.M)


def any_at(text: str) -> str:
    """`text` with "any" at a place after a plural heading given the heading's noun (`_ANY_AT`),
    read before the text is cut into sentences, since the heading's colon ends one."""
    return _ANY_AT.sub(lambda m: f"{m.group('lead')}{m.group('head')}{m.group('sep')}any "
                                 f"{m.group('head').lower()} ", text)


#: "down there", "up there", "over there" point back to a place as "there" does ("The band kept
#: dumping them on the floor - if they're still down there, ..."); the direction only says where
#: that place lies from the speaker
_DIRECTED_THERE = re.compile(r"\b(?:down|up|over|out)\s+(?=there\b)", re.I)
#: "Any you find there go in the grey box", "Any ones we spot down there belong in the bin": a
#: relative clause of coming upon with "any" as its head is the condition "if you find any there",
#: and what follows is its instruction
_ANY_FOUND = re.compile(
    r"\b(?P<any>any)(?:\s+ones?)?(?:\s+that)?\s+(?P<who>you|we|u)\s+(?P<verb>find|see|spot|notice)\s+there\s+"
    r"(?P<go>go|goes|belong|belongs|should\s+go|get\s+put|are\s+to\s+go)\b",
    re.I)

#: "Whichever drawer is open, close it": a fronted free relative with "whichever" is the condition
#: "if any drawer is open" (a quantified noun phrase: every drawer the text names is asked of)
_WHICHEVER = re.compile(r"^(?P<lead>\W*)whichever\s+(?P<rest>[a-z][a-z' -]*?\s+(?:is|are|was|were|has|have|looks?|"
                        r"seems?|gets?|got)\b[^,;:]*,)", re.I)


#: verbs of looking a thing over: an instruction to check a thing at a place leaves whether it is
#: there to the one who looks ("check the towel on the drying rack: once it's dry, ...")
INSPECTING = ("check", "examine", "inspect", "look at", "have a look at", "take a look at")
#: "check the towel on the drying rack: once it's dry, ...", "Examine the mug in the sink.": an
#: inspecting verb, a definite thing and the place it is looked at, the clause ending there, is
#: "check the towel if it is on the drying rack" (a check that goes on, "check the lamp on the
#: desk is off", is a check of a state, read by `analysis._ensured`)
_NOUN_WORD = r"(?!(?:is|are|was|were|has|have|be|been|looks?|seems?|and|or|then|before|after|when|if|on|in)\b)[a-z][a-z-]*"
_CHECK_AT = re.compile(
    r"\b(?P<verb>" + "|".join(v.replace(" ", r"\s+") for v in INSPECTING) + r")\s+"
    rf"(?P<thing>(?:the|your|my|our)(?:\s+{_NOUN_WORD}){{1,3}})\s+(?P<prep>on|in|inside)\s+"
    rf"(?P<place>(?:the|your|my|our)(?:\s+{_NOUN_WORD}){{1,3}})\s*(?=[:;,.!?\u2013\u2014]|\s-\s|$)",
    re.I | re.M)


#: colour adjectives used as plural nouns, as laundry is sorted ("dirty whites go in the machine,
#: darks in the hamper"): each is "<colour> ones", the kind the sentence speaks of in that colour
COLOUR_NOUNS = {"whites": "white", "darks": "dark", "coloureds": "coloured", "colors": "colored",
                "colours": "coloured"}
#: a colour noun as a subject, after the start of a clause or a state adjective and before the
#: verb that moves it ("dirty whites go into ...", "Whites -> machine"): not "egg whites"
_COLOUR_NOUN = re.compile(
    r"(?P<lead>(?:^|[;:,(]|\band|\bbut)\s*(?:(?:dirty|clean|wet|dry|washed|soiled)\s+)?)"
    r"(?P<noun>" + "|".join(COLOUR_NOUNS) + r")(?=\s+(?:go|goes|get|gets|should|must|belong|are|need|into|in|to)\b"
    r"|\s*(?:->|\u2192|:))", re.I | re.M)


#: a holder and a relative clause of place whose subject is a hedged "there" ("a bed, where there
#: may lie a book", "a console table, on which there might be a set of keys", "a drawer, in which
#: there could be a sock"): the things after it may be at the holder, as after "On the bed there
#: may lie"; read so, the relative's preposition kept ("where" as "on": a place one finds things at)
_WHERE_THERE = re.compile(
    r"\b(?P<np>(?:a|an|the|my|your|our|his|her|their)\s+[a-z][a-z-]*(?:\s+[a-z][a-z-]*){0,2}?)\s*,?\s+"
    r"(?P<rel>where|(?P<prep>on|upon|in|inside|on\s+top\s+of)\s+which)\s+there\s+"
    r"(?=(?:(?:often|sometimes|also|still|well|perhaps|possibly|probably)\s+)*"
    r"(?:may|might|could|can|will|would)\s+(?:(?:also|still|well|even)\s+)*(?:be|lie|sit|stand|rest|hang)\b)",
    re.I)
#: the preposition each relative is read with
_WHERE_PREPS = {"where": "on", "on": "on", "upon": "on", "on top of": "on", "in": "in", "inside": "in"}


def _where_there(m: re.Match[str]) -> str:
    noun = m.group("np").split(None, 1)[1]
    prep = _WHERE_PREPS[" ".join((m.group("prep") or "where").lower().split())]
    return f"{m.group('np')}; {prep} the {noun} there "


def _any_found(m: re.Match[str]) -> str:
    cue = "If" if m.group("any")[0].isupper() else "if"
    return f"{cue} {m.group('who')} {m.group('verb')} any there, they {m.group('go')}"


#: a spaced "=" between a verbless description and what to do ("shirt not in the basket = nothing
#: to do", "lamp on = switch it off") reads as an arrow does: the case, then its answer
_EQUALS = re.compile(r"(?<=[A-Za-z])\s+=\s+(?=[A-Za-z])")
#: an en or em dash opening a line is a bullet, as "-" is ("– shirt not in the basket = nothing
#: to do" in a bullet journal); left as it is, it hides the heading after it
_DASH_BULLET = re.compile(r"^(\s*)[\u2013\u2014](?=\s)", re.M)


#: a case said as "<adjective> one" before its arrow, the article dropped as a note drops it
#: ("dirty one -> sink", "ripe one -> fridge"): "a dirty one", so "one" is the thing spoken of
_BARE_ONE = re.compile(rf"(^|[;:,]\s*)([a-z]+)(\s+ones?\s*{ARROW_MARK})", re.I | re.M)


def _cases(sentence: str) -> str:
    """`sentence` with the article of an arrow list's cases restored (`_BARE_ONE`)."""
    return _BARE_ONE.sub(lambda m: m.group(0) if m.group(2).lower() in ("a", "an", "the", "any", "each", "no")
                         else f"{m.group(1)}a {m.group(2)}{m.group(3)}", sentence)


def implied(sentence: str) -> str:
    """`sentence` with the conditions its grammar implies spelled out as conditionals: an
    instruction that holds "if need be" (`_IF_NEED_BE`), an obligation to a state (`_OBLIGED`)
    "any you find there go ..." (`_ANY_FOUND`), "a bed, where there may lie ..." (`_WHERE_THERE`), "whichever X is Y, ..." (`_WHICHEVER`) and "check
    the X on the Y" (`_CHECK_AT`); "down there" as "there"
    (`_DIRECTED_THERE`), a spaced "=" as an arrow (`_EQUALS`), a dash opening a line as a bullet
    (`_DASH_BULLET`), "a" before a case "<adjective> one ->" (`_cases`); any other sentence as it is ("on top of" is "on" for every reader:
    `sentences.expand`)."""
    said = _cases(_EQUALS.sub(" -> ", _DASH_BULLET.sub(r"\1-", sentence)))
    said = _ANY_FOUND.sub(_any_found, _DIRECTED_THERE.sub("", said))
    said = _WHERE_THERE.sub(_where_there, said)
    said = _COLOUR_NOUN.sub(lambda m: f"{m.group('lead')}{COLOUR_NOUNS[m.group('noun').lower()]} ones", said)
    said = _CHECK_AT.sub(lambda m: f"{m.group('verb')} {m.group('thing')} if it is {m.group('prep')} "
                                   f"{m.group('place')}", said)
    said = _WHICHEVER.sub(lambda m: f"{m.group('lead')}{'I' if m.group(0).lstrip()[:1].isupper() else 'i'}f any "
                                    f"{m.group('rest')}", said)
    return _OBLIGED.sub(_obliged, _IF_NEED_BE.sub(_if_needed, said))
