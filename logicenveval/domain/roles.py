"""Binding task roles to the objects of an environment: one rule for every method and command.

Environments made by other tools (another generator, an imported ProcTHOR house, an LLM told
only the description) usually carry no `roles` map, yet the GT trees and the policies speak
about roles. The harness binds them by what the environment says of each object, by one rule
that never guesses and that `evaluate`, `lint`, `import-house`, `simulate --env` and every
generator's run share (`prepare_env`):

1. **Explicit map, checked.** A role that the EnvSpec's `roles` (or `--roles ROLE=ID`, `given`)
   maps keeps its mapping when the object is of the role's category and plays no other role;
   a mapping to null says the role is absent. An entry of the EnvSpec that fails the check is
   refused (`refused` says why) and the role is bound by meaning as if unmapped, so a forged map
   gains nothing; a failing `--roles` entry is bad input (`ConfigError`).
2. **Category.** An object is a *candidate* of a role when its category names the role's
   category in the one vocabulary (`domain.categories`: ``Toy Chest``, ``toy_chests`` and
   ``toy_box`` all name ``toy_box``) and it agrees with every attribute of the role: it states
   the attribute with the same value, or it does not state it and its name says the value
   (``red toy box`` or id ``red_box`` say ``color=red``; ``novel_shelf`` says
   ``purpose=novels``). Words are compared lemmatised (lemminflect), in any order.
3. Of several candidates, evidence decides, in this order: the one that **states the role's
   attributes** (`"purpose": "novels"`); the object whose **id** is the role's name; the one
   whose **name words** hold the role name's distinctive words (``novel_shelf`` and
   ``shelf for novels`` for role ``shelf_novels``); last, the one the environment's own map
   lists as a task object under a name of its own (``task object``: a generator told only the
   description names roles its own way, ``dirty_mark`` for the task's ``mark``, and may add a
   second stain ``dirty_mark_1`` as clutter; what it said it made for the task decides, as a
   shopper's list says which of two mugs is the one bought). Roles that evidence singles an
   object out for are bound before those that only their category speaks for.
4. One candidate: the role binds to it. Objects bound to a role are no longer candidates of the
   others; this is repeated until nothing changes, so a role left with one candidate after the
   others took theirs is bound too. When two roles are left with the same single object,
   neither is bound.
5. Several candidates and nothing to tell them apart (shelves named only top/middle/bottom for
   roles without attributes): the role is *ambiguous*, one problem names it and its candidates,
   and the environment is not well-formed: the judge never picks one silently. No candidate
   (shelves that state no `purpose` for roles that have one): the role stays unbound (null),
   which the GT evaluation accepts only for an optional role or where the reached path says the
   role does not exist; `why` then says in one message what the objects there lack (`top has
   no purpose; ... state purpose on the object meant`).

Every role's outcome is on record (`RoleBinding.record`): the object and the reason
(``explicit map``, ``id``, ``attribute``, ``name words``, ``task object``, ``category``: the one
candidate left),
written to each sample of `samples.jsonl` and shown on the per-task page.

Public API::

    bind_roles(env: EnvSpec, roles: Mapping[str, Role], catalog: Catalog | None = None)
        -> RoleBinding

`roles` is `task.roles` or `brief.roles` (a generator only sees the brief). `RoleBinding` has
`roles` (the complete map, given and bound), `bound` (only the roles bound here), `candidates`
(role -> object ids for every ambiguous role), `problems` (one message per ambiguous role),
`why` (one message per role left unbound with no candidate: what the nearest objects lack),
`refused` (one message per explicit entry refused), `reasons` (role -> why it has its object),
`well_formed`, `record` and `apply(env) -> EnvSpec` (the env with `roles` replaced by the
complete map).
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from functools import lru_cache
from typing import Literal

from lemminflect import getLemma
from pydantic import BaseModel, ConfigDict, Field

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.domain.categories import (
    CategoryReport,
    normalise_env,
    singular,
    snake,
    vocabulary,
)
from logicenveval.errors import ConfigError
from logicenveval.model.envspec import EnvObject, EnvSpec
from logicenveval.model.task import Role

#: words of an object's name that say nothing about which object it is
_NOISE = frozenset({"a", "an", "the", "of", "obj", "object", "item", "with", "and", "for", "to", "in",
                    "on", "at", "by"})
#: how many nearest objects an unbound role's message names
_NEAREST = 3

#: why a role has its object (or none), as recorded in every sample
Reason = Literal["explicit map", "id", "attribute", "name words", "task object", "category", "absent", "ambiguous"]


class RoleChoice(BaseModel):
    """One role's outcome: the object that plays it (None: nobody) and the reason."""

    model_config = ConfigDict(frozen=True)
    object: str | None = None
    reason: Reason


