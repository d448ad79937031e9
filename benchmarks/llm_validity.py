"""Share of valid LLM replies per request kind, from a replay pack (no model needed).

A replay pack is a run folder of a real model (`reports/real/<model>/`: results.json,
config.json and the `llm_cache.sqlite` of every reply). This re-runs the pack's configuration
with `--model replay:<pack>/llm_cache.sqlite` (every reply comes from the cache, so it takes
seconds), checks that the metrics equal the pack's results.json, and prints, per generator and
request kind, how many questions were asked, the share answered validly at the first attempt and
after re-asks, and the attempts cut at max_tokens. Last line:
`llm_validity pack=<folder> metrics_reproduced=<true|false> valid_first=<x> valid=<y>`.

    python benchmarks/llm_validity.py reports/real/qwen2.5-coder-0.5b-instruct-q4_k_m
"""

from __future__ import annotations

import argparse
import json
import shutil
import tempfile
import time
from pathlib import Path
from typing import Any

from logicenveval.atomic import atomic_write_text
from logicenveval.reporting.publish import publish
from logicenveval.runner.config import RunConfig
from logicenveval.runner.results import load_results, write_outputs
from logicenveval.runner.run import RunOutcome, run

#: the committed SmolLM2 replay pack: the default pack (and `--smoke`'s)
SMOKE_PACK = Path(__file__).resolve().parents[1] / "reports" / "real" / "SmolLM2-135M-Instruct.Q4_1"


def replay(pack: Path, output: Path, cache: Path | None = None, protocol: int | None = None) -> dict[str, Any]:
    """results.json of the pack's configuration replayed from its reply cache (`cache`: one
    shared by several run folders, e.g. the stability seed runs). `protocol`: replay the requests
    of another request protocol than the pack's (the replies a cache recorded under an earlier
    protocol: a request never recorded is a cache miss, not measured)."""
    return _replayed(pack, output, cache, protocol).results


def _replayed(pack: Path, output: Path, cache: Path | None, protocol: int | None = None) -> RunOutcome:
    config = json.loads((pack / "config.json").read_text(encoding="utf-8"))
    run_config = RunConfig(
        model=f"replay:{cache or pack / 'llm_cache.sqlite'}",
        model_args=f"protocol={protocol or pack_protocol(config)}",
        generators=tuple(config["generators"]),
        tasks=tuple(config["tasks"]), tasks_dir=config["tasks_dir"], limit=config["limit"],
        seed=config["seed"], layout_solver=config["layout_solver"], brief=config["brief"],
        output=str(output), run_id=pack.name, workers=1)
    return run(run_config, show_progress=False)


#: what a pack holds that its replies and the scoring code determine (rewritten by `rescore`)
DERIVED = ("results.json", "samples.jsonl", "units", "envs", "renders", "details",
           "leaderboard.md", "leaderboard.html")


def rescore(pack: Path, cache: Path | None = None) -> None:
    """Score a pack again with this code from its recorded replies: the judging changed (LD,
    JI, constraints, shapes...), the replies did not. Its derived files are rewritten; its
    config.json (the model named by its file, `portable_model`), reply cache and llm_errors/
    are kept, and results.json goes on naming the model that wrote the replies (the replay's
    own `replay:` spec is an artefact of scoring)."""
    config = json.loads((pack / "config.json").read_text(encoding="utf-8"))
    config["model"] = portable_model(config["model"])
    atomic_write_text(pack / "config.json", json.dumps(config, indent=2, sort_keys=True) + "\n")
    with tempfile.TemporaryDirectory() as tmp:
        outcome = _replayed(pack, Path(tmp), cache)
        results = outcome.results
        results["model"] = results["config"]["model"] = config["model"]
        results["config"]["model_args"] = config["model_args"]
        write_outputs(outcome.run_dir, results, outcome.records)
        publish(outcome.run_dir, results, outcome.records)
        for name in DERIVED:
            target = pack / name
            if target.is_dir():
                shutil.rmtree(target)
            elif target.exists():
                target.unlink()
            source = outcome.run_dir / name
            if source.is_dir():
                shutil.copytree(source, target)
            elif source.exists():
                shutil.copy2(source, target)


