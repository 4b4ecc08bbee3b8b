#!/usr/bin/env python3
"""scripts/run's rviz view on a map (scripts/lib/rviz_map_view.py), as scripts/run calls it: a
map small enough is shown whole and centred; on a larger one (Nav2's 100 m benchmark map) the
robot and the cleaning rows are still visible: the view is zoomed in around where the robot
starts, and stays inside the map. Only the map's known part counts (a map_saver map's unknown
border does not shrink the robot), read from a PGM or a PNG, and the 1 m grid lies over it."""
import math
import os
import struct
import subprocess
import sys
import tempfile
import unittest
import zlib

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "lib", "rviz_map_view.py")
BASE = os.path.join(ROOT, "config", "roomba_rrt.rviz")
HALF_WIDTH_PX, HALF_HEIGHT_PX = 300, 260  # half the view the script frames, in pixels
FREE, WALL, UNKNOWN = 254, 0, 205  # map_saver's grey levels


def room_in_unknown(cells, left, bottom, size):
    """Rows of grey levels (top row first): an unknown square of cells × cells with a walled
    room of size × size cells whose lower left cell is (left, bottom). The room's greys vary
    (free 215..254, walls 0..59), so that a PNG encoder's filters predict from every side."""
    rows = [[UNKNOWN] * cells for _ in range(cells)]
    for j in range(bottom, bottom + size):
        for i in range(left, left + size):
            edge = i in (left, left + size - 1) or j in (bottom, bottom + size - 1)
            shade = (7 * i + 13 * j + i * j) % 40
            rows[cells - 1 - j][i] = WALL + shade + shade // 2 if edge else FREE - shade
    return rows


def pgm(rows):
    return b"P5\n# a test map\n%d %d\n255\n" % (len(rows[0]), len(rows)) + bytes(
        v for row in rows for v in row)


def png(rows, channels):
    """An 8-bit PNG (grey, or RGB with channels 3) whose rows use each of the five filters in
    turn, as encoders mix them."""
    def paeth(a, b, c):
        p = a + b - c
        pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
        return a if pa <= pb and pa <= pc else b if pb <= pc else c

    raw, prior = bytearray(), bytes(len(rows[0]) * channels)
    for j, row in enumerate(rows):
        line = bytes(v for v in row for _ in range(channels))
        kind = j % 5
        out = bytearray([kind])
        for i, x in enumerate(line):
            a = line[i - channels] if i >= channels else 0
            b, c = prior[i], prior[i - channels] if i >= channels else 0
            predictor = [0, a, b, (a + b) >> 1, paeth(a, b, c)][kind]
            out.append((x - predictor) & 255)
        raw += out
        prior = line

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", len(rows[0]), len(rows), 8, 0 if channels == 1 else 2, 0,
                         0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw)) +
            chunk(b"IEND", b""))


class RvizMapViewTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def view(self, cells, resolution, origin, pose=None, image=None, name="map.pgm"):
        """The view (X, Y, Scale) for a map of cells × cells at `resolution` with `origin`:
        `image`'s bytes, or a PGM header without pixels (framed whole)."""
        with open(os.path.join(self.dir.name, name), "wb") as f:
            f.write(image or b"P5\n# a test map\n%d %d\n255\n" % (cells, cells))
        map_yaml = os.path.join(self.dir.name, "map.yaml")
        with open(map_yaml, "w", encoding="utf-8") as f:
            yaml.safe_dump({"image": name, "resolution": resolution,
                            "origin": [origin[0], origin[1], 0.0], "negate": 0,
                            "occupied_thresh": 0.65, "free_thresh": 0.196}, f)
        out = os.path.join(self.dir.name, "out.rviz")
        args = [sys.executable, SCRIPT, BASE, out, map_yaml] + ([pose] if pose else [])
        subprocess.run(args, check=True)
        with open(out, encoding="utf-8") as f:
            self.config = yaml.safe_load(f)["Visualization Manager"]
        view = self.config["Views"]["Current"]
        return view["X"], view["Y"], view["Scale"]

    def grid(self):
        """The 1 m grid's (first line x, first line y, cells) of the last view()."""
        grid = [d for d in self.config["Displays"] if d["Class"] == "rviz/Grid"][0]
        cells, offset = grid["Plane Cell Count"], grid["Offset"]
        return offset["X"] - cells / 2, offset["Y"] - cells / 2, cells

    def assertShows(self, view, x, y):
        cx, cy, scale = view
        self.assertLessEqual(abs(x - cx) * scale, HALF_WIDTH_PX, (x, y, view))
        self.assertLessEqual(abs(y - cy) * scale, HALF_HEIGHT_PX, (x, y, view))

    def test_a_small_map_is_shown_whole_and_centred(self):
        x, y, scale = self.view(200, 0.05, (-2.0, -3.0))  # 10 m
        self.assertAlmostEqual(x, 3.0)
        self.assertAlmostEqual(y, 2.0)
        self.assertAlmostEqual(scale, 52.0)  # 520 pixels for 10 m
        for corner in [(-2, -3), (8, -3), (-2, 7), (8, 7)]:
            self.assertShows((x, y, scale), *corner)

    def test_a_large_map_is_zoomed_in_on_the_robot(self):
        view = self.view(2000, 0.05, (0.0, 0.0), "40,60")  # 100 m, as nav2_bench_100by100_15
        self.assertGreaterEqual(view[2], 20)  # the Roomba (0.34 m) at least 7 pixels wide
        self.assertAlmostEqual(view[0], 40)
        self.assertAlmostEqual(view[1], 60)
        self.assertShows(self.view(2000, 0.05, (0.0, 0.0), "14,14"), 14, 14)

    def test_the_zoomed_view_stays_inside_the_map(self):
        cx, cy, scale = self.view(2000, 0.05, (-50.0, -50.0), "-49,49.5")
        self.assertShows((cx, cy, scale), -49, 49.5)
        self.assertAlmostEqual(cx - HALF_WIDTH_PX / scale, -50.0)  # the left edge on the map's
        self.assertAlmostEqual(cy + HALF_HEIGHT_PX / scale, 50.0)  # the top edge on the map's

    def test_without_a_pose_the_robot_starts_at_the_maps_origin(self):
        view = self.view(2000, 0.05, (-30.0, -20.0))
        self.assertShows(view, 0, 0)
        self.assertAlmostEqual(view[0], 0)
        self.assertAlmostEqual(view[1], 0)

    def test_the_unknown_border_of_a_map_is_left_out(self):
        # A 4 m room in a 20 m unknown image (the turtlebot3 arena in its 19 m map): the room
        # fills the view, where the whole image put it in a fifth of it.
        rows = room_in_unknown(400, 220, 140, 80)  # cells 220..299 × 140..219: (1, -3) to (5, 1)
        view = self.view(400, 0.05, (-10.0, -10.0), "3,-1", pgm(rows))
        self.assertAlmostEqual(view[0], 3.0)
        self.assertAlmostEqual(view[1], -1.0)
        self.assertGreaterEqual(view[2], 100)  # 4.5 m (the room and a margin) in 520 pixels
        for corner in [(1, -3), (5, -3), (1, 1), (5, 1)]:
            self.assertShows(view, *corner)
        # the grid's lines on whole metres, over the room
        x0, y0, cells = self.grid()
        self.assertEqual((x0, y0), (math.floor(x0), math.floor(y0)))
        self.assertLessEqual(x0, 1)
        self.assertLessEqual(y0, -3)
        self.assertGreaterEqual(x0 + cells, 5)
        self.assertGreaterEqual(y0 + cells, 1)
        self.assertLessEqual(cells, 7)

    def test_a_png_map_frames_as_its_pgm(self):
        rows = room_in_unknown(60, 12, 20, 30)
        expected = self.view(60, 0.1, (0.0, 0.0), "2.5,3.5", pgm(rows))
        for channels in (1, 3):
            self.assertEqual(self.view(60, 0.1, (0.0, 0.0), "2.5,3.5", png(rows, channels),
                                       "map.png"), expected, channels)
        self.assertAlmostEqual(expected[0], 2.7)  # cells 12..41 × 20..49: (1.2, 2) to (4.2, 5)
        self.assertAlmostEqual(expected[1], 3.5)

    def test_a_png_decodes_to_the_pgms_greys(self):
        sys.dont_write_bytecode = True  # no __pycache__ in the source tree
        sys.path.insert(0, os.path.dirname(SCRIPT))
        import rviz_map_view  # pylint: disable=import-outside-toplevel
        rows = room_in_unknown(60, 12, 20, 30)
        greys = pgm(rows)[-60 * 60:]
        for channels in (1, 3):
            path = os.path.join(self.dir.name, "map%d.png" % channels)
            with open(path, "wb") as f:
                f.write(png(rows, channels))
            self.assertEqual(rviz_map_view.read_image(path),
                             (60, 60, channels, bytes(v for v in greys for _ in range(channels))))

    def test_the_start_is_in_view_even_in_the_unknown(self):
        rows = room_in_unknown(400, 220, 140, 80)
        self.assertShows(self.view(400, 0.05, (-10.0, -10.0), None, pgm(rows)), 0, 0)

    def test_a_map_without_known_cells_is_framed_whole(self):
        view = self.view(200, 0.05, (-2.0, -3.0), None, pgm([[UNKNOWN] * 200] * 200))
        self.assertAlmostEqual(view[0], 3.0)
        self.assertAlmostEqual(view[1], 2.0)


if __name__ == "__main__":
    unittest.main()
