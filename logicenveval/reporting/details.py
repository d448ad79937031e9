"""What the per-task pages of a report show, read from a run folder's units (never recomputed).

A report's main page stays small: the table, the reasons and an index of (generator, task)
rows. Each row links to one page `details/[<run>/][seed<S>/]<generator>/<task>.html` holding
that task's environments: the top-down render (embedded as a data URI, so a page works copied
anywhere), the problems that made it ill-formed, every physics finding with its message, the
covered decision paths and each BT's verdict with its tick trace as a table. Faulty BTs read
"detected" / "missed": a faulty BT that passes is a fault the environment did not reveal.
"""

from __future__ import annotations

import ast
import base64
import functools
import hashlib
import html
import re
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from markupsafe import Markup

from logicenveval.atomic import atomic_write_text
from logicenveval.metrics.records import EnvDetail, UnitRecord
from logicenveval.model.task import FAULTY_KINDS, POLICY_KINDS
from logicenveval.runner.store import RunStore

_NOT_RECORDED = "no trace recorded (the unit was written by a version that did not store traces)"
_SAFE = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]{0,63}")
#: a render bigger than this is not embedded (renders are a few kB; a hostile file is not)
_MAX_RENDER_BYTES = 2_000_000
#: a trace line longer than this is shown as text, not parsed
_MAX_TRACE_LINE = 4000
_DIMENSIONS = ("floor_plan", "entity", "relation")
_WHY_KEYS = frozenset({"generator", "task_id", "env_id", "well_formed", "problems", "violations",
                       "verdicts", "physics"})


def slug(name: str) -> str:
    """A file-name and anchor-safe form of a name; names that need changing get a digest suffix
    so that two names never share a page."""
    if _SAFE.fullmatch(name) and name not in (".", ".."):
        return name
    clean = re.sub(r"[^A-Za-z0-9._-]+", "_", name).strip("._-")[:40] or "x"
    return f"{clean}-{hashlib.sha256(name.encode()).hexdigest()[:8]}"


def task_anchor(generator: str, task: str, scope: str = "") -> str:
    """`scope` tells apart the same task of several seeds or runs in one report."""
    return f"t-{slug(generator)}--{slug(task)}" + (f"--{scope}" if scope else "")


def env_anchor(env_id: str) -> str:
    return f"env-{slug(env_id)}"


@dataclass(frozen=True)
class Source:
    """A run folder whose units feed detail pages: a run, or one seed of a multi-seed run."""

    run_dir: Path
    results: dict[str, Any]
    #: path of its pages under `details/` ("" or "seed0/", "run1/seed0/", ...)
    prefix: str = ""
    seed: str = ""
    records: Mapping[tuple[str, str], UnitRecord] = field(default_factory=dict)
    #: write a re-drawn render back to the run folder (when the report is the run's own)
    restore: bool = False


def sources(run_dir: Path, results: dict[str, Any], prefix: str = "",
            records: Sequence[UnitRecord] | None = None, restore: bool = False) -> list[Source]:
    """The folders holding a run's units: the run itself, or each seed's folder of a multi-seed run."""
    from logicenveval.errors import RunStoreError
    from logicenveval.runner.results import load_results

    runs = results.get("runs")
    if not runs:
        by_key = {(r.generator, r.task_id): r for r in records or ()}
        return [Source(run_dir, results, prefix, "", by_key, restore)]
    out = []
    for seed, sub in runs.items():
        if not isinstance(sub, str) or not _SAFE.fullmatch(sub) or sub in (".", ".."):
            raise RunStoreError(f"seed folder {str(sub)[:60]!r} is not a folder name", field=f"runs.{seed}",
                                file=str(run_dir / "results.json"),
                                hint="the file was edited or damaged; re-run the command to rewrite it")
        out.append(Source(run_dir / sub, load_results(run_dir / sub), f"{prefix}seed{slug(str(seed))}/",
                          str(seed), restore=restore))
    return out


def page_path(source: Source, generator: str, task: str) -> str:
    """The page of one (generator, task), relative to the report folder."""
    return f"details/{source.prefix}{slug(generator)}/{slug(task)}.html"


