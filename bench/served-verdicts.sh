#!/usr/bin/env bash
# Served verdict comparison (issue #26): for the reference and every planted fault, run the gate in process and against
# `acphys serve` over protocol v1, and check that every invariant gets the same verdict (passed / failed / not tested).
#
#   bench/served-verdicts.sh                      # all faults, 300 cases, 1 failure class per invariant
#   bench/served-verdicts.sh --faults trunc-floor,nan-as-zero --cases 100
#   bench/served-verdicts.sh --no-reference --faults ...  # a shard: leave out the unfaulted reference
#   ACPHYS_DLL=/path/acphys.dll bench/served-verdicts.sh   # another build (default: cli/bin/Release/net10.0/acphys.dll)
#   bench/served-verdicts.sh --save DIR           # also keep each run's verdicts (DIR/FAULT.in.txt, DIR/FAULT.served.txt)
#                                                 # so two builds can be compared: diff -r BEFORE AFTER (a refactor guard)
#   bench/served-verdicts.sh --in-process-only --save DIR   # the in-process half only (a quicker refactor guard)
#
# Build first: dotnet build -c Release cli/AcPhys.Cli.csproj. The build is copied to a temporary folder, so rebuilding
# while this runs does not change what it measures. Each run writes JUnit XML (--junit); the verdicts are read from it.
# Exit codes: 0 every verdict equal; 1 a difference (listed per fault); 2 bad usage or a run that gave no report.
set -euo pipefail

cases=300
max_classes=1
faults=""
reference=reference
save=""
served=1
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dll="${ACPHYS_DLL:-$root/cli/bin/Release/net10.0/acphys.dll}"

usage() { sed -n '2,15p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --cases) cases="$2"; shift 2 ;;
    --max-classes) max_classes="$2"; shift 2 ;;
    --faults) faults="$2"; shift 2 ;;
    --no-reference) reference=""; shift ;;
    --save) save="$2"; shift 2 ;;
    --in-process-only) served=""; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "served-verdicts: unknown option $1" >&2; usage >&2; exit 2 ;;
  esac
done

if [[ ! -f "$dll" ]]; then
  echo "served-verdicts: no build at $dll (dotnet build -c Release cli/AcPhys.Cli.csproj, or set ACPHYS_DLL)" >&2
  exit 2
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/served-verdicts.XXXXXX")"
trap 'rm -rf "$work"' EXIT
trap 'exit 130' INT TERM # the EXIT trap then removes the copy; each served child ends with its verify (ImplProcesses)
cp -r "$(dirname "$dll")" "$work/bin"
acphys=(dotnet "$work/bin/$(basename "$dll")")

if [[ -z "$faults" ]]; then
  # The fault names are the first column of `acphys faults` (a box table; wrapped rows leave the column empty).
  faults="$("${acphys[@]}" faults | awk -F'│' 'NF > 2 { gsub(/ /, "", $2); if ($2 ~ /^[a-z0-9][a-z0-9-]*$/) print $2 }' | paste -sd, -)"
fi
if [[ -z "$faults" ]]; then
  echo "served-verdicts: no planted faults listed by acphys faults" >&2
  exit 2
fi

# Prints "ID verdict" per invariant of a JUnit report, sorted; verdict is passed, failed or not-tested.
verdicts() {
  python3 - "$1" <<'PY'
import sys, xml.etree.ElementTree as ET
rows = []
for case in ET.parse(sys.argv[1]).getroot().iter("testcase"):
    kind = "failed" if case.find("failure") is not None or case.find("error") is not None \
        else "not-tested" if case.find("skipped") is not None else "passed"
    rows.append(f"{case.get('name')} {kind}")
print("\n".join(sorted(rows)))
PY
}

count() { awk -v k="$2" '$2 == k' "$1" | wc -l | tr -d ' '; }

