#!/usr/bin/env python3
"""Start-up cost of the tools: process start to first answer, and the shared libraries loaded.

    bench/startup_probe.py BIN_DIR [--runs 30]

For each tool it runs a command that answers at once (a one-run Monte Carlo of scenario a, a
plot of it, a one-second simulated run, a map loaded and planned in) RUNS times and takes the
median wall time from fork to exit; it counts the shared libraries the executable loads (ldd).
Prints one JSON line: {"tools": [{"name", "command", "median_ms", "libraries"}, ...]}.
scripts/bench uses it for the start-up rows.
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time


def libraries(executable):
    out = subprocess.run(["ldd", executable], capture_output=True, text=True).stdout
    return sum(1 for line in out.splitlines() if line.strip())


def median_ms(command, runs):
    times = []
    for _ in range(runs):
        started = time.perf_counter()
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        times.append((time.perf_counter() - started) * 1000)
    return statistics.median(times)


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 0 if len(argv) >= 2 else 2
    bin_dir = argv[1]
    runs = int(argv[argv.index("--runs") + 1]) if "--runs" in argv else 30
    config = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "config")
    png = os.path.join(tempfile.mkdtemp(), "plot.png")
    tools = [
        ("rrt_monte_carlo", ["--scenario", "a", "--runs", "1"]),
        ("rrt_plot", ["--scenario", "a", "-o", png]),
        ("rrt_monte_carlo", ["--map", os.path.join(config, "maps", "apartment.yaml"),
                             "--start", "-3.8,2.2", "--goal", "3.8,2.2", "--runs", "1",
                             "--algorithm", "rrt_connect"]),
        ("roomba_coverage", ["--behavior", "fsm", "--duration", "1"]),
    ]
    out = []
    for name, args in tools:
        executable = os.path.join(bin_dir, name)
        command = [executable] + args
        shown = [a.replace(os.path.join(config, ""), "config/") for a in args if a != png]
        out.append({"name": name, "command": " ".join([name] + shown).replace(" -o", ""),
                    "median_ms": median_ms(command, runs), "libraries": libraries(executable)})
    print(json.dumps({"tools": out}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
