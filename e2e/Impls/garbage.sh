# A broken implementation for the e2e tests: answers the handshake with text that is not protocol v1.
read -r line
echo 'Welcome to my physics server v0.1!'
exec sleep 600
