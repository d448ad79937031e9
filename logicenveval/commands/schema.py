"""`schema envspec|task|results [--out FILE]`: the JSON Schema of a file kind, from the models.

The same schemas are committed under docs/schemas/ (a test keeps them current), so tools in any
language can validate EnvSpecs, tasks and results without this package.
"""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from logicenveval.schemas import SCHEMAS

    parser.add_argument("name", metavar="NAME", choices=sorted(SCHEMAS),
                        help="which file kind: " + ", ".join(f"{k} ({v[1]})" for k, v in SCHEMAS.items()))
    parser.add_argument("--out", metavar="FILE", default=None, help="write the schema here instead of printing it")


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from logicenveval.schemas import schema_text

    text = schema_text(args.name)
    if args.out:
        from logicenveval.scene.export_files import write_output

        write_output(Path(args.out), text, what="schema")
        print(f"wrote {args.out}")
    else:
        print(text, end="")
    return 0
