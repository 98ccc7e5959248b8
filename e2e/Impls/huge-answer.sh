# A broken implementation for the e2e tests: answers hello with one 100 MB line (issue 19: it once took 820 MB of acphys).
read -r line
head -c 100000000 /dev/zero | tr '\0' x
echo
sleep 30
