"""Offline LogicEnvGen LogCov on the original task descriptions vs reworded ones.

`tests/data/paraphrases/<task>.json` holds two rewordings of each task's description, written
before the offline analyser was tuned against them. For each task and each text, the task's
description is replaced (roles, rooms and GT trees unchanged), `logicenvgen` generates its
environments with the offline model, and LogCov is the share of GT decision paths the
environments cover (DESIGN.md §7), averaged over tasks. A generalising analyser keeps LogCov on
the paraphrases close to the originals'.
`tests/data/paraphrases_heldout/<task>.json` holds one more rewording per task, written before the
analyser was read and never tuned on; its LogCov is printed as `heldout_logcov=<z>` on the line
before the last. `--show-missing` lists the GT paths a text leaves uncovered.
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

DATA = Path(__file__).resolve().parents[1] / "tests" / "data"
PARAPHRASES = DATA / "paraphrases"
HELDOUT = DATA / "paraphrases_heldout"


def texts_of(folder: Path, task: Task) -> list[str]:
    """The rewordings of `task` stored in `folder`."""
    texts: list[str] = json.loads((folder / f"{task.id}.json").read_text(encoding="utf-8"))["paraphrases"]
    return texts


def logcov(task: Task, description: str, seed: int, work: Path, show_missing: bool = False) -> float:
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
    paths = all_path_keys(t)
    if show_missing:
        for key in sorted(set(paths) - covered):
            print(f"    missing [{work.name}] {key}")
    return len(covered) / len(paths)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--tasks", default="all", help="all or comma-separated task ids")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--work", default="/tmp/paraphrase_coverage")
    ap.add_argument("--show-missing", action="store_true", help="list uncovered GT paths per text")
    ap.add_argument("--smoke", action="store_true", help="seconds, not minutes: a small case of the same code path (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = ap.parse_args()
    if args.smoke:
        args.tasks = "lamp_or_pillow_fetch"
    tasks = load_tasks(None, None if args.tasks == "all" else args.tasks.split(","))
    orig: list[float] = []
    para: list[float] = []
    held: list[float] = []
    start = time.perf_counter()
    for task in tasks:
        work = Path(args.work) / task.id
        o = logcov(task, task.description, args.seed, work / "original", args.show_missing)
        ps = [logcov(task, text, args.seed, work / f"p{k}", args.show_missing)
              for k, text in enumerate(texts_of(PARAPHRASES, task))]
        hs = [logcov(task, text, args.seed, work / f"h{k}", args.show_missing)
              for k, text in enumerate(texts_of(HELDOUT, task))]
        orig.append(o)
        para.extend(ps)
        held.extend(hs)
        print(f"{task.id:28s} original={o:.3f} paraphrases={' '.join(f'{p:.3f}' for p in ps)}"
              f" heldout={' '.join(f'{h:.3f}' for h in hs)}", flush=True)
    print(f"tasks={len(tasks)} paraphrases={len(para)} heldout={len(held)}"
          f" seconds={time.perf_counter() - start:.1f}")
    print(f"heldout_logcov={sum(held) / len(held):.4f}")
    print(f"original_logcov={sum(orig) / len(orig):.4f} paraphrase_logcov={sum(para) / len(para):.4f}")


if __name__ == "__main__":
    main()
