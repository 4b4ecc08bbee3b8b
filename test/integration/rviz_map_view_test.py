#!/usr/bin/env python3
"""scripts/run's rviz view on a map (scripts/lib/rviz_map_view.py), as scripts/run calls it: a
map small enough is shown whole and centred; on a larger one (Nav2's 100 m benchmark map) the
robot and the cleaning rows are still visible: the view is zoomed in around where the robot
starts, and stays inside the map."""
import os
import subprocess
import sys
import tempfile
import unittest

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "lib", "rviz_map_view.py")
BASE = os.path.join(ROOT, "config", "roomba_rrt.rviz")
HALF_WIDTH_PX, HALF_HEIGHT_PX = 300, 260  # half the view the script frames, in pixels


class RvizMapViewTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def view(self, cells, resolution, origin, pose=None):
        """The view (X, Y, Scale) for a map of cells × cells at `resolution` with `origin`."""
        image = os.path.join(self.dir.name, "map.pgm")
        with open(image, "wb") as f:  # only the header is read
            f.write(b"P5\n# a test map\n%d %d\n255\n" % (cells, cells))
        map_yaml = os.path.join(self.dir.name, "map.yaml")
        with open(map_yaml, "w", encoding="utf-8") as f:
            yaml.safe_dump({"image": "map.pgm", "resolution": resolution,
                            "origin": [origin[0], origin[1], 0.0], "negate": 0,
                            "occupied_thresh": 0.65, "free_thresh": 0.196}, f)
        out = os.path.join(self.dir.name, "out.rviz")
        args = [sys.executable, SCRIPT, BASE, out, map_yaml] + ([pose] if pose else [])
        subprocess.run(args, check=True)
        with open(out, encoding="utf-8") as f:
            view = yaml.safe_load(f)["Visualization Manager"]["Views"]["Current"]
        return view["X"], view["Y"], view["Scale"]

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


if __name__ == "__main__":
    unittest.main()
