"""Names of the built-in generators; each module is imported only when its generator is made."""

from logicenveval.generators.base import register

BUILTIN: dict[str, str] = {
    "logicenvgen": "logicenveval.generators.logicenvgen:LogicEnvGen",
    "logicenvgen-no-dbp": "logicenveval.generators.logicenvgen:no_dbp",
    "logicenvgen-mtsa": "logicenveval.generators.logicenvgen:with_mtsa",
    "logicenvgen-exhaustive": "logicenveval.generators.logicenvgen:exhaustive",
    "logicenvgen-no-cas": "logicenveval.generators.logicenvgen:no_cas",
    "cot": "logicenveval.baselines.cot:CoT",
    "ifg": "logicenveval.baselines.ifg:IFG",
    "holodeck": "logicenveval.baselines.holodeck:Holodeck",
}

for _name, _entry in BUILTIN.items():
    register(_name, _entry)
