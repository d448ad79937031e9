"""Multi-world validation: varied worlds of one situation (`sim.worlds`) and `tasks validate`."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import load_task
from logicenveval.benchmark_validation import situations, validate_task
from logicenveval.cli import main
from logicenveval.model.tree import evaluate_task
from logicenveval.sim.situations import situation_env
from logicenveval.sim.world import holds_initial
from logicenveval.sim.worlds import situation_worlds

OLD = Path(__file__).parent / "fixtures" / "multiworld_old"
TASKS = ["hallway_coat_and_bag", "clean_living_room", "dining_table_clear", "multi_room_trash_run"]


def _placement(env: object) -> list[tuple[object, ...]]:
    return [(o.id, o.room, o.support, o.container, tuple(sorted(o.states.items())))
            for o in env.objects]  # type: ignore[attr-defined]


@settings(max_examples=12, deadline=None)
@given(st.sampled_from(TASKS), st.integers(min_value=0, max_value=10_000))
def test_every_world_realises_the_same_situation(task_id: str, pick: int) -> None:
    task = load_task(task_id)
    trajs = situations(task)
    traj = trajs[pick % len(trajs)]
    worlds = situation_worlds(task, traj, limit=6)
    assert worlds[0] == situation_env(task, traj)
    assert 1 <= len(worlds) <= 6
    want = [p.key for p in traj.paths]
    for env in worlds:
        got = [o.path.key if o.path else None for o in evaluate_task(task, holds_initial(env))]
        assert got == want
        for o in env.objects:  # physical axioms: one support xor one container, in the holder's room
            assert (o.support is None) != (o.container is None)
            holder = o.container or (o.support if o.support != "floor" else None)
            if holder is not None:
                assert next(h.room for h in env.objects if h.id == holder) == o.room
    assert len({str(_placement(w)) for w in worlds}) == len(worlds)  # all different
    assert situation_worlds(task, traj, limit=6) == worlds  # deterministic


def test_limit_one_is_the_minimal_world() -> None:
    task = load_task("clean_living_room")
    traj = situations(task)[0]
    assert situation_worlds(task, traj, limit=1) == [situation_env(task, traj)]


def test_varied_worlds_hide_the_backpack_in_a_closed_wardrobe() -> None:
    task = load_task("hallway_coat_and_bag")
    traj = next(t for t in situations(task)
                if "lunch_in_backpack=yes" in t.key and "backpack_on_floor=no" in t.key)
    worlds = situation_worlds(task, traj)
    hidden = [w for w in worlds for o in w.objects if o.id == "backpack" and o.container == "wardrobe"
              and not next(x for x in w.objects if x.id == "wardrobe").states.get("open", False)]
    assert hidden


def test_old_hallway_fails_multi_world_validation_and_passes_single_world() -> None:
    report = validate_task(OLD / "hallway_coat_and_bag", OLD)
    assert any("lunch_box" in p.message and "closed container 'wardrobe'" in p.message
               and p.file == "policies/correct.xml" for p in report.problems), report.problems[:3]
    assert validate_task(OLD / "hallway_coat_and_bag", OLD, worlds=1).ok


def test_fixed_hallway_passes_multi_world_validation() -> None:
    report = validate_task("hallway_coat_and_bag")
    assert report.ok, report.problems[:3]
    assert all(report.revealing[k] for k in ("counterfactual", "unreachable", "lackbranch"))


def test_validate_cli_exit_codes(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["tasks", "validate", "--tasks-dir", str(OLD)]) == 1
    out = capsys.readouterr().out
    assert "closed container 'wardrobe'" in out and "[in varied world" in out
    assert main(["tasks", "validate", "--task", "hallway_coat_and_bag"]) == 0
    with pytest.raises(SystemExit) as exc:
        main(["tasks", "validate", "--worlds", "0"])
    assert exc.value.code == 2
