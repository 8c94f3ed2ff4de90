#!/usr/bin/env python3
"""Runs a conformance suite on a DUT under a simulator (make conformance, docs/conformance.md).

  conformance.py --suite DIR --sim verilator|icarus --out DIR [--tests a,b] [-j N]
                 [--dut FILE ...] [--define NAME ...] [--plusarg ARG ...] [--param N=V ...] [--gap P]
                 [--lockstep --golden-libs LIB ...]

For each of the suite's configurations (depth bits, coverage samples) the testbench
conformance/sv/zb_conf_tb.sv is built once with the DUT (by default zb_rop and its adapter,
conformance/sv/zb_conf_adapter.sv); each test runs it on its stream.hex and writes
OUT/<test>/got.<plane>.hex and sim.log; then `zblend conformance check` compares the signatures
and names the first differing pixel. A DUT whose adapter has no accumulation plane (its
planes_o) skips the tests that need it: reported as skipped, not passed. Exit 0 when every test
that ran matches, 1 on a mismatch or a simulation that failed, 2 on bad usage.
"""
import argparse
import concurrent.futures
import json
import math
import os
import shlex
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SUITE_VERSION = 4  # conformance/suite.h kSuiteVersion
PLANES = ("color", "depth", "coverage", "peel", "accum")
# The testbench's parameters that each test's configuration sets (manifest "configs").
CONFIG_PARAMS = {"DEPTH_BITS": "depth_bits", "COV_SAMPLES": "coverage_samples",
                 "ACC_BITS": "acc_bits", "REV_BITS": "rev_bits", "WEIGHT_BITS": "weight_bits"}
SV = os.path.join(ROOT, "conformance", "sv")


# The waves' save file: the testbench's signals by role (zb_conf_tb.sv), hex for buses.
WAVE_GROUPS = [
    ("testbench: pass, fragment offered (index in the pass), tile, pass state",
     ["n_passes", "frag_index", "tile_x0[15:0]", "tile_y0[15:0]", "state[12:0]"]),
    ("fragments", ["clk", "frag_valid", "frag_ready", "frag_x[15:0]", "frag_y[15:0]",
                   "frag_z[31:0]", "frag_rgba[31:0]", "frag_cov[7:0]", "idle"]),
    ("tile load and store", ["ld_valid", "ld_ready", "ld_color[31:0]", "st_start", "st_valid",
                             "st_color[31:0]", "st_depth[31:0]"]),
    ("retire port (lock-step)", ["ret_d_valid", "ret_d_pixel[31:0]", "ret_dwe", "ret_wdepth[31:0]",
                                 "ret_vwe", "ret_wcov[7:0]", "ret_c_valid", "ret_c_pixel[31:0]",
                                 "ret_cwe", "ret_wcolor[31:0]", "ret_awe"]),
]


def mismatch_cycle(log_path):
    """The cycle of the first wrong write a lock-step run's log names, or None."""
    try:
        with open(log_path) as f:
            for ln in f:
                if ln.startswith("zb_conf: MISMATCH at cycle "):
                    return int(ln.split()[4].rstrip(":"))
    except OSError:
        pass
    return None


def write_save_file(fst, sim):
    """FST's GTKWave save file beside it: the signals by group, and when the run's sim.log names
    a lock-step mismatch, marker A at the first wrong write's cycle (c * 10 ns)."""
    top = "TOP.zb_conf_tb." if sim == "verilator" else "zb_conf_tb."
    gtkw = os.path.splitext(fst)[0] + ".gtkw"
    log = os.path.join(os.path.dirname(fst), "sim.log")
    cycle = mismatch_cycle(log)
    # At the start of the cycle whose retire port shows the wrong write (the run stops at its
    # edge, the file's last time).
    marker = "-1" if cycle is None else str(cycle * 10 * 1000)
    # The view: the window before the wrong write, or the whole run (its done line's cycles).
    span = 31
    if cycle is None:
        with open(log) as f:
            done = [ln.split(", ")[-1].split()[0] for ln in f if ln.startswith("zb_conf: done:")]
        span = int(done[0]) if done else 1000
    # GTKWave draws 2^-zoom ps per 200 pixels; the wave pane is about 850 pixels wide.
    zoom = -math.log2(max(1, span * 10000 * 200 / 850))
    with open(gtkw, "w") as f:
        f.write(f"[*] zblend conformance testbench; 10 ns clock\n[dumpfile] \"{fst}\"\n")
        f.write(f"[savefile] \"{gtkw}\"\n[size] 1600 900\n[pos] -1 -1\n")
        f.write(f"*{zoom:.6f} {marker}" + " -1" * 26 + "\n")
        if marker != "-1":
            f.write("[markername] Afirst wrong write\n")
        f.write("[sst_width] 260\n[signals_width] 330\n")
        for title, names in WAVE_GROUPS:
            f.write(f"@800200\n-{title}\n")
            for n in names:
                # Buses in hex, the testbench's counts (ints) in decimal.
                flag = "@22" if "[" in n else "@24" if n in ("n_passes", "frag_index") else "@28"
                f.write(f"{flag}\n{top}{n}\n")
            f.write(f"@1000200\n-{title}\n")
    return gtkw


