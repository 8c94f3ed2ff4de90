#!/usr/bin/env python3
"""The RTL's two views proven equal (docs/rtl.md "Two views"): `make formal`, and in `make test`.

Usage: equiv.py [--out DIR] [--defect] [--list]

A module with two views keeps its synthesis view (what Yosys, nextpnr and the formal proofs
read) and, under `ZB_SIM_FAST`, the view every Verilated model runs. For each such module this
finds every parameter set zb_rop gives it, at every lint parameter set (rtl/lint_sets.txt), and
proves the views equal there with Yosys: both elaborated through the module's harness (formal/,
which drives the inputs as zb_rop does), `equiv_make`, `equiv_simple`, `equiv_induct`,
`equiv_status -assert`.

--defect plants a difference in the simulation view of each module (one bit of an internal
signal tied to 0) and requires the proof to fail: the check can fail.
Writes OUT/summary.csv and each proof's Yosys log; exit 0 when every proof passed (with
--defect: every planted difference was caught), 1 otherwise, 2 on usage errors.
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# module: (harness module in formal/<harness>.sv, instance path in it, planted difference)
VIEWS = {
    "zb_mul8": ("zb_mul8_views", "u_mul", "u_mul.pair_d[0]"),
}


def rtl_files():
    files = sorted(f for f in os.listdir(os.path.join(ROOT, "rtl")) if f.endswith(".sv"))
    files.remove("zb_pkg.sv")
    return ["rtl/zb_pkg.sv"] + [f"rtl/{f}" for f in files]


def lint_sets():
    """(name, chparam arguments, defines) per line of rtl/lint_sets.txt."""
    sets = []
    with open(os.path.join(ROOT, "rtl", "lint_sets.txt")) as f:
        for line in f:
            if not line.strip() or line.startswith("#"):
                continue
            name, _, opts = line.partition(":")
            params, defines = [], []
            for o in opts.split():
                if m := re.fullmatch(r"-G(\w+)=(\S+)", o):
                    params += ["-set", m.group(1), m.group(2)]
                elif o.startswith("+define+"):
                    # The injected defects are simulation's alone ($test$plusargs): no
                    # synthesis flow reads them, and they change no parameter.
                    defines += [f"-D{d}" for d in o[len("+define+"):].split("+")
                                if d and not d.startswith("ZB_INJECT_")]
                else:
                    sys.exit(f"equiv: error: rtl/lint_sets.txt: '{name}': option {o} is neither "
                             "-GNAME=VALUE nor +define+NAME")
            sets.append((name.strip(), params, defines))
    return sets


def yosys(script, log):
    with tempfile.NamedTemporaryFile("w", suffix=".ys", delete=False) as f:
        f.write(script)
    try:
        proc = subprocess.run(["yosys", "-q", "-l", log, "-s", f.name], cwd=ROOT,
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    finally:
        os.unlink(f.name)
    return proc.returncode, proc.stderr


def instances(lint_set, out):
    """{module: set of parameter tuples} of the two-view modules in zb_rop at this lint set."""
    name, params, defines = lint_set
    js = os.path.join(out, f"hierarchy_{name}.json")
    rc, err = yosys(f"read_verilog -sv -DSYNTHESIS {' '.join(defines)} {' '.join(rtl_files())}\n"
                    f"chparam {' '.join(params)} zb_rop\nhierarchy -top zb_rop\nproc -noopt\n"
                    f"write_json {js}\n", os.path.join(out, f"hierarchy_{name}.log"))
    if rc:
        sys.exit(f"equiv: error: elaborating zb_rop at lint set '{name}':\n{err}")
    with open(js) as f:
        modules = json.load(f)["modules"]
    os.unlink(js)
    found = {}
    for mname, m in modules.items():
        base = mname.rsplit("\\", 1)[-1]
        if base in VIEWS:
            values = tuple(sorted((k, int(v, 2)) for k, v in
                                  m.get("parameter_default_values", {}).items()))
            found.setdefault(base, set()).add(values)
    return found


def prove(module, values, out, defect):
    harness, _, planted = VIEWS[module]
    chparam = " ".join(f"-set {k} {v}" for k, v in values)
    sources = f"rtl/zb_pkg.sv rtl/{module}.sv formal/{harness}.sv"
    def view(tag, define, extra=""):
        return (f"read_verilog -sv -DSYNTHESIS {define} {sources}\n"
                f"chparam {chparam} {harness}\n"
                f"hierarchy -top {harness}\nproc\nflatten\nopt_clean\nrename {harness} {tag}\n"
                f"{extra}design -stash {tag}\n")
    script = (view("gold", "") +
              view("gate", "-DZB_SIM_FAST", f"connect -set {planted} 1'b0\n" if defect else "") +
              "design -copy-from gold -as gold gold\ndesign -copy-from gate -as gate gate\n"
              "equiv_make gold gate equiv\nhierarchy -top equiv\nasync2sync\n"
              "equiv_simple -seq 2\nequiv_induct -seq 2\nequiv_status -assert\n")
    tag = "_".join(f"{k}{v}" for k, v in values) or "defaults"
    log = os.path.join(out, f"{module}_{tag}{'_defect' if defect else ''}.log")
    rc, err = yosys(script, log)
    with open(log) as f:
        text = f.read()
    m = re.search(r"Of those cells (\d+) are proven and (\d+) are unproven", text)
    if not m:  # Yosys stopped before the proof: neither proven nor a difference found
        return None, (err.strip().splitlines() or ["yosys failed"])[-1], log
    return rc == 0 and m.group(2) == "0", f"{m.group(1)} proven, {m.group(2)} unproven", log


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="out/equiv", help="output directory (default out/equiv)")
    ap.add_argument("--defect", action="store_true",
                    help="plant a difference in each simulation view; each proof must fail")
    ap.add_argument("--list", action="store_true", help="print the proofs and exit")
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    if subprocess.run(["which", "yosys"], capture_output=True).returncode:
        sys.exit("equiv: error: yosys not found (scripts/setup.sh)")

    proofs = {}  # (module, values) -> lint sets
    for ls in lint_sets():
        for module, combos in instances(ls, out).items():
            for values in combos:
                proofs.setdefault((module, values), []).append(ls[0])
    missing = set(VIEWS) - {m for m, _ in proofs}
    if missing:
        sys.exit(f"equiv: error: zb_rop has no instance of {', '.join(sorted(missing))} at any "
                 "lint set: VIEWS in scripts/equiv.py names a module the design lost")
    if a.defect:  # one planted difference a module, at its first parameter set
        first = {}
        for key in sorted(proofs):
            first.setdefault(key[0], key)
        proofs = {k: proofs[k] for k in first.values()}
    if a.list:
        for (module, values), sets in sorted(proofs.items()):
            print(f"{module:10} {' '.join(f'{k}={v}' for k, v in values):24} lint sets: "
                  f"{', '.join(sets)}")
        return 0

    failed = 0
    rows = []
    for (module, values), sets in sorted(proofs.items()):
        t0 = time.monotonic()
        ok, cells, log = prove(module, values, out, a.defect)
        if ok is None:
            status = "ERROR"
        elif a.defect:
            status = "MISSED" if ok else "caught"
        else:
            status = "proven" if ok else "FAILED"
        failed += status not in ("proven", "caught")
        params = " ".join(f"{k}={v}" for k, v in values)
        rows.append((module, params, " ".join(sets), status, f"{time.monotonic() - t0:.1f}",
                     cells, os.path.relpath(log, os.getcwd())))
        print(f"equiv: {module} {params}: {status} ({cells})"
              + ("" if status in ("proven", "caught") else f": {rows[-1][-1]}"), flush=True)
    with open(os.path.join(out, "summary.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["module", "parameters", "lint_sets", "status", "seconds", "equiv_cells", "log"])
        w.writerows(rows)
    what = "planted differences caught" if a.defect else "proofs passed"
    print(f"equiv: {len(rows) - failed} of {len(rows)} {what}: {os.path.join(a.out, 'summary.csv')}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
