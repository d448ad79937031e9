"""Time to refuse hostile inputs (issues 20 and 27), against the time to accept a genuine one.

First, large but *valid* policies (issue 27, item 18): `tasks mutants` (mutant generation and
classification by simulation) on a generated correct BT of clean_living_room — its guarded
TidyToy/TidyBook trees inlined again and again (`big_correct_bt`; 48 copies = 53 KB, the
reported case) or its TidyToy Fallback given ever more alternatives (`wide_correct_bt`) — in a
fresh process each, with wall time and peak RSS, against the shipped 4 KB BT in the same run.
Line: `mutants_53KB_s=<float> mutants_53KB_MB=<float> shipped_s=<float>`.

Before both, houses and exports (issue 27, items 6, 14, 15; `house_cases`): GLB and ProcTHOR
export of 10k-50k-vertex rooms, import-house/check-house of houses with repeated ids, over the
object limit, or with 1,500 rooms, each a fresh process.
Line: `worst_house_s=<float> worst_house_rss_mb=<float>`.

Then each hostile file is generated here (nothing big is committed) and handed to the public
loader; the figure is the wall time until the clear error. The baseline is loading a real
benchmark policy and task, so a ratio near 1 means a hostile file costs no more than a normal one.
Line: `worst_refusal_ms=<float> baseline_ms=<float> ratio=<float>`.

Then the model-side cases of the third pass (issue 37, `llm_cases_round3`): a foreign service on
the managed llama.cpp server's port, bad `server=` values, unparseable and 100 kB `base_url`s, a
repeated model argument, replay packs that are a folder, an empty file or a table without a
`reply` column, arguments replay cannot use, preflight `GET /models` replies that drip or weigh
50 MB, a `--tasks` typo that must be reported before a server starts, deeply nested replies, and
`noisy:llamacpp:` with two workers (one server). Each is a fresh CLI process against the stand-in
servers of `tests/` and must give its documented exit code, no traceback, and leave its inputs as
they were. Line: `llm_round3: cases=<int> failures=<int> worst_s=<float>`.

Last, resource cases (issue 27) through the CLI, each in a fresh process (peak memory is the
process's and its workers' maximum resident set, from `wait4`): a plug-in returning 10,001
environments or a 50,000-object one, a generator that never returns (bounded by
`--unit-timeout 1`, in-process and in a worker that even ignores the alarm), a 3 GB sparse file
in an `evaluate` folder, `check-env /dev/zero`. The plug-ins are `tests/hostile_generators.py`
(well under 1 MB). The baseline is a normal one-environment run of the same plug-in module. Last line:
`resources: worst_seconds=<float> worst_peak_mb=<float> baseline_seconds=<float> ratio=<float>`.

Then issue 37's file and message cases (`io_cases`, defect classes 1, 5, 17-19, 22-25): every
writer aimed at a device node, a FIFO, a symlink to /proc/self/fd/1 and a read-only file of
another user; FIFOs and a socket as task, policy, run-folder and ProcTHOR database files; edited
results.json with impossible values; 1e300 coordinates; 120 kB inputs echoed; `lint` of nothing;
`simulate --env` of another task's environment. Each is a fresh CLI process with a 60 s deadline;
a case fails on another exit code than documented, a traceback, a hang, an error line over
4,000 characters, or a target changed. Last line:
`io: cases=<int> failures=<int> worst_seconds=<float>`.
Then round 3 (issue 37) — plug-in loading, `--generator-args`, numeric options, limits
(`plugin_cases`): each case a fresh CLI process that must give its documented exit code and
one line without a traceback within 60 s. Last line:
`plugins3: cases=<int> failures=<int> worst_seconds=<float>`.

Last, round 4 (issue 50, `round4_cases`): a server dripping its headers (preflight and chat),
a reply holding a lone surrogate, 400-digit integers in results.json and a house, symbolic links
inside a run folder on resume, `compare --html` of folders named `javascript:alert(1)` and
`x#y?z`, one-unit runs with two workers of a plug-in calling `os._exit(0)` or blocking SIGALRM,
80/300 roles and 200 constraints, a one-word quote, loose booleans, a secret in a `--debug`
traceback. Each a fresh CLI process with a 120 s deadline. Last line:
`round4: cases=<int> failures=<int> worst_seconds=<float>`.

`python benchmarks/hostile_inputs.py round3` runs only the third pass's three blocks;
`round4` only the fourth pass's; `--smoke` only the hostile-file block on inputs 1000x smaller
(seconds: the smoke test).
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import stat
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from logicenveval.benchmark import DEFAULT_TASKS_DIR, load_task_file
from logicenveval.errors import LogicEnvEvalError
from logicenveval.sim.loader import load_policy, policy_to_xml
from logicenveval.sim.policy import Policy, PolicyNode

TASK = "clean_living_room"


def fan_out(levels: int) -> str:
    trees = [f'<BehaviorTree ID="T{i}"><Sequence><SubTree ID="T{i + 1}"/><SubTree ID="T{i + 1}"/>'
             "</Sequence></BehaviorTree>" for i in range(levels)]
    return ('<root BTCPP_format="4" main_tree_to_execute="T0">' + "".join(trees)
            + f'<BehaviorTree ID="T{levels}"><AlwaysSuccess/></BehaviorTree></root>')


def big_correct_bt(copies: int) -> str:
    """clean_living_room's correct BT with its guarded TidyToy and TidyBook trees inlined
    `copies` more times before CleanMark: still correct (the copies find nothing to do), every
    copy is ticked, and each adds its own mutants (48 copies: 53 KB)."""
    p = load_policy(DEFAULT_TASKS_DIR / TASK / "policies" / "correct.xml")
    main = p.trees[p.main]
    extra = tuple(p.trees[t] for _ in range(copies) for t in ("TidyToy", "TidyBook"))
    root = PolicyNode(main.kind, main.params, (*main.children[:-1], *extra, main.children[-1]),
                      main.name)
    return policy_to_xml(Policy(p.main, {**p.trees, p.main: root}))


def wide_correct_bt(alternatives: int) -> str:
    """clean_living_room's correct BT whose TidyToy Fallback has `alternatives` copies of its
    IfThenElse (never reached after the first): one node with thousands of children."""
    p = load_policy(DEFAULT_TASKS_DIR / TASK / "policies" / "correct.xml")
    fb = p.trees["TidyToy"]
    kids = (fb.children[0], *(fb.children[1] for _ in range(alternatives)))
    return policy_to_xml(Policy(p.main, {**p.trees, "TidyToy": PolicyNode(fb.kind, fb.params, kids,
                                                                           fb.name)}))


def _measure(argv: list[str]) -> tuple[float, float, int]:
    """(seconds, peak RSS in MB, exit code) of one CLI call in a fresh process."""
    t0 = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "logicenveval", *argv], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    return time.perf_counter() - t0, usage.ru_maxrss / 1024, proc.returncode


def _mutants_run(tasks: Path) -> tuple[float, float]:
    """Seconds and peak MB of `tasks mutants --json` on a tasks folder, in a fresh process."""
    seconds, mb, code = _measure(["tasks", "mutants", "--json", "--tasks-dir", str(tasks)])
    if code != 0:
        raise SystemExit(f"tasks mutants failed on {tasks} (exit {code})")
    return seconds, mb


def large_correct_bts() -> None:
    print(f"{'valid large policy':<24} {'bytes':>12} {'mutants s':>10} {'peak MB':>8}")
    with tempfile.TemporaryDirectory() as tmp:
        results: dict[str, tuple[float, float]] = {}
        cases = {"shipped": None, **{f"copies_{k}": big_correct_bt(k) for k in (24, 48, 96, 192)},
                 **{f"alternatives_{k}": wide_correct_bt(k) for k in (100, 1000, 2000)}}
        for name, text in cases.items():
            tasks = Path(tmp) / name
            shutil.copytree(DEFAULT_TASKS_DIR / TASK, tasks / TASK)
            policy = tasks / TASK / "policies" / "correct.xml"
            if text is not None:
                policy.write_text(text)
            results[name] = _mutants_run(tasks)
            print(f"{name:<24} {policy.stat().st_size:>12} {results[name][0]:>10.2f} "
                  f"{results[name][1]:>8.0f}")
    big_s, big_mb = results["copies_48"]
    print(f"mutants_53KB_s={big_s:.2f} mutants_53KB_MB={big_mb:.0f} shipped_s={results['shipped'][0]:.2f}")


def _ms(fn: Callable[[], object], repeat: int = 5) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        with contextlib.suppress(LogicEnvEvalError):
            fn()
        times.append((time.perf_counter() - t0) * 1000)
    return statistics.median(times)


def main() -> None:
    house_cases()  # first: each case's peak RSS includes this process's pages at the fork
    large_correct_bts()
    refusals()
    llm_cases_round3()
    resources()
    io_cases()
    plugin_cases()
    round4_cases()


def refusals(scale: int = 1000) -> None:
    """The hostile-file block; `scale` divides the big inputs' sizes (1000: 50 MB files; 1 000 000
    with `--smoke`: the same loaders on 50 B-50 kB inputs, for the smoke test)."""
    folder = DEFAULT_TASKS_DIR / TASK
    task = json.loads((folder / "task.json").read_text())
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        files: dict[str, tuple[Path, Callable[[Path], object]]] = {}

        def add(name: str, text: str | bytes, loader: Callable[[Path], object], suffix: str) -> None:
            path = d / name / f"{TASK}{suffix}" if suffix == "" else d / f"{name}{suffix}"
            path.parent.mkdir(parents=True, exist_ok=True)
            (path.write_bytes if isinstance(text, bytes) else path.write_text)(text)  # type: ignore[operator]
            files[name] = (path, loader)

        for levels in (16, 18, 40):
            add(f"subtree_fan_out_{levels}", fan_out(levels), load_policy, ".xml")
        add("sequence_500_deep", '<root BTCPP_format="4"><BehaviorTree ID="M">' + "<Sequence>" * 500
            + "<AlwaysSuccess/>" + "</Sequence>" * 500 + "</BehaviorTree></root>", load_policy, ".xml")
        add("attribute_50MB", '<root BTCPP_format="4"><BehaviorTree ID="M"><Sequence name="'
            + "a" * (50_000 * scale) + '"/></BehaviorTree></root>', load_policy, ".xml")
        add("xml_utf16", (folder / "policies" / "correct.xml").read_text().encode("utf-16"), load_policy, ".xml")
        big = dict(task, description="There may be a toy on the floor. " * (1_500 * scale))
        (d / "desc" / TASK).mkdir(parents=True)
        (d / "desc" / TASK / "task.json").write_text(json.dumps(big))
        files["description_50MB"] = (d / "desc" / TASK / "task.json", load_task_file)
        paren = dict(task)
        paren["variables"] = dict(task["variables"])
        paren["variables"]["toy_on_floor"] = {"question": "?", "values": {
            "yes": "(" * (50 * scale) + "on(toy, floor)" + ")" * (50 * scale), "no": "not on(toy, floor)"}}
        (d / "paren" / TASK).mkdir(parents=True)
        (d / "paren" / TASK / "task.json").write_text(json.dumps(paren))
        files["parentheses_50k"] = (d / "paren" / TASK / "task.json", load_task_file)

        baseline = _ms(lambda: (load_task_file(folder / "task.json"),
                                load_policy(folder / "policies" / "correct.xml")))
        print(f"{'input':<24} {'bytes':>12} {'refused in ms':>14}")
        worst = 0.0
        for name, (path, loader) in files.items():
            ms = _ms(lambda p=path, f=loader: f(p), repeat=3)  # type: ignore[misc]
            worst = max(worst, ms)
            print(f"{name:<24} {path.stat().st_size:>12} {ms:>14.1f}")
    print(f"baseline (load one real task + policy): {baseline:.1f} ms")
    print(f"worst_refusal_ms={worst:.1f} baseline_ms={baseline:.1f} ratio={worst / baseline:.2f}")


TESTS = Path(__file__).resolve().parents[1] / "tests"


def _measured(argv: list[str], cwd: Path) -> tuple[float, float, int, str]:
    """Wall seconds, peak resident MB (the process and the workers it waited for), exit code,
    last line of stderr."""
    start = time.perf_counter()
    with tempfile.TemporaryFile("w+") as err:
        proc = subprocess.Popen([sys.executable, "-m", "logicenveval", *argv], cwd=cwd,
                                stdout=subprocess.DEVNULL, stderr=err, text=True)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
        seconds = time.perf_counter() - start
        err.seek(0)
        lines = [line for line in err.read().splitlines() if line.strip()]
    return seconds, usage.ru_maxrss / 1024, proc.returncode, (lines[-1] if lines else "")[:90]


def resources() -> None:
    task = "clean_living_room"
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        folder = d / "envs" / task
        folder.mkdir(parents=True)
        shutil.copy(TESTS / "fixtures" / "envs" / "one_room.json", folder / "good.json")
        with open(folder / "sparse.json", "wb") as fh:
            fh.truncate(3 * 1024**3)

        def run(gen: str, *extra: str) -> list[str]:
            return ["run", "--generators", f"hostile_generators:{gen}", "--tasks", task,
                    "--output", str(d / gen), "--quiet", *extra]

        cases = {
            "baseline: one normal env": run("WithArgs", "--executor", "inprocess"),
            "plug-in: 10,001 envs": run("Many", "--executor", "inprocess"),
            "plug-in: 50,000-object env": run("Huge", "--executor", "inprocess"),
            "never returns (inprocess)": run("Forever", "--executor", "inprocess", "--unit-timeout", "1"),
            "never returns, ignores alarm": run("Stubborn", "--executor", "process", "--workers", "2",
                                                "--tasks", f"{task},kitchen_fridge_restock",
                                                "--unit-timeout", "1"),
            "evaluate: 3 GB sparse file": ["evaluate", str(d / "envs"), "--name", "ext", "--output",
                                           str(d / "ev"), "--executor", "inprocess"],
            "check-env /dev/zero": ["check-env", "/dev/zero"],
        }
        print(f"\n{'resource case':<32} {'seconds':>8} {'peak MB':>8} {'exit':>5}  message")
        worst_s = worst_mb = base_s = 0.0
        for name, argv in cases.items():
            seconds, peak, code, message = _measured(argv, TESTS)
            if name.startswith("baseline"):
                base_s = seconds
            else:
                worst_s, worst_mb = max(worst_s, seconds), max(worst_mb, peak)
            print(f"{name:<32} {seconds:>8.2f} {peak:>8.0f} {code:>5}  {message}")
    print(f"resources: worst_seconds={worst_s:.2f} worst_peak_mb={worst_mb:.0f} "
          f"baseline_seconds={base_s:.2f} ratio={worst_s / base_s:.2f}")


def _comb(n: int) -> list[tuple[float, float]]:
    """A simple room polygon with `n` vertices: teeth of alternating height (tests/test_hostile_house)."""
    k = n // 4
    low = [p for i in range(k) for p in ((round(i * 0.1, 2), 0.0), (round(i * 0.1 + 0.05, 2), 0.0))]
    high = [p for i in reversed(range(k)) for p in ((round(i * 0.1 + 0.05, 2), 5.0 + (i % 2) * 0.3),
                                                   (round(i * 0.1, 2), 5.0 + (i % 2) * 0.3))]
    return low + high


def _house_with(objects: list[dict[str, object]], rooms: int = 1) -> dict[str, object]:
    """A ProcTHOR-layout house (tests/fixtures/houses/procthor10k_kitchen.json) with other rooms
    and objects."""
    house: dict[str, object] = json.loads((Path(__file__).resolve().parents[1] / "tests" / "fixtures"
                                           / "houses" / "procthor10k_kitchen.json").read_text())
    house["rooms"] = [{"id": f"room|{i}", "roomType": "Kitchen", "floorMaterial": {"name": "PureWhite"},
                       "floorPolygon": [{"x": x + 4 * i, "y": 0, "z": z} for x, z in ((0, 0), (0, 4), (4, 4), (4, 0))]}
                      for i in range(rooms)]
    house["walls"], house["doors"], house["windows"], house["objects"] = [], [], [], objects
    return house


def house_cases() -> None:
    """Issue 27 items 6, 14, 15: export, import-house and check-house of big inputs under 1 MB,
    each in a fresh process (its Python start-up included; its peak RSS includes the pages of the
    parent at the fork, so this runs before anything big is loaded). Prints one row per case and
    `worst_house_s=<float> worst_house_rss_mb=<float>` (targets: < 10 s, < 1024 MB)."""
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        cases: dict[str, tuple[Path, list[str]]] = {}
        for n in (10_000, 20_000, 50_000):
            env = {"task_id": "t", "env_id": "e", "rooms": [{"id": "living_room", "polygon": _comb(n)}]}
            path = d / f"room_{n}.json"
            path.write_text(json.dumps(env))
            cases[f"glb_room_{n // 1000}k_vertices"] = (path, ["export", str(path), "--format", "glb",
                                                               "--out", str(d / "o.glb")])
            cases[f"procthor_room_{n // 1000}k_vertices"] = (path, ["export", str(path), "--format",
                                                                    "procthor", "--out", str(d / "o.json")])
        obj = {"assetId": "Bread_1", "id": "Bread|2|0", "kinematic": False, "position": {"x": 1, "y": 1, "z": 1},
               "rotation": {"x": 0, "y": 0, "z": 0}, "layer": "Procedural1", "material": None}
        for name, objects, rooms in (("house_1990_same_ids", [obj] * 1990, 1),
                                     ("house_5000_objects_over_limit", [obj] * 5000, 1),
                                     ("house_1500_rooms", [obj] * 1500, 1500)):
            path = d / f"{name}.json"
            path.write_text(json.dumps(_house_with(objects, rooms)))
            cases[f"import_{name}"] = (path, ["import-house", str(path), "--task", "kitchen_breakfast_prep",
                                             "--out", str(d / "imported.json")])
            cases[f"check_{name}"] = (path, ["check-house", str(path)])
        worst_s = worst_mb = 0.0
        print(f"{'house/export case':<34} {'bytes':>9} {'s':>7} {'RSS MB':>8} {'exit':>5}")
        for name, (path, argv) in cases.items():
            seconds, mb, code = _measure(argv)
            worst_s, worst_mb = max(worst_s, seconds), max(worst_mb, mb)
            print(f"{name:<34} {path.stat().st_size:>9} {seconds:>7.2f} {mb:>8.0f} {code:>5}")
        print(f"worst_house_s={worst_s:.2f} worst_house_rss_mb={worst_mb:.0f}")


# ----- issue 37: special files, edited results, echoes (branch i37-io) -----------------------

def _fingerprint(path: Path) -> tuple[object, ...]:
    st = os.lstat(path)
    link = os.readlink(path) if stat.S_ISLNK(st.st_mode) else None
    data = path.read_bytes() if stat.S_ISREG(st.st_mode) else None
    return st.st_ino, st.st_mode, st.st_uid, link, data


def _io_targets(d: Path) -> dict[str, Path]:
    """Output targets a rename must not replace (the device only as root)."""
    out: dict[str, Path] = {}
    if os.geteuid() == 0:
        os.mknod(d / "dev", stat.S_IFCHR | 0o666, os.makedev(1, 3))
        out["device"] = d / "dev"
    os.mkfifo(d / "fifo")
    os.symlink("/proc/self/fd/1", d / "link")
    (d / "ro").write_text("another user's file\n")
    if os.geteuid() == 0:
        os.chown(d / "ro", 65534, 65534)
    (d / "ro").chmod(0o444)
    out.update(fifo=d / "fifo", symlink=d / "link", readonly=d / "ro")
    return out


def _io_run(argv: list[str], cwd: Path) -> tuple[float, int, str, bool]:
    """Seconds, exit code, stderr and whether it hung (killed at the deadline)."""
    start = time.perf_counter()
    try:
        proc = subprocess.run([sys.executable, "-m", "logicenveval", *argv], cwd=cwd, text=True,
                              capture_output=True, timeout=60)
    except subprocess.TimeoutExpired:
        return time.perf_counter() - start, -1, "", True
    return time.perf_counter() - start, proc.returncode, proc.stdout + proc.stderr, False


def io_cases() -> None:
    envs_fixture = TESTS / "fixtures" / "envs"
    house = TESTS / "fixtures" / "houses" / "procthor10k_kitchen.json"
    one_room = str(envs_fixture / "one_room.json")
    big = "a" * 120_000
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        cases: list[tuple[str, list[str], set[int], list[Path]]] = []
        writers = {
            "schema --out": lambda o: ["schema", "envspec", "--out", str(o)],
            "export glb": lambda o: ["export", one_room, "--format", "glb", "--out", str(o)],
            "export procthor": lambda o: ["export", one_room, "--format", "procthor", "--out", str(o)],
            "import-house": lambda o: ["import-house", str(house), "--task", "kitchen_breakfast_prep",
                                       "--env-id", "k", "--out", str(o)],
        }
        for wname, argv in writers.items():
            folder = d / f"out_{len(cases)}"
            folder.mkdir()
            for kind, target in _io_targets(folder).items():
                cases.append((f"{wname} -> {kind}", argv(target), {2}, [target]))
        svg = d / "svg"
        svg.mkdir()
        os.mkfifo(svg / "r.svg")
        cases.append(("check-env --render -> fifo", ["check-env", one_room, "--render", str(svg / "r.svg")],
                      {2}, [svg / "r.svg"]))
        # inputs that are not regular files
        tasks = d / "tasks"
        for member in ("task.json", "policies/correct.xml"):
            folder = tasks / member.replace("/", "_")
            shutil.copytree(DEFAULT_TASKS_DIR / TASK, folder / TASK)
            (folder / TASK / member).unlink()
            os.mkfifo(folder / TASK / member)
            cases.append((f"tasks validate, {member} fifo", ["tasks", "validate", "--tasks-dir", str(folder)],
                          {1, 2}, [folder / TASK / member]))
        db = d / "db"
        db.mkdir()
        for name in ("asset-database.json", "material-database.json", "wall-holes.json"):
            os.mkfifo(db / name)
        cases.append(("check-house --procthor-db fifos", ["check-house", str(house), "--procthor-db", str(db)],
                      {2}, []))
        cases.append(("check-env /dev/zero", ["check-env", "/dev/zero"], {2}, []))
        # a scored run folder: FIFOs in it, edited results
        (d / "envs" / TASK).mkdir(parents=True)
        shutil.copy(envs_fixture / "one_room.json", d / "envs" / TASK / "one_room.json")
        evaluate = ["evaluate", str(d / "envs"), "--name", "ext", "--output", str(d / "scored"),
                    "--run-id", "r", "--executor", "inprocess"]
        _io_run(evaluate, TESTS)
        run = d / "scored" / "r"
        for member in ("config.json", "units/ext/clean_living_room.json"):
            copy = d / f"scored_{member[:5]}"
            shutil.copytree(d / "scored", copy)
            (copy / "r" / member).unlink()
            os.mkfifo(copy / "r" / member)
            cases.append((f"resume, {member.split('/')[0]} fifo",
                          [*evaluate[:5], str(copy), *evaluate[6:]], {2}, [copy / "r" / member]))
        fifo_run = d / "fifo_results"
        fifo_run.mkdir()
        os.mkfifo(fifo_run / "results.json")
        cases.append(("compare, results.json fifo", ["compare", str(run), str(fifo_run)], {2}, []))
        data = json.loads((run / "results.json").read_text())
        edits: dict[str, Callable[[dict[str, Any]], object]] = {
            "LogCov 750 %": lambda r: r["results"]["ext"].update(logcov=7.5),
            "lo > hi": lambda r: r["results"]["ext"]["ci95"].update(ji=[0.9, 0.1]),
            "n_failed > n_attempted": lambda r: r["results"]["ext"].update(n_failed=10**6),
            "unknown row": lambda r: r["results"].update(ghost=r["results"]["ext"]),
            "generators twice": lambda r: r.update(generators=["ext", "ext"]),
        }
        for name, edit in edits.items():
            copy = d / f"edited_{len(cases)}"
            shutil.copytree(run, copy)
            edited = json.loads(json.dumps(data))
            edit(edited)
            (copy / "results.json").write_text(json.dumps(edited))
            cases.append((f"report, {name}", ["report", str(copy)], {2}, [copy / "leaderboard.md"]))
        huge = json.loads((envs_fixture / "one_room.json").read_text())
        huge["objects"][0]["position"] = [1e300, 0.4, 3.5]
        (d / "huge.json").write_text(json.dumps(huge))
        cases.append(("export glb, 1e300 coordinates", ["export", str(d / "huge.json"), "--format", "glb",
                                                         "--out", str(d / "huge.glb")], {2}, []))
        for name, argv in (("tasks show", ["tasks", "show", big]), ("schema NAME", ["schema", big]),
                           ("check-env PATH", ["check-env", f"/tmp/{big}"]),
                           ("run --tasks", ["run", "--tasks", big, "--quiet"])):
            cases.append((f"120 kB echo: {name}", argv, {2}, []))
        (d / "lint" / TASK).mkdir(parents=True)
        cases.append(("lint of no EnvSpec", ["lint", str(d / "lint")], {2}, []))
        cases.append(("simulate --env of another task", ["simulate", "--task", "kitchen_fridge_restock",
                                                          "--policy", "correct", "--env", one_room], {2}, []))
        print(f"\n{'io case (issue 37)':<44} {'seconds':>8} {'exit':>5} {'ok':>3}  message")
        failures = 0
        worst = 0.0
        for name, argv, codes, kept in cases:
            before = [_fingerprint(p) for p in kept]
            seconds, code, text, hung = _io_run(argv, TESTS)
            lines = [ln for ln in text.splitlines() if ln.strip()]
            ok = (not hung and code in codes and "Traceback" not in text and len(text) < 4000
                  and [_fingerprint(p) for p in kept] == before)
            failures += not ok
            worst = max(worst, seconds)
            print(f"{name[:44]:<44} {seconds:>8.2f} {code:>5} {'yes' if ok else 'NO':>3}  "
                  f"{(lines[-1] if lines else '')[:70]}")
    print(f"io: cases={len(cases)} failures={failures} worst_seconds={worst:.2f}")


# ----- issue 37, model side: managed server, replay packs, model arguments -------------------------

def llm_cases_round3() -> None:
    """Each case: a fresh CLI process; (exit code, no traceback, inputs unchanged) as documented."""
    import hashlib
    import sqlite3

    sys.path.insert(0, str(TESTS))
    from loopback import Loopback

    fake = TESTS / "data" / "fake_llama_server.py"
    with tempfile.TemporaryDirectory() as tmp, Loopback() as other, \
            Loopback(get_mode="drip", trickle_s=0.5) as drip, Loopback(get_mode="huge") as huge, \
            Loopback(modes=["deep"]) as deep:
        d = Path(tmp)
        gguf = d / "model.gguf"
        gguf.write_bytes(b"GGUF" + bytes(60))
        empty = d / "empty.sqlite"
        empty.touch()
        cut = d / "cut.sqlite"
        with contextlib.closing(sqlite3.connect(cut)) as conn:
            conn.execute("CREATE TABLE replies (key TEXT, provider TEXT, model TEXT, kind TEXT)")
            conn.commit()
        pack = d / "pack.sqlite"
        shutil.copy(Path(__file__).resolve().parents[1] / "reports" / "real" / "stability" / "llm_cache.sqlite",
                    pack)
        inputs = {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in (gguf, empty, cut, pack)}
        starts = d / "starts.txt"
        port = other.url.split(":")[2].split("/")[0]

        def run(model: str, args: str, *extra: str, tasks: str = TASK, executor: str = "inprocess",
                out: str = "out") -> list[str]:
            return ["run", "--model", model, "--model-args", args, "--tasks", tasks, "--generators",
                    "holodeck", "--executor", executor, "--output", str(d / out), "--quiet", *extra]

        llama = f"llamacpp:{gguf}"
        cases: dict[str, tuple[list[str], int]] = {
            "foreign_service_on_port": (run(llama, f"server={fake},port={port}"), 2),
            "server_123": (run(llama, "server=123"), 2),
            "server_true": (run(llama, "server=true"), 2),
            "base_url_two_ports": (run("openai:m", "base_url=http://h:1:2"), 2),
            "base_url_100kB": (run("openai:m", "base_url=http://" + "a" * 100_000), 2),
            "repeated_model_arg": (run("openai:m", "timeout=5,timeout=50"), 2),
            "replay_a_folder": (run(f"replay:{d}", ""), 2),
            "replay_empty_file": (run(f"replay:{empty}", ""), 2),
            "replay_no_reply_column": (run(f"replay:{cut}", ""), 2),
            "replay_with_timeout_arg": (run(f"replay:{pack}", "timeout=5"), 2),
            "preflight_drip": (run("openai:m", f"base_url={drip.url}"), 2),
            "preflight_50MB": (run("openai:m", f"base_url={huge.url}"), 2),
            "tasks_typo_before_server": (run(llama, f"server={fake}", tasks="clean_livng_room"), 2),
            "deeply_nested_replies": (run("openai:m", f"base_url={deep.url},max_retries=0", "--no-cache"), 1),
            "noisy_llamacpp_2_workers": (run(f"noisy:llamacpp:{gguf}", f"server={fake},threads=1,rate=0.2",
                                             "--workers", "2", executor="process", out="noisy"), 1),
        }
        os.environ["FAKE_LLAMA_STARTS"] = str(starts)
        failures, worst = 0, 0.0
        print(f"{'model-side case (issue 37)':<28} {'s':>6} {'exit':>5} {'ok':>3}  last line")
        try:
            for name, (argv, expected) in cases.items():
                start = time.perf_counter()
                proc = subprocess.run([sys.executable, "-m", "logicenveval", *argv], cwd=TESTS,
                                      capture_output=True, text=True, timeout=600)
                seconds = time.perf_counter() - start
                worst = max(worst, seconds)
                lines = [line for line in proc.stderr.splitlines() if line.strip()]
                ok = proc.returncode == expected and "Traceback" not in proc.stdout + proc.stderr
                if name == "tasks_typo_before_server":
                    ok = ok and not starts.exists()
                if name == "noisy_llamacpp_2_workers":
                    ok = ok and len(starts.read_text().splitlines()) == 1
                failures += not ok
                print(f"{name:<28} {seconds:>6.2f} {proc.returncode:>5} {'yes' if ok else 'NO':>3}  "
                      f"{(lines[-1] if lines else '')[:80]}")
        finally:
            os.environ.pop("FAKE_LLAMA_STARTS", None)
        changed = [p.name for p, h in inputs.items() if hashlib.sha256(p.read_bytes()).hexdigest() != h]
        failures += len(changed)
        if changed:
            print(f"inputs changed: {changed}")
    print(f"llm_round3: cases={len(cases)} failures={failures} worst_s={worst:.2f}")


# ----- round 3 (issue 37): plug-in loading, --generator-args, numeric options, limits ---------

#: module -> source of a plug-in that cannot be loaded (each refused with exit 2)
BROKEN_PLUGINS = {
    "syntax_error": "class G:\n    name = 'g'\n  def x(\n",
    "raises_at_import": "raise RuntimeError('boom at import')\n",
    "exits_0": "import sys\nsys.exit(0)\n",
    "exits_3": "import sys\nsys.exit(3)\n",
    "getattr_raises": "def __getattr__(name):\n    raise RuntimeError('no ' + name)\n",
    "name_raises": "class G:\n    @property\n    def name(self):\n        raise ValueError('bad')\n"
                   "    def generate(self, brief, ctx):\n        pass\n",
    "missing_dependency": "import no_such_dependency_xyz\n",
    "hangs": "import time\nclass G:\n    name = 'hangs'\n    def __init__(self):\n"
             "        while True:\n            time.sleep(0.05)\n",
}
NAMED_PLUGIN = ("from logicenveval.generators.base import GenerationResult\n"
                "class G:\n    def __init__(self, name='named', n=1):\n        self.name = name\n"
                "    def generate(self, brief, ctx):\n        return GenerationResult(envs=[])\n")


def plugin_cases() -> None:
    """Issue 37 classes 4, 8, 9, 13, 16, 21: every case one line, its exit code, no traceback."""
    task = "clean_living_room"
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        for name, source in BROKEN_PLUGINS.items():
            (d / f"{name}.py").write_text(source)
        (d / "named.py").write_text(NAMED_PLUGIN)

        def run(gen: str, *extra: str) -> list[str]:
            return ["run", "--generators", gen, "--tasks", task, "--executor", "inprocess",
                    "--output", str(d / "out"), "--quiet", *extra]

        #: name -> (argv, extra environment, expected exit code, words of the message)
        cases: dict[str, tuple[list[str], dict[str, str], int, str]] = {
            f"plug-in {m}": (run(f"{m}:G", "--unit-timeout", "2"), {}, 2,
                             "not made within 2 s" if m == "hangs" else f"{m}.py:")
            for m in BROKEN_PLUGINS}
        cases |= {
            "plug-in .relative:G": (run(".named:G"), {}, 2, "relative module"),
            "generator-args name=": (run("named:G", "--generator-args", "named:G:name=x,n=1"), {}, 1,
                                     "x: 0 of 1 unit(s) failed"),  # made: the row is `x`
            "generator-args twice": (run("named:G", "--generator-args", "named:G:n=2",
                                         "--generator-args", "named:n=3"), {}, 2, "row name"),
            "generator-args typo": (run("named:G", "--generator-args", "nmaed:n=3"), {}, 2,
                                    "not in --generators"),
            "--unit-timeout 5e9": (run("named:G", "--unit-timeout", "5e9"), {}, 2, "a week"),
            "--limit 10^7": (run("named:G", "--limit", "10000000"), {}, 2, "out of range"),
            "--max-infra-failures 10^20": (run("named:G", "--max-infra-failures", "1" + "0" * 20),
                                           {}, 2, "out of range"),
            "simulate --tick-limit 10^9": (["simulate", "--task", task, "--policy", "correct",
                                            "--tick-limit", "1000000000"], {}, 2, "out of range"),
            "LOGICENVEVAL_MAX_WORKERS=abc": (run("named:G", "--workers", "2"),
                                             {"LOGICENVEVAL_MAX_WORKERS": "abc"}, 2, "not an integer"),
            "LOGICENVEVAL_MAX_ENV_OBJECT (typo)": (run("named:G"), {"LOGICENVEVAL_MAX_ENV_OBJECT": "9"},
                                                   2, "names no limit"),
        }
        print(f"\n{'round 3 case':<36} {'seconds':>8} {'exit':>5}  message")
        failures = 0
        worst = 0.0
        for name, (argv, env, expected, words) in cases.items():
            start = time.perf_counter()
            try:
                proc = subprocess.run([sys.executable, "-m", "logicenveval", *argv], cwd=d,
                                      capture_output=True, text=True, timeout=60,
                                      env={**os.environ, **env})
                code, err = proc.returncode, proc.stderr
            except subprocess.TimeoutExpired:
                code, err = -1, "hung (no answer within 60 s)"
            seconds = time.perf_counter() - start
            worst = max(worst, seconds)
            lines = [line for line in err.splitlines() if line.strip()]
            ok = code == expected and "Traceback" not in err and words in err and \
                (expected != 2 or len(lines) == 1 or lines[0].startswith("usage:"))  # argparse's
            failures += not ok
            print(f"{name:<36} {seconds:>8.2f} {code:>5}  {'' if ok else 'FAILED '}"
                  f"{(lines[-1] if lines else '')[:90]}")
    print(f"plugins3: cases={len(cases)} failures={failures} worst_seconds={worst:.2f}")


# ----- round 4 (issue 50): dripping headers, huge integers, links, isolation, task bounds -----

def _edited_task(root: Path, edit: Callable[[dict[str, Any]], None]) -> Path:
    """A tasks folder holding clean_living_room with its task.json edited."""
    shutil.copytree(DEFAULT_TASKS_DIR / TASK, root / TASK)
    path = root / TASK / "task.json"
    data = json.loads(path.read_text())
    edit(data)
    path.write_text(json.dumps(data))
    return root


def _tree(root: Path) -> list[tuple[str, int]]:
    return sorted((p.relative_to(root).as_posix(), p.stat().st_size)
                  for p in root.rglob("*") if p.is_file())


def round4_cases() -> None:
    """Issue 50 classes 1, 5-13: each case a fresh CLI process that must give its documented
    exit code, no traceback and the words of its message within 120 s, and leave the targets of
    links and the folders outside the output untouched (`check`)."""
    sys.path.insert(0, str(TESTS))
    from hostile_generators4 import SECRET
    from loopback import Loopback

    reference = Path(__file__).resolve().parents[1] / "reports" / "reference"
    with tempfile.TemporaryDirectory() as tmp, \
            Loopback(get_mode="dripheaders", trickle_s=1.0) as drip_get, \
            Loopback(modes=["dripheaders"], trickle_s=1.0) as drip_post, \
            Loopback(modes=["surrogate"]) as surrogate:
        d = Path(tmp)
        checks: dict[str, Callable[[], bool]] = {}

        def run(*argv: str, out: str = "out") -> list[str]:
            return ["run", *argv, "--output", str(d / out), "--quiet"]

        # run folders: a reference copy with a 400-digit integer; a plug-in run whose
        # sub-folders are made symbolic links to folders outside the output
        huge = d / "huge"
        shutil.copytree(reference, huge, ignore=shutil.ignore_patterns("envs", "renders", "units"))
        data = json.loads((huge / "results.json").read_text())
        data["results"]["cot"]["faudr"]["avg"] = 10**400
        (huge / "results.json").write_text(json.dumps(data))
        house = json.loads((TESTS / "fixtures" / "houses" / "kitchen_breakfast.json").read_text())
        house["objects"][0]["position"]["x"] = 10**400
        (d / "house.json").write_text(json.dumps(house))
        plug = ["--generators", "hostile_generators:WithArgs", "--tasks", TASK, "--executor",
                "inprocess", "--run-id", "r"]
        subprocess.run([sys.executable, "-m", "logicenveval", *run(*plug, out="base")], cwd=TESTS,
                       capture_output=True, check=True)
        for inside in ("units/with-args", "envs/with-args", "details"):
            name = inside.replace("/", "_")
            shutil.copytree(d / "base", d / name)
            target = d / f"target_{name}"
            target.mkdir()
            shutil.rmtree(d / name / "r" / inside)
            (d / name / "r" / inside).symlink_to(target, target_is_directory=True)
            checks[f"symlinked {inside} on resume"] = lambda t=target: not any(t.iterdir())
        for name in ("javascript:alert(1)/A", "x#y?z/B"):
            shutil.copytree(reference, d / name, ignore=shutil.ignore_patterns("envs", "renders"))

        def safe_links() -> bool:
            html = (d / "page.html").read_text()
            hrefs = [h.split('"')[0] for h in html.split('href="')[1:]]
            return bool(hrefs) and all(":" not in h.split("/")[0] and "#" not in h and "?" not in h
                                       for h in hrefs)
        checks["compare --html javascript: folder"] = safe_links
        roles80 = _edited_task(d / "roles80", lambda t: t["roles"].update(
            {f"extra_{i}": {"category": "book", "optional": True} for i in range(80)}))
        roles300 = _edited_task(d / "roles300", lambda t: t["roles"].update(
            {f"extra_{i}": {"category": "book", "optional": True} for i in range(300)}))
        cons = _edited_task(d / "cons", lambda t: t.update(constraints=t["constraints"][:1] * 200))
        the = _edited_task(d / "the", lambda t: t["constraints"][0].update(says="the"))
        yes = _edited_task(d / "yes", lambda t: t["roles"]["toy"].update(optional="yes"))
        one = _edited_task(d / "one", lambda t: t["roles"]["toy"].update(optional=1))

        def validate(folder: Path) -> list[str]:
            return ["tasks", "validate", "--tasks-dir", str(folder)]

        #: name -> (argv, expected exit code, words of stderr (stdout for `tasks validate`))
        cases: dict[str, tuple[list[str], int, str]] = {
            "preflight, headers drip": (run("--model", "openai:m", "--model-args",
                                            f"base_url={drip_get.url}", "--generators", "cot",
                                            "--tasks", TASK), 2, "no complete reply in time"),
            "chat, headers drip (timeout=5)": (run(
                "--model", "openai:m", "--model-args", f"base_url={drip_post.url},timeout=5",
                "--generators", "cot", "--tasks", TASK, "--brief", "description",
                "--unit-timeout", "20", "--workers", "1"), 1, "request"),
            "reply with a lone surrogate": (run(
                "--model", "openai:m", "--model-args", f"base_url={surrogate.url}", "--generators",
                "cot", "--tasks", TASK, "--brief", "roles", "--workers", "1", out="sur"), 1,
                "stayed invalid after 3 attempt(s)"),
            "results.json 400 digits: report": (["report", str(huge)], 2, "out of range"),
            "results.json 400 digits: compare": (["compare", str(reference), str(huge)], 2,
                                                 "out of range"),
            "house 400 digits: import-house": (["import-house", str(d / "house.json"), "--task",
                                                "kitchen_breakfast_prep", "--out",
                                                str(d / "env.json")], 2, "out of range"),
            **{f"symlinked {inside} on resume": (run(*plug, out=inside.replace("/", "_")), 2,
                                                 "is a symbolic link")
               for inside in ("units/with-args", "envs/with-args", "details")},
            "compare --html javascript: folder": (["compare", "javascript:alert(1)/A", "x#y?z/B",
                                                   "--html", "page.html"], 0, ""),
            "one unit, workers 2, os._exit(0)": (run(
                "--generators", "hostile_generators4:ExitsQuietly", "--tasks", TASK, "--workers",
                "2", out="exit0"), 1, "exited with status 0"),
            "one unit, workers 2, blocks SIGALRM": (run(
                "--generators", "hostile_generators:Stubborn", "--tasks", TASK, "--workers", "2",
                "--unit-timeout", "5", out="alarm"), 1, "ignored its time bound"),
            "80 optional roles: validate": (validate(roles80), 1, "more than the limit of 48"),
            "300 roles: one-unit run": (run("--tasks-dir", str(roles300), "--generators", "cot",
                                            "--tasks", TASK, out="r300"), 2, "limit of 48"),
            "200 constraints: validate": (validate(cons), 1, "more than the limit of 64"),
            "says 'the': validate": (validate(the), 1, "content words"),
            "optional 'yes': validate": (validate(yes), 1, "without quotes"),
            "optional 1: validate": (validate(one), 1, "without quotes"),
            "--debug, secret in exception": (run(
                "--generators", "hostile_generators4:LeaksSecret", "--tasks", TASK, "--debug",
                out="debug"), 1, "RuntimeError: request failed"),
        }

        def not_internal() -> bool:  # an invalid reply is a measurement, not a harness bug
            (results,) = list((d / "sur").glob("*/results.json"))
            failures = json.loads(results.read_text())["failures"]
            return bool(failures) and '"internal"' not in json.dumps(failures)
        checks["reply with a lone surrogate"] = not_internal
        outside = _tree(d / "base")
        print(f"\n{'round 4 case (issue 50)':<38} {'seconds':>8} {'exit':>5}  message")
        failures, worst = 0, 0.0
        for name, (argv, expected, words) in cases.items():
            start = time.perf_counter()
            try:
                proc = subprocess.run([sys.executable, "-m", "logicenveval", *argv], cwd=TESTS
                                      if "compare --html" not in name else d, capture_output=True,
                                      text=True, timeout=120)
                code, text = proc.returncode, proc.stderr + proc.stdout
            except subprocess.TimeoutExpired:
                code, text = -1, "hung (no answer within 120 s)"
            seconds = time.perf_counter() - start
            worst = max(worst, seconds)
            traceback_ok = "Traceback" not in text or name.startswith("--debug")
            ok = code == expected and traceback_ok and words in text and SECRET not in text \
                and checks.get(name, lambda: True)()
            failures += not ok
            lines = [line for line in proc.stderr.splitlines() if line.strip()] if code != -1 else [text]
            print(f"{name:<38} {seconds:>8.2f} {code:>5}  {'' if ok else 'FAILED '}"
                  f"{(lines[-1] if lines else '')[:90]}")
        if _tree(d / "base") != outside:
            failures += 1
            print("FAILED: the run folder the links were copied from changed")
    print(f"round4: cases={len(cases)} failures={failures} worst_seconds={worst:.2f}")


if __name__ == "__main__":
    if sys.argv[1:] == ["round4"]:  # only the fourth pass's cases (issue 50)
        round4_cases()
    elif sys.argv[1:] == ["round3"]:  # only the third pass's cases (issue 37)
        io_cases()
        llm_cases_round3()
        plugin_cases()
    elif sys.argv[1:] == ["io"]:
        io_cases()
    elif sys.argv[1:] == ["--smoke"]:  # tests/test_benchmarks_smoke.py: the refusal block, small inputs
        refusals(scale=1)
    else:
        main()
