"""What made a unit: fingerprints of the harness, the generator's code, the task's files and the
catalog, so that a resumed run reuses a unit only when none of them changed (docs/runner.md).

The run folder's identity (`RunConfig.identity`) covers the configuration; these cover the code
and data the configuration names. Each is a short digest string recorded in the unit
(`UnitRecord.inputs`); a stored unit whose recorded inputs differ from the current ones is
recomputed, and the run says which input changed and how many units that cost.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.metadata
import os
import re
from collections.abc import Iterable, Mapping
from pathlib import Path

from logicenveval.benchmark import tasks_dir
from logicenveval.domain.catalog import DEFAULT_CATALOG
from logicenveval.generators.base import registry_entry
from logicenveval.generators.plugin_code import locate, own_code
from logicenveval.generators.plugins import GeneratorRef

#: the inputs a unit records, in the order the run names them when they changed
INPUTS: tuple[str, ...] = ("harness", "generator", "task", "catalog")
_PACKAGE = "logicenveval"
_SKIPPED_DIRS = frozenset({"__pycache__", ".git", ".mypy_cache", ".pytest_cache", ".ruff_cache"})


def _digest_files(root: Path, files: Iterable[Path]) -> str:
    """One digest over the files' paths (relative to `root`, `../` for files beside it) and
    bytes, in sorted order."""
    h = hashlib.sha256()
    for path in sorted(files):
        h.update(Path(os.path.relpath(path, root)).as_posix().encode() + b"\0")
        try:
            h.update(path.read_bytes())
        except OSError:
            h.update(b"<unreadable>")
        h.update(b"\0")
    return h.hexdigest()[:16]


def _tree(root: Path, hidden: bool = False) -> list[Path]:
    """Regular files under `root`, caches left out, and hidden ones too unless `hidden`."""
    out = []
    for path in root.rglob("*"):
        rel = path.relative_to(root).parts
        if any(p in _SKIPPED_DIRS or (p.startswith(".") and not hidden) for p in rel) \
                or not path.is_file():
            continue
        out.append(path)
    return out


def _version(distribution: str) -> str | None:
    try:
        return importlib.metadata.version(distribution)
    except importlib.metadata.PackageNotFoundError:
        return None


@functools.cache
def harness_fingerprint() -> str:
    """The harness's package version and a digest of its source (every file of the package but
    caches): a commit that changes no file of the package recomputes nothing."""
    root = Path(__file__).resolve().parents[1]
    from logicenveval import __version__

    version = _version(_PACKAGE) or __version__
    return f"{version} src:{_digest_files(root, _tree(root))}"


def _module_of(ref: GeneratorRef) -> str | None:
    """The module a generator's factory lives in (None: unknown, e.g. a factory object)."""
    entry = registry_entry(ref.target)
    target = entry if isinstance(entry, str) else ref.target
    if ":" in target:
        return target.partition(":")[0]
    factory = entry if entry is not None and not isinstance(entry, str) else None
    module = getattr(factory, "__module__", None)
    return module if isinstance(module, str) else None


def _module_sources(module: str) -> tuple[Path, list[Path]] | None:
    """(root, files) of the code a generator module stands for: a built-in module's own file
    (the harness fingerprint covers the rest), or a plug-in's own code: its package or file and
    every module it imports from outside the installed environment (`plugin_code.own_code`)."""
    if module.startswith(_PACKAGE + "."):
        found = locate(module)
        return (found[0].parent, [found[0]]) if found is not None else None
    return own_code(module)


def generator_fingerprint(ref: GeneratorRef) -> str:
    """`built-in` or the plug-in's distribution (name and version), and a digest of its source
    files; a factory whose source cannot be found is named by its target only."""
    module = _module_of(ref)
    if module is None:
        return f"{ref.target} (source unknown)"
    top = module.split(".")[0]
    if top == _PACKAGE:
        origin = "built-in"
    else:
        dists = importlib.metadata.packages_distributions().get(top, [])
        origin = " ".join(f"{d} {_version(d) or '?'}" for d in dists[:1]) or "plug-in"
    sources = _module_sources(module)
    if sources is None:
        return f"{origin} {module} (source unknown)"
    return f"{origin} src:{_digest_files(*sources)}"


def generator_module(ref: GeneratorRef) -> Path | None:
    """The plug-in's top-level package folder or single module file (what a Ray cluster ships
    to its nodes, runner.cluster); None for a built-in, a script's (`__main__`) or a factory
    of unknown source."""
    module = _module_of(ref)
    if module is None or module == "__main__" or module.split(".")[0] == _PACKAGE:
        return None  # a script's own factories cannot be imported by a worker under that name
    sources = _module_sources(module)
    if sources is None or not sources[1]:
        return None
    folder = sources[0] / module.split(".")[0]
    return folder if folder.is_dir() else sources[1][0]


def task_fingerprint(task_id: str, directory: str | Path | None) -> str:
    """A digest of every file of the task's folder (task.json, the policies, anything else),
    whatever its name: a task may name a policy `policies/.correct.xml`."""
    root = tasks_dir(directory) / task_id
    return _digest_files(root, _tree(root, hidden=True))


@functools.cache
def _file_digest(path: Path, mtime_ns: int, size: int) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()[:16]


def catalog_fingerprint(path: Path = DEFAULT_CATALOG) -> str:
    stat = path.stat()
    return _file_digest(path, stat.st_mtime_ns, stat.st_size)


def unit_inputs(ref: GeneratorRef, task_id: str, directory: str | Path | None, *,
                generator: str | None = None, task: str | None = None) -> dict[str, str]:
    """The fingerprints a unit of `ref` on `task_id` records (`generator`, `task`: precomputed)."""
    return {"harness": harness_fingerprint(),
            "generator": generator if generator is not None else generator_fingerprint(ref),
            "task": task if task is not None else task_fingerprint(task_id, directory),
            "catalog": catalog_fingerprint()}


def scored_inputs(task_id: str, directory: str | Path | None) -> dict[str, str]:
    """What a unit of `evaluate` records: no generator ran (the environment files are in the
    folder's identity), but the harness, the task and the catalog judged them."""
    return {"harness": harness_fingerprint(), "task": task_fingerprint(task_id, directory),
            "catalog": catalog_fingerprint()}


def changed_inputs(stored: Mapping[str, str], current: Mapping[str, str]) -> list[str]:
    """The inputs that differ (all of them for a unit that recorded none: an older harness)."""
    if not stored:
        return ["unrecorded"]
    return [k for k in INPUTS if stored.get(k) != current.get(k)]


def stale_reason(key: str, generator: str, task_id: str, stored: Mapping[str, str],
                 current: Mapping[str, str]) -> str:
    """What changed (a line) and its fingerprints before and after (an indented line); the run
    groups units by it and counts them."""
    if key == "unrecorded":
        return "written by a harness that recorded no fingerprints"
    if key == "fresh":
        return "--fresh"
    what = {"harness": "the harness", "generator": f"generator {generator}'s code",
            "task": f"task {task_id}'s files", "catalog": "the catalog"}[key]
    detail = f"  was {_short(stored.get(key, 'none'))}, now {_short(current.get(key, ''))}"
    return f"{what} changed\n{detail if len(detail) <= 100 else detail[:99] + '…'}"


def _short(fingerprint: str) -> str:
    """A fingerprint as a person reads it: digests cut to 8 hex digits (still telling apart)."""
    return re.sub(r"\b([0-9a-f]{8})[0-9a-f]{8,}\b", r"\1", fingerprint)
