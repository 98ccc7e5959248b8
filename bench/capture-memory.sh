#!/bin/sh
# Constant memory of acphys capture check (issue 50): the peak working set (max RSS) checking 100,000 and 1,000,000
# outdoor frames streamed from disk, and their ratio (about 1 when the check holds no list of frames). Also the
# wall time per run, whole process (start-up included); the same for acphys render of each (its decimated path). Usage: bench/capture-memory.sh [OUT_DIR]. Prints the load.
set -eu
cd "$(dirname "$0")/.."
out="${1:-$(mktemp -d)}"
mkdir -p "$out"
dotnet build bench -c Release -v q -nologo >/dev/null
dotnet build cli -c Release -v q -nologo >/dev/null
bench=bench/bin/Release/net10.0/AcPhys.Bench.dll
tool=cli/bin/Release/net10.0/acphys.dll
echo "load: $(uptime)"
for n in 100000 1000000; do
  dotnet "$bench" capture-file "$n" "$out/capture-$n.tsv"
  /usr/bin/time -f "%M %e" -o "$out/time-$n" dotnet "$tool" capture check "$out/capture-$n.tsv" --quiet >"$out/out-$n" || { echo "capture check failed on $n frames"; cat "$out/out-$n"; exit 1; }
  read -r rss secs <"$out/time-$n"
  echo "$n frames: $(wc -c <"$out/capture-$n.tsv") bytes, peak RSS ${rss} KB, ${secs} s wall ($(tail -1 "$out/out-$n"))"
  eval "rss_$n=$rss"
  /usr/bin/time -f "%M %e" -o "$out/rtime-$n" dotnet "$tool" render "$out/capture-$n.tsv" -o "$out/capture-$n.svg" >"$out/rout-$n" || { echo "render failed on $n frames"; cat "$out/rout-$n"; exit 1; }
  read -r rss secs <"$out/rtime-$n"
  echo "$n frames: render peak RSS ${rss} KB, ${secs} s wall, SVG $(wc -c <"$out/capture-$n.svg") bytes"
  eval "rrss_$n=$rss"
done
awk -v a="$rss_100000" -v b="$rss_1000000" 'BEGIN { printf "peak RSS ratio 1M / 100k frames: %.2f\n", b / a }'
awk -v a="$rrss_100000" -v b="$rrss_1000000" 'BEGIN { printf "render peak RSS ratio 1M / 100k frames: %.2f\n", b / a }'
