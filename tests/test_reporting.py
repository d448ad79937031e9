"""Leaderboard cells (intervals as bounds, unmeasured rows), reasons, report pages, compare."""

from __future__ import annotations

import copy
import json
import re
import shutil
from pathlib import Path
from typing import Any

import pytest

from logicenveval.cli import main
from logicenveval.metrics.uncertainty import ci95
from logicenveval.reporting.compare import compare_results
from logicenveval.reporting.details import EnvView, VerdictView, slug, tick_data, trace_rows
from logicenveval.reporting.tables import markdown, rows
from logicenveval.reporting.why import reason_key, reasons, summary_text
from logicenveval.runner.unit_codec import full_paths

REFERENCE = Path(__file__).resolve().parents[1] / "reports" / "reference" / "results.json"
TASKS = "clean_living_room,hallway_entry_tidy,kitchen_fridge_restock"


def _reference() -> dict[str, Any]:
    data: dict[str, Any] = json.loads(REFERENCE.read_text())
    return data


def _only_dir(parent: Path) -> Path:
    (d,) = [p for p in parent.iterdir() if p.is_dir()]
    return d


# ----- intervals -------------------------------------------------------------------------------

def test_interval_depends_on_the_data_not_the_name() -> None:
    ref = _reference()
    cells = {(t, 0): m for t, m in ref["per_task"]["logicenvgen"].items()}
    assert ci95(cells) == ci95(dict(cells))  # fixed seed: reproducible
    renamed = {(t, 7): m for (t, _), m in cells.items()}  # another run seed, same figures
    assert ci95(renamed) == ci95(cells)
    other = {(t, 0): m for t, m in ref["per_task"]["cot"].items()}
    assert ci95(other) != ci95(cells)


def test_one_task_gives_no_interval() -> None:
    cell = _reference()["per_task"]["cot"]["clean_living_room"]
    got = ci95({("clean_living_room", 0): cell})
    assert got["logcov"] is None and got["phypr"]["entity"] is None


def test_cells_print_bounds_not_half_widths() -> None:
    ref = _reference()
    for gen in ref["results"]:
        ref["results"][gen]["ci95"] = ci95({(t, 0): m for t, m in ref["per_task"][gen].items()})
    text = markdown(ref)
    assert " ± " not in text
    holodeck = next(r for r in rows(ref) if r[0] == "holodeck")
    logcov = holodeck[1 + 1 + 4]  # Method, n, four PhyPR columns
    value, lo, hi = map(float, re.fullmatch(r"(\S+) \[(\S+), (\S+)\]", logcov).groups())  # type: ignore[union-attr]
    assert lo <= value <= hi and lo >= 0 and hi <= 100
    assert holodeck[1] == "25"


def test_old_half_width_results_and_one_task_rows() -> None:
    ref = _reference()
    one = copy.deepcopy(ref)
    one["tasks"] = ["clean_living_room"]
    for gen in one["per_task"]:
        one["per_task"][gen] = {"clean_living_room": one["per_task"][gen]["clean_living_room"]}
    row = rows(one)[0]
    assert row[1] == "1" and "[n/a]" in row[1 + 1 + 4]


def test_unmeasured_rows_budget_marks_and_failed_attempts() -> None:
    ref = _reference()
    ref["results"]["cot"] = {**{k: None for k in ref["results"]["cot"]}, "measured": False,
                             "n_attempted": 0, "n_failed": 0, "not_measured_tasks": ref["tasks"],
                             "budget_hit_tasks": []}
    ref["results"]["logicenvgen"].update(n_attempted=140, n_failed=2, measured=True,
                                         budget_hit_tasks=ref["tasks"][:4], not_measured_tasks=[])
    by_label = {r[0]: r for r in rows(ref)}
    assert set(by_label["cot"][1:]) == {"not measured"}
    assert "logicenvgen (budget hit 4/25)" in by_label
    assert by_label["logicenvgen (budget hit 4/25)"][-1] == "2/140"
    assert by_label["holodeck"][-1] == "0/25"
    for key in ("n_attempted", "n_failed"):  # results written before attempts were recorded
        del ref["results"]["holodeck"][key]
    assert {r[0]: r for r in rows(ref)}["holodeck"][-1] == "–"
    md = markdown(ref)
    assert "| cot | not measured | not measured |" in md and "0.00 ±" not in md


