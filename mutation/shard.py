#!/usr/bin/env python3
"""Shards of a Stryker.NET run over core/, and the merge of their reports into one.

    python3 mutation/shard.py files K N          the core files of shard K (0-based) of N, one per line
    python3 mutation/shard.py deal N             every shard's files: "K<tab>file" lines
    python3 mutation/shard.py weights N          files and weight per shard
    python3 mutation/shard.py stamp REPORT K N   marks a shard's report with its shard and files (run.sh does)
    python3 mutation/shard.py merge OUT REPORT...  one report from the shards' mutation-report.json files

A full run of all of core takes about 1 h 40 min on 2 cores (docs/mutation.md), so the nightly workflow runs it as N
shards side by side (.github/workflows/nightly-mutation.yml) and merges their reports. Files are dealt to shards by
weight, largest first, each to the lightest shard so far; a file's weight is its mutant count in the committed report
(mutation/reports/mutation-report.json; ignored and
non-compiling mutants left out), or its line count for a file that report does not know. The deal depends only
on the tree, so every shard of one run sees the same deal.

A partial Stryker run still reports every file of the project (the ones it did not mutate with "Ignored" mutants), so
each shard's report is stamped with its shard and files, and merge takes every file from its owner. merge refuses a
shard given twice, a missing shard, shards of different N, and a deal that misses a core file; it writes OUT/mutation-report.json
and OUT/mutation-report.md, prints the merged score, and exits 3 when the score is below the break threshold of
mutation/stryker-config.json (the threshold a single full run applies), 2 on bad input.
"""

import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COMMITTED = os.path.join(ROOT, "mutation", "reports", "mutation-report.json")
CONFIG = os.path.join(ROOT, "mutation", "stryker-config.json")
DETECTED = ("Killed", "Timeout")
UNDETECTED = ("Survived", "NoCoverage")


class Refused(Exception):
    """Bad input: the message says what, the exit code is 2."""


def core_files():
    out = subprocess.run(["git", "-C", ROOT, "ls-files", "core/*.cs"], check=True, capture_output=True, text=True)
    files = sorted(f for f in out.stdout.splitlines() if f.strip())
    if not files:
        raise Refused("no core/*.cs files tracked by git under " + ROOT)
    return files


def weights(files):
    known = {}
    if os.path.exists(COMMITTED):
        with open(COMMITTED, encoding="utf-8") as f:
            for name, entry in json.load(f)["files"].items():
                # Mutants Stryker tests: ignored ones and compile errors cost (almost) nothing.
                known[name] = sum(1 for m in entry["mutants"] if m["status"] not in ("Ignored", "CompileError"))
    result = {}
    for name in files:
        if name in known:
            result[name] = known[name]
        else:
            with open(os.path.join(ROOT, name), encoding="utf-8") as f:
                result[name] = sum(1 for _ in f)
    return result


def deal(files, n):
    w = weights(files)
    shards = [[] for _ in range(n)]
    load = [0] * n
    # Largest first, ties by name: the same tree always gives the same deal.
    for name in sorted(files, key=lambda f: (-w[f], f)):
        k = min(range(n), key=lambda i: (load[i], i))
        shards[k].append(name)
        load[k] += w[name]
    return [sorted(s) for s in shards], load


def parse_shard(k_text, n_text):
    try:
        k, n = int(k_text), int(n_text)
    except ValueError:
        raise Refused(f"shard: K and N must be integers, got '{k_text}' '{n_text}'")
    if n < 1 or not 0 <= k < n:
        raise Refused(f"shard: need 0 <= K < N and N >= 1, got K={k} N={n}")
    return k, n


def counts(report):
    c = {}
    for entry in report["files"].values():
        for m in entry["mutants"]:
            c[m["status"]] = c.get(m["status"], 0) + 1
    return c


def score_of(c):
    valid = sum(c.get(s, 0) for s in DETECTED + UNDETECTED)
    return 100.0 * sum(c.get(s, 0) for s in DETECTED) / valid if valid else 0.0


def stamp(path, k, n):
    """Records in a shard's report which shard it is and which files it owns (run.sh --shard calls this).

    Stryker's report of a partial run still lists every file of the project, the ones outside the run with their
    mutants "Ignored", so the merge takes each file from the shard that owns it, not from whichever report has it."""
    shards, _ = deal(core_files(), n)
    try:
        with open(path, encoding="utf-8") as f:
            report = json.load(f)
    except (OSError, ValueError) as e:
        raise Refused(f"stamp: cannot read {path}: {e}")
    report["acphysShard"] = {"shard": k, "of": n, "files": shards[k]}
    write_atomically(path, json.dumps(report))


