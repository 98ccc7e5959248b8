#!/usr/bin/env bash
# Mutation testing of core/ (AcPhys.Core) by the props/ test suite with Stryker.NET.
#
#   bash mutation/run.sh                    full run; publishes reports to mutation/reports/
#   bash mutation/run.sh --since:main       only mutants in files changed since main (PR use)
#   bash mutation/run.sh -m "**/LandDefs.cs" only one file
#   bash mutation/run.sh --shard K/N        shard K (0-based) of N: the files `python3 mutation/shard.py files K N`
#                                           deals it; merge the shards' reports with `shard.py merge` (nightly)
#
# Any other argument is passed to dotnet-stryker. A run with arguments is partial: its reports stay in
# mutation/StrykerOutput/<stamp>/ and mutation/reports/ (the committed full-run reports) is left alone.
#
# Stryker runs in a private copy of the working tree (tracked + untracked-not-ignored files and .git),
# not in place: it rebuilds props/ and swaps the mutated AcPhys.Core.dll into props/bin, so a build in
# the same tree during a run silently restores the original dll (every mutant then "survives"), and a
# `dotnet test` in the tree during a run would test mutated code. See docs/mutation.md.
#
# The config's test-case-filter leaves out the meta tests that check the suite, not core (PlantedFaultsAreCaught.EveryInvariantBites,
# IndoorFaultsAreCaught, ConformanceBites.IndoorFaultsAreCaught). EveryInvariantBites: it checks the suite
# (every invariant catches some planted fault, 31 invariants x every fault x 2,000 cases, ~28 s) rather than core,
# and per-test coverage would re-run it for nearly every mutant. Leaving it out can only lower the score.
#
# Exit code: 0 when the score is at or above thresholds.break in mutation/stryker-config.json,
# non-zero otherwise or when Stryker itself fails.
set -euo pipefail

script_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$script_dir/.." && pwd)"
config="$root/mutation/stryker-config.json"
start=$(date +%s)

cd "$root"

# --shard K/N: this shard's files as Stryker mutate patterns (a partial run; the merge applies the threshold).
shard=""
if [ "${1:-}" = "--shard" ]; then
    spec="${2:-}"
    if ! [[ "$spec" =~ ^([0-9]+)/([0-9]+)$ ]]; then
        echo "mutation: --shard needs K/N (0 <= K < N), got '${spec}'" >&2
        exit 2
    fi
    shift 2
    files="$(python3 "$root/mutation/shard.py" files "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}")" || exit 2
    shard="$spec"
    # A shard is never judged alone (the merge applies the threshold): without this, a shard under it made Stryker exit
    # non-zero and this script stopped before stamping the report (shard 1 of 4 on 2026-12-04, 94.08 %).
    args=(--break-at 0)
    # Patterns relative to core/ (the mutated project), "**/"-rooted as in the config; no two core files share a
    # path suffix, and the merge refuses overlapping shards if that ever changes.
    while IFS= read -r f; do [ -n "$f" ] && args+=(-m "**/${f#core/}"); done <<< "$files"
    set -- "${args[@]}" "$@"
    echo "mutation: shard $shard: $(( ${#args[@]} / 2 - 1 )) files: $(tr '\n' ' ' <<< "$files")"
fi

dotnet tool restore >/dev/null

export ACPHYS_PROFILE=mutation
export DOTNET_ROLL_FORWARD=Major
export DOTNET_CLI_TELEMETRY_OPTOUT=1
export DOTNET_NOLOGO=1

stamp="$(date -u +%Y%m%dT%H%M%SZ)"
out="$root/mutation/StrykerOutput/$stamp"
mkdir -p "$out"
log="$out/stryker.log"

if [ -n "$shard" ] && [ -z "$files" ]; then
    # More shards than weighted files: nothing to mutate here (without -m Stryker would mutate all of core).
    mkdir -p "$out/reports"
    printf '{"schemaVersion":"2","thresholds":{"high":0,"low":0},"files":{}}\n' > "$out/reports/mutation-report.json"
    python3 "$root/mutation/shard.py" stamp "$out/reports/mutation-report.json" "${shard%/*}" "${shard#*/}"
    echo "mutation: shard $shard has no files"
    echo "mutation: shard $shard report: $out/reports/mutation-report.json"
    exit 0
fi

