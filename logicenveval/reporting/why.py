"""Why environments were rejected or failed: reasons grouped per generator, counted, with an example.

A run's scores say how many environments were not valid; this says why, in one screen. Four
kinds of reason, from what the units recorded (`samples.jsonl`, `results.json` `failures`):

- `generation`: an environment the generator set out to build but could not (a failed unit, a
  trajectory without a layout, a draft that is not a valid EnvSpec), by stage and message;
- `built short`: a stage failure the generator recorded for an environment it still returned
  (e.g. a layout that does not realise its claimed trajectory): the environment exists and is
  scored, so it is no failed attempt (the count agrees with results.json's `n_failed`);
- `rejected`: an environment that is not a valid scenario — ill-formed (a role not bound, a
  reached path that does not allow it: its first problem) or one in which the correct BT fails;
- `physics`: an environment failing one of the paper's PhyPR dimensions, by failure code;
- `extra check`: an environment failing one of our plausibility checks beyond PhyPR (the
  leaderboard's "Extra checks" column), by failure code.

Messages name objects and roles; reasons group them by their shape (names, quoted text and numbers
replaced), and every group keeps its first example verbatim with its task and environment (and
seed, in a multi-seed run, where the seeds' environments share ids).
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

#: groups listed per generator before "... and N other reason(s)"
MAX_GROUPS = 6
_EXAMPLE_CHARS = 200
_KEY_CHARS = 90
#: generation failures and rejections come before physics findings
_KIND_ORDER = {"generation": 0, "built short": 1, "rejected": 2, "physics": 3, "extra check": 4}

_QUOTED = re.compile(r"'[^']*'|\"[^\"]*\"")
_NAMED = re.compile(r"\b(role|object|objects|category|door|window|room|target|env|environment)\s+"
                    r"(?!(?:is|are|has|not|and|or|of|to|in|on|the|a|an|with|for)\b)[\w.-]+")
_IDENT = re.compile(r"\b[A-Za-z][A-Za-z0-9]*(?:[_-][A-Za-z0-9]+)+\b")
_NUMBER = re.compile(r"-?\d+(?:\.\d+)?")
_BRACKETS = re.compile(r"\[[^\]]*\]")

#: (generator, task, env_id, seed) of one environment; seed "" outside a multi-seed run
Where = tuple[str, str, str, str]


def reason_key(message: str) -> str:
    """The shape of a message: what varies between environments (names, numbers) replaced."""
    first = (message.strip().splitlines() or [""])[0]
    text = _QUOTED.sub("'…'", first)
    text = _BRACKETS.sub("[…]", text)
    text = _NAMED.sub(lambda m: f"{m.group(1)} …", text)
    text = _IDENT.sub("…", text)
    text = _NUMBER.sub("#", text)
    text = " ".join(text.split())
    return text if len(text) <= _KEY_CHARS else text[: _KEY_CHARS - 1] + "…"


@dataclass
class Reason:
    """Environments of one generator that share a reason, with the first one as the example."""

    kind: str  # generation | built short | rejected | physics | extra check
    key: str
    count: int = 0
    task: str = ""
    env_id: str = ""
    example: str = ""
    seed: str = ""

    @property
    def label(self) -> str:
        return f"{self.kind}: {self.key}"

    @property
    def where(self) -> str:
        """`task/env` of the example, with its seed in a multi-seed run."""
        place = "/".join(x for x in (self.task, self.env_id) if x)
        return f"{place} (seed {self.seed})" if self.seed else place


@dataclass
class GeneratorReasons:
    generator: str
    n_envs: int = 0
    #: attempted environments that were not built: results.json's `n_failed` when the caller
    #: passes the results (a failed unit is one record but all its planned attempts), else the
    #: failure records that name no returned environment
    n_failed: int = 0
    #: all attempted environments (results.json's `n_attempted`); 0 when not known
    n_attempted: int = 0
    #: stage failures recorded for environments that were still returned (`built short`)
    n_short: int = 0
    n_rejected: int = 0
    n_physics: int = 0
    #: environments failing an extra plausibility check (beyond the paper's PhyPR)
    n_extra: int = 0
    reasons: list[Reason] = field(default_factory=list)

    @property
    def failed_text(self) -> str:
        """`3/6 attempted` when the attempts are known, else the count alone."""
        return f"{self.n_failed}/{self.n_attempted} attempted" if self.n_attempted else str(self.n_failed)

    @property
    def clean(self) -> bool:
        return not (self.n_failed or self.n_short or self.n_rejected or self.n_physics or self.n_extra)

    @property
    def counts_text(self) -> str:
        """The summary's counts: failed attempts, rejected, failing PhyPR, failing extra checks."""
        return (f"{self.failed_text} failed to generate, {self.n_rejected} not a valid scenario, "
                f"{self.n_physics} failing PhyPR, {self.n_extra} failing extra checks")


