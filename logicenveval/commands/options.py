"""Argument types that validate options at parse time (argparse then prints usage and exits 2)."""

from __future__ import annotations

import argparse
import math
import re
from collections.abc import Callable

from logicenveval.runner.config import MAX_SEED as MAX_SEED
from logicenveval.runner.config import MAX_UNIT_TIMEOUT

#: the largest `simulate --tick-limit` (the benchmark's trees finish in well under 100 ticks)
MAX_TICKS = 100_000


def int_range(low: int, high: int) -> Callable[[str], int]:
    """An int option within [low, high] (every count option has an upper bound too)."""

    def parse(text: str) -> int:
        if len(text.strip()) > 40:
            raise argparse.ArgumentTypeError(f"{text[:40]!r}... is too long for an integer here")
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
        if value < low or value > high:
            raise argparse.ArgumentTypeError(f"{value} is out of range: use an integer between "
                                             f"{low} and {high}")
        return value

    return parse


def workers(text: str) -> int:
    from logicenveval.errors import ConfigError
    from logicenveval.limits import limit

    try:
        high = limit("max_workers")
    except ConfigError as exc:  # argparse shows only these as one line
        raise argparse.ArgumentTypeError(str(exc)) from None
    return int_range(1, high)(text)


def non_negative_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value) or value < 0:
        raise argparse.ArgumentTypeError(f"{text!r} must be a finite number >= 0")
    return value


def task_list(text: str) -> tuple[str, ...]:
    """`--tasks`: `all` (returned as ()) or a `name_list` of task ids."""
    return () if text.strip() == "all" else name_list(text)


def name_list(text: str) -> tuple[str, ...]:
    """A comma-separated list of names: no empty list, no empty or repeated item."""
    items = [t.strip() for t in text.split(",")]
    if not any(items):
        raise argparse.ArgumentTypeError("empty list: name at least one")
    if not all(items):
        raise argparse.ArgumentTypeError(f"{text!r} has an empty item")
    dup = sorted({t for t in items if items.count(t) > 1})
    if dup:
        raise argparse.ArgumentTypeError(f"listed twice: {', '.join(dup)}")
    return tuple(items)


def folder_name(text: str) -> str:
    """One folder name (no path separators, not '.' or '..')."""
    if not re.fullmatch(r"[A-Za-z0-9_][A-Za-z0-9._-]{0,127}", text):
        raise argparse.ArgumentTypeError(
            f"{text!r} is not a plain folder name: use letters, digits, '.', '_' and '-' only")
    return text


def seed_list(text: str) -> list[int]:
    """`--seeds 0,1,2`: distinct integers >= 0, no empty item."""
    items = [t.strip() for t in text.split(",")]
    if not all(items):
        raise argparse.ArgumentTypeError(f"{text!r} has an empty item: write e.g. 0,1,2")
    try:
        seeds = [int(t) for t in items]
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a list of integers, e.g. 0,1,2") from None
    if any(s < 0 for s in seeds):
        raise argparse.ArgumentTypeError(f"{text!r} has a negative seed: seeds are integers >= 0")
    if any(s > MAX_SEED for s in seeds):
        raise argparse.ArgumentTypeError(f"{text!r} has a seed above {MAX_SEED}")
    dup = sorted({s for s in seeds if seeds.count(s) > 1})
    if dup:
        raise argparse.ArgumentTypeError(f"listed twice: {', '.join(map(str, dup))}")
    return seeds


def timeout(text: str) -> float | None:
    """Seconds > 0 up to `MAX_UNIT_TIMEOUT`, or 0 for no bound."""
    value = non_negative_float(text)
    if value > MAX_UNIT_TIMEOUT:
        raise argparse.ArgumentTypeError(f"{text!r} is more than {MAX_UNIT_TIMEOUT:g} s (a week): use "
                                         "a smaller bound, or 0 for none")
    return value or None


def _scalar(text: str) -> str | int | float | bool:
    """An argument value: an integer, a decimal number, true/false, else the text itself."""
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    if re.fullmatch(r"[+-]?[0-9]+", text):
        return int(text)
    if re.fullmatch(r"[+-]?([0-9]+\.[0-9]*|\.[0-9]+|[0-9]+)([eE][+-]?[0-9]+)?", text):
        value = float(text)
        if math.isfinite(value):
            return value
    return text


def factory_args(text: str) -> dict[str, str | int | float | bool]:
    """`key=value,...` -> {key: value}: the factory arguments of the one generator of `generate`."""
    try:
        return generator_args("generator:" + text)[1]
    except argparse.ArgumentTypeError:
        raise argparse.ArgumentTypeError(f"{text!r} is not key=value,... (e.g. n_envs=5,style=sparse)"
                                         ) from None


def generator_args(text: str) -> tuple[str, dict[str, str | int | float | bool]]:
    """`NAME:key=value,...` -> (NAME, {key: value}); values are numbers, true/false or text.

    NAME may itself hold ':' (`my_pkg.mod:MyGenerator:n_envs=5`): it ends at the last ':' before
    the first '='."""
    head, eq, _ = text.partition("=")
    name, colon, _ = head.rpartition(":")
    if not eq or not colon or not name.strip():
        raise argparse.ArgumentTypeError(f"{text!r} is not NAME:key=value,... (e.g. "
                                         "my-generator:n_envs=5,style=sparse)")
    args: dict[str, str | int | float | bool] = {}
    for item in text[len(name) + 1:].split(","):
        key, sep, value = item.partition("=")
        key = key.strip()
        if not sep or not key.isidentifier():
            raise argparse.ArgumentTypeError(f"{item!r} in {text!r} is not key=value with a "
                                             "Python keyword name as key")
        if key in args:
            raise argparse.ArgumentTypeError(f"{key!r} given twice in {text!r}")
        args[key] = _scalar(value.strip())
    return name.strip(), args
