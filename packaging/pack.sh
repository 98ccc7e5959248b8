#!/usr/bin/env bash
# pack.sh: NuGet packages of AcPhysVerify into one folder (docs/ci.md):
#   AcPhys.Core  (the reference core; core/ stays non-packable in its project file, so it is packed with IsPackable=true here)
#   AcPhys.Contract (the adapter contract a port implements: ICellPhysics, Op, Scene; depends on AcPhys.Core, no FsCheck)
#   AcPhys.Formats  (case values, corpus and scene JSON, dat records; depends on AcPhys.Contract)
#   AcPhys.Spec  (the checking engine: invariants, generators, shrinkers, planted faults, runner; depends on AcPhys.Formats, FsCheck)
#   AcPhys.Xunit (the gate as a port's xunit tests, GateTests<TAdapter>; depends on AcPhys.Spec, xunit 2, Xunit.SkippableFact)
#   AcPhys.Cli   (the acphys command as a .NET tool: dotnet tool install AcPhys.Cli; AcPhys.Protocol, protocol v1, travels
#                 inside it: no packed library depends on it, so it is not a package of its own)
# Usage: packaging/pack.sh [-o DIR] [-c Release|Debug] [--version X.Y.Z] [--no-build]
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$root/artifacts/packages"
configuration=Release
extra=()
no_build=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    -o|--output) out="$2"; shift 2 ;;
    -c|--configuration) configuration="$2"; shift 2 ;;
    --version) extra+=("-p:Version=$2"); shift 2 ;;
    --no-build) extra+=("--no-build"); no_build=1; shift ;;
    *) echo "pack.sh: unknown argument '$1' (known: -o DIR, -c CONFIG, --version X.Y.Z, --no-build)" >&2; exit 2 ;;
  esac
done

mkdir -p "$out"
# A build made here (with --version) must not replace the checkout's own cli/bin, which ./acphys runs (issue 19: it
# changed `./acphys --version`): build output and intermediates go to artifacts/pack-build. --no-build packs what is built.
if [[ $no_build == 0 ]]; then extra+=("--artifacts-path" "$root/artifacts/pack-build"); fi
for project in core/AcPhys.Core.csproj contract/AcPhys.Contract.csproj formats/AcPhys.Formats.csproj spec/AcPhys.Spec.csproj xunit/AcPhys.Xunit.csproj cli/AcPhys.Cli.csproj; do
  packable=()
  [[ "$project" == core/* ]] && packable=("-p:IsPackable=true")
  DOTNET_NOLOGO=1 dotnet pack "$root/$project" -c "$configuration" -o "$out" -nologo -v:quiet "${packable[@]}" "${extra[@]}"
done
ls -1 "$out"/*.nupkg