def _add(groups: dict[tuple[str, str], Reason], kind: str, key: str, where: Where,
         example: str, n: int = 1) -> None:
    _, task, env_id, seed = where
    reason = groups.setdefault((kind, key), Reason(kind, key, task=task, env_id=env_id, seed=seed,
                                                  example=" ".join(example.split())[:_EXAMPLE_CHARS]))
    reason.count += n


def _seed(record: Mapping[str, Any]) -> str:
    """The seed a sample or failure record was tagged with in a multi-seed run, else ""."""
    seed = record.get("seed")
    return "" if seed is None else str(seed)


def rejection(sample: Mapping[str, Any]) -> tuple[str, str] | None:
    """(reason key, message) why a sample is not a valid scenario, or None when it is one."""
    problems = [str(p) for p in sample.get("problems") or []]
    if not sample.get("well_formed", False):
        message = problems[0] if problems else "ill-formed (no problem recorded)"
        return f"ill-formed: {reason_key(message)}", message
    violations = [str(v) for v in sample.get("violations") or []]
    if violations:
        return f"violates a task constraint: {reason_key(violations[0])}", violations[0]
    verdict = (sample.get("verdicts") or {}).get("correct")
    if verdict != "passed":
        return f"the correct BT ends {verdict or 'without a verdict'}", f"correct BT: {verdict}"
    return None


def sample_reasons(sample: Mapping[str, Any]) -> list[tuple[str, str, str]]:
    """(kind, reason key, first message) of everything wrong with one environment: its rejection,
    each PhyPR failure code, each extra-check failure code (what the "why" section lists)."""
    out = []
    why = rejection(sample)
    if why is not None:
        out.append(("rejected", *why))
    physics = sample.get("physics") or {}
    failed = [f for f in physics.get("failures") or [] if isinstance(f, Mapping)]
    for dim, code in sorted({(str(f.get("dimension", "?")), str(f.get("code", "?"))) for f in failed}):
        first = next(f for f in failed if (str(f.get("dimension", "?")), str(f.get("code", "?"))) == (dim, code))
        out.append(("physics", f"PhyPR {dim}: {code}", str(first.get("message") or code)))
    extra = [f for f in physics.get("extended_failures") or [] if isinstance(f, Mapping)]
    for code in sorted({str(f.get("code", "?")) for f in extra}):
        first = next(f for f in extra if str(f.get("code", "?")) == code)
        out.append(("extra check", code, str(first.get("message") or code)))
    return out


def failure_reason(failure: Mapping[str, Any]) -> tuple[str, str]:
    """(reason key, message) of a recorded generation failure."""
    message = str(failure.get("message") or "no message")
    stage = str(failure.get("stage") or "unit")
    kind = failure.get("kind")
    return f"{stage}{f' ({kind})' if kind else ''}: {reason_key(message)}", message


