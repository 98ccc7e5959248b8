#!/usr/bin/env bash
# pack.sh: NuGet packages of AcPhysVerify into one folder (docs/ci.md):
#   AcPhys.Core  (the reference core; core/ stays non-packable in its project file, so it is packed with IsPackable=true here)
#   AcPhys.Spec  (invariants, generators, shrinkers, the adapter contract and protocol v1 client/server; depends on AcPhys.Core)
#   AcPhys.Cli   (the acphys command as a .NET tool: dotnet tool install AcPhys.Cli)
# Usage: packaging/pack.sh [-o DIR] [-c Release|Debug] [--version X.Y.Z] [--no-build]
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$root/artifacts/packages"
configuration=Release
extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -o|--output) out="$2"; shift 2 ;;
    -c|--configuration) configuration="$2"; shift 2 ;;
    --version) extra+=("-p:Version=$2"); shift 2 ;;
    --no-build) extra+=("--no-build"); shift ;;
    *) echo "pack.sh: unknown argument '$1' (known: -o DIR, -c CONFIG, --version X.Y.Z, --no-build)" >&2; exit 2 ;;
  esac
done

mkdir -p "$out"
for project in core/AcPhys.Core.csproj spec/AcPhys.Spec.csproj cli/AcPhys.Cli.csproj; do
  packable=()
  [[ "$project" == core/* ]] && packable=("-p:IsPackable=true")
  DOTNET_NOLOGO=1 dotnet pack "$root/$project" -c "$configuration" -o "$out" -nologo -v:quiet "${packable[@]}" "${extra[@]}"
done
ls -1 "$out"/*.nupkg