def merge(out_dir, paths):
    if not paths:
        raise Refused("merge: no reports given")
    merged = None
    by_shard = {}
    n = None
    for path in paths:
        try:
            with open(path, encoding="utf-8") as f:
                report = json.load(f)
        except (OSError, ValueError) as e:
            raise Refused(f"merge: cannot read {path}: {e}")
        if not isinstance(report, dict) or not isinstance(report.get("files"), dict):
            raise Refused(f"merge: {path} is not a Stryker JSON report (no 'files' object)")
        own = report.get("acphysShard")
        if not isinstance(own, dict) or not {"shard", "of", "files"} <= own.keys():
            raise Refused(f"merge: {path} is not a shard's report (no 'acphysShard': written by run.sh --shard)")
        if n is None:
            n = own["of"]
        elif own["of"] != n:
            raise Refused(f"merge: {path} is shard {own['shard']} of {own['of']}, the others are of {n}")
        if own["shard"] in by_shard:
            raise Refused(f"merge: shard {own['shard']} of {n} twice: {by_shard[own['shard']]} and {path}")
        by_shard[own["shard"]] = path
        if merged is None:
            merged = {k: v for k, v in report.items() if k not in ("files", "acphysShard")}
            merged["files"] = {}
        for name in own["files"]:
            if name not in report["files"]:
                raise Refused(f"merge: shard {own['shard']}'s report has no entry for its file {name} ({path})")
            merged["files"][name] = report["files"][name]
    missing_shards = [k for k in range(n) if k not in by_shard]
    if missing_shards:
        raise Refused(f"merge: no report of shard {', '.join(map(str, missing_shards))} of {n}")
    missing = [f for f in core_files() if f not in merged["files"]]
    if missing:
        raise Refused("merge: no shard mutated " + ", ".join(missing) + " (core changed since the shards were dealt?)")

    c = counts(merged)
    score = score_of(c)
    with open(CONFIG, encoding="utf-8") as f:
        break_at = float(json.load(f)["stryker-config"]["thresholds"]["break"])
    os.makedirs(out_dir, exist_ok=True)
    write_atomically(os.path.join(out_dir, "mutation-report.json"), json.dumps(merged))
    write_atomically(os.path.join(out_dir, "mutation-report.md"), markdown(merged, c, score, len(paths)))
    summary = " ".join(f"{s.lower()} {c.get(s, 0)}" for s in DETECTED + UNDETECTED)
    print(f"mutation: merged {len(paths)} shard reports, {len(merged['files'])} files: score {score:.2f} % ({summary})")
    if score < break_at:
        print(f"mutation: FAILED: {score:.2f} % is below the break threshold {break_at:g} %", file=sys.stderr)
        return 3
    print(f"mutation: OK ({score:.2f} % >= {break_at:g} %)")
    return 0


def markdown(report, c, score, shards):
    lines = [
        "# Mutation report (merged)",
        "",
        f"{shards} shards, {len(report['files'])} files. Score **{score:.2f} %** "
        f"= detected {sum(c.get(s, 0) for s in DETECTED)} / {sum(c.get(s, 0) for s in DETECTED + UNDETECTED)}.",
        "",
        "| file | score | killed | timeout | survived | no coverage |",
        "|---|---:|---:|---:|---:|---:|",
    ]
    for name in sorted(report["files"]):
        fc = counts({"files": {name: report["files"][name]}})
        row = [fc.get(s, 0) for s in ("Killed", "Timeout", "Survived", "NoCoverage")]
        lines.append(f"| {name} | {score_of(fc):.2f} % | " + " | ".join(str(x) for x in row) + " |")
    return "\n".join(lines) + "\n"


def write_atomically(path, text):
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".merge.")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def main(argv):
    try:
        if len(argv) == 4 and argv[1] == "files":
            k, n = parse_shard(argv[2], argv[3])
            shards, _ = deal(core_files(), n)
            print("\n".join(shards[k]))
            return 0
        if len(argv) == 3 and argv[1] == "deal":
            _, n = parse_shard("0", argv[2])
            shards, _ = deal(core_files(), n)
            print("\n".join(f"{k}\t{f}" for k in range(n) for f in shards[k]))
            return 0
        if len(argv) == 3 and argv[1] == "weights":
            _, n = parse_shard("0", argv[2])
            shards, load = deal(core_files(), n)
            for k in range(n):
                print(f"shard {k}/{n}: {len(shards[k])} files, weight {load[k]}")
            return 0
        if len(argv) == 5 and argv[1] == "stamp":
            k, n = parse_shard(argv[3], argv[4])
            stamp(argv[2], k, n)
            return 0
        if len(argv) >= 3 and argv[1] == "merge":
            return merge(argv[2], argv[3:])
        raise Refused("usage: shard.py files K N | deal N | weights N | stamp REPORT K N | merge OUT REPORT...")
    except Refused as e:
        print(f"mutation: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
