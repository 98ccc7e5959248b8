#!/usr/bin/env bash
# docs/tradeoffs/run.sh: regenerate the measured tables and the plot of docs/tradeoffs.md and docs/numerics.md.
#   bash docs/tradeoffs/run.sh budget     # budget-samples.csv, budget-curve.csv, budget.md, budget-curve.{svg,png}
#   bash docs/tradeoffs/run.sh accuracy   # accuracy.md (float32 / double vs the exact oracle, by boundary class)
#   bash docs/tradeoffs/run.sh numerics   # numerics.md (extreme sweeps, tie bands)
#   bash docs/tradeoffs/run.sh bench      # bench.md (acphys bench)
#   bash docs/tradeoffs/run.sh all
# Each table file starts with the exact acphys command and the load average (the machine is shared).
# Installs gnuplot (Debian gnuplot-nox) with apt-get when it is missing.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="$root/docs/tradeoffs"
cd "$root"

write() { # write FILE: stdin to FILE atomically
  local tmp
  tmp="$(mktemp "$1.XXXXXX")"
  cat > "$tmp"
  chmod 644 "$tmp"
  mv -f "$tmp" "$1"
}

ensure_gnuplot() {
  if command -v gnuplot >/dev/null 2>&1; then return; fi
  echo "run.sh: gnuplot not found; installing gnuplot-nox with apt-get" >&2
  if [[ $(id -u) -eq 0 ]]; then apt-get update -qq && apt-get install -y -qq gnuplot-nox >/dev/null
  else sudo apt-get update -qq && sudo apt-get install -y -qq gnuplot-nox >/dev/null; fi
}

budget() {
  ./acphys tradeoffs budget --seeds 20 --max-cases 20000 --out "$out" --fuzz "$out/fuzz-first-crash.csv" | write "$out/budget.md"
  ensure_gnuplot
  gnuplot -e "dir='$out'" "$out/budget.gp"
  echo "run.sh: wrote $out/budget.md, budget-curve.csv, budget-samples.csv, budget-curve.svg, budget-curve.png" >&2
}

accuracy() { ./acphys tradeoffs accuracy --seed 8 --cases 20000 | write "$out/accuracy.md"; echo "run.sh: wrote $out/accuracy.md" >&2; }
numerics() { ./acphys tradeoffs numerics | write "$out/numerics.md"; echo "run.sh: wrote $out/numerics.md" >&2; }
bench() { ./acphys bench | write "$out/bench.md"; echo "run.sh: wrote $out/bench.md" >&2; }

case "${1:-all}" in
  budget) budget ;;
  accuracy) accuracy ;;
  numerics) numerics ;;
  bench) bench ;;
  all) numerics; accuracy; bench; budget ;;
  *) echo "usage: bash docs/tradeoffs/run.sh [budget|accuracy|numerics|bench|all]" >&2; exit 2 ;;
esac
