#!/usr/bin/env bash
# False-alarm sweep (issue 27, "no false alarm from the reference"): the unfaulted reference judged by the gate on many
# base seeds, in every declared mode, in process and served over protocol v1. The reference is correct by definition,
# so every FAIL line here is a defect of the suite (a generator, an oracle or the wire), never of the reference.
#
#   bench/false-alarm-sweep.sh --seeds 20                      # 20 fresh base seeds (printed), pr gate in process
#   bench/false-alarm-sweep.sh --seeds 1234,5678 --served      # these seeds, also served (`acphys serve`, records)
#   bench/false-alarm-sweep.sh --seeds 20 --served --served-cases 300 --modes retail,ace
#   bench/false-alarm-sweep.sh --seeds 20 --cases 1000 --modes current-first,ace   # a smaller in-process budget
#   bench/false-alarm-sweep.sh --seeds 20 --only PARTS-INDOOR-SOUNDNESS,PARTS-INDOOR-CONFORMANCE  # these invariants only
#
# Modes (what the reference declares, and the gate is told): retail; current-first (--pick current-first); ace
# (--fidelity ace); double (--fidelity double); ace-current-first (both); any one switch by its name
# (ace-keeps-stale-cells, ace-early-return, …, drop-unloaded-land-cells, reframe-transit). A served run serves the same mode
# (`acphys serve --pick ... --fidelity ...`), so its hello declares it. Served runs use --served-cases cases per
# invariant (default 300) to keep the sweep to minutes; in-process runs the full pr budget unless --cases is given.
# --only ID,ID passes the list to verify --only (both in process and served): a change that touches only some
# invariants' generators is swept on those alone.
#
# Build first: dotnet build -c Release cli/AcPhys.Cli.csproj; the build is copied, so rebuilding meanwhile is safe.
# Output: one line per run (mode, where, seed, exit, passed/failed/not tested, wall) and every FAIL line; a table in
# OUT (default /tmp/acphys-false-alarms/sweep.tsv). Exit codes: 0 no run failed; 1 a run failed (a false alarm:
# its FAIL lines and replay commands are printed); 2 bad usage or a run that did not finish.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dll="${ACPHYS_DLL:-$root/cli/bin/Release/net10.0/acphys.dll}"
seeds=""
served=0
served_cases=300
cases=""
only=""
modes="retail,current-first,ace,double,ace-current-first"
out="/tmp/acphys-false-alarms"

usage() { sed -n '2,23p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) seeds="$2"; shift 2 ;;
    --served) served=1; shift ;;
    --served-cases) served_cases="$2"; shift 2 ;;
    --cases) cases="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --modes) modes="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "false-alarm-sweep: unknown option $1" >&2; usage >&2; exit 2 ;;
  esac
done
[[ -n "$seeds" ]] || { echo "false-alarm-sweep: --seeds N or --seeds S1,S2,... is required" >&2; exit 2; }
[[ -f "$dll" ]] || { echo "false-alarm-sweep: no build at $dll (dotnet build -c Release cli/AcPhys.Cli.csproj)" >&2; exit 2; }

if [[ "$seeds" =~ ^[0-9]+$ ]] && (( seeds <= 1000 )); then
  # N fresh seeds: 40-bit values from the kernel's random source, printed so the sweep can be repeated.
  seeds="$(od -An -N$(( seeds * 5 )) -tu1 /dev/urandom | tr -s ' \n' ' ' | python3 -c '
import sys
b = [int(v) for v in sys.stdin.read().split()]
print(",".join(str(int.from_bytes(bytes(b[i:i + 5]), "big") + 1) for i in range(0, len(b), 5)))')"
fi
echo "false-alarm-sweep: seeds $seeds"

work="$(mktemp -d "${TMPDIR:-/tmp}/false-alarm-sweep.XXXXXX")"
trap 'rm -rf "$work"' EXIT
cp -r "$(dirname "$dll")" "$work/bin"
acphys=(dotnet "$work/bin/$(basename "$dll")")
mkdir -p "$out"
table="$out/sweep.tsv"
printf 'mode\twhere\tseed\texit\tpassed\tfailed\tnot_tested\twall_s\n' > "$table.tmp"

flags_of() {
  case "$1" in
    retail) echo "" ;;
    current-first) echo "--pick current-first" ;;
    ace) echo "--fidelity ace" ;;
    double) echo "--fidelity double" ;;
    ace-current-first) echo "--pick current-first --fidelity ace" ;;
    ace-*|drop-unloaded-land-cells|reframe-transit) echo "--fidelity $1" ;; # one declared switch (issue 41)
    *) echo "false-alarm-sweep: unknown mode $1" >&2; exit 2 ;;
  esac
}

alarms=0
unfinished=0
IFS=',' read -ra seed_list <<< "$seeds"
IFS=',' read -ra mode_list <<< "$modes"
for mode in "${mode_list[@]}"; do
  flags="$(flags_of "$mode")"
  for seed in "${seed_list[@]}"; do
    wheres=(inproc)
    (( served )) && wheres+=(served)
    for where in "${wheres[@]}"; do
      log="$work/$mode-$where-$seed.out"
      start=$(date +%s.%N)
      set +e
      if [[ "$where" == inproc ]]; then
        # shellcheck disable=SC2086
        "${acphys[@]}" verify -q --base-seed "$seed" ${cases:+--cases "$cases"} ${only:+--only "$only"} $flags > "$log" 2>&1
      else
        # shellcheck disable=SC2086
        "${acphys[@]}" verify -q --base-seed "$seed" --cases "$served_cases" --timeout 60 ${only:+--only "$only"} \
          --impl-cmd "${acphys[*]} serve $flags" > "$log" 2>&1
      fi
      rc=$?
      set -e
      wall=$(python3 -c "import time; print(f'{time.time() - $start:.1f}')")
      summary="$(grep -E '^verify: [0-9]+ invariants' "$log" | tail -1 || true)"
      read -r passed failed not_tested < <(python3 -c '
import re, sys
m = re.search(r"(\d+) passed, (\d+) failed, (\d+) not tested", sys.argv[1])
print(*(m.groups() if m else ("-", "-", "-")))' "$summary")
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$mode" "$where" "$seed" "$rc" "$passed" "$failed" "$not_tested" "$wall" >> "$table.tmp"
      echo "$mode $where seed $seed: exit $rc, $passed passed, $failed failed, $not_tested not tested (${wall} s)"
      if [[ "$rc" == 1 ]]; then
        alarms=$(( alarms + 1 ))
        grep -E '^FAIL|replay' "$log" | sed 's/^/    /' || true
        cp "$log" "$out/alarm-$mode-$where-$seed.out"
      elif [[ "$rc" != 0 ]]; then
        unfinished=$(( unfinished + 1 ))
        tail -5 "$log" | sed 's/^/    /'
        cp "$log" "$out/unfinished-$mode-$where-$seed.out"
      fi
    done
  done
done
mv "$table.tmp" "$table"
echo "false-alarm-sweep: $alarms run(s) with a false alarm, $unfinished unfinished; table $table"
(( alarms == 0 )) || exit 1
(( unfinished == 0 )) || exit 2
