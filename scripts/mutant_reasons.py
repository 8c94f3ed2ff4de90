"""Written reasons for mutants no test kills (tb/mutation/reasons.json, docs/mutation.md).

A reason names the mutants it covers by regular expressions over their descriptions (Yosys's
`mutate` command lines, build/tb/mutation/mutations.txt), says which kind of survivor they are and
why no test of zblend's can kill them. A survivor with a reason still counts as a survivor: the
reason explains the score, it does not raise it. A reason that matches no mutant of the netlist
is stale (the RTL moved) and is reported as such.
"""
import json
import re

KINDS = {
    "equivalent": "equivalent to zb_rop on every reachable state, argued in writing (the prover "
                  "did not close it)",
    "contract": "differs only for inputs the port contract rules out (docs/rtl.md)",
    "unobservable": "differs only after more events than a run has, or in a count no driver reads",
    "unchecked": "differs only in a behaviour the checker does not check (the reason says which): a "
                 "gap in the checker, stated",
}


class Reasons:
    def __init__(self, path):
        self.entries = []
        with open(path) as f:
            data = json.load(f)
        for n, e in enumerate(data.get("reasons", [])):
            where = f"{path}: reasons[{n}]"
            for key in ("id", "kind", "match", "why"):
                if key not in e:
                    raise ValueError(f"{where}: '{key}' is missing")
            if e["kind"] not in KINDS:
                raise ValueError(f"{where}: kind '{e['kind']}' is not one of {sorted(KINDS)}")
            try:
                pats = [re.compile(p) for p in e["match"]]
            except re.error as err:
                raise ValueError(f"{where}: match: {err}") from None
            self.entries.append({**e, "patterns": pats, "hits": 0})

    def explain(self, description):
        """The first reason whose pattern matches `description`, or None."""
        for e in self.entries:
            if any(p.search(description) for p in e["patterns"]):
                return e
        return None

    def count(self, descriptions):
        """Counts each reason's matches over the netlist's descriptions."""
        for e in self.entries:
            e["hits"] = sum(1 for d in descriptions if any(p.search(d) for p in e["patterns"]))

    def stale(self):
        return [e["id"] for e in self.entries if e["hits"] == 0]