def _samples_file(run_dir: Path) -> dict[tuple[str, str], list[dict[str, Any]]]:
    """A run folder's samples.jsonl grouped by (generator, task), for folders without units."""
    import json

    from logicenveval.errors import RunStoreError
    from logicenveval.limits import read_text

    path = run_dir / "samples.jsonl"
    if not path.exists():
        return {}
    text = read_text(path, what="samples.jsonl", error=RunStoreError, max_bytes="max_run_file_bytes",
                     hint="re-run the command to rewrite it")
    out: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            sample = json.loads(line)
        except (ValueError, RecursionError):
            sample = None
        if not isinstance(sample, dict) or not {"generator", "task_id", "env_id"} <= set(sample):
            raise RunStoreError("not a complete sample (truncated or edited file)", file=str(path),
                                line=n, hint="re-run the same `run` command: it rewrites samples.jsonl "
                                "from the committed units")
        out.setdefault((str(sample["generator"]), str(sample["task_id"])), []).append(sample)
    return out


class UnitReader:
    """Each (generator, task)'s samples and details of one source, units first, samples.jsonl else."""

    def __init__(self, source: Source) -> None:
        self.source = source
        self.store = RunStore(source.run_dir)
        self._loose: dict[tuple[str, str], list[dict[str, Any]]] | None = None

    def envs(self, generator: str, task: str) -> list[tuple[dict[str, Any], EnvDetail | None]]:
        unit = self.source.records.get((generator, task)) or self.store.load(generator, task)
        if unit is not None:
            by_id = {d.env_id: d for d in unit.details}
            return [(s.model_dump(mode="json"), by_id.get(s.env_id)) for s in unit.samples]
        if self._loose is None:  # a folder without units (e.g. a published reference run)
            self._loose = _samples_file(self.source.run_dir)
        return [(s, None) for s in self._loose.get((generator, task), [])]


def _inside(run_dir: Path, rel: str) -> Path | None:
    """`run_dir/rel` when it stays inside the run folder (a unit file could name any path)."""
    if not rel or "\0" in rel:
        return None
    root = run_dir.resolve()
    try:
        path = (root / rel).resolve()
    except (OSError, RuntimeError, ValueError):
        return None
    return path if path.is_relative_to(root) else None


def _svg_from_env(run_dir: Path, generator: str, task: str, sample: Mapping[str, Any]) -> str | None:
    """Draw a missing render from the stored environment and its stored physics failures."""
    from logicenveval.envfiles import load_env
    from logicenveval.errors import LogicEnvEvalError
    from logicenveval.physics.render import render_svg
    from logicenveval.physics.report import DimensionReport, PhysicsFailure, PhysicsReport

    env_path = _inside(run_dir, f"envs/{generator}/{task}/{sample['env_id']}.json")
    if env_path is None or not env_path.is_file():
        return None
    try:
        env = load_env(env_path)
        physics = sample.get("physics") or {}
        failures = [PhysicsFailure.model_validate(f) for f in physics.get("failures", [])]
        extended = [PhysicsFailure.model_validate(f) for f in physics.get("extended_failures", [])]
    except (LogicEnvEvalError, ValueError):
        return None
    report = PhysicsReport(**{d: DimensionReport.of([f for f in failures if f.dimension == d])
                              for d in _DIMENSIONS},
                           extended=DimensionReport.of(extended))
    return render_svg(env, report)


def render_uri(run_dir: Path, generator: str, task: str, sample: Mapping[str, Any],
               detail: EnvDetail | None, restore: bool = False) -> str | None:
    """The environment's top-down render as a `data:` URI, drawn afresh when the file is gone
    (and written back to its place in the run folder with `restore`: renders are derived)."""
    rel = detail.render if detail is not None and detail.render else \
        f"renders/{generator}/{task}/{sample['env_id']}.svg"
    path = _inside(run_dir, rel)
    svg: bytes | None = None
    if path is not None and path.suffix == ".svg" and path.is_file():
        try:
            if path.stat().st_size <= _MAX_RENDER_BYTES:
                svg = path.read_bytes()
        except OSError:
            svg = None
    if svg is None:
        drawn = _svg_from_env(run_dir, generator, task, sample)
        if drawn is None:
            return None
        svg = drawn.encode()
        if restore and path is not None and path.suffix == ".svg":
            atomic_write_text(path, drawn, durable=False)
    return "data:image/svg+xml;base64," + base64.b64encode(svg).decode("ascii")


