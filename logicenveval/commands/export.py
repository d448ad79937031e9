"""`export ENV.json --format procthor|glb|bt-model --out FILE`: write an environment as an
AI2-THOR-loadable ProcTHOR house JSON or a GLB scene, or the action library's Groot2 node model
(`bt-model`: a BT.CPP v4 file holding only the `<TreeNodesModel>`, for Groot2's palette)."""

from __future__ import annotations

import argparse

FORMATS = ("procthor", "glb", "bt-model")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("env", metavar="ENV.json", nargs="?",
                        help="EnvSpec file (not needed for --format bt-model)")
    parser.add_argument("--format", required=True, choices=FORMATS)
    parser.add_argument("--out", required=True, metavar="FILE", help="file to write")
    parser.add_argument("--catalog", default=None, help="catalog.json (default: the benchmark's)")


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from logicenveval.errors import ConfigError
    from logicenveval.scene.export_files import export_env, write_bt_model

    out = Path(args.out)
    if args.format == "bt-model":
        write_bt_model(out)
    else:
        if args.env is None:
            raise ConfigError(f"--format {args.format} needs an ENV.json", field="ENV.json",
                              hint=f"python -m logicenveval export ENV.json --format {args.format} --out FILE")
        export_env(Path(args.env), args.format, out, args.catalog)
    print(f"wrote {out}")
    return 0
