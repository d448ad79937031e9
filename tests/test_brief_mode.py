"""`--brief description`: generators see only id, description and rooms (the paper's input), every
request carries the paper's few-shot example, and the harness binds the task's roles itself."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from scripted import Scripted

from logicenveval.benchmark import load_task
from logicenveval.cli import main
from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.base import GenerationContext, make_generator
from logicenveval.generators.brief import BriefMode, generator_brief
from logicenveval.llm.base import ChatModel, ChatRequest
from logicenveval.llm.fewshot import FewShotModel, few_shot_example
from logicenveval.model.task import Role, Task
from logicenveval.offline.model import OfflineModel
from logicenveval.offline.naming import name_objects
from logicenveval.runner.config import DEFAULT_GENERATORS

TASKS = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks"
#: its roles red_box and blue_box are named nowhere in its description
TASK = "kids_room_toy_cleanup"


class Recorder:
    """Innermost model: keeps every request exactly as the provider would receive it."""

    name = "offline"

    def __init__(self) -> None:
        self.inner = OfflineModel()
        self.stats = self.inner.stats
        self.requests: list[ChatRequest] = []

    def complete(self, request: ChatRequest) -> str:
        self.requests.append(request)
        return self.inner.complete(request)


def _canary_task() -> Task:
    """The task with a unique marker in every role's attributes: it reaches a prompt only if the
    roles do."""
    task = load_task(TASK, TASKS)
    roles = {n: Role(category=r.category, attributes={**r.attributes, "marker": f"zqx{n}"})
             for n, r in task.roles.items()}
    return task.model_copy(update={"roles": roles})


def _prompts(mode: BriefMode, generator: str) -> list[str]:
    task = _canary_task()
    recorder = Recorder()
    model: ChatModel = FewShotModel(recorder) if mode == "description" else recorder
    brief = generator_brief(task, mode, model, seed=0)
    ctx = GenerationContext(model=model, catalog=load_catalog(), rng=np.random.default_rng(0), seed=0)
    make_generator(generator).generate(brief, ctx)
    assert recorder.requests
    return [json.dumps(r.messages) + json.dumps(r.payload, default=str) for r in recorder.requests]


@pytest.mark.parametrize("generator", DEFAULT_GENERATORS)
def test_description_brief_never_leaks_roles_into_a_prompt(generator: str) -> None:
    task = _canary_task()
    leaked = [n for n in task.roles if f"zqx{n}" in "".join(_prompts("roles", generator))]
    assert leaked == sorted(task.roles, key=list(task.roles).index)  # the check can fail: roles mode shows them
    prompts = _prompts("description", generator)
    for text in prompts:
        assert "zqx" not in text
        assert "red_box" not in text and "blue_box" not in text
        assert json.dumps(few_shot_example())[1:-1] in text  # the same example in every request


def test_description_brief_names_objects_from_the_description_only() -> None:
    task = load_task(TASK, TASKS)
    brief = generator_brief(task, "description", OfflineModel(), seed=0)
    assert brief.id == task.id and brief.description == task.description and brief.rooms == task.rooms
    assert set(brief.roles) == {o["name"] for o in name_objects(task.description, load_catalog())}
    assert set(brief.roles) != set(task.roles)
    assert generator_brief(task, "roles", OfflineModel()) == task.brief()


def test_run_records_the_brief_and_binds_roles(tmp_path: Path) -> None:
    assert main(["run", "--model", "offline", "--brief", "description", "--tasks", "clean_living_room",
                 "--generators", "logicenvgen", "--executor", "inprocess", "--output", str(tmp_path),
                 "--quiet"]) == 0
    (run_dir,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    results = json.loads((run_dir / "results.json").read_text())
    assert results["brief"] == "description" and results["config"]["brief"] == "description"
    brief = json.loads((run_dir / "envs" / "logicenvgen" / "clean_living_room" / "brief.json").read_text())
    assert "red_box" not in brief["roles"]
    samples = [json.loads(line) for line in (run_dir / "samples.jsonl").read_text().splitlines()]
    # the harness bound the task's roles it could decide (book, sofa, ...); the red and white
    # boxes are not told apart by the offline model's object names, so those envs are ill-formed
    assert samples and all("role red_box" in " ".join(s["problems"]) for s in samples if not s["well_formed"])
    assert any(s["covered_paths"] for s in samples)


def test_description_brief_with_the_oracle_is_refused(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", "--model", "oracle", "--brief", "description", "--tasks", TASK]) == 2
    assert "--brief description cannot be used with --model oracle" in capsys.readouterr().err


def test_the_oracle_reads_the_runs_own_tasks_folder(tmp_path: Path) -> None:
    """`run --model oracle --tasks-dir D` answers from D's GT plans without `--model-args
    tasks_dir=`: a task only D holds gets its GT trees (LogCov 100 with the oracle)."""
    folder = Path(__file__).parent / "data" / "reader_dev" / "tasks_new"
    out = tmp_path / "runs"
    assert main(["run", "--model", "oracle", "--tasks-dir", str(folder), "--tasks", "garage_lock_up",
                 "--generators", "logicenvgen", "--output", str(out), "--run-id", "o", "--quiet"]) == 0
    results = json.loads((out / "o" / "results.json").read_text(encoding="utf-8"))
    assert results["results"]["logicenvgen"]["logcov"] == pytest.approx(1.0)


def test_named_objects_are_of_the_catalogs_kinds_and_a_word_outside_it_is_re_asked() -> None:
    """Qwen2.5-Coder-1.5B named a kitchen's plate, sponge and counter "container" (free categories);
    every scene built on them failed. The request binds a category to the catalog's kinds (all of
    them: a text may name a kind generators are not offered unasked) and re-asks a word outside."""
    model = Scripted([json.dumps({"objects": [{"name": "plate", "category": "container"}]}),
                      json.dumps({"objects": [{"name": "plate", "category": "plate"},
                                              {"name": "drawer", "category": "drawer"}]})], reply_protocol=5)
    brief = generator_brief(load_task("kitchen_dish_cleanup", TASKS), "description", model, seed=0)
    assert {n: r.category for n, r in brief.roles.items()} == {"plate": "plate", "drawer": "drawer"}
    assert len(model.requests) == 2 and "container" in json.dumps(model.requests[1].messages)
    schema = model.requests[0].schema
    assert schema is not None
    kinds = json.dumps(schema)
    assert '"drawer"' in kinds and '"plate"' in kinds and '"container"' not in kinds
