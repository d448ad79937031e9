"""PhyPR on real AI2-THOR / ProcTHOR houses (tests/data/houses, Apache-2.0; issue 35).

The houses: AI2-THOR's `train_4`, ProcTHOR-10K train 1 and `house_3703` (every `*.json` there).

Per house: objects (with children), how many got a catalog category (typed), how many were
sized from ProcTHOR's asset database, entity failures (objects named by one), whether the floor
plan passes and how many rooms are unreachable — imported for every task given (default: three
tasks of different rooms; the type ties a task's roles break can change categories).
Needs ProcTHOR's databases: `pip install 'logicenveval[procthor]'` or `--procthor-db DIR`.
Last line per house: `house=<name> objects=<n> typed=<n> sized=<n> entity_failed=<n>
entity_pass=<fraction> floor_plan=<pass|fail> unreachable=<n>`.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.scene.house_import import import_house, load_house
from logicenveval.scene.import_report import format_rooms, house_report
from logicenveval.scene.procthor import installed_procthor_db, load_procthor_db

HOUSES = Path(__file__).resolve().parents[1] / "tests" / "data" / "houses"
TASKS = ("living_room_evening_reset", "kitchen_breakfast_prep", "bedroom_morning_tidy")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("houses", nargs="*", default=sorted(str(p) for p in HOUSES.glob("*.json")))
    parser.add_argument("--tasks", default=",".join(TASKS))
    parser.add_argument("--procthor-db", default=None)
    parser.add_argument("--rooms", action="store_true", help="print the room-level import report")
    parser.add_argument("--smoke", action="store_true", help="seconds, not minutes: a small case of the same code path (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = parser.parse_args(argv)
    if args.smoke:  # the smallest house, one task
        args.houses = [min(args.houses, key=lambda p: Path(p).stat().st_size)]
        args.tasks = TASKS[0]
    db = load_procthor_db(args.procthor_db) if args.procthor_db else installed_procthor_db()
    if db is None:
        print("ProcTHOR's databases are not installed: pip install 'logicenveval[procthor]' or --procthor-db",
              file=sys.stderr)
        return 2
    catalog = load_catalog()
    for path in map(Path, args.houses):
        worst: tuple[float, str] | None = None
        for task_id in args.tasks.split(","):
            task = load_task(task_id)
            rep = import_house(load_house(path), task_id=task.id, env_id=path.stem, catalog=catalog, assets=db,
                               role_categories=[r.category for r in task.roles.values()])
            house = house_report(rep, catalog)
            n = house.objects
            typed = sum(r.typed for r in house.rooms)
            sized = rep.size_sources.get("asset database", 0) + rep.size_sources.get("house", 0)
            unreachable = sum(f.code == "unreachable_room" for f in house.physics.extended.failures)
            line = (f"house={path.stem} task={task.id} objects={n} typed={typed} sized={sized} "
                    f"entity_failed={house.entity_failed} entity_pass={(n - house.entity_failed) / n:.3f} "
                    f"floor_plan={'pass' if house.physics.floor_plan.passed else 'fail'} unreachable={unreachable}")
            print(line)
            if args.rooms:
                print("\n".join(format_rooms(house)))
            worst = min(worst or ((n - house.entity_failed) / n, line), ((n - house.entity_failed) / n, line))
        assert worst is not None
        print(worst[1].replace(f" task={worst[1].split('task=')[1].split()[0]}", ""))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
