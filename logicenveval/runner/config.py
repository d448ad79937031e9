"""The configuration of a run: what is evaluated, with which model, where results go.

The run folder name is derived from the configuration, so re-running the same command finds its
own folder and resumes it; a different configuration never mixes into an existing folder.
"""

from __future__ import annotations

import hashlib
import json
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from logicenveval.errors import ConfigError, did_you_mean
from logicenveval.model.repeats import repeated
from logicenveval.redact import is_secret_name, strip_url_credentials
from logicenveval.scene.layout import DEFAULT_SOLVER, Solver

#: a run id is one folder name inside --output: no separators, no leading dot
RUN_ID_PATTERN = r"^[A-Za-z0-9_][A-Za-z0-9._-]{0,127}$"
DEFAULT_GENERATORS: tuple[str, ...] = ("logicenvgen", "logicenvgen-exact", "cot", "ifg", "holodeck")
#: seconds one generator may take for one task (`--unit-timeout`); 0 or None: no bound
DEFAULT_UNIT_TIMEOUT = 1800.0
#: the largest `--unit-timeout` (a week): every timer and wait of the run stays far inside what
#: the platform's clocks take (`threading.TIMEOUT_MAX`, `setitimer`) with the executor's budget
MAX_UNIT_TIMEOUT = 7 * 24 * 3600.0
#: the largest count option (`--limit`, `--max-infra-failures`): far above 25 tasks, bounded so a
#: typo cannot make a number nothing downstream expects
MAX_COUNT = 1_000_000
#: the largest seed (numpy takes any integer; a longer one only makes folder names longer)
MAX_SEED = 2**63 - 1
#: a generator's factory arguments: JSON scalars
ArgValue = str | int | float | bool


