"""Which folder a run goes to: a finished run is never replaced by a run of other inputs.

A run folder is named for its configuration (`RunConfig.resolved_run_id`), so "edit the
plug-in, run the same command, `compare OLD NEW`" used to recompute the edited units inside the
old folder, leaving no OLD; a named baseline (`--run-id floor-v1`) re-run with new code was
silently replaced (issue 48). Now every finished run records the fingerprints of what made it
(`results.json` `inputs`: harness, catalog, each generator's code, each task's files; see
`runner.fingerprint`), and a run whose inputs differ from those of a finished run in its folder:

* with a derived run id goes to the next free version of the folder, `<run_id>-2`, `-3`, ...
  (the first that is absent, unfinished — it resumes — or finished with the same inputs), and
  reuses the unchanged units of the newest earlier version by copying them;
* with `--run-id X` is refused (exit 2) with the commands that keep X (a new id) or replace it
  (`--replace`).

An unfinished run (no results.json yet) is resumed in place whatever changed: nothing finished is
replaced, and its stale units are recomputed as before.
"""

from __future__ import annotations

import json
import shutil
import textwrap
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from logicenveval.errors import LogicEnvEvalError, RunStoreError
from logicenveval.limits import read_bytes
from logicenveval.paths import safe_relative

#: inputs names listed in a message before "+N more"
MAX_NAMED = 4
#: versions of one run folder tried before giving up (a guard, far above any real use)
MAX_VERSIONS = 10_000


class FinishedRunError(RunStoreError):
    """A named run folder (`--run-id`) holds a finished run of other inputs: it is kept."""

    def __init__(self, run_dir: Path, changed: list[str], free_id: str) -> None:
        self.run_dir = run_dir
        self.changed = changed
        self.free_id = free_id
        super().__init__(
            f"the run folder holds a finished run made by other inputs ({changes_text(changed)}); "
            "it is kept, not replaced", file=str(run_dir),
            hint=f"keep it and run under a new id: --run-id {free_id}; or replace it: add --replace")


@dataclass(frozen=True)
class Placement:
    run_dir: Path
    #: a finished run folder of other inputs this run leaves alone, whose unchanged units it copies
    previous: Path | None = None
    #: what changed since that finished run (empty when it is None)
    changed: tuple[str, ...] = ()

    def note(self) -> str:
        """What a person reads: which finished run was kept, and that this one went elsewhere
        ("" if none); lines of at most 100 columns but the path, which is never cut."""
        if self.previous is None:
            return ""
        head = textwrap.wrap(f"kept the finished run made by other inputs "
                             f"({changes_text(list(self.changed))}), not replaced:", 100,
                             break_long_words=False)
        return "\n".join([*head, f"  {self.previous}", "this run went to the new folder above "
                          "(unchanged units copied); --replace would replace it instead"])


def run_inputs(harness: str, catalog: str, generators: Mapping[str, str],
               tasks: Mapping[str, str]) -> dict[str, Any]:
    """What results.json records as `inputs`: every fingerprint of what made the run."""
    return {"harness": harness, "catalog": catalog, "generators": dict(generators),
            "tasks": dict(tasks)}


def finished_inputs(run_dir: Path) -> dict[str, Any] | None:
    """The `inputs` of the finished run in `run_dir` ({} when its results.json records none or is
    unreadable: made by an older harness, or damaged), or None when no run finished there."""
    path = run_dir / "results.json"
    if not path.exists() and not path.is_symlink():
        return None
    try:
        data = json.loads(read_bytes(path, what="results.json", error=RunStoreError,
                                     max_bytes="max_run_file_bytes",
                                     hint="a run folder holds regular files only"))
    except (LogicEnvEvalError, ValueError, RecursionError):
        return {}
    inputs = data.get("inputs") if isinstance(data, dict) else None
    return inputs if isinstance(inputs, dict) else {}


def changes(old: Mapping[str, Any], new: Mapping[str, Any]) -> list[str]:
    """What differs between two runs' inputs, as a person names it ([] when nothing does)."""
    if not old:
        return ["the harness (the finished run recorded no fingerprints)"]
    out = [what for key, what in (("harness", "the harness"), ("catalog", "the catalog"))
           if old.get(key) != new.get(key)]
    for key, what in (("generators", "generator {}'s code"), ("tasks", "task {}'s files")):
        before, after = old.get(key) or {}, new.get(key) or {}
        if not isinstance(before, dict):
            before = {}
        out += [what.format(name) for name in after if before.get(name) != after[name]]
        out += [what.format(name).replace("'s ", " (gone)'s ", 1) for name in before
                if name not in after]
    return out


def changes_text(changed: list[str]) -> str:
    more = len(changed) - MAX_NAMED
    return ", ".join(changed[:MAX_NAMED]) + (f", +{more} more" if more > 0 else "")


def place(run_dir: Path, inputs: Mapping[str, Any], *, named: bool, replace: bool) -> Placement:
    """The folder a run of `inputs` configured for `run_dir` goes to (see the module docstring);
    `named`: the run id was given (`--run-id`), so the folder is never switched silently."""
    old = finished_inputs(run_dir)
    if replace or old is None or not (changed := changes(old, inputs)):
        return Placement(run_dir)
    if named:
        raise FinishedRunError(run_dir, changed, _free(run_dir))
    previous, why = run_dir, changed
    for k in range(2, MAX_VERSIONS):
        candidate = run_dir.with_name(f"{run_dir.name}-{k}")
        old = finished_inputs(candidate)
        if old is None or not (changed := changes(old, inputs)):
            return Placement(candidate, previous, tuple(why))
        previous, why = candidate, changed
    raise RunStoreError(f"{MAX_VERSIONS} versions of the run folder exist", file=str(run_dir),
                        hint="delete old versions, or use --run-id")


def _free(run_dir: Path) -> str:
    """The first `<name>-<k>` beside `run_dir` that does not exist (a new id to suggest)."""
    k = 2
    while run_dir.with_name(f"{run_dir.name}-{k}").exists():
        k += 1
    return f"{run_dir.name}-{k}"


def adopt(previous: Path, run_dir: Path, files: list[str]) -> bool:
    """Copy a unit's files (`files`: paths relative to the run folder) from the finished run
    `previous` into `run_dir`; False (nothing half-copied counts) when one cannot be copied."""
    for rel in files:
        safe = safe_relative(rel)
        if safe is None:
            return False
        source, target = previous / safe, run_dir / safe
        try:
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(source, target)
        except OSError:
            return False
    return True
