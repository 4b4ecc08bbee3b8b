#!/usr/bin/env python3
"""The rviz view for a world that is a map (scripts/run --world map.yaml [--pose X,Y]): the
mode's own configuration with the top-down camera centred on the map and zoomed to show all of
it; on a map too large for that to show the robot (Nav2's 100 m benchmark map would draw the
Roomba 2 pixels wide and the cleaning rows 2 pixels apart), zoomed to MIN_SCALE around where
the robot starts instead, kept inside the map. The mouse wheel zooms out in rviz.

usage: rviz_map_view.py BASE.rviz OUT.rviz MAP.yaml [X,Y]  (the start; default the map's (0, 0))"""
import os
import sys

import yaml

VIEW_WIDTH, VIEW_HEIGHT = 600.0, 520.0  # pixels: about what rviz's default window shows
MIN_SCALE = 20.0  # pixels per metre: the Roomba 7 pixels wide, the rows 7 pixels apart


def view_centre_and_scale(x0, y0, w, h, start):
    """The camera's centre (m) and scale (pixels per metre) for a map of w × h m whose lower
    left corner is (x0, y0), the robot starting at `start` (x, y)."""
    scale = min(VIEW_WIDTH / w, VIEW_HEIGHT / h)
    if scale >= MIN_SCALE:
        return (x0 + w / 2, y0 + h / 2), scale
    half_w, half_h = VIEW_WIDTH / MIN_SCALE / 2, VIEW_HEIGHT / MIN_SCALE / 2

    def inside(c, low, size, half):
        if size <= 2 * half:
            return low + size / 2
        return min(max(c, low + half), low + size - half)

    return (inside(start[0], x0, w, half_w), inside(start[1], y0, h, half_h)), MIN_SCALE


def image_size(path):
    """Width and height from a PGM's or PNG's header (the simulator refuses anything else)."""
    with open(path, "rb") as f:
        head = f.read(4096)
    if head[:8] == b"\x89PNG\r\n\x1a\n":
        return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    tokens = []
    for line in head.split(b"\n"):
        tokens += line.split(b"#")[0].split()
        if len(tokens) >= 3:
            return int(tokens[1]), int(tokens[2])
    raise ValueError("%s: not a PGM or PNG image" % path)


def main():
    base, out, map_yaml = sys.argv[1:4]
    start = (0.0, 0.0)
    if len(sys.argv) > 4:
        start = tuple(float(v) for v in sys.argv[4].split(",")[:2])
    with open(map_yaml, encoding="utf-8") as f:
        info = yaml.safe_load(f)
    image = os.path.join(os.path.dirname(map_yaml), info["image"])
    width, height = image_size(image)
    resolution = float(info["resolution"])
    x0, y0 = float(info["origin"][0]), float(info["origin"][1])
    w, h = width * resolution, height * resolution
    with open(base, encoding="utf-8") as f:
        config = yaml.safe_load(f)
    view = config["Visualization Manager"]["Views"]["Current"]
    (view["X"], view["Y"]), view["Scale"] = view_centre_and_scale(x0, y0, w, h, start)
    with open(out, "w", encoding="utf-8") as f:
        yaml.safe_dump(config, f, default_flow_style=False)


if __name__ == "__main__":
    main()
