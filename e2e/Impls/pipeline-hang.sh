#!/bin/sh
# A pipelining implementation that answers three requests and then reads on without answering: a hang mid-stream.
read -r hello
echo '{"protocol":1,"name":"pipeline-hang","ops":["gid_to_lcoord","lcoord_to_gid","pipeline"]}'
n=0
while read -r line; do
  n=$((n + 1))
  if [ "$n" -le 3 ]; then
    case "$line" in
      *'"op":"gid_to_lcoord"'*) echo '{"ok":true,"x":0,"y":0}' ;;
      *) echo '{"cell":"0x00000000"}' ;;
    esac
  fi
done