class RoleBinding(BaseModel):
    """The outcome of binding: a complete role map plus what could not be decided."""

    model_config = ConfigDict(frozen=True)
    roles: dict[str, str | None] = Field(default_factory=dict)
    bound: dict[str, str | None] = Field(default_factory=dict)
    candidates: dict[str, list[str]] = Field(default_factory=dict)
    problems: list[str] = Field(default_factory=list)
    #: role left unbound with no candidate -> what the nearest objects lack (one message)
    why: dict[str, str] = Field(default_factory=dict)
    #: one message per entry of the EnvSpec's own map that the check refused
    refused: list[str] = Field(default_factory=list)
    #: role -> why it has its object (`Reason`), for every role of the task
    reasons: dict[str, Reason] = Field(default_factory=dict)

    @property
    def well_formed(self) -> bool:
        return not self.problems

    def record(self) -> dict[str, RoleChoice]:
        """Role -> object and reason, for every role bound here or mapped explicitly."""
        return {name: RoleChoice(object=self.roles.get(name), reason=reason)
                for name, reason in self.reasons.items()}

    def apply(self, env: EnvSpec) -> EnvSpec:
        """`env` with its `roles` map replaced by the complete one (unchanged when equal)."""
        if dict(env.roles) == self.roles:
            return env
        return env.model_copy(update={"roles": dict(self.roles)})


def category_names(category: str, catalog: Catalog) -> set[str]:
    """Names (snake_case) that denote `category`: itself and its catalog synonyms."""
    return vocabulary(catalog).names(category)


def name_words(obj: EnvObject) -> frozenset[str]:
    """The words an object's name says: its id and its category as written (lemmas)."""
    written = getattr(obj, "source_category", None)
    text = " ".join(str(t) for t in (obj.id, written or obj.category))
    return _words(text)


@lru_cache(maxsize=8192)  # pure; every object's name is read for every role it may bind
def _words(text: str) -> frozenset[str]:
    """The lemmas of the words of `text` (`shelf for novels` -> {shelf, novel}), noise and
    numbers left out, so that names compare in any order and any number."""
    return frozenset(_lemma(w) for w in snake(text).split("_")
                     if w and not w.isdigit() and w not in _NOISE)


@lru_cache(maxsize=8192)
def _lemma(word: str) -> str:
    """The noun lemma of `word` (lemminflect: a maintained dictionary plus rules), else the
    likeliest singular."""
    found = getLemma(word, upos="NOUN")
    return str(found[0]) if found else singular(word)


def _same_category(obj: EnvObject, role: Role, catalog: Catalog) -> bool:
    return vocabulary(catalog).canonical(obj.category, (role.category,)) == role.category


def _stated(obj: EnvObject) -> dict[str, frozenset[str]]:
    return {snake(k): _words(v) for k, v in obj.attributes.items()}


def attribute_gaps(obj: EnvObject, role: Role) -> list[str]:
    """What `obj` lacks of the role's attributes: `no color` or `color=blue`; [] when it agrees.

    A stated value agrees when its words hold the value's (lemmas: `Novels` and `novel` agree
    with `novels`, `other books` with `other`); an attribute the object does not state agrees
    when its name says the value."""
    have = _stated(obj)
    words = name_words(obj)
    gaps = []
    for key, value in role.attributes.items():
        got = have.get(snake(key))
        if _words(value) <= (words if got is None else got):
            continue
        gaps.append(f"no {key}" if got is None else f"{key}={obj.attributes[_key(obj, key)]}")
    return gaps


def _key(obj: EnvObject, key: str) -> str:
    return next(k for k in obj.attributes if snake(k) == snake(key))


def _states_all(obj: EnvObject, role: Role) -> bool:
    have = _stated(obj)
    return bool(role.attributes) and all(_words(v) <= have.get(snake(k), frozenset())
                                         for k, v in role.attributes.items())