@dataclass(frozen=True)
class TickRow:
    tick: str
    node: str
    status: str
    path: str



#: the form the simulator's trace entries are recorded in (`str` of a dict, keys in this order)
_TRACE_LINE = re.compile(r"\{'tick': (\d+), 'node': '([^'\\]*)', 'path': '([^'\\]*)', "
                         r"'status': '([A-Z_]+)'\}")


def trace_rows(lines: Sequence[str]) -> tuple[list[TickRow], list[str]]:
    """Tick-table rows of a recorded trace, and the lines that are not tick entries (kept as text).

    Traces hold one `{'tick': .., 'node': .., 'path': .., 'status': ..}` literal per line: the
    common form is matched directly, others are read with `ast.literal_eval` (literals only,
    never code).
    """
    rows: list[TickRow] = []
    other: list[str] = []
    for line in lines:
        text = line.strip()
        plain = _TRACE_LINE.fullmatch(text)
        if plain is not None:
            rows.append(TickRow(plain[1], plain[2], plain[4], plain[3]))
            continue
        entry: object = None
        if text.startswith("{") and len(text) <= _MAX_TRACE_LINE:
            try:
                entry = ast.literal_eval(text)
            except (ValueError, SyntaxError, MemoryError, RecursionError, TypeError):
                entry = None
        if isinstance(entry, dict) and {"tick", "node", "status"} <= set(entry):
            rows.append(TickRow(str(entry["tick"]), str(entry["node"]), str(entry["status"]),
                                str(entry.get("path", ""))))
        else:
            other.append(line)
    return rows, other


@functools.lru_cache(maxsize=4096)
def _where(path: str) -> str:
    """The `where` cell of a tick row: the short path, the full one on hover (paths repeat a lot)."""
    parts = path.split("/")
    short = ("…/" if len(parts) > 3 else "") + "/".join(parts[-3:])
    return f'<td title="{html.escape(path)}"><code>{html.escape(short)}</code></td>'


def tick_table(rows: Sequence[TickRow]) -> Markup:
    """The trace as an HTML table (built here, not in the template: a report holds ~60,000 rows)."""
    if not rows:
        return Markup("")
    esc = html.escape
    out = ['<table class="ticks"><thead><tr><th>tick</th><th>node</th><th>status</th>'
           "<th>where</th></tr></thead><tbody>"]
    out += [f'<tr class="st-{esc(r.status.lower())}"><td class="t">{esc(r.tick)}</td><td>{esc(r.node)}'
            f"</td><td>{esc(r.status)}</td>{_where(r.path)}</tr>" for r in rows]
    out.append("</tbody></table>")
    return Markup("\n".join(out))


@dataclass(frozen=True)
class VerdictView:
    kind: str
    status: str
    #: passed / failed for the correct BT; detected / missed for a faulty one
    label: str
    good: bool
    #: False where the environment is not a valid scenario (FauDR does not count it)
    counted: bool
    message: str
    rows: list[TickRow]
    other: list[str]

    @property
    def table(self) -> Markup:
        return tick_table(self.rows)


@dataclass(frozen=True)
class EnvView:
    env_id: str
    anchor: str
    render: str | None
    well_formed: bool
    valid: bool
    problems: list[str]
    #: dimension -> messages of its failures (empty: passed)
    physics: dict[str, list[str]]
    extra: list[str]
    covered_paths: list[str]
    claimed: str
    verdicts: list[VerdictView]

    @property
    def summary(self) -> str:
        """One line for the index and the filter: what is wrong with the environment, if anything."""
        bad = []
        if not self.well_formed:
            bad.append("ill-formed")
        elif not self.valid:
            bad.append("violates a task constraint" if self.problems else "correct BT fails")
        bad += [f"{d} fails" for d, msgs in self.physics.items() if msgs]
        return ", ".join(bad) or "valid"


