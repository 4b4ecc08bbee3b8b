#!/usr/bin/env python3
"""The rviz view for a world that is a map (scripts/run --world map.yaml [--pose X,Y]): the
mode's own configuration with the top-down camera on the map's known part (its free and occupied
cells, and the start: a map_saver map is mostly unknown border, and the turtlebot3 arena fills a
quarter of its 19 m image) and its 1 m grid laid over that part. The view is centred on it and
zoomed to show all of it; on a map too large for that to show the robot (Nav2's 100 m benchmark
map would draw the Roomba 2 pixels wide and the cleaning rows 2 pixels apart), zoomed to
MIN_SCALE around where the robot starts instead, kept inside the known part. The mouse wheel
zooms out in rviz.

The cells are classified as roomba_sim reads them (map_server's trinary mode: the average of a
pixel's channels, negate, occupied_thresh and free_thresh). An image this script cannot decode
(a PNG that is interlaced or not 8 bits per channel) is framed whole.

usage: rviz_map_view.py BASE.rviz OUT.rviz MAP.yaml [X,Y]  (the start; default the map's (0, 0))"""
import math
import os
import struct
import sys
import zlib

import yaml

VIEW_WIDTH, VIEW_HEIGHT = 600.0, 520.0  # pixels: about what rviz's default window shows
MIN_SCALE = 20.0  # pixels per metre: the Roomba 7 pixels wide, the rows 7 pixels apart
MARGIN = 0.25  # metres of view round the known part, so that its walls are not on the edge


def view_centre_and_scale(x0, y0, w, h, start):
    """The camera's centre (m) and scale (pixels per metre) for a region of w × h m whose lower
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


def read_pgm(data):
    """(width, height, channels, pixel bytes or None) of a PGM (P5, 8 bits: pixels too; P2 or
    16 bits: the size only)."""
    tokens, k = [], 2
    while len(tokens) < 3:
        while k < len(data) and (data[k:k + 1].isspace() or data[k:k + 1] == b"#"):
            if data[k:k + 1] == b"#":
                k = data.index(b"\n", k) if b"\n" in data[k:] else len(data)
            k += 1
        start = k
        while k < len(data) and data[k:k + 1].isdigit():
            k += 1
        if start == k:
            raise ValueError("not a PGM header")
        tokens.append(int(data[start:k]))
    width, height, maxval = tokens
    pixels = data[k + 1:k + 1 + width * height]
    if data[:2] != b"P5" or maxval > 255 or len(pixels) < width * height:
        return width, height, 1, None
    return width, height, 1, pixels


def unfilter(raw, width, height, bpp):
    """PNG's scanline filters undone: the pixel bytes, row after row (8 bits per channel)."""
    stride = width * bpp
    out = bytearray(stride * height)
    prior = bytearray(stride)
    k = 0
    for j in range(height):
        kind, line = raw[k], bytearray(raw[k + 1:k + 1 + stride])
        k += 1 + stride
        if kind == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif kind == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, prior))
        elif kind == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + prior[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b, c = prior[i], prior[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out[j * stride:(j + 1) * stride] = line
        prior = line
    return bytes(out)


def read_png(data):
    """(width, height, channels, pixel bytes or None) of a PNG (8 bits per channel, not
    interlaced: pixels too; else the size only). A palette image's channel is its index, as
    roomba_sim's loader (SDL_image) averages it."""
    width, height = struct.unpack(">II", data[16:24])
    depth, colour, interlace = data[24], data[25], data[28]
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}.get(colour)
    if depth != 8 or interlace != 0 or channels is None:
        return width, height, 1, None
    chunks, k = [], 8
    while k + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[k:k + 8])
        if kind == b"IDAT":
            chunks.append(data[k + 8:k + 8 + length])
        k += 12 + length
    raw = zlib.decompress(b"".join(chunks))
    return width, height, channels, unfilter(raw, width, height, channels)


