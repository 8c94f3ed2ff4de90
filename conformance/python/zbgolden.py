#!/usr/bin/env python3
"""zbgolden: zblend's golden model from Python: ctypes over libzbgolden.so, planes as NumPy arrays.

    import zbgolden
    suite = zbgolden.Suite("suite")               # written by zblend-conformance export
    frame = suite.replay("cad-three-pass")        # the test's stream.hex through the golden model
    color = frame.plane("color")                  # shape (height, width), uint32
    assert (color == suite.expect("cad-three-pass", "color")).all()

Planes: "color" (packed RGBA8, r in the low byte), "depth", "coverage", "peel", and the
accumulation word's parts "acc_r", "acc_g", "acc_b", "acc_a", "reveal": each (height, width),
uint32. "accum" is the whole word as its five parts, (height, width, 5) uint32, in the word's
order from bit 0: acc_r, acc_g, acc_b, acc_a, reveal (expect.accum.hex is {r, acc_A, acc_B,
acc_G, acc_R}; up to 144 bits, wider than any NumPy integer).

The library: load(path), or the first found of $ZBGOLDEN_LIB, libzbgolden.so beside this file,
the kit's layout (PREFIX/lib beside PREFIX/share/zblend-conformance/python), the source tree's
build-kit/ and build/, then the system's library path. A failed call raises ZbGoldenError: the
C API's one line (zb_golden_last_error), and .status its ZB_E* code.

As a program: zbgolden.py [--lib PATH] SUITE [TEST ...] replays each test (every test of the
suite when none is named) and compares every plane with its expect file: exit 0 when all equal,
1 when any differs, 2 for bad input.
"""
import ctypes
import json
import os
import sys

try:
    import numpy as np
except ImportError:  # one line, with the fix
    raise ImportError("zbgolden needs NumPy: apt-get install python3-numpy (or pip install "
                      "numpy)") from None

# zb_golden.h's constants.
ZB_OK, ZB_EARG, ZB_EORDER, ZB_EHANDLE, ZB_ENOMEM, ZB_EINTERNAL = range(6)
PLANES = {"color": 0, "depth": 1, "coverage": 2, "peel": 3, "acc_r": 4, "acc_g": 5, "acc_b": 6,
          "acc_a": 7, "reveal": 8}
ACCUM_PARTS = ("acc_r", "acc_g", "acc_b", "acc_a", "reveal")
EXPECT_PLANES = ("color", "depth", "coverage", "peel", "accum")  # the expect.<plane>.hex files

HERE = os.path.dirname(os.path.abspath(__file__))
LIB_NAME = "libzbgolden.so"


class ZbGoldenError(Exception):
    """A failed call: str() is the C API's line; .status the ZB_E* code (0 for the module's own)."""

    def __init__(self, message, status=0):
        super().__init__(message)
        self.status = status


_I, _U32, _U64, _P = ctypes.c_int, ctypes.c_uint32, ctypes.c_uint64, ctypes.POINTER
_SIGNATURES = {  # name: (result, argument types), as zb_golden.h declares them
    "zb_golden_create": (_I, [_P(ctypes.c_void_p), _I, _I, _I, _I, _U32]),
    "zb_golden_set_wboit": (_I, [ctypes.c_void_p, _I, _I, _I]),
    "zb_golden_destroy": (None, [ctypes.c_void_p]),
    "zb_golden_begin_pass": (_I, [ctypes.c_void_p, _U32]),
    "zb_golden_push": (_I, [ctypes.c_void_p, _I, _I, _U32, _U32, _I] + [_P(_U32)] * 4),
    "zb_golden_end_pass": (_I, [ctypes.c_void_p] + [_P(_U64)] * 6),
    "zb_golden_frame_op": (_I, [ctypes.c_void_p, _I, _U32, _U32]),
    "zb_golden_read": (_I, [ctypes.c_void_p, _I, _I, _I, _P(_U32)]),
    "zb_golden_replay_file": (_I, [_P(ctypes.c_void_p), ctypes.c_char_p]),
    "zb_golden_frame_info": (_I, [ctypes.c_void_p] + [_P(_I)] * 7),
    "zb_golden_read_plane": (_I, [ctypes.c_void_p, _I, _P(_U32), ctypes.c_size_t]),
    "zb_golden_last_error": (ctypes.c_char_p, [ctypes.c_void_p]),
    "zb_golden_pixel_history": (_I, [ctypes.c_char_p, _I, _I, ctypes.c_char_p, ctypes.c_size_t,
                                     _P(ctypes.c_size_t)]),
}
_lib = None


