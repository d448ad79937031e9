"""Imported once by the process executor's fork server: what units need, loaded before the
workers are forked from it (see `executors.ProcessExecutor`). Only a speed-up: a worker imports
whatever is missing on its own."""

from __future__ import annotations

import gc
import importlib
import sys

import logicenveval.faults.score  # noqa: F401  (what a unit imports when it first needs it: mutants,
import logicenveval.llm.registry  # noqa: F401  the layout, ...)
import logicenveval.logic.reference  # noqa: F401  (a unit's figures: JI's closest cover)
import logicenveval.offline.model  # noqa: F401  (the embedded model: it imports the reader and registers its answers)
import logicenveval.physics.render  # noqa: F401
import logicenveval.runner.evaluation  # noqa: F401
import logicenveval.runner.unit  # noqa: F401
import logicenveval.scene.construct  # noqa: F401
import logicenveval.scene.layout_cpsat  # noqa: F401  (the default layout backend, with OR-tools)
import logicenveval.sim.loader  # noqa: F401
from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.registry import BUILTIN
from logicenveval.runner.executors import kill_me_with_parent

if "multiprocessing.forkserver" in sys.modules and sys.argv[:1] == ["-c"]:
    kill_me_with_parent()  # the fork server dies with the run; its workers then die with it
load_catalog()
for _entry in BUILTIN.values():
    importlib.import_module(_entry.partition(":")[0])
# what is loaded now is shared by every forked worker: keep the workers' collector off it, so it
# neither scans it nor copies its pages (copy-on-write) — the use gc.freeze documents
gc.freeze()
