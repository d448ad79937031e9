"""One category vocabulary: every object category, from any source, mapped once to a catalog key.

Objects reach the harness from EnvSpec files written by any tool, plug-in generators, LLM replies
and imported houses, spelled as their authors like (`Couch`, `Toy Chest`, `CoffeeTable`,
`toy_boxes`, `wet wipes`). Binding, physics and the simulator all read the catalog by key, so a
name is mapped to a key exactly once, when an environment enters the harness
(`normalise_env`), by this rule:

1. The *forms* of the name, in order: the name itself, normalised (case, spaces, dashes,
   CamelCase and snake_case are one: `CoffeeTable` = `coffee table` = `coffee_table`, compared
   without underscores so `toybox` = `toy_box`); its singulars by the lemmatiser (`domain.lemmas`:
   the last word's noun lemmas, `knives` → `knife`, `glasses` → `glass`, `glasses`; then every
   word's); its plurals (`key` → `keys`, for catalog keys that are plural).
2. For the first form that names anything: a catalog key, else a catalog synonym, else an
   AI2-THOR object type (`ai2thor_type`).
3. Else the longest tail of the name's words that names a category (`red toy box` ->
   `toy_box`: the head of an English compound is its last word); the other words stay in the
   name, where role binding reads them (`domain.roles`).
4. When that names several categories (`GarbageCan`: `trash_can`, `recycling_bin`; `clock`:
   `alarm_clock`, `wall_clock`): the only one among `prefer` (a task's role categories), else the
   one whose own name is the form, else the first by name — and the choice is reported.

A name that names nothing stays as it is: the simulator treats it as an immovable obstacle and
the physics checker has no size for it; `normalise_env` lists such objects per environment.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from functools import lru_cache
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.domain.catalog import Catalog, per_catalog
from logicenveval.domain.lemmas import noun_lemma, noun_lemmas, noun_plurals
from logicenveval.model.envspec import EnvSpec

How = Literal["key", "synonym", "ai2thor_type"]
_RANK: dict[How, int] = {"key": 0, "synonym": 1, "ai2thor_type": 2}

@lru_cache(maxsize=8192)  # pure, and called per object and role on every environment judged
def snake(text: str) -> str:
    """`Toy Chest`, `toy-chest`, `ToyChest`, `TVStand` -> `toy_chest`, `tv_stand`."""
    spaced = re.sub(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", "_", text.strip())
    return re.sub(r"[^a-z0-9]+", "_", spaced.lower()).strip("_")


def _squash(key: str) -> str:
    return key.replace("_", "")


@lru_cache(maxsize=8192)
def singular(name: str) -> str:
    """The noun lemma of every word (`domain.lemmas`): `toy_boxes` -> `toy_box`, `shoes` -> `shoe`."""
    return "_".join(noun_lemma(w) for w in snake(name).split("_"))


def forms(name: str) -> list[str]:
    """The spellings `name` is looked up by, in order (snake_case, before squashing)."""
    key = snake(name)
    if not key:
        return []
    *head, last = key.split("_")
    out = [key, *("_".join([*head, s]) for s in noun_lemmas(last)), singular(key)]
    if not key.endswith("s"):
        out += ["_".join([*head, p]) for p in noun_plurals(last)]
    return list(dict.fromkeys(out))


@dataclass(frozen=True)
class Resolution:
    """Where a name led: the catalog key (None when it names nothing), how, and the rivals."""

    name: str
    category: str | None
    how: How | None = None
    #: every category the name fits when it fits several (the choice is `category`)
    candidates: tuple[str, ...] = ()

    @property
    def ambiguous(self) -> bool:
        return len(self.candidates) > 1


class Vocabulary:
    """The names of one catalog, indexed for `resolve` (build once per catalog: `vocabulary`)."""

    def __init__(self, catalog: Catalog) -> None:
        self.catalog = catalog
        self._index: dict[str, dict[How, list[str]]] = {}
        for name, cat in sorted(catalog.categories.items()):
            self._add(name, "key", name)
            for syn in cat.synonyms:
                self._add(syn, "synonym", name)
            if cat.ai2thor_type:
                self._add(cat.ai2thor_type, "ai2thor_type", name)
        self._by_type: dict[str, list[str]] = {}
        for name, cat in sorted(catalog.categories.items()):
            if cat.ai2thor_type:
                self._by_type.setdefault(_squash(snake(cat.ai2thor_type)), []).append(name)
        self._cache: dict[tuple[str, frozenset[str]], Resolution] = {}

    def _add(self, text: str, how: How, category: str) -> None:
        slot = self._index.setdefault(_squash(snake(text)), {}).setdefault(how, [])
        if category not in slot:
            slot.append(category)

    def resolve(self, name: str, prefer: Iterable[str] = ()) -> Resolution:
        """The catalog category `name` denotes (rule in the module docstring)."""
        if name in self.catalog.categories:
            return Resolution(name, name, "key")
        wanted = frozenset(prefer)
        memo = self._cache.get((name, wanted))
        if memo is None:
            memo = self._cache[(name, wanted)] = self._resolve(name, wanted)
        return memo

    def _resolve(self, name: str, prefer: frozenset[str]) -> Resolution:
        for form in forms(name):
            hit = self._index.get(_squash(form))
            if not hit:
                continue
            how = min(hit, key=_RANK.__getitem__)
            names = hit[how]
            if len(names) == 1:
                return Resolution(name, names[0], how)
            preferred = [n for n in names if n in prefer]
            own = [n for n in names if _squash(n) == _squash(form)]
            choice = (preferred if len(preferred) == 1 else own or sorted(names))[0]
            return Resolution(name, choice, how, tuple(sorted(names)))
        return Resolution(name, None)

    def resolve_type(self, object_type: str, prefer: Iterable[str] = ()) -> Resolution:
        """The catalog category of an AI2-THOR object type (a house's `objectType`).

        The categories that carry the type come first — of several, the only one among
        `prefer`, else the one named like the type (`GarbageCan` -> `trash_can`, "garbage can"),
        else the first by name; a type no category carries is read as any other name
        (`WallClock` -> `wall_clock`)."""
        key = _squash(snake(object_type))
        names = self._by_type.get(key, [])
        if not names:
            return self.resolve(object_type, prefer)
        if len(names) == 1:
            return Resolution(object_type, names[0], "ai2thor_type")
        wanted = set(prefer)
        preferred = [n for n in names if n in wanted]
        named = [n for n in names if key in {_squash(x) for x in self.names(n)}]
        choice = (preferred if len(preferred) == 1 else named or names)[0]
        return Resolution(object_type, choice, "ai2thor_type", tuple(names))

    def canonical(self, name: str, prefer: Iterable[str] = ()) -> str | None:
        """The catalog key `name` denotes, or None."""
        return self.resolve(name, prefer).category

    def names(self, category: str) -> set[str]:
        """Names (snake_case) that denote `category` as its key or a synonym."""
        cat = self.catalog.get(category)
        return {snake(n) for n in (category, *(cat.synonyms if cat else ()))}


@per_catalog
def vocabulary(catalog: Catalog) -> Vocabulary:
    """The vocabulary of `catalog`, built once (the few catalogs of a process are kept)."""
    return Vocabulary(catalog)


class CategoryReport(BaseModel):
    """What `normalise_env` did to one environment's categories."""

    model_config = ConfigDict(frozen=True)
    #: written name -> catalog key, for every name that was not a key already
    mapped: dict[str, str] = Field(default_factory=dict)
    #: written name -> the categories it fits, where it fits several (the choice is in `mapped`)
    ambiguous: dict[str, list[str]] = Field(default_factory=dict)
    #: written name that names no catalog category -> ids of its objects (kept as obstacles)
    unknown: dict[str, list[str]] = Field(default_factory=dict)

    def notes(self) -> list[str]:
        """One line per ambiguous or unknown name, for command output."""
        out = [f"category {name!r} fits {', '.join(cands)}: used {self.mapped[name]}"
               for name, cands in sorted(self.ambiguous.items())]
        out += [f"category {name!r} is not in the catalog: {', '.join(_first(ids))} kept as "
                "immovable obstacle(s) without affordances (use a catalog category or synonym, "
                "docs/catalog.md)" for name, ids in sorted(self.unknown.items())]
        return out


def _first(ids: list[str], n: int = 5) -> list[str]:
    return ids if len(ids) <= n else [*ids[:n], f"... ({len(ids) - n} more)"]


def head_noun(vocab: Vocabulary, name: str, prefer: Iterable[str] = ()) -> Resolution:
    """`vocab.resolve(name)`, else the longest tail of its words that names a category (an
    English compound's head is last: `red toy box` -> `toy_box`, `wet mop` -> `mop`); the words
    left over stay in the object's name (`source_category`), where binding reads them."""
    res = vocab.resolve(name, prefer)
    words = snake(name).split("_")
    for k in range(1, len(words)):
        if res.category is not None:
            break
        tail = vocab.resolve("_".join(words[k:]), prefer)
        if tail.category is not None:
            res = Resolution(name, tail.category, tail.how, tail.candidates)
    return res


def normalise_env(env: EnvSpec, catalog: Catalog, prefer: Iterable[str] = ()
                  ) -> tuple[EnvSpec, CategoryReport]:
    """`env` with every object category mapped to its catalog key; the written name is kept on
    the object as `source_category`. `prefer` (the task's role categories) breaks ties."""
    vocab = vocabulary(catalog)
    wanted = frozenset(prefer)
    mapped: dict[str, str] = {}
    ambiguous: dict[str, list[str]] = {}
    unknown: dict[str, list[str]] = {}
    objects = []
    changed = False
    for o in env.objects:
        res = head_noun(vocab, o.category, wanted)
        if res.category is None:
            unknown.setdefault(o.category, []).append(o.id)
        elif res.category != o.category:
            mapped[o.category] = res.category
            if res.ambiguous:
                ambiguous[o.category] = list(res.candidates)
            o = o.model_copy(update={"category": res.category, "source_category": o.category})
            changed = True
        objects.append(o)
    report = CategoryReport(mapped=mapped, ambiguous=ambiguous, unknown=unknown)
    return (env.model_copy(update={"objects": objects}) if changed else env), report
