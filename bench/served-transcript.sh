#!/usr/bin/env bash
# Served transcript hashes (issue #42, a refactor guard): runs the gate against `acphys serve` over protocol v1 and
# prints the SHA-256 of every byte the tool sent (requests) and every byte the server answered (answers). A refactor of
# the protocol, the generators or the engine that keeps every verdict keeps both hashes: compare two builds' output.
#
#   bench/served-transcript.sh                          # the pr gate's seeds
#   bench/served-transcript.sh --base-seed 90417        # another base seed (any verify arguments pass through)
#   ACPHYS_DLL=/path/acphys.dll bench/served-transcript.sh   # another build (default: cli/bin/Release/net10.0/acphys.dll)
#
# Prints "requests HASH", "answers HASH" and the gate's summary line. Exit codes: 0 hashes printed (whatever the gate's
# verdict: the verdict is part of what is compared); 2 no build or no transcript.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dll="${ACPHYS_DLL:-$root/cli/bin/Release/net10.0/acphys.dll}"
if [[ "${1:-}" == -h || "${1:-}" == --help ]]; then sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0; fi
if [[ ! -f "$dll" ]]; then
  echo "served-transcript: no build at $dll (dotnet build -c Release cli/AcPhys.Cli.csproj, or set ACPHYS_DLL)" >&2
  exit 2
fi
work="$(mktemp -d "${TMPDIR:-/tmp}/served-transcript.XXXXXX")"
trap 'rm -rf "$work"' EXIT
cp -r "$(dirname "$dll")" "$work/bin"
served="$work/bin/$(basename "$dll")"
# The child the gate spawns: a tee on each side of the server, each side written whole to a file.
cat > "$work/serve.sh" <<SH
#!/usr/bin/env bash
tee "$work/requests" | dotnet "$served" serve | tee "$work/answers"
SH
chmod +x "$work/serve.sh"
set +e
dotnet "$served" verify --impl-cmd "$work/serve.sh" -q "$@" > "$work/out" 2>&1
rc=$?
set -e
if [[ ! -s "$work/requests" || ! -s "$work/answers" ]]; then
  echo "served-transcript: the gate wrote no transcript (exit $rc):" >&2
  tail -5 "$work/out" >&2
  exit 2
fi
echo "requests $(sha256sum < "$work/requests" | cut -d' ' -f1) ($(wc -c < "$work/requests") bytes)"
echo "answers  $(sha256sum < "$work/answers" | cut -d' ' -f1) ($(wc -c < "$work/answers") bytes)"
echo "gate     exit $rc: $(grep -E 'passed|failed' "$work/out" | tail -1)"
