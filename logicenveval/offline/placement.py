"""Where the description says things are, read as a careful reader (an LLM) reads it.

A description states some placements outright, whatever the situation: "a nightstand with a
lamp", "the drying rack out on the balcony", "the kitchen, where the dishwasher, the sink ... are",
"In the study the laptop belongs on the desk", "it's kept in the vanity". A model asked to build
the scene puts those objects there unless the situation it builds says otherwise. Like the
analyser, this reads only the brief (description, rooms, roles), never ground truth.
"""

from __future__ import annotations

import json
import re
import threading
from collections import OrderedDict
from collections.abc import Mapping
from typing import Any

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.offline.lexicon import COLOR_WORDS, Lexicon, Mention, tokens
from logicenveval.offline.sentences import (
    ACTIONS,
    PREP_IN,
    PREP_ON,
    STATE_WORDS,
    expand,
    split_sentences,
)

#: "it's kept in the vanity", "we keep spares in the vanity", "it lives in the vanity"
KEEP_VERBS = frozenset({"keep", "keeps", "kept", "live", "lives", "lived"})
#: words between an object and "in/on <room>" that still describe where it is
#: ("the drying rack out on the balcony", "the nearest sink is in the kitchen")
_BETWEEN = frozenset({"out", "over", "down", "up", "is", "are", "be", "still", "always"})
#: words before an object that make what follows a condition or a possibility, not a statement
#: ("if there is a pan in the kitchen", "a pan may be in the kitchen")
_UNSURE = frozenset({"if", "whether", "unless", "when", "case", "may", "might", "maybe", "perhaps",
                     "possibly", "could", "once", "while"})
_MODAL = frozenset({"may", "might", "could", "maybe", "perhaps", "possibly"})
#: prepositions of where a thing is (not "into"/"onto", which say where it goes)
_AT = frozenset({"on", "in", "inside", "atop", "upon"})
#: words that let a room introduce a list of what it holds ("a kitchen with a stove, ...",
#: "the bedroom has a bed, ...", "the kitchen, where the sink ... are", "in the kitchen there are ...")
_ROOM_LIST = frozenset({"with", "has", "have", "where", "there"})
_LEADS = frozenset({"over", "out", "down", "up", "and", "then", "also"})
_ARTICLES = frozenset({"a", "an", "the", "some", "any", "its", "their", "our", "my", "your", "this", "that"})
_INDEFINITE = frozenset({"a", "an"})


#: what a phrase says of a place: `settled` (a statement: "a nightstand with a lamp", "a kitchen
#: with a stove", "the drying rack out on the balcony"), `kept` (where it belongs: "it's kept in
#: the vanity", which the text may still doubt: "wherever else it may be lying"), `presumed` (a
#: noun phrase takes it for granted: "check the towel on the drying rack")
KINDS = frozenset({"settled", "kept", "presumed"})


#: `described_placements` per (catalog, brief, kinds), most recent last: the same brief is read
#: once per situation and per request of a task (measured: 367 readings of 25 briefs per run,
#: ~0.4 s of LogicEnvGen's generation), and the reading depends on nothing else
_READ: OrderedDict[tuple[int, str, frozenset[str]], tuple[Catalog, tuple[str, ...]]] = OrderedDict()
_READ_MAX = 64
_READ_LOCK = threading.Lock()


def described_placements(brief: Mapping[str, Any], catalog: Catalog | None = None, *,
                         kinds: frozenset[str] = KINDS) -> list[str]:
    """Facts (condition language) placing the brief's roles where its description says they are:
    `on(lamp, nightstand)`, `inside(old_towel, vanity)`, `in_room(drying_rack, balcony)`, from the
    phrases of `kinds`. One fact per object; on/inside wins over a room; the first phrase wins."""
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


