"""`export ENV.json --format procthor|glb|bt-model --out FILE`: write an environment as an
AI2-THOR-loadable ProcTHOR house JSON or a GLB scene, or the action library's Groot2 node model
(`bt-model`: a BT.CPP v4 file holding only the `<TreeNodesModel>`, for Groot2's palette).
`export RUN_DIR --csv --out DIR` (= `--format csv`): a run's figures as `samples.csv` (one row per
environment), `tasks.csv` (per method and task) and `methods.csv` (per method, with the 95 %
intervals) for a spreadsheet or pandas (`logicenveval.reporting.frames`)."""

from __future__ import annotations

import argparse

FORMATS = ("procthor", "glb", "bt-model", "csv")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("env", metavar="ENV.json|RUN_DIR", nargs="?",
                        help="EnvSpec file; a run folder for --csv (not needed for --format bt-model)")
    parser.add_argument("--format", choices=FORMATS, help="what to write (--csv is --format csv)")
    parser.add_argument("--csv", dest="format", action="store_const", const="csv",
                        help="a run's figures as samples.csv, tasks.csv and methods.csv in the folder --out")
    parser.add_argument("--out", required=True, metavar="FILE|DIR", help="file to write (a folder for --csv)")
    parser.add_argument("--catalog", default=None, help="catalog.json (default: the benchmark's)")


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from logicenveval.errors import ConfigError

    out = Path(args.out)
    if args.format is None:
        raise ConfigError("say what to write", field="--format",
                          hint=f"--format {'|'.join(FORMATS)} (or --csv for a run folder's figures)")
    if args.format == "bt-model":
        from logicenveval.scene.export_files import write_bt_model

        write_bt_model(out)
        print(f"wrote {out}")
        return 0
    if args.env is None:
        what = "RUN_DIR" if args.format == "csv" else "ENV.json"
        raise ConfigError(f"--format {args.format} needs {'a' if what == 'RUN_DIR' else 'an'} {what}",
                          field=what, hint=f"python -m logicenveval export {what} --format {args.format} --out "
                          f"{'DIR' if what == 'RUN_DIR' else 'FILE'}")
    if args.format == "csv":
        from logicenveval.reporting.frames import write_csv

        if out.exists() and not out.is_dir():
            raise ConfigError(f"--out {args.out} is not a folder", field="--out",
                              hint="--csv writes samples.csv, tasks.csv and methods.csv into a folder: name one")

        for path in write_csv(Path(args.env), out):
            print(f"wrote {path}")
        return 0
    from logicenveval.scene.export_files import export_env

    export_env(Path(args.env), args.format, out, args.catalog)
    print(f"wrote {out}")
    return 0
