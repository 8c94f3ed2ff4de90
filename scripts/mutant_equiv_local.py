#!/usr/bin/env python3
"""Is a surviving mutant equivalent, proven on its own module? (docs/mutation.md)

scripts/mutant_equiv.sh proves a mutant on the whole flattened zb_rop, which at LAYERS 4 gives no
verdict in its time. This proves a stronger claim on a much smaller design: the module that
holds the mutated cell (zb_layers_insert, zb_mul8, ...), elaborated with zb_rop's parameters but
not flattened into it, equal to its mutant on every output in every cycle for ANY inputs. A
module equal in every context is equal in zb_rop's, so "proven" here is sound for zb_rop; a
mutant equal only in zb_rop's context (the port contract) is not proven.

The mutated cell is found again in the module by its path (the instances in the flattened
name), then by its own name where the module still has it at the same type and source location,
else by type and source location alone: when several cells share them (a loop's or a
function's), each is proven in turn, proven only if all are. The proof itself is scripts/mutant_equiv.sh on the module.
Exit: 0 proven; 1 not proven; 2 usage; 3 no verdict (time limit, Yosys failed, cell not found).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rtlil_modules(path):
    """{module: {cell name: (type, its src attribute)}}: a cell's type is the module of an
    instance, which descends the hierarchy."""
    mods, mod, attrs = {}, None, {}
    with open(path) as f:
        for line in f:
            s = line.strip()
            if s.startswith("attribute "):
                key, _, val = s[len("attribute "):].partition(" ")
                attrs[key] = val
            elif s.startswith("module "):
                mod = s.split(None, 1)[1]
                mods[mod] = {}
                attrs = {}
            elif s.startswith("cell ") and mod is not None:
                _, ctype, name = s.split(None, 2)
                mods[mod][name] = (ctype, attrs.get("\\src", "").strip('"'))
                attrs = {}
            elif s == "end" or s.startswith("wire ") or s.startswith("memory ") or s.startswith("process "):
                attrs = {}
    return mods


def split_flat_name(cell):
    """'$flatten\\a.b.\\c.\\d.$add$x' -> (['a.b', 'c', 'd'], '$add$x'): each level's instance name
    starts with a backslash in the flattened name (public names), the cell's own is the last."""
    assert cell.startswith("$flatten\\")
    rest = cell[len("$flatten\\"):]
    parts = re.split(r"\.(?=\\|\$)", rest)
    levels = [p.lstrip("\\") for p in parts[:-1]]
    return levels, parts[-1]


def flat_cell_info(design, cell):
    """The flattened cell's type and source locations in design.il."""
    mods = rtlil_modules(design)
    top = mods.get("\\zb_rop", {})
    if cell not in top:
        return None, None
    return top[cell]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("design", help="the flattened netlist the mutations name (design.il; "
                    "scripts/mutants.sh writes hier.il, the same not flattened, beside it)")
    ap.add_argument("mutant", type=int, help="line N of mutations.txt beside DESIGN")
    ap.add_argument("--time-limit", type=int, default=300, help="seconds a candidate cell")
    ap.add_argument("--up", type=int, default=0,
                    help="prove on the module this many levels above the cell's (its constant "
                         "inputs there join the proof; default 0: the cell's own module)")
    a = ap.parse_args()
    a.hier = os.path.join(os.path.dirname(a.design), "hier.il")
    if not os.path.exists(a.hier):
        print(f"mutant_equiv_local: {a.hier} is missing (scripts/mutants.sh of this build)",
              file=sys.stderr)
        return 2
    listing = os.path.join(os.path.dirname(a.design), "mutations.txt")
    with open(listing) as f:
        lines = f.read().splitlines()
    if not 1 <= a.mutant <= len(lines):
        print(f"mutant_equiv_local: {listing} has no mutant {a.mutant}", file=sys.stderr)
        return 2
    desc = lines[a.mutant - 1]
    m = re.search(r"-cell (\S+)", desc)
    if not m:
        print(f"mutant_equiv_local: mutant {a.mutant} names no cell", file=sys.stderr)
        return 2
    flat = m.group(1)
    ctype, src = flat_cell_info(a.design, flat)
    if ctype is None:
        print(f"no verdict: {flat} is not in {a.design}")
        return 3
    levels, own_name = split_flat_name(flat)
    mods = rtlil_modules(a.hier)
    path = ["\\zb_rop"]
    for inst in levels:
        cells = mods.get(path[-1], {})
        key = "\\" + inst
        if key not in cells:
            print(f"no verdict: no instance {inst} in {path[-1]}")
            return 3
        path.append(cells[key][0])
    if not 0 <= a.up < len(path):
        print(f"mutant_equiv_local: --up {a.up}: the cell is {len(path) - 1} levels down", file=sys.stderr)
        return 2
    mod = path[-1]
    top = path[-1 - a.up]
    prefix = "".join("\\" + inst + "." for inst in levels[len(levels) - a.up:])
    # The cell's own source location is the one in the module's file (the others are the
    # instances'); its type must match.
    own = set(src.split("|"))
    def same_place(t, s):
        return t == ctype and s and set(s.split("|")) <= own
    # Both netlists come from one elaboration up to the flattening, which keeps a cell's own name
    # (its global index included): the cell of that name, when the module still has it at the
    # same place, is the one. Else every cell at the place.
    here = mods[mod].get(own_name)
    if here and same_place(*here):
        candidates = [own_name]
    else:
        candidates = [n for n, (t, s) in mods[mod].items() if same_place(t, s)]
    if not candidates:
        print(f"no verdict: no {ctype} cell at {src} in {mod}")
        return 3
    verdicts = []
    with tempfile.TemporaryDirectory() as tmp:
        design = os.path.join(tmp, "module.il")
        r = subprocess.run(["yosys", "-q", "-p", f"read_rtlil {a.hier}; hierarchy -top {top}; "
                            f"flatten; rename -top zb_rop; write_rtlil {design}"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            print(f"no verdict: yosys failed on {mod}: {r.stderr.strip()[-300:]}")
            return 3
        for c in candidates:
            # Flattened into `top`, the cell's name carries the instances below it.
            cell = ("$flatten" + prefix + c) if a.up else c
            mutation = re.sub(r"-cell \S+", lambda _: f"-cell {cell}", desc)
            mutation = re.sub(r" -(wire|wirebit|src) \S+", "", mutation)
            p = subprocess.run([os.path.join(ROOT, "scripts", "mutant_equiv.sh"), "--time-limit",
                                str(a.time_limit), design, mutation], capture_output=True,
                               text=True)
            verdicts.append((c, p.returncode, p.stdout.strip()))
            if p.returncode != 0:
                break
    name = top.split("\\")[-1]
    if all(rc == 0 for _, rc, _ in verdicts):
        print(f"proven equivalent on {name} alone ({len(verdicts)} cell(s) at its source)")
        return 0
    c, rc, out = verdicts[-1]
    print(f"{'not proven' if rc == 1 else 'no verdict'} on {name} ({c}): {out}")
    return 1 if rc == 1 else 3


if __name__ == "__main__":
    sys.exit(main())
