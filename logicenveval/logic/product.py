"""`product`: every trajectory of the Cartesian product (the paper's ablation "W/O MTSA")."""

from __future__ import annotations

import itertools

from logicenveval.logic.constraints import PathConstraints
from logicenveval.logic.selectors import PathsPerSubtask, check_inputs
from logicenveval.model.tree import Trajectory


class ProductSelector:
    name = "product"

    def select(
        self, paths_per_subtask: PathsPerSubtask, constraints: PathConstraints | None = None
    ) -> list[Trajectory]:
        """All admissible trajectories in lexicographic (subtask, branch) order."""
        cons = check_inputs(paths_per_subtask, constraints)
        return [
            Trajectory(combo)
            for combo in itertools.product(*paths_per_subtask)
            if cons.admits(combo)
        ]


SELECTOR = ProductSelector()
