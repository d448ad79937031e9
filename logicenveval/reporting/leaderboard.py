"""`leaderboard.md` and a static `leaderboard.html` with per-task pages, for a run folder.

The main page holds the table (grouped, sticky header, sortable), the reasons environments were
rejected or failed, a filter box and an index of every (generator, task) with anchors; each index
row links to the task's page under `details/` (`reporting.details`), loaded only when opened. All
of it was recorded by the units when they evaluated the environments (`UnitRecord.details`), so a
report only reads: no physics check, no simulation, no solving. Renders and environment files
are linked where the run wrote them (relative links: the run folder works when moved or copied
whole); a report written elsewhere copies them under `files/`.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Collection, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from jinja2 import Environment, PackageLoader, select_autoescape

from logicenveval.atomic import atomic_write_text
from logicenveval.metrics.records import UnitRecord
from logicenveval.model.task import FAULTY_KINDS
from logicenveval.reporting.charts import headline_charts
from logicenveval.reporting.details import (
    KIND_SHORT,
    Source,
    TaskRow,
    search_words,
    slug,
    sources,
    tick_data,
)
from logicenveval.reporting.tables import (
    COLUMNS,
    GROUPS,
    LEGEND,
    SUBHEADERS,
    Cell,
    interval_note,
    is_measured,
    llm_validity,
    markdown,
    row_cells,
    row_label,
)
from logicenveval.reporting.why import GeneratorReasons, Where, reasons


@functools.cache
def jinja() -> Environment:
    """The report's templates, compiled once per process (a worker writes many pages)."""
    env = Environment(loader=PackageLoader("logicenveval", "reporting/templates"),
                      autoescape=select_autoescape(["html", "j2"]))
    env.globals.update(kind_short=KIND_SHORT, faulty_kinds=FAULTY_KINDS)
    return env


def gen_anchor(generator: str, scope: str = "") -> str:
    return f"gen-{slug(generator)}" + (f"--{scope}" if scope else "")


@dataclass(frozen=True)
class HeaderCell:
    text: str
    colspan: int = 1
    rowspan: int = 1
    #: the body column this header sorts (None for a group title)
    col: int | None = None
    title: str = ""


def header_rows(lead: Sequence[str]) -> tuple[list[HeaderCell], list[HeaderCell]]:
    """Two header rows: lead columns, n, grouped metric columns (PhyPR, FauDR, ST), failed."""
    top = [HeaderCell(h, rowspan=2, col=i) for i, h in enumerate(lead)]
    top.append(HeaderCell("n", rowspan=2, col=len(lead), title="tasks × seeds"))
    sub: list[HeaderCell] = []
    first = len(lead) + 1
    group_at = {start: (title, size) for title, start, size in GROUPS}
    for i, (header, _, pct) in enumerate(COLUMNS):
        unit = " (%)" if pct else ""
        if i in group_at:
            title, size = group_at[i]
            top.append(HeaderCell(title + (" (%)" if pct else ""), colspan=size))
        if i in SUBHEADERS:
            sub.append(HeaderCell(SUBHEADERS[i], col=first + i, title=header + unit))
        else:
            top.append(HeaderCell(header, rowspan=2, col=first + i, title=header + unit))
    top.append(HeaderCell("Failed", rowspan=2, col=first + len(COLUMNS),
                          title="environments the generator could not build / attempted"))
    return top, sub


@dataclass(frozen=True)
class TableRow:
    lead: list[str]
    cells: list[Cell]
    anchor: str
    href: str
    filter: str


@dataclass(frozen=True)
class EnvLink:
    env_id: str
    href: str
    summary: str
    valid: bool


@dataclass(frozen=True)
class IndexRow:
    """One (generator, task[, seed]) of the index: counts, per-task figures, link to its page."""

    generator: str
    task: str
    seed: str
    anchor: str
    href: str
    measured: bool
    n_envs: int
    n_valid: int
    n_physics: int
    failed: str
    logcov: str
    detected: dict[str, bool | None]
    budget_hit: bool
    envs: list[EnvLink]
    #: the filter's text: every word the row and its environments' reasons show
    filter: str = ""