def _says_name(obj: EnvObject, name: str, role: Role, catalog: Catalog) -> bool:
    """Does the object's name hold the role name's distinctive words (those that do not name
    the category: `novel` of `shelf_novels`)? A role name of category words only (`table`)
    distinguishes nothing."""
    common = set().union(*(_words(n) for n in category_names(role.category, catalog)))
    distinctive = _words(name) - common
    return bool(distinctive) and distinctive <= name_words(obj)


def named_attributes(obj: EnvObject, role: Role) -> dict[str, str]:
    """The role attributes `obj` says otherwise than the role writes them — through its name
    (`red_box`) or in other words (`"purpose": "other books"` for `purpose=other`) — as the role
    writes them, to put in its attributes: the trees, constraints and simulator compare values
    exactly."""
    have = {snake(k): (k, v) for k, v in obj.attributes.items()}
    words = name_words(obj)
    out = {}
    for key, value in role.attributes.items():
        got = have.get(snake(key))
        if got is None and _words(value) <= words:
            out[key] = value
        elif got is not None and got[1] != value and _words(value) <= _words(got[1]):
            out[got[0]] = value
    return out


def matches(obj: EnvObject, role: Role, catalog: Catalog) -> bool:
    """Does `obj` qualify for `role` (its category names the role's, every role attribute agrees)?

    The object's category is read through the one vocabulary (`domain.categories`), preferring
    the role's category where a name fits several."""
    return _same_category(obj, role, catalog) and not attribute_gaps(obj, role)


def role_named(object_id: str, roles: Iterable[str]) -> str | None:
    """The role whose name `object_id` is (`Red Box`, `red_box` for `red_box`), if any: an object
    so named plays that role for every method (the judge's id rule; `llm.replies.bind_objects`
    applies the same rule to a reply before the judge sees it)."""
    key = snake(object_id)
    return next((r for r in roles if r == key), None)


def _evidence(obj: EnvObject, name: str, role: Role, catalog: Catalog) -> Reason:
    """The strongest reason `obj` plays `name` (rule 3), `category` when nothing but its
    category and agreeing attributes speak for it."""
    if _states_all(obj, role):
        return "attribute"
    if role_named(obj.id, (name,)):
        return "id"
    if _says_name(obj, name, role, catalog) or (role.attributes and named_attributes(obj, role)):
        return "name words"
    return "category"


def check_map(env: EnvSpec, mapping: Mapping[str, str | None], roles: Mapping[str, Role],
              catalog: Catalog) -> dict[str, str]:
    """Role -> why its entry of `mapping` is refused: an object that is not there, of another
    category than the role's, or given to several roles (each of them refused)."""
    by_id = {o.id: o for o in env.objects}
    refused: dict[str, str] = {}
    owners: dict[str, list[str]] = {}
    for name, oid in mapping.items():
        if name not in roles or oid is None:
            continue
        obj = by_id.get(oid)
        if obj is None:
            refused[name] = f"{name} is mapped to {oid!r}, which is not an object of {env.env_id}"
        elif not _same_category(obj, roles[name], catalog):
            shown = vocabulary(catalog).canonical(obj.category) or repr(obj.category)
            refused[name] = (f"{name} is mapped to {oid}, a {shown}, but the task's {name} is a "
                             f"{roles[name].category}")
        else:
            owners.setdefault(oid, []).append(name)
    for oid, names in owners.items():
        if len(names) > 1:
            for name in names:
                refused[name] = (f"{name} is mapped to {oid}, which is also mapped to "
                                 f"{', '.join(n for n in names if n != name)}: one object plays at most one role")
    return refused


