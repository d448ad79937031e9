"""Binding task roles to the objects of an environment that does not name them.

Environments made by other tools (another generator, an imported ProcTHOR house) usually carry
no `roles` map, yet the GT trees and the policies speak about roles. The harness binds them by a
rule that never guesses:

* A role that the EnvSpec already maps (to an object id or to null) keeps its mapping.
* Any other role is a *candidate match* for an object when the object's category names the
  role's category in the one vocabulary (`domain.categories`: the catalog key, a synonym, an
  AI2-THOR type, in any case, spacing or plural: ``Toy Chest``, ``toy_chests`` and ``toy_box``
  all name ``toy_box``) — and the object has every attribute of the role with the same value (a role
  ``toy_box`` with ``color=red`` needs an object whose ``color`` is ``red``; an object without a
  colour does not agree).
* One candidate: the role binds to it. None: the role stays unbound (null), which the GT
  evaluation accepts only where the reached path says the role does not exist.
* Objects bound to a role are no longer candidates of the others; this is repeated until
  nothing changes, so a role left with one candidate after the others took theirs is bound too.
  When two roles are left with the same single object, neither is bound.
* Several candidates: the role stays unbound and the binding reports a problem naming the role
  and every candidate; the environment is then not well-formed (the harness never picks one
  silently, and a role that the EnvSpec maps itself is never second-guessed).

Public API::

    bind_roles(env: EnvSpec, roles: Mapping[str, Role], catalog: Catalog | None = None)
        -> RoleBinding

`roles` is `task.roles` or `brief.roles` (a generator only sees the brief). `RoleBinding` has
`roles` (the complete map, given and bound), `bound` (only the roles bound here), `candidates`
(role -> object ids for every role with several), `problems` (one message per ambiguous role),
`well_formed` and `apply(env) -> EnvSpec` (the env with `roles` replaced by the complete map).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.domain.categories import CategoryReport, normalise_env, snake, vocabulary
from logicenveval.model.envspec import EnvObject, EnvSpec
from logicenveval.model.task import Role


class RoleBinding(BaseModel):
    """The outcome of binding: a complete role map plus what could not be decided."""

    model_config = ConfigDict(frozen=True)
    roles: dict[str, str | None] = Field(default_factory=dict)
    bound: dict[str, str | None] = Field(default_factory=dict)
    candidates: dict[str, list[str]] = Field(default_factory=dict)
    problems: list[str] = Field(default_factory=list)

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


def matches(obj: EnvObject, role: Role, catalog: Catalog) -> bool:
    """Does `obj` qualify for `role` (its category names the role's, every role attribute agrees)?

    The object's category is read through the one vocabulary (`domain.categories`), preferring
    the role's category where a name fits several."""
    if vocabulary(catalog).canonical(obj.category, (role.category,)) != role.category:
        return False
    have = {snake(k): snake(v) for k, v in obj.attributes.items()}
    return all(have.get(snake(k)) == snake(v) for k, v in role.attributes.items())


def bind_roles(env: EnvSpec, roles: Mapping[str, Role], catalog: Catalog | None = None) -> RoleBinding:
    """Bind every role of `roles` that `env.roles` does not map (rule in the module docstring)."""
    cat = catalog if catalog is not None else load_catalog()
    taken = {oid for oid in env.roles.values() if oid is not None}
    cands = {
        name: [o.id for o in env.objects if o.id not in taken and matches(o, role, cat)]
        for name, role in roles.items() if name not in env.roles
    }
    decided, ambiguous = _decide(cands)
    problems = []
    for name, left in ambiguous.items():
        if len(left) > 1:
            why = f"{len(left)} objects qualify ({', '.join(left)})"
        else:
            rivals = sorted(n for n, ids in ambiguous.items() if n != name and ids == left)
            why = f"its one candidate {left[0]} is also the one candidate of {', '.join(rivals)}"
        problems.append(f"role {name} is ambiguous: {why}; add \"roles\": "
                        f"{{\"{name}\": \"<object id>\"}} to the EnvSpec to choose")
    bound = {name: decided.get(name) for name in cands}
    return RoleBinding(roles={**env.roles, **bound}, bound=bound, candidates=ambiguous,
                       problems=problems)


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


@dataclass(frozen=True)
class PreparedEnv:
    """An environment as the harness judges it, and what preparing it found."""

    #: categories mapped to catalog keys, the task's unmapped roles bound
    env: EnvSpec
    binding: RoleBinding
    categories: CategoryReport


def prepare_env(env: EnvSpec, roles: Mapping[str, Role], catalog: Catalog | None = None) -> PreparedEnv:
    """Map every category to its catalog key (ties go to the roles' categories), then bind the
    roles of `roles` the environment does not map.

    Names the environment maps that are not roles of the task (a generator that was not told
    the roles names objects its own way: `--brief description`) neither bind nor block objects;
    they stay in the map for the relations that use them. Evaluation, `simulate --env`,
    `check-env` and `lint` all prepare environments here, so they agree on every binding.
    """
    cat = catalog if catalog is not None else load_catalog()
    env, categories = normalise_env(env, cat, prefer={r.category for r in roles.values()})
    own = {name: oid for name, oid in env.roles.items() if name in roles}
    binding = bind_roles(env.model_copy(update={"roles": own}), roles, cat)
    if binding.roles != own:
        env = env.model_copy(update={"roles": {**env.roles, **binding.roles}})
    return PreparedEnv(env=env, binding=binding, categories=categories)
