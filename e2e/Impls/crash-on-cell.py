"""A port that crashes on one cell, for the fuzz e2e tests: a proxy in front of another protocol v1 implementation.

    python3 crash-on-cell.py PATTERN COMMAND...

Every request line is passed to COMMAND and its answer back, except that a request whose "cell" matches the regular
expression PATTERN (e.g. "0x..FF": a block row of 0xFF) makes this process write a line to stderr and exit 3 without
answering: the child crashed on that case.
"""
import re
import subprocess
import sys

pattern, command = re.compile('"cell":"' + sys.argv[1]), sys.argv[2:]
inner = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
for line in sys.stdin:
    if pattern.search(line):
        print("crash-on-cell: simulated crash on " + line.strip(), file=sys.stderr, flush=True)
        inner.kill()
        sys.exit(3)
    inner.stdin.write(line)
    inner.stdin.flush()
    answer = inner.stdout.readline()
    if not answer:
        sys.exit(4)
    sys.stdout.write(answer)
    sys.stdout.flush()
