"""How much disk a run folder takes, by top-level part (printed at the end of a run)."""

from __future__ import annotations

import os
from pathlib import Path


def folder_bytes(run_dir: Path) -> dict[str, int]:
    """Bytes of each top-level entry of `run_dir` (files' own sizes; links not followed),
    largest first."""
    sizes: dict[str, int] = {}
    if not run_dir.is_dir():
        return sizes
    for entry in sorted(run_dir.iterdir()):
        total = 0
        if entry.is_symlink() or not entry.is_dir():
            total = entry.lstat().st_size if entry.is_file() and not entry.is_symlink() else 0
        else:
            for dirpath, _dirs, files in os.walk(entry):
                for name in files:
                    path = Path(dirpath) / name
                    if not path.is_symlink():
                        total += path.lstat().st_size
        sizes[entry.name] = total
    return dict(sorted(sizes.items(), key=lambda kv: (-kv[1], kv[0])))


def _mb(n: int) -> str:
    return f"{n / 1e6:.1f} MB"


def size_text(sizes: dict[str, int], parts: int = 5) -> str:
    """`33.1 MB (units 12.9 MB, details 10.8 MB, ...)`: the total and its largest parts."""
    shown = [f"{name} {_mb(n)}" for name, n in list(sizes.items())[:parts]]
    rest = sum(list(sizes.values())[parts:])
    if rest:
        shown.append(f"other {_mb(rest)}")
    return f"{_mb(sum(sizes.values()))} ({', '.join(shown)})" if shown else _mb(0)
