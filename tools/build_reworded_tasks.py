"""Write the reworded built-in tasks of the reader's test sets as complete task folders.

A set is a folder under `tests/data/`: the development set `reader_dev` (the default), the
held-out set `reader_holdout`, the second unseen set `reader_dev3`, the fourth development set `reader_dev4`, the second
held-out set `reader_holdout2`, the fifth development set `reader_dev5`, the sixth development set `reader_dev6`, the seventh
development set `reader_dev7`, the eighth development set `reader_dev8`, the ninth development set `reader_dev9`, the
tenth development set `reader_dev10`, the eleventh development set `reader_dev11`, the twelfth development set
`reader_dev12`, the thirteenth `reader_dev13`, the fourteenth `reader_dev14`, the fifteenth `reader_dev15`, the sixteenth `reader_dev16`, the seventeenth `reader_dev17`, the eighteenth `reader_dev18`, the nineteenth `reader_dev19`, the twentieth `reader_dev20`, the twenty-first `reader_dev21`, the twenty-second `reader_dev22`, the twenty-third `reader_dev23`, the twenty-fourth `reader_dev24` or the twenty-fifth `reader_dev25`, the twenty-sixth `reader_dev26`, the twenty-seventh `reader_dev27`, the twenty-eighth `reader_dev28`, the twenty-ninth `reader_dev29`, the thirtieth `reader_dev30`, the thirty-first `reader_dev31`, the thirty-second `reader_dev32`, the thirty-third `reader_dev33`, the thirty-fourth `reader_dev34`, the thirty-fifth `reader_dev35`, the thirty-sixth `reader_dev36`, the thirty-seventh `reader_dev37`, the thirty-eighth `reader_dev38`, the thirty-ninth `reader_dev39`, the fortieth `reader_dev40`, the forty-first `reader_dev41`, the forty-second `reader_dev42`, the forty-third `reader_dev43`, the forty-fourth `reader_dev44`, the forty-fifth `reader_dev45`, the forty-sixth `reader_dev46`, the forty-seventh `reader_dev47`, the forty-eighth `reader_dev48`, the forty-ninth `reader_dev49`, the fiftieth `reader_dev50`, the fifty-first `reader_dev51`, the fifty-second `reader_dev52`, the fifty-third `reader_dev53`, the fifty-fourth `reader_dev54`, the fifty-fifth `reader_dev55`, the fifty-sixth `reader_dev56`, the fifty-seventh `reader_dev57`, the fifty-eighth `reader_dev58`. Its `rewordings.json` holds each rewording once: its new task id, the built-in
task it rewords, its register, the new description and, for every constraint fact of the
original, the words of the new description that assert it (`says` must quote the description,
docs/task-format.md). A task's policies must lie inside its own folder (`benchmark.policy_path`),
so each folder gets a copy of the original's four BTs; `tests/test_reader_dev_data.py` and
`tests/test_reader_holdout_data.py`, `tests/test_reader_dev3_data.py`, `tests/test_reader_dev4_data.py`,
`tests/test_reader_holdout2_data.py` and `tests/test_reader_later_dev_sets_data.py` check
that every copy still equals its original and that
nothing but `id`, `description` and the constraints' `says` differs.

    python tools/build_reworded_tasks.py            # (re)write tests/data/reader_dev/tasks_reworded/
    python tools/build_reworded_tasks.py --set reader_holdout   # the held-out set's folders
    python tools/build_reworded_tasks.py --set reader_dev3      # the second unseen set's folders
    python tools/build_reworded_tasks.py --set reader_dev4      # the fourth development set's folders
    python tools/build_reworded_tasks.py --set reader_holdout2  # the second held-out set's folders
    python tools/build_reworded_tasks.py --set reader_dev5      # the fifth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev6      # the sixth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev7      # the seventh development set's folders
    python tools/build_reworded_tasks.py --set reader_dev8      # the eighth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev9      # the ninth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev10     # the tenth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev11     # the eleventh development set's folders
    python tools/build_reworded_tasks.py --set reader_dev12     # the twelfth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev13     # the thirteenth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev14     # the fourteenth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev15     # the fifteenth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev16     # the sixteenth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev17     # the seventeenth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev18     # the eighteenth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev19     # the nineteenth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev20     # the twentieth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev21     # the twenty-first development set's folders
    python tools/build_reworded_tasks.py --set reader_dev22     # the twenty-second development set's folders
    python tools/build_reworded_tasks.py --set reader_dev23     # the twenty-third development set's folders
    python tools/build_reworded_tasks.py --set reader_dev24     # the twenty-fourth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev25     # the twenty-fifth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev26     # the twenty-sixth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev27     # the twenty-seventh development set's folders
    python tools/build_reworded_tasks.py --set reader_dev28     # the twenty-eighth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev29     # the twenty-ninth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev30     # the thirtieth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev32     # the thirty-second development set's folders
    python tools/build_reworded_tasks.py --set reader_dev33     # the thirty-third development set's folders
    python tools/build_reworded_tasks.py --set reader_dev34     # the thirty-fourth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev35     # the thirty-fifth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev36     # the thirty-sixth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev37     # the thirty-seventh development set's folders
    python tools/build_reworded_tasks.py --set reader_dev38     # the thirty-eighth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev39     # the thirty-ninth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev40     # the fortieth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev41     # the forty-first development set's folders
    python tools/build_reworded_tasks.py --set reader_dev42     # the forty-second development set's folders
    python tools/build_reworded_tasks.py --set reader_dev43     # the forty-third development set's folders
    python tools/build_reworded_tasks.py --set reader_dev44     # the forty-fourth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev45     # the forty-fifth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev46     # the forty-sixth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev47     # the forty-seventh development set's folders
    python tools/build_reworded_tasks.py --set reader_dev48     # the forty-eighth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev49     # the forty-ninth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev50     # the fiftieth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev51     # the fifty-first development set's folders
    python tools/build_reworded_tasks.py --set reader_dev52     # the fifty-second development set's folders
    python tools/build_reworded_tasks.py --set reader_dev53     # the fifty-third development set's folders
    python tools/build_reworded_tasks.py --set reader_dev54     # the fifty-fourth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev55     # the fifty-fifth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev56     # the fifty-sixth development set's folders
    python tools/build_reworded_tasks.py --set reader_dev57     # the fifty-seventh development set's folders
    python tools/build_reworded_tasks.py --set reader_dev58     # the fifty-eighth development set's folders
    python tools/build_reworded_tasks.py --mutants  # also ship killable_mutants.json (minutes)

Folders of ids no longer listed are removed, so the directory always equals the JSON.
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data"
#: the sets whose rewordings this tool writes (a folder under tests/data/ each)
SETS = ("reader_dev", "reader_holdout", "reader_dev3", "reader_dev4", "reader_holdout2", "reader_dev5",
        "reader_dev6", "reader_dev7", "reader_dev8", "reader_dev9", "reader_dev10", "reader_dev11",
        "reader_dev12", "reader_dev13", "reader_dev14", "reader_dev15", "reader_dev16", "reader_dev17",
        "reader_dev18", "reader_dev19", "reader_dev20", "reader_dev21",
        "reader_dev22", "reader_dev23", "reader_dev24", "reader_dev25",
        "reader_dev26", "reader_dev27", "reader_dev28", "reader_dev29", "reader_dev30",
        "reader_dev31", "reader_dev32", "reader_dev33", "reader_dev34", "reader_dev35",
        "reader_dev36", "reader_dev37", "reader_dev38", "reader_dev39",
        "reader_dev40", "reader_dev41", "reader_dev42", "reader_dev43", "reader_dev44",
        "reader_dev45", "reader_dev46", "reader_dev47", "reader_dev48", "reader_dev49", "reader_dev50",
        "reader_dev51", "reader_dev52", "reader_dev53", "reader_dev54", "reader_dev55", "reader_dev56",
        "reader_dev57", "reader_dev58")
BUILTIN = ROOT / "benchmark_data" / "tasks"


def reworded_task(entry: dict[str, Any]) -> dict[str, Any]:
    """The original task.json with the rewording's id, description and constraint quotes."""
    original = json.loads((BUILTIN / entry["original"] / "task.json").read_text(encoding="utf-8"))
    says: dict[str, str] = entry["says"]
    facts = [c["fact"] for c in original.get("constraints", [])]
    if set(says) != set(facts):
        sys.exit(f"{entry['id']}: `says` must quote exactly the original's constraint facts; "
                 f"missing {sorted(set(facts) - set(says))}, unknown {sorted(set(says) - set(facts))}")
    task = dict(original)
    task["id"] = entry["id"]
    task["description"] = entry["description"]
    if facts:
        task["constraints"] = [{**c, "says": says[c["fact"]]} for c in original["constraints"]]
    return task


