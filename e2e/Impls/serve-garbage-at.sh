#!/bin/sh
# A pipelining implementation that misbehaves mid-stream: `acphys serve` (the rest of the arguments) whose N-th answer
# line ($1) is replaced by text that is not protocol v1; every other answer passes through, flushed line by line (GNU sed -u).
n=$1
shift
"$@" | sed -u "${n}s/.*/garbage, not JSON/"