def _verdicts(sample: Mapping[str, Any], detail: EnvDetail | None, valid: bool) -> list[VerdictView]:
    order = {k: i for i, k in enumerate(POLICY_KINDS)}
    if detail is not None:
        traces = {k: (v.status, v.message, list(v.trace)) for k, v in detail.traces.items()}
    else:
        traces = {k: (str(v), _NOT_RECORDED, []) for k, v in (sample.get("verdicts") or {}).items()}
    out = []
    for kind in sorted(traces, key=lambda k: (order.get(k, len(order)), k)):
        status, message, lines = traces[kind]
        if kind in FAULTY_KINDS:
            good = status != "passed"
            label = "detected" if good else "missed"
        else:
            good = status == "passed"
            label = "passed" if good else "failed"
        rows, other = trace_rows(lines)
        out.append(VerdictView(kind, status, label, good, valid or kind not in FAULTY_KINDS,
                               message, rows, other))
    return out


def env_view(run_dir: Path, generator: str, task: str, sample: dict[str, Any],
             detail: EnvDetail | None, restore: bool = False) -> EnvView:
    physics = sample.get("physics") or {}
    failures = [f for f in physics.get("failures") or [] if isinstance(f, dict)]
    dims = {d: [str(f.get("message") or f.get("code")) for f in failures if f.get("dimension") == d]
            for d in _DIMENSIONS}
    for d in _DIMENSIONS:  # a dimension marked failed without a recorded message
        if not physics.get(d, True) and not dims[d]:
            dims[d] = ["failed (no message recorded)"]
    extra = [f"{f.get('code')}: {f.get('message')}" for f in physics.get("extended_failures") or []
             if isinstance(f, dict)]
    valid = (bool(sample.get("well_formed")) and not sample.get("violations")
             and (sample.get("verdicts") or {}).get("correct") == "passed")
    claimed = sample.get("claimed_trajectory") or {}
    claim = " | ".join(f"{sub}: " + ", ".join(f"{k}={v}" for k, v in sorted(vals.items()))
                       for sub, vals in sorted(claimed.items()) if isinstance(vals, dict))
    return EnvView(
        env_id=str(sample["env_id"]), anchor=env_anchor(str(sample["env_id"])),
        render=render_uri(run_dir, generator, task, sample, detail, restore),
        well_formed=bool(sample.get("well_formed")), valid=valid,
        problems=[str(p) for p in [*(sample.get("problems") or []), *(sample.get("violations") or [])]],
        physics=dims, extra=extra,
        covered_paths=[str(p) for p in sample.get("covered_paths") or []], claimed=claim,
        verdicts=_verdicts(sample, detail, valid))


@dataclass(frozen=True)
class TaskRow:
    """One (generator, task[, seed]) row of a report's index, and the data of its page."""

    generator: str
    task: str
    seed: str
    anchor: str
    href: str
    metrics: dict[str, Any]
    failures: list[dict[str, Any]]
    envs: list[EnvView]
    #: the environments' samples as recorded (what `why.reasons` reads)
    samples: list[dict[str, Any]] = field(default_factory=list)

    @property
    def n_valid(self) -> int:
        return sum(e.valid for e in self.envs)

    @property
    def n_physics(self) -> int:
        return sum(any(e.physics.values()) for e in self.envs)

    @property
    def detected(self) -> dict[str, bool | None]:
        """Per faulty kind: revealed by a valid environment (None: no valid environment)."""
        valid = [e for e in self.envs if e.valid]
        if not valid:
            return {k: None for k in FAULTY_KINDS}
        return {k: any(v.kind == k and v.good for e in valid for v in e.verdicts) for k in FAULTY_KINDS}


def task_rows(source: Source, generators: Sequence[str]) -> Iterator[TaskRow]:
    """Every (generator, task) of a source with its environments, in results order."""
    reader = UnitReader(source)
    per_task = source.results.get("per_task", {})
    failures = source.results.get("failures", {})
    scope = source.prefix.strip("/").replace("/", "-")
    for gen in generators:
        for task in source.results.get("tasks", []):
            pairs = reader.envs(gen, task)
            envs = [env_view(source.run_dir, gen, task, s, d, source.restore) for s, d in pairs]
            yield TaskRow(
                generator=gen, task=task, seed=source.seed, anchor=task_anchor(gen, task, scope),
                href=page_path(source, gen, task),
                metrics=dict(per_task.get(gen, {}).get(task) or {}),
                failures=[f for f in failures.get(gen, []) if isinstance(f, dict) and f.get("task") == task],
                envs=envs, samples=[{k: v for k, v in s.items() if k in _WHY_KEYS} for s, _ in pairs])
