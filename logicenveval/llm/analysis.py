"""A small natural-language analyser of task descriptions (the offline model's reading).

It reads only what an LLM would read (the brief: description, rooms, roles) and finds:
sentences and clauses; conditional and uncertainty cues ("if", "unless", "in case", "depending
on whether", "otherwise", "may", "if available", ...); mentions grounded to roles; and facts
(on/inside/in_room/state/attr/exists) in the condition language. Facts in conditional or
uncertain clauses become *factors* (uncertain environment variables with exclusive, exhaustive
values), grouped by the role they test, which is what task decomposition and decision trees need.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.llm.lexicon import COLOR_WORDS, Lexicon, Mention, tokens

#: adjective/participle -> (state flag, polarity)
STATE_WORDS: dict[str, tuple[str, bool]] = {
    "open": ("open", True), "opened": ("open", True), "ajar": ("open", True),
    "closed": ("open", False), "shut": ("open", False),
    "on": ("toggled_on", True), "lit": ("toggled_on", True), "running": ("toggled_on", True),
    "off": ("toggled_on", False),
    "dirty": ("dirty", True), "stained": ("dirty", True), "messy": ("dirty", True),
    "dusty": ("dirty", True), "muddy": ("dirty", True), "greasy": ("dirty", True),
    "clean": ("dirty", False), "spotless": ("dirty", False),
    "wet": ("wet", True), "damp": ("wet", True), "soaked": ("wet", True), "dry": ("wet", False),
    "full": ("filled", True), "filled": ("filled", True), "empty": ("filled", False),
    "cooked": ("cooked", True), "raw": ("cooked", False), "sliced": ("sliced", True),
    "broken": ("broken", True), "cracked": ("broken", True),
}
LINKING = frozenset(
    ["is", "are", "was", "were", "be", "been", "being", "seem", "seems", "look", "looks", "appear", "appears", "get", "gets", "got", "left", "still", "already", "currently", "the", "a", "an", "it", "they", "them", "there", "some", "any", "lying", "sitting", "standing", "kept", "placed", "put", "sit", "lie", "lies", "stand", "stands", "remain", "remains", "turned", "switched"]
)
NEGATIONS = frozenset({"not", "no", "none", "never", "without", "nothing", "nobody"})
UNCERTAIN = frozenset({"may", "might", "possibly", "perhaps", "maybe", "could", "sometimes",
                       "occasionally", "potentially", "probably"})
CONDITIONAL = ("depending on whether", "depending on if", "in case", "only if", "if not",
               "if so", "if", "unless", "whenever", "when", "should there be", "should")
ELSE_CUES = ("otherwise", "else", "if not", "if there isn't", "if there aren't", "failing that")
AVAILABILITY = frozenset({"available", "any", "present", "possible", "exist", "exists", "there"})
PREP_ON = frozenset({"on", "onto", "atop", "upon"})
PREP_IN = frozenset({"in", "inside", "into", "within"})
VERB_GOALS = {
    "clean": ("dirty", False), "wipe": ("dirty", False), "mop": ("dirty", False),
    "scrub": ("dirty", False), "wash": ("dirty", False), "dust": ("dirty", False),
    "close": ("open", False), "shut": ("open", False), "open": ("open", True),
    "fill": ("filled", True), "refill": ("filled", True), "dry": ("wet", False),
}

_SENT = re.compile(r"(?<=[.!?;])\s+|\n+")
_ABBREV = re.compile(r"\b(e\.g|i\.e|etc|approx|vs)\.", re.I)


def _joined(words: list[str], a: Mention, b: Mention) -> bool:
    """Mentions `a` and `b` are items of one list (`a book or a toy`, `cups, plates and bowls`)."""
    between = words[a.end : b.start]
    return len(between) <= 3 and any(w in {"or", "and"} for w in between) and all(
        w in {"or", "and", "a", "an", "the", "some", "any", "either"} for w in between
    )


def _uncertain(text: str) -> bool:
    return any(w in UNCERTAIN for w in re.findall(r"[a-z]+", text.lower()))


def _is_negation(word: str) -> bool:
    return word in NEGATIONS or word.endswith("n't")


@dataclass(frozen=True)
class Fact:
    """An atomic condition on the initial state found in the text."""

    subject: str
    condition: str  # positive form, condition language
    kind: str  # "location" | "state" | "attr" | "exists"
    key: str = ""  # attribute key for attr facts
    negated: bool = False


@dataclass(frozen=True)
class Clause:
    text: str
    sentence: int
    cue: str | None  # conditional/uncertainty cue that governs it
    role: str  # "condition" | "consequence" | "else" | "uncertain" | "statement"
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
    consequences: list[str] = field(default_factory=list)  # texts of dependent clauses
    roles: set[str] = field(default_factory=set)  # roles of the consequences


@dataclass
class TaskAnalysis:
    sentences: list[str]
    clauses: list[Clause]
    factors: list[Factor]
    groups: list[list[str]]  # factor ids per subtask (independent groups)
    group_roles: list[set[str]]
    other_roles: set[str]  # roles in no group


def _sentences(text: str) -> list[str]:
    protected = _ABBREV.sub(lambda m: m.group(0).replace(".", "\u2024"), text)
    parts = [p.strip().replace("\u2024", ".") for p in _SENT.split(protected)]
    return [p for p in parts if p]


def _split_clauses(sentence: str) -> list[tuple[str, str | None, str]]:
    """(text, cue, role) pieces: a conditional part, its consequence, or a plain statement."""
    low = sentence.lower()
    pieces: list[tuple[str, str | None, str]] = []
    for cue in ELSE_CUES:
        if re.match(rf"^\W*{re.escape(cue)}\b", low):
            rest = sentence[re.match(rf"^\W*{re.escape(cue)}\b", low).end():]  # type: ignore[union-attr]
            if cue.startswith("if there"):
                return [(sentence, cue, "else_condition")]
            return [(rest.strip(" ,"), cue, "else")]
    best: tuple[int, str] | None = None
    for cue in CONDITIONAL:
        m = re.search(rf"\b{re.escape(cue)}\b", low)
        if m and (best is None or m.start() < best[0]):
            best = (m.start(), cue)
    if best is None:
        return [(part, None, "uncertain" if _uncertain(part) else "statement")
                for part in re.split(r",\s*(?:and|but|while)\s+|\s+but\s+", sentence) if part.strip()]
    start, cue = best
    after = re.match(r"\W*([a-z' ]{0,30}?)\W*$", low[start + len(cue):])
    if cue == "if" and after and set(after.group(1).split()) & AVAILABILITY:
        return [(sentence, "if available", "uncertain")]
    if cue == "when" and re.search(r"\bwhen (you|you're|you are|done|finished)\b", low):
        return [(sentence, None, "statement")]
    head = sentence[:start].strip(" ,")
    tail = sentence[start + len(cue):]
    if start < 3 or not head:  # "If C, then A" / "If C A"
        m = re.search(r",\s*(then\s+)?|\bthen\b", tail)
        cond, cons = (tail[: m.start()], tail[m.end():]) if m else (tail, "")
        pieces.append((cond, cue, "condition"))
        if cons.strip():
            pieces.append((cons, cue, "consequence"))
    else:  # "Do A if C" / "A, otherwise B"
        other = re.search(r"[,;]?\s*\b(otherwise|else)\b", tail)
        cond = tail[: other.start()] if other else tail
        pieces.append((head, cue, "consequence"))
        pieces.append((cond, cue, "condition"))
        if other:
            pieces.append((tail[other.end():], "otherwise", "else"))
    return pieces


class _Extractor:
    def __init__(self, lex: Lexicon) -> None:
        self.lex = lex
        self.attr_mentions: dict[tuple[str, str], list[str]] = {}

    def facts(self, text: str) -> tuple[tuple[Fact, ...], tuple[str, ...]]:
        toks = tokens(text)
        words = [t[0] for t in toks]
        mentions = self.lex.find_mentions(toks)
        facts: list[Fact] = []
        negated = any(_is_negation(w) for w in words)
        role_mentions = [m for m in mentions if m.kind == "role"]
        for idx, m in enumerate(mentions):
            if m.kind != "role":
                continue
            subjects = self._coordinated(words, mentions, idx)
            facts += self._location(words, mentions, idx, subjects, negated)
            facts += self._state(words, m, negated)
            facts += self._attribute(words, m, negated)
        if not facts and negated and role_mentions:
            facts += [Fact(r, f"exists({r})", "exists", negated=True) for r in role_mentions[0].roles]
        unique = list(dict.fromkeys(facts))
        names = tuple(dict.fromkeys(r for m in role_mentions for r in m.roles))
        return tuple(unique), names

    def _coordinated(self, words: list[str], mentions: list[Mention], idx: int) -> list[str]:
        """`a book or a toy on the floor`: the location phrase applies to every listed subject."""
        group = [idx]
        j = idx - 1
        while j >= 0 and mentions[j].kind == "role" and _joined(words, mentions[j], mentions[j + 1]):
            group.insert(0, j)
            j -= 1
        return [r for g in group for r in mentions[g].roles]

    def _location(self, words: list[str], mentions: list[Mention], idx: int, subjects: list[str],
                  negated: bool) -> list[Fact]:
        m = mentions[idx]
        if idx + 1 < len(mentions) and mentions[idx + 1].kind == "role" and _joined(words, m, mentions[idx + 1]):
            return []  # part of a coordinated list; the last item carries the location
        k = m.end
        while k < len(words) and words[k] in LINKING | NEGATIONS | {"top", "of", "still"} - PREP_ON - PREP_IN:
            k += 1
        if k >= len(words) or words[k] not in PREP_ON | PREP_IN:
            return []
        prep = words[k]
        if prep == "on" and k + 2 < len(words) and words[k + 1] == "top" and words[k + 2] == "of":
            k += 2
        target = next((t for t in mentions if t.start > k), None)
        if target is None or target.start - k > 3 or any(w in {",", "and"} for w in words[k + 1: target.start]):
            return []
        out = []
        for s in dict.fromkeys(subjects):
            for t in target.roles:
                if t == s:
                    continue
                if target.kind == "room":
                    cond, kind = f"in_room({s}, {t})", "location"
                elif prep in PREP_ON or t == "floor":
                    cond, kind = f"on({s}, {t})", "location"
                else:
                    cond, kind = f"inside({s}, {t})", "location"
                out.append(Fact(s, cond, kind, negated=negated))
        return out

    def _state(self, words: list[str], m: Mention, negated: bool) -> list[Fact]:
        out = []
        window: list[str] = []
        k = m.end
        while k < len(words) and len(window) < 4 and (words[k] in LINKING or _is_negation(words[k])):
            window.append(words[k])
            k += 1
        after = words[k] if k < len(words) else ""
        before = words[m.start - 1] if m.start > 0 else ""
        for word in (after, before):
            if word in STATE_WORDS and not (word == "on" and word == after and k + 1 < len(words)
                                            and words[k + 1] not in {",", "and", "or", ""}
                                            and self._is_place_after(words, k)):
                flag, pol = STATE_WORDS[word]
                if word in {"on", "off"} and word != after:
                    continue
                for r in m.roles:
                    out.append(Fact(r, f"state({r}, {flag})", "state", negated=negated != (not pol)))
                break
        return out

    def _is_place_after(self, words: list[str], k: int) -> bool:
        """`on` followed by a noun phrase is a preposition, not 'switched on'."""
        rest = words[k + 1 : k + 3]
        return bool(rest) and rest[0] in {"the", "a", "an", "top", "floor", "it", "its", "their"}

    def _attribute(self, words: list[str], m: Mention, negated: bool) -> list[Fact]:
        out = []
        k = m.end
        while k < len(words) and words[k] in LINKING | {"made", "of", "kind", "type", "sort"}:
            k += 1
        candidates = words[k : k + 2] if k < len(words) else []
        before = words[max(0, m.start - 1) : m.start]
        fixed = {v for attrs in self.lex.fixed.values() for v in attrs.values()}
        for w in [*candidates, *before]:
            for r in m.roles:
                if w in fixed:
                    continue
                hit = self.lex.attribute_of(r, w)
                if hit is not None:
                    key, value = hit
                    out.append(Fact(r, f"attr({r}, {key}, {value})", "attr", key=key, negated=negated))
        return out

    def attribute_classes(self, text: str) -> dict[tuple[str, str], list[str]]:
        """Attribute values used as classes (`a red box for dolls`, `novels go on the top shelf`).

        A value word of a role's category domain that is not part of a mention and not a fixed
        attribute of a nearby role is evidence that the task distinguishes objects by it.
        """
        toks = tokens(text)
        words = [t[0] for t in toks]
        mentions = self.lex.find_mentions(toks)
        covered = {i for mm in mentions for i in range(mm.start, mm.end)}
        fixed_words = {v for attrs in self.lex.fixed.values() for v in attrs.values()}
        found: dict[tuple[str, str], list[str]] = {}
        for i, w in enumerate(words):
            if i in covered or w in fixed_words:
                continue
            for role in self.lex.roles:
                hit = self.lex.attribute_of(role, w)
                if hit is None:
                    continue
                if w in COLOR_WORDS:
                    near = [mm for mm in mentions if 0 <= mm.start - i <= 2]
                    if not near or role not in near[0].roles:
                        continue  # a colour word only describes the object it precedes
                values = found.setdefault((role, hit[0]), [])
                if hit[1] not in values:
                    values.append(hit[1])
        return found


def _factor_id(fact: Fact) -> str:
    inner = fact.condition[fact.condition.index("(") + 1 : -1].split(", ")
    if fact.kind == "attr":
        return f"{fact.subject}_{fact.key}"
    if fact.kind == "state":
        return f"{fact.subject}_{inner[1]}"
    if fact.kind == "exists":
        return f"{fact.subject}_present"
    pred = fact.condition.split("(")[0]
    return f"{fact.subject}_{pred}_{inner[1]}"


def _question(fact: Fact) -> str:
    s = fact.subject.replace("_", " ")
    inner = fact.condition[fact.condition.index("(") + 1 : -1].split(", ")
    if fact.kind == "exists":
        return f"Is there a {s}?"
    if fact.kind == "state":
        return f"Is the {s} {inner[1].replace('_', ' ')}?"
    if fact.kind == "attr":
        return f"What is the {fact.key} of the {s}?"
    pred = fact.condition.split("(")[0].replace("_", " ")
    return f"Is the {s} {pred} the {inner[1].replace('_', ' ')}?"


def analyse(brief: Mapping[str, Any], catalog: Catalog | None = None) -> TaskAnalysis:
    """Analyse a task brief (`id`, `description`, `rooms`, `roles`)."""
    lex = Lexicon.build(brief, catalog or load_catalog())
    ex = _Extractor(lex)
    sentences = _sentences(str(brief["description"]))
    clauses: list[Clause] = []
    for si, sent in enumerate(sentences):
        for text, cue, role in _split_clauses(sent):
            facts, names = ex.facts(text)
            clauses.append(Clause(text, si, cue, role, facts, names))
    factors: dict[str, Factor] = {}
    last: Factor | None = None

    def add(fact: Fact, order: int) -> Factor:
        fid = _factor_id(fact)
        if fid not in factors:
            values = ({"yes": fact.condition, "no": f"not {fact.condition}"} if fact.kind != "attr"
                      else {})
            factors[fid] = Factor(fid, fact.subject, _question(fact), values, fact.kind, order)
        return factors[fid]

    attr_values: dict[tuple[str, str], list[str]] = {}
    for ci, cl in enumerate(clauses):
        if cl.role in ("condition", "uncertain", "else_condition"):
            for fact in cl.facts:
                f = add(fact, ci)
                if fact.kind == "attr":
                    vals = attr_values.setdefault((fact.subject, fact.key), [])
                    value = fact.condition.rsplit(", ", 1)[1][:-1]
                    if value not in vals:
                        vals.append(value)
                last = f
        elif cl.role in ("consequence", "else") and last is not None:
            last.consequences.append(cl.text)
            last.roles |= set(cl.mentions)
    for (role, key), values in ex.attribute_classes(str(brief["description"])).items():
        vals = attr_values.setdefault((role, key), [])
        vals += [v for v in values if v not in vals]
        add(Fact(role, f"attr({role}, {key}, {values[0]})", "attr", key=key), len(clauses))
    for (role, key), values in attr_values.items():
        fid = f"{role}_{key}"
        real = [v for v in values if v != "other"]
        domain = {v: f"attr({role}, {key}, {v})" for v in real}
        domain["other"] = " and ".join(f"not attr({role}, {key}, {v})" for v in real)
        factors[fid].values = domain
    _drop_redundant_existence(factors)
    ordered = sorted(factors.values(), key=lambda f: (f.order, f.id))
    groups, group_roles = _group(ordered)
    mentioned = {r for cl in clauses for r in cl.mentions}
    covered = set().union(*group_roles) if group_roles else set()
    return TaskAnalysis(sentences, clauses, ordered, groups, group_roles,
                        (mentioned | set(lex.roles)) - covered)


def _drop_redundant_existence(factors: dict[str, Factor]) -> None:
    """`if there aren't any wipes` refers back to the wipes' location factor when there is one."""
    for fid in [f for f, x in factors.items() if x.kind == "exists"]:
        subject = factors[fid].subject
        if any(x.subject == subject and x.kind == "location" for x in factors.values()):
            consequences = factors.pop(fid).consequences
            loc = next(x for x in factors.values() if x.subject == subject and x.kind == "location")
            loc.consequences += consequences