@dataclass
class Collected:
    """What the main page needs of the detail pages once they are written."""

    rows: list[IndexRow]
    samples: list[dict[str, Any]]
    #: per environment (generator, task, env_id, seed): the correct BT's message, its page link
    messages: dict[Where, str]
    hrefs: dict[Where, str]
    written: set[Path]


#: files every detail page links (`details/<name>`), made of these templates' text
PAGE_ASSETS = {"page.css": ("report.css", "task.css"), "page.js": ("task.js", "report.js")}


def _template_text(env: Environment, name: str) -> str:
    if env.loader is None:
        raise TypeError("the report's Jinja environment has no loader")
    return env.loader.get_source(env, name)[0]


def _index_row(row: TaskRow, not_measured: set[str]) -> IndexRow:
    m = row.metrics
    measured = row.task not in not_measured and m.get("n_envs") is not None if m else False
    attempted, n_failed = m.get("n_attempted"), m.get("n_failed")
    logcov = m.get("logcov")
    return IndexRow(
        generator=row.generator, task=row.task, seed=row.seed, anchor=row.anchor, href=row.href,
        measured=measured or (not m and bool(row.envs)), n_envs=len(row.envs), n_valid=row.n_valid,
        n_physics=row.n_physics,
        failed=f"{int(n_failed)}/{int(attempted)}" if attempted is not None and n_failed is not None
        else (str(int(n_failed)) if n_failed else "0"),
        logcov="–" if logcov is None else f"{100 * float(logcov):.0f}",
        detected=row.detected, budget_hit=bool(m.get("budget_hit")),
        envs=[EnvLink(e.env_id, f"{row.href}#{e.anchor}", e.summary, e.valid) for e in row.envs],
        filter=row.search)


def write_details(out: Path, srcs: Sequence[Source], generators: Sequence[str],
                  env: Environment, *, paged: Collection[tuple[str, str]] = (),
                  shared: bool = True, index: bool = True) -> Collected:
    """Write every (generator, task) page of `srcs` under `out/details/`, but those in `paged`
    (written where their unit was computed: `unit_page`); return the index. `shared`: also the
    style and script every page links. `index=False`: the pages only, the index left empty (a
    worker writing its unit's page: the run's process makes the index)."""
    from logicenveval.reporting.details import Assets, task_rows

    got = Collected([], [], {}, {}, set())
    for name, parts in PAGE_ASSETS.items() if shared else ():
        path = out / "details" / name
        atomic_write_text(path, "".join(_template_text(env, part) for part in parts), durable=False)
        got.written.add(path)
    for source in srcs:
        results = source.results
        assets = Assets(out, source, got.written)
        for row in task_rows(source, [g for g in generators if g in results.get("results", {})], assets,
                             paged):
            values = results["results"].get(row.generator, {})
            not_measured = set(values.get("not_measured_tasks") or ())
            path = out / row.href
            got.written.add(path)
            if (row.generator, row.task) not in paged:
                up = "../" * row.href.count("/")  # the template is compiled when first needed
                html = env.get_template("task.html.j2").render(
                    row=row, back=f"{up}leaderboard.html#{row.anchor}", up=up, ticks=tick_data(row.envs),
                    run_id=results.get("run_id", ""), model=results.get("model", ""),
                    measured=row.task not in not_measured and is_measured(values))
                atomic_write_text(path, html, durable=False)
            if not index:
                continue
            got.rows.append(_index_row(row, not_measured))
            for e in row.envs:
                key = (row.generator, row.task, e.env_id, source.seed)
                got.hrefs.setdefault(key, f"{row.href}#{e.anchor}")
                correct = next((v for v in e.verdicts if v.kind == "correct"), None)
                if correct is not None and correct.message:
                    got.messages.setdefault(key, f"correct BT {correct.status}: {correct.message}")
            got.samples.extend({**s, "seed": source.seed} if source.seed else s for s in row.samples)
    return got


def remove_stale(folder: Path, keep: set[Path], pattern: str = "*.html") -> None:
    """Drop pages (or copied files) a previous report wrote that this one did not (a generator
    or task left)."""
    if not folder.is_dir():
        return
    for path in sorted(p for p in folder.rglob(pattern) if p.is_file()):
        if path not in keep:
            path.unlink(missing_ok=True)
    for dirpath, _dirs, _files in sorted(os.walk(folder), key=lambda w: -len(w[0])):
        if Path(dirpath) != folder and not any(Path(dirpath).iterdir()):
            Path(dirpath).rmdir()


