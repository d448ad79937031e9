"""Argument types that validate options at parse time (argparse then prints usage and exits 2)."""

from __future__ import annotations

import argparse
import math
import re
from collections.abc import Callable


def int_range(low: int, high: int | None = None) -> Callable[[str], int]:
    """An int option within [low, high]."""

    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
        if value < low or (high is not None and value > high):
            bound = f"between {low} and {high}" if high is not None else f">= {low}"
            raise argparse.ArgumentTypeError(f"{value} is out of range: use an integer {bound}")
        return value

    return parse


def workers(text: str) -> int:
    from logicenveval.limits import limit

    return int_range(1, limit("max_workers"))(text)


def non_negative_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value) or value < 0:
        raise argparse.ArgumentTypeError(f"{text!r} must be a finite number >= 0")
    return value


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