def build(entries: list[dict[str, Any]], out: Path) -> list[str]:
    """Write every folder under `out`; returns the ids written."""
    ids = [e["id"] for e in entries]
    if len(set(ids)) != len(ids):
        sys.exit("rewording ids must be unique")
    out.mkdir(parents=True, exist_ok=True)
    for stale in sorted(p for p in out.iterdir() if p.is_dir() and p.name not in ids):
        shutil.rmtree(stale)
    for entry in entries:
        folder = out / entry["id"]
        folder.mkdir(exist_ok=True)
        text = json.dumps(reworded_task(entry), indent=2, ensure_ascii=False) + "\n"
        (folder / "task.json").write_text(text, encoding="utf-8")
        if (folder / "policies").exists():
            shutil.rmtree(folder / "policies")
        shutil.copytree(BUILTIN / entry["original"] / "policies", folder / "policies")
    return ids


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--set", default="reader_dev", choices=SETS, dest="set_name",
                    help="the set under tests/data/ whose rewordings.json to build (default: reader_dev)")
    ap.add_argument("--mutants", action="store_true",
                    help="also write each folder's killable_mutants.json (`tasks mutants --write`)")
    args = ap.parse_args()
    source = DATA / args.set_name / "rewordings.json"
    out = DATA / args.set_name / "tasks_reworded"
    entries: list[dict[str, Any]] = json.loads(source.read_text(encoding="utf-8"))["rewordings"]
    ids = build(entries, out)
    print(f"wrote {len(ids)} task folders under {out.relative_to(ROOT)}")
    if args.mutants:
        subprocess.run([sys.executable, "-m", "logicenveval", "tasks", "mutants", "--write",
                        "--tasks-dir", str(out)], check=True)


if __name__ == "__main__":
    main()
