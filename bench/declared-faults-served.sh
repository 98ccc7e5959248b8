#!/usr/bin/env bash
# Declaration × fault, served (issue 41, "every declaration × every non-deviation planted fault: the gate fails, in
# process and served"). For each planted fault that is not a documented deviation and each declaration a port can make
# (every fidelity name, and the current-first pick), serve the fault with the declaration announced in hello
# (`acphys serve --fault F --fidelity X`) and run the gate against it over protocol v1 with the fault's expected
# catchers, then (if they pass) the four conformance invariants (`--only`, `--max-classes 1`). The gate must fail (exit 1) every time:
# a declaration may excuse only its own deviation. In process the same matrix is props/Judging/IntendedIsProvedTests
# (DeclaringNeverTurnsAFaultGreen).
#
#   bench/declared-faults-served.sh                          # every non-deviation fault × 13 declarations (hours)
#   bench/declared-faults-served.sh --faults close-is-outside,trunc-floor --declarations ace,current-first
#   bench/declared-faults-served.sh --cases 1000 --out table.md   # the markdown table, written atomically
#   ACPHYS_DLL=/path/acphys.dll bench/declared-faults-served.sh   # another build (default: cli/bin/Release/net10.0/acphys.dll)
#
# Build first: dotnet build -c Release cli/AcPhys.Cli.csproj (the build is copied to a temporary folder).
# A pass whose judges are all NOT TESTED under the declaration (verify exit 4) is not a catch: the next pass runs.
# Exit codes: 0 the gate failed for every pair; 1 some pair passed (a declaration turned a fault green: listed);
# 2 bad usage or a run that ended with neither verdict (the pair and its exit code are listed).
set -euo pipefail

cases=""
faults=""
declarations=""
out=""
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dll="${ACPHYS_DLL:-$root/cli/bin/Release/net10.0/acphys.dll}"
# The documented deviations among the planted faults (docs/conformance.md, "Which declaration would make a finding
# intended"): a port that declares them is right to behave so, so they are not in this matrix.
deviations=" no-hysteresis sticky-pick no-hysteresis-indoor ace-hint-key early-return-undeclared ace-announced-retail ace-box-side-undeclared "
conformance="LANDDEFS-CONFORMANCE,OUTSIDE-CELLS-CONFORMANCE,FIND-CELL-QUERY-CONFORMANCE,FIND-CELL-CONFORMANCE"

usage() { sed -n '2,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --cases) cases="${2:?--cases needs a number}"; shift 2 ;;
    --faults) faults="${2:?--faults needs a list}"; shift 2 ;;
    --declarations) declarations="${2:?--declarations needs a list}"; shift 2 ;;
    --out) out="${2:?--out needs a file}"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "declared-faults-served: unknown option $1" >&2; usage >&2; exit 2 ;;
  esac
done
if [[ -n "$cases" && ! "$cases" =~ ^[1-9][0-9]*$ ]]; then
  echo "declared-faults-served: --cases must be a positive whole number, not '$cases'" >&2
  exit 2
fi
if [[ ! -f "$dll" ]]; then
  echo "declared-faults-served: no build at $dll (dotnet build -c Release cli/AcPhys.Cli.csproj, or set ACPHYS_DLL)" >&2
  exit 2
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/declared-faults.XXXXXX")"
trap 'rm -rf "$work"' EXIT
trap 'exit 130' INT TERM # the EXIT trap then removes the copy; each served child ends with its verify
cp -r "$(dirname "$dll")" "$work/bin"
acphys=(dotnet "$work/bin/$(basename "$dll")")
serve="dotnet $work/bin/$(basename "$dll") serve"

# Fault name → expected catchers, from `acphys faults` (a box table: column 2 the name, column 4 the catchers; a
# wrapped row continues the catchers with an empty name).
"${acphys[@]}" faults | awk -F'│' '
  NF > 3 { name = $2; gsub(/ /, "", name); c = $4; gsub(/ /, "", c)
           if (name ~ /^[a-z0-9][a-z0-9-]*$/) { if (cur != "") print cur "\t" cat; cur = name; cat = c }
           else if (cur != "" && c != "") cat = cat c }
  END { if (cur != "") print cur "\t" cat }' > "$work/catchers.tsv"
