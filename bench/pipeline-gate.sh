#!/bin/sh
# The pr gate served over protocol v1 against the same gate in process, per invariant and whole (issue 26,
# docs/protocol.md "Speed"). A benchmark, not a test: it prints a table and asserts nothing.
#
#   bench/pipeline-gate.sh [OUT_DIR] [-- extra verify arguments, e.g. --only X,Y --cases 1000]
#
# Runs, one right after the other: in process; `acphys serve` (scenes as dat records); `serve --no-dat-records`
# (JSON scenes); `serve --no-pipeline` (each answer awaited); the Python example with and without `pipeline` (its
# outdoor ops, so the comparison stays on the same ops while the example grows). Each run's JUnit file, output and
# wall/CPU time land in OUT_DIR (default /tmp/acphys-pipeline-bench); the load average is printed before each run.
# Build first: dotnet build -c Release cli/AcPhys.Cli.csproj
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-/tmp/acphys-pipeline-bench}
[ $# -gt 0 ] && shift
[ "${1:-}" = "--" ] && shift
mkdir -p "$out"
acphys="dotnet $here/cli/bin/Release/net10.0/acphys.dll"
py_ops="blockid_to_lcoord,gid_to_lcoord,lcoord_to_gid,inbound_valid_cellid,get_outside_lcoord,adjust_to_outside,outside_cells,find_cell,find_cell_walk"

run() { # name, then verify arguments
  name=$1
  shift
  printf '%s  %s\n' "$name" "$(cut -d' ' -f1-3 /proc/loadavg)" >&2
  /usr/bin/time -f "%e %U %S" -o "$out/$name.time" $acphys verify --junit "$out/$name.xml" "$@" >"$out/$name.out" 2>"$out/$name.err" || true
  printf '%s\n' "$(cut -d' ' -f1-3 /proc/loadavg)" >"$out/$name.load"
}

run inproc "$@"
run served --impl-cmd "$acphys serve" --timeout 60 "$@"
run served-json --impl-cmd "$acphys serve --no-dat-records" --timeout 60 "$@"
run served-waiting --impl-cmd "$acphys serve --no-pipeline" --timeout 60 "$@"
run python --impl-cmd "python3 $here/examples/python/acphys_impl.py --ops $py_ops,pipeline" --timeout 60 "$@"
run python-waiting --impl-cmd "python3 $here/examples/python/acphys_impl.py --ops $py_ops" --timeout 60 "$@"

python3 - "$out" <<'EOF'
import sys, xml.etree.ElementTree as ET
out = sys.argv[1]
runs = ["inproc", "served", "served-json", "served-waiting", "python", "python-waiting"]
times, verdicts, wall = {}, {}, {}
for r in runs:
    root = ET.parse(f"{out}/{r}.xml").getroot()
    for tc in root.iter("testcase"):
        if tc.get("classname") != "acphys.invariants":
            continue
        v = "FAIL" if tc.find("failure") is not None else "NT" if tc.find("skipped") is not None else "pass"
        times.setdefault(tc.get("name"), {})[r] = float(tc.get("time"))
        verdicts.setdefault(tc.get("name"), {})[r] = v
    w, u, s = open(f"{out}/{r}.time").read().split()
    wall[r] = (float(w), float(u) + float(s), open(f"{out}/{r}.load").read().strip())

def cell(inv, r):
    t, base = times[inv].get(r), times[inv].get("inproc")
    if t is None or verdicts[inv][r] == "NT":
        return "not tested"
    ratio = f" ({t / base:.1f}x)" if base else ""
    return f"{t:.2f} s{ratio}" + (" FAIL" if verdicts[inv][r] == "FAIL" else "")

print("| invariant | " + " | ".join(runs) + " |")
print("|---|" + "---|" * len(runs))
for inv in times:
    print(f"| {inv} | " + " | ".join(cell(inv, r) for r in runs) + " |")
base = wall["inproc"][0]
print("| whole run, wall (CPU tool+child; load after) | " + " | ".join(f"{w:.1f} s ({w / base:.1f}x; CPU {c:.0f} s; load {l})" for (w, c, l) in (wall[r] for r in runs)) + " |")
same = all(len({verdicts[i][r] for r in ["inproc", "served", "served-json", "served-waiting"]}) == 1 for i in verdicts)
pysame = all(verdicts[i]["python"] == verdicts[i]["python-waiting"] for i in verdicts)
print(f"\nverdicts: served runs equal in process: {same}; python with and without pipeline equal: {pysame}")
EOF
