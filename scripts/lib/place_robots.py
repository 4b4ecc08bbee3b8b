#!/usr/bin/env python3
"""place_robots.py WORLD N OUT: writes WORLD with N named robots (robot1 .. robotN) to OUT.

Used by `scripts/run --robots N`. The robots stand on a grid over the room, each at least its
radius + 5 cm from the walls, the furniture and the other robots, facing alternately +x and -x.
Exits non-zero with a message when N of them do not fit.
"""
import math
import sys

import yaml


def free(world, x, y, r):
    room = world["room"]
    if not (r <= x <= room["width"] - r and r <= y <= room["height"] - r):
        return False
    furniture = world.get("furniture") or {}
    for c in furniture.get("circles") or []:
        if math.hypot(x - c["x"], y - c["y"]) < c["radius"] + r:
            return False
    for b in furniture.get("rectangles") or []:
        dx = max(b["min_x"] - x, 0.0, x - b["max_x"])
        dy = max(b["min_y"] - y, 0.0, y - b["max_y"])
        if math.hypot(dx, dy) < r:
            return False
    return True


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    source, count, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    with open(source) as f:
        world = yaml.safe_load(f)
    world.pop("initial_pose", None)  # with robots: each robot has its own
    world.pop("robots", None)
    radius = world.get("robot", {}).get("radius", 0.17)
    keep = radius + 0.05
    width, height = world["room"]["width"], world["room"]["height"]
    spacing = 2 * keep + 0.1
    cols, rows = int(width / spacing), int(height / spacing)
    spots = [((i + 0.5) * width / cols, (j + 0.5) * height / rows)
             for j in range(rows) for i in range(cols)]
    spots = [(x, y) for x, y in spots if free(world, x, y, keep)]
    if count < 1 or count > len(spots):
        sys.exit(f"scripts/run: --robots: between 1 and {len(spots)} robots fit in {source}")
    # Spread out: the free spot nearest the room's centre first, then each time the spot farthest
    # from those already taken.
    chosen = [min(spots, key=lambda p: math.hypot(p[0] - width / 2, p[1] - height / 2))]
    while len(chosen) < count:
        chosen.append(max((p for p in spots if p not in chosen),
                          key=lambda p: min(math.hypot(p[0] - q[0], p[1] - q[1]) for q in chosen)))
    spots = chosen
    world["robots"] = [
        {"name": f"robot{k + 1}",
         "initial_pose": {"x": round(x, 3), "y": round(y, 3), "theta": 0.0 if k % 2 == 0 else math.pi}}
        for k, (x, y) in enumerate(spots[:count])
    ]
    with open(out, "w") as f:
        f.write(f"# {count} robots placed by scripts/run --robots in {source}\n")
        yaml.safe_dump(world, f, sort_keys=False)


if __name__ == "__main__":
    main()