def test_model_reply_validity_is_shown_when_recorded() -> None:
    ref = _reference()
    ref.pop("llm", None)
    assert "Valid model replies" not in markdown(ref)  # results without an `llm` block
    ref["llm"] = {"cot": {"all": {"questions": 40, "valid_first": 38, "valid": 40,
                                  "valid_first_share": 0.95, "valid_share": 1.0}},
                  "ifg": "damaged"}
    line = next(x for x in markdown(ref).splitlines() if x.startswith("Valid model replies"))
    assert line.endswith("questions asked): cot: 95.0 % / 100.0 % of 40")  # the damaged entry is left out


def test_generator_args_tell_two_otherwise_equal_runs_apart() -> None:
    from logicenveval.reporting.merged import merged_markdown

    a, b = _reference(), _reference()
    a["config"]["generator_args"] = {"cot": {"n_envs": 3, "strict": True}}
    # keyed by the `--generators` item as written, which is not the row's name
    b["config"]["generators"] = ["my_pkg.gen:Cot" if g == "cot" else g for g in b["generators"]]
    b["config"]["generator_args"] = {"my_pkg.gen:Cot": {"n_envs": 5}}
    assert "| cot (n_envs=3, strict=true) |" in markdown(a)
    assert "| cot (n_envs=5) |" in markdown(b) and "| holodeck |" in markdown(b)
    merged = merged_markdown([(Path("gridA"), a), (Path("gridB"), b)])
    assert "cot (n_envs=3, strict=true) |" in merged and "cot (n_envs=5) |" in merged
    from logicenveval.reporting.leaderboard import table_rows

    html_rows = {r.anchor: r for r in table_rows(b)}
    assert html_rows["gen-cot"].lead == ["cot (n_envs=5)"] and "n_envs=5" in html_rows["gen-cot"].filter


def test_markdown_cells_cannot_break_the_table() -> None:
    ref = _reference()
    ref["results"] = {"a|b\nc": ref["results"]["cot"]}
    ref["per_task"] = {"a|b\nc": ref["per_task"]["cot"]}
    line = next(x for x in markdown(ref).splitlines() if x.startswith("| a"))
    assert line.startswith("| a\\|b c |") and "\n" not in line


# ----- reasons -----------------------------------------------------------------------------------

def test_reasons_group_by_shape_and_keep_the_first_example() -> None:
    assert reason_key("role vanity is not bound to an object") == reason_key("role spare_bag is not bound to an object")
    samples = [
        {"generator": "g", "task_id": "t", "env_id": "e0", "well_formed": False,
         "problems": ["role white_box is not bound to an object"], "verdicts": {"correct": "passed"},
         "physics": {"failures": []}},
        {"generator": "g", "task_id": "t", "env_id": "e1", "well_formed": False,
         "problems": ["role mop is not bound to an object"], "verdicts": {}, "physics": {"failures": []}},
        {"generator": "g", "task_id": "t", "env_id": "e2", "well_formed": True, "problems": [],
         "verdicts": {"correct": "goal_unmet"},
         "physics": {"failures": [{"dimension": "entity", "code": "floating", "message": "cup floats 0.3 m"}]}},
    ]
    failures = {"g": [{"task": "t", "stage": "construct", "message": "no layout for x"}]}
    (g,) = reasons(samples, failures, ["g"], {("g", "t", "e2", ""): "correct BT goal_unmet: cup not on table"})
    assert (g.n_envs, g.n_failed, g.n_rejected, g.n_physics) == (3, 1, 3, 1)
    labels = {r.label: r for r in g.reasons}
    bound = labels["rejected: ill-formed: role … is not bound to an object"]
    assert bound.count == 2 and bound.env_id == "e0" and "white_box" in bound.example
    assert labels["rejected: the correct BT ends goal_unmet"].example == "correct BT goal_unmet: cup not on table"
    assert labels["physics: PhyPR entity: floating"].example == "cup floats 0.3 m"
    assert g.reasons[0].kind == "generation"
    text = summary_text([g])
    assert "2 × rejected: ill-formed" in text and "t/e0: role white_box" in text