class RunConfig(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")
    model: str = "offline"
    model_args: str = ""
    generators: tuple[str, ...] = DEFAULT_GENERATORS
    tasks: tuple[str, ...] = ()  # empty = all tasks of tasks_dir
    tasks_dir: str | None = None
    limit: int | None = Field(default=None, ge=1, le=MAX_COUNT)
    seed: int = Field(default=0, ge=0, le=MAX_SEED)
    layout_solver: Solver = DEFAULT_SOLVER
    workers: int = Field(default=1, ge=1)
    executor: str = "process"
    #: the Ray cluster of `--executor ray` (`--ray-address`; default `RAY_ADDRESS`, else a local
    #: instance started for the run); not identity: where units run does not change them
    ray_address: str | None = None
    output: str = "reports"
    cache: str | None = None
    no_cache: bool = False
    run_id: str | None = Field(default=None, pattern=RUN_ID_PATTERN)
    #: stop the run after this many consecutive units failed for infrastructure reasons (0: never)
    max_infra_failures: int = Field(default=5, ge=0, le=MAX_COUNT)
    #: what generators are given: as in the paper, the description (the default; with the oracle,
    #: whose replies name the task's roles, the roles), or the task's roles (our variant)
    brief: Literal["roles", "description"] = "description"
    #: wall-time bound of one generator on one task (runner.unit); None: unbounded
    unit_timeout: float | None = Field(default=DEFAULT_UNIT_TIMEOUT, gt=0, le=MAX_UNIT_TIMEOUT,
                                       allow_inf_nan=False)
    #: `--generators` item (as written, or its row name) -> keyword arguments of its factory
    generator_args: dict[str, dict[str, ArgValue]] = Field(default_factory=dict)
    #: recompute every unit, even those whose fingerprints are unchanged (`--fresh`; not identity)
    fresh: bool = False
    #: re-raise a generator's exception in this process, for a debugger (`--debug`; not identity)
    debug: bool = False
    #: let a run of other inputs replace the finished run in its folder (`--replace`; not
    #: identity): by default it goes to a new folder, or is refused under `--run-id`
    #: (runner.placement)
    replace: bool = False

    @model_validator(mode="before")
    @classmethod
    def _default_brief(cls, data: Any) -> Any:
        """No brief given: the paper's (description), except for the oracle, which needs roles,
        and a replay of a run folder, which asks what that run asked (`recorded_setup`): its
        brief, and its request protocol unless `--model-args protocol=N` says otherwise."""
        if not isinstance(data, dict):
            return data
        recorded = recorded_setup(data.get("model"))
        if data.get("brief") is None:
            brief = recorded.brief if recorded else "roles" if data.get("model") == "oracle" else "description"
            data = {**data, "brief": brief}
        if recorded and "protocol" not in _model_args(data.get("model_args")):
            args = str(data.get("model_args") or "")
            data = {**data, "model_args": f"{args},protocol={recorded.protocol}" if args else
                    f"protocol={recorded.protocol}"}
        return data

    @model_validator(mode="after")
    def _brief_fits_model(self) -> RunConfig:
        if self.brief == "description" and self.model == "oracle":
            from logicenveval.errors import ConfigError

            raise ConfigError("--brief description cannot be used with --model oracle", field="--brief",
                              hint="the oracle answers with the GT plans, which name the task's roles; "
                                   "use --brief roles with the oracle")
        return self

    @field_validator("generators")
    @classmethod
    def _current_names(cls, names: tuple[str, ...]) -> tuple[str, ...]:
        """Old generator names (aliases) become current ones, with a FutureWarning."""
        from logicenveval.generators.base import canonical_name

        return tuple(canonical_name(n) for n in names)

    def identity(self) -> dict[str, object]:
        """The fields that define *what* is computed (not how fast or where)."""
        return {
            "model": self.model,
            "model_args": strip_url_credentials(_redact(self.model_args)),
            "generators": list(self.generators),
            "tasks": list(self.tasks),
            "tasks_dir": self.tasks_dir,
            "limit": self.limit,
            "seed": self.seed,
            "layout_solver": self.layout_solver,
            "brief": self.brief,
            # recorded only when set, so the identity (and folder) of earlier runs is unchanged
            **({"generator_args": {g: dict(sorted(a.items()))
                                   for g, a in sorted(self.generator_args.items())}}
               if self.generator_args else {}),
            **({"unit_timeout": self.unit_timeout}
               if self.unit_timeout != DEFAULT_UNIT_TIMEOUT else {}),
        }

    def resolved_run_id(self) -> str:
        if self.run_id:
            return self.run_id
        blob = json.dumps(self.identity(), sort_keys=True).encode()
        slug = re.sub(r"[^A-Za-z0-9]+", "-", self.model).strip("-").lower()[:40] or "model"
        return f"{slug}-seed{self.seed}-{hashlib.sha256(blob).hexdigest()[:8]}"

    def run_dir(self) -> Path:
        return Path(self.output) / self.resolved_run_id()


def _model_args(args: object) -> dict[str, Any]:
    """The model arguments as parsed, or none where they do not parse (building the model then
    says what is wrong with them)."""
    from logicenveval.llm.registry import parse_model_args

    try:
        return parse_model_args(args if isinstance(args, str | dict) else None)
    except ConfigError:
        return {}


class RecordedSetup(BaseModel):
    """What a recorded run asked its model: the replies in its cache answer these requests only."""

    model_config = ConfigDict(frozen=True)
    brief: Literal["roles", "description"]
    protocol: int
    source: str


def recorded_setup(model: object) -> RecordedSetup | None:
    """For `replay:FILE` where FILE is a run folder's reply cache (a replay pack,
    `reports/real/<model>/llm_cache.sqlite`), the brief and request protocol that run was
    recorded with, read from its `results.json` (or `config.json`): a pack replays with the
    README's command as written, whatever the defaults became since. Protocol: `results.json`'s
    `protocol`, else the run's `protocol=` model argument, else 1 (a pack recorded before
    protocols were named, issue 39). None for any other model or a cache outside a run folder."""
    if not isinstance(model, str) or not model.startswith("replay:"):
        return None
    folder = Path(model.partition(":")[2]).parent
    for name in ("results.json", "config.json"):
        path = folder / name
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
        config = data.get("config", data) if isinstance(data, dict) else None
        if not isinstance(config, dict) or config.get("brief") not in ("roles", "description"):
            continue
        return RecordedSetup(brief=config["brief"], protocol=recorded_protocol(data), source=str(path))
    return None


def recorded_protocol(data: Mapping[str, Any]) -> int:
    """The request protocol of a recorded run, from its `results.json` (or `config.json`) data:
    its `protocol`, else its `protocol=` model argument, else 1 (a run recorded before protocols
    were named, issue 39)."""
    protocol = data.get("protocol")
    if isinstance(protocol, int) and not isinstance(protocol, bool):
        return protocol
    config = data.get("config", data)
    named = _model_args(config.get("model_args") if isinstance(config, Mapping) else None).get("protocol", 1)
    return named if isinstance(named, int) and not isinstance(named, bool) else 1


def _redact(model_args: str) -> str:
    """Model args go into reports; anything that looks like a secret value is masked."""
    parts = []
    for item in filter(None, (p.strip() for p in model_args.split(","))):
        key, _, value = item.partition("=")
        if is_secret_name(key.strip()):
            value = "***"
        parts.append(f"{key}={value}" if _ else key)
    return ",".join(parts)


def selected_tasks(tasks: Sequence[str], known: Sequence[str]) -> list[str]:
    """A `--tasks` list checked against the task ids there are: each named once and each known
    (`run` and `evaluate` take the same list; an empty one is theirs to default)."""
    dup = repeated(tasks)
    if dup:
        raise ConfigError(f"task(s) listed twice: {dup}", field="--tasks", hint="list each task once")
    missing = [t for t in tasks if t not in known]
    if missing:
        hints = "".join(did_you_mean(t, known) for t in missing[:5])
        raise ConfigError(f"unknown task(s) {missing}{hints}", field="--tasks",
                          hint="see `python -m logicenveval tasks list`")
    return list(tasks)
