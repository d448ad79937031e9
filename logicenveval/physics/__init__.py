"""PhyPR physics checker (floor plan / entity / relation) and top-down renders."""

from logicenveval.physics.check import check_env
from logicenveval.physics.report import (
    DEFAULT_TOLERANCES,
    DIMENSIONS,
    EXTENDED_CODES,
    DimensionReport,
    PhysicsFailure,
    PhysicsReport,
    Tolerances,
)

__all__ = ["DEFAULT_TOLERANCES", "DIMENSIONS", "EXTENDED_CODES", "DimensionReport", "PhysicsFailure", "PhysicsReport",
           "Tolerances", "check_env"]
