"""What `python -m logicenveval generators list` shows: every generator a run can name, with its
name in the paper (the paper "LogicEnvGen: Task-Logic Driven Generation of Diverse Simulated
Environments for Embodied AI"), where it comes from and what it does."""

from __future__ import annotations

import importlib.metadata
from dataclasses import dataclass

from logicenveval.generators.base import registered, registry_entry
from logicenveval.generators.plugins import ENTRY_POINT_GROUP

#: built-in name -> (name in the paper, or "" for our own variants; what it does)
BUILTIN_INFO: dict[str, tuple[str, str]] = {
    "logicenvgen": ("LogicEnvGen", "decision-tree plans, MTSA trajectory selection, solver layout"),
    "logicenvgen-exact": ("", "ours: LogicEnvGen with a polynomial exact minimum cover"),
    "logicenvgen-no-dbp": ("W/O DBP", "ablation: flat plans instead of decision trees"),
    "logicenvgen-no-mtsa": ("W/O MTSA", "ablation: the whole Cartesian product of trajectories"),
    "logicenvgen-exhaustive": ("Exhaustive", "exponential minimum-set-cover search"),
    "logicenvgen-no-cas": ("W/O CAS", "ablation: coordinates written by the model, no solver"),
    "cot": ("CoT", "baseline: one chain-of-thought request writes several environments, no solver"),
    "ifg": ("IFG", "baseline: intent-first generation, one environment per sampled intent"),
    "holodeck": ("Holodeck", "baseline: one scene from the description, Holodeck-like solver"),
}


@dataclass(frozen=True)
class GeneratorInfo:
    name: str
    paper_name: str  # "" when the paper has no such method
    source: str  # "built-in", "plug-in <distribution> <version>", "registered in this process"
    description: str


def _first_line(obj: object) -> str:
    doc = (getattr(obj, "__doc__", None) or "").strip()
    return doc.splitlines()[0] if doc else ""


def _plugins() -> list[GeneratorInfo]:
    out = []
    for ep in sorted(importlib.metadata.entry_points(group=ENTRY_POINT_GROUP), key=lambda e: e.name):
        dist = getattr(ep, "dist", None)
        source = f"plug-in {dist.name} {dist.version}" if dist is not None else "plug-in"
        try:
            description = _first_line(ep.load())
        except Exception as exc:  # listed all the same: `run` gives the one-line error
            description = f"cannot be imported: {type(exc).__name__}: {str(exc)[:120]}"
        out.append(GeneratorInfo(ep.name, "", source, description))
    return out


def generator_infos() -> list[GeneratorInfo]:
    """Built-ins (in the paper's order), then installed plug-ins, then factories registered in
    this process (`logicenveval.register_generator`)."""
    out = [GeneratorInfo(n, paper, "built-in", what) for n, (paper, what) in BUILTIN_INFO.items()]
    plugins = _plugins()
    known = set(BUILTIN_INFO) | {p.name for p in plugins}
    out += plugins
    for name in registered():
        if name not in known:
            entry = registry_entry(name)
            what = entry if isinstance(entry, str) else _first_line(entry)
            out.append(GeneratorInfo(name, "", "registered in this process", what))
    return out
