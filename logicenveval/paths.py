"""The one builder of output paths from ids and names (env ids, generator names, `--name`, run ids).

Ids come from generators, plug-ins and files written by other tools, and each one becomes a file
or folder name inside a run folder. A name is accepted only when it is one plain path component:
not empty, no `/` or `\\`, no NUL or other control character, not `.`/`..`, no leading dot
(hidden files are skipped by `evaluate` and would vanish), and at most `MAX_NAME_BYTES` bytes of
UTF-8 so that `<name>.json` and its temp file fit every file system's 255-byte limit. So `a` and
`sub/../a` can never name the same file, and nothing is written outside the folder. Paths a run
folder records (render paths, the files a unit vouches for) are checked the same way on reading
(`safe_relative`), so a damaged or hand-edited unit cannot redirect a later write or read.
"""

from __future__ import annotations

import os
import unicodedata
from pathlib import Path, PurePosixPath

from logicenveval.errors import ConfigError, LogicEnvEvalError

#: bytes of one name: room for a suffix (`.json`, `.house.json`) and an atomic write's temp name
MAX_NAME_BYTES = 160


def name_problem(name: object) -> str | None:
    """Why `name` cannot be one file/folder name, or None when it can."""
    if not isinstance(name, str):
        return f"is a {type(name).__name__}, not a string"
    if not name:
        return "is empty"
    if any(unicodedata.category(c) in ("Cc", "Cs") for c in name):
        return "holds a control character (NUL, newline, ...)"
    if "/" in name or "\\" in name:
        return "holds a path separator ('/' or '\\')"
    if name in (".", "..") or name.startswith("."):
        return "starts with '.'"
    if name != name.strip():
        return "starts or ends with white space"
    size = len(name.encode("utf-8"))
    if size > MAX_NAME_BYTES:
        return f"is {size} bytes long, more than {MAX_NAME_BYTES}"
    return None


def shown(name: object, limit: int = 60) -> str:
    """A short, printable rendering of an untrusted name for messages."""
    text = repr(name)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def check_name(name: object, *, what: str, field: str | None = None, file: str | None = None,
               error: type[LogicEnvEvalError] = ConfigError) -> str:
    """`name` when it is a plain file/folder name; otherwise one precise error."""
    problem = name_problem(name)
    if problem is not None:
        raise error(f"{what} {shown(name)} {problem}", field=field, file=file,
                    hint="use a plain name of letters, digits, '.', '_' or '-' "
                    f"(no '/', not starting with '.', at most {MAX_NAME_BYTES} bytes)")
    assert isinstance(name, str)
    return name


def child(root: Path, *names: str, suffix: str = "", what: str = "name") -> Path:
    """`root/names[0]/.../names[-1]<suffix>` after checking every name (`check_name`)."""
    for n in names:
        check_name(n, what=what)
    return root.joinpath(*names[:-1], names[-1] + suffix) if names else root


def safe_relative(rel: object) -> PurePosixPath | None:
    """`rel` as a relative path that stays inside its folder, or None (absolute, `..`, odd names)."""
    if not isinstance(rel, str) or not rel:
        return None
    path = PurePosixPath(rel)
    if path.is_absolute() or not path.parts:
        return None
    if any(name_problem(part) is not None for part in path.parts):
        return None
    return path


def refuse_links(root: Path, *, error: type[LogicEnvEvalError] = ConfigError) -> None:
    """Refuse a folder that holds a symbolic link anywhere inside (the folder itself may be one).

    A run folder's `units/<generator>`, `envs/<generator>` or `details` made a link (by hand,
    or by an unpacked archive) would have a resumed run or a report write its units, EnvSpecs
    and pages into the link's target, outside the output folder; the harness never makes a link
    there, so one is refused before anything is written. One `lstat` per entry, no link followed.
    """
    pending = [root]
    while pending:
        folder = pending.pop()
        try:
            entries = list(os.scandir(folder))
        except OSError:
            continue  # unreadable or gone: the write that needs it reports it
        for entry in entries:
            if entry.is_symlink():
                rel = Path(entry.path).relative_to(root).as_posix()
                raise error(f"{rel!r} inside the output folder is a symbolic link; nothing is "
                            "written through it", file=str(root),
                            hint="replace the link with a real folder (or copy the run folder) "
                            "and re-run the command")
            if entry.is_dir(follow_symlinks=False):
                pending.append(Path(entry.path))