def usage_error(msg):
    print(f"conformance.py: error: {msg}", file=sys.stderr)
    sys.exit(2)


def rtl_sources():
    """zb_rop's sources, the package first, and its adapter."""
    rtl = os.path.join(ROOT, "rtl")
    files = sorted(os.path.join(rtl, f) for f in os.listdir(rtl) if f.endswith(".sv"))
    pkg = os.path.join(rtl, "zb_pkg.sv")
    return [pkg] + [f for f in files if f != pkg] + [os.path.join(SV, "zb_conf_adapter.sv")]


def load_suite(suite, only):
    path = os.path.join(suite, "manifest.json")
    try:
        with open(path) as f:
            m = json.load(f)
    except (OSError, ValueError) as e:
        usage_error(f"{path}: {e} (write a suite with `zblend conformance export DIR`)")
    if m.get("suite") != "zblend-conformance" or m.get("version") != SUITE_VERSION:
        usage_error(f"{path}: not a version {SUITE_VERSION} zblend conformance suite")
    configs = {c["name"]: c for c in m["configs"]}
    tests = m["tests"]
    if only:
        names = {t["name"] for t in tests}
        unknown = [n for n in only if n not in names]
        if unknown:
            usage_error(f"--tests: no test {', '.join(unknown)} in {path}")
        tests = [t for t in tests if t["name"] in only]
    return configs, tests


def build(sim, config, a, bdir):
    """Builds the testbench for one configuration; returns the command that runs it."""
    params = {k: config[v] for k, v in CONFIG_PARAMS.items()}
    params.update(a.params)
    sources = a.dut or rtl_sources()
    tb = [os.path.join(SV, "zb_conf_tb.sv")]
    defines = list(a.define)
    if a.lockstep:
        defines.append("ZB_CONF_LOCKSTEP")
        tb = [os.path.join(SV, "zb_golden_pkg.sv"),
              os.path.join(SV, "zb_conf_scoreboard.sv")] + tb
    os.makedirs(bdir, exist_ok=True)
    if sim == "verilator":
        # zblend's sources lint clean (-Wall, their waivers); a team's DUT warns without failing.
        cmd = ["verilator", "--binary", "--timing", "--assert", "-Wall", "--timescale", "1ns/1ps",
               "--top-module", "zb_conf_tb", "-Mdir", bdir, "-o", "zb_conf_tb", "-j", str(a.jobs)]
        cmd += ["--trace-fst", "--trace-structs"] if a.waves else []
        cmd += ["-Wno-fatal"] if a.dut else [os.path.join(ROOT, "rtl", "lint_waivers.vlt")]
        cmd += [os.path.join(SV, "zb_conf.vlt")]
        cmd += [os.path.join(SV, "zb_golden_pkg.vlt")] if a.lockstep else []
        cmd += [f"-G{k}={v}" for k, v in params.items()]
        cmd += [f"+define+{d}" for d in defines]
        cmd += sources + tb + list(a.golden_libs)
        if a.golden_libs:
            cmd += ["-LDFLAGS", "-lfmt -lpthread"]
        run_cmd = [os.path.join(bdir, "zb_conf_tb")]
    else:
        if a.lockstep:
            usage_error("--lockstep needs DPI-C: run it under --sim verilator")
        vvp = os.path.join(bdir, "zb_conf_tb.vvp")
        cmd = ["iverilog", "-g2012", "-o", vvp, "-s", "zb_conf_tb"]
        cmd += [f"-Pzb_conf_tb.{k}={v}" for k, v in params.items()]
        cmd += [f"-D{d}" for d in defines]
        cmd += [os.path.join(SV, "zb_conf_timescale.sv")] + sources + tb
        run_cmd = ["vvp", "-n", vvp] + (["-fst"] if a.waves else [])
    t0 = time.time()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(bdir, "build.log"), "w") as f:
        f.write(shlex.join(cmd) + "\n" + p.stdout)
    if p.returncode != 0:
        print(p.stdout[-4000:], file=sys.stderr)
        print(f"conformance: FAILED to build the {sim} testbench for {config['name']}: "
              f"{shlex.join(cmd)}", file=sys.stderr)
        sys.exit(1)
    print(f"conformance: {sim} testbench for {config['name']} built in {time.time() - t0:.0f} s",
          file=sys.stderr, flush=True)
    return run_cmd


