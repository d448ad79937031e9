"""Unit files store traces as [tick, step] pairs with tree paths and steps once, killed mutants
as numbers; loading gives back the same record."""

from __future__ import annotations

import json
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from logicenveval.metrics.records import (
    EnvDetail,
    EnvSample,
    PhysicsSummary,
    UnitRecord,
    VerdictTrace,
)
from logicenveval.runner.store import RunStore, _digest
from logicenveval.runner.unit_codec import (
    PATHS,
    STEPS,
    PathTable,
    decode_unit,
    encode_unit,
    full_paths,
)

PATH = "CleanLivingRoom/Sequence/SubTree(TidyToy)[0]/Fallback/IfThenElse[1]/Sequence[1]/Walk[0]"
LINES = [
    f"{{'tick': 1, 'node': 'Walk', 'path': '{PATH}', 'status': 'RUNNING', 'ports': 'target=toy'}}",
    f"{{'tick': 2, 'node': 'Walk', 'path': '{PATH}', 'status': 'SUCCESS'}}",
    f"{{'tick': 3, 'node': 'Pick', 'path': '{PATH}', 'status': 'FAILURE', 'ports': ''}}",
    "{'tick': 4, 'node': \"it's\", 'path': 'a', 'status': 'SUCCESS'}",  # not the plain form: text
    "{'tick': 05, 'node': 'Walk', 'path': 'a', 'status': 'SUCCESS'}",  # a row would read 5: text
    "the goal holds",
]


def _record(lines: list[str], killed: tuple[list[str], ...] = ()) -> UnitRecord:
    traces = {k: VerdictTrace(status="passed", trace=lines) for k in ("correct", "unreachable")}
    physics = PhysicsSummary(floor_plan=True, entity=True, relation=True)
    return UnitRecord(generator="cot", task_id="clean_living_room",
                      mutants={"m-b": "counterfactual", "m-a": "unreachable", "m-c": "lackbranch"},
                      samples=[EnvSample(generator="cot", task_id="clean_living_room", env_id=f"cot-0{i}",
                                         physics=physics, killed_mutants=k) for i, k in enumerate(killed)],
                      details=[EnvDetail(env_id=e, traces=traces) for e in ("cot-00", "cot-01")])


def test_rows_with_paths_once_and_the_same_record_back(tmp_path: Path) -> None:
    record = _record(LINES)
    payload = encode_unit(record.model_dump(mode="json"))
    parts = PATH.split("/")
    assert payload[PATHS] == [parts[0], *([i, part] for i, part in enumerate(parts[1:]))]  # a trie
    assert full_paths(payload[PATHS])[-1] == PATH
    last = len(parts) - 1
    assert payload[STEPS] == [["Walk", last, "RUNNING", "target=toy"], ["Walk", last, "SUCCESS"],
                              ["Pick", last, "FAILURE", ""]]
    trace = payload["details"][0]["traces"]["correct"]["trace"]
    assert trace[:3] == [[1, 0], [2, 1], [3, 2]]
    assert trace[3:] == LINES[3:]
    assert payload["details"][1]["traces"]["unreachable"]["trace"][:3] == trace[:3]  # steps shared
    assert UnitRecord.model_validate(decode_unit(json.loads(json.dumps(payload)))) == record
    store = RunStore(tmp_path)
    store.save(record)
    assert store.load("cot", "clean_living_room") == record
    assert len(store.unit_path("cot", "clean_living_room").read_text()) < \
        len(json.dumps(record.model_dump(mode="json")))


def test_a_unit_written_with_text_lines_still_loads(tmp_path: Path) -> None:
    record = _record(LINES)
    payload = record.model_dump(mode="json")  # the earlier form: no trace_paths, every line text
    path = RunStore(tmp_path).unit_path("cot", "clean_living_room")
    path.parent.mkdir(parents=True)
    path.write_text(json.dumps({"sha256": _digest(payload), "unit": payload}))
    assert RunStore(tmp_path).load("cot", "clean_living_room") == record


