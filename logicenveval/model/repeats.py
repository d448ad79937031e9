"""Which items of a list occur more than once: the one check behind every "listed twice" error."""

from __future__ import annotations

from collections import Counter
from collections.abc import Hashable, Iterable
from typing import TypeVar

T = TypeVar("T", bound=Hashable)


def repeated(items: Iterable[T]) -> list[T]:
    """The items that occur more than once, each once, sorted (linear, not a count per item)."""
    return sorted((item for item, n in Counter(items).items() if n > 1), key=str)
