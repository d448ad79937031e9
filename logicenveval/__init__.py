"""LogicEnvEval: a benchmark and harness for generators of logically diverse test environments."""

from logicenveval.errors import LogicEnvEvalError

__version__ = "0.1.0"
__all__ = ["LogicEnvEvalError", "__version__"]
