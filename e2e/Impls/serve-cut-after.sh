#!/bin/sh
# A pipelining implementation cut off mid-stream: `acphys serve` (the rest of the arguments) that reads only the first
# N request lines ($1) and then exits, as a port killed in the middle of a stream of queries (its reader gone (GNU sed -u passes each line on at once): the tool's
# further writes fail and no answer comes after the N-th).
n=$1
shift
sed -u "${n}q" | "$@"
