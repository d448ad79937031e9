"""The WordNet names of the catalog's kinds (`wordnet_names.json`, beside this module; WordNet 3.1,
licence in `WORDNET_LICENSE`), the offline reader's last-resort vocabulary (`offline.vocabulary`).

Built by `tools/wordnet_names.py` from the hand-checked senses in
`benchmark_data/wordnet_senses.json` (docs/reader.md)."""

from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path
from typing import Any

WORDNET_NAMES = Path(__file__).with_name("wordnet_names.json")


@lru_cache(maxsize=1)
def _tables() -> dict[str, Any]:
    """The file, read once for both of its tables (`wordnet_names`, `contents_names`)."""
    tables: dict[str, Any] = json.loads(WORDNET_NAMES.read_text(encoding="utf-8"))
    return tables


def wordnet_names() -> dict[str, str]:
    """Word (spaces between words) -> catalog kind."""
    names: dict[str, str] = _tables()["names"]
    return names


def contents_names() -> dict[str, str]:
    """Word (spaces between words) -> the vessel kind that holds what it names ("claret": the
    wine bottle), read only as a vessel's contents ("a bottle of claret", "the merlot bottle":
    `offline.naming`), never as a name of its own (`tools/wordnet_names.py`, `build_contents`)."""
    contents: dict[str, str] = _tables()["contents"]
    return contents


def room_words() -> frozenset[str]:
    """The WordNet names of a kind that name the room holding it ("lavatory", "washroom": the
    toilet's), which the reader reads as the room where something is in or goes to it
    (`tools/wordnet_names.py`, `room_words`)."""
    return frozenset(_tables()["rooms"])


def is_wordnet_name(text: str) -> bool:
    """Whether a synonym of the reading catalog is a WordNet name (not the catalog's own): such
    a name is matched as a whole phrase only, never lends its head noun ("lady's slipper", a
    flower, must not make every "slipper" a flower)."""
    return text in wordnet_names()
