"""What the per-task pages of a report show, read from a run folder's units (never recomputed).

A report's main page stays small: the table, the reasons and an index of (generator, task)
rows. Each row links to one page `details/[<run>/][seed<S>/]<generator>/<task>.html` holding
that task's environments: the top-down render (linked, not inlined: the unit wrote it once under
`renders/`; click to open it full size) and a link to the EnvSpec JSON, the problems that made it ill-formed, every physics finding with its message, the
covered decision paths and each BT's verdict with its tick trace as a table (drawn by the page
from one compact JSON when the BT is opened: `tick_data`). Faulty BTs read
"detected" / "missed": a faulty BT that passes is a fault the environment did not reveal.
"""

from __future__ import annotations

import ast
import functools
import hashlib
import re
from collections.abc import Collection, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

from markupsafe import Markup

from logicenveval.atomic import atomic_write_bytes, atomic_write_text
from logicenveval.metrics.records import EnvDetail, UnitRecord
from logicenveval.model.task import FAULTY_KINDS, POLICY_KINDS
from logicenveval.runner.store import RunStore
from logicenveval.runner.unit_codec import PathTable

_NOT_RECORDED = "no trace recorded (the unit was written by a version that did not store traces)"
_SAFE = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]{0,63}")
#: a render bigger than this is not copied into a merged report (renders are a few kB; a hostile file is not)
_MAX_RENDER_BYTES = 2_000_000
#: a trace line longer than this is shown as text, not parsed
_MAX_TRACE_LINE = 4000
_DIMENSIONS = ("floor_plan", "entity", "relation")
#: the faulty kinds' short names in the index
KIND_SHORT = {"counterfactual": "CF", "unreachable": "Unreach", "lackbranch": "LBranch"}
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


def samples_file(run_dir: Path) -> dict[tuple[str, str], list[dict[str, Any]]]:
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

    def unit(self, generator: str, task: str) -> UnitRecord | None:
        return self.source.records.get((generator, task)) or self.store.load(generator, task)

    def envs(self, generator: str, task: str,
             unit: UnitRecord | None = None) -> list[tuple[dict[str, Any], EnvDetail | None]]:
        unit = unit or self.unit(generator, task)
        if unit is not None:
            by_id = {d.env_id: d for d in unit.details}
            return [(s.model_dump(mode="json"), by_id.get(s.env_id)) for s in unit.samples]
        if self._loose is None:  # a folder without units (e.g. a published reference run)
            self._loose = samples_file(self.source.run_dir)
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


#: an environment file bigger than this is not copied into a merged report (it is linked from
#: its run folder only when the report is the run's own)
_MAX_ENV_BYTES = 50_000_000


@dataclass(frozen=True)
class Assets:
    """Where a source's renders and environment files are linked from.

    A run's own report links the files in place (`renders/...`, `envs/...`: each written once,
    by the unit); a report in another folder (`report RUN RUN --out DIR`) copies them to
    `DIR/files/<prefix>` so that folder stands alone. `written` collects the copies."""

    out: Path
    source: Source
    written: set[Path] = field(default_factory=set)
    root: Path = field(init=False)
    in_place: bool = field(init=False)
    _dirs: dict[Path, Path] = field(init=False, default_factory=dict)

    def __post_init__(self) -> None:  # resolved once: a report links ~1,300 files
        root = self.source.run_dir.resolve()
        object.__setattr__(self, "root", root)
        object.__setattr__(self, "in_place", root == self.out.resolve())

    def inside(self, rel: str) -> Path | None:
        """The run folder's file `rel` when it stays inside the folder (a unit could name any
        path). Folders are resolved once each (a report links ~1,300 files in ~250 folders)."""
        if not rel or "\0" in rel:
            return None
        try:
            rough = self.root / rel
            parent = self._dirs.get(rough.parent)
            if parent is None:
                parent = self._dirs.setdefault(rough.parent, rough.parent.resolve())
            path = parent / rough.name
            if rough.name in ("", ".", "..") or path.is_symlink():
                path = path.resolve()
        except (OSError, RuntimeError, ValueError):
            return None
        return path if path.is_relative_to(self.root) else None

    def place(self, src: Path, data: bytes | None) -> str | None:
        """The href (relative to the report folder) of the run folder's file `src`, copying it (or
        `data`, when the file is gone) when the report lives elsewhere."""
        rel = src.relative_to(self.root).as_posix()
        if self.in_place:
            return rel if src.is_file() else None
        if data is None:
            return None
        dest = self.out / "files" / self.source.prefix / rel
        if dest not in self.written:
            dest.parent.mkdir(parents=True, exist_ok=True)
            if not dest.is_file() or dest.read_bytes() != data:
                atomic_write_bytes(dest, data, durable=False)
            self.written.add(dest)
        return dest.relative_to(self.out).as_posix()