def read_image(path):
    """(width, height, channels, pixels or None): PGM or PNG, as roomba_sim accepts them."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] == b"\x89PNG\r\n\x1a\n":
        return read_png(data)
    if data[:1] == b"P":
        return read_pgm(data)
    raise ValueError("%s: not a PGM or PNG image" % path)


def known_columns_and_rows(info, width, height, channels, pixels):
    """The first and last image column and row holding a free or occupied cell (row 0 at the
    top), or None when every cell is unknown."""
    negate = bool(info.get("negate", 0))
    occupied = float(info.get("occupied_thresh", 0.65))
    free = float(info.get("free_thresh", 0.196))
    known = bytearray(256 * channels)  # per sum of a pixel's channels: free or occupied?
    for total in range(len(known)):
        average = total / channels
        occupancy = (average if negate else 255.0 - average) / 255.0
        known[total] = occupancy > occupied or occupancy < free
    if channels == 1:
        table = bytes(known[:256])
        flags = pixels.translate(table)
    else:
        flags = bytes(known[sum(pixels[k:k + channels])]
                      for k in range(0, width * height * channels, channels))
    rows = [j for j in range(height) if any(flags[j * width:(j + 1) * width])]
    if not rows:
        return None
    columns = bytearray(width)
    for j in range(rows[0], rows[-1] + 1):
        line = flags[j * width:(j + 1) * width]
        columns = bytearray(a | b for a, b in zip(columns, line)) if any(line) else columns
    used = [i for i in range(width) if columns[i]]
    return used[0], used[-1], rows[0], rows[-1]


def framed_region(info, image, start):
    """(x0, y0, w, h): the part of the map to frame, in metres."""
    width, height, channels, pixels = image
    resolution = float(info["resolution"])
    x0, y0 = float(info["origin"][0]), float(info["origin"][1])
    bounds = known_columns_and_rows(info, width, height, channels, pixels) if pixels else None
    if bounds is None:
        return x0, y0, width * resolution, height * resolution
    first_col, last_col, top_row, bottom_row = bounds
    left = min(x0 + first_col * resolution, start[0]) - MARGIN
    right = max(x0 + (last_col + 1) * resolution, start[0]) + MARGIN
    bottom = min(y0 + (height - 1 - bottom_row) * resolution, start[1]) - MARGIN
    top = max(y0 + (height - top_row) * resolution, start[1]) + MARGIN
    return left, bottom, right - left, top - bottom


def lay_grid(config, x0, y0, w, h):
    """The 1 m grid over the region, its lines on whole metres."""
    for display in config["Visualization Manager"]["Displays"]:
        if display.get("Class") == "rviz/Grid" and display.get("Cell Size", 1) == 1:
            left, bottom = math.floor(x0), math.floor(y0)
            cells = max(math.ceil(x0 + w) - left, math.ceil(y0 + h) - bottom, 1)
            display["Plane Cell Count"] = cells
            display["Offset"]["X"] = left + cells / 2
            display["Offset"]["Y"] = bottom + cells / 2


def main():
    base, out, map_yaml = sys.argv[1:4]
    start = (0.0, 0.0)
    if len(sys.argv) > 4:
        start = tuple(float(v) for v in sys.argv[4].split(",")[:2])
    with open(map_yaml, encoding="utf-8") as f:
        info = yaml.safe_load(f)
    image = read_image(os.path.join(os.path.dirname(map_yaml), info["image"]))
    x0, y0, w, h = framed_region(info, image, start)
    with open(base, encoding="utf-8") as f:
        config = yaml.safe_load(f)
    view = config["Visualization Manager"]["Views"]["Current"]
    (view["X"], view["Y"]), view["Scale"] = view_centre_and_scale(x0, y0, w, h, start)
    lay_grid(config, x0, y0, w, h)
    with open(out, "w", encoding="utf-8") as f:
        yaml.safe_dump(config, f, default_flow_style=False)


if __name__ == "__main__":
    main()
