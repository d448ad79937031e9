"""How gracefully each method degrades when its LLM errs (beyond the paper).

Runs every default generator with `--model noisy:offline --model-args rate=R,seed=S` for the
error rates 0, 0.1, 0.3, 0.5 (llm/noisy.py: coordinates displaced, objects or relations dropped,
categories renamed, rooms swapped, branches emptied, JSON truncated or wrapped in prose) and
prints each metric per rate with its 95 % bootstrap interval over tasks. A metric should fall,
or stay, as the rate rises; one that rises beyond its interval would mean a method scores higher
by failing. Last line: `robustness rates=<...> rises_beyond_interval=<n>`.

    python benchmarks/robustness.py                       # all tasks, ~4 min per rate on 2 cores
    python benchmarks/robustness.py --tasks clean_living_room,kitchen_dish_cleanup --workers 2
"""

from __future__ import annotations

import argparse
import tempfile
from typing import Any

from logicenveval.runner.config import DEFAULT_GENERATORS, RunConfig
from logicenveval.runner.run import run

RATES = (0.0, 0.1, 0.3, 0.5)
#: (label, path into results[gen], path into results[gen]["ci95"])
METRICS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("PhyPR", ("phypr", "avg")), ("LogCov", ("logcov",)), ("SceVR", ("scevr",)),
    ("FauDR", ("faudr", "avg")), ("LD", ("ld",)), ("JI", ("ji",)),
)


def _get(data: dict[str, Any], path: tuple[str, ...]) -> Any:
    for key in path:
        data = data[key]
    return data


def sweep(rates: tuple[float, ...], generators: tuple[str, ...], tasks: tuple[str, ...], seed: int,
          workers: int) -> dict[float, dict[str, Any]]:
    """results.json `results` block per rate."""
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for rate in rates:
            config = RunConfig(model="noisy:offline", model_args=f"rate={rate},seed={seed}",
                               generators=generators, tasks=tasks, output=tmp, workers=workers,
                               seed=seed)
            out[rate] = run(config, show_progress=False).results["results"]
    return out


def rises(by_rate: dict[float, dict[str, Any]], generator: str) -> list[str]:
    """Metrics of `generator` whose value at a higher rate is above rate 0's interval."""
    base = by_rate[min(by_rate)][generator]
    found = []
    for label, path in METRICS:
        interval = _get(base["ci95"], path)  # None with fewer than two tasks: the value itself
        high = interval[1] if interval is not None else _get(base, path)
        if high is None:
            continue
        for rate, results in sorted(by_rate.items()):
            value = _get(results[generator], path)
            if rate > min(by_rate) and value is not None and value > high + 1e-9:
                found.append(f"{label}@{rate:g}")
    return found


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tasks", default="", help="comma-separated task ids (default: all)")
    parser.add_argument("--generators", default=",".join(DEFAULT_GENERATORS))
    parser.add_argument("--rates", default=",".join(f"{r:g}" for r in RATES))
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--smoke", action="store_true", help="seconds, not minutes: a small case of the same code path (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = parser.parse_args(argv)
    if args.smoke:
        args.tasks, args.generators, args.rates = "lamp_or_pillow_fetch", "logicenvgen,holodeck", "0,0.5"
    rates = tuple(float(r) for r in args.rates.split(","))
    generators = tuple(g for g in args.generators.split(",") if g)
    tasks = tuple(t for t in args.tasks.split(",") if t)
    by_rate = sweep(rates, generators, tasks, args.seed, args.workers)
    print(f"| method | rate | {' | '.join(label for label, _ in METRICS)} | envs |")
    print("|---|---:|" + "---:|" * (len(METRICS) + 1))
    total = 0
    for gen in generators:
        for rate in rates:
            res = by_rate[rate][gen]
            cells = []
            for _, path in METRICS:
                value, interval = _get(res, path), _get(res["ci95"], path)
                ci = "n/a" if interval is None else f"[{100 * interval[0]:.1f}, {100 * interval[1]:.1f}]"
                cells.append("–" if value is None else f"{100 * value:.1f} {ci}")
            print(f"| {gen} | {rate:g} | {' | '.join(cells)} | {res['n_envs']} |")
        up = rises(by_rate, gen)
        total += len(up)
        if up:
            print(f"  {gen}: above rate {min(rates):g}'s interval: {', '.join(up)}")
    print(f"robustness rates={','.join(f'{r:g}' for r in rates)} rises_beyond_interval={total}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
