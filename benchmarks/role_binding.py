"""How the one binding rule (`domain.roles`) reads environments it was not written for.

Prints three tables:

1. **Map removed.** Every EnvSpec of a run folder (default: the committed reference run) judged
   with its own `roles` map and with the map removed: how many bind every task role to the same
   object, how many differ, how many leave a role ambiguous.
2. **Renamed.** The environments of the tasks whose roles share a category, with the objects of
   those roles renamed as a person or a real model might name them — the name's words reversed
   (`novels_shelf`), with a preposition (`shelf_for_novels`), neutral ids stating the role's
   attributes (`wall_shelf_a` with `"purpose": "novels"`), neutral ids stating nothing (which
   must stay unbound or ambiguous: the judge never guesses) — and the map removed: how many
   bind every renamed role to its object.
3. **Unseen categories.** Roles of categories and names no built-in task uses (cups for coffee
   and tea, pillows for sofa and bed, towels by colour, bowls for a dog and a cat), objects
   named in several ways: how many bind as meant, and how many that nothing tells apart are
   refused rather than guessed.

    python benchmarks/role_binding.py [RUN_DIR] [--smoke]

It takes seconds; `--smoke` (the test suite's run) is the same run.
"""

from __future__ import annotations

import json
import re
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.domain.roles import bind_roles, prepare_env
from logicenveval.envfiles import env_from_dict
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import Role, Task

ROOT = Path(__file__).resolve().parents[1]
CATALOG = load_catalog()


def _shared(task: Task) -> list[str]:
    """The roles of `task` whose category another role has too."""
    by: Counter[str] = Counter(r.category for r in task.roles.values())
    return [n for n, r in task.roles.items() if by[r.category] > 1]


def _env_files(run: Path) -> list[Path]:
    """The EnvSpecs of a run folder (not the briefs and plans beside them)."""
    return [p for p in sorted((run / "envs").glob("*/*/*.json")) if p.name not in ("brief.json", "plan.json")]


def map_removed(run: Path) -> Counter[str]:
    out: Counter[str] = Counter()
    tasks: dict[str, Task] = {}
    for path in _env_files(run):
        env = EnvSpec.model_validate_json(path.read_text(encoding="utf-8"))
        task = tasks.setdefault(env.task_id, load_task(env.task_id))
        own = prepare_env(env, task.roles, CATALOG).binding
        bare = prepare_env(env.model_copy(update={"roles": {}}), task.roles, CATALOG).binding
        out["environments"] += 1
        if not bare.well_formed:
            out["ambiguous without the map"] += 1
        elif {r: bare.roles.get(r) for r in task.roles} == {r: own.roles.get(r) for r in task.roles}:
            out["same binding"] += 1
        else:
            out["other binding"] += 1
    return out


def _rename(text: str, names: dict[str, str]) -> str:
    for old, new in names.items():
        text = re.sub(rf'"{re.escape(old)}"', f'"{new}"', text)
    return text


SCHEMES = ("reversed", "preposition", "neutral + attribute", "neutral, nothing stated")


def _scheme(scheme: str, role: str, spec: Role, k: int) -> tuple[str, dict[str, str]]:
    words = role.split("_")
    if scheme == "reversed":
        return "_".join(reversed(words)), {}
    if scheme == "preposition":
        head = spec.category.split("_")[-1]
        rest = [w for w in words if w != head] or words
        return f"{head}_for_{'_'.join(rest)}", {}
    neutral = f"{spec.category}_{'abcdefgh'[k]}"
    return neutral, (dict(spec.attributes) if scheme == "neutral + attribute" else {})


def renamed(run: Path) -> dict[str, Counter[str]]:
    out: dict[str, Counter[str]] = {s: Counter() for s in SCHEMES}
    for path in _env_files(run):
        text = path.read_text(encoding="utf-8")
        env = EnvSpec.model_validate_json(text)
        task = load_task(env.task_id)
        shared = _shared(task)
        own = prepare_env(env, task.roles, CATALOG).binding.roles
        played = {r: own.get(r) for r in shared if own.get(r)}
        categories = {o.category for o in env.objects}
        if not played or any(oid in categories for oid in played.values()):
            continue
        for scheme in SCHEMES:
            names, stated = {}, {}
            for k, (role, oid) in enumerate(sorted(played.items())):
                new, attrs = _scheme(scheme, role, task.roles[role], k)
                names[str(oid)], stated[new] = new, attrs
            data: dict[str, Any] = json.loads(_rename(text, names))
            data["roles"] = {}
            for o in data["objects"]:
                if o["id"] in stated:
                    o["attributes"] = {k: v for k, v in (o.get("attributes") or {}).items()
                                       if k not in task.roles[shared[0]].attributes}
                    o["attributes"].update(stated[o["id"]])
            binding = prepare_env(env_from_dict(data), task.roles, CATALOG).binding
            right = all(binding.roles.get(r) == names[str(oid)] for r, oid in played.items())
            wrong = any(binding.roles.get(r) not in (None, names[str(oid)]) for r, oid in played.items())
            out[scheme]["environments"] += 1
            out[scheme]["bound as meant" if right else "a wrong object" if wrong else "left unbound/ambiguous"] += 1
    return out


