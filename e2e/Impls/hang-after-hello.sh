# A broken implementation for the e2e tests: completes the handshake, then never answers.
read -r line
echo '{"protocol":1,"name":"hangs","ops":["lcoord_to_gid","gid_to_lcoord"]}'
echo "hang-after-hello: going to sleep" >&2
read -r line
exec sleep 600
