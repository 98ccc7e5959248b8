#!/usr/bin/env bash
# AFL++ campaign over the AcPhys .NET code, through SharpFuzz (see docs/fuzzing.md).
#
#   fuzz/run.sh [--minutes N] [--jobs J] [--target T] [--fault F] [--timeout-ms MS] [--seeds DIR]
#               [--name NAME] [--fail-on-crash]
#
# Builds the harness (Release) into .fuzz/runs/NAME/build, instruments AcPhys.Core.dll, AcPhys.Contract.dll, AcPhys.Formats.dll, AcPhys.Protocol.dll, AcPhys.Spec.dll and the
# toy target in place, runs afl-fuzz for N minutes (J=1: one -M main; J>1: one -M main and J-1 -S secondaries on
# one sync dir), copies crashes and hangs to .fuzz/runs/NAME/findings, replays the crashes and prints a summary.
# Non-interactive (no TTY needed). Exit 0 when the campaign ran (crashes or not; with --fail-on-crash, 3 when it
# found any), 1 when it could not run, 2 on a usage error.
set -euo pipefail

usage() {
    sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
    cat <<'EOF'

Options:
  --minutes N       campaign length, decimals allowed (default 5)
  --jobs J          afl-fuzz instances (default 1)
  --target T        harness target: land, toy, toy-slow (default land)
  --fault F         planted fault id, exported to the harness as ACPHYS_FAULT (default: none, the correct core)
  --timeout-ms MS   afl-fuzz -t per input (default 1000)
  --seeds DIR       extra seed files, added to the target's built-in seeds
  --name NAME       run directory name under .fuzz/runs (default TARGET-FAULT-TIMESTAMP)
  --fail-on-crash   exit 3 when any crash was found
EOF
}

minutes=5 jobs=1 target=land fault="" timeout_ms=1000 extra_seeds="" name="" fail_on_crash=0
while [[ $# -gt 0 ]]; do
    case "$1" in
        --minutes) minutes=${2:?}; shift 2 ;;
        --jobs) jobs=${2:?}; shift 2 ;;
        --target) target=${2:?}; shift 2 ;;
        --fault) fault=${2?}; shift 2 ;;
        --timeout-ms) timeout_ms=${2:?}; shift 2 ;;
        --seeds) extra_seeds=${2:?}; shift 2 ;;
        --name) name=${2:?}; shift 2 ;;
        --fail-on-crash) fail_on_crash=1; shift ;;
        -h|--help) usage; exit 0 ;;
        *) echo "run.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
    esac
done