UNSEEN: list[tuple[dict[str, Role], list[tuple[str, str, dict[str, str]]], dict[str, str] | None]] = [
    ({"cup_coffee": Role(category="cup", attributes={"purpose": "coffee"}),
      "cup_tea": Role(category="cup", attributes={"purpose": "tea"})}, objs, want)
    for objs, want in [
        ([("coffee_mug", "Cup", {}), ("mug_for_tea", "cups", {})], {"cup_coffee": "coffee_mug", "cup_tea": "mug_for_tea"}),
        ([("c1", "cup", {"purpose": "Tea"}), ("c2", "cup", {"purpose": "coffee"})], {"cup_coffee": "c2", "cup_tea": "c1"}),
        ([("cup_tea", "cup", {}), ("cup_2", "cup", {"purpose": "coffee"})], {"cup_coffee": "cup_2", "cup_tea": "cup_tea"}),
        ([("tea_cup", "cup", {}), ("coffee_cups", "cup", {})], {"cup_coffee": "coffee_cups", "cup_tea": "tea_cup"}),
        ([("cup_left", "cup", {}), ("cup_right", "cup", {})], None),
    ]
] + [
    ({"pillow_sofa": Role(category="pillow"), "pillow_armchair": Role(category="pillow")}, objs, want)
    for objs, want in [
        ([("armchair_pillow", "pillow", {}), ("sofa_pillows", "Pillow", {})],
         {"pillow_sofa": "sofa_pillows", "pillow_armchair": "armchair_pillow"}),
        ([("pillow_for_the_sofa", "pillow", {}), ("p2", "pillow", {})],
         {"pillow_sofa": "pillow_for_the_sofa", "pillow_armchair": "p2"}),
        ([("pillow_1", "pillow", {}), ("pillow_2", "pillow", {})], None),
    ]
] + [
    ({"towel_guest": Role(category="towel", attributes={"color": "green"}),
      "towel_kids": Role(category="towel", attributes={"color": "yellow"})}, objs, want)
    for objs, want in [
        ([("t1", "towel", {"color": "yellow"}), ("green_towel", "towel", {})], {"towel_guest": "green_towel", "towel_kids": "t1"}),
        ([("Yellow Towel", "Towel", {}), ("towel_2", "towel", {"color": "Green"})],
         {"towel_guest": "towel_2", "towel_kids": "Yellow Towel"}),
        ([("towel_a", "towel", {}), ("towel_b", "towel", {})], None),
    ]
] + [
    ({"bowl_dog": Role(category="pet_bowl", attributes={"purpose": "dog"}),
      "bowl_cat": Role(category="pet_bowl", attributes={"purpose": "cat"})}, objs, want)
    for objs, want in [
        ([("dogs_bowl", "pet bowl", {}), ("cat_bowl", "PetBowl", {})], {"bowl_dog": "dogs_bowl", "bowl_cat": "cat_bowl"}),
        ([("bowl_1", "pet_bowl", {"purpose": "cats"}), ("bowl_2", "pet_bowl", {"purpose": "dogs"})],
         {"bowl_dog": "bowl_2", "bowl_cat": "bowl_1"}),
        ([("bowl_1", "pet_bowl", {}), ("bowl_2", "pet_bowl", {})], None),
    ]
]


def unseen() -> Counter[str]:
    out: Counter[str] = Counter()
    for roles, objects, want in UNSEEN:
        env = env_from_dict({"task_id": "t", "env_id": "e", "rooms": [{"id": "r"}],
                             "objects": [{"id": i, "category": c, "room": "r", "attributes": a}
                                         for i, c, a in objects]})
        b = bind_roles(env, roles, CATALOG)
        if want is None:
            guessed = any(oid is not None for oid in b.roles.values())
            out["indistinct: refused" if not guessed else "indistinct: GUESSED"] += 1
        else:
            out["distinct: bound as meant" if b.roles == want else "distinct: not as meant"] += 1
    return out


def main(argv: list[str]) -> int:
    args = [a for a in argv if a != "--smoke"]
    run = Path(args[0]) if args else ROOT / "reports" / "reference"
    removed = map_removed(run)
    print(f"1. map removed ({run.name}): " + ", ".join(f"{k} {v}" for k, v in removed.items()))
    print("2. shared-category roles renamed, map removed:")
    for scheme, counts in renamed(run).items():
        print(f"   {scheme:24s} " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    print("3. unseen categories and names: " + ", ".join(f"{k} {v}" for k, v in sorted(unseen().items())))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
