"""Binding task roles to the objects of an environment that does not name them.

Environments made by other tools (another generator, an imported ProcTHOR house, an LLM told
only the description) usually carry no `roles` map, yet the GT trees and the policies speak
about roles. The harness binds them from what the environment says of each object — its
category, its attributes and its *name* (the object id and the category as written) — by a rule
that never guesses:

* A role that the EnvSpec already maps (to an object id or to null), or that `given` maps
  (`--roles ROLE=ID`), keeps its mapping.
* Any other role is a *candidate match* for an object when the object's category names the
  role's category in the one vocabulary (`domain.categories`: the catalog key, a synonym, an
  AI2-THOR type, in any case, spacing or plural: ``Toy Chest``, ``toy_chests`` and ``toy_box``
  all name ``toy_box``) and the object agrees with every attribute of the role: it has the
  attribute with the same value, or it has no such attribute and its name says the value
  (``red toy box`` or id ``red_box`` say ``color=red``). An object with another value, or with
  neither the attribute nor the word, does not agree.
* Of several candidates, the one whose name holds every word of the role's name (id
  ``red_box``, ``Red Box 1`` for role ``red_box``) is the generator's own choice and binds.
* One candidate: the role binds to it. None: the role stays unbound (null), which the GT
  evaluation accepts only for an optional role or where the reached path says the role does
  not exist; `why` then says in one message what the nearest objects lack.
* Objects bound to a role are no longer candidates of the others; this is repeated until
  nothing changes, so a role left with one candidate after the others took theirs is bound too.
  When two roles are left with the same single object, neither is bound.
* Several candidates: the role stays unbound and the binding reports one problem naming the
  role and every candidate; the environment is then not well-formed (the harness never picks one
  silently, and a role that the EnvSpec maps itself is never second-guessed).

Public API::

    bind_roles(env: EnvSpec, roles: Mapping[str, Role], catalog: Catalog | None = None)
        -> RoleBinding

`roles` is `task.roles` or `brief.roles` (a generator only sees the brief). `RoleBinding` has
`roles` (the complete map, given and bound), `bound` (only the roles bound here), `candidates`
(role -> object ids for every role with several), `problems` (one message per ambiguous role),
`why` (one message per role left unbound with no candidate: what the nearest objects lack),
`well_formed` and `apply(env) -> EnvSpec` (the env with `roles` replaced by the complete map).
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache

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
_NOISE = frozenset({"a", "an", "the", "of", "obj", "object", "item", "with", "and"})
#: how many nearest objects an unbound role's message names
_NEAREST = 3


class RoleBinding(BaseModel):
    """The outcome of binding: a complete role map plus what could not be decided."""

    model_config = ConfigDict(frozen=True)
    roles: dict[str, str | None] = Field(default_factory=dict)
    bound: dict[str, str | None] = Field(default_factory=dict)
    candidates: dict[str, list[str]] = Field(default_factory=dict)
    problems: list[str] = Field(default_factory=list)
    #: role left unbound with no candidate -> what the nearest objects lack (one message)
    why: dict[str, str] = Field(default_factory=dict)

    @property
    def well_formed(self) -> bool:
        return not self.problems

    def apply(self, env: EnvSpec) -> EnvSpec:
        """`env` with its `roles` map replaced by the complete one (unchanged when equal)."""
        if dict(env.roles) == self.roles:
            return env
        return env.model_copy(update={"roles": dict(self.roles)})


def category_names(category: str, catalog: Catalog) -> set[str]:
    """Names (snake_case) that denote `category`: itself and its catalog synonyms."""
    return vocabulary(catalog).names(category)


def name_words(obj: EnvObject) -> frozenset[str]:
    """The words an object's name says: its id and its category as written (singular forms)."""
    written = getattr(obj, "source_category", None)
    text = " ".join(str(t) for t in (obj.id, written or obj.category))
    return _words(text)


@lru_cache(maxsize=8192)  # pure; every object's name is read for every role it may bind
def _words(text: str) -> frozenset[str]:
    out: set[str] = set()
    for word in snake(text).split("_"):
        if word and not word.isdigit() and word not in _NOISE:
            out |= {word, singular(word)}
    return frozenset(out)


def _same_category(obj: EnvObject, role: Role, catalog: Catalog) -> bool:
    return vocabulary(catalog).canonical(obj.category, (role.category,)) == role.category