def _candidates():
    root = os.path.dirname(os.path.dirname(HERE))  # the kit's PREFIX/share, or the source tree
    return [os.path.join(HERE, LIB_NAME),
            os.path.join(os.path.dirname(root), "lib", LIB_NAME),
            os.path.join(root, "build-kit", "conformance", LIB_NAME),
            os.path.join(root, "build", "conformance", LIB_NAME)]


def _open(path):
    try:
        return ctypes.CDLL(path)
    except OSError as e:
        raise ZbGoldenError(f"cannot load {path}: {e}")


def load(path=None):
    """The library with every call's prototype set: `path`, or the first found (see above)."""
    global _lib
    if path is None and _lib is not None:
        return _lib
    named = path or os.environ.get("ZBGOLDEN_LIB")
    if named:  # that one or an error, never another
        lib = _open(named)
    else:
        found = [p for p in _candidates() if os.path.exists(p)]
        try:
            lib = _open(found[0]) if found else ctypes.CDLL(LIB_NAME)
        except OSError:
            raise ZbGoldenError(f"{LIB_NAME} not found (beside {HERE}, in the kit's lib/, "
                                f"build-kit/ or build/, or on the library path): build it with "
                                f"`make kit`, or name it with ZBGOLDEN_LIB or --lib")
    for name, (result, args) in _SIGNATURES.items():
        fn = getattr(lib, name)
        fn.restype, fn.argtypes = result, args
    if path is None:
        _lib = lib
    return lib


def _check_handleless(lib, status):
    """Raises a failed call without a frame handle with the library's last error."""
    if status != ZB_OK:
        raise ZbGoldenError(lib.zb_golden_last_error(None).decode(), status)


class Frame:
    """One frame of the golden model (a zb_golden handle); close() or `with` frees it."""

    def __init__(self, handle, lib):
        self._lib, self._h = lib, handle
        v = [_I() for _ in range(7)]
        self._check(lib.zb_golden_frame_info(handle, *[ctypes.byref(x) for x in v]))
        (self.width, self.height, self.depth_bits, self.coverage_samples, self.acc_bits,
         self.rev_bits, self.weight_bits) = [x.value for x in v]

    @classmethod
    def replay(cls, stream_path, lib=None):
        """A new frame with the stream.hex at `stream_path` replayed on it."""
        lib = lib or load()
        h = ctypes.c_void_p()
        _check_handleless(lib, lib.zb_golden_replay_file(ctypes.byref(h),
                                                         os.fsencode(stream_path)))
        return cls(h, lib)

    def _check(self, status):
        if status != ZB_OK:
            raise ZbGoldenError(self._lib.zb_golden_last_error(self._h).decode(), status)

    def plane(self, name):
        """A plane by name (PLANES, or "accum"), row 0 first: (height, width) uint32 arrays."""
        if name == "accum":
            return np.stack([self.plane(p) for p in ACCUM_PARTS], axis=-1)
        if name not in PLANES:
            names = ", ".join(list(PLANES) + ["accum"])
            raise ZbGoldenError(f"plane '{name}' is not one of {names}")
        if not self._h:
            raise ZbGoldenError("the frame is closed")
        out = np.empty((self.height, self.width), dtype=np.uint32)
        self._check(self._lib.zb_golden_read_plane(self._h, PLANES[name],
                                                   out.ctypes.data_as(_P(_U32)), out.size))
        return out

    def close(self):
        if self._h:
            self._lib.zb_golden_destroy(self._h)
            self._h = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()