def bind_roles(env: EnvSpec, roles: Mapping[str, Role], catalog: Catalog | None = None, *,
               declared: frozenset[str] = frozenset()) -> RoleBinding:
    """Bind every role of `roles` (rule in the module docstring); `env.roles` is checked first.
    `declared`: the objects the environment's own map lists under names that are no roles of the
    task (`prepare_env` passes them), the last evidence between candidates."""
    cat = catalog if catalog is not None else load_catalog()
    refused = check_map(env, env.roles, roles, cat)
    explicit = {n: oid for n, oid in env.roles.items() if n not in refused}
    taken = {oid for n, oid in explicit.items() if oid is not None}
    by_id = {o.id: o for o in env.objects}
    free = [o for o in env.objects if o.id not in taken]
    cands: dict[str, list[str]] = {}
    decisive: set[str] = set()
    declared_by: set[str] = set()  # roles whose candidates only the environment's own map told apart
    for name, role in roles.items():
        if name in explicit:
            continue
        agree = [o for o in free if matches(o, role, cat)]
        cands[name] = _narrow(agree, name, role, cat)
        if len(cands[name]) > 1 and len(own := [i for i in cands[name] if i in declared]) == 1:
            cands[name] = own
            declared_by.add(name)
        if len(cands[name]) == 1 and (name in declared_by
                                      or _evidence(by_id[cands[name][0]], name, role, cat) != "category"):
            decisive.add(name)
    # roles that evidence singles an object out for bind first; the others share what is left
    # (one toilet roll named spare_roll: spare_roll plays it, roll is left without one)
    decided, ambiguous = _decide({n: ids for n, ids in cands.items() if n in decisive})
    taken_now = {oid for oid in decided.values() if oid is not None}
    rest, undecided = _decide({n: [i for i in ids if i not in taken_now] for n, ids in cands.items()
                               if n not in decisive})
    decided.update(rest)
    ambiguous.update(undecided)
    problems = []
    for name, left in ambiguous.items():
        if len(left) > 1:
            why = f"{len(left)} objects qualify ({', '.join(left)}) and nothing tells them apart"
        else:
            rivals = sorted(n for n, ids in ambiguous.items() if n != name and ids == left)
            why = f"its one candidate {left[0]} is also the one candidate of {', '.join(rivals)}"
        problems.append(f"role {name} is ambiguous: {why}; state the distinguishing attribute on "
                        f"the object meant, or add \"roles\": {{\"{name}\": \"<object id>\"}} to the "
                        f"EnvSpec (or --roles {name}=<object id>) to choose")
    bound = {name: decided.get(name) for name in cands}
    full = {**env.roles, **{n: None for n in refused}, **bound}
    reasons: dict[str, Reason] = {}
    for name in roles:
        oid = full.get(name)
        if name in explicit:
            reasons[name] = "explicit map" if oid is not None else "absent"
        elif name in ambiguous:
            reasons[name] = "ambiguous"
        elif oid is None:
            reasons[name] = "absent"
        elif name in declared_by:
            reasons[name] = "task object"
        else:
            reasons[name] = _evidence(by_id[oid], name, roles[name], cat)
    used = {oid for oid in full.values() if oid is not None}
    nearest = {name: _nearest(name, roles[name], env, full, used, cat)
               for name, oid in bound.items() if oid is None and name not in ambiguous}
    for name, oid in explicit.items():
        if oid is None and name in roles:
            same = [o.id for o in env.objects if _same_category(o, roles[name], cat)]
            there = (f": {', '.join(same[:_NEAREST])} {'is a' if len(same) == 1 else 'are'} "
                     f"{roles[name].category}{'' if len(same) == 1 else 's'} (map one, or leave "
                     f"{name} out of the map for the harness to bind it)" if same else "")
            nearest[name] = f"the EnvSpec's roles map {name} to null (absent){there}"
    return RoleBinding(roles=full, bound=bound, candidates=ambiguous, problems=problems, why=nearest,
                       refused=[refused[n] + "; refused, bound by meaning instead" for n in sorted(refused)],
                       reasons=reasons)


def _narrow(agree: list[EnvObject], name: str, role: Role, cat: Catalog) -> list[str]:
    """The candidates of a role after the evidence of rule 3 (stated attributes, id, name
    words: the first that singles out one object decides); all of them when none does."""
    tests: tuple[Callable[[EnvObject], bool], ...] = (
        lambda o: _states_all(o, role), lambda o: role_named(o.id, (name,)) is not None,
        lambda o: _says_name(o, name, role, cat))
    for test in tests:
        hit = [o.id for o in agree if test(o)]
        if len(hit) == 1:
            return hit
    return [o.id for o in agree]


