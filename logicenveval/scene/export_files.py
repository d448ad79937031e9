"""Export files next to environments: `<env>.house.json` (ProcTHOR/AI2-THOR) and `<env>.glb`.

Used by the `export` command and by `run --export`, which writes them for every environment of a
run (skipping files already written, so a resumed run does not redo them). Every file is written
to a temporary file and renamed (`write_output`): a full disk or a killed process leaves the old
file, never a truncated one.
"""

from __future__ import annotations

import json
from pathlib import Path

from logicenveval.atomic import RESOURCE_ERRNOS, atomic_write_bytes
from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.envfiles import load_env
from logicenveval.errors import ConfigError, EnvSpecError, LogicEnvEvalError
from logicenveval.limits import read_text
from logicenveval.model.envspec import ENV_SCHEMA

SUFFIX = {"procthor": ".house.json", "glb": ".glb"}


def write_output(out: Path, data: str | bytes, *, what: str = "output file",
                 field: str = "--out") -> None:
    """Write `data` to `out` atomically (missing folders are made); a path that cannot be
    written is one message naming the file, and whatever was at `out` stays as it was."""
    if out.is_dir():
        raise ConfigError(f"the {what} is a folder", file=str(out), field=field,
                          hint=f"give a file name inside it, e.g. {out / 'out'}{_example(what)}")
    try:
        atomic_write_bytes(out, data.encode("utf-8") if isinstance(data, str) else data)
    except OSError as exc:
        if exc.errno in RESOURCE_ERRNOS:
            raise  # the machine failed the work (a full disk): the CLI names the file, exit 1
        raise ConfigError(f"cannot write the {what}: {exc.strerror or exc}", file=str(out), field=field,
                          hint="choose a writable path whose folders are folders, on a disk with "
                          "free space (nothing was changed there)") from None


def _example(what: str) -> str:
    return ".glb" if "glb" in what else ".xml" if "Groot" in what else ".json"


def export_env(env_path: Path, fmt: str, out: Path, catalog: Catalog | str | None = None) -> None:
    from logicenveval.scene.export import to_glb, to_procthor

    if fmt not in SUFFIX:
        raise ConfigError(f"unknown export format {fmt!r}", field="--export",
                          hint=f"use {', '.join(SUFFIX)}")
    env = load_env(env_path)
    if fmt == "glb":
        data: str | bytes = to_glb(env)
    else:
        cat = catalog if isinstance(catalog, Catalog) else load_catalog(catalog)
        # compact: the indenting encoder is pure Python, 4x slower on a big house
        data = json.dumps(to_procthor(env, cat), separators=(",", ":"), allow_nan=False) + "\n"
    write_output(out, data, what=f"{fmt} export")


def export_run(run_dir: Path, formats: list[str], catalog: Catalog | None = None) -> list[Path]:
    """Write each format next to every environment JSON under `run_dir/envs`; returns new files."""
    cat = catalog or load_catalog()
    written = []
    for env_path in sorted((run_dir / "envs").rglob("*.json")):
        if env_path.name.endswith(".house.json") or not _is_env(env_path):
            continue
        for fmt in formats:
            out = env_path.with_name(env_path.stem + SUFFIX[fmt])
            if not out.exists():
                export_env(env_path, fmt, out, cat)
                written.append(out)
    return written


def _is_env(path: Path) -> bool:
    """An EnvSpec file (the env folders also hold each unit's plan.json); a file that is not
    one — not JSON, not UTF-8, too big, a FIFO put there — is not exported, never a crash."""
    try:
        data = json.loads(read_text(path, what="environment file", error=EnvSpecError,
                                    max_bytes="max_env_bytes", hint="not exported"))
        return isinstance(data, dict) and data.get("schema") == ENV_SCHEMA
    except (LogicEnvEvalError, ValueError, RecursionError):
        return False


def write_bt_model(out: Path) -> None:
    from logicenveval.sim.groot import tree_nodes_model

    write_output(out, '<?xml version="1.0" encoding="UTF-8"?>\n<root BTCPP_format="4">\n'
                 + tree_nodes_model() + "</root>\n", what="Groot2 model")