def run_test(test, run_cmd, a):
    d = os.path.join(a.out, test["name"])
    os.makedirs(d, exist_ok=True)
    for plane in PLANES:
        try:
            os.remove(os.path.join(d, f"got.{plane}.hex"))
        except FileNotFoundError:
            pass
    # A lock-step run that failed here before: its waves start 30 cycles before the wrong write.
    first_wrong = mismatch_cycle(os.path.join(d, "sim.log"))
    cmd = run_cmd + [f"+stream={os.path.join(a.suite, test['name'], 'stream.hex')}",
                     f"+out={d}", f"+gap={a.gap}", f"+seed={a.seed}"] + list(a.plusarg)
    if a.waves:
        cmd.append(f"+dump={os.path.join(d, 'waves.fst')}")
        if first_wrong is not None:
            cmd.append(f"+dump_from={max(0, first_wrong - 30)}")
    t0 = time.time()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(d, "sim.log"), "w") as f:
        f.write(shlex.join(cmd) + "\n" + p.stdout)
    if a.waves:
        write_save_file(os.path.join(d, "waves.fst"), a.sim)
    # Icarus's $fatal exits 0 on some versions: a run counts only with its done (or skip) line.
    skipped = "zb_conf: skip:" in p.stdout
    ok = p.returncode == 0 and ("zb_conf: done:" in p.stdout or skipped)
    first = next((ln for ln in p.stdout.splitlines()
                  if ln.startswith(("zb_conf: FAILED", "zb_conf: MISMATCH", "%Error"))), "")
    # The DUT's planes, as the testbench read them from the adapter.
    no_accum = any(ln.startswith("zb_conf: planes:") and "accum" not in ln.split()
                   for ln in p.stdout.splitlines())
    return test["name"], ok, time.time() - t0, first, skipped, no_accum


