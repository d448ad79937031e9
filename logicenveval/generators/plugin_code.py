"""The files of a plug-in generator's own code: what its fingerprint must cover.

A plug-in is rarely one file: a one-file plug-in imports a sibling `helper.py`, a package imports
a sibling package. A fingerprint of the plug-in's module alone would let a resumed run reuse
units made by an old helper (issue 48). So the plug-in's code is its module (or its whole
top-level package) plus every module it imports, transitively, that lies outside the installed
environment: the standard library and site-packages are versioned by the environment, and the
harness (`logicenveval`) has a fingerprint of its own, but anything else the plug-in reaches is
code its author may edit.

Imports are read from the source (`ast`), never executed: a plug-in's lazy import inside a
function counts too, and resolving a name imports nothing (a dotted name is looked up folder by
folder from its top-level module's location). Imports by computed names (`importlib.import_module(
name)`) cannot be seen; such code belongs in the plug-in's package, whose every `.py` file counts.
"""

from __future__ import annotations

import ast
import contextlib
import functools
import importlib.util
import site
import sys
import sysconfig
from collections.abc import Iterator
from pathlib import Path

#: files of a plug-in's own code at most (a bound: a plug-in importing a huge local tree)
MAX_FILES = 2000
_HARNESS = Path(__file__).resolve().parents[1]
_SKIPPED_DIRS = frozenset({"__pycache__", ".git", ".mypy_cache", ".pytest_cache", ".ruff_cache"})


@functools.cache
def _installed_roots() -> tuple[Path, ...]:
    """The folders of the installed environment: standard library and site-packages."""
    paths = sysconfig.get_paths()
    roots = [paths.get(k) for k in ("stdlib", "platstdlib", "purelib", "platlib")]
    with contextlib.suppress(AttributeError):
        roots += site.getsitepackages()
    with contextlib.suppress(AttributeError):
        roots.append(site.getusersitepackages())
    out = []
    for root in roots:
        if root:
            with contextlib.suppress(OSError):
                out.append(Path(root).resolve())
    return tuple(dict.fromkeys(out))


def is_installed(path: Path) -> bool:
    """Whether `path` belongs to the installed environment or to the harness itself."""
    return path.is_relative_to(_HARNESS) or any(path.is_relative_to(r) for r in _installed_roots())


def _package_files(root: Path) -> list[Path]:
    """The `.py` files of a package folder (caches and hidden folders left out)."""
    out = []
    for path in root.rglob("*.py"):
        parts = path.relative_to(root).parts
        if not any(p in _SKIPPED_DIRS or p.startswith(".") for p in parts) and path.is_file():
            out.append(path.resolve())
    return sorted(out)


def locate(name: str) -> tuple[Path, bool] | None:
    """(file, is a package) of module `name`, found without importing anything new."""
    module = sys.modules.get(name)
    file = getattr(module, "__file__", None)
    if isinstance(file, str) and Path(file).is_file():
        return Path(file).resolve(), hasattr(module, "__path__")
    top, *rest = name.split(".")
    try:
        spec = importlib.util.find_spec(top)  # a top-level name: nothing is imported
    except (ImportError, ValueError):
        return None
    if spec is None:
        return None
    if not rest:
        if spec.origin and Path(spec.origin).is_file():
            return Path(spec.origin).resolve(), spec.submodule_search_locations is not None
        return None
    folders = [Path(p) for p in spec.submodule_search_locations or ()]
    found: tuple[Path, bool] | None = None
    for i, part in enumerate(rest):
        last = i == len(rest) - 1
        found, next_folders = None, []
        for folder in folders:
            if (folder / part / "__init__.py").is_file():
                found, next_folders = ((folder / part / "__init__.py").resolve(), True), [folder / part]
                break
            if last and (folder / f"{part}.py").is_file():
                found = ((folder / f"{part}.py").resolve(), False)
                break
            if (folder / part).is_dir():  # a namespace package
                next_folders.append(folder / part)
        folders = next_folders
        if not folders and not last:
            return None
    return found


def _imported(path: Path, module: str | None, is_package: bool) -> Iterator[str]:
    """The absolute names of every module the file's source imports (each package on the way)."""
    try:
        tree = ast.parse(path.read_bytes(), filename=str(path))
    except (OSError, SyntaxError, ValueError, RecursionError, MemoryError):
        return
    package = (module if is_package else module.rpartition(".")[0]) if module else ""
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield from _prefixes(alias.name)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".") if package else []
                if node.level - 1 > len(parts) or not package:
                    continue
                base = ".".join(parts[: len(parts) - (node.level - 1)])
                name = f"{base}.{node.module}" if node.module else base
            else:
                name = node.module or ""
            if not name:
                continue
            yield from _prefixes(name)
            for alias in node.names:  # `from pkg import helper` may name a module
                if alias.name != "*":
                    yield f"{name}.{alias.name}"


def _prefixes(name: str) -> Iterator[str]:
    parts = name.split(".")
    for i in range(1, len(parts) + 1):
        yield ".".join(parts[:i])


def own_code(module: str) -> tuple[Path, list[Path]] | None:
    """(root, files) of the plug-in whose factory lives in `module`: its top-level package's
    `.py` files (or its one file), and every module those import, transitively, from outside
    the installed environment; None when its source cannot be found. `root` is the folder the
    plug-in was imported from (files are named relative to it in the digest)."""
    start: list[tuple[Path, str | None, bool]]
    if module == "__main__":
        main = getattr(sys.modules.get("__main__"), "__file__", None)
        if not main:
            return None
        start = [(Path(main).resolve(), None, False)]
        root = start[0][0].parent
    else:
        top = module.split(".")[0]
        found = locate(top)
        if found is None:
            return None
        file, is_package = found
        if is_package:
            root = file.parent.parent
            start = [(p, _module_name(p, root), p.name == "__init__.py")
                     for p in _package_files(file.parent)]
        else:
            root = file.parent
            start = [(file, top, False)]
    seen = {p for p, _, _ in start}
    queue = list(start)
    while queue and len(seen) < MAX_FILES:
        path, name, is_package = queue.pop()
        for imported in _imported(path, name, is_package):
            where = locate(imported)
            if where is None or where[0] in seen or is_installed(where[0]):
                continue
            seen.add(where[0])
            queue.append((where[0], imported, where[1]))
    return root, sorted(seen)


def _module_name(path: Path, root: Path) -> str:
    parts = list(path.relative_to(root).with_suffix("").parts)
    if parts and parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)
