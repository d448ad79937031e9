"""Crash-safe, resumable storage of a run's finished units.

Each finished (generator, task) unit is one JSON file written atomically (temp file, fsync,
rename) and carrying a checksum of its content, so a run killed at any instant leaves either a
complete unit or none; a truncated or edited unit fails its checksum and is recomputed.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import LogicEnvEvalError, RunStoreError
from logicenveval.limits import read_bytes
from logicenveval.metrics.records import UnitRecord
from logicenveval.paths import child, refuse_links, safe_relative
from logicenveval.runner.unit_codec import decode_unit, encode_unit


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
        self._lock_fd: int | None = None

    def unit_path(self, generator: str, task_id: str) -> Path:
        return child(self.units_dir, generator, task_id, suffix=".json", what="unit name")

    def claim(self, identity: dict[str, Any]) -> None:
        """`lock` the folder, then `bind_config`: what a run does before its first unit. A folder
        holding a symbolic link is refused (`paths.refuse_links`: nothing written through it)."""
        self.lock(identity)
        try:
            refuse_links(self.run_dir, error=RunStoreError)
            self.bind_config(identity)
        except BaseException:
            self.unlock()
            raise

    def lock(self, identity: dict[str, Any] | None = None) -> None:
        """Hold the folder for this process until `unlock` (or its exit, even a SIGKILL).

        Two processes writing one run folder would delete each other's temp files and race on
        the same units, so a second run of the folder is refused while the first is alive.
        Where the platform has no `flock` only the config claim protects the folder.
        """
        try:
            import fcntl
        except ImportError:  # pragma: no cover - not POSIX
            return
        self.run_dir.mkdir(parents=True, exist_ok=True)
        fd = os.open(self.run_dir / ".lock", os.O_RDWR | os.O_CREAT, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            other = ""
            with contextlib.suppress(LogicEnvEvalError, ValueError, RecursionError):
                stored = json.loads(_run_file(self.run_dir / "config.json"))
                other = " of the same configuration" if stored == identity else \
                    " of a different configuration"
            raise RunStoreError(
                f"the run folder is in use by another run{other} that is still going",
                file=str(self.run_dir),
                hint="wait for it to finish (then re-run to resume), or use another --output/--run-id",
            ) from None
        self._lock_fd = fd

    def unlock(self) -> None:
        fd, self._lock_fd = self._lock_fd, None
        if fd is not None:
            os.close(fd)

    def bind_config(self, identity: dict[str, Any]) -> None:
        """Claim the folder for `identity`, or check that it already belongs to the same one.

        The claim is one exclusive create of `config.json` (a hard link of a complete temp
        file), so of two runs started together with different configurations exactly one gets
        the folder and the other is refused; nothing is checked and then written.
        """
        path = self.run_dir / "config.json"
        text = json.dumps(identity, indent=2, sort_keys=True) + "\n"
        had_units = self.units_dir.exists()  # observed before the claim: see below
        if not path.exists() and not path.is_symlink():
            self.run_dir.mkdir(parents=True, exist_ok=True)
            if _create_exclusive(path, text):
                if had_units:  # units older than any config: nothing says what made them
                    path.unlink()
                    raise RunStoreError(
                        "the run folder has units but no config.json, so they cannot be trusted",
                        file=str(self.run_dir),
                        hint="delete the run folder to start over, or use another --output/--run-id",
                    )
                return
        try:
            stored = json.loads(_run_file(path))
        except (LogicEnvEvalError, ValueError, RecursionError):
            # never guess: units of an unknown configuration must not be reused
            raise RunStoreError(
                "the run's config.json is unreadable, so its units cannot be trusted",
                file=str(path),
                hint="delete the run folder to start over, or use another --output/--run-id",
            ) from None
        if stored != identity:
            differs = sorted(k for k in set(stored) | set(identity)
                             if not isinstance(stored, dict) or stored.get(k) != identity.get(k))
            raise RunStoreError(
                "this run folder belongs to a different configuration (another run claimed it"
                + (f"; differs in {', '.join(differs[:6])}" if differs else "") + ")",
                file=str(path),
                hint="use another --output/--run-id, or delete the folder to start over",
            )

    def discard_if_unused(self) -> None:
        """Remove the folder when it holds nothing but this store's own `.lock` and
        `config.json` (a run refused before its first unit leaves no empty run folder)."""
        try:
            entries = {p.name for p in self.run_dir.iterdir()}
        except OSError:
            return
        if entries <= {".lock", "config.json"}:
            for name in entries:
                with contextlib.suppress(OSError):
                    (self.run_dir / name).unlink()
            with contextlib.suppress(OSError):
                self.run_dir.rmdir()

    def remove_stale_temp_files(self) -> int:
        """Delete temp files left by a writer that was killed before its rename."""
        removed = 0
        for tmp in self.run_dir.rglob(".*.tmp") if self.run_dir.is_dir() else ():
            with contextlib.suppress(OSError):
                tmp.unlink()
                removed += 1
        return removed

    def save(self, record: UnitRecord) -> None:
        atomic_write_text(*self._unit_file(record))

    def save_meanwhile(self, record: UnitRecord) -> Callable[[], None]:
        """`save` with the durable write in a thread: its fsyncs wait on the disk (~3 ms each
        here, two per unit) while the caller works on; the function returned waits for the
        write and raises its error, so a unit is durable before anyone is told it is saved."""
        path, text = self._unit_file(record)
        failed: list[BaseException] = []

        def write() -> None:
            try:
                atomic_write_text(path, text)
            except BaseException as exc:  # handed to the waiting caller
                failed.append(exc)

        thread = threading.Thread(target=write, name="unit-commit", daemon=True)
        thread.start()

        def wait() -> None:
            thread.join()
            if failed:
                raise failed[0]
        return wait

    def _unit_file(self, record: UnitRecord) -> tuple[Path, str]:
        payload = encode_unit(record.model_dump(mode="json"))
        # compact: with an indent, json falls back to its pure-Python encoder (units hold traces)
        text = json.dumps({"sha256": _digest(payload), "unit": payload}, sort_keys=True,
                          separators=(",", ":"))
        return self.unit_path(record.generator, record.task_id), text + "\n"

    def load(self, generator: str, task_id: str) -> UnitRecord | None:
        """The stored unit, or None when absent, partial, corrupt, or recording a path that
        leaves the run folder (then it is recomputed)."""
        path = self.unit_path(generator, task_id)
        try:
            blob = json.loads(_run_file(path))
            payload = blob["unit"]
            if blob.get("sha256") != _digest(payload):
                return None
            record = UnitRecord.model_validate(decode_unit(payload))
        except (LogicEnvEvalError, ValueError, KeyError, TypeError, AttributeError, ValidationError):
            return None
        if record.generator != generator or record.task_id != task_id:
            return None
        recorded = [d.render for d in record.details if d.render is not None] + list(record.files)
        if any(safe_relative(rel) is None for rel in recorded):
            return None
        return record

    def files_intact(self, record: UnitRecord) -> bool:
        """Whether every file the unit wrote (environments, plan) is still there, unchanged.

        Those files are written without fsync; only the unit file is durable. After a power loss
        a unit whose files did not reach the disk is therefore recomputed, never half-reused.
        """
        for rel, digest in record.files.items():
            safe = safe_relative(rel)
            try:
                if safe is None:
                    return False
                data = _run_file(self.run_dir / safe)
            except LogicEnvEvalError:
                return False
            if hashlib.sha256(data).hexdigest() != digest:
                return False
        return True


def new_folders(path: Path) -> list[Path]:
    """`path` and the folders above it that do not exist yet, deepest first."""
    out = []
    for folder in (path, *path.parents):
        if folder.exists() or folder.is_symlink():
            break
        out.append(folder)
    return out


def remove_created(created: list[Path]) -> None:
    """Remove what a refused start-up created (`created`: none existed before it), in order:
    files, and folders only when empty."""
    for path in created:
        with contextlib.suppress(OSError):
            if path.is_dir() and not path.is_symlink():
                path.rmdir()
            elif path.exists() or path.is_symlink():
                path.unlink()


def _run_file(path: Path) -> bytes:
    """A file of the run folder, read like any untrusted file (`limits.read_bytes`): a FIFO or
    device put in its place is refused, never waited on."""
    return read_bytes(path, what=path.name, error=RunStoreError, max_bytes="max_run_file_bytes",
                      hint="a run folder holds regular files only")


def _create_exclusive(path: Path, text: str) -> bool:
    """Create `path` holding `text` unless it exists (then False), never showing a partial file:
    the text goes to a temp file that is hard-linked to `path` (an atomic create-if-absent)."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.claim.tmp")
    atomic_write_text(tmp, text)
    try:
        os.link(tmp, path)
    except FileExistsError:
        return False
    except OSError:  # a file system without hard links: an exclusive create, then the content
        try:
            fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        except FileExistsError:
            return False
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
    return True
