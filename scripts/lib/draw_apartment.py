#!/usr/bin/env python3
"""Draws the package's own map: a small apartment (10 m x 7 m, 5 cm cells) with a living room,
a kitchen, a bedroom and a bathroom, doors between them and some furniture, as map_server's PGM
and YAML (config/maps/apartment.pgm, .yaml). The map's (0, 0) is the hallway's centre, free
floor, where the robot starts by default. Also the same apartment without its furniture
(apartment_walls.pgm, .yaml): the stale map a robot is given with --known-map, which finds the
furniture with its lidar. Run it again after changing the plan below.

usage: draw_apartment.py OUT_DIR"""
import os
import sys

RESOLUTION = 0.05            # m per cell
WIDTH, HEIGHT = 10.5, 7.5    # m: the apartment (10 x 7) and a 0.25 m unknown margin round it
ORIGIN = (-5.25, -3.75)      # the lower-left corner: (0, 0) is the centre
FREE, WALL, UNKNOWN = 254, 0, 205  # map_saver's grey levels

# Rectangles in metres, from the apartment's lower-left inner corner (0, 0) to (10, 7).
WALLS = [  # x0, y0, x1, y1; 10 cm thick
    (-0.1, -0.1, 10.1, 0.0), (-0.1, 7.0, 10.1, 7.1),   # south, north
    (-0.1, -0.1, 0.0, 7.1), (10.0, -0.1, 10.1, 7.1),   # west, east
    (6.0, 0.0, 6.1, 2.6), (6.0, 3.5, 6.1, 7.0),        # living room | bedroom, bathroom: doors
    (6.1, 4.0, 7.4, 4.1), (8.3, 4.0, 10.0, 4.1),       # bedroom | bathroom, door 7.4-8.3
    (0.0, 4.5, 2.2, 4.6), (3.1, 4.5, 3.8, 4.6),        # living room | kitchen, door 2.2-3.1
    (3.8, 4.5, 3.9, 7.0),                               # kitchen | hall
]
FURNITURE = [
    (0.3, 0.3, 2.3, 1.2),    # sofa
    (2.8, 1.8, 4.0, 2.8),    # table
    (0.0, 6.4, 3.8, 7.0),    # kitchen counter
    (8.0, 0.3, 10.0, 2.5),   # bed
    (9.4, 5.8, 10.0, 7.0),   # bathtub
    (5.3, 0.0, 6.0, 0.5),    # shelf
]


def draw(out, name, furniture, title):
    columns, rows = round(WIDTH / RESOLUTION), round(HEIGHT / RESOLUTION)
    margin = 0.25
    grid = [[UNKNOWN] * columns for _ in range(rows)]

    def fill(x0, y0, x1, y1, value):
        # Cells whose centre is inside the rectangle (apartment coordinates).
        for j in range(rows):
            y = (j + 0.5) * RESOLUTION - margin
            if not y0 <= y <= y1:
                continue
            for i in range(columns):
                x = (i + 0.5) * RESOLUTION - margin
                if x0 <= x <= x1:
                    grid[j][i] = value

    fill(0.0, 0.0, 10.0, 7.0, FREE)
    for rect in WALLS + furniture:
        fill(*rect, WALL)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, name + ".pgm"), "wb") as f:
        f.write(b"P5\n# roomba_rrt: scripts/lib/draw_apartment.py\n%d %d\n255\n" % (columns, rows))
        for j in reversed(range(rows)):  # the image's first row is the top (largest y)
            f.write(bytes(grid[j]))
    with open(os.path.join(out, name + ".yaml"), "w", encoding="utf-8") as f:
        f.write("# %s\n"
                "image: %s.pgm\nresolution: %g\norigin: [%g, %g, 0.0]\nnegate: 0\n"
                "occupied_thresh: 0.65\nfree_thresh: 0.196\n" % (title, name, RESOLUTION, *ORIGIN))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "config/maps"
    draw(out, "apartment", FURNITURE,
         "The package's own map (scripts/lib/draw_apartment.py): a 10 m x 7 m apartment.")
    draw(out, "apartment_walls", [],
         "The apartment without its furniture (scripts/lib/draw_apartment.py): a stale map for\n"
         "# --known-map / ~known_map, its walls and doors only.")


if __name__ == "__main__":
    main()