def test_extra_check_failures_are_reasons_not_a_clean_bill() -> None:
    """An environment that passes PhyPR but fails an extra check (the leaderboard's Extra checks
    below 100) is listed, not summed up as "none rejected ... physically implausible"."""
    samples = [{"generator": "g", "task_id": "t", "env_id": f"e{i}", "well_formed": True, "problems": [],
                "verdicts": {"correct": "passed"},
                "physics": {"failures": [], "extended_failures": [
                    {"dimension": "entity", "code": "blocks_door", "message": f"towel stands in door d{i}'s swing"}]}}
               for i in range(2)]
    (g,) = reasons(samples, {}, ["g"])
    assert not g.clean and (g.n_rejected, g.n_physics, g.n_extra) == (0, 0, 2)
    (r,) = g.reasons
    assert (r.label, r.count, r.example) == ("extra check: blocks_door", 2, "towel stands in door d0's swing")
    text = summary_text([g])
    assert "none rejected" not in text and "2 failing extra checks" in text
    assert "2 × extra check: blocks_door — t/e0" in text


def test_a_stage_failure_of_a_returned_environment_is_no_failed_attempt() -> None:
    """A layout that misses its claimed trajectory is logged as a construct failure, yet the
    environment is returned and scored: the summary must agree with results.json's n_failed."""
    samples = [{"generator": "g", "task_id": "t", "env_id": "e0", "well_formed": False,
                "problems": ["role toy is not bound to an object"], "verdicts": {}, "physics": {}}]
    failures = {"g": [{"task": "t", "env_id": "e0", "stage": "construct",
                       "message": "e0 does not realise its trajectory in subtasks ['sofa']"},
                      {"task": "t", "env_id": "e1", "stage": "construct", "message": "no layout for x"}]}
    (g,) = reasons(iter(samples), failures, ["g"])
    assert (g.n_envs, g.n_failed, g.n_short, g.n_rejected) == (1, 1, 1, 1)
    assert [r.kind for r in g.reasons] == ["generation", "built short", "rejected"]
    text = summary_text([g])
    assert "1 environment(s) (1 stage failure(s) in returned ones); 1 failed to generate" in text
    assert "1 × built short: construct: e# does not realise its trajectory" in text
    # a failed unit is one record but all its planned attempts: with results.json's counts the
    # summary says what the leaderboard's Failed / attempted says
    (g,) = reasons(samples, failures, ["g"], scores={"g": {"n_failed": 12, "n_attempted": 13}})
    assert "; 12/13 attempted failed to generate" in summary_text([g])


def test_in_a_multi_seed_run_a_failure_is_matched_to_its_own_seeds_environments() -> None:
    """Seeds' environments share ids: seed 1's failed e0 is not the e0 seed 0 built, and each
    example names its seed."""
    samples = [{"generator": "g", "task_id": "t", "env_id": "e0", "seed": "0", "well_formed": True,
                "problems": [], "verdicts": {"correct": "goal_unmet"}, "physics": {}}]
    failures = {"g": [{"task": "t", "env_id": "e0", "seed": 1, "stage": "construct", "message": "no layout"}]}
    (g,) = reasons(samples, failures, messages={("g", "t", "e0", "0"): "correct BT goal_unmet: seed 0's",
                                                ("g", "t", "e0", "1"): "correct BT goal_unmet: seed 1's"})
    assert (g.n_failed, g.n_short, g.n_rejected) == (1, 0, 1)
    gen, rejected = g.reasons
    assert (gen.kind, gen.where) == ("generation", "t/e0 (seed 1)")
    assert rejected.where == "t/e0 (seed 0)" and rejected.example == "correct BT goal_unmet: seed 0's"
    assert "1 × generation: construct: no layout — t/e0 (seed 1): no layout" in summary_text([g])


