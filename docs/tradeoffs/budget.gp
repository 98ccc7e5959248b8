# gnuplot script: the verification budget curve (docs/tradeoffs.md). Run by docs/tradeoffs/run.sh.
# Input: budget-curve.csv and fuzz-first-crash.csv in `dir`; output: budget-curve.svg and budget-curve.png there.
if (!exists("dir")) dir = "docs/tradeoffs"
csv = dir."/budget-curve.csv"
fuzz = dir."/fuzz-first-crash.csv"
set datafile separator ","
faults = system("tail -n +2 ".csv." | cut -d, -f1 | uniq | tr '\\n' ' '")

set style line 1 lw 1.5
set grid
set yrange [-0.03:1.03]
set ylabel "P(detect), fresh seeds"

do for [fmt in "svg png"] {
    if (fmt eq "svg") { set terminal svg size 1300,560 dynamic font "sans,11" ; set output dir."/budget-curve.svg" }
    if (fmt eq "png") { set terminal pngcairo size 1300,560 font "sans,10" ; set output dir."/budget-curve.png" }
    set multiplot title "Planted faults: detection probability against the verification budget (20 fresh seeds; lines = suite, triangles = AFL++)"
    set logscale x
    set xrange [1:100000]
    set size 0.4,0.95
    set origin 0.0,0.0
    set key off
    set xlabel "generated cases per invariant (pr = 5,000, nightly = 200,000)"
    set arrow 1 from 5000, graph 0 to 5000, graph 1 nohead dt 2 lc rgb "gray40"
    plot for [f in faults] "< grep '^".f.",' ".csv using 2:4 with linespoints pt 7 ps 0.5 title f, \
         fuzz using 4:(valid(3) ? 1.0 : NaN) with points pt 9 ps 1.3 lc rgb "black" title "AFL++ first crash (execs)"
    unset arrow 1
    set size 0.6,0.95
    set autoscale x
    set origin 0.4,0.0
    set key outside right top font ",9" spacing 0.9
    set xlabel "seconds for the whole catalogue at that budget (2 shared cores)"
    plot for [f in faults] "< grep '^".f.",' ".csv using 3:4 with linespoints pt 7 ps 0.5 title f, \
         fuzz using 3:(1.0) with points pt 9 ps 1.3 lc rgb "black" title "AFL++ first crash"
    unset multiplot
    unset output
}
