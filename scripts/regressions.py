"""The regression file (tb/regressions.json, docs/regressions.md): groups of tests as data.

An entry is one test or a cross product of tests:
  {"name": N, "args": [...]}                       zblend_tb with these arguments;
  {"name": N, "suite": S, "seeds": [..], "backpressure": [..], "args": [...]}
                                                   zblend_tb --suite S per seed x back-pressure;
  {"name": N, "render": {"scene": [..], "method": [..]}, "seeds": [..], "backpressure": [..],
   "args": [...]}                                  zblend render --backend both per scene x method
                                                   (x seed x back-pressure): golden model and RTL
                                                   compared at every write.
Each expands to tests with explicit seeds: the name grows -SCENE-METHOD, -sSEED, -bpP. An
entry's "rtl": [..] runs it on each named RTL parameter set of the file's "rtl_params" ({"window4":
{"ZBLEND_RTL_WINDOW": 4}, ...}: CMake's ZBLEND_RTL_* options, a build tree each), "default"
being the build given; the name grows -SET. A group may also list {"group": G}: G's tests, in
order.
"""
import os
import re

from zbscript import ROOT, load_json

DEFAULT = os.path.join(ROOT, "tb", "regressions.json")
NAME = re.compile(r"[A-Za-z0-9_.+-]+")
KEYS = {"name", "args", "suite", "seeds", "backpressure", "render", "group", "rtl"}


class RegressionError(ValueError):
    """A malformed regression file: what, where, how to fix."""


def _num(v):
    return f"{v:g}" if isinstance(v, float) else str(v)


def _expand(entry, where, rtl_params):
    unknown = set(entry) - KEYS
    if unknown:
        raise RegressionError(f"{where}: unknown key(s) {', '.join(sorted(unknown))} "
                              f"(known: {', '.join(sorted(KEYS))})")
    name = entry.get("name")
    if not isinstance(name, str) or not NAME.fullmatch(name):
        raise RegressionError(f"{where}: 'name' must be letters, digits, _ . + - (got {name!r})")
    args = entry.get("args", [])
    if not isinstance(args, list) or not all(isinstance(a, str) for a in args):
        raise RegressionError(f"{where} ({name}): 'args' must be a list of strings")
    seeds = entry.get("seeds", [None])
    bps = entry.get("backpressure", [None])
    for key, vals in (("seeds", seeds), ("backpressure", bps)):
        if not isinstance(vals, list) or not vals:
            raise RegressionError(f"{where} ({name}): '{key}' must be a non-empty list")
    if any(s is not None and (not isinstance(s, int) or s < 0) for s in seeds):
        raise RegressionError(f"{where} ({name}): seeds are integers >= 0")
    if any(b is not None and (not isinstance(b, (int, float)) or not 0 <= b < 1) for b in bps):
        raise RegressionError(f"{where} ({name}): back-pressure is a probability in [0, 1)")
    if "suite" in entry and "render" in entry:
        raise RegressionError(f"{where} ({name}): 'suite' or 'render', not both")
    combos = [("", [], "tb")]
    if "suite" in entry:
        combos = [("", ["--suite", entry["suite"]], "tb")]
    elif "render" in entry:
        r = entry["render"]
        if not isinstance(r, dict) or not r.get("scene") or not r.get("method"):
            raise RegressionError(f"{where} ({name}): 'render' needs 'scene' and 'method' lists")
        combos = [(f"-{s}-{m}", ["--scene", s, "--method", m, "--backend", "both"], "render")
                  for s in r["scene"] for m in r["method"]]
    sets = entry.get("rtl", ["default"])
    if not isinstance(sets, list) or not sets:
        raise RegressionError(f"{where} ({name}): 'rtl' must be a non-empty list of parameter "
                              "sets")
    for r in sets:
        if r != "default" and r not in rtl_params:
            raise RegressionError(f"{where} ({name}): no RTL parameter set '{r}' in "
                                  f"\"rtl_params\" (sets: default, {', '.join(rtl_params)})")
    combos = [(suffix + (f"-{r}" if len(sets) > 1 else ""), head, tool, r)
              for suffix, head, tool in combos for r in sets]
    tests = []
    for suffix, head, tool, rtl in combos:
        for s in seeds:
            for b in bps:
                tail = []
                n = name + suffix
                if s is not None:
                    tail += ["--seed", str(s)]
                    n += f"-s{s}" if len(seeds) > 1 else ""
                if b is not None:
                    tail += ["--backpressure", _num(b)]
                    n += f"-bp{_num(b)}" if len(bps) > 1 else ""
                tests.append({"name": n, "tool": tool, "args": head + args + tail, "rtl": rtl,
                              "rtl_cache": rtl_params.get(rtl, {})})
    return tests


def load(path=DEFAULT):
    """{group: [test]} with every entry expanded; each test {name, tool, args}."""
    doc = load_json(path, RegressionError)
    groups = doc.get("groups") if isinstance(doc, dict) else None
    if not isinstance(groups, dict) or not groups:
        raise RegressionError(f"{path}: no \"groups\" object")
    rtl_params = doc.get("rtl_params", {})
    if not isinstance(rtl_params, dict) or any(
            not NAME.fullmatch(k) or k == "default" or not isinstance(v, dict) or
            any(not str(o).startswith("ZBLEND_RTL_") for o in v) for k, v in rtl_params.items()):
        raise RegressionError(f"{path}: \"rtl_params\" maps set names (not 'default') to "
                              "{ZBLEND_RTL_*: value} objects")
    out = {}

    def resolve(g, stack):
        if g in out:
            return out[g]
        if g in stack:
            raise RegressionError(f"{path}: group {g} includes itself")
        if g not in groups or not isinstance(groups[g], list):
            raise RegressionError(f"{path}: no group '{g}' (groups: {', '.join(groups)})")
        tests = []
        for i, e in enumerate(groups[g]):
            where = f"{path}: groups.{g}[{i}]"
            if not isinstance(e, dict):
                raise RegressionError(f"{where}: an entry is an object")
            if "group" in e:
                tests += resolve(e["group"], stack + [g])
            else:
                tests += _expand(e, where, rtl_params)
        seen = set()
        for t in tests:
            if t["name"] in seen:
                raise RegressionError(f"{path}: group {g} has two tests named {t['name']}")
            seen.add(t["name"])
        out[g] = tests
        return tests

    for g in groups:
        resolve(g, [])
    return out
