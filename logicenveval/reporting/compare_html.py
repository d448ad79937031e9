"""The HTML page of a comparison (`compare --html PAGE`): the verdicts of the text and JSON, in
the same words, and per task the headline figures of both runs with links to both detail pages,
so a regression is followed down to the environments that moved."""

from __future__ import annotations

import os
import urllib.parse
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from logicenveval.atomic import atomic_write_text
from logicenveval.metrics.uncertainty import cells_of, point_metrics
from logicenveval.reporting.compare import Comparison, Pair
from logicenveval.reporting.compare_text import interval_text, verdict_text
from logicenveval.reporting.details import slug
from logicenveval.reporting.tables import metric
from logicenveval.reporting.terminal import HEADLINE


@dataclass(frozen=True)
class TaskDiff:
    """One task of a compared pair: headline figures (percent) of A and B, links to both pages."""

    task: str
    a: list[float | None]
    b: list[float | None]
    href_a: str | None
    href_b: str | None

    @property
    def changes(self) -> list[float | None]:
        return [None if x is None or y is None else y - x for x, y in zip(self.a, self.b, strict=True)]


def _per_task(results: dict[str, Any], generator: str) -> dict[str, dict[str, Any]]:
    """Each task's figures of one generator (its seeds pooled)."""
    by_task: dict[str, list[Any]] = {}
    for (task, _), cell in cells_of(results, generator).items():
        by_task.setdefault(task, []).append(cell)
    return {t: point_metrics(cells) for t, cells in by_task.items()}


def detail_href(run_dir: Path, results: dict[str, Any], generator: str, task: str,
                page: Path) -> str | None:
    """The link from `page` to a (generator, task) detail page of a run (its first seed's in a
    multi-seed run), or None when the run folder has no such page."""
    runs = results.get("runs")
    prefix = f"seed{slug(str(next(iter(runs))))}/" if isinstance(runs, dict) and runs else ""
    target = run_dir / "details" / f"{prefix}{slug(generator)}" / f"{slug(task)}.html"
    if not target.is_file():
        return None
    return relative_url(Path(os.path.relpath(target.resolve(), page.resolve().parent)))


def relative_url(path: Path) -> str:
    """A relative path as a URL path: each segment percent-encoded, so that a folder named
    `javascript:alert(1)` is never read as a scheme (`:` is `%3A`) and `#` or `?` in a folder
    name do not end the path (they are `%23` and `%3F`)."""
    return "/".join(urllib.parse.quote(part, safe="") for part in path.as_posix().split("/"))


def task_diffs(pair: Pair, a: dict[str, Any], b: dict[str, Any], run_a: Path, run_b: Path,
               page: Path) -> list[TaskDiff]:
    ta, tb = _per_task(a, pair.gen_a), _per_task(b, pair.gen_b)
    out = []
    for task in [t for t in a.get("tasks", []) if t in ta or t in tb]:
        out.append(TaskDiff(
            task=task,
            a=[metric(ta[task], path) if task in ta else None for _, path in HEADLINE],
            b=[metric(tb[task], path) if task in tb else None for _, path in HEADLINE],
            href_a=detail_href(run_a, a, pair.gen_a, task, page),
            href_b=detail_href(run_b, b, pair.gen_b, task, page)))
    return out


def write_comparison_html(page: Path, c: Comparison, a: dict[str, Any], b: dict[str, Any],
                          run_a: Path, run_b: Path) -> None:
    from logicenveval.reporting.leaderboard import jinja

    pairs = [(p, task_diffs(p, a, b, run_a, run_b, page)) for p in c.pairs]
    html = jinja().get_template("compare.html.j2").render(
        c=c, pairs=pairs, run_a=str(run_a), run_b=str(run_b), headline=[h for h, _ in HEADLINE],
        verdict_text=verdict_text, interval_text=interval_text)
    atomic_write_text(page, html)
