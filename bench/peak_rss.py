#!/usr/bin/env python3
"""Peak resident memory of one command, as the kernel accounts it for that process.

    bench/peak_rss.py COMMAND [ARGS...]

Runs COMMAND (its stdout goes to our stderr, so only the result is on stdout), waits for it
with wait4(2) and prints one JSON line:

    {"command": "...", "exit_code": 0, "seconds": 1.23, "peak_rss_mb": 45.6}

peak_rss_mb is ru_maxrss of that child alone (MiB): the largest resident set the process ever
had, shared libraries included. scripts/bench uses it for the memory rows.
"""
import json
import os
import shlex
import subprocess
import sys
import time


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    command = argv[1:]
    started = time.monotonic()
    try:
        child = subprocess.Popen(command, stdout=sys.stderr.fileno())
    except OSError as e:
        print(f"peak_rss.py: cannot start {command[0]}: {e.strerror}", file=sys.stderr)
        return 127
    _, status, usage = os.wait4(child.pid, 0)
    child.returncode = os.waitstatus_to_exitcode(status)
    seconds = time.monotonic() - started
    print(json.dumps({
        "command": shlex.join(command),
        "exit_code": child.returncode,
        "seconds": round(seconds, 3),
        "peak_rss_mb": round(usage.ru_maxrss / 1024.0, 1),  # Linux reports KiB
    }))
    return 0 if child.returncode == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
