"""Atomic file writes, shared by every layer that writes a file a user or a later run reads.

A reader sees the old file or the complete new one, never a part: the content goes to a temp
file in the target's folder, which is renamed over the target. A write that fails (a full disk,
a killed process) leaves no temp file behind when it can clean up, and the error names the
target. New files get the permissions of the process umask, like any file the user's tools
write (a temp file alone would be private, mode 0600).
"""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import BinaryIO

#: write errors of the machine rather than of the path given: the work failed (CLI exit 1)
RESOURCE_ERRNOS = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EIO, errno.EFBIG, errno.ENOMEM})


def _umask() -> int:
    """The process umask, read without changing it where the platform allows (Linux /proc)."""
    with contextlib.suppress(OSError, ValueError), \
            open("/proc/self/status", encoding="ascii", errors="replace") as fh:
        for line in fh:
            if line.startswith("Umask:"):
                return int(line.split()[1], 8)
    mask = os.umask(0o022)  # elsewhere: read by setting it, then restore
    os.umask(mask)
    return mask


def _named(exc: OSError, path: Path) -> OSError:
    """The same error, naming the target (not the temp file, nor nothing, as `write` does)."""
    return OSError(exc.errno, exc.strerror or str(exc), str(path))


@contextlib.contextmanager
def _temp_for(path: Path, *, durable: bool) -> Iterator[tuple[BinaryIO, Path]]:
    """An open temp file (file object, path) in `path`'s folder, renamed to `path` when the block
    ends without an exception and removed otherwise; OS errors name `path`."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    except OSError as exc:
        raise _named(exc, path) from exc
    try:
        with os.fdopen(fd, "wb") as fh:
            yield fh, Path(tmp)
            fh.flush()
            os.fchmod(fh.fileno(), 0o666 & ~_umask())
            if durable:
                os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException as exc:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise _named(exc, path) from exc
        raise
    if durable:
        _sync_folder(path.parent)


@contextlib.contextmanager
def atomic_path(path: Path, *, durable: bool = True) -> Iterator[Path]:
    """A temp path in `path`'s folder for a writer that wants a file name (an image library);
    renamed to `path` when the block ends without an exception, removed otherwise."""
    with _temp_for(path, durable=durable) as (_, tmp):
        yield tmp


def atomic_write_bytes(path: Path, data: bytes, *, durable: bool = True) -> None:
    """Write `data` so that readers see the old file or the complete new one, never a part.

    `durable` also fsyncs the file and its folder, so the write survives a power loss; files a
    unit commit vouches for by digest (or that are rebuilt from units) skip that cost.
    """
    with _temp_for(path, durable=durable) as (fh, _):
        fh.write(data)


def atomic_write_text(path: Path, text: str, *, durable: bool = True) -> None:
    """`atomic_write_bytes` of UTF-8 text."""
    atomic_write_bytes(path, text.encode("utf-8"), durable=durable)


def _sync_folder(folder: Path) -> None:
    try:
        dir_fd = os.open(folder, os.O_RDONLY)
    except OSError as exc:
        raise _named(exc, folder) from exc
    try:
        os.fsync(dir_fd)
    finally:
        os.close(dir_fd)