def _read(path: Path | None, limit: int) -> bytes | None:
    if path is None or not path.is_file():
        return None
    try:
        return path.read_bytes() if path.stat().st_size <= limit else None
    except OSError:
        return None


def render_href(assets: Assets, generator: str, task: str, sample: Mapping[str, Any],
                detail: EnvDetail | None) -> str | None:
    """The environment's top-down render, linked (never inlined: it is written once, under
    `renders/`), drawn afresh when the file is gone (and written back to its place in the run
    folder with `restore`: renders are derived)."""
    rel = detail.render if detail is not None and detail.render else \
        f"renders/{generator}/{task}/{sample['env_id']}.svg"
    path = assets.inside(rel)
    if path is None or path.suffix != ".svg":
        return None
    if path.is_file():
        return assets.place(path, None if assets.in_place else _read(path, _MAX_RENDER_BYTES))
    drawn = _svg_from_env(assets.source.run_dir, generator, task, sample)
    if drawn is None:
        return None
    if assets.source.restore:
        atomic_write_text(path, drawn, durable=False)
    return assets.place(path, drawn.encode())


def env_href(assets: Assets, generator: str, task: str, env_id: str) -> str | None:
    """The environment's EnvSpec JSON, linked from its page (copied into a merged report)."""
    path = assets.inside(f"envs/{generator}/{task}/{env_id}.json")
    if path is None:
        return None
    return assets.place(path, None if assets.in_place else _read(path, _MAX_ENV_BYTES))


class TickRow(NamedTuple):
    """One row of a tick table (a tuple: a page has ~500 of them, made per line)."""

    tick: str
    node: str
    status: str
    path: str



#: the form the simulator's trace entries are recorded in (`str` of a dict, keys in this order)
_TRACE_LINE = re.compile(r"\{'tick': (\d+), 'node': '([^'\\]*)', 'path': '([^'\\]*)', "
                         r"'status': '([A-Z_]+)'(?:, 'ports': '([^'\\]*)')?\}")


def _with_ports(node: str, ports: str | None) -> str:
    """`Walk target=kitchen`: the node with the port values it ran with (older traces: the node)."""
    return f"{node} {ports}" if ports else node


#: lines of the common form already matched in this process: the four BTs of an environment,
#: and environments of one situation, repeat most of their lines (bounded: `_plain` clears it)
_PLAIN: dict[str, tuple[str, str, str, str, str | None] | None] = {}


def _plain(line: str) -> tuple[str, str, str, str, str | None] | None:
    """(tick, node, path, status, ports) of a line of the common form, else None."""
    try:
        return _PLAIN[line]
    except KeyError:
        pass
    if len(_PLAIN) >= 200_000:
        _PLAIN.clear()
    m = _TRACE_LINE.fullmatch(line.strip())
    got = _PLAIN[line] = None if m is None else (m[1], m[2], m[3], m[4], m[5])
    return got


def trace_rows(lines: Sequence[str]) -> tuple[list[TickRow], list[str]]:
    """Tick-table rows of a recorded trace, and the lines that are not tick entries (kept as text).

    Traces hold one `{'tick': .., 'node': .., 'path': .., 'status': ..}` literal per line, with
    `'ports'` on a node's first line (carried forward to its later rows by path): the common form
    is matched directly, others are read with `ast.literal_eval` (literals only, never code).
    """
    rows: list[TickRow] = []
    other: list[str] = []
    ports: dict[str, str] = {}
    for line in lines:
        plain = _plain(line)
        if plain is not None:
            tick, node, path, status, own = plain
            if own:
                ports[path] = own
            rows.append(TickRow(tick, _with_ports(node, ports.get(path)), status, path))
            continue
        text = line.strip()
        entry: object = None
        if text.startswith("{") and len(text) <= _MAX_TRACE_LINE:
            try:
                entry = ast.literal_eval(text)
            except (ValueError, SyntaxError, MemoryError, RecursionError, TypeError):
                entry = None
        if isinstance(entry, dict) and {"tick", "node", "status"} <= set(entry):
            path = str(entry.get("path", ""))
            if entry.get("ports"):
                ports[path] = str(entry["ports"])
            rows.append(TickRow(str(entry["tick"]), _with_ports(str(entry["node"]), ports.get(path)),
                                str(entry["status"]), path))
        else:
            other.append(line)
    return rows, other


