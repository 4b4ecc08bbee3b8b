#!/usr/bin/env python3
"""free_goal.py WORLD START: prints "GX GY", a goal that roomba_bt's navigation takes in WORLD for
the robot at START: the robot's disc (its radius + 0.1 m) free there, reachable from START over
such free points, and as far from it along the floor as any (so that the plan goes round what is
in the way). START is X,Y (m), a robot of the world file (robot2), or - for the world's initial
pose ((0, 0) in a map). Prints nothing and exits 1 when the robot has no free floor around it.

Used by `scripts/run` for the goal its `ready:` line suggests. WORLD is a world file or a
map_server YAML, read as place_robots.py reads it.
"""
import collections
import math
import os
import sys

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from place_robots import Grid, free  # noqa: E402

MAX_SAMPLES = 40000  # the floor is sampled this finely at most (a building in about a second)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    source, where = sys.argv[1], sys.argv[2]
    with open(source) as f:
        world = yaml.safe_load(f) or {}
    if "," in where:
        sx, sy = (float(v) for v in where.split(",")[:2])
    else:
        robots = {r.get("name"): r for r in world.get("robots") or []}
        pose = (robots[where] if where in robots else world).get("initial_pose") or {}
        default = (0.0, 0.0) if "image" in world or "map" in world else (3.2, 2.4)
        sx, sy = float(pose.get("x", default[0])), float(pose.get("y", default[1]))
    grid = None
    if "image" in world:
        grid, world = Grid(source, world), {}
    elif "map" in world:
        map_yaml = os.path.join(os.path.dirname(os.path.abspath(source)), world["map"])
        with open(map_yaml) as f:
            grid = Grid(map_yaml, yaml.safe_load(f))
    room = world.setdefault("room", {})
    room.setdefault("width", 6.4)
    room.setdefault("height", 4.8)
    keep = (world.get("robot") or {}).get("radius", 0.17) + 0.1
    if grid is not None:
        x0, y0 = grid.x0, grid.y0
        width, height = grid.width * grid.resolution, grid.height * grid.resolution
    else:
        x0, y0, width, height = 0.0, 0.0, room["width"], room["height"]
    step = max(0.1, math.sqrt(width * height / MAX_SAMPLES))
    cols, rows = max(1, int(width / step)), max(1, int(height / step))

    def centre(i, j):
        return x0 + (i + 0.5) * width / cols, y0 + (j + 0.5) * height / rows

    is_free = {}

    def open_cell(i, j):
        if (i, j) not in is_free:
            is_free[(i, j)] = (0 <= i < cols and 0 <= j < rows
                               and free(world, *centre(i, j), keep, grid))
        return is_free[(i, j)]

    # The robot's own sample, or the nearest free one within half a metre.
    si, sj = int((sx - x0) / width * cols), int((sy - y0) / height * rows)
    reach = int(math.ceil(0.5 / step))
    near = sorted(((i, j) for i in range(si - reach, si + reach + 1)
                   for j in range(sj - reach, sj + reach + 1)),
                  key=lambda c: math.hypot(*(a - b for a, b in zip(centre(*c), (sx, sy)))))
    start = next((c for c in near if open_cell(*c)), None)
    if start is None:
        return 1
    # Breadth first over the free samples: the last one reached is the farthest along the floor.
    seen, queue, last = {start}, collections.deque([start]), start
    while queue:
        last = i, j = queue.popleft()
        for n in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)):
            if n not in seen and open_cell(*n):
                seen.add(n)
                queue.append(n)
    gx, gy = centre(*last)
    print(f"{gx:.2f} {gy:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
