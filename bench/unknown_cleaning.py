#!/usr/bin/env python3
"""Cleaning a home the robot has never seen, beside the known map and the lab's FSM: issue 43's
nine worlds through roomba_coverage --compare --unknown (simulated time, deterministic).

Each world runs `roomba_coverage --compare --unknown --world W [--crop ...] [--pose ...]
--duration 900`: the lab's FSM and BT, the cleaning tree on the known map and the cleaning of
the unknown world (lidar and bumper only), all measured on the *true* reachable floor against
the same ideal time. Prints one line per world (or, with --json, what scripts/bench's report
reads):

  furnished      unknown 98.6 / 99.6 % by 2x / 2.5x ideal, 99 % at 346 s, 0 bumps, explored by
                 50 s · known map 99.7 / 99.7 % · lab FSM 48.3 / 53.0 %  · target met

  bench/unknown_cleaning.py [--json] [--only NAME] [--maps DIR] [--roomba-coverage PATH]
                            [-- extra roomba_coverage arguments, e.g. --pose X,Y]

Targets (issue 43): >= 95 % by 2x the ideal time, >= 99 % by 2.5x, <= 2 bumps per run. The
turtlebot3 arena's 99 % is not required: its staircase walls keep even the known map at 97 %
(doc/coverage.md#results); its row reports that bound beside it.
"""
import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# name, label, world (relative to the repository, or a map of --maps), extra arguments; the known
# map's table (doc/coverage.md#results) uses the same crops and starts.
WORLDS = [
    ("furnished", "furnished room", "furnished", []),
    ("dining", "dining room", "test/navigation/worlds/dining.yaml", []),
    ("office", "office", "test/navigation/worlds/office.yaml", []),
    ("apartment", "apartment map", "apartment", []),
    ("turtlebot3", "turtlebot3_world", "maps:turtlebot3_world.yaml", ["--pose", "0.5,0"]),
    ("willow", "willow_full crop", "maps:willow_full.yaml",
     ["--crop", "-16,-4,-8,3.5", "--pose", "-12,0"]),
    ("warehouse", "warehouse crop", "maps:warehouse.yaml",
     ["--crop", "-10.9,-15,-3.4,-7.5", "--pose", "-6.5,-10.8"]),
    ("depot", "depot crop", "maps:depot.yaml", ["--crop", "21.5,0.5,29,8.5", "--pose", "25,5"]),
    ("nav2_bench", "nav2_bench crop", "maps:nav2_bench_100by100_15.yaml",
     ["--crop", "10,10,17.5,17.5", "--pose", "14,14"]),
]
# Worlds whose 99 % is not required (the known map's own bound is below it).
WAIVED_99 = {"turtlebot3"}
DURATION = 900


def world_path(world, maps):
    if world.startswith("maps:"):
        return os.path.join(maps, world[len("maps:"):])
    if "/" in world:
        return os.path.join(ROOT, world)
    return world  # the package's names: furnished, apartment


def columns(text):
    """{row label: [cell per behaviour]} and the behaviours, from roomba_coverage's table."""
    lines = text.splitlines()
    header = next((i for i, l in enumerate(lines) if l.strip().startswith("time [s]")), None)
    if header is None:
        raise ValueError("no table in roomba_coverage's output")
    names = lines[header].split()[2:]
    rows = {}
    for line in lines[header + 1:]:
        if not line.startswith("  ") or line.startswith("  simulated"):
            break
        cells = re.split(r"\s{2,}", line.strip())
        rows[cells[0]] = cells[1:]
    return names, rows


def number(cell):
    m = re.match(r"[\d.]+", cell or "")
    return float(m.group(0)) if m else None


