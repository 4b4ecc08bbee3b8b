#!/usr/bin/env python3
"""Draws the stale maps of the package's rooms: each room of a world file without its furniture,
as map_server's PGM and YAML in the world's frame (5 cm cells, the room's floor free, a wall two
cells thick round it, origin at the wall's outer corner). A robot given one with --known-map
(roomba_coverage, roomba_nav_eval) or ~known_map (roomba_bt) trusts its walls and finds the
furniture with its lidar. Writes config/maps/{furnished,dining,office}_walls.{pgm,yaml} from
config/roomba_world_furnished.yaml and test/navigation/worlds/{dining,office}.yaml; run it again
after changing a room's size.

usage: draw_room_walls.py [REPOSITORY_ROOT]"""
import os
import sys

import yaml

RESOLUTION = 0.05          # m per cell
WALL = 2                   # cells of wall round the room
FREE, OCCUPIED = 254, 0    # map_saver's grey levels
ROOMS = {                  # map name: the world file it is drawn from
    "furnished_walls": "config/roomba_world_furnished.yaml",
    "dining_walls": "test/navigation/worlds/dining.yaml",
    "office_walls": "test/navigation/worlds/office.yaml",
}


def draw(root, name, world_file):
    with open(os.path.join(root, world_file), encoding="utf-8") as f:
        room = yaml.safe_load(f)["room"]
    inner_w, inner_h = round(room["width"] / RESOLUTION), round(room["height"] / RESOLUTION)
    if abs(inner_w * RESOLUTION - room["width"]) > 1e-9 or \
            abs(inner_h * RESOLUTION - room["height"]) > 1e-9:
        sys.exit("%s: the room is not a whole number of %g m cells" % (world_file, RESOLUTION))
    columns, rows = inner_w + 2 * WALL, inner_h + 2 * WALL
    out = os.path.join(root, "config", "maps")
    with open(os.path.join(out, name + ".pgm"), "wb") as f:
        f.write(b"P5\n# roomba_rrt: scripts/lib/draw_room_walls.py\n%d %d\n255\n" % (columns, rows))
        for j in reversed(range(rows)):  # the image's first row is the top (largest y)
            f.write(bytes(FREE if WALL <= i < columns - WALL and WALL <= j < rows - WALL
                          else OCCUPIED for i in range(columns)))
    with open(os.path.join(out, name + ".yaml"), "w", encoding="utf-8") as f:
        f.write("# %s without its furniture (scripts/lib/draw_room_walls.py): a stale map for\n"
                "# --known-map / ~known_map, its walls only.\n"
                "image: %s.pgm\nresolution: %g\norigin: [%g, %g, 0.0]\nnegate: 0\n"
                "occupied_thresh: 0.65\nfree_thresh: 0.196\n"
                % (world_file, name, RESOLUTION, -WALL * RESOLUTION, -WALL * RESOLUTION))


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    for name, world_file in ROOMS.items():
        draw(root, name, world_file)


if __name__ == "__main__":
    main()
