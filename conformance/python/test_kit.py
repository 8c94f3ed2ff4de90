#!/usr/bin/env python3
"""The kit's own tests (tests/conformance/kit.cmake; not installed with the kit).

  test_kit.py errors LIB SUITE TEST      zbgolden's errors: each a ZbGoldenError carrying the
                                         C API's line (a missing stream, a truncated one, a bad
                                         plane name, a closed frame, a suite without the test),
                                         a changed expect word found at its pixel, and a pixel's
                                         history ending at its expect words
  test_kit.py program KIT ZBLEND WORK    zblend-conformance's export equals zblend's byte for
                                         byte (--quick), and its check passes on the expect
                                         files as got files
"""
import filecmp
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import zbgolden  # noqa: E402

failures = 0


def check(ok, what):
    global failures
    print(("ok    " if ok else "FAIL  ") + what)
    failures += not ok


def raises(fn, *want):
    """fn() raises ZbGoldenError whose line holds every `want`; the line is printed."""
    try:
        fn()
    except zbgolden.ZbGoldenError as e:
        print(f"      raised: {e} (status {e.status})")
        return all(w in str(e) for w in want)
    return False


def errors(lib, suite_dir, test):
    zbgolden.load(lib)
    suite = zbgolden.Suite(suite_dir)
    missing = os.path.join(suite_dir, "no-such-test", "stream.hex")
    check(raises(lambda: zbgolden.Frame.replay(missing, zbgolden.load(lib)),
                 "zb_golden_replay_file:", missing, "cannot open"),
          "a missing stream raises, naming the file")
    work = os.path.join(os.path.dirname(os.path.abspath(suite_dir)), "kit-python")
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(os.path.join(suite_dir, test), os.path.join(work, test))
    shutil.copy(os.path.join(suite_dir, "manifest.json"), work)
    stream = os.path.join(work, test, "stream.hex")
    with open(stream) as f:
        lines = f.readlines()
    with open(stream, "w") as f:
        f.writelines(lines[:40])
    check(raises(lambda: zbgolden.Frame.replay(stream, zbgolden.load(lib)), stream,
                 "line 41: the file ends here", "truncated"),
          "a truncated stream raises, naming the file and the line")
    with open(stream, "w") as f:
        f.writelines(lines)
    with suite.replay(test, zbgolden.load(lib)) as frame:
        check(raises(lambda: frame.plane("colour"), "'colour' is not one of"),
              "a misspelt plane raises, naming the planes")
        accum = frame.plane("accum")
        check(accum.shape == (frame.height, frame.width, 5) and accum.dtype == "uint32",
              f"accum is (height, width, 5) uint32: {accum.shape} {accum.dtype}")
    check(raises(lambda: frame.plane("depth"), "closed"), "a closed frame raises")
    check(raises(lambda: suite.test("nope"), "no test 'nope'"), "an unknown test raises")
    # One expect word changed: compare() finds that pixel, and no other.
    path = os.path.join(work, test, "expect.depth.hex")
    with open(path) as f:
        words = f.read().split()
    w = suite.test(test)["width"]
    words[w + 3] = f"{int(words[w + 3], 16) ^ 1:08x}"
    with open(path, "w") as f:
        f.write("\n".join(words) + "\n")
    result = dict((p, (n, at)) for p, n, at in zbgolden.compare(zbgolden.Suite(work), test,
                                                                zbgolden.load(lib)))
    check(result["depth"] == (1, (3, 1)) and all(n == 0 for p, (n, _) in result.items()
                                                  if p != "depth"),
          f"a changed depth word is found at (3, 1): {result}")
    # The pixel's history from the suite alone (the frame's middle, where the scene is): it
    # ends at the expect words, after fragments that reached it.
    x, y = w // 2, suite.test(test)["height"] // 2
    h = suite.history(test, x, y, zbgolden.load(lib))["pixels"][0]
    r, g, b, a = h["final"]["color"]
    colour = int(suite.expect(test, "color")[y, x])
    check((h["x"], h["y"]) == (x, y) and r | g << 8 | b << 16 | a << 24 == colour and
          h["final"]["depth"] == int(suite.expect(test, "depth")[y, x]),
          f"the history of ({x}, {y}) ends at its expect words ({len(h['events'])} events)")
    kinds = [e["kind"] for e in h["events"]]
    check("fragment" in kinds and set(kinds) <= {"fragment", "frame_op"},
          f"the history holds the fragments that reached the pixel: {kinds}")
    check(raises(lambda: suite.history(test, w, 0, zbgolden.load(lib)), "zb_golden_pixel_history:",
                 f"pixel ({w}, 0) is outside"), "a pixel outside the frame raises")
    with open(stream, "w") as f:
        f.writelines(lines[:40])
    check(raises(lambda: zbgolden.Suite(work).history(test, 0, 0, zbgolden.load(lib)), stream,
                 "truncated"), "the history of a truncated stream raises, naming the file")
    with open(stream, "w") as f:
        f.writelines(lines)


def program(kit, zblend, work):
    shutil.rmtree(work, ignore_errors=True)
    a, b, got = (os.path.join(work, d) for d in ("kit", "zblend", "got"))
    for cmd in ([kit, "export", "--quick", a], [zblend, "conformance", "export", "--quick", b]):
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    differ = []

    def walk(d):
        differ.extend(os.path.join(d.left, f) for f in d.diff_files + d.left_only + d.right_only)
        for sub in d.subdirs.values():
            walk(sub)
    walk(filecmp.dircmp(a, b))
    check(not differ and len(os.listdir(a)) == len(os.listdir(b)),
          f"zblend-conformance export --quick equals zblend's ({len(os.listdir(a))} entries; "
          f"differ: {differ})")
    for test in os.listdir(a):
        if not os.path.isdir(os.path.join(a, test)):
            continue
        os.makedirs(os.path.join(got, test))
        for p in zbgolden.EXPECT_PLANES:
            shutil.copy(os.path.join(a, test, f"expect.{p}.hex"),
                        os.path.join(got, test, f"got.{p}.hex"))
    r = subprocess.run([kit, "check", a, got], capture_output=True, text=True)
    print(r.stdout + r.stderr, end="")
    tests = sum(os.path.isdir(os.path.join(a, t)) for t in os.listdir(a))
    check(r.returncode == 0 and f"{tests} of {tests} tests pass" in r.stdout,
          "zblend-conformance check passes the expect files")
    r = subprocess.run([kit, "pixel", a, "hazard", "--at", "3,3"], capture_output=True, text=True)
    check(r.returncode == 0 and "pixel (3, 3)" in r.stdout and "\nfinal  colour" in r.stdout,
          f"zblend-conformance pixel prints a history: {r.stdout[:200]}{r.stderr}")
    r = subprocess.run([kit, "check", a], capture_output=True, text=True)
    check(r.returncode == 2 and r.stderr.startswith("zblend-conformance") and
          r.stderr.count("\n") == 1, f"a usage error: exit 2, one line: {r.stderr.strip()}")


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "errors":
        errors(*sys.argv[2:])
    elif len(sys.argv) == 5 and sys.argv[1] == "program":
        program(*sys.argv[2:])
    else:
        sys.exit(__doc__)
    print(f"test_kit: {failures} failures")
    sys.exit(1 if failures else 0)