class Suite:
    """A suite written by `zblend-conformance export` (or `zblend conformance export`)."""

    def __init__(self, path):
        self.path = path
        manifest = os.path.join(path, "manifest.json")
        try:
            with open(manifest) as f:
                m = json.load(f)
        except (OSError, ValueError) as e:
            raise ZbGoldenError(f"{manifest}: {e} (give a directory written by "
                                f"`zblend-conformance export DIR`)")
        if not isinstance(m, dict) or m.get("suite") != "zblend-conformance":
            raise ZbGoldenError(f"{manifest}: not a zblend conformance suite")
        self.version = m.get("version")
        self.configs = {c["name"]: c for c in m["configs"]}
        self._tests = {t["name"]: t for t in m["tests"]}
        self.tests = [t["name"] for t in m["tests"]]  # in the suite's order

    def test(self, name):
        """The test's manifest entry."""
        if name not in self._tests:
            raise ZbGoldenError(f"{self.path}: no test '{name}' (`zblend-conformance export "
                                f"--list` lists them)")
        return self._tests[name]

    def replay(self, name, lib=None):
        self.test(name)
        return Frame.replay(os.path.join(self.path, name, "stream.hex"), lib)

    def history(self, name, x, y, lib=None):
        """Pixel (x, y)'s history in the test (zblend pixel's JSON as a dict, docs/history.md):
        ["pixels"][0]["events"] are the fragments that reached it and the frame operations."""
        self.test(name)
        lib = lib or load()
        path = os.fsencode(os.path.join(self.path, name, "stream.hex"))
        needed = ctypes.c_size_t()
        _check_handleless(lib, lib.zb_golden_pixel_history(path, x, y, None, 0,
                                                           ctypes.byref(needed)))
        buf = ctypes.create_string_buffer(needed.value)
        _check_handleless(lib, lib.zb_golden_pixel_history(path, x, y, buf, needed.value, None))
        return json.loads(buf.value.decode())

    def expect(self, name, plane):
        """expect.<plane>.hex as plane() returns it (plane one of EXPECT_PLANES)."""
        t = self.test(name)
        if plane not in EXPECT_PLANES:
            raise ZbGoldenError(f"no expect file for plane '{plane}' (one of "
                                f"{', '.join(EXPECT_PLANES)})")
        path = os.path.join(self.path, name, f"expect.{plane}.hex")
        with open(path) as f:
            words = f.read().split()
        w, h = t["width"], t["height"]
        if len(words) != w * h:
            raise ZbGoldenError(f"{path}: {len(words)} words, the {w}x{h} frame has {w * h}")
        values = [int(x, 16) for x in words]
        if plane != "accum":
            return np.array(values, dtype=np.uint32).reshape(h, w)
        c = self.configs[t["config"]]
        a, r = c["acc_bits"], c["rev_bits"]
        fields = [(k * a, a) for k in range(4)] + [(4 * a, r)]
        return np.array([[v >> lo & ((1 << n) - 1) for lo, n in fields] for v in values],
                        dtype=np.uint32).reshape(h, w, 5)


def compare(suite, name, lib=None):
    """The test replayed against its expect files: (plane, pixels differing, first (x, y))."""
    with suite.replay(name, lib) as frame:
        out = []
        for p in EXPECT_PLANES:
            got, want = frame.plane(p), suite.expect(name, p)
            diff = (got != want).reshape(frame.height, frame.width, -1).any(axis=-1)
            ys, xs = np.nonzero(diff)
            out.append((p, int(diff.sum()), (int(xs[0]), int(ys[0])) if len(xs) else None))
        return out


def main(argv):
    import argparse
    ap = argparse.ArgumentParser(description="Replay a suite's tests through the golden model "
                                 "(libzbgolden.so) and compare every plane with the expect files")
    ap.add_argument("--lib", help="libzbgolden.so to load (default: see `pydoc zbgolden`)")
    ap.add_argument("suite")
    ap.add_argument("tests", nargs="*")
    a = ap.parse_args(argv)
    try:
        lib = load(a.lib)
        suite = Suite(a.suite)
        names = a.tests or suite.tests
        for n in names:
            suite.test(n)
        failed = 0
        for n in names:
            result = compare(suite, n, lib)
            bad = [f"{p} {d} pixels differ, first ({at[0]}, {at[1]})" for p, d, at in result if d]
            failed += bool(bad)
            print(f"{'FAIL' if bad else 'pass'}  {n}" + (f": {'; '.join(bad)}" if bad else ""))
    except ZbGoldenError as e:
        print(f"zbgolden: error: {e}", file=sys.stderr)
        return 2
    print(f"{len(names) - failed} of {len(names)} tests equal to their expect files")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
