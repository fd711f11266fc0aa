#!/usr/bin/env python3
"""Mutation campaign over every case kind (issue 20): runs `gearbench run` on mutated copies of
the cases in cases/ and counts the outcomes per kind. A finding is a crash (signal), exit 1
(internal error) on any input, an error message that is not one `error:` line, or an exit-0
result that fails a plausibility rule (see `implausible`). A run past --timeout is kept and run
again, once, with --retry-timeout: one that then finishes is counted by its outcome and listed
as slow with its time; one that still does not is a finding ("hang").

usage: mutation_campaign.py GEARBENCH CASES_DIR [--per-case N] [--seed S] [--timeout T]
                             [--retry-timeout T2] [--out DIR] [--skip KIND,...]
Findings are kept as finding_<kind>_<case>_<n>.json in DIR, with a FINDING line each.
"""
import argparse, collections, copy, json, math, os, random, subprocess, tempfile, time

def leaves(node, path=()):
    if isinstance(node, dict):
        for k, v in node.items():
            yield from leaves(v, path + (k,))
        yield path, node
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from leaves(v, path + (i,))
        yield path, node
    else:
        yield path, node

def get(node, path):
    for p in path:
        node = node[p]
    return node

def put(node, path, value):
    for p in path[:-1]:
        node = node[p]
    node[path[-1]] = value

def delete(node, path):
    for p in path[:-1]:
        node = node[p]
    del node[path[-1]]

NUMBER_MUTATIONS = [
    lambda v, r: v * 10 ** r.randint(-12, 12),
    lambda v, r: -v,
    lambda v, r: 0,
    lambda v, r: 1e308,
    lambda v, r: 5e-324,
    lambda v, r: -1,
    lambda v, r: v + 1,
    lambda v, r: 2 ** 63 + 7,
    lambda v, r: v * (1 + r.uniform(-0.9, 3)),
    lambda v, r: str(v),
    lambda v, r: None,
    lambda v, r: [v, v],
]
OTHER_MUTATIONS = [
    lambda v, r: None,
    lambda v, r: 1,
    lambda v, r: "",
    lambda v, r: [],
    lambda v, r: {},
    lambda v, r: "x" * 300,
]

def mutate(case, r):
    m = copy.deepcopy(case)
    choices = [p for p, _ in leaves(m) if p and p != ("kind",)]
    path = r.choice(choices)
    value = get(m, path)
    roll = r.random()
    if roll < 0.08 and isinstance(path[-1], str):
        delete(m, path)
        return m, f"delete {path}"
    if roll < 0.12:
        m["unknown_key_" + str(r.randint(0, 99))] = 1
        return m, "unknown key"
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if r.random() < 0.6:  # valid-looking but extreme: the solvers' own ranges, not the reader's
            new = value * 10 ** r.uniform(-3, 3) if r.random() < 0.7 else value * (1 + r.uniform(-0.5, 0.5))
            if isinstance(value, int) and r.random() < 0.5:
                new = int(round(new))
        else:
            new = r.choice(NUMBER_MUTATIONS)(value, r)
    else:
        new = r.choice(OTHER_MUTATIONS)(value, r)
    put(m, path, new)
    return m, f"{path} = {str(new)[:40]}"

def numbers(node, path=""):
    if isinstance(node, dict):
        for k, v in node.items():
            yield from numbers(v, f"{path}.{k}" if path else k)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from numbers(v, f"{path}[{i}]")
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield path, node

def implausible(result):
    """Plausibility rules every kind's result must meet: efficiencies in (0, 1]; films,
    stiffnesses and peak pressures not negative; a friction coefficient below 1 in magnitude
    (a liquid film carries no shear force above the normal load); a positive dynamic factor."""
    bad = []
    for path, v in numbers(result):
        leaf = path.split(".")[-1].split("[")[0]
        if not math.isfinite(v):
            bad.append(f"{path} = {v}")
        elif leaf.endswith(("efficiency", "efficiency_mean", "efficiency_min", "efficiency_max")) and not 0 < v <= 1.0:
            bad.append(f"{path} = {v}")
        elif (leaf.startswith(("h_min", "h_central", "h_c")) and leaf.endswith("_m")) and v < 0:
            bad.append(f"{path} = {v}")
        elif "stiffness" in leaf and leaf.endswith("N_per_m") and v < 0:
            bad.append(f"{path} = {v}")
        elif leaf == "dynamic_factor" and not v > 0:
            bad.append(f"{path} = {v}")
        elif leaf in ("friction_coefficient", "mean_friction_coefficient") and not (abs(v) < 1):
            bad.append(f"{path} = {v}")
        elif leaf.startswith("p_max") and v <= 0:
            bad.append(f"{path} = {v}")
    return bad

