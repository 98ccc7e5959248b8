#!/usr/bin/env bash
# Never lose a finding: start a campaign with a planted fault, SIGKILL it after its first crash, check that every
# crash file found so far is intact (same bytes, still crashes), that no half-written file is left, then restart the
# same command and check that it resumes the queue and triages the crashes into replayable regressions.
#
#   fuzz/tests/sigkill.sh [group|parent]   group: SIGKILL acphys, afl-fuzz and the harness at once (a runner dying);
#                                          parent: SIGKILL acphys only (afl-fuzz must stop by itself: pdeathsig)
# Exit 0 when every check passed. Takes about a minute; needs afl-fuzz and a build (run acphys fuzz once first).
set -euo pipefail
mode=${1:-group}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
fault=map-edge-2040 target=land
work=$(mktemp -d /tmp/acphys-sigkill.XXXXXX)
campaign=$work/campaign regressions=$work/regressions
harness=$root/.fuzz/build/harness/AcPhys.Fuzz
cmd=("$root/acphys" fuzz --target "$target" --fault "$fault" --no-build --quiet --campaign "$campaign" --regressions "$regressions")
fail() { echo "FAIL: $*" >&2; exit 1; }
ok() { echo "ok: $*"; }

[[ -x $harness ]] || fail "no build at $harness (run: ./acphys fuzz --target toy --minutes 0.1 once)"
echo "sigkill test ($mode), work folder $work"
setsid "${cmd[@]}" --minutes 3 >"$work/run1.log" 2>&1 &
leader=$!
for _ in $(seq 1 600); do
    compgen -G "$campaign/sync/*/crashes/id:*" >/dev/null && break
    kill -0 "$leader" 2>/dev/null || fail "campaign ended before its first crash (see $work/run1.log)"
    sleep 0.2
done
compgen -G "$campaign/sync/*/crashes/id:*" >/dev/null || fail "no crash within 120 s"
sleep 2 # keep fuzzing a little: the kill lands mid-campaign, not on the first crash's write
afl_pids=$(pgrep -g "$leader" -x afl-fuzz || true)
( cd "$campaign/sync" && sha256sum ./*/crashes/id:* ) >"$work/crashes-before.sha"
queue_before=$(find "$campaign/sync" -path '*/queue/id:*' | wc -l)
if [[ $mode == group ]]; then
    kill -KILL -- "-$leader"
else
    kill -KILL "$leader"
fi
ok "SIGKILL ($mode) after $(wc -l <"$work/crashes-before.sha") crash file(s), $queue_before queue entries"

# No afl-fuzz of this campaign may survive (parent mode: they get SIGTERM from the kernel and stop cleanly).
for _ in $(seq 1 100); do
    alive=0
    for p in $afl_pids; do kill -0 "$p" 2>/dev/null && alive=1; done
    ((alive == 0)) && break
    sleep 0.2
done
((alive == 0)) || fail "afl-fuzz still running 20 s after the kill"
ok "no afl-fuzz left running"

( cd "$campaign/sync" && sha256sum --quiet -c "$work/crashes-before.sha" ) || fail "a crash file changed or vanished"
ok "every crash file found before the kill is there, byte for byte"
rc=0
ACPHYS_FAULT=$fault "$harness" replay "$target" "$campaign"/sync/*/crashes/id:* >"$work/replay-before.log" 2>&1 || rc=$?
n=$(wc -l <"$work/crashes-before.sha")
grep -q "replayed $n input(s): $n crash(es)" "$work/replay-before.log" || fail "not every saved crash still crashes (see $work/replay-before.log)"
ok "all $n crash file(s) still crash when replayed"
leftovers=$( (find "$campaign" "$regressions" -name '*.tmp' 2>/dev/null || true) | wc -l)
((leftovers == 0)) || fail "$leftovers half-written .tmp file(s) left"
ok "no half-written file"

"${cmd[@]}" --minutes 0.5 >"$work/run2.log" 2>&1 || [[ $? == 1 ]] || fail "restart failed (see $work/run2.log)"
grep -q "resuming" "$work/run2.log" 2>/dev/null || grep -q "campaign folder" "$work/run2.log" || fail "restart did not run"
grep -q "Detected prior run with AFL_AUTORESUME set. Resuming" "$campaign/logs/afl-main.log" || fail "afl-fuzz did not resume (see $campaign/logs/afl-main.log)"
ok "restart resumed: $(grep -a -m1 "Resuming" "$campaign/logs/afl-main.log" | sed 's/\x1b\[[0-9;]*m//g' | tr -s ' ')"
queue_after=$(find "$campaign/sync" -path '*/queue/id:*' | wc -l)
((queue_after >= queue_before)) || fail "queue shrank: $queue_before -> $queue_after"
ok "queue kept: $queue_before -> $queue_after entries"
while read -r _ file; do
    [[ -f "$campaign/sync/$file" ]] || compgen -G "$campaign/sync/$(dirname "$(dirname "$file")")/crashes*/$(basename "$file")" >/dev/null \
        || fail "crash $file lost on restart"
done <"$work/crashes-before.sha"
ok "every earlier crash file kept by the resumed run"
shopt -s nullglob
files=("$regressions"/*.json)
((${#files[@]} > 0)) || fail "triage wrote no regression"
for f in "${files[@]}"; do
    rc=0
    "$root/acphys" replay "$f" --fault "$fault" >"$work/replay-$(basename "$f").log" 2>&1 || rc=$?
    ((rc == 1)) || fail "acphys replay $f --fault $fault exited $rc, expected 1 (violation)"
    rc=0
    "$root/acphys" replay "$f" >/dev/null 2>&1 || rc=$?
    ((rc == 0)) || fail "acphys replay $f on the correct core exited $rc, expected 0"
done
ok "${#files[@]} regression file(s) written; each replays as a violation with --fault $fault and holds on the correct core"
echo "PASS ($mode): $work"