def test_trace_lines_become_tick_rows_and_slugs_are_safe() -> None:
    lines = ["{'tick': 1, 'node': 'Walk', 'path': 'R/Sequence/Walk[0]', 'status': 'RUNNING'}",
             "{'tick': 2, 'node': 'Walk', 'path': 'R/Sequence/Walk[0]', 'status': 'SUCCESS', "
             "'ports': 'target=kitchen'}",
             "{'tick': 3, 'node': 'Pick', 'path': 'R/Sequence/Pick[1]', 'status': 'violation', "
             "'detail': \"not 'near'\", 'ports': 'obj=cup_1'}",
             "{'tick': 4, 'node': 'Walk', 'path': 'R/Sequence/Walk[0]', 'status': 'SUCCESS'}",
             "__import__('os').system('x')", "plain text"]
    got, other = trace_rows(lines)
    assert [(r.tick, r.node, r.status) for r in got] == [
        ("1", "Walk", "RUNNING"), ("2", "Walk target=kitchen", "SUCCESS"), ("3", "Pick obj=cup_1", "violation"),
        ("4", "Walk target=kitchen", "SUCCESS")]  # ports carried forward by path
    assert other == lines[4:]
    # a page's tables travel as one compact JSON: paths and (node, status, path) steps once each
    env = EnvView("e0", "env-e0", True, True, [], {}, [], [], "", [
        VerdictView("correct", "passed", "passed", True, True, "", lines),
        VerdictView("lackbranch", "passed", "missed", False, True, "", [])])
    assert (env.verdicts[0].rows, env.verdicts[0].other) == (got, other)  # read when a page shows it
    data = tick_data([env, env])
    assert data.at == [[0, None], [1, None]]
    assert page_ticks(f'<script type="application/json" id="ticks">{data.json}</script>') == [
        [(r.tick, r.node, r.status, r.path) for r in got]] * 2
    assert len(json.loads(data.json)["steps"]) == 3
    assert json.loads(data.json)["paths"] == ["R", [0, "Sequence"], [1, "Walk[0]"], [1, "Pick[1]"]]  # a trie
    assert slug("logicenvgen-exact") == "logicenvgen-exact"
    for bad in ("../x", "/abs", "a b", "", ".."):
        s = slug(bad)
        assert re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9._-]*", s) and "/" not in s and s != slug(bad + "y")


# ----- compare -----------------------------------------------------------------------------------

def test_compare_two_generators_and_missing_ones() -> None:
    ref = _reference()
    c = compare_results(ref, ref, gen_a="logicenvgen", gen_b="holodeck")  # a clear LogCov drop
    (pair,) = c.pairs
    logcov = next(d for d in pair.deltas if d.metric == "LogCov")
    assert logcov.ci95 is not None and logcov.ci95[0] <= logcov.change <= logcov.ci95[1]  # type: ignore[operator]
    assert logcov.regression and c.failed
    assert not compare_results(ref, ref).failed
    lost = copy.deepcopy(ref)
    del lost["results"]["ifg"]
    assert [m.text for m in compare_results(ref, lost).missing] == ["generator ifg: missing in B"]
    assert compare_results(ref, lost).failed and not compare_results(ref, lost, allow_missing=True).failed
    empty = {**ref, "results": {}}
    assert compare_results(ref, empty).failed
    unmeasured = copy.deepcopy(ref)
    unmeasured["results"]["cot"]["measured"] = False
    assert compare_results(ref, unmeasured).missing[0].text == "generator cot: not measured in B"


# ----- through the CLI ---------------------------------------------------------------------------

@pytest.fixture(scope="module")
def run_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("run")
    assert main(["run", "--model", "offline", "--tasks", TASKS, "--generators", "logicenvgen,cot,holodeck",
                 "--executor", "inprocess", "--quiet", "--output", str(out)]) == 0
    return _only_dir(out)


