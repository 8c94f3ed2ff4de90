#!/usr/bin/env python3
"""Checks a GTKWave save file against its FST (docs/testbench.md "Waves").

Usage: check_waves.py FILE.gtkw [--window] [--gtkwave]

The FST is read with GTKWave's own fst2vcd, not with the code that wrote both files:
  - [dumpfile] names the FST; [timestart] lies in it, and with --window (a mismatch window's
    FST) is its first time: the file starts where the window starts;
  - every signal the save file lists is a variable of the FST;
  - a marker "first wrong write #N" sits on a rising edge (10 ns clock: 5 ns past a multiple of
    10) where tb.mismatch is 1 (and was 0 the cycle before) and the X4 or X11 probe names
    fragment N; a marker "#N accepted" on a rising edge where, in that cycle, zb_rop offered
    fragment N (tb.frag_index) with frag_valid_i and frag_ready_o high; a marker "#N X4" or
    "#N X11" on a rising edge where that stage's probe retires fragment N (zblend pixel's
    prefix the history's numbering: "pass P fragment F (#N) X4");
  - the zoom's span holds every marker.
With --gtkwave, GTKWave itself (under Xvfb) opens the save file: it must show every listed
signal and group, and its named marker A at the save file's time.
Exit 0 when all hold, 1 with each failure on its own line, 2 on bad usage.
"""
import bisect
import os
import re
import shutil
import subprocess
import sys
import tempfile

PERIOD = 10000  # ps


def parse_gtkw(path):
    s = {"signals": [], "groups": 0, "markers": [], "names": {}}
    for ln in open(path):
        ln = ln.rstrip("\n")
        if ln.startswith("[dumpfile] "):
            s["dumpfile"] = ln.split(" ", 1)[1].strip('"')
        elif ln.startswith("[timestart] "):
            s["timestart"] = int(ln.split()[1])
        elif ln.startswith("[markername] "):
            body = ln.split(" ", 1)[1]
            s["names"][body[0]] = body[1:]
        elif ln.startswith("*"):
            f = ln[1:].split()
            s["zoom"], s["primary"] = float(f[0]), int(f[1])
            s["named"] = [int(x) for x in f[2:]]
        elif ln.startswith("-"):
            s["groups"] += 1
        elif ln and not ln.startswith(("[", "@")):
            s["signals"].append(ln)
    for i, t in enumerate(s.get("named", [])):
        if t >= 0:
            s["markers"].append((chr(ord("A") + i), t, s["names"].get(chr(ord("A") + i), "")))
    return s


def read_vcd(fst, wanted):
    """Variables by full name ({name: bits}) and the changes of `wanted` ({name: [(t, v)]})."""
    p = subprocess.run(["fst2vcd", fst], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                       text=True, check=True)
    scope, names, ids, changes, t, first = [], {}, {}, {}, None, None
    for ln in p.stdout.splitlines():
        if ln.startswith("$scope"):
            scope.append(ln.split()[2])
        elif ln.startswith("$upscope"):
            scope.pop()
        elif ln.startswith("$var"):
            f = ln.split()
            rng = f[5] if len(f) > 6 and f[5].startswith("[") else ""
            full = ".".join(scope + [f[4] + rng])
            names[full] = int(f[2])
            if full in wanted:
                ids.setdefault(f[3], []).append(full)
        elif ln.startswith("#"):
            t = int(ln[1:])
            first = t if first is None else first
        elif t is not None and ln and ln[0] in "01xzb":
            if ln[0] == "b":
                val, code = ln[1:].split()
            else:
                val, code = ln[0], ln[1:]
            for full in ids.get(code, []):
                changes.setdefault(full, []).append((t, int(val, 2) if set(val) <= {"0", "1"} else -1))
    return names, changes, first


def value_at(changes, name, t):
    ch = changes.get(name, [])
    i = bisect.bisect_right([c[0] for c in ch], t) - 1
    return ch[i][1] if i >= 0 else None


