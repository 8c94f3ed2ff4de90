"""What zblend's Python scripts share: `import zbscript` (or `from zbscript import ...`).

A script run as `python3 scripts/x.py`, from the repository or from anywhere else, finds this
module beside it (Python puts the script's folder first on sys.path).

  ROOT               the repository: the folder above scripts/
  usage_error(what)  bad usage: `<script>: error: <what>` on stderr, exit 2 (argparse's format
                     for its own errors, and the zblend programs')
  Progress           a progress line on stderr per finished item, with the time left
  load_json(path, error)  a JSON file, or error(what, where) raised: unreadable, not JSON

scripts/conformance.py keeps its own ROOT, usage_error and progress line: it ships alone in
the conformance kit's archive (make kit, scripts/kit.sh), without this module, and stays one
self-contained file.
"""
import json
import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load_json(path, error):
    """The JSON document in `path`; raises error (an exception class) with "path: why" or
    "path:line:column: not JSON: why"."""
    try:
        with open(path) as f:
            return json.load(f)
    except OSError as e:
        raise error(f"{path}: {e.strerror}")
    except json.JSONDecodeError as e:
        raise error(f"{path}:{e.lineno}:{e.colno}: not JSON: {e.msg}")


def usage_error(what):
    """Bad usage: one line, `<script>: error: <what>`, on stderr; exit 2."""
    print(f"{os.path.basename(sys.argv[0])}: error: {what}", file=sys.stderr)
    sys.exit(2)


class Progress:
    """The progress of a run over items (tests, mutants), a line on stderr per finished item:
    `PREFIX: ` and what line(self) says, from done, n, elapsed (seconds) and left (seconds: the
    items not yet done, each at its time in `known` where it has one, else at the mean so far,
    over `jobs` processes). With `every`, at most a line that many seconds apart, and the last.
    """

    def __init__(self, prefix, items, jobs=1, known=None, every=0.0):
        self.prefix, self.jobs, self.known, self.every = prefix, jobs, known or {}, every
        self.todo = set(items)
        self.n, self.done, self.elapsed, self.left = len(self.todo), 0, 0.0, 0.0
        self.t0, self.shown = time.monotonic(), 0.0

    def step(self, item, line):
        """`item` has finished; line(self) is the text of its progress line."""
        self.done += 1
        self.todo.discard(item)
        now = time.monotonic()
        if now - self.shown < self.every and self.done != self.n:
            return
        self.shown = now
        self.elapsed = now - self.t0
        mean = self.elapsed * self.jobs / self.done
        unknown = sum(1 for i in self.todo if i not in self.known)
        self.left = (sum(self.known[i] for i in self.todo if i in self.known)
                     + mean * unknown) / self.jobs
        print(f"{self.prefix}: {line(self)}", file=sys.stderr, flush=True)
