#!/usr/bin/env bash
# Does the gate bite on a port's code? Stryker.NET over a port's project with its gate tests (AcPhys.Xunit,
# `GateTests<TAdapter>`) as the test project: every mutant of the port the gate does not notice is a line of the port
# no invariant pins (docs/ports.md, "Does the gate bite on your code?").
#
#   bash mutation/port.sh [PORT_DIR] [--publish DIR] [-- STRYKER ARGS...]
#
# PORT_DIR (default examples/dotnet-port) holds the port's project and a stryker-config.json naming it and its gate
# test project (examples/dotnet-port/stryker-config.json is one to copy). The gate runs under ACPHYS_PROFILE=pr (the PR
# gate as CI runs it; set ACPHYS_PROFILE to change it). Stryker runs in a private copy of the git work tree holding
# PORT_DIR (tracked and untracked-not-ignored files), as mutation/run.sh does: it swaps the mutated port assembly into
# the gate tests' bin, so a build in the real tree during the run would put the original back and every later mutant
# would "survive". Its output goes to artifacts/mutation-port/<UTC stamp>/ of this repository. --publish DIR copies the json and markdown reports there (each moved into place
# whole). Prints the score, the survivors (file:line, mutator, replacement), the wall time and the load.
# Exit: 0 when Stryker ran (the score is a measurement, not a gate here), 2 on a usage error, Stryker's code otherwise.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
port="$root/examples/dotnet-port"
publish=""
extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --publish) publish="${2:?--publish needs a folder}"; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    -*) echo "port.sh: unknown option '$1' (known: --publish DIR, -- STRYKER ARGS)" >&2; exit 2 ;;
    *) port="$(cd "$1" 2>/dev/null && pwd)" || { echo "port.sh: no folder '$1'" >&2; exit 2; }; shift ;;
  esac
done
[[ -f "$port/stryker-config.json" ]] || { echo "port.sh: $port has no stryker-config.json (copy examples/dotnet-port/stryker-config.json)" >&2; exit 2; }

export ACPHYS_PROFILE="${ACPHYS_PROFILE:-pr}"
export DOTNET_ROLL_FORWARD=Major DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
(cd "$root" && dotnet tool restore >/dev/null)

stamp="$(date -u +%Y%m%dT%H%M%SZ)"
out="$root/artifacts/mutation-port/$stamp"
mkdir -p "$out"
start=$(date +%s)
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
echo "mutation/port: stryker on $port (gate profile $ACPHYS_PROFILE), output $out, load $load_before"
tree="$(git -C "$port" rev-parse --show-toplevel)"
work="$(mktemp -d "${TMPDIR:-/tmp}/acphys-port-mutation.XXXXXX")"
trap 'rm -rf "$work"' EXIT
git -C "$tree" ls-files -z -co --exclude-standard | tar -C "$tree" --null -T - --ignore-failed-read -cf - 2>/dev/null | tar -C "$work" -xf -
copy="$work${port#"$tree"}"
set +e
(cd "$copy" && dotnet stryker --skip-version-check --output "$out" "${extra[@]}") 2>&1 | tee "$out/stryker.log"
rc=${PIPESTATUS[0]}
set -e
elapsed=$(( $(date +%s) - start ))
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

json="$out/reports/mutation-report.json"
[[ -f "$json" ]] || { echo "mutation/port: FAILED: stryker exited $rc and wrote no report (log: $out/stryker.log)" >&2; exit $(( rc == 0 ? 1 : rc )); }
for f in "$out"/reports/mutation-report.*; do sed -i "s#$copy/##g; s#$work/##g" "$f"; done

python3 - "$json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
c, survivors = {}, []
for name, f in sorted(d["files"].items()):
    lines = f["source"].split("\n")
    for m in f["mutants"]:
        c[m["status"]] = c.get(m["status"], 0) + 1
        if m["status"] in ("Survived", "NoCoverage"):
            line = m["location"]["start"]["line"]
            survivors.append(f'  {m["status"]:<10} {name}:{line}  {m["mutatorName"]}: {m.get("replacement", "")!r}  |  {lines[line - 1].strip()}')
k, t, s, n = c.get("Killed", 0), c.get("Timeout", 0), c.get("Survived", 0), c.get("NoCoverage", 0)
valid = k + t + s + n
print(f"mutation/port: score {100.0 * (k + t) / valid if valid else 0:.2f} % (killed {k}, timeout {t}, survived {s}, no coverage {n}; compile errors {c.get('CompileError', 0)}, ignored {c.get('Ignored', 0)})")
print("mutation/port: survivors (lines of the port no invariant pins):" if survivors else "mutation/port: no survivors")
print("\n".join(survivors))
PY
echo "mutation/port: wall ${elapsed} s on $(nproc) cores; load ${load_before} before, ${load_after} after"

if [[ -n "$publish" ]]; then
  mkdir -p "$publish"
  stage="$(mktemp -d "$publish/.staging.XXXXXX")"
  cp "$out/reports/mutation-report.json" "$out/reports/mutation-report.md" "$stage/"
  for f in "$stage"/*; do mv -f "$f" "$publish/$(basename "$f")"; done
  rmdir "$stage"
  echo "mutation/port: reports published to $publish"
fi
exit "$rc"
