# A broken implementation for the e2e tests: completes the handshake, then dies on the first request.
read -r line
echo '{"protocol":1,"name":"crashes","ops":["lcoord_to_gid","gid_to_lcoord"]}'
read -r line
echo "crash-after-hello: simulated segmentation fault in lcoord_to_gid" >&2
exit 3
