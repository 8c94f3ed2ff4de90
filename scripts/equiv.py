#!/usr/bin/env python3
"""The RTL's two views proven equal (docs/rtl.md "Two views"): `make formal`, and in `make test`.

Usage: equiv.py [--ci] [--out DIR] [--defect] [--list]

A module with two views keeps its synthesis view in rtl/X.sv (what Yosys, nextpnr, the formal
proofs, the mutants and Icarus read) and its simulation view in rtl/sim/X.sv (what every
Verilated model runs). For each such module this
finds every parameter set zb_rop gives it, at every lint parameter set (rtl/lint_sets.txt), and
proves the views equal there with Yosys: both views elaborated through the module's harness
(tb/formal/), `equiv_make` pairing their signals by name, `equiv_simple`, `equiv_induct`,
`equiv_status -assert`: from equal states, equal forever.
  zb_mul8: the harness drives k3_i as zb_rop does; every register and output is paired.
  zb_resolve: combinational; the simulation view computes the products only when en_i
    resolves the beat. Both views' products are the same cells on the same inputs, merged
    before the proof (MERGE), which is then of the choice around them.
  zb_plane: the views keep different state (banks, one array), so the harness builds the state
    they must agree on from each view's own registers (taps this script connects after
    flattening) and pairs that; the tile port is compared after tile reads, where zb_rop looks.
    The memories are bit-blasted, so its proof runs at two beats of words, the lint set's other
    parameters as they are: the views' logic is the same at every address.

--ci runs the slice `make test` runs: every zb_mul8 proof, and zb_plane's at each BEAT,
READ_ONLY and FORWARDED of the lint sets, at the narrowest WIDTH zb_rop gives it there (the
views' logic is the same in every bit of a word; the widest take minutes, in `make formal`).

--defect plants a difference in the simulation view of each module (one bit of an internal
signal tied to 0, or a constant edited) and requires the proof to fail: the check can fail.
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

from zbscript import ROOT

# module: (harness module in tb/formal/<harness>.sv, the modules it reads besides, planted
# difference in the simulation view: a signal tied to 0, or ("edit", text, replacement) for a
# view whose signals are all ports or a function's)
VIEWS = {
    "zb_mul8": ("zb_mul8_views", [], "u_mul.pair_d[0]"),
    "zb_plane": ("zb_plane_views", ["zb_tile_mem"], "u_plane.rd_fresh"),
    "zb_resolve": ("zb_resolve_views", [], ("edit", "17'h80", "17'h7f")),  # the rounding
}
# Modules whose views compute the same products in different places (zb_resolve: every lane's
# product in the synthesis view, only under en_i in the simulation view): opt_merge shares the
# $mul cells both views build on the same inputs, so that equiv_simple proves the choice around
# them instead of two multipliers equal bit by bit, which it does not finish.
MERGE = {"zb_resolve"}
# Signals of one name in both views that differ where zb_rop does not look, so not paired: the
# tile port between tile reads (the harness pairs tile_beat_o), the fresh flags but at W2
# (inv_fresh2).
UNPAIRED = {"zb_plane": ["u_plane.tile_rdata_o", "trd", "t_fresh2"]}
PLANE_BEATS = 2  # the words of zb_plane's proof: two beats


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
        # zb_mul8, $paramod$HASH\zb_mul8, $paramod\zb_resolve\BEAT=s32'...: the module's name
        base = re.match(r"(?:\$paramod(?:\$[0-9a-f]+)?\\)?([^\\]+)", mname).group(1)
        if base in VIEWS:
            values = tuple(sorted((k, int(v, 2)) for k, v in
                                  m.get("parameter_default_values", {}).items()))
            found.setdefault(base, set()).add(values)
    return found


def prove(module, values, out, defect):
    if module == "zb_plane":
        values = tuple((k, PLANE_BEATS * dict(values)["BEAT"] if k == "WORDS" else v)
                       for k, v in values)
    tag = "_".join(f"{k}{v}" for k, v in values) or "defaults"
    log = os.path.join(out, f"{module}_{tag}{'_defect' if defect else ''}.log")
    rc, err = yosys(equiv_script(module, values, defect, out), log)
    with open(log) as f:
        text = f.read()
    m = re.search(r"Of those cells (\d+) are proven and (\d+) are unproven", text)
    if not m:  # Yosys stopped before the proof: neither proven nor a difference found
        return None, (err.strip().splitlines() or ["yosys failed"])[-1], log, values
    return (rc == 0 and m.group(2) == "0", f"{m.group(1)} proven, {m.group(2)} unproven", log,
            values)


def equiv_script(module, values, defect, out):
    harness, others, planted = VIEWS[module]
    chparam = " ".join(f"-set {k} {v}" for k, v in values)
    sources = " ".join(["rtl/zb_pkg.sv"] + [f"rtl/{m}.sv" for m in others + [module]] +
                       [f"tb/formal/{harness}.sv"])
    def view(tag, sim):
        reg_taps, mem_taps = plane_taps(values, sim) if module == "zb_plane" else ("", "")
        view_file = f"rtl/sim/{module}.sv"
        if sim and defect and isinstance(planted, tuple):
            view_file = planted_view(module, planted[1:], out)
        read = sources.replace(f"rtl/{module}.sv", view_file) if sim else sources
        return (f"read_verilog -sv -DSYNTHESIS {'-DZB_VIEW_SIM' if sim else ''} {read}\n"
                f"chparam {chparam} {harness}\n"
                f"hierarchy -check -top {harness}\nproc\nflatten\n{reg_taps}"
                f"memory -nomap\nmemory_map\n{mem_taps}"
                + (f"connect -set {planted} 1'b0\n"
                   if sim and defect and isinstance(planted, str) else "") +
                f"opt_clean\ncheck -assert\nrename {harness} {tag}\ndesign -stash {tag}\n")
    unpaired = ""
    if module in UNPAIRED:
        unpaired = os.path.join(os.path.abspath(out), f"{module}_unpaired.txt")  # beside the logs
        with open(unpaired, "w") as f:
            f.write("\n".join(UNPAIRED[module]) + "\n")
        unpaired = f"-blacklist {unpaired} "
    return (view("gold", False) + view("gate", True) +
            "design -copy-from gold -as gold gold\ndesign -copy-from gate -as gate gate\n"
            f"equiv_make {unpaired}gold gate equiv\nhierarchy -top equiv\nasync2sync\n"
            + ("opt_merge\n" if module in MERGE else "") +
            "equiv_simple -seq 2\nequiv_induct -seq 1\nequiv_status -assert\n")


def planted_view(module, edit, out):
    """A copy of the simulation view with one text edited (its first occurrence), in out."""
    with open(os.path.join(ROOT, "rtl", "sim", f"{module}.sv")) as f:
        text = f.read()
    if edit[0] not in text:
        sys.exit(f"equiv: error: rtl/sim/{module}.sv no longer holds '{edit[0]}', the planted "
                 "difference of VIEWS in scripts/equiv.py")
    path = os.path.join(os.path.abspath(out), f"{module}_planted.sv")
    with open(path, "w") as f:
        f.write(text.replace(edit[0], edit[1], 1))
    return path


def plane_taps(values, sim):
    """connect commands for zb_plane_views' taps (tb/formal/zb_plane_views.sv) in one view: the
    registers' (before the memories are mapped, which drops unread wires) and the memory words'
    (after)."""
    p = dict(values)
    width, words, beat, ro = p["WIDTH"], p["WORDS"], p["BEAT"], p["READ_ONLY"]
    ww = width + (0 if ro else p.get("GEN_BITS", 1))
    regs = [f"connect -nounset -set t_{r} u_plane.{r}_q"
            for r in ("wback", "wb2", "epoch", "plane_fresh", "rbank")]
    mems = []
    def tap(taps, wire, lo, w, src):
        taps.append(f"connect -nounset -set {wire}[{lo + w - 1}:{lo}] {src}")
    if sim:
        for q in range(words):
            tap(mems, "inv_mem", q * ww, ww, f"u_plane.mem_q[{q}]")
        regs += ["connect -nounset -set t_prd u_plane.prd_q",
                 "connect -nounset -set t_tile_fresh u_plane.tile_fresh_q",
                 "connect -nounset -set t_fresh2 " + ("0" if ro else "u_plane.fresh2_q")]
    else:
        for b in range(beat):
            for i in range(words // beat):
                tap(mems, "inv_mem", (i * beat + b) * ww, ww,
                    f"u_plane.g_bank[{b}].u_mem.mem_q[{i}]")
            tap(regs, "t_rdata", b * ww, ww, f"u_plane.g_bank[{b}].u_mem.rdata_q")
            if not ro:
                tap(regs, "t_fresh2", b, 1, f"u_plane.g_bank[{b}].g_rw.fresh2_q")
        if ro:
            regs.append("connect -nounset -set t_fresh2 0")
    return "\n".join(regs) + "\n", "\n".join(mems) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="out/equiv", help="output directory (default out/equiv)")
    ap.add_argument("--defect", action="store_true",
                    help="plant a difference in each simulation view; each proof must fail")
    ap.add_argument("--ci", action="store_true",
                    help="the CI slice: zb_plane at the narrowest WIDTH of each BEAT, READ_ONLY, "
                         "FORWARDED")
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
    sim_views = {f[:-3] for f in os.listdir(os.path.join(ROOT, "rtl", "sim")) if f.endswith(".sv")}
    if sim_views != set(VIEWS):
        sys.exit("equiv: error: rtl/sim/ holds simulation views of "
                 f"{', '.join(sorted(sim_views)) or 'nothing'}, VIEWS in scripts/equiv.py proves "
                 f"{', '.join(sorted(VIEWS))}: each view needs its proof")
    missing = set(VIEWS) - {m for m, _ in proofs}
    if missing:
        sys.exit(f"equiv: error: zb_rop has no instance of {', '.join(sorted(missing))} at any "
                 "lint set: VIEWS in scripts/equiv.py names a module the design lost")
    if a.ci:
        narrowest = {}
        for module, values in sorted(proofs, key=lambda k: dict(k[1]).get("WIDTH", 0)):
            rest = tuple(kv for kv in values if kv[0] != "WIDTH")
            key = (module, rest if module == "zb_plane" else values)
            narrowest.setdefault(key, (module, values))
        proofs = {k: proofs[k] for k in narrowest.values()}
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
        ok, cells, log, values = prove(module, values, out, a.defect)
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
    summary = os.path.join(a.out, "summary.csv")
    print(f"equiv: {len(rows) - failed} of {len(rows)} {what}: {summary}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