if [[ ! -s "$work/catchers.tsv" ]]; then
  echo "declared-faults-served: no planted faults listed by acphys faults" >&2
  exit 2
fi
if [[ -z "$faults" ]]; then
  faults="$(cut -f1 "$work/catchers.tsv" | while read -r f; do [[ "$deviations" == *" $f "* ]] || echo "$f"; done | paste -sd, -)"
fi
if [[ -z "$declarations" ]]; then
  # Every fidelity name the tool knows (its own error message lists them), then the pick.
  known="$( { "${acphys[@]}" verify --fidelity '?' 2>&1 || true; } | sed -n 's/.*(known: \(.*\))$/\1/p' | tr -d ' ')"
  [[ -n "$known" ]] || { echo "declared-faults-served: could not list the fidelity names" >&2; exit 2; }
  declarations="$known,current-first"
fi

declare_flag() { if [[ "$1" == current-first ]]; then echo "--pick current-first"; else echo "--fidelity $1"; fi; }

echo "declared faults served: $(echo "$faults" | tr ',' '\n' | wc -l | tr -d ' ') faults × $(echo "$declarations" | tr ',' '\n' | wc -l | tr -d ' ') declarations${cases:+, --cases $cases}, build $dll"
echo "load at start: $(uptime | sed 's/.*load average: //')"
started=$(date +%s)
table="$work/table.md"
{
  echo "| fault | $(echo "$declarations" | sed 's/,/ | /g') |"
  echo "|---|$(echo "$declarations" | sed 's/[^,]*/---/g; s/,/|/g')|"
} > "$table"
green=0
broken=0
for fault in ${faults//,/ }; do
  catchers="$(awk -F'\t' -v f="$fault" '$1 == f { print $2 }' "$work/catchers.tsv")"
  if [[ -z "$catchers" ]]; then
    echo "declared-faults-served: unknown fault '$fault' (see: acphys faults)" >&2
    exit 2
  fi
  row="| \`$fault\` |"
  for decl in ${declarations//,/ }; do
    flag="$(declare_flag "$decl")"
    # The expected catchers first (most faults fail there within seconds), then the conformance invariants.
    for judges in "$catchers" "$conformance"; do
      set +e
      # shellcheck disable=SC2086 # $flag is two words on purpose
      "${acphys[@]}" verify -q --impl-cmd "$serve --fault $fault $flag" --only "$judges" --max-classes 1 ${cases:+--cases "$cases"} > "$work/run.log" 2>&1
      rc=$?
      set -e
      # 1: caught. 0, or 4 (every judge of this pass NOT TESTED under the declaration, as a BrokenByDesign statement
      # is): not caught here, so the next pass judges (in process: props IntendedIsProvedTests, catchers ∪ conformance).
      [[ "$rc" == 0 || "$rc" == 4 ]] || break
    done
    case "$rc" in
      1) row="$row fails |" ;;
      0|4) row="$row **passes** |"; green=$((green + 1)); echo "GREEN: serve --fault $fault $flag passed the gate (its catchers $catchers and the conformance invariants; last exit $rc)" ;;
      *) row="$row exit $rc |"; broken=$((broken + 1)); echo "BROKEN: serve --fault $fault $flag: verify exited $rc"; tail -3 "$work/run.log" | sed 's/^/    /' ;;
    esac
  done
  echo "$row" >> "$table"
  echo "$row"
done
elapsed=$(( $(date +%s) - started ))
echo "declared faults served: $green pairs passed the gate, $broken ended with neither verdict, ${elapsed} s, load at end: $(uptime | sed 's/.*load average: //')"
if [[ -n "$out" ]]; then
  tmp="$(mktemp "$(dirname "$out")/.declared-faults.XXXXXX")"
  cp "$table" "$tmp"
  mv -f "$tmp" "$out"
  echo "table written to $out"
fi
if (( broken > 0 )); then exit 2; fi
if (( green > 0 )); then exit 1; fi
exit 0