def run_case(gearbench, path, limit):
    """`gearbench run path` with a time limit: (completed process, seconds), or (None, limit)."""
    start = time.monotonic()
    try:
        p = subprocess.run([gearbench, "run", path], capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return None, limit
    return p, time.monotonic() - start

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("gearbench"); ap.add_argument("cases")
    ap.add_argument("--per-case", type=int, default=30); ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=20.0); ap.add_argument("--out", default="mutation_out")
    ap.add_argument("--retry-timeout", type=float, default=600.0)
    ap.add_argument("--skip", default="")
    a = ap.parse_args()
    r = random.Random(a.seed)
    os.makedirs(a.out, exist_ok=True)
    counts = collections.defaultdict(collections.Counter)
    findings = []
    slow = []  # (kind, case, mutation, seconds, exit code) of runs past --timeout that finished
    skip = set(a.skip.split(",")) if a.skip else set()
    files = sorted(f for f in os.listdir(a.cases) if f.endswith(".json"))
    for f in files:
        case = json.load(open(os.path.join(a.cases, f)))
        kind = case.get("kind", "?")
        if kind in skip:
            continue
        for n in range(a.per_case):
            m, what = mutate(case, r)
            with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False, dir=a.out) as t:
                json.dump(m, t)
                path = t.name
            p, seconds = run_case(a.gearbench, path, a.timeout)
            if p is None:  # past the limit: once more with the long one
                p, seconds = run_case(a.gearbench, path, a.retry_timeout)
                if p is None:
                    counts[kind]["hang"] += 1
                    keep = os.path.join(a.out, f"finding_{kind}_{f[:-5]}_{n}.json")
                    os.replace(path, keep)
                    findings.append((kind, f, "hang", what, f"no result after {a.retry_timeout:g} s", keep))
                    continue
                slow.append((kind, f, what, seconds, p.returncode))
            code = p.returncode
            errors = [l for l in p.stderr.splitlines() if l.startswith("error:")]
            if code < 0:
                outcome = "crash"
            elif code == 0:
                try:
                    bad = implausible(json.loads(p.stdout))
                except json.JSONDecodeError:
                    bad = ["stdout is not JSON"]
                outcome = "implausible exit 0" if bad else "exit 0"
                if bad:
                    what += " -> " + "; ".join(bad[:3])
            elif code in (2, 3):
                outcome = f"exit {code}" if len(errors) == 1 else f"exit {code}, {len(errors)} error lines"
            else:
                outcome = f"exit {code}"
            counts[kind][outcome] += 1
            if outcome not in ("exit 0", "exit 2", "exit 3"):
                keep = os.path.join(a.out, f"finding_{kind}_{f[:-5]}_{n}.json")
                os.replace(path, keep)
                findings.append((kind, f, outcome, what, (p.stderr.strip().splitlines() or [""])[-1][:200], keep))
            else:
                os.unlink(path)
    total = collections.Counter()
    columns = ["exit 0", "exit 2", "exit 3", "hang"]
    print(f"{'kind':22s} " + " ".join(f"{c:>8s}" for c in columns + ["other", "slow"]))
    slow_per_kind = collections.Counter(s[0] for s in slow)
    for kind, c in sorted(counts.items()):
        total.update(c)
        other = sum(v for k, v in c.items() if k not in columns)
        print(f"{kind:22s} " + " ".join(f"{c[k]:>8d}" for k in columns) + f" {other:>8d} {slow_per_kind[kind]:>8d}")
    print("total", dict(total), f"slow {len(slow)}")
    for kind, case, what, seconds, code in slow:
        print("SLOW", kind, case, what, f"{seconds:.1f} s", f"exit {code}", sep=" | ")
    for fnd in findings:
        print("FINDING", *fnd, sep=" | ")

if __name__ == "__main__":
    main()
