"""`check-house HOUSE.json [--procthor-db DIR] [--json]`: will AI2-THOR load this house?

Verifies asset ids, wall holes, materials, required keys and finite numbers against ProcTHOR's
databases (`--procthor-db`: its procthor/databases folder; by default those of the installed
`procthor` package, the `[procthor]` extra), or, without them, against our recorded mapping (benchmark_data/procthor_assets.json) — which only knows the ids our exporter chooses, so
an asset id outside it is a warning, not a problem. Exit 0 when every house passes, 1 when one
has problems, 2 on an unreadable file or database.
"""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("house", metavar="HOUSE.json", nargs="+", help="house JSON file(s)")
    parser.add_argument("--procthor-db", metavar="DIR", default=None,
                        help="ProcTHOR's procthor/databases folder (default: our recorded mapping)")
    parser.add_argument("--json", action="store_true", help="print the reports as JSON")


def run(args: argparse.Namespace) -> int:
    import json
    from pathlib import Path

    from logicenveval.scene.house_check import check_house
    from logicenveval.scene.house_import import load_house
    from logicenveval.scene.procthor import installed_procthor_db, load_procthor_db, our_assets

    found = load_procthor_db(args.procthor_db) if args.procthor_db else installed_procthor_db()
    real = found is not None
    db = found if found is not None else our_assets()
    if not real and not args.json:
        print("ProcTHOR's databases are not installed (pip install 'logicenveval[procthor]') and no "
              "--procthor-db: checking against our recorded mapping only "
              "(benchmark_data/procthor_assets.json), not ProcTHOR's full databases")
    failed = 0
    reports = {}
    for name in args.house:
        report = check_house(load_house(Path(name)), db, authoritative=real)
        reports[name] = report
        failed += not report.passed
        if not args.json:
            state = "ok" if report.passed else f"{len(report.problems)} problem(s)"
            print(f"{name}: {state} ({report.assets} asset ids, {report.unknown_ids} unknown ids, "
                  f"{report.unknown_materials} unknown materials, {len(report.warnings)} warning(s))")
            for p in report.problems:
                print(f"  {p.where}: {p.message}")
            for p in report.warnings[:10]:
                print(f"  warning: {p.where}: {p.message}")
            if len(report.warnings) > 10:
                print(f"  ... {len(report.warnings) - 10} more warning(s) (--json lists all)")
    if args.json:
        print(json.dumps({k: r.model_dump(mode="json") for k, r in reports.items()}, indent=2))
    else:
        print(f"{len(reports) - failed} of {len(reports)} house(s) pass against {db.source}")
    return 1 if failed else 0