def why_text(g: GeneratorReasons) -> str:
    """A generator's reasons as filter text: its table row is found by any reason it has."""
    return search_words(*(f"{r.label} {r.where} {r.example}" for r in g.reasons))


def table_rows(results: dict[str, Any], lead: Sequence[str] = (), scope: str = "",
               why: Sequence[GeneratorReasons] = ()) -> list[TableRow]:
    texts = {g.generator: why_text(g) for g in why}
    out = []
    for gen, values in results["results"].items():
        label = row_label(gen, values, results)
        out.append(TableRow([*lead, label], row_cells(results, gen), gen_anchor(gen, scope),
                            f"#{gen_anchor(gen, scope)}", search_words(*lead, label, texts.get(gen, ""))))
    return out


def group_rows(rows: Sequence[IndexRow], scope: str = "") -> list[dict[str, Any]]:
    groups: dict[str, list[IndexRow]] = {}
    for r in rows:
        groups.setdefault(r.generator, []).append(r)
    return [{"generator": g, "anchor": gen_anchor(g, scope), "rows": rs} for g, rs in groups.items()]


def render_main(results: dict[str, Any], collected: Collected, env: Environment) -> str:
    why: list[GeneratorReasons] = reasons(collected.samples, results.get("failures", {}),
                                          messages=collected.messages, scores=results["results"])
    top, sub = header_rows(["Method"])
    return env.get_template("leaderboard.html.j2").render(
        results=results, top=top, sub=sub, rows=table_rows(results, why=why), legend=LEGEND,
        note=interval_note(results), why=why, hrefs=collected.hrefs,
        groups=group_rows(collected.rows), seeded=bool(results.get("runs")), llm=llm_validity(results),
        charts=headline_charts(results))


def _rebase(got: Collected, sub: str, seed: str) -> Collected:
    """A seed run's index as seen from its multi-seed parent folder (`sub/` in front of links)."""
    def env(e: EnvLink) -> EnvLink:
        return replace(e, href=f"{sub}/{e.href}")

    rows = [replace(r, href=f"{sub}/{r.href}", anchor=f"{r.anchor}--seed{slug(seed)}", seed=seed,
                    envs=[env(e) for e in r.envs], filter=search_words(r.filter, f"seed{seed}"))
            for r in got.rows]
    def at(key: Where) -> Where:  # the seed run's own environments, named by their seed here
        return (*key[:3], seed)

    return Collected(rows, [{**s, "seed": seed} for s in got.samples],
                     {at(k): v for k, v in got.messages.items()},
                     {at(k): f"{sub}/{v}" for k, v in got.hrefs.items()}, got.written)


def write_leaderboards(run_dir: Path, results: dict[str, Any],
                       records: Sequence[UnitRecord] | None = None,
                       paged: Collection[tuple[str, str]] = ()) -> Collected:
    """`leaderboard.md`, `leaderboard.html` and `details/` of a run folder; `records` are the
    run's units when the caller holds them already (otherwise they are read from `units/`);
    `paged`: (generator, task) whose page the worker that ran the unit wrote (`unit_page`).

    A multi-seed run's pages are its seed runs' own: each seed folder gets its leaderboards, and
    the parent's index links to their pages."""
    env = jinja()
    if results.get("runs"):
        collected = Collected([], [], {}, {}, set())
        for source in sources(run_dir, results):
            sub = source.run_dir.name
            got = _rebase(write_leaderboards(source.run_dir, source.results), sub, source.seed)
            collected.rows += got.rows
            collected.samples += got.samples
            for k, v in got.messages.items():
                collected.messages.setdefault(k, v)
            for k, v in got.hrefs.items():
                collected.hrefs.setdefault(k, v)
    else:
        collected = write_details(run_dir, sources(run_dir, results, records=records, restore=True),
                                  list(results["results"]), env, paged=paged)
        remove_stale(run_dir / "details", collected.written)
    atomic_write_text(run_dir / "leaderboard.md", markdown(results), durable=False)
    atomic_write_text(run_dir / "leaderboard.html", render_main(results, collected, env), durable=False)
    return collected

