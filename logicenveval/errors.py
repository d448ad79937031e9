"""One exception root for misuse and bad input.

Every message names where the problem is (file, field or line) and how to fix it, so a user can
act on the first line they read. Outcomes of evaluation (verdicts, physics reports) are typed
results, never exceptions.
"""

from __future__ import annotations

from collections.abc import Iterable

#: characters of each part of a message (what, file, field, fix): an input echoed into a
#: message (a 100 kB task id, path or option value) is cut in its middle, so an error stays a
#: line a user can read, and a log line stays small
ECHO_LIMITS = {"message": 1500, "file": 400, "field": 200, "hint": 800}


def clip(text: str, limit: int) -> str:
    """`text` cut in its middle to at most `limit` characters, saying how much was left out."""
    if len(text) <= limit:
        return text
    keep = max(limit - len(f" ...[{len(text)} characters cut]... "), 2)
    mark = f" ...[{len(text) - keep} characters cut]... "
    return text[: keep // 2 + keep % 2] + mark + text[len(text) - keep // 2:]


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """` (did you mean 'x'?)` for a misspelt name, the closest of `choices`; "" when none is
    close (difflib's ratio of at least 0.6, as `get_close_matches` judges)."""
    import difflib

    close = difflib.get_close_matches(word, list(choices), n=2)
    if not close:
        return ""
    return " (did you mean " + " or ".join(repr(c) for c in close) + "?)"


class LogicEnvEvalError(Exception):
    """Root of every error this package raises on purpose."""

    #: process exit code of the CLI: 2 for bad input; subclasses for failed work use 1
    exit_code = 2

    def __init__(
        self,
        message: str,
        *,
        file: str | None = None,
        field: str | None = None,
        line: int | None = None,
        column: int | None = None,
        hint: str | None = None,
    ) -> None:
        self.message = message
        self.file = file
        self.field = field
        self.line = line
        self.column = column
        self.hint = hint
        super().__init__(self._format())

    def _format(self) -> str:
        where = []
        if self.file:
            loc = clip(self.file, ECHO_LIMITS["file"])
            if self.line is not None:
                loc += f":{self.line}"
                if self.column is not None:
                    loc += f":{self.column}"
            elif self.column is not None:
                loc += f", column {self.column}"
            where.append(loc)
        elif self.line is not None:
            where.append(f"line {self.line}" + (f", column {self.column}" if self.column else ""))
        elif self.column is not None:
            where.append(f"column {self.column}")
        if self.field:
            where.append(f"field '{clip(self.field, ECHO_LIMITS['field'])}'")
        message = clip(self.message, ECHO_LIMITS["message"])
        text = (": ".join([", ".join(where), message]) if where else message)
        if self.hint:
            text += f" (fix: {clip(self.hint, ECHO_LIMITS['hint'])})"
        return text


class ConditionSyntaxError(LogicEnvEvalError, ValueError):
    """A condition string does not follow the condition language (DESIGN.md §3).

    Also a ValueError so that pydantic validators report it with the field path.
    """


class TaskFormatError(LogicEnvEvalError):
    """A task.json is malformed or inconsistent."""


class PolicyFormatError(LogicEnvEvalError):
    """A Behavior Tree XML file is malformed or uses unknown nodes/ports/roles."""


class EnvSpecError(LogicEnvEvalError):
    """An EnvSpec JSON is malformed."""


class CatalogError(LogicEnvEvalError):
    """The asset catalog is malformed or a category lookup cannot be resolved."""


class TrajectoryError(LogicEnvEvalError):
    """A logical trajectory is inconsistent with a task or cannot be realised."""


class ModelReplyError(LogicEnvEvalError):
    """An LLM reply stayed invalid after the bounded repair/re-ask budget."""


class ModelTruncatedError(ModelReplyError):
    """A reply was cut at `max_tokens` (`finish_reason: length`): the model's output, not the
    infrastructure, so it counts as a failed generation attempt."""


class ModelConnectionError(LogicEnvEvalError):
    """An LLM endpoint could not be reached or kept failing (timeouts, 429/5xx)."""


class UnitBudgetError(ModelConnectionError):
    """The unit's time budget ran out inside (or before) a model request. One label whichever
    timer fires first, the model's own deadline or the runner's `--unit-timeout` alarm: the
    method did not finish within the budget on this machine, a *generation* failure
    (`runner.unit.failure_kind`), not a broken endpoint (docs/runner.md)."""


class ServerStartError(ModelConnectionError):
    """A managed local model server (llama.cpp) did not start: infrastructure, not the model."""


class CacheMissError(LogicEnvEvalError):
    """`replay:` found no cached reply for a request."""


class ConfigError(LogicEnvEvalError):
    """A command-line option or model argument is invalid."""


class RunStoreError(LogicEnvEvalError):
    """A run folder is unreadable or belongs to a different configuration."""


class MetricsError(LogicEnvEvalError):
    """Metric inputs are inconsistent (samples of another task, no tasks to aggregate)."""


class RunFailedError(LogicEnvEvalError):
    """The work itself failed (every unit of a generator, or a run stopped early): exit 1."""

    exit_code = 1
