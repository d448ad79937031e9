"""Stability of each method over repeated LLM runs (the paper's App. C), from a `run --seeds` folder.

`python -m logicenveval run --seeds 0,1,2,3,4 ...` makes one run per seed in `<folder>/seed<S>/`;
with a real model the seed is the model's sampling seed (sent as the request's `seed`) and the
harness's random generator, at the paper's temperature 0 (re-asks step it up). This prints, per
method and metric, the mean over the runs, the standard deviation and the range, with the share
of valid model replies (after re-asks) and of attempted environments that failed. Last line:
`stability runs=<n> methods=<m>`.

    python benchmarks/stability.py reports/real/stability/<run-id>
"""

from __future__ import annotations

import argparse
import statistics
from pathlib import Path
from typing import Any

from llm_validity import portable_model

from logicenveval.runner.results import load_results

COMMITTED = Path(__file__).resolve().parents[1] / "reports" / "real" / "stability" / "SmolLM2-135M-Instruct.Q4_1"

#: (label, where in results.json: a path under `results.<method>`, or a function of the run and method)
METRICS: tuple[tuple[str, Any], ...] = (
    ("PhyPR", ("phypr", "avg")), ("LogCov", ("logcov",)), ("SceVR", ("scevr",)),
    ("FauDR", ("faudr", "avg")), ("LD", ("ld",)), ("JI", ("ji",)),
    # how often the model's reply was usable: the LLM-side stability App. C is about
    ("Valid replies", lambda run, method: _get(run.get("llm"), (method, "all", "valid_share"))),
    ("Failed attempts", lambda run, method: _share(_get(run["results"], (method, "n_failed")),
                                                   _get(run["results"], (method, "n_attempted")))),
    ("Envs", ("n_envs",)),
)


def _get(data: Any, path: tuple[str, ...]) -> Any:
    for key in path:
        if not isinstance(data, dict) or key not in data:
            return None
        data = data[key]
    return data


def _share(part: Any, whole: Any) -> float | None:
    return part / whole if isinstance(part, int) and isinstance(whole, int) and whole > 0 else None


def _value(run: dict[str, Any], method: str, where: Any) -> Any:
    if callable(where):
        return where(run, method)
    return _get(run["results"].get(method), where)


def load_runs(folder: Path) -> list[dict[str, Any]]:
    """The results.json of each seed run of a `run --seeds` folder, in seed-folder order."""
    runs = [load_results(p.parent) for p in sorted(folder.glob("seed*/results.json"))]
    if not runs:
        raise SystemExit(f"no seed*/results.json under {folder}")
    return runs


def table(runs: list[dict[str, Any]]) -> list[str]:
    """The markdown table (caption, header line, then rows) of the seed runs of a `run --seeds`
    folder (`load_runs`): per method and metric the mean over the runs, the standard deviation
    and the range."""
    lines = [f"model: {portable_model(runs[0]['model'])} · {len(runs)} runs (seeds "
             f"{', '.join(str(r['seed']) for r in runs)}) · tasks: {', '.join(runs[0]['tasks'])}",
             f"| method | {' | '.join(label for label, _ in METRICS)} |",
             "|---|" + "---:|" * len(METRICS)]
    for method in runs[0]["results"]:
        cells = []
        for label, path in METRICS:
            values = [v for r in runs if (v := _value(r, method, path)) is not None]
            if not values:
                cells.append("–")
                continue
            scale = 1 if label == "Envs" else 100
            mean, sd = statistics.fmean(values) * scale, statistics.pstdev(values) * scale
            cells.append(f"{mean:.1f} ± {sd:.1f} ({min(values) * scale:.1f}–{max(values) * scale:.1f})")
        lines.append(f"| {method} | {' | '.join(cells)} |")
    return lines


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", type=Path, nargs="?", default=COMMITTED,
                        help="the parent folder of a `run --seeds` run (default: the committed SmolLM2 one)")
    parser.add_argument("--smoke", action="store_true",
                        help="accepted for tests/test_benchmarks_smoke.py: the script only reads results "
                        "and is quick as it is")
    args = parser.parse_args(argv)
    runs = load_runs(args.folder)
    lines = table(runs)
    print("\n".join(lines))
    print(f"stability runs={len(runs)} methods={len(lines) - 3}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
