"""Names of the built-in generators; each module is imported only when its generator is made."""

from logicenveval.generators.base import register

BUILTIN: dict[str, str] = {}

for _name, _entry in BUILTIN.items():
    register(_name, _entry)