def _read(brief: Mapping[str, Any], catalog: Catalog, kinds: frozenset[str]) -> list[str]:
    lex = Lexicon.build(brief, catalog)
    held: dict[str, str] = {}
    rooms: dict[str, str] = {}
    recent: list[str] = []
    for sentence in split_sentences(expand(str(brief.get("description", "")))):
        toks = tokens(sentence)
        low = sentence.lower()
        raw = [low[a:b] for _, a, b in toks]
        mentions = [m for m in lex.find_mentions(toks) if len(m.roles) == 1]
        if "kept" in kinds:
            _kept(catalog, lex, raw, mentions, recent, held)
        if "settled" in kinds:
            _with(lex, raw, toks, low, mentions, catalog, held)
        if "presumed" in kinds:
            _resting(catalog, lex, raw, mentions, held)
        if "settled" in kinds:
            _room_lists(raw, toks, low, mentions, rooms)
            _in_room(raw, mentions, rooms)
        recent += [m.roles[0] for m in mentions if m.kind == "role"]
    out = list(held.values())
    out += [f"in_room({role}, {room})" for role, room in rooms.items() if role not in held]
    return out


def _kept(catalog: Catalog, lex: Lexicon, raw: list[str], mentions: list[Mention], recent: list[str],
          held: dict[str, str]) -> None:
    """"it's kept in the vanity", "(we keep spares in the vanity cabinet)": the object spoken of
    last (or the one named after the verb) is kept in/on the holder named after a preposition."""
    for i, word in enumerate(raw):
        if word not in KEEP_VERBS:
            continue
        after = [m for m in mentions if m.kind == "role" and i < m.start <= i + 6]
        holder = next((m for m in after if _prep_before(raw, m.start) is not None), None)
        if holder is None:
            continue
        named = [m.roles[0] for m in after if m.start < holder.start]
        before = [m.roles[0] for m in mentions if m.kind == "role" and m.end <= i]
        earlier = [r for r in recent + before if r != holder.roles[0]]
        item = named[0] if named else (earlier[-1] if earlier else None)
        prep = _prep_before(raw, holder.start)
        if item is not None and prep is not None:
            fact = _contain(catalog, lex, item, holder.roles[0], prep)
            if fact is not None:
                held.setdefault(item, fact)


def _contain(catalog: Catalog, lex: Lexicon, item: str, holder: str, prep: str) -> str | None:
    """`inside(...)` for a container said "in" (or one that is no surface), `on(...)` for a surface."""
    cat = catalog.get(str(lex.roles[holder]["category"]))
    if item == holder or cat is None or not (cat.container or cat.surface):
        return None
    inside = cat.container and (prep in PREP_IN or not cat.surface)
    return f"{'inside' if inside else 'on'}({item}, {holder})"


def _prep_before(raw: list[str], start: int) -> str | None:
    """The preposition right before a mention, articles skipped ("in the vanity")."""
    j = start - 1
    while j >= 0 and raw[j] in _ARTICLES:
        j -= 1
    return raw[j] if j >= 0 and raw[j] in PREP_IN | PREP_ON else None


def _with(lex: Lexicon, raw: list[str], toks: list[tuple[str, int, int]], low: str, mentions: list[Mention],
          catalog: Catalog, held: dict[str, str]) -> None:
    """"a nightstand with a lamp", "a coffee table with a mug on it": an item on its holder (not "a
    table with a mop leaning against it", which says where the mop stands, not that it is on top)."""
    for a, b in zip(mentions, mentions[1:], strict=False):
        if a.kind != "role" or b.kind != "role" or raw[a.end:b.start] not in (["with", "a"], ["with", "an"]):
            continue
        if a.start == 0 or raw[a.start - 1] not in _INDEFINITE:
            continue
        cat = catalog.get(str(lex.roles[b.roles[0]]["category"]))
        if cat is None or not cat.pickable or not _list_ends(raw, toks, low, b.end):
            continue
        fact = _contain(catalog, lex, b.roles[0], a.roles[0], "on")
        if fact is not None:
            held.setdefault(b.roles[0], fact)


def _list_ends(raw: list[str], toks: list[tuple[str, int, int]], low: str, end: int) -> bool:
    """The noun phrase ending at token `end` is a list item: the sentence, a comma or "and" follows,
    or "on it" / "in it"."""
    if end >= len(raw) or raw[end] == "and" or raw[end:end + 2] in (["on", "it"], ["in", "it"]):
        return True
    return bool(re.search(r"[,;()]", low[toks[end - 1][2]:toks[end][1]]))