[[ $minutes =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "run.sh: --minutes must be a number" >&2; exit 2; }
[[ $jobs =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: --jobs must be a positive integer" >&2; exit 2; }
[[ $timeout_ms =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: --timeout-ms must be a positive integer" >&2; exit 2; }
seconds=$(awk -v m="$minutes" 'BEGIN { s = int(m * 60 + 0.5); print (s < 1 ? 1 : s) }')

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
name=${name:-$target-${fault:-correct}-$(date -u +%Y%m%dT%H%M%SZ)}
run="$root/.fuzz/runs/$name"
build="$run/build" out="$run/afl" findings="$run/findings" logs="$run/logs" seeds="$run/seeds"
harness="$build/harness/AcPhys.Fuzz"

say() { printf '[fuzz] %s\n' "$*"; }
die() { printf '[fuzz] error: %s\n' "$*" >&2; exit 1; }

ensure_afl() {
    if ! command -v afl-fuzz >/dev/null 2>&1; then
        say "afl-fuzz not found: installing the Debian package afl++"
        local sudo=()
        if [[ $(id -u) != 0 ]]; then
            command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null || die "afl-fuzz missing and no root/sudo to install afl++"
            sudo=(sudo -n)
        fi
        DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get update -qq >/dev/null
        DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq afl++ >/dev/null
        command -v afl-fuzz >/dev/null 2>&1 || die "apt-get install afl++ did not provide afl-fuzz"
    fi
    say "fuzzer: $(afl-fuzz -h 2>&1 | head -n 1 | sed 's/\x1b\[[0-9;]*m//g')"
}

build_and_instrument() {
    command -v dotnet >/dev/null 2>&1 || die "dotnet not found"
    say "publishing harness and instrumenter (Release) into $build"
    dotnet publish "$root/fuzz/AcPhys.Fuzz/AcPhys.Fuzz.csproj" -c Release -o "$build/harness" --nologo \
        >"$logs/publish-harness.log" 2>&1 || { tail -n 30 "$logs/publish-harness.log" >&2; die "publish of the harness failed"; }
    dotnet publish "$root/fuzz/AcPhys.Fuzz.Instrumenter/AcPhys.Fuzz.Instrumenter.csproj" -c Release -o "$build/instrument" --nologo \
        >"$logs/publish-instrument.log" 2>&1 || { tail -n 30 "$logs/publish-instrument.log" >&2; die "publish of the instrumenter failed"; }
    local assemblies=()
    for dll in AcPhys.Core.dll AcPhys.Contract.dll AcPhys.Formats.dll AcPhys.Protocol.dll AcPhys.Spec.dll AcPhys.Fuzz.Toy.dll; do
        [[ -f "$build/harness/$dll" ]] && assemblies+=("$build/harness/$dll")
    done
    # One process for all of them: SharpFuzz's block ids come from one fixed-seed generator per process.
    "$build/instrument/AcPhys.Fuzz.Instrumenter" "${assemblies[@]}" | tee "$logs/instrument.log" | sed 's/^/[fuzz]   /'
}

prepare_seeds() {
    "$harness" seeds "$target" "$seeds" >/dev/null || die "unknown target '$target' (try: $harness list)"
    if [[ -n $extra_seeds ]]; then
        [[ -d $extra_seeds ]] || die "--seeds $extra_seeds is not a directory"
        find "$extra_seeds" -maxdepth 1 -type f -exec cp -t "$seeds" {} +
    fi
    # Also checks that the fault id exists (exit 2) before afl-fuzz would only see a failed handshake.
    local rc=0
    ACPHYS_FAULT="$fault" "$harness" replay "$target" "$seeds"/* >"$logs/seed-replay.log" 2>&1 || rc=$?
    case $rc in
        0) say "seeds: $(find "$seeds" -type f | wc -l) file(s), none crashes" ;;
        1) say "warning: some seeds crash already (afl-fuzz skips them): see $logs/seed-replay.log" ;;
        *) cat "$logs/seed-replay.log" >&2; die "harness rejected target '$target' / fault '${fault}'" ;;
    esac
}

pids=()
stop_jobs() {
    for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
}

run_campaign() {
    export AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_NO_UI=1 AFL_TRY_AFFINITY=1
    # The target is the dotnet apphost: it has no AFL marker strings for afl-fuzz's binary check.
    export AFL_SKIP_BIN_CHECK=1
    export AFL_SKIP_CRASHES=1 AFL_FORKSRV_INIT_TMOUT=${AFL_FORKSRV_INIT_TMOUT:-60000}
    export ACPHYS_FAULT="$fault"
    say "campaign: target=$target fault=${fault:-none} jobs=$jobs duration=${seconds}s timeout=${timeout_ms}ms"
    trap stop_jobs INT TERM
    local i role inst
    for ((i = 0; i < jobs; i++)); do
        if ((i == 0)); then role=(-M main) inst=main; else role=(-S "sec$i") inst="sec$i"; fi
        timeout --signal=INT --kill-after=30 $((seconds + 180)) \
            afl-fuzz -i "$seeds" -o "$out" "${role[@]}" -V "$seconds" -t "$timeout_ms" -m none -- "$harness" "$target" \
            >"$logs/afl-$inst.log" 2>&1 &
        pids+=($!)
    done
    local failed=0
    for pid in "${pids[@]}"; do wait "$pid" || failed=$((failed + 1)); done
    trap - INT TERM
    ((failed == 0)) || say "warning: $failed afl-fuzz instance(s) exited non-zero (see $logs/afl-*.log)"
}

stat_of() { awk -F' *: *' -v k="$2" '$1 == k { print $2; exit }' "$1"; }

# In AFL++ 4.04c crash file names, time:N is milliseconds since that instance began fuzzing (after its dry run)
# and execs:N its execution count then. Prints "MS EXECS" of the earliest crash, or nothing.
first_crash() {
    find "$1" -maxdepth 1 -type f -name 'id:*' 2>/dev/null \
        | sed -n 's/.*,time:\([0-9]*\),execs:\([0-9]*\).*/\1 \2/p' | sort -n | head -n 1
}

# "MS EXECS" -> "1.9s@28787"
show_crash() { [[ -z $1 ]] || awk -v ms="${1% *}" -v ex="${1#* }" 'BEGIN { printf "%.1fs@%s", ms / 1000, ex }'; }

summarize() {
    mkdir -p "$findings/crashes" "$findings/hangs"
    local summary="$run/summary.txt" total_execs=0 total_rate=0 total_crashes=0 total_hangs=0 first=""
    {
        echo "target=$target fault=${fault:-none} jobs=$jobs duration=${seconds}s timeout=${timeout_ms}ms"
        printf '%-6s %12s %10s %7s %8s %6s %10s %16s\n' instance execs exec/s paths crashes hangs stability first-crash@execs
    } >"$summary"
    local dir inst stats execs rate paths crashes hangs stability fc f
    for dir in "$out"/*/; do
        inst=$(basename "$dir") stats="$dir/fuzzer_stats"
        [[ -f $stats ]] || continue
        execs=$(stat_of "$stats" execs_done) rate=$(stat_of "$stats" execs_per_sec)
        paths=$(stat_of "$stats" corpus_count); paths=${paths:-$(stat_of "$stats" paths_total)}
        crashes=$(stat_of "$stats" saved_crashes); crashes=${crashes:-$(stat_of "$stats" unique_crashes)}
        hangs=$(stat_of "$stats" saved_hangs); hangs=${hangs:-$(stat_of "$stats" unique_hangs)}
        stability=$(stat_of "$stats" stability)
        fc=$(first_crash "$dir/crashes")
        printf '%-6s %12s %10s %7s %8s %6s %10s %16s\n' "$inst" "$execs" "$rate" "$paths" "$crashes" "$hangs" \
            "$stability" "$(show_crash "$fc")" >>"$summary"
        total_execs=$((total_execs + execs)) total_crashes=$((total_crashes + crashes)) total_hangs=$((total_hangs + hangs))
        total_rate=$(awk -v a="$total_rate" -v b="$rate" 'BEGIN { print a + b }')
        if [[ -n $fc ]] && { [[ -z $first ]] || ((${fc% *} < ${first% *})); }; then first=$fc; fi
        for f in "$dir"/crashes/id:* "$dir"/hangs/id:*; do
            [[ -f $f ]] || continue
            local kind=crashes; [[ $f == */hangs/* ]] && kind=hangs
            cp "$f" "$findings/$kind/$inst-$(basename "$f" | sed 's/^id:\([0-9]*\).*/\1/')"
            echo "$inst-$(basename "$f" | sed 's/^id:\([0-9]*\).*/\1/') <- $f" >>"$findings/$kind/INDEX.txt"
        done
    done
    printf '%-6s %12s %10s %7s %8s %6s %10s %16s\n' total "$total_execs" "$total_rate" "" "$total_crashes" "$total_hangs" "" \
        "$(show_crash "$first")" >>"$summary"

    local crash_files=("$findings"/crashes/*-[0-9]*)
    if [[ -f ${crash_files[0]} ]]; then
        ACPHYS_FAULT="$fault" "$harness" replay "$target" "${crash_files[@]}" >"$findings/replay.txt" 2>&1 || true
        {
            echo "crashes replayed: $findings/replay.txt"
            echo "broken invariants (by crash count):"
            grep -o 'InvariantViolationException: [A-Z0-9-]*' "$findings/replay.txt" | sed 's/.*: /  /' | sort | uniq -c | sort -rn || true
            grep -E '^[A-Za-z.]+Exception: ' "$findings/replay.txt" | grep -v InvariantViolationException | sort | uniq -c | sed 's/^/  other: /' || true
        } >>"$summary"
    fi
    echo "findings: $findings" >>"$summary"
    echo
    sed 's/^/[fuzz] /' "$summary"
    ln -sfn "$run" "$root/.fuzz/runs/latest"
    summary_crashes=$total_crashes
}

mkdir -p "$build" "$out" "$findings" "$logs" "$seeds"
ensure_afl
build_and_instrument
prepare_seeds
run_campaign
summary_crashes=0
summarize
compgen -G "$out/*/fuzzer_stats" >/dev/null || { tail -n 40 "$logs"/afl-main.log >&2; die "afl-fuzz did not run (see $logs)"; }
if ((fail_on_crash && summary_crashes > 0)); then exit 3; fi
exit 0