def test_run_ends_with_the_reasons(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # CoT writes doors off the walls of this task's rooms: the reasons name the PhyPR finding
    assert main(["run", "--model", "offline", "--tasks", "multi_room_trash_run", "--generators", "cot",
                 "--executor", "inprocess", "--quiet", "--output", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    why = out[out.index("Why (count × reason; examples in leaderboard.html)"):]
    # in the words of its first example, wrapped, never shortened to its shape (issue 48)
    assert "cot: " in why and "door_not_on_wall" in why
    assert "…" not in why
    # the terminal summary fits 100 columns (issue 36); a long path gets a line of its own, whole
    assert max(len(line) for line in out.splitlines() if not line.startswith(str(tmp_path))) <= 100
    page = (_only_dir(tmp_path) / "leaderboard.html").read_text(encoding="utf-8")
    assert "door_not_on_wall" in page  # the examples are on the page


def test_same_environments_under_two_names_same_interval(run_dir: Path, tmp_path: Path) -> None:
    for name in ("first", "second"):
        assert main(["evaluate", str(run_dir / "envs" / "cot"), "--name", name, "--executor", "inprocess",
                     "--output", str(tmp_path / name)]) == 0
    a, b = (json.loads((_only_dir(tmp_path / n) / "results.json").read_text()) for n in ("first", "second"))
    assert a["results"]["first"]["ci95"] == b["results"]["second"]["ci95"]
    original = json.loads((run_dir / "results.json").read_text())["results"]["cot"]["ci95"]
    assert a["results"]["first"]["ci95"] == original


def test_one_task_evaluate_prints_na(run_dir: Path, tmp_path: Path) -> None:
    src = tmp_path / "envs"
    (src / "clean_living_room").mkdir(parents=True)
    for f in (run_dir / "envs" / "cot" / "clean_living_room").glob("cot-*.json"):
        (src / "clean_living_room" / f.name).write_text(f.read_text())
    assert main(["evaluate", str(src), "--name", "one", "--executor", "inprocess",
                 "--output", str(tmp_path / "o")]) == 0
    md = (_only_dir(tmp_path / "o") / "leaderboard.md").read_text()
    assert "[n/a]" in md and "± 0.00" not in md


def test_compare_two_generators_of_one_run_and_json(run_dir: Path, capsys: pytest.CaptureFixture[str]) -> None:
    capsys.readouterr()
    code = main(["compare", str(run_dir), "--gen-a", "logicenvgen", "--gen-b", "holodeck"])
    out = capsys.readouterr().out
    assert code == 1 and "logicenvgen (A) → holodeck (B)" in out
    assert "95 % CI of change" in out and "verdict" in out
    assert re.search(r"LogCov \(%\) .*[-+]\d+\.\d\d .*\[[-+]\d+\.\d\d, [-+]\d+\.\d\d\] .*REGRESSION", out), out
    assert main(["compare", str(run_dir), str(run_dir), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert sorted(p["a"] for p in data["pairs"]) == ["cot", "holodeck", "logicenvgen"] and not data["failed"]
    assert main(["compare", str(run_dir), "--gen-a", "nope"]) == 2
    assert "--gen-a" in capsys.readouterr().err


def test_compare_candidate_that_lost_a_generator(run_dir: Path, tmp_path: Path,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    data = json.loads((run_dir / "results.json").read_text())
    for name, change in (("lost", lambda d: d["results"].pop("cot")), ("empty", lambda d: d.update(results={}))):
        damaged = copy.deepcopy(data)
        change(damaged)
        (tmp_path / name).mkdir()
        (tmp_path / name / "results.json").write_text(json.dumps(damaged))
        capsys.readouterr()
        assert main(["compare", str(run_dir), str(tmp_path / name)]) == 1
        assert "generator cot: missing in B" in capsys.readouterr().out
    assert main(["compare", str(run_dir), str(tmp_path / "lost"), "--allow-missing"]) == 0


@pytest.mark.parametrize("damage,field", [
    (lambda d: d.update(benchmark=[]), "field 'benchmark'"),
    (lambda d: d.update(per_task=[]), "field 'per_task'"),
    (lambda d: d["per_task"]["cot"].update(clean_living_room="x"), "per_task.cot.clean_living_room"),
    (lambda d: d["per_task"].update(cot=["x"]), "per_task.cot"),
    (lambda d: d["results"]["cot"].update(n_envs=float("nan")), "results.cot.n_envs"),
    (lambda d: d["per_task"]["cot"]["clean_living_room"].update(n_envs=float("inf")),
     "per_task.cot.clean_living_room.n_envs"),
    (lambda d: d["results"]["cot"].update(measured="yes"), "results.cot.measured"),
    (lambda d: d["results"]["cot"]["ci95"].update(logcov=[0.1]), "results.cot.ci95.logcov"),
    (lambda d: d["per_task"]["cot"]["clean_living_room"].update(faudr={}), "per_task.cot.clean_living_room.faudr"),
])
def test_damaged_results_exit_2_naming_the_field(run_dir: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                 damage: Any, field: str) -> None:
    data = json.loads((run_dir / "results.json").read_text())
    damage(data)
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "results.json").write_text(json.dumps(data))  # NaN/inf written as JSON's extensions
    for argv in (["report", str(bad)], ["compare", str(run_dir), str(bad)], ["report", str(run_dir), str(bad),
                                                                             "--out", str(tmp_path / "m")]):
        capsys.readouterr()
        assert main(argv) == 2, argv
        err = capsys.readouterr().err
        assert field in err and "Traceback" not in err


def test_report_pages_show_why_and_stand_alone(run_dir: Path, tmp_path: Path) -> None:
    written_by_run = (run_dir / "leaderboard.md").read_text()
    assert main(["report", str(run_dir)]) == 0
    # results.json's keys are sorted; its `generators` keeps the run's row order for the report
    assert (run_dir / "leaderboard.md").read_text() == written_by_run
    assert [x.split(" |")[0] for x in written_by_run.splitlines() if x.startswith("| ") and "Method" not in x] \
        == ["| logicenvgen", "| cot", "| holodeck"]
    html = (run_dir / "leaderboard.html").read_text()
    assert 'id="gen-cot"' in html and 'id="t-cot--clean_living_room"' in html and 'id="filter"' in html
    assert "Why environments were rejected or failed" in html
    page = (run_dir / "details" / "cot" / "kitchen_fridge_restock.html").read_text()
    assert 'id="env-cot-00"' in page and 'data-trace="0"' in page and "{'tick'" not in page
    assert page_ticks(page)[0][0][0] == "1" and "<table" not in page.split('<div class="envs-grid">')[1]
    assert re.search(r">(detected|missed)</span>", page)
    samples = [json.loads(x) for x in (run_dir / "samples.jsonl").read_text().splitlines()]
    physics = next(f for s in samples for f in s["physics"]["failures"] if s["generator"] == "cot")
    owner = next(s for s in samples if physics in s["physics"]["failures"])
    owner_page = (run_dir / "details" / "cot" / f"{owner['task_id']}.html").read_text()
    assert physics["message"].replace("'", "&#39;") in owner_page  # the message, not only a red label
    # renders are linked (written once, under renders/), with the EnvSpec file; links are relative,
    # so the run folder works moved whole
    moved = tmp_path / "moved"
    shutil.copytree(run_dir, moved)
    page_path = moved / "details" / "cot" / "clean_living_room.html"
    moved_page = page_path.read_text()
    assert "data:image" not in moved_page and 'src="../../renders/cot/clean_living_room/cot-00.svg"' in moved_page
    assert 'href="../../envs/cot/clean_living_room/cot-00.json"' in moved_page
    assert _broken_links(page_path) == []
    # a render that is gone is re-drawn from the stored environment, written back once and linked
    (moved / "renders" / "cot" / "clean_living_room" / "cot-00.svg").unlink()
    assert main(["report", str(moved)]) == 0
    assert (moved / "renders" / "cot" / "clean_living_room" / "cot-00.svg").read_text().startswith("<svg")
    assert _broken_links(page_path) == []


def page_ticks(page: str) -> list[list[tuple[str, str, str, str]]]:
    """A detail page's tick tables as its script draws them: (tick, node, status, full path) rows."""
    found = re.search(r'<script type="application/json" id="ticks">(.*?)</script>', page, re.S)
    assert found is not None and "<" not in found.group(1)
    data = json.loads(found.group(1))
    data["paths"] = full_paths(data["paths"])
    return [[(str(flat[i]), *data["steps"][flat[i + 1]][:2], data["paths"][data["steps"][flat[i + 1]][2]])
             for i in range(0, len(flat), 2)] for flat in data["traces"]]


def _broken_links(page: Path) -> list[str]:
    """The page's relative src/href targets (anchors and queries aside) that are not files."""
    from urllib.parse import unquote

    links = re.findall(r'(?:src|href)="([^"#?]+)[^"]*"', page.read_text())
    return [x for x in links if "://" not in x and not (page.parent / unquote(x)).is_file()]


def test_report_replaces_files_atomically(run_dir: Path, monkeypatch: pytest.MonkeyPatch,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    import errno

    from logicenveval import atomic

    before = (run_dir / "leaderboard.html").read_bytes()

    def full(src: str, dst: str) -> None:
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(atomic.os, "replace", full)
    assert main(["report", str(run_dir)]) == 1
    monkeypatch.undo()
    assert (run_dir / "leaderboard.html").read_bytes() == before
    assert not list(run_dir.rglob("*.tmp"))
    assert "No space left on device" in capsys.readouterr().err


def test_report_of_runs_has_a_run_column(run_dir: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    capsys.readouterr()
    assert main(["report", str(run_dir), str(run_dir), "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert f"| {run_dir.name} (1) | offline | 0 | cot |" in out and f"| {run_dir.name} (2) | offline | 0 | cot |" in out
    html = (tmp_path / "leaderboard.html").read_text()
    assert 'href="details/run1/cot/clean_living_room.html' in html
    assert len(html) < 1_000_000
    # the merged folder stands alone: each run's renders and environments are copied under files/
    page = tmp_path / "details" / "run1" / "cot" / "clean_living_room.html"
    assert 'src="../../../files/run1/renders/cot/clean_living_room/cot-00.svg"' in page.read_text()
    assert _broken_links(page) == [] and _broken_links(tmp_path / "leaderboard.html") == []


# ----- filters find every word shown --------------------------------------------------------------

_WORD = re.compile(r"[A-Za-z][\w-]*")


def _text(fragment: str) -> str:
    import html as html_lib

    return html_lib.unescape(re.sub(r"<[^>]+>", " ", fragment))


def _filters(page: str, tag: str, marker: str = "") -> list[tuple[str, str]]:
    """(filter text, inner HTML) of each `tag` with a data-filter (and `marker`) on a page."""
    import html as html_lib

    return [(html_lib.unescape(m.group(1)).lower(), m.group(2)) for m in re.finditer(
        rf'<{tag}\b[^>]*{marker}[^>]*data-filter="([^"]*)"[^>]*>(.*?)</{tag}>', page, re.S)]


def _found(filter_text: str, typed: str) -> bool:
    """The page's filter: every typed word is a substring of the element's filter text."""
    return all(w in filter_text for w in typed.lower().split())


@pytest.fixture(scope="module")
def faulty_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A run with every kind of reason: ill-formed, a failing correct BT, PhyPR codes, extra checks."""
    out = tmp_path_factory.mktemp("faulty")
    tasks = _without_spare_bag_purpose(tmp_path_factory.mktemp("tasks"))
    assert main(["run", "--model", "offline", "--tasks", "bathroom_towel_refresh,multi_room_trash_run",
                 "--generators", "cot,holodeck,logicenvgen", "--executor", "inprocess", "--quiet",
                 "--tasks-dir", str(tasks), "--output", str(out)]) == 0
    return _only_dir(out)


def _without_spare_bag_purpose(folder: Path) -> Path:
    """The benchmark tasks with multi_room_trash_run's two trash-bag roles told apart by nothing:
    an environment with one bag leaves both ambiguous (ill-formed), as before issue 45."""
    from logicenveval.benchmark import tasks_dir

    tasks = folder / "tasks"
    shutil.copytree(tasks_dir(), tasks)
    path = tasks / "multi_room_trash_run" / "task.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["roles"]["spare_bag"].pop("attributes")
    data["constraints"] = [c for c in data["constraints"] if "spare_bag, purpose" not in c["fact"]]
    path.write_text(json.dumps(data), encoding="utf-8")
    return tasks


def test_the_filters_find_every_reason_word_and_code_shown(faulty_run: Path) -> None:
    run_dir = faulty_run
    page = (run_dir / "leaderboard.html").read_text()
    rows = [f for f, _ in _filters(page, "tr", "data-count")]
    reasons = _filters(page, "li")
    assert rows and reasons and any("extra check" in f for f, _ in reasons)
    typed_any = set()
    for filter_text, inner in reasons:
        shown = _text(inner).replace("e.g.", " ")
        for word in _WORD.findall(shown):
            typed_any.add(word.lower())
            assert _found(filter_text, word), (word, filter_text)  # the reason stays listed
            assert any(_found(r, word) for r in rows), word  # and the index finds its rows
    assert {"interpenetration", "outside_room", "ill-formed", "blocks_door"} <= typed_any
    # every code and verdict word the index shows finds the rows showing it
    for word in ("missed", "detected", "entity", "fails", "valid"):
        if word in page:
            assert any(_found(r, word) for r in rows), word
    # the detail pages: a card is searched by its filter text and its own text (data-text), which
    # holds its lists and trace; codes that only the filter text carries are found too
    pages = sorted((run_dir / "details").rglob("*.html"))
    cards = [(f + " " + _text(inner).lower(), inner) for p in pages
             for f, inner in _filters(p.read_text(), "article", "data-text")]
    assert cards and len(cards) == sum(p.read_text().count("<article") for p in pages)
    for code in ("interpenetration", "outside_room", "blocks_door", "ill-formed", "missed"):
        assert any(_found(text, code) for text, _ in cards), code
    # traces show port values (`Walk target=...`); the page's script draws them and adds them to
    # each card's filter text, drawn or not; every traced BT of a card names its trace
    traces = [page_ticks(p.read_text()) for p in pages]
    assert any(re.fullmatch(r"\w+ \w+=\w.*", node) for t in traces for rows in t for _, node, _, _ in rows)
    for p, t in zip(pages, traces, strict=True):
        named = [int(n) for n in re.findall(r'<details class="bt" data-trace="(\d+)">', p.read_text())]
        assert named == list(range(len(t))) and all(t)


def test_linked_files_never_leave_the_run_folder(tmp_path: Path) -> None:
    """A report links (or, elsewhere, copies) renders and environments named by units: a path or
    symlink leading out of the run folder is neither linked nor copied."""
    from logicenveval.reporting.details import Assets, Source

    run = tmp_path / "run"
    (run / "envs" / "g" / "t").mkdir(parents=True)
    secret = tmp_path / "secret.json"
    secret.write_text("{}")
    (run / "envs" / "g" / "t" / "e0.json").symlink_to(secret)
    (run / "envs" / "g" / "t" / "e1.json").write_text("{}")
    own = Assets(run, Source(run, {}))
    for bad in ("envs/g/t/e0.json", "../secret.json", "envs/../../secret.json", str(secret), ""):
        assert own.inside(bad) is None, bad
    good = own.inside("envs/g/t/e1.json")
    assert good is not None and own.place(good, None) == "envs/g/t/e1.json"
    out = tmp_path / "merged"
    other = Assets(out, Source(run, {}, prefix="run0/"))
    copied = other.inside("envs/g/t/e1.json")
    assert copied is not None and other.place(copied, b"{}") == "files/run0/envs/g/t/e1.json"
    assert (out / "files" / "run0" / "envs" / "g" / "t" / "e1.json").read_text() == "{}"