def portable_model(spec: str) -> str:
    """`llamacpp:/any/dir/m.gguf` -> `llamacpp:m.gguf`: a model named by its file, not by the
    folder it sat in on the machine that ran it."""
    kind, sep, arg = spec.partition(":")
    return f"{kind}{sep}{Path(arg).name}" if sep and "/" in arg else spec


def pack_protocol(config: dict[str, Any]) -> int:
    """The request protocol a pack was recorded with (`llm.ask.PROTOCOL`): its `--model-args
    protocol=N`, or 1 for a pack recorded before issue 39, whose config names none
    (`runner.config.recorded_protocol`, what `replay:` of the pack asks with)."""
    from logicenveval.runner.config import recorded_protocol

    return recorded_protocol(config)


def same_metrics(a: dict[str, Any], b: dict[str, Any]) -> bool:
    """Equal per-task metrics, wall-clock timings aside."""
    def strip(per_task: dict[str, Any]) -> dict[str, Any]:
        return {g: {t: {k: v for k, v in m.items() if k != "st_ms"} for t, m in tasks.items()}
                for g, tasks in per_task.items()}
    return strip(a["per_task"]) == strip(b["per_task"])


def validity_table(llm: dict[str, Any]) -> tuple[list[str], dict[str, int]]:
    """The markdown table of a results.json `llm` block (per method and request kind: questions,
    valid first and after re-asks, attempts, cut at max_tokens) and the totals over methods."""
    lines = ["| method | request kind | questions | valid first (%) | valid after re-asks (%) | "
             "attempts | cut at max_tokens |", "|---|---|---:|---:|---:|---:|---:|"]
    totals = {"questions": 0, "valid_first": 0, "valid": 0}
    for gen, kinds in llm.items():
        for kind, row in kinds.items():
            lines.append(f"| {gen} | {kind} | {row['questions']} | {100 * row['valid_first_share']:.1f} | "
                         f"{100 * row['valid_share']:.1f} | {row['attempts']} | {row['truncated']} |")
            if kind == "all":
                for key in totals:
                    totals[key] += row[key]
    return lines, totals


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pack", type=Path, nargs="?", default=SMOKE_PACK,
                        help="a run folder holding llm_cache.sqlite (default: the committed SmolLM2 pack)")
    parser.add_argument("--smoke", action="store_true",
                        help="accepted for tests/test_benchmarks_smoke.py: replaying a pack takes seconds")
    parser.add_argument("--rescore", action="store_true",
                        help="score the pack again with this code (its derived files rewritten)")
    parser.add_argument("--cache", type=Path, help="the reply cache, when it is not the pack's own")
    parser.add_argument("--protocol", type=int,
                        help="replay the requests of this request protocol instead of the pack's: the "
                        "valid replies its cache recorded under it (a request never recorded is not "
                        "measured); the metrics are then not compared")
    args = parser.parse_args(argv)
    if args.rescore:
        rescore(args.pack, args.cache)
    recorded = load_results(args.pack)
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        replayed = replay(args.pack, Path(tmp), args.cache, args.protocol)
        seconds = time.perf_counter() - start
    print(f"model: {recorded['model']} · tasks: {len(recorded['tasks'])} · replayed in {seconds:.1f} s"
          + (f" · protocol {args.protocol}" if args.protocol else ""))
    lines, totals = validity_table(replayed["llm"])
    print("\n".join(lines))
    asked = max(1, totals["questions"])
    reproduced = args.protocol is None and same_metrics(recorded, replayed)
    print(f"llm_validity pack={args.pack} metrics_reproduced={str(reproduced).lower()} "
          f"valid_first={totals['valid_first'] / asked:.4f} valid={totals['valid'] / asked:.4f}")
    return 0 if reproduced or args.protocol is not None else 1


if __name__ == "__main__":
    raise SystemExit(main())
