#!/usr/bin/env python3
"""Runs a conformance suite on a DUT under a simulator (make conformance, docs/conformance.md).

  conformance.py --suite DIR --sim verilator|icarus --out DIR [--profile FILE]
                 [--features GLOBS] [--tests GLOBS] [--feature GLOB ...] [--list] [-j N]
                 [--timeout S] [--watchdog N] [--dut FILE ...] [--define NAME ...]
                 [--plusarg ARG ...] [--param N=V ...] [--gap P] [--seed N] [--quick]
                 [--timing tight|loose|random] [--schedule resident|pass]
                 [--lockstep --golden-libs LIB ...]

The DUT declares what it supports in a profile (--profile; zb_rop's, the full one, by default):
features, testbench parameters, its sources, whether it has a retire port. A test whose manifest
features are not all in the profile is NOT SUPPORTED: not run, not failed, counted apart. For
each of the suite's configurations (depth bits, coverage samples) the testbench
conformance/sv/zb_conf_tb.sv is built once with the DUT; each test runs it on its stream.hex
(killed after --timeout seconds; the testbench's watchdog fails a DUT that stops making
progress) and writes OUT/<test>/got.<plane>.hex and sim.log; then `zblend conformance check`
compares the signatures and names the first differing pixel (a finished simulation's progress
line says `ran`: the verdict is the checker's line). Every file of the suite is checked against
the manifest's SHA-256 first: a corrupt suite is bad input, never a DUT failure.
Results: this text, OUT/results.json and OUT/junit.xml. Exit 0 when every test that ran
passed, 1 on a failure, a timeout or when no test was supported, 2 on bad usage or a bad suite.

The testbench drives the port contract's tightest legal timing by default (--timing tight: each
event at the first edge allowed), or a cycle more before each wait (loose), or 0 to 3 cycles drawn
from --seed (random). A DUT whose profile says "resident_tile" runs the passes between frame
operations on resident tiles (one load, each pass's state and fragments, one store), as a tiled
GPU runs a multi-pass method; --schedule pass runs it tile by tile and pass by pass instead.

Tiers: --quick runs the manifest's quick tier (the fewest tests keeping the most of the reach);
the whole suite is the full tier; `zblend conformance export --seed N` writes the seeded random
tier, a suite of its own.

Suite versions: 8 (the blends' generated tests at 16 and 32 bits; 7 added mlab-K's layers, 6 the
generated tests and tiers). Earlier suites lack
what this script selects by or the layers tests: export the suite again with this zblend.
"""
import argparse
import concurrent.futures
import fnmatch
import glob
import hashlib
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tarfile
import time
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SUITE_VERSIONS = (8,)  # the versions this script runs (conformance/suite.h kSuiteVersion)
# Why each earlier version is refused.
REFUSED = {v: "it has no per-test features or file checksums (version 5 added them)"
           for v in range(1, 5)}
REFUSED[5] = ("it has no tiers and none of the tests generated from the coverage plan "
              "(version 6 added them)")
REFUSED[6] = ("it has no tests of mlab-K's layers, and its PASS words carry the 13-bit pass "
              "state (version 7 added them)")
REFUSED[7] = ("at 16 and 32 bits it has none of the tests of the replace, alpha and additive "
              "blends' states, values and same-pixel runs (version 8 added them)")
TIMINGS = {"tight": 0, "loose": 1, "random": 2}  # zb_conf_tb's +timing
PLANES = ("color", "depth", "coverage", "peel", "accum")
# The testbench's parameters that each test's configuration sets (manifest "configs").
CONFIG_PARAMS = {"DEPTH_BITS": "depth_bits", "COV_SAMPLES": "coverage_samples",
                 "ACC_BITS": "acc_bits", "REV_BITS": "rev_bits", "WEIGHT_BITS": "weight_bits"}
# In the source tree: ROOT/conformance/sv and the checker build/zblend. In the kit (make kit):
# this script in share/zblend-conformance/scripts, the SV files in ../sv, the checker in bin/.
SV = os.path.join(ROOT, "conformance", "sv")
if not os.path.isdir(SV):
    SV = os.path.join(ROOT, "sv")
CHECKERS = [os.path.join(ROOT, "build", "zblend"),
            os.path.normpath(os.path.join(ROOT, "..", "..", "bin", "zblend-conformance")),
            os.path.join(ROOT, "build-kit", "zblend-conformance")]
DEFAULT_PROFILE = os.path.join(SV, "zb_rop.profile.json")
# The manifest's feature names (conformance/export.cpp trace_features): a profile's pattern must
# match one, so a misspelt feature is an error, not a silently unsupported test.
FEATURES = (["blend." + b for b in ("replace", "alpha", "additive", "coverage", "under",
                                    "accumulate")]
            + ["depth_func." + f for f in ("never", "less", "equal", "lequal", "greater",
                                           "notequal", "gequal", "always")]
            + ["blend.layers"] + [f"layers.{k}" for k in range(1, 9)]
            + ["depth_write", "color_mask", "peel_test", "accum_plane"]
            + [f"depth_bits.{b}" for b in range(8, 33)] + [f"coverage_samples.{n}" for n in
                                                             (1, 2, 4, 8, 16)])
