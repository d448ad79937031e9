"""Task validator: broken fixtures give precise problems; shipped tasks validate; z3 checks agree
with brute force."""

from __future__ import annotations

import itertools
import shutil
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import DEFAULT_TASKS_DIR, load_task
from logicenveval.benchmark_validation import situations, validate_all, validate_task
from logicenveval.logic.axioms import Axioms
from logicenveval.model.conditions import evaluate, parse

FIXTURES = Path(__file__).parent / "fixtures" / "broken_tasks"
TASK = "living_room_toy_boxes"
OWN = ["lamp_or_pillow_fetch", "bedroom_bookshelf_sorting", "living_room_toy_boxes"]


def _problems(case: str, simulate: bool = True) -> list[str]:
    report = validate_task(TASK, FIXTURES / case, simulate=simulate)
    return [str(p) for p in report.problems]


def test_missing_role_names_file_line_and_role() -> None:
    (p,) = _problems("missing_role")
    assert "policies/correct.xml" in p and ":56" in p and "'broom'" in p


def test_unknown_category() -> None:
    (p,) = _problems("unknown_category", simulate=False)
    assert "roles.mop.category" in p and "hoverboard_mop" in p


def test_overlapping_values() -> None:
    probs = _problems("overlapping_values", simulate=False)
    assert any("'doll' and 'other' overlap" in p and "variables.toy_kind" in p for p in probs)


def test_non_exhaustive_values() -> None:
    (p,) = _problems("non_exhaustive_values", simulate=False)
    assert "variables.pillow_on_floor" in p and "not exhaustive" in p and "subtasks.pillow.tree" in p


def test_faulty_policy_passing_everywhere() -> None:
    (p,) = _problems("faulty_passes_everywhere")
    assert "policies/unreachable.xml" in p and "passes every situation" in p


def test_correct_policy_failing_a_situation() -> None:
    probs = _problems("correct_fails_one_situation")
    assert probs and all("policies/correct.xml" in p and "toy_kind=doll" in p for p in probs)
    assert all("goal_unmet" in p and "inside(toy, blue_box)" in p for p in probs)


def test_own_tasks_validate_and_faults_are_not_all_on_first_branch() -> None:
    for tid in OWN:
        report = validate_task(tid)
        assert report.ok, report.problems
        first = situations(load_task(tid))[0].key
        assert set(report.revealing) == {"counterfactual", "unreachable", "lackbranch"}
        assert any(first not in keys for keys in report.revealing.values()), tid
        assert all(0 < len(keys) < report.situations for keys in report.revealing.values())


def test_situations_are_cartesian_product() -> None:
    task = load_task("bedroom_bookshelf_sorting")
    assert len(situations(task)) == 4 * 3 * 2


@pytest.mark.slow
def test_whole_benchmark_validates() -> None:
    bad = [str(p) for r in validate_all() for p in r.problems]
    assert bad == []


# ----- property: the z3 encoding agrees with a brute-force truth table over the axioms -------------

_ATOMS = ["on(toy, floor)", "on(toy, sofa)", "inside(toy, box)", "attr(toy, kind, doll)",
          "attr(toy, kind, car)", "state(toy, dirty)"]
_conds = st.recursive(
    st.sampled_from(_ATOMS),
    lambda inner: st.one_of(inner.map(lambda c: f"not ({c})"),
                            st.tuples(inner, inner).map(lambda ab: f"({ab[0]}) and ({ab[1]})"),
                            st.tuples(inner, inner).map(lambda ab: f"({ab[0]}) or ({ab[1]})")),
    max_leaves=4)


def _axioms_hold(world: dict[str, bool]) -> bool:
    placed = sum(world[a] for a in _ATOMS[:3])
    kinds = sum(world[a] for a in _ATOMS[3:5])
    return placed <= 1 and kinds <= 1


@settings(max_examples=40, deadline=None)
@given(a=_conds, b=_conds)
def test_overlap_check_matches_truth_table(a: str, b: str) -> None:
    task = load_task("clean_living_room").model_copy(update={"variables": {}})
    ca, cb = parse(a), parse(b)
    enc = Axioms(task.roles, (ca, cb))
    z3_overlap = enc.witness(enc.cond(ca), enc.cond(cb)) is not None
    brute = False
    for bits in itertools.product([False, True], repeat=len(_ATOMS)):
        world = dict(zip(_ATOMS, bits, strict=True))
        if not _axioms_hold(world):
            continue

        def holds(name: str, args: tuple[str, ...], w: dict[str, bool] = world) -> bool:
            return w[f"{name}({', '.join(args)})"]

        if evaluate(ca, holds) and evaluate(cb, holds):
            brute = True
            break
    assert z3_overlap == brute


def test_faulty_policy_of_the_wrong_kind(tmp_path: Path) -> None:
    d = tmp_path / TASK
    shutil.copytree(DEFAULT_TASKS_DIR / TASK, d)
    cf, unr = d / "policies" / "counterfactual.xml", d / "policies" / "unreachable.xml"
    text = cf.read_text(encoding="utf-8")
    cf.write_text(unr.read_text(encoding="utf-8"), encoding="utf-8")
    unr.write_text(text, encoding="utf-8")
    probs = [str(p) for p in validate_task(TASK, tmp_path).problems]
    assert any("counterfactual.xml" in p and "goal_unmet" in p and "not a counterfactual fault" in p
               for p in probs)
    assert any("unreachable.xml" in p and "precondition_violation" in p for p in probs)


def test_stale_tree_nodes_model_is_a_problem_and_write_models_fixes_it(tmp_path: Path) -> None:
    from logicenveval.benchmark_validation import write_models

    d = tmp_path / TASK
    shutil.copytree(DEFAULT_TASKS_DIR / TASK, d)
    correct = d / "policies" / "correct.xml"
    correct.write_text(correct.read_text(encoding="utf-8").replace(
        '<input_port name="obj" type="std::string">role name of the object</input_port>', "", 1),
        encoding="utf-8")
    probs = [str(p) for p in validate_task(TASK, tmp_path, simulate=False).problems]
    assert len(probs) == 1 and "correct.xml" in probs[0] and "TreeNodesModel" in probs[0]
    assert write_models(tmp_path) == [correct]
    assert validate_task(TASK, tmp_path, simulate=False).problems == []
    assert write_models(tmp_path) == []
