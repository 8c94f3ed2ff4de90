"""The functional coverage plan (tb/cov/coverage_plan.json, docs/coverage.md) and Verilator's
coverage files: the plan's bins, and which of them a .dat file's cover points hit."""
import os
import re

from zbscript import ROOT, load_json

DEFAULT = os.path.join(ROOT, "tb", "cov", "coverage_plan.json")
ENTRY_KEYS = {"id", "about", "cover", "dims", "bins", "sets", "tests", "unreachable"}


class PlanError(ValueError):
    """A malformed plan: what, where, how to fix."""


def _pattern(glob):
    """A cover path pattern as a regular expression: [*] captures a generate index, * a label."""
    out = ""
    for tok in re.split(r"(\[\*\]|\*)", glob):
        if tok == "[*]":
            out += r"\[(\d+)\]"
        elif tok == "*":
            out += r"([A-Za-z0-9_]+)"
        else:
            out += re.escape(tok)
    return re.compile(out + "$")


def load(path=DEFAULT):
    doc = load_json(path, PlanError)
    entries = doc.get("entries") if isinstance(doc, dict) else None
    if not isinstance(entries, list) or not entries:
        raise PlanError(f"{path}: no \"entries\" list")
    seen = set()
    for i, e in enumerate(entries):
        where = f"{path}: entries[{i}]"
        if not isinstance(e, dict):
            raise PlanError(f"{where}: an entry is an object")
        if isinstance(e.get("id"), str):
            where += f" ({e['id']})"
        unknown = set(e) - ENTRY_KEYS
        if unknown:
            raise PlanError(f"{where}: unknown key(s) {', '.join(sorted(unknown))} "
                            f"(known: {', '.join(sorted(ENTRY_KEYS))})")
        eid = e.get("id")
        if not isinstance(eid, str) or not re.fullmatch(r"[a-z0-9_]+", eid) or eid in seen:
            raise PlanError(f"{where}: 'id' must be a new name of a-z, 0-9, _ (got {eid!r})")
        seen.add(eid)
        if ("cover" in e) == ("bins" in e):
            raise PlanError(f"{where}: give 'cover' (with 'dims') or 'bins', one of them")
        if "bins" in e and (not isinstance(e["bins"], dict) or not e["bins"] or
                            not all(isinstance(v, str) for v in e["bins"].values())):
            raise PlanError(f"{where}: 'bins' maps bin names to cover paths")
        if "cover" in e:
            covers = e["cover"] if isinstance(e["cover"], list) else [e["cover"]]
            if not covers or not all(isinstance(c, str) and c for c in covers):
                raise PlanError(f"{where}: 'cover' is a path pattern or a list of them")
            dims = e.get("dims", [])
            caps = len(re.findall(r"\[\*\]|\*", covers[0]))
            if len(covers) == 1 and len(dims) != caps:
                raise PlanError(f"{where}: {caps} capture(s) ([*] or *) in 'cover' but "
                                f"{len(dims)} 'dims': one dimension each")
            if len(covers) > 1 and dims:
                raise PlanError(f"{where}: a list of covers takes no 'dims' (its bins are named "
                                "by their paths)")
            for d in dims:
                if not isinstance(d, dict) or "name" not in d or \
                        ("values" in d) == ("from" in d):
                    raise PlanError(f"{where}: a dimension is {{\"name\", \"values\": [...]}} "
                                    "or {\"name\", \"from\": N}")
        for key in ("sets", "tests"):
            if not isinstance(e.get(key, ["default"]), list) or \
                    not all(isinstance(s, str) for s in e.get(key, [])):
                raise PlanError(f"{where}: '{key}' is a list of names")
        for j, u in enumerate(e.get("unreachable", [])):
            if not isinstance(u, dict) or not isinstance(u.get("bins"), str) or \
                    not isinstance(u.get("why"), str) or not u["why"].strip():
                raise PlanError(f"{where}: unreachable[{j}] is {{\"bins\": REGEX, "
                                "\"why\": TEXT}")
            try:
                u["re"] = re.compile(u["bins"])
            except re.error as err:
                raise PlanError(f"{where}: unreachable[{j}]: bad regular expression: {err}")
        e.setdefault("sets", ["default"])
        e.setdefault("tests", [])
        e.setdefault("unreachable", [])
    return entries


def read_dat(path):
    """{cover path under zb_rop: count} of a coverage file's cover properties (page v_user).
    zb_rop is the instance holding u_cov: the model's top (zblend_tb) or deeper (the
    conformance testbench's DUT); covers outside it are left out."""
    raw = {}
    with open(path, errors="replace") as f:
        for line in f:
            if not line.startswith("C '"):
                continue
            body, _, count = line.rstrip("\n").rpartition("' ")
            fields = dict(kv.split("\002", 1) for kv in body[3:].split("\001") if "\002" in kv)
            if not fields.get("page", "").startswith("v_user"):
                continue
            h = fields.get("h", "").replace("__BRA__", "[").replace("__KET__", "]")
            raw[h] = raw.get(h, 0) + int(count)
    top = next((h[:h.index(".u_cov.") + 1] for h in raw if ".u_cov." in h), None)
    if top is None:  # no plan module: the top's prefix as Verilator writes it
        return {re.sub(r"^(TOP\.)?(zb_rop\.)+", "", h): n for h, n in raw.items()}
    return {h[len(top):]: n for h, n in raw.items() if h.startswith(top)}


def bins(entry, paths):
    """[(bin name, cover path)] of the entry among the cover paths; raises PlanError where the
    covers and the plan disagree (a dimension's value out of its list, a missing bin)."""
    eid = entry["id"]
    if "bins" in entry:
        missing = [p for p in entry["bins"].values() if p not in paths]
        if missing:
            raise PlanError(f"plan entry {eid}: no cover {missing[0]} in the model (rename it "
                            "in the plan or in tb/cov/zb_rop_cov.sv)")
        return [(f"{eid}.{name}", p) for name, p in entry["bins"].items()]
    covers = entry["cover"] if isinstance(entry["cover"], list) else [entry["cover"]]
    out = []
    for glob in covers:
        pat = _pattern(glob)
        hits = sorted((p for p in paths if pat.match(p)), key=natural_key)
        if not hits:
            raise PlanError(f"plan entry {eid}: no cover matches {glob} in the model")
        if len(covers) > 1:
            out += [(f"{eid}.{p}", p) for p in hits]
            continue
        for p in hits:
            labels = []
            for d, cap in zip(entry.get("dims", []), pat.match(p).groups()):
                if "from" in d:
                    labels.append(f"{d['name']}={int(cap) + d['from']}")
                    continue
                vals = d["values"]
                if cap.isdigit():
                    if int(cap) >= len(vals):
                        raise PlanError(f"plan entry {eid}: {p}: index {cap} beyond the "
                                        f"{len(vals)} values of dimension {d['name']}")
                    cap = vals[int(cap)]
                elif cap not in vals:
                    raise PlanError(f"plan entry {eid}: {p}: '{cap}' is not a value of "
                                    f"dimension {d['name']} ({', '.join(vals)})")
                labels.append(f"{d['name']}={cap}")
            out.append((f"{eid}[{','.join(labels)}]", p))
    full = 1
    for d in entry.get("dims", []):
        full *= len(d["values"]) if "values" in d else 0
    if entry.get("dims") and full and len(out) != full:
        raise PlanError(f"plan entry {eid}: {len(out)} covers in the model, the dimensions "
                        f"make {full}")
    return out


def natural_key(s):
    """A sort key that orders the numbers in a name by value (slot[10] after slot[9])."""
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", s)]
