"""`generators list`: the generators `run --generators` and `generate --generator` accept."""

from __future__ import annotations

import argparse


def add_arguments(p: argparse.ArgumentParser) -> None:
    sub = p.add_subparsers(dest="action", required=True, metavar="ACTION")
    ls = sub.add_parser("list", help="name, paper name, source (built-in or plug-in with its "
                        "version) and description of every generator")
    ls.add_argument("--json", action="store_true", help="print the list as JSON")


def run(args: argparse.Namespace) -> int:
    import json
    from dataclasses import asdict

    from rich.console import Console
    from rich.table import Table

    from logicenveval.generators.listing import generator_infos

    infos = generator_infos()
    if args.json:
        print(json.dumps([asdict(i) for i in infos], indent=2))
        return 0
    table = Table(title="generators (run --generators NAME,...; also PKG.MODULE:ATTR)",
                  title_justify="left")
    for col in ("name", "paper name", "source", "description"):
        table.add_column(col, overflow="fold")
    for i in infos:
        table.add_row(i.name, i.paper_name or "–", i.source, i.description)
    # at least 120 columns, so that piped output keeps each generator on one line
    Console(width=max(Console().width, 120), highlight=False).print(table)
    return 0