started=$(date +%s)
echo "served verdicts: $(echo "$faults" | tr ',' '\n' | wc -l | tr -d ' ') faults${reference:+ + the reference}, --cases $cases --max-classes $max_classes, $([[ -n "$served" ]] && echo "in process and served" || echo "in process only"), build $dll"
echo "load at start: $(uptime | sed 's/.*load average: //')"
differ=0
broken=0
for fault in $reference ${faults//,/ }; do
  flag=(); serve_flag=""
  if [[ "$fault" != reference ]]; then flag=(--fault "$fault"); serve_flag=" --fault $fault"; fi
  common=(--cases "$cases" --max-classes "$max_classes" -q)
  t0=$(date +%s.%N)
  set +e
  "${acphys[@]}" verify "${flag[@]}" "${common[@]}" --junit "$work/in.xml" > "$work/in.log" 2>&1
  rc_in=$?
  t1=$(date +%s.%N)
  if [[ -n "$served" ]]; then
    "${acphys[@]}" verify --impl-cmd "${acphys[*]} serve$serve_flag" "${common[@]}" --junit "$work/served.xml" > "$work/served.log" 2>&1
    rc_served=$?
  fi
  t2=$(date +%s.%N)
  set -e
  if [[ -z "$served" ]]; then
    if [[ ! -s "$work/in.xml" ]]; then
      echo "$fault: NO REPORT (exit $rc_in in process)"
      tail -3 "$work/in.log" | sed 's/^/    /'
      broken=1
      rm -f "$work/in.xml"
      continue
    fi
    verdicts "$work/in.xml" > "$work/in.txt"
    if [[ -n "$save" ]]; then
      mkdir -p "$save"
      { cat "$work/in.txt"; echo "exit $rc_in"; } > "$save/$fault.in.txt"
    fi
    echo "$fault: $(count "$work/in.txt" passed) passed, $(count "$work/in.txt" failed) failed, $(count "$work/in.txt" not-tested) not tested; exit $rc_in; $(printf '%.1f s in process' "$(echo "$t1 - $t0" | bc)")"
    rm -f "$work/in.xml"
    continue
  fi
  times=$(printf '%.1f s in process, %.1f s served' "$(echo "$t1 - $t0" | bc)" "$(echo "$t2 - $t1" | bc)")
  if [[ ! -s "$work/in.xml" || ! -s "$work/served.xml" ]]; then
    echo "$fault: NO REPORT (exit $rc_in in process, $rc_served served; $times)"
    tail -3 "$work/in.log" "$work/served.log" | sed 's/^/    /'
    broken=1
    rm -f "$work/in.xml" "$work/served.xml"
    continue
  fi
  verdicts "$work/in.xml" > "$work/in.txt"
  verdicts "$work/served.xml" > "$work/served.txt"
  if [[ -n "$save" ]]; then
    mkdir -p "$save"
    { cat "$work/in.txt"; echo "exit $rc_in"; } > "$save/$fault.in.txt"
    { cat "$work/served.txt"; echo "exit $rc_served"; } > "$save/$fault.served.txt"
  fi
  summary="$(count "$work/in.txt" passed) passed, $(count "$work/in.txt" failed) failed, $(count "$work/in.txt" not-tested) not tested"
  if cmp -s "$work/in.txt" "$work/served.txt" && [[ $rc_in == "$rc_served" ]]; then
    echo "$fault: same ($summary; exit $rc_in; $times)"
  else
    differ=1
    echo "$fault: DIFFERENT (in process: $summary, exit $rc_in; served exit $rc_served; $times)"
    join -a1 -a2 -e '(absent)' -o 0,1.2,2.2 "$work/in.txt" "$work/served.txt" \
      | awk '$2 != $3 { printf "    %s: in process %s, served %s\n", $1, $2, $3 }'
  fi
  rm -f "$work/in.xml" "$work/served.xml"
done

echo "wall time $(( $(date +%s) - started )) s; load at end: $(uptime | sed 's/.*load average: //')"
if [[ $broken == 1 ]]; then
  echo "served-verdicts: a run gave no report (see above)" >&2
  exit 2
fi
if [[ $differ == 1 ]]; then
  echo "served-verdicts: verdicts differ between in process and served (see above)" >&2
  exit 1
fi
if [[ -n "$served" ]]; then echo "served-verdicts: every verdict equal"; else echo "served-verdicts: every run reported (in process only: compare --save folders with diff -r)"; fi