def _group(factors: list[Factor]) -> tuple[list[list[str]], list[set[str]]]:
    """Factors that test the same subject role belong to one subtask."""
    by_subject: dict[str, list[str]] = {}
    for f in factors:
        by_subject.setdefault(f.subject, []).append(f.id)
    groups = list(by_subject.values())
    roles = [{factors_by_id.subject for factors_by_id in factors if factors_by_id.id in g} for g in groups]
    for g, rs in zip(groups, roles, strict=True):
        for f in factors:
            if f.id in g:
                rs |= f.roles
    return groups, roles


def nest(factors: list[Factor]) -> dict[str, Any]:
    """A decision tree over one subtask's factors: location/existence first, then the others.

    Later factors are asked only where the object is where the task handles it (the positive
    branch of a location factor); other factors nest under every branch.
    """
    rank = {"exists": 0, "location": 1, "state": 2, "attr": 3}
    ordered = sorted(factors, key=lambda f: (rank[f.kind], f.order))

    def build(i: int) -> dict[str, Any]:
        if i == len(ordered):
            return {"plan": [], "goal": "true"}
        f = ordered[i]
        branches = {}
        for value in f.values:
            stop = f.kind in ("location", "exists") and value == "no"
            branches[value] = {"plan": [], "goal": "true"} if stop else build(i + 1)
        return {"var": f.id, "query": f.question, "branches": branches}

    return build(0)
