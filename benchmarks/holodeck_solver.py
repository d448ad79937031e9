"""Holodeck's DFS grid solver vs greedy first-fit placement, on the same random rooms.

Both search the same candidate poses (same grid, same seeded shuffle); greedy takes the first
free pose per object and never revisits a choice. The figures are the share of objects placed
and the share of `near` relations honoured, DFS over greedy, measured in the same run.
Last line: `placed_ratio=<float> near_ratio=<float>`.
"""

from __future__ import annotations

import argparse

import numpy as np

from logicenveval.baselines.holodeck_solver import (
    NEAR_GAP,
    FloorItem,
    Pose,
    candidates,
    solve_floor,
)


def _rooms(n: int, seed: int) -> list[tuple[float, float, list[FloorItem]]]:
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        width, depth = float(rng.uniform(2.5, 5.0)), float(rng.uniform(2.5, 4.5))
        items = [FloorItem(f"o{i}", (float(rng.uniform(0.4, 1.6)), 0.8, float(rng.uniform(0.4, 1.2))),
                           edge=bool(rng.random() < 0.5)) for i in range(int(rng.integers(3, 8)))]
        for i in range(1, len(items)):
            if rng.random() < 0.4:
                items[i].near.append(items[int(rng.integers(0, i))].id)
        out.append((width, depth, items))
    return out


def _greedy(items: list[FloorItem], width: float, depth: float, rng: np.random.Generator) -> dict[str, Pose]:
    poses: dict[str, Pose] = {}
    for it in sorted(items, key=lambda it: (not it.edge, -it.size[0] * it.size[2], it.id)):
        pool = candidates(it, width, depth, 0.25)
        rng.shuffle(pool)
        for p in pool:
            if not any(p.box.overlaps(q.box) for q in poses.values()):
                poses[it.id] = p
                break
    return poses


def _scores(items: list[FloorItem], poses: dict[str, Pose]) -> tuple[int, int, int]:
    near_total = sum(len(it.near) for it in items)
    near_ok = sum(1 for it in items for n in it.near if it.id in poses and n in poses
                  and poses[it.id].box.gap(poses[n].box) <= NEAR_GAP)
    return len(poses), near_ok, near_total


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--rooms", type=int, default=60)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--smoke", action="store_true", help="seconds, not minutes: a small case of the same code path (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = ap.parse_args()
    if args.smoke:
        args.rooms = 3
    totals = {"dfs": [0, 0], "greedy": [0, 0]}
    n_items = n_near = 0
    for k, (width, depth, items) in enumerate(_rooms(args.rooms, args.seed)):
        layout = solve_floor(items, width, depth, [], np.random.default_rng(k), max_nodes=1500)
        placed, near_ok, near_total = _scores(items, dict(layout.poses))
        g_placed, g_near, _ = _scores(items, _greedy(items, width, depth, np.random.default_rng(k)))
        totals["dfs"][0] += placed
        totals["dfs"][1] += near_ok
        totals["greedy"][0] += g_placed
        totals["greedy"][1] += g_near
        n_items += len(items)
        n_near += near_total
    for name, (placed, near_ok) in totals.items():
        print(f"{name:6s} placed {placed}/{n_items} ({placed / n_items:.3f})  near honoured {near_ok}/{n_near} "
              f"({near_ok / max(n_near, 1):.3f})")
    placed_ratio = totals["dfs"][0] / max(totals["greedy"][0], 1)
    near_ratio = totals["dfs"][1] / max(totals["greedy"][1], 1)
    print(f"placed_ratio={placed_ratio:.3f} near_ratio={near_ratio:.3f}")


if __name__ == "__main__":
    main()
