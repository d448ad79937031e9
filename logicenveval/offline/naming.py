"""The offline model's answer to `name_objects`: the objects a description names, read as a
careful reader would list them (the request every method asks first under `--brief description`,
`generators.brief`). Its rules (determiners, counts, spare/packaging words, verbs that are also
nouns) are the data tables below, beside the code that applies them."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

from logicenveval.domain.catalog import Catalog, load_catalog, per_catalog
from logicenveval.domain.categories import vocabulary
from logicenveval.llm.base import ChatRequest
from logicenveval.model.rooms import room_type_of
from logicenveval.offline.handlers import handler
from logicenveval.offline.lexicon import COLOR_WORDS, tokens, words_of


@handler("name_objects")
def _offline_name_objects(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """The objects the description names, as a careful reader would list them (`name_objects`)."""
    task = payload["task"]
    return {"objects": name_objects(task["description"], load_catalog(), rooms=task.get("rooms", ()))}


#: words before a noun that say which one, not what it is like
_DETERMINERS = frozenset({"a", "an", "the", "no", "any", "some", "its", "their", "our", "my", "your",
                          "this", "that", "each", "every", "one", "other"})
_COUNTS = {"two": 2, "three": 3, "four": 4}
#: "a fresh bag ... no spare bag": one more of the kind, told apart from the one in use
_SPARE = frozenset({"spare", "fresh", "new", "extra"})
#: "a bag of pet food", "a pack of wipes": the contents are the object
_PACKAGING = frozenset({"bag", "pack", "packet", "carton"})
#: nouns that are verbs as often ("you can use", "switch it off"): objects only after a determiner
_ALSO_VERBS = frozenset({"can", "throw", "stand", "switch", "set", "press", "iron", "watch", "hook"})
#: words too common to say which of several categories a bare noun means
_NOT_CONTEXT = frozenset({"floor", "wall", "ceiling", "room"})
#: "the bookshelf's three levels hold novels, essays and other books"
_LEVELS = re.compile(r"(?:two|three|four) (?:levels|shelves|shelf levels) (?:hold|are for|keep) "
                     r"([a-z ,]+?)(?: respectively)?[.;]")


@dataclass
class _Kind:
    """What the description says of one category: generic mentions and told-apart instances."""

    generic: bool = False
    count: int = 0
    #: (name, attributes) of each instance, in order of first mention
    instances: dict[str, dict[str, str]] = field(default_factory=dict)
    purposes: set[str] = field(default_factory=set)


@per_catalog
def _phrase_tables(catalog: Catalog) -> tuple[dict[tuple[str, ...], str], dict[str, list[str]], int]:
    """Each category name and synonym as words -> its category; last word -> the categories it
    ends; the longest phrase's length: ~500 names, the same for every description the process
    reads. Callers only read them."""
    phrases: dict[tuple[str, ...], str] = {}
    heads: dict[str, list[str]] = {}
    for name, cat in catalog.categories.items():
        for text in (name, *cat.synonyms):
            phrase = words_of(text)
            phrases.setdefault(phrase, name)
            heads.setdefault(phrase[-1], []).append(name)
    return phrases, heads, max(len(p) for p in phrases)


def name_objects(description: str, catalog: Catalog, rooms: Iterable[str] = ()) -> list[dict[str, Any]]:
    """Catalog categories and synonyms named in the description (longest match), read as a careful
    reader would: a bare noun means a kind already named ("the box" after "the red toy box") or,
    among several kinds, the one its context fits ("a nightstand with a lamp": a bedside lamp);
    objects of one kind told apart by colour ("a red one", "the blue toy box"), by purpose ("two
    pet bowls, one for food and one for water"), as a spare ("the spare roll") or as levels of a
    shelf become one object each, named for what tells them apart, with the colour as attribute."""
    phrases, heads, longest = _phrase_tables(catalog)
    text = description.lower()
    toks = tokens(description)
    words = [w for w, _, _ in toks]
    raw = [text[a:b] for _, a, b in toks]
    context = _context(words, phrases, longest, catalog)
    room_types = {room_type_of(r) for r in rooms}
    kinds: dict[str, _Kind] = {}
    last_counted: tuple[str, int] | None = None  # (category, token index) of "two <kind>"
    last_colored: str | None = None
    recent: list[str] = []  # kinds in order of their last mention

    def instance(category: str, name: str, attrs: dict[str, str]) -> None:
        kinds.setdefault(category, _Kind()).instances.setdefault(name, attrs)

    shelf = vocabulary(catalog).canonical("shelf")
    for m in _LEVELS.finditer(text):
        for item in re.split(r",\s*(?:and\s+)?|\s+and\s+", m.group(1).strip()):
            if item.split() and shelf is not None:
                instance(shelf, f"shelf_{item.split()[0]}", {})
    i = 0
    while i < len(words):
        prev = words[i - 1] if i > 0 else ""
        if words[i] == "one" and prev in COLOR_WORDS and last_colored is not None:
            instance(last_colored, f"{prev}_{last_colored}", {"color": prev})
            i += 1
            continue
        if words[i] == "one" and i + 2 < len(words) and words[i + 1] == "for" and last_counted \
                and i - last_counted[1] <= 12:
            counted, purpose = last_counted[0], raw[i + 2]
            kinds[counted].purposes.add(purpose)
            instance(counted, f"{purpose}_{words_of(counted)[-1]}", {})
            i += 3
            continue
        category: str | None
        n, category = next(((n, phrases[tuple(words[i:i + n])]) for n in range(min(longest, len(words) - i), 0, -1)
                            if tuple(words[i:i + n]) in phrases), (1, None))
        if n == 1:
            if (words[i] in _PACKAGING and i + 1 < len(words) and words[i + 1] == "of"
                    or words[i] in _ALSO_VERBS and prev not in _DETERMINERS and prev not in COLOR_WORDS):
                i += 1
                continue
            category = _bare_noun(words[i], category, prev, heads, recent, context, room_types, catalog)
        if category is None:
            i += 1
            continue
        kind = kinds.setdefault(category, _Kind())
        recent = [c for c in recent if c != category] + [category]
        allowed = catalog.categories[category].attributes.get("color", [])
        if prev in COLOR_WORDS and prev in allowed:
            instance(category, f"{prev}_{category}", {"color": prev})
            last_colored = category
        elif prev in _SPARE:
            instance(category, f"spare_{words[i + n - 1]}", {})
        elif prev in kind.purposes:
            instance(category, f"{prev}_{words[i + n - 1]}", {})
        else:
            kind.generic = True
            if prev in _COUNTS:
                kind.count = _COUNTS[prev]
                last_counted = (category, i)
                if allowed:
                    last_colored = category
        i += n
    found: list[dict[str, Any]] = []
    for category, kind in kinds.items():
        told_apart = len(kind.instances) >= max(2, kind.count)
        if kind.generic and not told_apart:
            found.append({"name": _snake(category), "category": category, "attributes": {}})
        found += [{"name": _snake(name), "category": category, "attributes": attrs}
                  for name, attrs in kind.instances.items()]
    return list({o["name"]: o for o in found}.values())


def _snake(name: str) -> str:
    return re.sub(r"[^a-z0-9_]", "_", name)


def _context(words: list[str], phrases: dict[tuple[str, ...], str], longest: int,
             catalog: Catalog) -> set[str]:
    """The description's words and the words of every name of the kinds it names outright."""
    out = set(words)
    for i in range(len(words)):
        for n in range(min(longest, len(words) - i), 0, -1):
            category = phrases.get(tuple(words[i:i + n]))
            if category is not None:
                for text in (category, *catalog.categories[category].synonyms):
                    out.update(words_of(text))
                break
    return out - _NOT_CONTEXT


def _bare_noun(word: str, exact: str | None, prev: str, heads: dict[str, list[str]], recent: list[str],
               context: set[str], room_types: set[str], catalog: Catalog) -> str | None:
    """The kind a one-word noun means: the kind last named that it ends, else the kind whose other
    name words its context holds most (the exact name wins ties; then the kind most specific to
    the task's rooms). A noun that names no kind itself must follow a determiner ("a lamp")."""
    options = list(dict.fromkeys(heads.get(word, [])))
    named = [c for c in reversed(recent) if c in options]
    if named:
        return named[0]
    if exact is None and (not options or prev not in _DETERMINERS):
        return None

    def score(category: str) -> tuple[int, int, int]:
        cat = catalog.categories[category]
        others = {w for text in (category, *cat.synonyms) for w in words_of(text)} - {word}
        rooms = set(cat.rooms)
        return (len(others & context), category == exact,
                -len(rooms) if rooms & room_types else -1000)

    candidates = options if options else ([exact] if exact is not None else [])
    return max(candidates, key=score)