def reasons(samples: Iterable[Mapping[str, Any]],
            failures: Mapping[str, Sequence[Mapping[str, Any]]],
            generators: Sequence[str] | None = None,
            messages: Mapping[Where, str] | None = None,
            scores: Mapping[str, Mapping[str, Any]] | None = None) -> list[GeneratorReasons]:
    """Per generator (results order), its reasons, most frequent first.

    `messages` optionally maps an environment (`Where`) to the correct BT's verdict message, so
    a rejected environment's example says where the BT failed. In a multi-seed run, samples and
    failures carry their `seed`: the seeds' environments share ids, so a failure in one seed is
    never taken for an environment another seed built. `scores` (results.json's
    `results`) gives the attempt counts, so the summary's numbers are the leaderboard's, and,
    without `generators`, the order.
    """
    by_gen: dict[str, GeneratorReasons] = {}
    groups: dict[str, dict[tuple[str, str], Reason]] = {}
    order = list(generators or scores or [])

    def gen_of(name: str) -> GeneratorReasons:
        if name not in by_gen:
            by_gen[name] = GeneratorReasons(name)
            groups[name] = {}
            if name not in order:
                order.append(name)
        return by_gen[name]

    for gen in order:
        gen_of(gen)
    samples = list(samples)
    built = {(str(s["generator"]), str(s["task_id"]), str(s["env_id"]), _seed(s)) for s in samples}
    for gen, items in failures.items():
        g = gen_of(gen)
        for f in items:
            where = (gen, str(f.get("task", "")), str(f.get("env_id") or ""), _seed(f))
            returned = where in built
            # an entry counts the failed attempts it states (results.json `attempts`): a unit
            # that failed as a whole, or attempts no generation failure stated
            n = f.get("attempts") if isinstance(f.get("attempts"), int) else 1
            n = max(1, n or 1)
            g.n_failed += 0 if returned else n
            g.n_short += returned
            key, message = failure_reason(f)
            _add(groups[gen], "built short" if returned else "generation", key, where, message,
                 1 if returned else n)
    for s in samples:
        where = (str(s["generator"]), str(s["task_id"]), str(s["env_id"]), _seed(s))
        gen = where[0]
        g = gen_of(gen)
        g.n_envs += 1
        found = sample_reasons(s)
        kinds = {kind for kind, _, _ in found}
        g.n_rejected += "rejected" in kinds
        g.n_physics += "physics" in kinds
        g.n_extra += "extra check" in kinds
        for kind, key, message in found:
            if kind == "rejected" and messages and s.get("well_formed"):
                message = messages.get(where) or message
            _add(groups[gen], kind, key, where, message)
    out = []
    for gen in order:
        g = by_gen[gen]
        row = (scores or {}).get(gen) or {}
        if isinstance(row.get("n_failed"), int) and isinstance(row.get("n_attempted"), int):
            g.n_failed, g.n_attempted = row["n_failed"], row["n_attempted"]
        g.reasons = sorted(groups[gen].values(), key=lambda r: (_KIND_ORDER.get(r.kind, len(_KIND_ORDER)),
                                                                  -r.count, r.key))
        out.append(g)
    return out


def summary_text(per_gen: Sequence[GeneratorReasons], max_groups: int = MAX_GROUPS) -> str:
    """The end-of-run summary: per generator its counts and its most frequent reasons."""
    lines = ["Why environments were rejected or failed (count × reason — first example):"]
    for g in per_gen:
        if g.clean:
            lines.append(f"  {g.generator}: {g.n_envs} environment(s), none rejected, failed, "
                         "physically implausible or failing an extra check")
            continue
        short = f" ({g.n_short} stage failure(s) in returned ones)" if g.n_short else ""
        lines.append(f"  {g.generator}: {g.n_envs} environment(s){short}; {g.counts_text}")
        for r in g.reasons[:max_groups]:
            lines.append(f"    {r.count} × {r.label} — {r.where}: {r.example}")
        if len(g.reasons) > max_groups:
            lines.append(f"    ... and {len(g.reasons) - max_groups} other reason(s): see "
                         "leaderboard.html, samples.jsonl and results.json 'failures'")
    return "\n".join(lines)
