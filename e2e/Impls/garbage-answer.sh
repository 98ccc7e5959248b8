# A broken implementation for the e2e tests: a valid handshake, then answers with the wrong shape.
read -r line
echo '{"protocol":1,"name":"garbage","ops":["lcoord_to_gid","gid_to_lcoord"]}'
while read -r line; do echo '{"cell":12345}'; done