def check(path, window, use_gtkwave):
    errors = []
    s = parse_gtkw(path)
    fst = s.get("dumpfile", "")
    if not os.path.exists(fst):
        return [f"{path}: [dumpfile] {fst!r} does not exist"]
    probe = ["tb.mismatch", "tb.frag_index[31:0]", "tb.x4_retire", "tb.x4_index[31:0]",
             "tb.x11_retire", "tb.x11_index[31:0]", "zb_rop.frag_valid_i", "zb_rop.frag_ready_o"]
    names, ch, first = read_vcd(fst, set(probe))
    if window and s.get("timestart") != first:
        errors.append(f"[timestart] {s.get('timestart')} is not the FST's first time {first}")
    if s.get("timestart", -1) < (first or 0):
        errors.append(f"[timestart] {s.get('timestart')} is before the FST's first time {first}")
    missing = [x for x in s["signals"] if x not in names]
    if missing:
        errors.append(f"{len(missing)} listed signals not in the FST, e.g. {missing[:3]}")
    if not s["signals"]:
        errors.append("no signals listed")
    span = 2 ** -s.get("zoom", 0) * 850 / 200  # GTKWave: 2^-zoom ps per 200 pixels, 850 shown
    for letter, t, name in s["markers"]:
        if not (t - PERIOD // 2) % PERIOD == 0:
            errors.append(f"marker {letter} ({name}) at {t} ps is not on a rising edge")
        if not s["timestart"] <= t <= s["timestart"] + span:
            errors.append(f"marker {letter} ({name}) at {t} ps is outside the zoomed span")
        m = re.fullmatch(r"first wrong write(?: #(\d+))?", name)
        # zblend pixel's names the fragment as its text does too: "pass P fragment N (#S) ..."
        own = r"(?:pass \d+ fragment \d+ \()?#(\d+)\)?"
        a = re.fullmatch(own + r" accepted", name)
        w = re.fullmatch(own + r" (X4|X11)", name)
        if w:
            n, st = int(w.group(1)), w.group(2).lower()
            if not (value_at(ch, f"tb.{st}_retire", t) == 1 and
                    value_at(ch, f"tb.{st}_index[31:0]", t) == n):
                errors.append(f"marker {letter} ({name}) at {t}: no {w.group(2)} retire of "
                              f"fragment {n} there")
        elif m:
            if value_at(ch, "tb.mismatch", t) != 1 or value_at(ch, "tb.mismatch", t - PERIOD) != 0:
                errors.append(f"marker {letter} ({name}) at {t}: tb.mismatch is not 1 there and 0 "
                              "the cycle before")
            if m.group(1):
                n = int(m.group(1))
                if not any(value_at(ch, f"tb.{st}_retire", t) == 1 and
                           value_at(ch, f"tb.{st}_index[31:0]", t) == n for st in ("x4", "x11")):
                    errors.append(f"marker {letter} ({name}) at {t}: no X4 or X11 retire of "
                                  f"fragment {n} there")
        elif a:
            n, fall = int(a.group(1)), t - PERIOD // 2
            got = (value_at(ch, "tb.frag_index[31:0]", fall),
                   value_at(ch, "zb_rop.frag_valid_i", fall), value_at(ch, "zb_rop.frag_ready_o", fall))
            if got != (n, 1, 1):
                errors.append(f"marker {letter} ({name}) at {t}: (frag_index, valid, ready) = "
                              f"{got} in that cycle, want ({n}, 1, 1)")
        else:
            errors.append(f"marker {letter}: unknown name {name!r}")
    if use_gtkwave:
        errors += check_in_gtkwave(path, s)
    return errors


def check_in_gtkwave(path, s):
    for tool in ("gtkwave", "xvfb-run"):
        if not shutil.which(tool):
            return [f"{tool} is missing: scripts/setup.sh view installs it"]
    with tempfile.TemporaryDirectory() as d:
        tcl = os.path.join(d, "q.tcl")
        with open(tcl, "w") as f:
            f.write("set n [gtkwave::getTotalNumTraces]\n"
                    "puts \"TRACES $n A [gtkwave::getNamedMarker A]\"\n"
                    "gtkwave::/File/Quit\n")
        p = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1600x900x24", "gtkwave", "-S", tcl,
                            path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           timeout=120)
    m = re.search(r"^TRACES (\d+) A (-?\d+)", p.stdout, re.M)
    if not m:
        return [f"GTKWave did not answer (exit {p.returncode}): {p.stdout[-300:]}"]
    errors = []
    want = len(s["signals"]) + s["groups"]
    if int(m.group(1)) != want:
        errors.append(f"GTKWave shows {m.group(1)} traces, the save file lists {want} "
                      "(signals and group comments)")
    a = next((t for letter, t, _ in s["markers"] if letter == "A"), -1)
    if int(m.group(2)) != a:
        errors.append(f"GTKWave's named marker A is at {m.group(2)}, the save file's at {a}")
    return errors


def main():
    args = [a for a in sys.argv[1:] if a not in ("--gtkwave", "--window")]
    if len(args) != 1 or not args[0].endswith(".gtkw"):
        print(__doc__.split("\n")[2], file=sys.stderr)
        return 2
    if not shutil.which("fst2vcd"):
        print("check_waves.py: fst2vcd is missing: scripts/setup.sh view installs GTKWave",
              file=sys.stderr)
        return 2
    errors = check(args[0], "--window" in sys.argv, "--gtkwave" in sys.argv)
    for e in errors:
        print(f"check_waves.py: {args[0]}: {e}")
    if not errors:
        s = parse_gtkw(args[0])
        print(f"check_waves.py: {args[0]}: {len(s['signals'])} signals in {s['groups'] // 2} "
              f"groups, {len(s['markers'])} markers, all as the FST shows"
              + (", and as GTKWave opens it" if "--gtkwave" in sys.argv else ""))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
