#!/usr/bin/env python3
"""The rviz view for a world that is a map (scripts/run --world map.yaml): the mode's own
configuration with the top-down camera centred on the map and zoomed to show all of it.

usage: rviz_map_view.py BASE.rviz OUT.rviz MAP.yaml"""
import os
import sys

import yaml


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
    view["X"], view["Y"] = x0 + w / 2, y0 + h / 2
    view["Scale"] = min(600.0 / w, 520.0 / h)  # pixels per metre: the whole map in the view
    with open(out, "w", encoding="utf-8") as f:
        yaml.safe_dump(config, f, default_flow_style=False)


if __name__ == "__main__":
    main()
