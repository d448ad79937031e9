"""Crash-safe, resumable storage of a run's finished units.

Each finished (generator, task) unit is one JSON file written atomically (temp file, fsync,
rename) and carrying a checksum of its content, so a run killed at any instant leaves either a
complete unit or none; a truncated or edited unit fails its checksum and is recomputed.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import RunStoreError
from logicenveval.metrics.records import UnitRecord


def _digest(payload: Any) -> str:
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()


def text_digest(text: str) -> str:
    """The SHA-256 a unit records for each file it wrote (`UnitRecord.files`)."""
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


class RunStore:
    """The `units/` folder of a run directory plus its `config.json`."""

    def __init__(self, run_dir: Path) -> None:
        self.run_dir = run_dir
        self.units_dir = run_dir / "units"

    def unit_path(self, generator: str, task_id: str) -> Path:
        return self.units_dir / generator / f"{task_id}.json"

    def bind_config(self, identity: dict[str, Any]) -> None:
        """Record the run's identity, or check that an existing folder has the same one."""
        path = self.run_dir / "config.json"
        if path.exists() or path.is_symlink():
            try:
                stored = json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError, RecursionError):
                # never guess: units of an unknown configuration must not be reused
                raise RunStoreError(
                    "the run's config.json is unreadable, so its units cannot be trusted",
                    file=str(path),
                    hint="delete the run folder to start over, or use another --output/--run-id",
                ) from None
            if stored != identity:
                raise RunStoreError(
                    "this run folder belongs to a different configuration",
                    file=str(path),
                    hint="use another --output/--run-id, or delete the folder to start over",
                )
            return
        if self.units_dir.exists():
            raise RunStoreError(
                "the run folder has units but no config.json, so they cannot be trusted",
                file=str(self.run_dir),
                hint="delete the run folder to start over, or use another --output/--run-id",
            )
        atomic_write_text(path, json.dumps(identity, indent=2, sort_keys=True) + "\n")

    def remove_stale_temp_files(self) -> int:
        """Delete temp files left by a writer that was killed before its rename."""
        removed = 0
        for tmp in self.run_dir.rglob(".*.tmp") if self.run_dir.is_dir() else ():
            with contextlib.suppress(OSError):
                tmp.unlink()
                removed += 1
        return removed

    def save(self, record: UnitRecord) -> None:
        payload = record.model_dump(mode="json")
        # compact: with an indent, json falls back to its pure-Python encoder (units hold traces)
        text = json.dumps({"sha256": _digest(payload), "unit": payload}, sort_keys=True,
                          separators=(",", ":"))
        atomic_write_text(self.unit_path(record.generator, record.task_id), text + "\n")

    def load(self, generator: str, task_id: str) -> UnitRecord | None:
        """The stored unit, or None when absent, partial or corrupt (then it is recomputed)."""
        path = self.unit_path(generator, task_id)
        try:
            blob = json.loads(path.read_text(encoding="utf-8"))
            payload = blob["unit"]
            if blob.get("sha256") != _digest(payload):
                return None
            record = UnitRecord.model_validate(payload)
        except (OSError, ValueError, KeyError, TypeError, ValidationError):
            return None
        if record.generator != generator or record.task_id != task_id:
            return None
        return record

    def files_intact(self, record: UnitRecord) -> bool:
        """Whether every file the unit wrote (environments, plan) is still there, unchanged.

        Those files are written without fsync; only the unit file is durable. After a power loss
        a unit whose files did not reach the disk is therefore recomputed, never half-reused.
        """
        for rel, digest in record.files.items():
            try:
                data = (self.run_dir / rel).read_bytes()
            except OSError:
                return False
            if hashlib.sha256(data).hexdigest() != digest:
                return False
        return True