def strip_option(argv, name):
    """argv without `name VALUE` and `name=VALUE`."""
    out, skip = [], False
    for x in argv:
        if skip:
            skip = False
        elif x == name:
            skip = True
        elif not x.startswith(name + "="):
            out.append(x)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("--suite", required=True, help="a suite written by `zblend conformance export`")
    ap.add_argument("--sim", required=True, choices=["verilator", "icarus"])
    ap.add_argument("--out", required=True, help="got signatures, logs and the builds")
    ap.add_argument("--tests", default="", help="comma-separated test names (default: all)")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--dut", nargs="+", default=[],
                    help="the DUT's sources and its adapter (default: rtl/*.sv, zb_conf_adapter.sv)")
    ap.add_argument("--define", action="append", default=[],
                    help="a preprocessor define, e.g. ZB_INJECT_BLEND_BUG")
    ap.add_argument("--plusarg", action="append", default=[], help="given to every run, e.g. +zb_bug_window")
    ap.add_argument("--param", action="append", default=[], metavar="NAME=VALUE",
                    help="a parameter of zb_conf_tb, e.g. TILE_W=32 (the DUT's tile, given to the adapter)")
    ap.add_argument("--gap", type=int, default=0, help="percent of cycles with no fragment offered")
    ap.add_argument("--seed", type=int, default=1, help="the gaps' pattern")
    ap.add_argument("--lockstep", action="store_true",
                    help="the golden model as a DPI-C scoreboard beside the DUT (verilator)")
    ap.add_argument("--golden-libs", nargs="+", default=[],
                    help="with --lockstep: the C API's libraries to link")
    ap.add_argument("--waves", action="store_true",
                    help="every run writes OUT/<test>/waves.fst (the testbench built with tracing)")
    ap.add_argument("--zblend", default=os.path.join(ROOT, "build", "zblend"),
                    help="the zblend command that checks the signatures")
    a = ap.parse_args()
    if not 0 <= a.gap <= 95:
        usage_error(f"--gap {a.gap}: choose 0 to 95 (percent)")
    if a.jobs < 1:
        usage_error(f"-j {a.jobs}: at least 1")
    if a.lockstep and not a.golden_libs:
        usage_error("--lockstep needs --golden-libs (the C API's static libraries)")
    a.params = {}
    for p in a.param:
        name, eq, value = p.partition("=")
        if not eq or not name.isidentifier() or not value.isdigit():
            usage_error(f"--param {p!r}: give NAME=VALUE, e.g. TILE_W=32")
        if name in CONFIG_PARAMS:
            usage_error(f"--param {name}: set by each test's configuration in the suite")
        a.params[name] = int(value)
    a.golden_libs = [os.path.abspath(f) for f in a.golden_libs]
    for f in a.golden_libs:
        if not os.path.isfile(f):
            usage_error(f"--golden-libs: no file {f} (build it: cmake --build build "
                        "--target zbgolden_dpi)")
    a.suite = os.path.abspath(a.suite)
    a.out = os.path.abspath(a.out)
    only = [t for t in a.tests.split(",") if t]
    configs, tests = load_suite(a.suite, only)

    by_config = {}
    for t in tests:
        by_config.setdefault(t["config"], []).append(t)
    runs = []
    for name, group in by_config.items():
        kind = f"{a.sim}{'-waves' if a.waves else ''}-{name}"
        run_cmd = build(a.sim, configs[name], a, os.path.join(a.out, "build", kind))
        runs += [(t, run_cmd) for t in group]

    unfinished = set()
    no_accum = False
    t0 = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = [pool.submit(run_test, t, c, a) for t, c in runs]
        for i, f in enumerate(concurrent.futures.as_completed(futures), 1):
            name, ok, secs, first, skipped, lacks_accum = f.result()
            no_accum |= lacks_accum
            if not ok:
                unfinished.add(name)
            verdict = "skipped (no accumulation plane)" if ok and skipped else "ok" if ok else "FAILED"
            print(f"conformance: [{i}/{len(runs)}] {verdict} {name} {secs:.1f} s"
                  + (f": {first}" if first else ""), file=sys.stderr, flush=True)
    print(f"conformance: {len(runs)} simulations on {a.sim} in {time.time() - t0:.0f} s, "
          f"{len(unfinished)} failed to finish", file=sys.stderr)
    check = [a.zblend, "conformance", "check", a.suite, a.out]
    if only:
        check += ["--tests", ",".join(only)]
    if no_accum:
        check.append("--no-accum")
    p = subprocess.run(check, stdout=subprocess.PIPE, text=True)
    sys.stdout.write(p.stdout)
    if p.returncode == 2:
        sys.exit(2)
    bad = sorted({ln.split()[1].rstrip(":") for ln in p.stdout.splitlines() if ln.startswith("FAIL ")}
                 | unfinished)
    if bad and not a.waves:
        # The same run again, only the failing tests, with waves: one command to paste.
        again = [sys.argv[0]] + [x for x in sys.argv[1:]]
        again = strip_option(again, "--tests") + ["--tests", ",".join(bad), "--waves"]
        print(f"conformance: reproduce with waves: python3 {shlex.join(again)}", file=sys.stderr)
    elif bad:
        for t in bad:
            w = os.path.join(a.out, t, "waves")
            print(f"conformance: waves: gtkwave {w}.gtkw  ({w}.fst, its save file beside it)",
                  file=sys.stderr)
    sys.exit(1 if p.returncode != 0 or unfinished else 0)


if __name__ == "__main__":
    main()
