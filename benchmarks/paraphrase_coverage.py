"""Offline LogicEnvGen LogCov on the original task descriptions vs reworded ones.

`tests/data/paraphrases/<task>.json` holds two rewordings of each task's description, written
before the offline analyser was tuned against them. For each task and each text, the task's
description is replaced (roles, rooms and GT trees unchanged), `logicenvgen` generates its
environments with the offline model, and LogCov is the share of GT decision paths the
environments cover (DESIGN.md §7), averaged over tasks. A generalising analyser keeps LogCov on
the paraphrases close to the originals'.
Last line: `original_logcov=<x> paraphrase_logcov=<y>`.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from logicenveval.benchmark import load_tasks
from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.base import GenerationContext, make_generator
from logicenveval.llm.registry import make_model
from logicenveval.metrics.evaluate import coverage_of_env
from logicenveval.model.task import Task
from logicenveval.model.tree import all_path_keys

PARAPHRASES = Path(__file__).resolve().parents[1] / "tests" / "data" / "paraphrases"


def logcov(task: Task, description: str, seed: int, work: Path) -> float:
    """LogCov of offline LogicEnvGen on `task` described by `description`."""
    catalog = load_catalog()
    t = task.model_copy(update={"description": description})
    ctx = GenerationContext(model=make_model("offline", "", no_cache=True), catalog=catalog,
                            rng=np.random.default_rng(seed), seed=seed, work_dir=work)
    result = make_generator("logicenvgen").generate(t.brief(), ctx)
    covered: set[str] = set()
    for env in result.envs:
        cov = coverage_of_env(t, env, catalog)
        if cov.well_formed:
            covered.update(cov.covered_paths)
    return len(covered) / len(all_path_keys(t))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--tasks", default="all", help="all or comma-separated task ids")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--work", default="/tmp/paraphrase_coverage")
    args = ap.parse_args()
    tasks = load_tasks(None, None if args.tasks == "all" else args.tasks.split(","))
    orig: list[float] = []
    para: list[float] = []
    start = time.perf_counter()
    for task in tasks:
        texts = json.loads((PARAPHRASES / f"{task.id}.json").read_text(encoding="utf-8"))["paraphrases"]
        o = logcov(task, task.description, args.seed, Path(args.work) / task.id / "original")
        ps = [logcov(task, text, args.seed, Path(args.work) / task.id / f"p{k}")
              for k, text in enumerate(texts)]
        orig.append(o)
        para.extend(ps)
        print(f"{task.id:28s} original={o:.3f} paraphrases={' '.join(f'{p:.3f}' for p in ps)}",
              flush=True)
    print(f"tasks={len(tasks)} paraphrases={len(para)} seconds={time.perf_counter() - start:.1f}")
    print(f"original_logcov={sum(orig) / len(orig):.4f} paraphrase_logcov={sum(para) / len(para):.4f}")


if __name__ == "__main__":
    main()