def attribute_gaps(obj: EnvObject, role: Role) -> list[str]:
    """What `obj` lacks of the role's attributes: `no color` or `color=blue`; [] when it agrees.

    An attribute the object does not state agrees when its name says the value."""
    have = {snake(k): snake(v) for k, v in obj.attributes.items()}
    words = name_words(obj)
    gaps = []
    for key, value in role.attributes.items():
        got = have.get(snake(key))
        if got == snake(value) or (got is None and _words(value) <= words):
            continue
        gaps.append(f"no {key}" if got is None else f"{key}={got}")
    return gaps


def named_attributes(obj: EnvObject, role: Role) -> dict[str, str]:
    """The role attributes `obj` states only through its name (to add to its attributes)."""
    have = {snake(k) for k in obj.attributes}
    words = name_words(obj)
    return {k: v for k, v in role.attributes.items() if snake(k) not in have and _words(v) <= words}


def matches(obj: EnvObject, role: Role, catalog: Catalog) -> bool:
    """Does `obj` qualify for `role` (its category names the role's, every role attribute agrees)?

    The object's category is read through the one vocabulary (`domain.categories`), preferring
    the role's category where a name fits several."""
    return _same_category(obj, role, catalog) and not attribute_gaps(obj, role)


def bind_roles(env: EnvSpec, roles: Mapping[str, Role], catalog: Catalog | None = None) -> RoleBinding:
    """Bind every role of `roles` that `env.roles` does not map (rule in the module docstring)."""
    cat = catalog if catalog is not None else load_catalog()
    taken = {oid for oid in env.roles.values() if oid is not None}
    by_id = {o.id: o for o in env.objects}
    cands = {}
    for name, role in roles.items():
        if name in env.roles:
            continue
        ids = [o.id for o in env.objects if o.id not in taken and matches(o, role, cat)]
        own = [i for i in ids if _words(name) <= name_words(by_id[i])]
        cands[name] = own if len(own) == 1 else ids
    decided, ambiguous = _decide(cands)
    problems = []
    for name, left in ambiguous.items():
        if len(left) > 1:
            why = f"{len(left)} objects qualify ({', '.join(left)})"
        else:
            rivals = sorted(n for n, ids in ambiguous.items() if n != name and ids == left)
            why = f"its one candidate {left[0]} is also the one candidate of {', '.join(rivals)}"
        problems.append(f"role {name} is ambiguous: {why}; add \"roles\": "
                        f"{{\"{name}\": \"<object id>\"}} to the EnvSpec (or --roles "
                        f"{name}=<object id>) to choose")
    bound = {name: decided.get(name) for name in cands}
    full = {**env.roles, **bound}
    used = {oid for oid in full.values() if oid is not None}
    nearest = {name: _nearest(name, roles[name], env, full, used, cat)
               for name, oid in bound.items() if oid is None and name not in ambiguous}
    return RoleBinding(roles=full, bound=bound, candidates=ambiguous, problems=problems, why=nearest)


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
    """`--roles ROLE=ID,...` as a map (`ConfigError` on a malformed item). With `roles`, each
    ROLE must be one of them (`strict`) or is left out (not strict: several tasks share a
    `--roles`, each takes its own)."""
    out: dict[str, str] = {}
    for item in (text or "").split(","):
        if not item.strip():
            continue
        role, sep, oid = (x.strip() for x in item.partition("="))
        if not sep or not role or not oid:
            raise ConfigError(f"{item.strip()!r} is not ROLE=ID", field="--roles",
                              hint="write --roles red_box=box_2,toy=doll_1")
        if roles is not None and role not in roles:
            if not strict:
                continue
            raise ConfigError(f"{role!r} is not a role of the task", field="--roles",
                              hint=f"roles: {', '.join(sorted(roles))}")
        out[role] = oid
    return out


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
    they stay in the map for the relations that use them. A role attribute that its object
    states only through its name (`red toy box` for `color=red`) is added to the object's
    attributes, so the trees, the constraints and the simulator read what the name says.
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
    own = {**{name: oid for name, oid in env.roles.items() if name in roles}, **(given or {})}
    binding = bind_roles(env.model_copy(update={"roles": own}), roles, cat)
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