def _room_lists(raw: list[str], toks: list[tuple[str, int, int]], low: str, mentions: list[Mention],
                rooms: dict[str, str]) -> None:
    """Objects a room is said to hold: "a kitchen with a stove, a counter and a sink", "the
    bedroom has a bed, ...", "the kitchen, where the dishwasher ... are", "In the bedroom, turn off
    the table lamp ... and close the wardrobe". The list ends at the next room or parenthesis."""
    for n, m in enumerate(mentions):
        if m.kind != "room":
            continue
        lead = raw[:m.start]
        opens = (m.end < len(raw) and raw[m.end] in _ROOM_LIST) or (
            bool(lead) and lead[-1:] == ["the"] and lead[-2:-1] == ["in"]
            and all(w in _LEADS for w in lead[:-2]))
        if not opens:
            continue
        for later in mentions[n + 1:]:
            if later.kind == "room" or "(" in low[toks[m.end - 1][2]:toks[later.start][1]] \
                    or ")" in low[toks[m.end - 1][2]:toks[later.start][1]]:
                break
            if later.kind == "role" and _named(raw, later.start) and not _doubted(raw, later):
                rooms.setdefault(later.roles[0], m.roles[0])


def _doubted(raw: list[str], m: Mention) -> bool:
    """"where a pan may be", "where there might be a pan": the object only possibly there."""
    return bool(set(raw[m.end:m.end + 2]) & _MODAL or set(raw[max(0, m.start - 4):m.start]) & _UNSURE)


def _named(raw: list[str], start: int) -> bool:
    """A noun phrase with its article ("the wardrobe", "a potted plant"), not a verb ("bin the wipe")."""
    return any(w in _ARTICLES for w in raw[max(0, start - 2):start])


def _in_room(raw: list[str], mentions: list[Mention], rooms: dict[str, str]) -> None:
    """"the drying rack out on the balcony", "the nearest sink is in the kitchen": an object named
    right before "in/on <room>", unless an instruction moves it there ("put the mug in the kitchen")."""
    for a, b in zip(mentions, mentions[1:], strict=False):
        if a.kind != "role" or b.kind != "room":
            continue
        between = raw[a.end:b.start]
        if not between or between[-1] not in ("the",) and between[-1] not in PREP_IN | PREP_ON:
            continue
        words = between[:-1] if between[-1] == "the" else between
        if not words or words[-1] not in PREP_IN | PREP_ON or not all(w in _BETWEEN for w in words[:-1]):
            continue
        if _moved_or_unsure(raw, a.start):
            continue
        rooms.setdefault(a.roles[0], b.roles[0])


def _moved_or_unsure(raw: list[str], start: int) -> bool:
    """The object at `start` follows an instruction verb ("put the mug ...") or a condition /
    possibility cue a few words before ("if there is a pan ...")."""
    j = start - 1
    while j >= 0 and (raw[j] in _ARTICLES or raw[j] in STATE_WORDS or raw[j] in COLOR_WORDS
                      or re.fullmatch(r"[a-z]+(ed|est)", raw[j])):
        j -= 1  # "put a clean lunch box in the kitchen cabinet"
    return j >= 0 and raw[j] in ACTIONS or bool(set(raw[max(0, start - 4):start]) & _UNSURE)


def _resting(catalog: Catalog, lex: Lexicon, raw: list[str], mentions: list[Mention],
             held: dict[str, str]) -> None:
    """"check the towel on the drying rack": an item named right before "on/in <holder>" rests
    there, unless an instruction moves it ("hang the shirt on the rack") or a cue makes it a
    condition ("if the mug on the table is dirty" still says where the mug is; "if there is a pan
    in the kitchen" does not)."""
    for a, b in zip(mentions, mentions[1:], strict=False):
        if a.kind != "role" or b.kind != "role":
            continue
        between = raw[a.end:b.start]
        if not between or between[0] not in _AT or not all(w in _ARTICLES for w in between[1:]):
            continue
        cat = catalog.get(str(lex.roles[a.roles[0]]["category"]))
        if cat is None or not cat.pickable or _moved_or_unsure(raw, a.start) and not _described_subject(raw, a.start):
            continue
        fact = _contain(catalog, lex, a.roles[0], b.roles[0], between[0])
        if fact is not None:
            held.setdefault(a.roles[0], fact)


def _described_subject(raw: list[str], start: int) -> bool:
    """"if the mug on the coffee table is dirty": a definite object whose state is in question."""
    return start > 0 and raw[start - 1] == "the" and start > 1 and raw[start - 2] in ("if", "whether", "when")
