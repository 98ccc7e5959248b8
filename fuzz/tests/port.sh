#!/usr/bin/env bash
# acphys fuzz on a port (issue 40): exec/s per target in process (--impl), over protocol (--impl-cmd: acphys serve,
# the Python example) next to the reference, and time to first finding for seeded bugs and served planted faults next
# to the same fault in process. Every regression a run writes is replayed: exit 1 on the port, exit 0 on the reference.
#
#   fuzz/tests/port.sh rates   [SECONDS]        exec/s, 1 job, SECONDS of afl time per campaign (default 30)
#   fuzz/tests/port.sh seeded  [RUNS]           the examples' seeded bugs, --until-crash (default 1 run each)
#   fuzz/tests/port.sh served  [RUNS] [FAULT…]  planted faults served over protocol and in process, --until-crash
#   fuzz/tests/port.sh clean   [MINUTES]        clean ports, no finding expected: examples/dotnet-port in process (land,
#                                               walk: its ops) and acphys serve (land, walk, scene, parts), default 10 min
#
# Needs the builds (./acphys fuzz once, once with --impl and once with --impl-cmd: .fuzz/build, build-impl, build-cmd)
# and examples/dotnet-adapter built (Release).
# MINUTES caps each --until-crash run (default 2); TIMEOUT_MS sets afl-fuzz -t for both sides of `served` (the scene
# target's seeds time out at the in-process default of 1000 ms under a load of 15-20; --impl-cmd defaults to 5000). Results: .fuzz/port/. State the load next to every figure (uptime).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
acphys=(dotnet "$root/cli/bin/Release/net10.0/acphys.dll")
serve="dotnet $root/cli/bin/Release/net10.0/acphys.dll serve"
python="python3 $root/examples/python/acphys_impl.py"
example=$root/examples/dotnet-adapter/bin/Release/net10.0/ExampleAdapter.dll
port=$root/examples/dotnet-port/bin/Release/net10.0/ExamplePort.dll
out=$root/.fuzz/port
minutes=${MINUTES:-2}
mkdir -p "$out"

# run NAME TARGET ARGS...: one fresh campaign; prints "execs exec/s first" from its summary.
run() {
    local name=$1 target=$2; shift 2
    local log=$out/$name.txt
    rm -rf "${out:?}/$name" && mkdir -p "$out/$name"
    "${acphys[@]}" fuzz --target "$target" --fresh --no-build --quiet --campaign "$out/$name/campaign" --regressions "$out/$name/regressions" "$@" >"$log" 2>&1 || true
    # A correct-core campaign grows corpus/fuzz/TARGET (cmin); a measurement must leave the checkout as it was, and
    # the next campaign must start from the same seeds.
    git -C "$root" checkout -q -- corpus/fuzz && git -C "$root" clean -fdq -- corpus/fuzz
    local main first
    main=$(grep -m1 '^  main ' "$log" | awk '{print $2, $3}' || true)
    first=$(grep -m1 'time to first crash:' "$log" | sed 's/^ *time to first crash: //' || true)
    echo "${main:-0 0} | ${first:-none}"
}