@dataclass(frozen=True)
class TickData:
    """A page's tick tables as one compact JSON (the page's script draws a table when its BT is
    opened): tree paths (a trie, `PathTable`) and distinct (node, status, path) steps listed
    once, each trace a flat list `[tick, step, tick, step, ...]`. Tables drawn as HTML were 83 %
    of a run's `details/`."""

    #: the `<script type="application/json">` text (no `<` can end the script)
    json: Markup
    #: per environment of the page, per verdict: the number of its trace (None: no rows)
    at: list[list[int | None]]


def tick_data(envs: Sequence[EnvView]) -> TickData:
    """The compact traces of a page's environments, in card order."""
    import json

    paths = PathTable()
    steps: dict[tuple[str, str, int], int] = {}
    #: (node, status, path) -> its step: a path is numbered where its first step is
    step_of: dict[tuple[str, str, str], int] = {}
    traces: list[list[int | str]] = []
    at: list[list[int | None]] = []
    for e in envs:
        numbers: list[int | None] = []
        for v in e.verdicts:
            if not v.rows:
                numbers.append(None)
                continue
            flat: list[int | str] = []
            for tick, node, status, path in v.rows:
                step = step_of.get((node, status, path))
                if step is None:
                    step = step_of[(node, status, path)] = steps.setdefault(
                        (node, status, paths.number(path)), len(steps))
                flat += (int(tick) if tick.isdigit() else tick, step)
            numbers.append(len(traces))
            traces.append(flat)
        at.append(numbers)
    text = json.dumps({"paths": paths.entries, "steps": [list(k) for k in steps], "traces": traces},
                      ensure_ascii=False, separators=(",", ":"))
    return TickData(Markup(text.replace("<", "\\u003c")), at)


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
    #: the recorded trace, read into `rows` and `other` only when a page shows it (the index
    #: needs none of it)
    lines: Sequence[str] = ()

    @functools.cached_property
    def _read(self) -> tuple[list[TickRow], list[str]]:
        return trace_rows(self.lines)

    @property
    def rows(self) -> list[TickRow]:
        return self._read[0]

    @property
    def other(self) -> list[str]:
        """The trace's lines that are not tick entries (kept as text)."""
        return self._read[1]


@dataclass(frozen=True)
class EnvView:
    env_id: str
    anchor: str
    well_formed: bool
    valid: bool
    problems: list[str]
    #: dimension -> messages of its failures (empty: passed)
    physics: dict[str, list[str]]
    extra: list[str]
    covered_paths: list[str]
    claimed: str
    verdicts: list[VerdictView]
    #: the words of what is wrong (reasons as the "why" section names them, codes, messages,
    #: object and room ids, verdicts): the index row's filter text
    reasons_text: str = ""
    #: the render and the environment file, relative to the report folder (None: absent)
    render: str | None = None
    env_file: str | None = None
    #: role -> "object (reason)" as the judge bound it (`EnvSample.binding`); refused map entries
    binding: list[tuple[str, str]] = field(default_factory=list)
    refused: list[str] = field(default_factory=list)

    @property
    def search(self) -> str:
        """The detail page's filter text beside the card's own text (which the page's filter reads
        too): the reasons as the "why" section names them, codes, object and room ids."""
        return search_words(self.env_id, self.summary, self.reasons_text)

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
        out.append(VerdictView(kind, status, label, good, valid or kind not in FAULTY_KINDS,
                               message, lines))
    return out


def search_words(*texts: str) -> str:
    """One filter text of `texts`: each whitespace-separated word once, in lower case, in order of
    first appearance (a page's filter matches typed words as substrings of this)."""
    seen: dict[str, None] = {}
    for text in texts:
        for word in text.lower().split():
            seen.setdefault(word, None)
    return " ".join(seen)


def _reasons_text(sample: Mapping[str, Any], verdicts: Sequence[VerdictView]) -> str:
    from logicenveval.reporting.why import sample_reasons

    physics = sample.get("physics") or {}
    found = [f for key in ("failures", "extended_failures") for f in physics.get(key) or []
             if isinstance(f, dict)]
    return search_words(
        *(f"{kind}: {key} {message}" for kind, key, message in sample_reasons(sample)),
        *(str(p) for p in sample.get("problems") or []),
        *(f"{f.get('dimension', '')} {f.get('code', '')} {f.get('message', '')} "
          + " ".join(str(x) for x in [*(f.get("objects") or []), *(f.get("rooms") or [])])
          for f in found),
        *(f"{v.kind} {kind_short(v.kind)} {v.label} {v.status} {v.message}" for v in verdicts))