# --- private copy of the tree -------------------------------------------------------------------
work="$(mktemp -d "${TMPDIR:-/tmp}/acphys-mutation.XXXXXX")"
cleanup() { rm -rf "$work"; }
trap cleanup EXIT
mkdir -p "$work/repo"
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git -C "$root" ls-files -z -co --exclude-standard \
        | tar -C "$root" --null -T - --ignore-failed-read -cf - 2>/dev/null \
        | tar -C "$work/repo" -xf -
    cp -a "$root/.git" "$work/repo/.git"
else
    tar -C "$root" --exclude=bin --exclude=obj --exclude=StrykerOutput --exclude=TestResults -cf - . \
        | tar -C "$work/repo" -xf -
fi
# Tests find ../shared beside the repository root (props/Support/RepoPaths.cs).
if [ -d "$root/../shared" ]; then
    ln -s "$(cd "$root/../shared" && pwd)" "$work/shared"
fi

# --- run ----------------------------------------------------------------------------------------
echo "mutation: stryker on core/ in $work/repo (profile $ACPHYS_PROFILE), output $out"
set +e
(cd "$work/repo/mutation" && dotnet stryker --skip-version-check --output "$out" "$@") 2>&1 | tee "$log"
stryker_rc=${PIPESTATUS[0]}
set -e
elapsed=$(( $(date +%s) - start ))

json="$out/reports/mutation-report.json"
if [ ! -f "$json" ]; then
    echo "mutation: FAILED: stryker exited $stryker_rc and wrote no report (log: $log)" >&2
    exit "$(( stryker_rc == 0 ? 1 : stryker_rc ))"
fi

# Reports name files by the private copy's absolute path: make them repository-relative.
for f in "$out"/reports/mutation-report.*; do
    sed -i "s#$work/repo/##g" "$f"
done

# --- score --------------------------------------------------------------------------------------
read -r killed timeout survived nocov compile ignored score < <(python3 - "$json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
c = {}
for f in d["files"].values():
    for m in f["mutants"]:
        c[m["status"]] = c.get(m["status"], 0) + 1
k, t, s, n = c.get("Killed", 0), c.get("Timeout", 0), c.get("Survived", 0), c.get("NoCoverage", 0)
valid = k + t + s + n
score = 100.0 * (k + t) / valid if valid else 0.0
print(k, t, s, n, c.get("CompileError", 0), c.get("Ignored", 0), f"{score:.2f}")
PY
)
break_at=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["stryker-config"]["thresholds"]["break"])' "$config")

# --- publish (full runs only) -------------------------------------------------------------------
if [ "$#" -eq 0 ]; then
    dest="$root/mutation/reports"
    mkdir -p "$dest"
    stage="$(mktemp -d "$dest/.staging.XXXXXX")"
    cp "$out/reports/mutation-report.md" "$out/reports/mutation-report.json" "$stage/"
    html="$out/reports/mutation-report.html"
    keep_html=0
    if [ -f "$html" ] && [ "$(stat -c %s "$html")" -lt 2097152 ]; then
        cp "$html" "$stage/"
        keep_html=1
    fi
    # Same filesystem: each mv is an atomic rename, so a reader never sees a half-written report.
    for f in "$stage"/*; do
        mv -f "$f" "$dest/$(basename "$f")"
    done
    [ "$keep_html" -eq 1 ] || rm -f "$dest/mutation-report.html"
    rmdir "$stage"
    echo "mutation: reports published to mutation/reports/"
else
    echo "mutation: partial run (arguments: $*): mutation/reports/ left as it was"
fi

echo "mutation: score ${score} % (killed $killed, timeout $timeout, survived $survived, no coverage $nocov; compile errors $compile, ignored $ignored)"
echo "mutation: runtime ${elapsed} s on $(nproc) cores; break threshold ${break_at} %; reports in $out/reports"

if [ "$stryker_rc" -ne 0 ]; then
    echo "mutation: FAILED: stryker exited $stryker_rc" >&2
    exit "$stryker_rc"
fi
if [ -n "$shard" ]; then
    # A shard's score says little alone: the merged report is judged (python3 mutation/shard.py merge).
    python3 "$root/mutation/shard.py" stamp "$json" "${shard%/*}" "${shard#*/}"
    echo "mutation: shard $shard report: $json"
    exit 0
fi
if python3 -c 'import sys; sys.exit(0 if float(sys.argv[1]) >= float(sys.argv[2]) else 1)' "$score" "$break_at"; then
    echo "mutation: OK (${score} % >= ${break_at} %)"
else
    echo "mutation: FAILED: ${score} % is below the break threshold ${break_at} %" >&2
    exit 3
fi
