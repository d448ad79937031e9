"""`check-env ENV.json [--json] [--render OUT.svg|OUT.png]`: PhyPR check of one environment.

Exit 0 when the paper's three PhyPR dimensions pass, 1 otherwise (with `--strict`, also when an
extra plausibility check fails: the `extended` block), 2 on a malformed file (via the CLI's error
handler).
"""

from __future__ import annotations

import argparse
import json

#: failures per dimension shown in the table (a pile of objects can fail thousands of pairs)
TABLE_ROWS = 50


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("env", metavar="ENV.json", help="EnvSpec file to check")
    parser.add_argument("--json", action="store_true", help="print the report as JSON")
    parser.add_argument("--render", metavar="OUT", help="write a top-down render (.svg or .png)")
    parser.add_argument("--strict", action="store_true",
                        help="exit 1 also when an extra plausibility check (not in PhyPR) fails")


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from rich.console import Console
    from rich.table import Table

    from logicenveval.atomic import RESOURCE_ERRNOS, atomic_path, atomic_write_text
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.domain.categories import normalise_env
    from logicenveval.envfiles import load_env
    from logicenveval.errors import ConfigError
    from logicenveval.physics import DIMENSIONS, check_env
    from logicenveval.physics.render import render_png, render_svg

    catalog = load_catalog()
    if args.render and Path(args.render).suffix.lower() not in (".svg", ".png"):
        raise ConfigError(f"unsupported render format {Path(args.render).suffix!r}", field="--render",
                          hint="name the output file OUT.svg or OUT.png")
    env, categories = normalise_env(load_env(args.env), catalog)
    report = check_env(env, catalog, mesh_dir=Path(args.env).parent)
    if args.render:  # temp file + rename: a failed write leaves the old file or none, never a part
        out = Path(args.render)
        try:
            if out.suffix.lower() == ".svg":
                atomic_write_text(out, render_svg(env, report))
            else:
                with atomic_path(out) as tmp:
                    render_png(env, tmp, report)
        except OSError as exc:
            if exc.errno in RESOURCE_ERRNOS:
                raise  # a full disk: the CLI names the file, exit 1
            raise ConfigError(f"cannot write the render: {exc.strerror or exc}", file=str(out),
                              field="--render", hint="choose a writable path for the render") from None
    if args.json:
        print(json.dumps(report.model_dump(mode="json"), indent=2))
    else:
        console = Console()
        for note in categories.notes():
            console.print(f"note: {note}", markup=False)
        table = Table(title=f"PhyPR check of {env.env_id}")
        for col in ("dimension", "result", "code", "objects"):
            table.add_column(col, no_wrap=True)
        table.add_column("message", ratio=1)
        for dim in (*DIMENSIONS, "extended"):
            rep = getattr(report, dim)
            label = "extended (not PhyPR)" if dim == "extended" else dim
            if rep.passed:
                table.add_row(label, "[green]pass[/]", "", "", "")
            for f in rep.failures[:TABLE_ROWS]:
                table.add_row(label, "[red]FAIL[/]", f.code, ", ".join(f.objects + f.rooms), f.message)
            if len(rep.failures) > TABLE_ROWS:
                table.add_row(label, "[red]FAIL[/]", "…", "", f"{len(rep.failures) - TABLE_ROWS} more failures "
                              "(--json lists all)")
        console.print(table)
    return 0 if report.passed and (report.extended.passed or not args.strict) else 1