def _nearest(name: str, role: Role, env: EnvSpec, full: Mapping[str, str | None],
             used: set[str], cat: Catalog) -> str:
    """One sentence: which objects come nearest to playing `role`, and what each lacks."""
    owner = {oid: r for r, oid in full.items() if oid is not None}
    attrs = ", ".join(f"{k}={v}" for k, v in role.attributes.items())
    want = role.category + (f" with {attrs}" if attrs else "")
    same = [o for o in env.objects if _same_category(o, role, cat)]
    if same:
        parts = []
        for o in same[:_NEAREST]:
            if o.id in used:
                parts.append(f"{o.id} plays {owner.get(o.id, 'another role')}")
            else:
                parts.append(f"{o.id} has {' and '.join(attribute_gaps(o, role))}")
        more = f" (and {len(same) - _NEAREST} more)" if len(same) > _NEAREST else ""
        missing = sorted({g[3:] for o in same if o.id not in used for g in attribute_gaps(o, role)
                          if g.startswith("no ")})
        fix = (f"state {', '.join(missing)} on the object meant (or name it so)" if missing
               else "map the role with --roles or \"roles\"")
        return f"no {role.category} has {attrs or 'what ' + name + ' needs'}: {'; '.join(parts)}{more}; {fix}"
    related = _related(name, role, [o for o in env.objects if o.id not in used], cat)
    if not related:
        return f"no object is a {role.category} (a {want} would bind)"
    parts = [f"{o.id} is a {vocabulary(cat).canonical(o.category) or repr(o.category)}, "
             f"not a {role.category}" for o in related]
    return f"no object is a {role.category}: {'; '.join(parts)} (a {want} would bind)"


def _related(name: str, role: Role, objects: list[EnvObject], cat: Catalog) -> list[EnvObject]:
    """Objects of other categories that are near the role: a shared word (the role's name, its
    category and synonyms, its kinds) or a similar category name; nearest first."""
    spec = cat.get(role.category)
    words = _words(name) | set().union(*(_words(n) for n in category_names(role.category, cat)))
    if spec is not None:
        words |= set().union(set(), *(_words(v) for v in spec.attributes.get("kind", [])))
    words |= set().union(set(), *(_words(v) for v in role.attributes.values()))
    scored = []
    for o in objects:
        key = vocabulary(cat).canonical(o.category) or o.category
        theirs = name_words(o) | set().union(*(_words(n) for n in category_names(key, cat)))
        shared = len(words & theirs)
        ratio = difflib.SequenceMatcher(None, snake(key), snake(role.category)).ratio()
        if shared or ratio >= 0.75:
            scored.append((-shared, -ratio, o.id, o))
    return [o for *_, o in sorted(scored, key=lambda t: t[:3])[:_NEAREST]]


def _decide(cands: Mapping[str, list[str]]) -> tuple[dict[str, str | None], dict[str, list[str]]]:
    """Bind forced choices until nothing changes; return (decided, undecided -> candidates left).

    A role is forced when exactly one of its candidates is still free and no other undecided role
    is left with that same single object; a role whose candidates were all taken stays unbound.
    """
    decided: dict[str, str | None] = {}
    changed = True
    while changed:
        changed = False
        used = {oid for oid in decided.values() if oid is not None}
        left = {n: [i for i in ids if i not in used] for n, ids in cands.items() if n not in decided}
        for name, ids in left.items():
            if not ids:
                decided[name] = None
                changed = True
            elif len(ids) == 1 and not any(m != name and other == ids for m, other in left.items()):
                decided[name] = ids[0]
                changed = True
                break  # `used` changed: recompute what is left for the others
    used = {oid for oid in decided.values() if oid is not None}
    ambiguous = {n: [i for i in ids if i not in used] for n, ids in cands.items() if n not in decided}
    return decided, ambiguous