def measure(binary, name, label, world, extra, maps):
    args = ["--compare", "--unknown", "--world", world_path(world, maps),
            "--duration", str(DURATION)] + extra
    out = subprocess.run([binary] + args, capture_output=True, text=True, timeout=900)
    if out.returncode != 0:
        raise RuntimeError(f"roomba_coverage {' '.join(args)} failed ({out.returncode}): "
                           f"{(out.stdout + out.stderr).strip().splitlines()[:1]}")
    names, rows = columns(out.stdout)
    ideal = float(re.search(r"ideal time ([\d.]+) s", out.stdout).group(1))

    def at(multiple):
        label_ = next((k for k in rows if k.endswith(f"({multiple:.1f}× ideal)")), None)
        return {n: number(rows[label_][k]) if label_ else None for k, n in enumerate(names)}

    def row(label_):
        return {n: rows[label_][k] for k, n in enumerate(names)} if label_ in rows else {}

    at2, at25 = at(2.0), at(2.5)
    t99, bumps, explored = row("time to 99 % [s]"), row("bumps per run"), row("explored by [s]")
    result = {"world": name, "label": label, "args": " ".join(args[1:]), "ideal_s": ideal,
              "waived_99": name in WAIVED_99}
    for behavior in names:
        result[behavior] = {"at_2x": at2[behavior], "at_2_5x": at25[behavior],
                            "time_to_99_s": number(t99.get(behavior)),
                            "bumps": number(bumps.get(behavior))}
    result["unknown"]["explored_s"] = number(explored.get("unknown"))
    u = result["unknown"]
    # 99 % by 2.5x from the time 99 % is first reached, not from the coverage printed at 2.5x:
    # that is rounded to 0.1 % (98.95 % prints 99.0).
    reached_99 = u["time_to_99_s"] is not None and u["time_to_99_s"] <= 2.5 * ideal
    result["met"] = bool(u["at_2x"] is not None and u["at_2x"] >= 95 and u["bumps"] <= 2 and
                         (name in WAIVED_99 or reached_99))
    return result


def line(r):
    u, k, f = r["unknown"], r["coverage"], r["fsm"]
    t99 = "—" if u["time_to_99_s"] is None else f"{u['time_to_99_s']:.0f} s"
    verdict = "target met" if r["met"] else "**target missed**"
    if r["waived_99"]:
        verdict += " (99 % waived)"
    return (f"{r['world']:12s} unknown {u['at_2x']:.1f} / {u['at_2_5x']:.1f} % by 2x / 2.5x "
            f"ideal, 99 % at {t99}, {u['bumps']:.0f} bumps, explored by {u['explored_s']:.0f} s"
            f" · known map {k['at_2x']:.1f} / {k['at_2_5x']:.1f} % · lab FSM {f['at_2x']:.1f} / "
            f"{f['at_2_5x']:.1f} % · {verdict}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--only", help="one world by name (furnished, dining, ...)")
    parser.add_argument("--maps", default=os.path.join(ROOT, "..", "shared", "maps"))
    parser.add_argument("--roomba-coverage", default=os.path.join(
        ROOT, "devel", "lib", "roomba_rrt", "roomba_coverage"))
    parser.add_argument("extra", nargs="*", help="more roomba_coverage arguments (after --)")
    o = parser.parse_args()
    worlds = [w for w in WORLDS if not o.only or w[0] == o.only]
    if not worlds:
        sys.exit(f"unknown_cleaning: no world called {o.only!r} "
                 f"(one of {', '.join(w[0] for w in WORLDS)})")
    results, errors = [], []
    for name, label, world, extra in worlds:
        try:
            r = measure(o.roomba_coverage, name, label, world, extra + o.extra, o.maps)
        except (RuntimeError, ValueError, AttributeError, subprocess.TimeoutExpired) as e:
            errors.append({"world": name, "label": label, "error": str(e)})
            if not o.json:
                print(f"{name:12s} n/a: {e}", flush=True)
            continue
        results.append(r)
        if not o.json:
            print(line(r), flush=True)
    if o.json:
        print(json.dumps({"duration_s": DURATION, "worlds": results, "errors": errors}))
    else:
        print(f"worlds {len(results)} · target met in {sum(r['met'] for r in results)}"
              + (f" · {len(errors)} failed" if errors else ""))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
