#!/usr/bin/env bash
# Issue 42, item 3: (re)generates the public API baselines of every packed assembly. Re-runnable and idempotent.
#
#   bash packaging/publicapi-baseline.sh [REPO_DIR]   (default: this repository)
#
# The packed projects are the ones packaging/pack.sh packs (its `for project in ...` list), so a project added there gets
# a baseline too. For each: PublicAPI.Shipped.txt and
# PublicAPI.Unshipped.txt are reset to "#nullable enable", `dotnet format analyzers --diagnostics RS0016` (the
# PublicApiAnalyzers' own code fix, offline) declares every public symbol in Unshipped, and the declarations move to
# Shipped (sorted, ordinal): the baseline is what is shipped; a later public change shows up as an RS0016/RS0017 error
# until it is declared in Unshipped, a reviewed diff. Needs Directory.Build.targets (the analyzer for projects holding
# the files) and the PackageVersion in Directory.Packages.props, the hand-written part of the change.
set -euo pipefail
REPO="$(cd "${1:-$(dirname "${BASH_SOURCE[0]}")/..}" && pwd)"
cd "$REPO"
grep -q 'Microsoft.CodeAnalysis.PublicApiAnalyzers' Directory.Packages.props || { echo "publicapi-baseline: Directory.Packages.props has no PackageVersion for Microsoft.CodeAnalysis.PublicApiAnalyzers" >&2; exit 2; }
grep -q 'PublicAPI.Shipped.txt' Directory.Build.targets 2>/dev/null || { echo "publicapi-baseline: Directory.Build.targets does not add the analyzer (the hand-written part of item 3)" >&2; exit 2; }
mapfile -t projects < <(sed -n 's/^for project in \(.*\); do$/\1/p' packaging/pack.sh | tr ' ' '\n' | grep '\.csproj$')
[ "${#projects[@]}" -gt 0 ] || { echo "publicapi-baseline: no project list found in packaging/pack.sh" >&2; exit 2; }
for p in "${projects[@]}"; do
  d="$(dirname "$p")"
  printf '#nullable enable\n' > "$d/PublicAPI.Shipped.txt"
  printf '#nullable enable\n' > "$d/PublicAPI.Unshipped.txt"
done
dotnet restore AcPhysVerify.sln -v:quiet
for p in "${projects[@]}"; do
  echo "publicapi-baseline: $p"
  dotnet format "$p" analyzers --diagnostics RS0016 --severity warn --no-restore
  d="$(dirname "$p")"
  python3 - "$d" <<'PY'
import sys, os
d = sys.argv[1]
def lines(f):
    with open(os.path.join(d, f), encoding="utf-8") as fh:
        return [l.rstrip("\r\n") for l in fh if l.strip() and not l.startswith("#nullable")]
api = sorted(set(lines("PublicAPI.Shipped.txt") + lines("PublicAPI.Unshipped.txt")), key=lambda s: s.encode("utf-8"))
for name, body in (("PublicAPI.Shipped.txt", api), ("PublicAPI.Unshipped.txt", [])):
    tmp = os.path.join(d, name + ".tmp")
    with open(tmp, "w", encoding="utf-8", newline="\n") as fh:
        fh.write("#nullable enable\n" + "".join(l + "\n" for l in body))
    os.replace(tmp, os.path.join(d, name))
print(f"  {len(api)} public symbols")
PY
done
for p in "${projects[@]}"; do
  dotnet build "$p" -c Release -warnaserror -v:quiet -nologo | tail -3
done
echo "publicapi-baseline: done"
