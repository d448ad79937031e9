"""Names of the built-in generators; each module is imported only when its generator is made.
Data only: `generators.base` registers these names on first use (this module imports nothing, so
the two never import each other)."""

BUILTIN: dict[str, str] = {
    "logicenvgen": "logicenveval.generators.logicenvgen:LogicEnvGen",
    "logicenvgen-exact": "logicenveval.generators.logicenvgen:exact",
    "logicenvgen-no-dbp": "logicenveval.generators.logicenvgen:no_dbp",
    "logicenvgen-no-mtsa": "logicenveval.generators.logicenvgen:no_mtsa",
    "logicenvgen-exhaustive": "logicenveval.generators.logicenvgen:exhaustive",
    "logicenvgen-no-cas": "logicenveval.generators.logicenvgen:no_cas",
    "logicenvgen-reselect": "logicenveval.generators.logicenvgen:reselect",
    "cot": "logicenveval.baselines.cot:CoT",
    "ifg": "logicenveval.baselines.ifg:IFG",
    "holodeck": "logicenveval.baselines.holodeck:Holodeck",
}

#: old name -> current name. Two names changed meaning when the paper's names were adopted and
#: cannot be aliases: `logicenvgen` (was the exact cover, now MTSA: the old row is
#: `logicenvgen-exact`) and `logicenvgen-exhaustive` (was the Cartesian product, now the paper's
#: exponential search: the old row is `logicenvgen-no-mtsa`).
ALIASES: dict[str, str] = {"logicenvgen-mtsa": "logicenvgen"}
