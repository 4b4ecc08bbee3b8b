#!/usr/bin/env python3
"""coverage_planner's ~plan_coverage through a real master (test/coverage/plan_coverage.test)."""
import math
import threading
import time
import unittest

import rospy
import rosunit
from nav_msgs.msg import OccupancyGrid, Path
from roomba_rrt.srv import PlanCoverage, PlanCoverageRequest
from visualization_msgs.msg import MarkerArray

SERVICE = "/coverage_planner/plan_coverage"


def request(x, y, **fields):
    r = PlanCoverageRequest()
    r.start.x, r.start.y = x, y
    for name, value in fields.items():
        setattr(r, name, value)
    return r


def length(path):
    points = [(p.pose.position.x, p.pose.position.y) for p in path.poses]
    return sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:]))


class PlanCoverageTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("plan_coverage_test")
        rospy.wait_for_service(SERVICE, timeout=30)
        cls.plan = rospy.ServiceProxy(SERVICE, PlanCoverage)
        cls.lock = threading.Lock()
        cls.published = []
        cls.markers = []
        rospy.Subscriber("/coverage_planner/coverage_path", Path, cls.on_path, queue_size=10)
        rospy.Subscriber("/coverage_planner/coverage_markers", MarkerArray, cls.on_markers,
                         queue_size=10)

    @classmethod
    def on_path(cls, msg):
        with cls.lock:
            cls.published.append(msg)

    @classmethod
    def on_markers(cls, msg):
        with cls.lock:
            cls.markers.append(msg)

    def test_the_room_is_planned_and_the_plan_latched_for_rviz(self):
        r = self.plan(request(1.0, 1.0))
        self.assertTrue(r.success, r.message)
        self.assertEqual(r.path.header.frame_id, "map")
        self.assertGreater(len(r.row_starts), 10)
        self.assertAlmostEqual(length(r.path), r.length, places=6)
        first = r.path.poses[0].pose.position
        self.assertEqual((first.x, first.y), (1.0, 1.0))
        for pose in r.path.poses:  # the furnished room: 6.4 m x 4.8 m, the disc inside its walls
            self.assertTrue(0.17 <= pose.pose.position.x <= 6.4 - 0.17)
            self.assertTrue(0.17 <= pose.pose.position.y <= 4.8 - 0.17)
        self.assertGreater(r.reachable_area, 25)
        deadline = rospy.get_time() + 10
        while rospy.get_time() < deadline and not rospy.is_shutdown():
            with self.lock:
                if any(len(p.poses) == len(r.path.poses) for p in self.published):
                    break
            rospy.sleep(0.1)
        with self.lock:
            self.assertTrue(any(len(p.poses) == len(r.path.poses) for p in self.published))
        # rviz's markers: this plan's rows, a line from each row start to the next pose.
        expected = [r.path.poses[k].pose.position for k in r.row_starts]

        def drawn():
            with self.lock:
                return any(m.ns == "rows" and m.points[::2] == expected
                           for array in self.markers for m in array.markers)
        deadline = rospy.get_time() + 10
        while rospy.get_time() < deadline and not drawn() and not rospy.is_shutdown():
            rospy.sleep(0.1)
        self.assertTrue(drawn())

    def test_the_map_on_slash_map_is_planned(self):
        r = self.plan_on_the_map()
        self.assertTrue(r.success, r.message)
        # The apartment's rooms lie on both sides of x = 0; the furnished room only at x >= 0.
        self.assertTrue(any(p.pose.position.x < -1.0 for p in r.path.poses))
        self.assertGreater(r.unreachable_area, 0)

    def plan_on_the_map(self):
        r = self.plan(request(0.0, 0.0, world="map"))
        deadline = rospy.get_time() + 20
        while r.message.startswith("world: no map") and rospy.get_time() < deadline:
            rospy.sleep(0.2)  # roomba_sim has not published it yet
            r = self.plan(request(0.0, 0.0, world="map"))
        return r

    def test_unusable_maps_on_slash_map_never_replace_the_one_in_force(self):
        # Issue 44, item 3: a resolution of 1e-30 replaced the map, and every plan then failed.
        self.assertTrue(self.plan_on_the_map().success)
        publisher = rospy.Publisher("/map", OccupancyGrid, queue_size=10)
        deadline = rospy.get_time() + 10
        while publisher.get_num_connections() == 0 and rospy.get_time() < deadline:
            rospy.sleep(0.1)
        self.assertGreater(publisher.get_num_connections(), 0)
        for resolution, roll in [(1e-30, 0.0), (3e38, 0.0), (0.05, 0.5)]:
            bad = OccupancyGrid()
            bad.header.frame_id = "map"
            bad.info.resolution = resolution
            bad.info.width, bad.info.height = 3, 2
            bad.info.origin.orientation.x = math.sin(roll / 2)
            bad.info.origin.orientation.w = math.cos(roll / 2)
            bad.data = [0] * 6
            publisher.publish(bad)
        time.sleep(1.0)  # wall time for the node to take (and refuse) them
        r = self.plan(request(0.0, 0.0, world="map"))
        self.assertTrue(r.success, r.message)
        self.assertTrue(any(p.pose.position.x < -1.0 for p in r.path.poses))  # the apartment
        publisher.unregister()

    def test_bad_requests_name_their_field_and_the_node_plans_on(self):
        for bad, field in [(request(1.3, 3.5), "start"),  # in the round table
                           (request(float("nan"), 1.0), "start.x"),
                           (request(1.0, 1.0, world="moon"), "world"),
                           (request(1.0, 1.0, x_max=1e308, y_max=1.0), "x_min..y_max"),
                           (request(1.0, 1.0, swath=5.0), "swath"),
                           (request(1.0, 1.0, robot_radius=-1.0), "robot_radius")]:
            r = self.plan(bad)
            self.assertFalse(r.success, field)
            self.assertTrue(r.message.startswith(field + ": "), r.message)
            self.assertEqual(len(r.path.poses), 0)
        self.assertTrue(self.plan(request(1.0, 1.0)).success)


if __name__ == "__main__":
    rosunit.unitrun("roomba_rrt", "plan_coverage", PlanCoverageTest)
