# gnuplot script: the verification budget curve (docs/tradeoffs.md). Run by docs/tradeoffs/run.sh.
# Input: budget-curve.csv and fuzz-first-crash.csv in `dir`; output: budget-curve.svg and budget-curve.png there.
# One line per known-bug catalogue entry: outdoor bugs solid, indoor bugs dashed (column 7 of budget-curve.csv).
if (!exists("dir")) dir = "docs/tradeoffs"
csv = dir."/budget-curve.csv"
fuzz = dir."/fuzz-first-crash.csv"
set datafile separator ","
outdoor = system("awk -F, 'NR > 1 && $7 == \"outdoor\" { print $1 }' ".csv." | uniq | tr '\\n' ' '")
indoor = system("awk -F, 'NR > 1 && $7 == \"indoor\" { print $1 }' ".csv." | uniq | tr '\\n' ' '")
nbugs = words(outdoor) + words(indoor)

set grid
set yrange [-0.03:1.03]
set ylabel "P(detect), fresh seeds"

do for [fmt in "svg png"] {
    if (fmt eq "svg") { set terminal svg size 1400,640 dynamic font "sans,11" ; set output dir."/budget-curve.svg" }
    if (fmt eq "png") { set terminal pngcairo size 1400,640 font "sans,10" ; set output dir."/budget-curve.png" }
    set multiplot title sprintf("Known-bug catalogue (%d bugs: outdoor solid, indoor dashed): detection probability against the verification budget (fresh seeds; triangles = AFL++)", nbugs)
    set logscale x
    set xrange [1:300000]
    set size 0.4,0.95
    set origin 0.0,0.0
    set key off
    set xlabel "generated cases per invariant (dotted: pr = 5,000, nightly = 200,000)"
    set arrow 1 from 5000, graph 0 to 5000, graph 1 nohead dt 3 lc rgb "gray40"
    set arrow 2 from 200000, graph 0 to 200000, graph 1 nohead dt 3 lc rgb "gray40"
    plot for [f in outdoor] "< grep '^".f.",' ".csv using 2:4 with linespoints dt 1 pt 7 ps 0.5 title f, \
         for [f in indoor] "< grep '^".f.",' ".csv using 2:4 with linespoints dt 2 pt 5 ps 0.5 title f, \
         fuzz using 4:(valid(3) ? 1.0 : NaN) with points pt 9 ps 1.3 lc rgb "black" title "AFL++ first crash (execs)"
    unset arrow 1
    unset arrow 2
    set size 0.6,0.95
    set autoscale x
    set origin 0.4,0.0
    set key outside right top font ",8" spacing 0.85
    set xlabel "seconds for the whole catalogue at that budget (2 shared cores)"
    plot for [f in outdoor] "< grep '^".f.",' ".csv using 3:4 with linespoints dt 1 pt 7 ps 0.5 title f, \
         for [f in indoor] "< grep '^".f.",' ".csv using 3:4 with linespoints dt 2 pt 5 ps 0.5 title f, \
         fuzz using 3:(1.0) with points pt 9 ps 1.3 lc rgb "black" title "AFL++ first crash"
    unset multiplot
    unset output
}
