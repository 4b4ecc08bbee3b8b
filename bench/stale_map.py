#!/usr/bin/env python3
"""Cleaning and navigation with a stale map of the home (issue 43): the robot is given the room's
or the apartment's map without its furniture (config/maps/*_walls.yaml, --known-map) and finds
the furniture with its lidar. For each of the furnished room, the dining room, the office and
the apartment: roomba_coverage's time to 95 % of the true reachable floor knowing the world
(--behavior coverage) and with the stale map (--unknown --known-map), the ratio and the bumps;
roomba_nav_eval --unknown --known-map over 200 random goals: reached and bumps. Simulated time,
deterministic. Prints one JSON object for bench/report.py.

  bench/stale_map.py [--bin devel/lib/roomba_rrt] [--goals 200] [--duration 900]
"""
import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
WORLDS = [  # name, world, its stale map
    ("furnished room", "config/roomba_world_furnished.yaml", "config/maps/furnished_walls.yaml"),
    ("dining room", "test/navigation/worlds/dining.yaml", "config/maps/dining_walls.yaml"),
    ("office", "test/navigation/worlds/office.yaml", "config/maps/office_walls.yaml"),
    ("apartment", "config/maps/apartment.yaml", "config/maps/apartment_walls.yaml"),
]


def cleaning(binary, args):
    """Time to 95 % (s, None when not reached), bumps and plans of one roomba_coverage run."""
    out = subprocess.run([binary] + args, capture_output=True, text=True, timeout=900,
                         check=True).stdout
    time95 = re.search(r"time to 95 % \[s\]\s+(\S+)", out).group(1)
    plans = re.search(r"plans per run\s+(\S+)", out)
    return {"time95": None if time95 == "—" else float(time95),
            "bumps": float(re.search(r"bumps per run\s+(\S+)", out).group(1)),
            "plans": float(plans.group(1)) if plans else None}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=os.path.join(ROOT, "devel", "lib", "roomba_rrt"))
    parser.add_argument("--goals", type=int, default=200)
    parser.add_argument("--duration", type=int, default=900)
    a = parser.parse_args()
    rows = []
    for name, world, walls in WORLDS:
        world, walls = os.path.join(ROOT, world), os.path.join(ROOT, walls)
        common = ["--behavior", "coverage", "--world", world, "--duration", str(a.duration)]
        known = cleaning(os.path.join(a.bin, "roomba_coverage"), common)
        stale = cleaning(os.path.join(a.bin, "roomba_coverage"),
                         common + ["--unknown", "--known-map", walls])
        nav = json.loads(subprocess.run(
            [os.path.join(a.bin, "roomba_nav_eval"), "--unknown", "--known-map", walls,
             "--world", world, "--goals", str(a.goals), "--json"],
            capture_output=True, text=True, timeout=900, check=True).stdout)
        rows.append({"world": name, "known_s": known["time95"], "stale_s": stale["time95"],
                     "bumps": stale["bumps"], "plans": stale["plans"],
                     "goals": nav["goals"], "reached_pct": nav["reached_pct"],
                     "nav_bumps": nav["bumps"]})
    print(json.dumps({"worlds": rows}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