def parse_role_map(text: str | None, roles: Mapping[str, Role] | None = None, *,
                   strict: bool = True) -> dict[str, str]:
    """`--roles ROLE=ID,...` as a map (`ConfigError` on a malformed item or a ROLE given twice:
    neither is silently last-wins). With `roles`, each ROLE must be one of them (`strict`) or is
    left out (not strict: several tasks share a `--roles`, each takes its own; the command then
    checks with `unknown_roles` that every ROLE is a role of some task)."""
    out: dict[str, str] = {}
    seen: dict[str, str] = {}
    for item in (text or "").split(","):
        if not item.strip():
            continue
        role, sep, oid = (x.strip() for x in item.partition("="))
        if not sep or not role or not oid:
            raise ConfigError(f"{item.strip()!r} is not ROLE=ID", field="--roles",
                              hint="write --roles red_box=box_2,toy=doll_1")
        if role in seen:
            raise ConfigError(f"role {role!r} is given twice ({role}={seen[role]} and {role}={oid})",
                              field="--roles", hint=f"give each role once: --roles {role}=<object id>")
        seen[role] = oid
        if roles is not None and role not in roles:
            if not strict:
                continue
            raise ConfigError(f"{role!r} is not a role of the task", field="--roles",
                              hint=f"roles: {', '.join(sorted(roles))}")
        out[role] = oid
    return out


def unknown_roles(text: str | None, role_sets: list[Mapping[str, Role]]) -> None:
    """`ConfigError` when a ROLE of `--roles` is a role of none of the tasks (a typo such as
    `red_bx` would otherwise bind nothing, silently)."""
    known = set().union(*(set(r) for r in role_sets)) if role_sets else set()
    for role in parse_role_map(text):
        if role not in known:
            close = difflib.get_close_matches(role, sorted(known), n=1)
            raise ConfigError(f"{role!r} is not a role of the task(s)", field="--roles",
                              hint=(f"did you mean {close[0]}? " if close else "")
                              + f"roles: {', '.join(sorted(known)[:20])}")


@dataclass(frozen=True)
class PreparedEnv:
    """An environment as the harness judges it, and what preparing it found."""

    #: categories mapped to catalog keys, the task's unmapped roles bound
    env: EnvSpec
    binding: RoleBinding
    categories: CategoryReport


def prepare_env(env: EnvSpec, roles: Mapping[str, Role], catalog: Catalog | None = None,
                given: Mapping[str, str] | None = None) -> PreparedEnv:
    """Map every category to its catalog key (ties go to the roles' categories), then bind the
    roles of `roles` the environment does not map; `given` (`--roles`) maps roles first.

    Names the environment maps that are not roles of the task (a generator that was not told
    the roles names objects its own way: `--brief description`) neither bind nor block objects;
    they stay in the map for the relations that use them, and the objects they list are the
    last evidence between a role's candidates (`declared`: the task objects it said it made). A
    role attribute that its object states only through its name (`red toy box` for `color=red`)
    is added to the object's attributes, so the trees, the constraints and the simulator read what
    the name says.
    Evaluation, `simulate --env`, `check-env` and `lint` all prepare environments here, so they
    agree on every binding.
    """
    cat = catalog if catalog is not None else load_catalog()
    env, categories = normalise_env(env, cat, prefer={r.category for r in roles.values()})
    ids = {o.id for o in env.objects}
    for role, oid in (given or {}).items():
        if oid not in ids:
            raise ConfigError(f"{role}={oid}: the environment {env.env_id} has no object {oid!r}",
                              field="--roles", hint=f"object ids: {', '.join(sorted(ids)[:12])}")
    bad = check_map(env, dict(given or {}), roles, cat)
    if bad:
        role = min(bad)
        raise ConfigError(f"{role}={(given or {})[role]}: {bad[role]}", field="--roles",
                          hint="map each role to one object of the role's category")
    chosen = set((given or {}).values())
    own = {**{name: oid for name, oid in env.roles.items() if name in roles and oid not in chosen},
           **(given or {})}
    declared = frozenset(oid for name, oid in env.roles.items() if name not in roles and oid is not None)
    binding = bind_roles(env.model_copy(update={"roles": own}), roles, cat, declared=declared)
    merged = {**env.roles, **binding.roles}
    if merged != dict(env.roles):
        env = env.model_copy(update={"roles": merged})
    owner = {oid: name for name, oid in binding.roles.items() if oid is not None}
    named = {o.id: named_attributes(o, roles[owner[o.id]]) for o in env.objects if o.id in owner}
    if any(named.values()):
        env = env.model_copy(update={"objects": [
            o.model_copy(update={"attributes": {**o.attributes, **named[o.id]}}) if named.get(o.id)
            else o for o in env.objects]})
    return PreparedEnv(env=env, binding=binding, categories=categories)