def kind_short(kind: str) -> str:
    """The faulty kinds' short names (index columns): CF, Unreach, LBranch; others as they are."""
    return KIND_SHORT.get(kind, kind)


def env_view(assets: Assets | None, generator: str, task: str, sample: dict[str, Any],
             detail: EnvDetail | None) -> EnvView:
    """What a card shows of one environment; without `assets` (an index row whose page is
    written already) its render and file are not looked up."""
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
    verdicts = _verdicts(sample, detail, valid)
    return EnvView(
        env_id=str(sample["env_id"]), anchor=env_anchor(str(sample["env_id"])),
        render=None if assets is None else render_href(assets, generator, task, sample, detail),
        env_file=None if assets is None else env_href(assets, generator, task, str(sample["env_id"])),
        well_formed=bool(sample.get("well_formed")), valid=valid,
        problems=[str(p) for p in [*(sample.get("problems") or []), *(sample.get("violations") or [])]],
        physics=dims, extra=extra,
        covered_paths=[str(p) for p in sample.get("covered_paths") or []], claimed=claim,
        verdicts=verdicts, reasons_text=_reasons_text(sample, verdicts),
        binding=_binding(sample), refused=[str(m) for m in sample.get("refused_roles") or []])


def _binding(sample: Mapping[str, Any]) -> list[tuple[str, str]]:
    """Role -> `object (reason)` of a sample (samples written before the binding was recorded
    have none)."""
    out = []
    for role, choice in sorted((sample.get("binding") or {}).items()):
        if isinstance(choice, dict):
            oid = choice.get("object")
            out.append((str(role), f"{oid if oid is not None else '—'} ({choice.get('reason', '?')})"))
    return out


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
    #: the traceback of the exception that failed the unit as a whole (`UnitRecord.traceback`)
    traceback: str | None = None

    @property
    def n_valid(self) -> int:
        return sum(e.valid for e in self.envs)

    @property
    def search(self) -> str:
        """The index row's filter text: task, seed, each environment's id, summary and reasons,
        the task's generation failures as the "why" section names them, what the row shows."""
        from logicenveval.reporting.why import failure_reason

        detected = [f"{k} {kind_short(k)} {'–' if d is None else ('detected' if d else 'missed')}"
                    for k, d in self.detected.items()]
        failed = [f"{'built short' if f.get('env_id') in {e.env_id for e in self.envs} else 'generation'}"
                  f": {failure_reason(f)[0]} {failure_reason(f)[1]} {f.get('env_id') or ''}"
                  for f in self.failures]
        return search_words(self.generator, self.task, f"seed{self.seed}" if self.seed else "",
                            "budget" if self.metrics.get("budget_hit") else "", *detected, *failed,
                            *(f"{e.env_id} {e.summary} {e.reasons_text}" for e in self.envs))

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


def task_rows(source: Source, generators: Sequence[str], assets: Assets | None = None,
              paged: Collection[tuple[str, str]] = ()) -> Iterator[TaskRow]:
    """Every (generator, task) of a source with its environments, in results order; `assets`
    says where the report links renders and environment files from (default: in place);
    `paged`: (generator, task) whose page is written already (its files are not looked up)."""
    assets = assets or Assets(source.run_dir, source)
    reader = UnitReader(source)
    per_task = source.results.get("per_task", {})
    failures = source.results.get("failures", {})
    scope = source.prefix.strip("/").replace("/", "-")
    for gen in generators:
        for task in source.results.get("tasks", []):
            unit = reader.unit(gen, task)
            pairs = reader.envs(gen, task, unit)
            links = None if (gen, task) in paged else assets
            envs = [env_view(links, gen, task, s, d) for s, d in pairs]
            yield TaskRow(
                generator=gen, task=task, seed=source.seed, anchor=task_anchor(gen, task, scope),
                href=page_path(source, gen, task),
                metrics=dict(per_task.get(gen, {}).get(task) or {}),
                failures=[f for f in failures.get(gen, []) if isinstance(f, dict) and f.get("task") == task],
                envs=envs, samples=[{k: v for k, v in s.items() if k in _WHY_KEYS} for s, _ in pairs],
                traceback=unit.traceback if unit is not None else None)