PROFILE_KEYS = {"dut", "features", "params", "retire_port", "resident_tile", "sources", "defines",
                "adapter_version", "arithmetic", "checkout", "include_dirs"}
# A declared arithmetic's name (docs/datapath.md "Declared arithmetic"; rop/arithmetic.h): the
# checker replays the streams in it. zblend's is the default.
# "cts" asks instead for the Khronos CTS blend tests' verdict (per-channel thresholds), reported
# apart from exact passes as cts_pass.
ARITHMETIC = re.compile(r"zblend|cts|(each|sum)-(zblend|round255|floor256|ceil256|round256)(-one256)?")
# The adapter interface's versions (docs/conformance.md "Adapter versions"): each adds ports, and
# the testbench connects only a version's own (ZB_CONF_ADAPTER_V<N>), so an adapter written for
# an earlier version keeps building; what its ports cannot carry is NOT SUPPORTED, with the reason.
ADAPTER_VERSION = 7
ADAPTER_LACKS = {  # version: (the features it cannot run, why)
    6: (["blend.layers", "layers.*"],
        "adapter version 6 has no layers port (state_layers_i, st_resolve_i, layers_o came with "
        "version 7)"),
    7: ([], ""),
}


# The waves' save file: the testbench's signals by role (zb_conf_tb.sv), hex for buses.
WAVE_GROUPS = [
    ("testbench: pass, fragment offered (index in the pass), tile, pass state",
     ["pass_index", "frag_index", "tile_x0[15:0]", "tile_y0[15:0]", "state[12:0]",
      "state_layers[2:0]"]),
    ("fragments", ["clk", "frag_valid", "frag_ready", "frag_x[15:0]", "frag_y[15:0]",
                   "frag_z[31:0]", "frag_rgba[31:0]", "frag_cov[7:0]", "idle"]),
    ("tile load and store", ["ld_valid", "ld_ready", "ld_color[31:0]", "st_start", "st_resolve",
                             "st_valid",
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
                flag = "@22" if "[" in n else "@24" if n in ("pass_index", "frag_index") else "@28"
                f.write(f"{flag}\n{top}{n}\n")
            f.write(f"@1000200\n-{title}\n")
    return gtkw


def usage_error(msg):
    print(f"conformance.py: error: {msg}", file=sys.stderr)
    sys.exit(2)


def unpack_suite(archive, out):
    """A suite archive (.tar.gz, as `make kit` writes it) unpacked into OUT/suite; its folder."""
    dest = os.path.join(out, "suite")
    try:
        with tarfile.open(archive) as tar:
            for m in tar.getmembers():
                if m.name.startswith("/") or ".." in m.name.split("/") or not (m.isfile() or m.isdir()):
                    usage_error(f"--suite {archive}: member {m.name!r} is not a plain file inside it")
            if os.path.isdir(dest):
                shutil.rmtree(dest)
            tar.extractall(dest)
    except (OSError, tarfile.TarError) as e:
        usage_error(f"--suite {archive}: {e}")
    for d, _, files in os.walk(dest):
        if "manifest.json" in files:
            return d
    usage_error(f"--suite {archive}: no manifest.json inside (is it a suite archive?)")


def load_suite(suite):
    """The manifest's configs, tests and version, after every file matched its checksum."""
    path = os.path.join(suite, "manifest.json")
    again = "export it again: zblend conformance export DIR"
    try:
        with open(path) as f:
            m = json.load(f)
    except (OSError, ValueError) as e:
        usage_error(f"{path}: {e} (write a suite with `zblend conformance export DIR`)")
    if not isinstance(m, dict) or m.get("suite") != "zblend-conformance":
        usage_error(f"{path}: not a zblend conformance suite (no \"suite\": \"zblend-conformance\")")
    v = m.get("version")
    if v not in SUITE_VERSIONS:
        why = REFUSED.get(v, "it is newer than this script: use the kit of the zblend that wrote it")
        usage_error(f"{path}: suite version {v} is refused: {why}; this script runs version "
                    f"{', '.join(map(str, SUITE_VERSIONS))} ({again})")
    try:
        configs = {c["name"]: c for c in m["configs"]}
        tests = m["tests"]
        for t in tests:
            t["features"], t["files"], t["config"]  # noqa: B018 (present in every entry)
    except (KeyError, TypeError) as e:
        usage_error(f"{path}: malformed manifest, no {e} in an entry ({again})")
    for t in tests:
        for name, want in sorted(t["files"].items()):
            fp = os.path.join(suite, t["name"], name)
            try:
                with open(fp, "rb") as f:
                    got = hashlib.sha256(f.read()).hexdigest()
            except OSError as e:
                usage_error(f"corrupt suite: {fp}: {e.strerror} ({again})")
            if got != want:
                usage_error(f"corrupt suite: {fp}: SHA-256 {got[:16]}..., the manifest says "
                            f"{want[:16]}... (truncated or changed; {again})")
    return configs, tests, v


def resolve_paths(path, prof, key, checkout, must_match):
    """A profile's list of paths: relative to its folder, absolute, or under the DUT's own
    checkout ("$CHECKOUT/..." and --checkout DIR); globs allowed."""
    base = os.path.dirname(os.path.abspath(path))
    out = []
    for pattern in prof[key]:
        if not isinstance(pattern, str):
            usage_error(f"--profile {path}: {key}: {pattern!r} is not a path")
        if pattern.startswith("$CHECKOUT/"):
            if not checkout:
                c = prof.get("checkout") or {}
                usage_error(f"--profile {path}: its {key} are in a checkout of "
                            f"{c.get('name', 'the DUT')}"
                            + (f" ({c['url']} at {c['commit']})" if "url" in c and "commit" in c
                               else "")
                            + ": give its folder with --checkout DIR (docs/conformance.md "
                            "\"Outside ROPs\")")
            pattern = os.path.join(checkout, pattern[len("$CHECKOUT/"):])
        found = sorted(glob.glob(os.path.join(base, pattern)))
        if not found and must_match:
            usage_error(f"--profile {path}: {key[:-1]} {pattern!r} matches no file in "
                        f"{checkout if pattern.startswith(checkout or chr(0)) else base}")
        out += [f for f in found if f not in out]
    return out


def check_checkout(prof, checkout):
    """The checkout's commit and local changes, for results.json: warns when it is not at the
    commit the profile names, or when tracked files are modified (the run is then of a modified
    DUT, not of that commit)."""
    want = (prof.get("checkout") or {}).get("commit")
    if not checkout:
        return None
    p = subprocess.run(["git", "-C", checkout, "rev-parse", "HEAD"], stdout=subprocess.PIPE,
                       stderr=subprocess.DEVNULL, text=True)
    have = p.stdout.strip()
    if p.returncode != 0:
        print(f"conformance: warning: --checkout {checkout} is not a git checkout: its commit is "
              f"unknown" + (f" (the profile was written for {want})" if want else ""),
              file=sys.stderr)
        return {"path": checkout, "commit": None, "modified": []}
    st = subprocess.run(["git", "-C", checkout, "status", "--porcelain", "--untracked-files=no"],
                        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    modified = sorted(ln[3:] for ln in st.stdout.splitlines() if ln.strip())
    if want and not have.startswith(want) and not want.startswith(have):
        print(f"conformance: warning: --checkout {checkout} is at {have[:12]}; the profile was "
              f"written for {want[:12]}", file=sys.stderr)
    else:
        print(f"conformance: checkout {checkout} at {have[:12]}", file=sys.stderr)
    if modified:
        print(f"conformance: warning: --checkout {checkout} has {len(modified)} modified file"
              f"{'s' if len(modified) != 1 else ''} ({', '.join(modified[:3])}"
              f"{', ...' if len(modified) > 3 else ''}): the run is of a modified DUT, not of "
              f"{have[:12]}", file=sys.stderr)
    return {"path": checkout, "commit": have, "modified": modified}


def load_profile(path, features_arg, checkout=None):
    """The DUT's profile: {features, params, retire_port, sources, defines, dut, path, ...}."""
    prof = {"features": [], "params": {}, "retire_port": False, "resident_tile": False,
            "sources": [], "defines": [], "dut": "", "path": path, "arithmetic": "zblend",
            "include_dirs": []}
    try:
        with open(path) as f:
            j = json.load(f)
    except (OSError, ValueError) as e:
        usage_error(f"--profile {path}: {e}")
    if not isinstance(j, dict):
        usage_error(f"--profile {path}: not a JSON object")
    unknown = sorted(set(j) - PROFILE_KEYS)
    if unknown:
        usage_error(f"--profile {path}: unknown key {unknown[0]!r} (keys: "
                    f"{', '.join(sorted(PROFILE_KEYS))})")
    prof.update(j)
    if prof.get("checkout") is not None and not isinstance(prof["checkout"], dict):
        usage_error(f"--profile {path}: checkout: give {{\"name\", \"url\", \"commit\"}}")
    prof["sources"] = resolve_paths(path, prof, "sources", checkout, True)
    prof["include_dirs"] = resolve_paths(path, prof, "include_dirs", checkout, True)
    if features_arg is not None:
        prof["features"] = [f for f in features_arg.split(",") if f]
    for pattern in prof["features"]:
        if not fnmatch.filter(FEATURES, pattern):
            usage_error(f"feature {pattern!r} (in {'--features' if features_arg else path}) names "
                        f"no feature; they are: {', '.join(FEATURES[:18])}, depth_bits.N, "
                        "coverage_samples.N (globs allowed)")
    if not isinstance(prof["arithmetic"], str) or not ARITHMETIC.fullmatch(prof["arithmetic"]):
        usage_error(f"--profile {path}: arithmetic: {prof['arithmetic']!r} is not an arithmetic: "
                    "zblend, or <each|sum>-<zblend|round255|floor256|ceil256|round256>[-one256] "
                    "(docs/datapath.md \"Declared arithmetic\")")
    v = prof.get("adapter_version")
    if v is not None and (isinstance(v, bool) or v not in ADAPTER_LACKS):
        usage_error(f"--profile {path}: adapter_version: {v!r} is not one of "
                    f"{', '.join(map(str, sorted(ADAPTER_LACKS)))} (docs/conformance.md "
                    "\"Adapter versions\")")
    for k in ("retire_port", "resident_tile"):
        if not isinstance(prof[k], bool):
            usage_error(f"--profile {path}: {k}: {prof[k]!r} is not true or false")
    for k, v in prof["params"].items():
        if not k.isidentifier() or not isinstance(v, int):
            usage_error(f"--profile {path}: params: {k!r}: {v!r} is not NAME: integer")
    return prof


def missing_features(test, prof):
    """The test's features the profile does not cover."""
    return [f for f in test["features"]
            if not any(fnmatch.fnmatchcase(f, p) for p in prof["features"])]


def adapter_version(prof, sources):
    """The adapter's interface version: the profile's adapter_version, else read off the
    adapter's ports (a profile written before the key existed): version 7's layers port, or 6.
    Returns (version, how it was known)."""
    if prof.get("adapter_version") is not None:
        return prof["adapter_version"], "the profile's adapter_version"
    for f in sources:
        try:
            with open(f, errors="replace") as fh:
                text = fh.read()
        except OSError:
            continue
        m = re.search(r"\bmodule\s+zb_conf_adapter\b(.*?)\);", text, re.S)
        if m:
            v = 7 if re.search(r"\bstate_layers_i\b", m.group(1)) else 6
            return v, f"read off {os.path.basename(f)}'s ports; the profile names no adapter_version"
    return ADAPTER_VERSION, "no module zb_conf_adapter found in the sources: the current version"


def adapter_lacks(test, version):
    """The test's features that the adapter's interface version cannot carry."""
    globs = ADAPTER_LACKS[version][0]
    return [f for f in test["features"] if any(fnmatch.fnmatchcase(f, g) for g in globs)]


def select(tests, globs, feature_globs):
    """The tests named by --tests (globs) and using every --feature (globs), in suite order."""
    chosen = tests
    if globs:
        for g in globs:
            if not any(fnmatch.fnmatchcase(t["name"], g) for t in tests):
                usage_error(f"--tests: {g!r} names no test of the suite (`--list` shows them)")
        chosen = [t for t in chosen if any(fnmatch.fnmatchcase(t["name"], g) for g in globs)]
    for g in feature_globs:
        if not fnmatch.filter(FEATURES, g):
            usage_error(f"--feature {g!r} names no feature")
        chosen = [t for t in chosen if fnmatch.filter(t["features"], g)]
    if not chosen:
        usage_error("no test of the suite matches --tests and --feature")
    return chosen


def build(sim, config, a, bdir):
    """Builds the testbench for one configuration; returns the command that runs it."""
    params = {k: config[v] for k, v in CONFIG_PARAMS.items()}
    params.update(a.prof["params"])
    params.update(a.params)
    sources = (a.dut or a.prof["sources"]) + a.extra_sources
    tb = [os.path.join(SV, "zb_conf_tb.sv")]
    defines = list(a.prof["defines"]) + list(a.define)
    if a.adapter_version != ADAPTER_VERSION:
        defines.append(f"ZB_CONF_ADAPTER_V{a.adapter_version}")
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
        cmd += [os.path.join(ROOT, "rtl", "lint_waivers.vlt")] if a.ours else ["-Wno-fatal"]
        cmd += [os.path.join(SV, "zb_conf.vlt")]
        cmd += [os.path.join(SV, "zb_golden_pkg.vlt")] if a.lockstep else []
        cmd += [f"-G{k}={v}" for k, v in params.items()]
        cmd += [f"+define+{d}" for d in defines]
        cmd += [f"+incdir+{d}" for d in a.prof["include_dirs"]]
        cmd += list(a.verilator_arg) + sources + tb + list(a.golden_libs)
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
        cmd += [f"-I{d}" for d in a.prof["include_dirs"]]
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
    """Runs one test's simulation; returns (name, finished, seconds, first error line, verdict
    hint: "timeout", "not_supported" (the testbench skipped it) or "", DUT lacks accum)."""
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
                     f"+out={d}", f"+gap={a.gap}", f"+seed={a.seed}",
                     f"+watchdog={a.watchdog}", f"+timing={TIMINGS[a.timing]}",
                     f"+resident={1 if a.schedule == 'resident' else 0}"] + list(a.plusarg)
    if a.waves:
        cmd.append(f"+dump={os.path.join(d, 'waves.fst')}")
        if first_wrong is not None:
            cmd.append(f"+dump_from={max(0, first_wrong - 30)}")
    t0 = time.time()
    # Line-buffered, so a run killed at --timeout keeps what it printed.
    p = subprocess.Popen(["stdbuf", "-oL", "-eL"] + cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         start_new_session=True)
    timed_out = False
    try:
        out, _ = p.communicate(timeout=a.timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(p.pid, 9)
        out, _ = p.communicate()
        out += (f"conformance: killed after {a.timeout} s (--timeout): the simulation's output "
                "up to then is above\n")
    secs = time.time() - t0
    with open(os.path.join(d, "sim.log"), "w") as f:
        f.write(shlex.join(cmd) + "\n" + out)
    if a.waves and os.path.exists(os.path.join(d, "waves.fst")):
        write_save_file(os.path.join(d, "waves.fst"), a.sim)
    lines = out.splitlines()
    # Icarus's $fatal exits 0 on some versions: a run counts only with its done (or skip) line.
    skipped = any(ln.startswith("zb_conf: skip:") for ln in lines)
    finished = not timed_out and p.returncode == 0 and (
        skipped or any(ln.startswith("zb_conf: done:") for ln in lines))
    first = next((ln for ln in lines if ln.startswith(
        ("zb_conf: PROTOCOL", "zb_conf: WATCHDOG", "zb_conf: FAILED", "zb_conf: MISMATCH",
         "%Error"))), "")
    if timed_out:
        first = f"killed after {a.timeout} s (--timeout){': ' + first if first else ''}"
    elif skipped and finished:  # the testbench's reason: "zb_conf: skip: STREAM: why"
        first = next(ln for ln in lines if ln.startswith("zb_conf: skip:")).split(": ", 3)[-1]
    elif not finished and not first:
        first = f"the simulation exited {p.returncode} without its done line (sim.log)"
    # The DUT's planes, as the testbench read them from the adapter.
    no_accum = any(ln.startswith("zb_conf: planes:") and "accum" not in ln.split()
                   for ln in lines)
    hint = "timeout" if timed_out else "not_supported" if skipped and finished else ""
    return test["name"], finished, secs, first, hint, no_accum


def layers_skip(sim):
    """Whether a run (finished, seconds, first line, hint) was skipped by the testbench for the
    layers its test keeps a pixel (more than the adapter's layers_o)."""
    return sim[3] == "not_supported" and "layers a pixel" in sim[2]


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


def write_results(a, results, counts, suite_version, no_accum):
    """OUT/results.json and OUT/junit.xml: every selected test's verdict, in suite order, and
    whether the DUT has the accumulation plane (`zblend conformance check SUITE OUT` checks the
    tests simulated here as this run checked them)."""
    doc = {"suite": a.suite, "suite_version": suite_version, "sim": a.sim,
           "timing": a.timing, "schedule": a.schedule, "seed": a.seed,
           "profile": a.prof["path"], "dut": a.prof["dut"], "accum_plane": not no_accum,
           "adapter_version": a.adapter_version, "arithmetic": a.prof["arithmetic"],
           "checkout": a.checkout_state,
           "counts": counts, "tests": results}
    with open(os.path.join(a.out, "results.json"), "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    root = ET.Element("testsuites")
    suite = ET.SubElement(root, "testsuite", name=f"zblend-conformance-{a.sim}",
                          tests=str(len(results)), failures=str(counts["fail"]),
                          errors=str(counts["timeout"]),
                          skipped=str(counts["not_supported"] + counts["not_run"]),
                          time=f"{sum(r['seconds'] for r in results):.3f}")
    for r in results:
        case = ET.SubElement(suite, "testcase", classname=f"conformance.{r['config']}",
                             name=r["name"], time=f"{r['seconds']:.3f}")
        if r["verdict"] == "fail":
            ET.SubElement(case, "failure", message=r["message"]).text = r["message"]
        elif r["verdict"] == "timeout":
            ET.SubElement(case, "error", message=r["message"]).text = r["message"]
        elif r["verdict"] == "not_supported":
            ET.SubElement(case, "skipped", message="NOT SUPPORTED: " + r["message"])
        elif r["verdict"] == "not_run":
            ET.SubElement(case, "skipped", message=r["message"])
        elif r["verdict"] == "cts_pass":
            ET.SubElement(case, "system-out").text = "passed by the CTS threshold only: " + r["message"]
    ET.ElementTree(root).write(os.path.join(a.out, "junit.xml"), encoding="utf-8",
                               xml_declaration=True)


VERDICTS = ("pass", "cts_pass", "fail", "not_supported", "timeout", "not_run")


def check_tests(a, names, no_accum):
    """zblend conformance check on the named tests: {name: (pass | FAIL | skip, why)}."""
    if not names:
        return {}
    sub = ["check"] if os.path.basename(a.zblend).startswith("zblend-conformance") else \
        ["conformance", "check"]
    check = [a.zblend] + sub + [a.suite, a.out, "--tests", ",".join(names)]
    if no_accum:
        check.append("--no-accum")
    check += ["--arithmetic", a.prof["arithmetic"]]
    p = subprocess.run(check, stdout=subprocess.PIPE, text=True)
    sys.stdout.write(p.stdout)
    if p.returncode == 2:
        sys.exit(2)
    out = {}
    for ln in p.stdout.splitlines():
        word, _, rest = ln.partition(" ")
        if word in ("pass", "FAIL", "skip", "cts"):
            name, _, why = rest.strip().partition(":")
            out[name] = (word, why.strip())
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("--suite", required=True,
                    help="a suite written by `zblend conformance export`, or its .tar.gz archive")
    ap.add_argument("--sim", required=True, choices=["verilator", "icarus"])
    ap.add_argument("--out", required=True, help="got signatures, logs, results and the builds")
    ap.add_argument("--profile", default=DEFAULT_PROFILE,
                    help="the DUT's profile, JSON (default: zb_rop's, conformance/sv/zb_rop.profile.json)")
    ap.add_argument("--arithmetic", default=None, metavar="NAME",
                    help="the DUT's blend arithmetic, in place of the profile's (docs/datapath.md "
                         "\"Declared arithmetic\": zblend, sum-round255, sum-ceil256, ...)")
    ap.add_argument("--checkout", default=None, metavar="DIR",
                    help="the DUT's own checkout, for a profile whose sources say $CHECKOUT/... "
                         "(an outside ROP run in place: docs/conformance.md \"Outside ROPs\")")
    ap.add_argument("--features", default=None, metavar="GLOBS",
                    help="comma-separated features the DUT supports, in place of the profile's")
    ap.add_argument("--tests", default="", metavar="GLOBS",
                    help="comma-separated test names or globs, e.g. 'cad-*,hazard' (default: all)")
    ap.add_argument("--feature", action="append", default=[], metavar="GLOB",
                    help="only the tests that use this feature, e.g. blend.alpha (repeatable: all of them)")
    ap.add_argument("--list", action="store_true",
                    help="list the selected tests, supported or not and why; run nothing")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--timeout", type=float, default=600,
                    help="seconds a test's simulation may take before it is killed (default 600)")
    ap.add_argument("--watchdog", type=int, default=10000,
                    help="cycles without progress before the testbench fails the test (default 10000)")
    ap.add_argument("--dut", nargs="+", default=[],
                    help="the DUT's sources and its adapter, in place of the profile's")
    ap.add_argument("--extra-sources", nargs="+", default=[], metavar="FILE",
                    help="sources compiled beside the DUT's (e.g. a coverage bind module; "
                         "C++ files under Verilator)")
    ap.add_argument("--verilator-arg", action="append", default=[], metavar="ARG",
                    help="an argument for Verilator (repeatable), e.g. --verilator-arg=--coverage-user")
    ap.add_argument("--define", action="append", default=[],
                    help="a preprocessor define, e.g. ZB_INJECT_BLEND_BUG")
    ap.add_argument("--plusarg", action="append", default=[], help="given to every run, e.g. +zb_bug_window")
    ap.add_argument("--param", action="append", default=[], metavar="NAME=VALUE",
                    help="a parameter of zb_conf_tb, e.g. TILE_W=32 (the DUT's tile, given to the adapter)")
    ap.add_argument("--gap", type=int, default=0, help="percent of cycles with no fragment offered")
    ap.add_argument("--seed", type=int, default=1,
                    help="the gaps' and the random timing's pattern (default 1)")
    ap.add_argument("--timing", choices=list(TIMINGS), default="tight",
                    help="tight: each event at the first edge the port contract allows "
                         "(default); loose: a cycle more before each wait; random: 0 to 3 "
                         "cycles drawn from --seed")
    ap.add_argument("--schedule", choices=["resident", "pass"], default=None,
                    help="resident: the passes between frame operations on resident tiles (the "
                         "default when the profile has resident_tile); pass: tile by tile, "
                         "pass by pass")
    ap.add_argument("--first-fail", action="store_true",
                    help="run the tests one at a time in suite order and stop at the first that "
                         "fails (a defect hunt; the rest are reported not_run)")
    ap.add_argument("--quick", action="store_true",
                    help="only the suite's quick tier (the manifest's \"tier\": \"quick\")")
    ap.add_argument("--lockstep", action="store_true",
                    help="the golden model as a DPI-C scoreboard beside the DUT (verilator; a retire port)")
    ap.add_argument("--golden-libs", nargs="+", default=[],
                    help="with --lockstep: the C API's libraries to link")
    ap.add_argument("--waves", action="store_true",
                    help="every run writes OUT/<test>/waves.fst (the testbench built with tracing)")
    ap.add_argument("--zblend", default=next((c for c in CHECKERS if os.access(c, os.X_OK)),
                                             CHECKERS[0]),
                    help="the program that checks the signatures: zblend, or the kit's "
                         "zblend-conformance (default: the first of build/zblend, the kit's "
                         "bin/zblend-conformance, build-kit/zblend-conformance)")
    a = ap.parse_args()
    if not 0 <= a.gap <= 95:
        usage_error(f"--gap {a.gap}: choose 0 to 95 (percent)")
    if a.jobs < 1:
        usage_error(f"-j {a.jobs}: at least 1")
    if a.verilator_arg and a.sim != "verilator":
        usage_error("--verilator-arg: only with --sim verilator")
    if a.timeout <= 0 or a.watchdog < 1:
        usage_error("--timeout and --watchdog: more than 0")
    a.params = {}
    for p in a.param:
        name, eq, value = p.partition("=")
        if not eq or not name.isidentifier() or not value.isdigit():
            usage_error(f"--param {p!r}: give NAME=VALUE, e.g. TILE_W=32")
        if name in CONFIG_PARAMS:
            usage_error(f"--param {name}: set by each test's configuration in the suite")
        a.params[name] = int(value)
    if a.checkout is not None:
        a.checkout = os.path.abspath(a.checkout)
        if not os.path.isdir(a.checkout):
            usage_error(f"--checkout {a.checkout}: not a folder (the DUT's own checkout)")
    a.prof = load_profile(a.profile, a.features, a.checkout)
    a.checkout_state = check_checkout(a.prof, a.checkout)
    if a.arithmetic is not None:
        if not ARITHMETIC.fullmatch(a.arithmetic):
            usage_error(f"--arithmetic {a.arithmetic!r}: not an arithmetic: zblend, or <each|sum>-"
                        "<zblend|round255|floor256|ceil256|round256>[-one256]")
        a.prof["arithmetic"] = a.arithmetic
    if a.prof["arithmetic"] == "cts":
        if a.lockstep:
            usage_error("--lockstep with arithmetic cts: the lock-step scoreboard compares every "
                        "write exactly; declare the DUT's arithmetic instead")
        print(f"conformance: arithmetic cts: colour within the Khronos CTS blend threshold of "
              "zblend's passes as cts_pass, apart from exact passes", file=sys.stderr)
    elif a.arithmetic is not None or a.prof["arithmetic"] != "zblend":
        print(f"conformance: declared arithmetic {a.prof['arithmetic']}: the expected planes "
              "are the streams replayed in it", file=sys.stderr)
        a.plusarg = list(a.plusarg) + [f"+zb_arith={a.prof['arithmetic']}"]
    a.ours = not a.dut and os.path.abspath(a.profile) == DEFAULT_PROFILE
    if not a.dut and not a.prof["sources"]:
        usage_error(f"--profile {a.profile} lists no sources: give them there or with --dut")
    if a.schedule is None:
        a.schedule = "resident" if a.prof["resident_tile"] else "pass"
    elif a.schedule == "resident" and not a.prof["resident_tile"]:
        usage_error(f"--schedule resident: the profile {a.profile} does not say "
                    "\"resident_tile\": true")
    if a.lockstep and not a.prof["retire_port"]:
        usage_error(f"--lockstep needs a retire port; the profile {a.profile} says "
                    "\"retire_port\": false")
    if a.lockstep and not a.golden_libs:
        usage_error("--lockstep needs --golden-libs (the C API's static libraries)")
    a.extra_sources = [os.path.abspath(f) for f in a.extra_sources]
    for f in a.extra_sources:
        if not os.path.isfile(f):
            usage_error(f"--extra-sources: no file {f}")
    a.golden_libs = [os.path.abspath(f) for f in a.golden_libs]
    for f in a.golden_libs:
        if not os.path.isfile(f):
            usage_error(f"--golden-libs: no file {f} (build it: cmake --build build "
                        "--target zbgolden_dpi)")
    if not a.list and not os.access(a.zblend, os.X_OK):
        usage_error(f"--zblend {a.zblend}: not a program (it checks the signatures: build it, or "
                    "name the kit's)")
    a.suite = os.path.abspath(a.suite)
    a.out = os.path.abspath(a.out)
    if os.path.isfile(a.suite):
        os.makedirs(a.out, exist_ok=True)
        a.suite = unpack_suite(a.suite, a.out)
    configs, all_tests, suite_version = load_suite(a.suite)
    if a.quick:
        all_tests = [t for t in all_tests if t.get("tier") == "quick"]
    tests = select(all_tests, [g for g in a.tests.split(",") if g], a.feature)
    a.adapter_version, how = adapter_version(a.prof, a.dut or a.prof["sources"])
    print(f"conformance: adapter interface version {a.adapter_version} ({how})",
          file=sys.stderr)
    unsupported = {t["name"]: missing_features(t, a.prof) for t in tests}
    unsupported = {k: v for k, v in unsupported.items() if v}
    # Tests the profile allows but the adapter's interface version cannot carry.
    by_adapter = {t["name"]: adapter_lacks(t, a.adapter_version) for t in tests
                  if t["name"] not in unsupported}
    by_adapter = {k: v for k, v in by_adapter.items() if v}
    if a.list:
        for t in tests:
            miss = unsupported.get(t["name"])
            lacks = by_adapter.get(t["name"])
            why = (f"needs {', '.join(miss)}" if miss else
                   f"{ADAPTER_LACKS[a.adapter_version][1]} ({', '.join(lacks)})" if lacks else
                   ", ".join(t["features"]))
            print(f"{'NOT SUPPORTED' if miss or lacks else 'supported':13}  {t['name']:32} {why}")
        unsupported = {**unsupported, **by_adapter}
        print(f"{len(tests) - len(unsupported)} of {len(tests)} selected tests supported by the "
              f"profile ({'--features' if a.features is not None else a.profile}) and the "
              f"adapter (version {a.adapter_version})")
        return
    os.makedirs(a.out, exist_ok=True)
    to_run = [t for t in tests if t["name"] not in unsupported and t["name"] not in by_adapter]

    by_config = {}
    for t in to_run:
        by_config.setdefault(t["config"], []).append(t)
    runs = []
    for name, group in by_config.items():
        kind = f"{a.sim}{'-waves' if a.waves else ''}-{name}"
        run_cmd = build(a.sim, configs[name], a, os.path.join(a.out, "build", kind))
        runs += [(t, run_cmd) for t in group]

    sims, checked = {}, {}
    no_accum = False
    t0 = time.time()

    def report(i, result):
        nonlocal no_accum
        name, finished, secs, first, hint, lacks_accum = result
        no_accum |= lacks_accum
        sims[name] = (finished, secs, first, hint)
        # The simulation's end only: whether it passed is the checker's line, after it.
        verdict = ("skipped" if hint == "not_supported" else
                   "ran" if finished else "TIMEOUT" if hint == "timeout" else "FAILED")
        print(f"conformance: [{i}/{len(runs)}] {verdict} {name} {secs:.1f} s"
              + (f": {first}" if first else ""), file=sys.stderr, flush=True)
        return finished, name

    if a.first_fail:
        # In suite order, one at a time, each checked as it ends: the first failure stops the run.
        for i, (t, c) in enumerate(runs, 1):
            finished, name = report(i, run_test(t, c, a))
            if finished:
                checked.update(check_tests(a, [name], no_accum))
            if not finished or checked.get(name, ("",))[0] == "FAIL":
                break
    else:
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
            futures = [pool.submit(run_test, t, c, a) for t, c in runs]
            for i, f in enumerate(concurrent.futures.as_completed(futures), 1):
                report(i, f.result())
    unfinished = sorted(n for n, (done, *_rest) in sims.items() if not done)
    print(f"conformance: {len(sims)} simulations on {a.sim} in {time.time() - t0:.0f} s, "
          f"{len(unfinished)} failed to finish", file=sys.stderr)

    # The checker judges what ran; a test the testbench skipped for the layers it keeps wrote
    # nothing (the checker's --no-accum names the accumulation plane's skips itself).
    finished = [t["name"] for t in to_run if sims.get(t["name"], (False,))[0]
                and not layers_skip(sims[t["name"]])]
    if not a.first_fail:
        checked.update(check_tests(a, finished, no_accum))

    results = []
    for t in tests:
        name = t["name"]
        r = {"name": name, "config": t["config"], "features": t["features"], "seconds": 0.0}
        if name in unsupported:
            r.update(verdict="not_supported",
                     message=f"needs {', '.join(unsupported[name])}, not in the profile")
        elif name in by_adapter:
            r.update(verdict="not_supported", message=ADAPTER_LACKS[a.adapter_version][1])
        elif name not in sims:
            r.update(verdict="not_run", message="--first-fail: an earlier test failed")
        else:
            done, secs, first, hint = sims[name]
            r["seconds"] = round(secs, 3)
            word, why = checked.get(name, ("", ""))
            if hint == "timeout":
                r.update(verdict="timeout", message=first)
            elif not done:
                r.update(verdict="fail", message=first)
            elif word == "pass":
                r.update(verdict="pass", message="")
            elif word == "cts":
                r.update(verdict="cts_pass", message=why)
            elif layers_skip(sims[name]):
                r.update(verdict="not_supported", message=first)
            elif word == "skip" or hint == "not_supported":
                r.update(verdict="not_supported",
                         message="the DUT has no accumulation plane (planes_o[4] low)")
            else:
                r.update(verdict="fail", message=why or "the checker gave no verdict")
        results.append(r)
    counts = {v: sum(r["verdict"] == v for r in results) for v in VERDICTS}
    write_results(a, results, counts, suite_version, no_accum)
    if counts["not_supported"]:
        needs = {}
        for r in results:
            for feat in unsupported.get(r["name"], []):
                needs[feat] = needs.get(feat, 0) + 1
        if needs:
            print("conformance: NOT SUPPORTED by the profile: " + ", ".join(
                f"{k} ({v} tests)" for k, v in sorted(needs.items(), key=lambda kv: -kv[1])),
                file=sys.stderr)
        if by_adapter:
            print(f"conformance: NOT SUPPORTED by the adapter's interface: {len(by_adapter)} "
                  f"tests: {ADAPTER_LACKS[a.adapter_version][1]}", file=sys.stderr)
        skipped = sum(r["verdict"] == "not_supported" and r["name"] not in unsupported
                      and r["name"] not in by_adapter for r in results)
        if skipped:
            print(f"conformance: NOT SUPPORTED by the DUT (skipped by the testbench: planes_o, "
                  f"layers_o): {skipped} tests", file=sys.stderr)
    print(f"conformance: {counts['pass']} pass, "
          + (f"{counts['cts_pass']} pass by the CTS threshold only (not exact), "
             if counts["cts_pass"] else "")
          + f"{counts['fail']} fail, {counts['not_supported']} "
          f"not supported, {counts['timeout']} timeout, "
          + (f"{counts['not_run']} not run (--first-fail), " if counts["not_run"] else "")
          + f"of {len(results)} tests "
          f"(results: {os.path.join(a.out, 'results.json')}, junit.xml)", file=sys.stderr)
    bad = [r["name"] for r in results if r["verdict"] in ("fail", "timeout")]
    if bad and not a.waves:
        # The same run again, only the failing tests, with waves: one command to paste.
        again = strip_option(sys.argv[1:], "--tests") + ["--tests", ",".join(bad), "--waves"]
        print(f"conformance: reproduce: python3 {shlex.join([sys.argv[0]] + again)}",
              file=sys.stderr)
    elif bad:
        for t in bad:
            w = os.path.join(a.out, t, "waves")
            print(f"conformance: waves: gtkwave {w}.gtkw  ({w}.fst, its save file beside it)",
                  file=sys.stderr)
    if not bad and counts["pass"] + counts["cts_pass"] == 0:
        print("conformance: no test ran to a verdict: the profile supports none of the selection",
              file=sys.stderr)
        sys.exit(1)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
