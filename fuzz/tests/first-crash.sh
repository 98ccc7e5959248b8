#!/usr/bin/env bash
# Time to first crash for each planted fault: RUNS fresh campaigns (1 job, stop at the first crash) per fault, on the
# target whose invariants catch it; prints one markdown row per fault with the median, every run's afl time@execs,
# the invariants of the regressions triage wrote, and whether `acphys replay FILE --fault F` reproduced each of them.
#
#   fuzz/tests/first-crash.sh [RUNS] [FAULT...]      (default 5 runs, every fault a target reaches)
#   MINUTES=2 fuzz/tests/first-crash.sh 3 no-reframe  (cap each run at MINUTES of afl time; default 5)
#   TIMEOUT_MS=5000 fuzz/tests/first-crash.sh 1 no-reframe  (afl-fuzz -t; default 1000: under a heavy load an
#                                                  out-of-process target's first input, a dotnet start, can take longer)
# Needs a build (./acphys fuzz ... once). Results go to .fuzz/first-crash/.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
runs=${1:-5}; shift || true
declare -A target_of=(
    [trunc-floor]=land [nan-as-zero]=land [map-edge-2040]=land [sign-extend-by]=land [drop-block-length]=land
    [no-eps-snap]=land [inbound-x-only]=land
    [clamp-106]=walk [in-cell-neighbours]=walk [else-diagonal]=walk [sphere-guard-inverted]=walk [sphere-leak]=walk
    [no-reset]=walk [no-hysteresis]=walk [sticky-pick]=walk
    [outdoor-wins]=scene [no-hysteresis-indoor]=scene [inverted-portal-side]=scene [no-visibility-filter]=scene
    [no-reframe]=scene [stale-scene-array]=scene [ace-hint-key]=scene [keep-current-on-miss]=scene [no-exit-transit]=scene
    [ace-same-block-guard]=parts [ace-every-part-anchors]=parts
)
minutes=${MINUTES:-5}
faults=("$@")
((${#faults[@]} > 0)) || faults=(trunc-floor nan-as-zero map-edge-2040 sign-extend-by drop-block-length no-eps-snap inbound-x-only
    clamp-106 in-cell-neighbours else-diagonal sphere-guard-inverted sphere-leak no-reset no-hysteresis sticky-pick
    outdoor-wins no-hysteresis-indoor inverted-portal-side no-visibility-filter no-reframe stale-scene-array ace-hint-key
    keep-current-on-miss no-exit-transit ace-same-block-guard ace-every-part-anchors)
out=$root/.fuzz/first-crash
mkdir -p "$out"
echo "| fault | target | seeds failing | median afl time | median execs | runs (afl time s @ execs) | regressions (invariant × files) | replay reproduces |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for fault in "${faults[@]}"; do
    target=${target_of[$fault]:?no target for $fault}
    times=() execs=() cells=()
    seeds=$("$root/.fuzz/build/harness/AcPhys.Fuzz" seeds "$target" "$out/seeds-$target" | sed -n 's/wrote \([0-9]*\).*/\1/p')
    extra=$( (find "$root/corpus/fuzz/$target" -type f 2>/dev/null || true) | wc -l)
    seeds=$((seeds + extra))
    regs=$out/$fault/regressions
    rm -rf "${out:?}/$fault"
    for ((i = 1; i <= runs; i++)); do
        log=$out/$fault/run$i.txt
        mkdir -p "$out/$fault"
        "$root/acphys" fuzz --target "$target" --fault "$fault" --minutes "$minutes" --until-crash --fresh --no-build --quiet --timeout-ms "${TIMEOUT_MS:-1000}" \
            --campaign "$out/$fault/campaign$i" --regressions "$regs" >"$log" 2>&1 || true
        line=$(grep -m1 'time to first crash:' "$log" || echo "time to first crash: none")
        seeded=$(sed -n 's/.*found by \([0-9]*\) seed.*/\1/p' <<<"$line")
        t=$(sed -n 's/.* \([0-9.]*\) s afl time @ \([0-9]*\) execs.*/\1/p' <<<"$line")
        e=$(sed -n 's/.* \([0-9.]*\) s afl time @ \([0-9]*\) execs.*/\2/p' <<<"$line")
        times+=("${t:-inf}") execs+=("${e:-inf}") cells+=("${t:-none}@${e:-none}")
    done
    median_t=$(printf '%s\n' "${times[@]}" | sort -g | sed -n "$(((runs + 1) / 2))p")
    median_e=$(printf '%s\n' "${execs[@]}" | sort -g | sed -n "$(((runs + 1) / 2))p")
    invariants=$( (find "$regs" -name '*.json' 2>/dev/null || true) | xargs -r -n1 basename | sed 's/-[0-9a-f]*\.json$//' | sort | uniq -c | awk '{printf "%s%s×%s", sep, $2, $1; sep=", "}')
    good=0 total=0
    for f in "$regs"/*.json; do
        [[ -f $f ]] || continue
        total=$((total + 1)); rc=0
        "$root/acphys" replay "$f" --fault "$fault" >/dev/null 2>&1 || rc=$?
        ((rc == 1)) && good=$((good + 1))
    done
    echo "| $fault | $target | ${seeded:-0}/$seeds | $median_t s | $median_e | ${cells[*]} | ${invariants:-none} | $good/$total |"
done
