#!/usr/bin/env python3
"""place_robots.py WORLD N OUT: writes WORLD with N named robots (robot1 .. robotN) to OUT.

Used by `scripts/run --robots N`. The robots stand on a grid over the room, each at least its
radius + 5 cm from the walls, the furniture, a map's occupied and unknown cells and the other
robots, facing alternately +x and -x. WORLD may be a map_server YAML (PGM image): OUT is then a
world file naming it (`map:`). Exits non-zero with a message when N of them do not fit.
"""
import math
import os
import sys

import yaml


class Grid:
    """A map_server map read as map_server reads a PGM in trinary mode: blocked[j][i] (row 0 at
    the bottom) for occupied and unknown cells."""

    def __init__(self, yaml_path, info):
        image = os.path.join(os.path.dirname(os.path.abspath(yaml_path)), info["image"])
        with open(image, "rb") as f:
            data = f.read()
        tokens, pos = [], 0
        while len(tokens) < 4:  # magic, width, height, maxval; comments skipped
            while data[pos:pos + 1].isspace():
                pos += 1
            if data[pos:pos + 1] == b"#":
                pos = data.index(b"\n", pos)
                continue
            end = pos
            while not data[end:end + 1].isspace():
                end += 1
            tokens.append(data[pos:end])
            pos = end
        if tokens[0] not in (b"P5", b"P2"):
            sys.exit(f"scripts/run: --robots in a map: {image} is not a PGM (convert it, or give "
                     "the robots in a world file that names the map)")
        self.width, self.height, maxval = int(tokens[1]), int(tokens[2]), int(tokens[3])
        n = self.width * self.height
        pixels = (list(data[pos + 1:pos + 1 + n]) if tokens[0] == b"P5"
                  else [int(v) for v in data[pos:].split()[:n]])
        scale = 255.0 / maxval
        negate, free_t = int(info.get("negate", 0)), float(info.get("free_thresh", 0.196))
        self.resolution = float(info["resolution"])
        self.x0, self.y0 = float(info["origin"][0]), float(info["origin"][1])
        self.blocked = []
        for j in range(self.height):  # grid row j is image row height - 1 - j
            row = pixels[(self.height - 1 - j) * self.width:(self.height - j) * self.width]
            occ = [(p * scale) / 255.0 if negate else (255.0 - p * scale) / 255.0 for p in row]
            self.blocked.append([o >= free_t for o in occ])

    def clear(self, x, y, r):
        """No blocked cell's square within r of (x, y)."""
        res = self.resolution
        i0, i1 = int(math.floor((x - r - self.x0) / res)), int(math.floor((x + r - self.x0) / res))
        j0, j1 = int(math.floor((y - r - self.y0) / res)), int(math.floor((y + r - self.y0) / res))
        for j in range(j0, j1 + 1):
            for i in range(i0, i1 + 1):
                if 0 <= i < self.width and 0 <= j < self.height and not self.blocked[j][i]:
                    continue
                cx0, cy0 = self.x0 + i * res, self.y0 + j * res
                dx = max(cx0 - x, 0.0, x - (cx0 + res))
                dy = max(cy0 - y, 0.0, y - (cy0 + res))
                if math.hypot(dx, dy) <= r:
                    return False
        return True


def free(world, x, y, r, grid=None):
    """The disc of radius r at (x, y) is inside the room (the map's free cells) and off the
    furniture."""
    if grid is not None:
        if not grid.clear(x, y, r):
            return False
    else:
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
    grid = None
    if "image" in world:  # a map_server YAML: the world file names it
        grid = Grid(source, world)
        world = {"map": os.path.abspath(source)}
    elif "map" in world:
        map_yaml = os.path.join(os.path.dirname(os.path.abspath(source)), world["map"])
        with open(map_yaml) as f:
            grid = Grid(map_yaml, yaml.safe_load(f))
        world["map"] = map_yaml
    world.pop("initial_pose", None)  # with robots: each robot has its own
    world.pop("robots", None)
    radius = (world.get("robot") or {}).get("radius", 0.17)
    keep = radius + 0.05
    if grid is not None:
        x0, y0 = grid.x0, grid.y0
        width, height = grid.width * grid.resolution, grid.height * grid.resolution
    else:
        x0, y0 = 0.0, 0.0
        width, height = world["room"]["width"], world["room"]["height"]
    spacing = 2 * keep + 0.1
    cols, rows = int(width / spacing), int(height / spacing)
    spots = [(x0 + (i + 0.5) * width / cols, y0 + (j + 0.5) * height / rows)
             for j in range(rows) for i in range(cols)]
    spots = [(x, y) for x, y in spots if free(world, x, y, keep, grid)]
    if count < 1 or count > len(spots):
        sys.exit(f"scripts/run: --robots: between 1 and {len(spots)} robots fit in {source}")
    # Spread out: the free spot nearest the room's centre first, then each time the spot farthest
    # from those already taken.
    chosen = [min(spots, key=lambda p: math.hypot(p[0] - x0 - width / 2, p[1] - y0 - height / 2))]
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
