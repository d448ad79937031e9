"""Atomic file writes, shared by every layer that writes a file a user or a later run reads.

A reader sees the old file or the complete new one, never a part: the content goes to a temp
file in the target's folder, which is renamed over the target. A write that fails (a full disk,
a killed process) leaves no temp file behind when it can clean up, and the error names the
target. New files get the permissions of the process umask, like any file the user's tools
write (a temp file alone would be private, mode 0600).

Only a regular file the user may write is replaced (`check_output`): a rename would silently put
a plain file in place of a device node, a FIFO, a symbolic link (say to `/proc/self/fd/1`) or a
read-only file of another user — even `/dev/null` when run as root. Permission is judged from the
mode bits as for an ordinary user, so root gets the same refusal.
"""

from __future__ import annotations

import contextlib
import errno
import os
import stat
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import BinaryIO

from logicenveval.errors import ConfigError

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


def _kind(mode: int) -> str:
    """What a non-regular file is, for messages."""
    for test, name in ((stat.S_ISLNK, "a symbolic link"), (stat.S_ISDIR, "a folder"),
                       (stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISSOCK, "a socket"),
                       (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device")):
        if test(mode):
            return name
    return "not a regular file"


def _may_write(st: os.stat_result) -> bool:
    """Whether the mode bits let this process's user write (root judged like its uid's owner)."""
    if st.st_uid == os.geteuid():
        return bool(st.st_mode & stat.S_IWUSR)
    if st.st_gid == os.getegid() or st.st_gid in os.getgroups():
        return bool(st.st_mode & stat.S_IWGRP)
    return bool(st.st_mode & stat.S_IWOTH)


def check_output(path: Path) -> None:
    """Refuse (ConfigError, exit 2) an output path a rename must not replace: anything but a
    regular file the user may write, or a missing file whose folder the user may not write.
    Nothing is changed at `path`."""
    try:
        st = os.lstat(path)
    except FileNotFoundError:
        folder = path.parent
        try:
            fst = os.stat(folder)
        except (FileNotFoundError, NotADirectoryError):
            return  # made by the writer (mkdir), or its error names the path
        except OSError as exc:
            raise _named(exc, path) from exc
        if stat.S_ISDIR(fst.st_mode) and not _may_write(fst):
            raise ConfigError("the folder of this output is not writable", file=str(path),
                              hint="choose an output path in a folder you may write") from None
        return
    except OSError as exc:
        raise _named(exc, path) from exc
    except ValueError:
        raise ConfigError("the output path holds a NUL character", file=repr(str(path)),
                          hint="pass a real file path") from None
    if not stat.S_ISREG(st.st_mode):
        raise ConfigError(f"the output path is {_kind(st.st_mode)}, not a regular file; it was "
                          "left as it was", file=str(path),
                          hint="give the path of a regular file (or of a new one) to write")
    if not _may_write(st):
        raise ConfigError("the output file is read-only (or another user's); it was left as it was",
                          file=str(path), hint="choose another output path, or make the file "
                          "writable if it is yours to replace")


def _named(exc: OSError, path: Path) -> OSError:
    """The same error, naming the target (not the temp file, nor nothing, as `write` does)."""
    return OSError(exc.errno, exc.strerror or str(exc), str(path))


@contextlib.contextmanager
def _temp_for(path: Path, *, durable: bool) -> Iterator[tuple[BinaryIO, Path]]:
    """An open temp file (file object, path) in `path`'s folder, renamed to `path` when the block
    ends without an exception and removed otherwise; OS errors name `path`; a path
    `check_output` refuses is left as it was."""
    check_output(path)
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