# replays NAME PORT-WORDS...: every regression of a run, on the port (must exit 1) and on the reference (must exit 0).
replays() {
    local name=$1; shift
    local good=0 total=0 f rc1 rc0
    for f in "$out/$name/regressions"/*.json; do
        [[ -f $f ]] || continue
        total=$((total + 1)); rc1=0; rc0=0
        "${acphys[@]}" replay "$f" "$@" >/dev/null 2>&1 || rc1=$?
        "${acphys[@]}" replay "$f" >/dev/null 2>&1 || rc0=$?
        ((rc1 == 1 && rc0 == 0)) && good=$((good + 1))
    done
    echo "$good/$total"
}

case ${1:-rates} in
rates)
    secs=${2:-30}; m=$(awk "BEGIN{print $secs/60}")
    echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "| target | implementation | execs | exec/s | load after |"
    echo "| --- | --- | --- | --- | --- |"
    for target in land walk scene parts; do
        echo "| $target | reference in process | $(run "rate-$target-ref" "$target" --minutes "$m" | cut -d'|' -f1 | tr ' ' '|' | sed 's/|$//') | $(cut -d' ' -f1 /proc/loadavg) |"
        if [[ $target == land ]]; then
            echo "| $target | --impl example (instrumented) | $(run "rate-$target-impl" "$target" --minutes "$m" --impl "$example" | cut -d'|' -f1 | tr ' ' '|' | sed 's/|$//') | $(cut -d' ' -f1 /proc/loadavg) |"
        fi
        echo "| $target | --impl-cmd acphys serve | $(run "rate-$target-serve" "$target" --minutes "$m" --impl-cmd "$serve" | cut -d'|' -f1 | tr ' ' '|' | sed 's/|$//') | $(cut -d' ' -f1 /proc/loadavg) |"
        echo "| $target | --impl-cmd Python example | $(run "rate-$target-python" "$target" --minutes "$m" --impl-cmd "$python" | cut -d'|' -f1 | tr ' ' '|' | sed 's/|$//') | $(cut -d' ' -f1 /proc/loadavg) |"
    done
    ;;
seeded)
    runs=${2:-1}
    echo "| port | seeded bug | target | run | afl execs, exec/s | time to first finding | replays (port 1, reference 0) |"
    echo "| --- | --- | --- | --- | --- | --- | --- |"
    for ((i = 1; i <= runs; i++)); do
        r=$(ACPHYS_EXAMPLE_BUG=inbound-x-only run "seeded-example-$i" land --minutes "$minutes" --until-crash --impl "$example")
        echo "| --impl example-dotnet | inbound-x-only | land | $i | ${r%%|*} | ${r#*|} | $(ACPHYS_EXAMPLE_BUG=inbound-x-only replays "seeded-example-$i" --impl "$example") |"
        for pair in trunc-floor:land clamp-106:walk portal-side-inverted:scene; do
            bug=${pair%%:*} target=${pair##*:}
            r=$(run "seeded-python-$bug-$i" "$target" --minutes "$minutes" --until-crash --impl-cmd "$python --bug $bug")
            echo "| --impl-cmd Python example | $bug | $target | $i | ${r%%|*} | ${r#*|} | $(replays "seeded-python-$bug-$i" --impl-cmd "$python --bug $bug") |"
        done
    done
    ;;
served)
    runs=${2:-1}; shift 2 || shift $#
    declare -A target_of=(
        [trunc-floor]=land [map-edge-2040]=land [sign-extend-by]=land [no-eps-snap]=land
        [in-cell-neighbours]=walk [else-diagonal]=walk [sphere-leak]=walk [no-hysteresis]=walk
        [inverted-portal-side]=scene [keep-current-on-miss]=scene [ace-hint-key]=scene
        [ace-same-block-guard]=parts [ace-every-part-anchors]=parts
    )
    faults=("$@")
    ((${#faults[@]} > 0)) || faults=(trunc-floor map-edge-2040 sign-extend-by no-eps-snap in-cell-neighbours else-diagonal sphere-leak
        no-hysteresis inverted-portal-side keep-current-on-miss ace-hint-key ace-same-block-guard ace-every-part-anchors)
    echo "| fault | target | run | in process: execs, exec/s / first finding | served (acphys serve --fault): execs, exec/s / first finding | served replays (port 1, reference 0) | load |"
    echo "| --- | --- | --- | --- | --- | --- | --- |"
    for fault in "${faults[@]}"; do
        target=${target_of[$fault]:?no target for $fault}
        for ((i = 1; i <= runs; i++)); do
            a=$(run "served-$fault-$i-inproc" "$target" --minutes "$minutes" --until-crash --fault "$fault" ${TIMEOUT_MS:+--timeout-ms "$TIMEOUT_MS"})
            b=$(run "served-$fault-$i-serve" "$target" --minutes "$minutes" --until-crash --impl-cmd "$serve --fault $fault" ${TIMEOUT_MS:+--timeout-ms "$TIMEOUT_MS"})
            echo "| $fault | $target | $i | $a | $b | $(replays "served-$fault-$i-serve" --impl-cmd "$serve --fault $fault") | $(cut -d' ' -f1 /proc/loadavg) |"
        done
    done
    ;;
clean)
    m=${2:-10}
    echo "| target | implementation | minutes | execs, exec/s | findings | port edges | load before / after |"
    echo "| --- | --- | --- | --- | --- | --- | --- |"
    # (target, words) pairs: the example port where it has the ops, then the reference served over protocol v1.
    for spec in "land|--impl|$port" "walk|--impl|$port" "land|--impl-cmd|$serve" "walk|--impl-cmd|$serve" \
        "scene|--impl-cmd|$serve" "parts|--impl-cmd|$serve"; do
        IFS='|' read -r target flag impl <<<"$spec"
        name=clean-$target-${flag#--}
        before=$(cut -d' ' -f1 /proc/loadavg)
        r=$(run "$name" "$target" --minutes "$m" "$flag" "$impl")
        findings=$(grep -m1 '^  findings:' "$out/$name.txt" | sed 's/^  findings: //' || true)
        edges=$(grep -m1 '^  port coverage:' "$out/$name.txt" | sed -E 's/.*coverage: ([0-9]+) .* over ([0-9]+) probe.*/\1 of \2/' || true)
        echo "| $target | ${flag} $(basename "${impl%% serve}") | $m | ${r%%|*} | ${findings:-?} | ${edges:--} | $before / $(cut -d' ' -f1 /proc/loadavg) |"
    done
    ;;
*)
    sed -n '2,14p' "$0"; exit 2 ;;
esac