def test_killed_mutants_are_numbers_of_the_units_sorted_mutants(tmp_path: Path) -> None:
    record = _record(LINES, (["m-c", "m-a"], [], ["m-b"]))
    payload = encode_unit(record.model_dump(mode="json"))
    assert [s["killed_mutants"] for s in payload["samples"]] == [[2, 0], [], [1]]
    assert payload["mutants"] == {"unreachable": ["m-a"], "counterfactual": ["m-b"], "lackbranch": ["m-c"]}
    assert UnitRecord.model_validate(decode_unit(json.loads(json.dumps(payload)))) == record
    store = RunStore(tmp_path)
    store.save(record)
    assert store.load("cot", "clean_living_room") == record
    odd = _record(LINES, (["m-a", "not-a-mutant"],))  # an id the unit does not list stays an id
    assert encode_unit(odd.model_dump(mode="json"))["samples"][0]["killed_mutants"] == ["m-a", "not-a-mutant"]


def test_a_unit_written_with_full_rows_still_loads(tmp_path: Path) -> None:
    record = _record(LINES)
    payload = record.model_dump(mode="json")  # the form before steps: [tick, node, path, status(, ports)]
    rows = [[1, "Walk", 0, "RUNNING", "target=toy"], [2, "Walk", 0, "SUCCESS"], [3, "Pick", 0, "FAILURE", ""]]
    for detail in payload["details"]:
        for verdict in detail["traces"].values():
            verdict["trace"] = [*rows, *LINES[3:]]
    payload[PATHS] = [PATH]
    path = RunStore(tmp_path).unit_path("cot", "clean_living_room")
    path.parent.mkdir(parents=True)
    path.write_text(json.dumps({"sha256": _digest(payload), "unit": payload}))
    assert RunStore(tmp_path).load("cot", "clean_living_room") == record


def test_a_damaged_row_makes_the_unit_recomputed(tmp_path: Path) -> None:
    payload = encode_unit(_record(LINES, (["m-a"],)).model_dump(mode="json"))
    for bad in ([1, 7], [1, -1], [1, "Walk"], ["1", 0], [1, "Walk", 0, "SUCCESS"], 3):
        payload["details"][0]["traces"]["correct"]["trace"][0] = bad
        path = RunStore(tmp_path).unit_path("cot", "clean_living_room")
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps({"sha256": _digest(payload), "unit": payload}))
        assert RunStore(tmp_path).load("cot", "clean_living_room") is None
    payload = encode_unit(_record(LINES, (["m-a"],)).model_dump(mode="json"))
    for paths, steps, killed in ((payload[PATHS], [["Walk", 99, "SUCCESS"]], [0]),
                                 (payload[PATHS], [["Walk", 0]], [0]), (payload[PATHS], payload[STEPS], [3]),
                                 (payload[PATHS], payload[STEPS], [0, "m-a"]),
                                 (["R", [2, "a"], [0, "b"]], payload[STEPS], [0]),  # a parent after its child
                                 (["R", [0, 1]], payload[STEPS], [0]), (["R", 3], payload[STEPS], [0])):
        damaged = {**payload, PATHS: paths, STEPS: steps,
                   "samples": [{**payload["samples"][0], "killed_mutants": killed}]}
        path.write_text(json.dumps({"sha256": _digest(damaged), "unit": damaged}))
        assert RunStore(tmp_path).load("cot", "clean_living_room") is None


_TEXT = st.text(st.characters(blacklist_categories=("Cs",)), max_size=12)


@given(st.lists(st.one_of(
    st.builds(lambda t, n, p, s, ports: f"{{'tick': {t}, 'node': '{n}', 'path': '{p}', 'status': "
              f"'{s}'" + ("" if ports is None else f", 'ports': '{ports}'") + "}",
              st.integers(0, 10**6), _TEXT, _TEXT, _TEXT, st.none() | _TEXT),
    _TEXT), max_size=8))
def test_any_lines_round_trip(lines: list[str]) -> None:
    payload = _record(lines).model_dump(mode="json")
    assert decode_unit(json.loads(json.dumps(encode_unit(payload)))) == payload


@given(st.lists(st.text(st.sampled_from("ab/[]0"), max_size=12), max_size=12))
def test_a_path_trie_gives_back_every_path(paths: list[str]) -> None:
    table = PathTable()
    numbers = [table.number(p) for p in paths]
    full = full_paths(json.loads(json.dumps(table.entries)))
    assert [full[n] for n in numbers] == paths
    assert len(full) == len(set(full))  # each path (and parent) listed once
