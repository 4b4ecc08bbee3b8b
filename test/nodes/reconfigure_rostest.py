#!/usr/bin/env python3
"""dynamic_reconfigure on the package's nodes, as `dynparam set` and rqt_reconfigure use it."""
import math
import threading
import time
import unittest

import rospy
import rosunit
from dynamic_reconfigure.client import Client
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from roomba_rrt.srv import PlanPath
from std_msgs.msg import String


def longest_edge(path):
    pts = [(p.pose.position.x, p.pose.position.y) for p in path.poses]
    return max(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(pts, pts[1:]))


class Reconfigure(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("reconfigure_test")
        cls.lock = threading.Lock()
        cls.commands, cls.states, cls.speeds = [], [], []
        rospy.Subscriber("/cmd_vel", Twist, cls.on_cmd, queue_size=1000)
        rospy.Subscriber("/roomba_fsm/state", String, cls.on_state, queue_size=100)
        rospy.Subscriber("/odom", Odometry, cls.on_odom, queue_size=1000)

    @classmethod
    def on_cmd(cls, msg):
        with cls.lock:
            cls.commands.append((time.time(), msg.linear.x))

    @classmethod
    def on_state(cls, msg):
        with cls.lock:
            cls.states.append((time.time(), msg.data))

    @classmethod
    def on_odom(cls, msg):
        with cls.lock:
            cls.speeds.append((time.time(), msg.twist.twist.linear.x))

    def client(self, node):
        return Client(node, timeout=30)

    def test_planner_step_changes_the_plans_and_bad_values_are_clamped_or_refused(self):
        rospy.wait_for_service("/rrt_planner/plan_path", 30)
        plan = rospy.ServiceProxy("/rrt_planner/plan_path", PlanPath)
        before = plan(scenario="a")
        self.assertTrue(before.success, before.message)
        self.assertLessEqual(longest_edge(before.path), 0.2 + 1e-9)  # the lab's step

        planner = self.client("/rrt_planner")
        config = planner.update_configuration({"step": 0.6, "algorithm": "rrt_connect"})
        self.assertAlmostEqual(config["step"], 0.6)
        after = plan(scenario="a")
        self.assertTrue(after.success, after.message)
        self.assertGreater(longest_edge(after.path), 0.2 + 1e-6)
        self.assertLessEqual(longest_edge(after.path), 0.6 + 1e-9)
        self.assertEqual(planner.get_configuration(timeout=10)["algorithm"], "rrt_connect")

        # dynamic_reconfigure clamps to the .cfg's range (the range the planner validates) ...
        self.assertAlmostEqual(planner.update_configuration({"goal_bias": 7.0})["goal_bias"], 1.0)
        # ... and the node refuses what its rules forbid, keeping the values in force.
        kept = planner.update_configuration({"max_planning_time": 0.0})
        self.assertAlmostEqual(kept["max_planning_time"], 5.0)
        self.assertAlmostEqual(planner.get_configuration(timeout=10)["max_planning_time"], 5.0)
        self.assertAlmostEqual(rospy.get_param("/rrt_planner/step"), 0.6)  # written back
        planner.update_configuration({"goal_bias": 0.1, "step": 0.2, "algorithm": "rrt"})
        self.assertTrue(plan(scenario="a").success)  # still serving

    def test_behaviour_speed_takes_effect_when_the_next_motion_starts(self):
        fsm = self.client("/roomba_fsm")
        self.assertAlmostEqual(fsm.get_configuration(timeout=10)["forward_speed"], 0.5)
        deadline = time.time() + 30
        while time.time() < deadline:  # wait until it drives forwards at the lab's speed
            with self.lock:
                if self.commands and abs(self.commands[-1][1] - 0.5) < 1e-9:
                    break
            time.sleep(0.01)
        t_set = time.time()
        self.assertAlmostEqual(fsm.update_configuration({"forward_speed": 0.3})["forward_speed"],
                               0.3)
        deadline = time.time() + 60
        first_new = None
        while time.time() < deadline and first_new is None:
            with self.lock:
                first_new = next((t for t, v in self.commands if t > t_set and
                                  abs(v - 0.3) < 1e-9), None)
            time.sleep(0.05)
        self.assertIsNotNone(first_new, "forward_speed 0.3 never seen on /cmd_vel")
        # ~state and /cmd_vel of one tick go out together but arrive on two connections: allow
        # 50 ms between them (a tick is 17 ms of robot time, 3 ms of wall time here).
        time.sleep(0.1)
        with self.lock:
            changes = [t for t, _ in self.states if t_set < t <= first_new + 0.05]
            timeline = [(round(t - t_set, 3), s) for t, s in self.states[-5:]]
        self.assertTrue(changes, "0.3 appeared at %.3f s, before a new motion started (a "
                        "mid-motion change); states %s" % (first_new - t_set, timeline))
        # An open end is refused and the value in force kept; the node keeps commanding.
        self.assertAlmostEqual(fsm.update_configuration({"forward_speed": 0.0})["forward_speed"],
                               0.3)
        n = len(self.commands)
        time.sleep(1.0)
        self.assertGreater(len(self.commands), n)

    def test_simulator_speed_limit_applies_from_the_next_step(self):
        sim = self.client("/roomba_sim")
        self.assertAlmostEqual(sim.update_configuration({"max_linear_speed": 0.25})
                               ["max_linear_speed"], 0.25)
        t_set = time.time() + 0.5
        time.sleep(3.0)
        with self.lock:
            later = [abs(v) for t, v in self.speeds if t > t_set]
        self.assertTrue(later)
        self.assertLessEqual(max(later), 0.25 + 1e-9)
        # 20 m/s would let the robot pass its radius in one step: refused, limit kept.
        self.assertAlmostEqual(sim.update_configuration({"max_linear_speed": 20.0})
                               ["max_linear_speed"], 0.25)
        sim.update_configuration({"max_linear_speed": 1.0})

    def test_navigation_follower_limits_are_served_on_follower(self):
        follower = self.client("/nav/roomba_bt/follower")
        config = follower.get_configuration(timeout=10)
        self.assertAlmostEqual(config["max_linear_speed"], 0.3)
        self.assertAlmostEqual(follower.update_configuration({"max_linear_speed": 0.2})
                               ["max_linear_speed"], 0.2)
        self.assertAlmostEqual(rospy.get_param("/nav/roomba_bt/follower/max_linear_speed"), 0.2)


if __name__ == "__main__":
    rosunit.unitrun("roomba_rrt", "reconfigure", Reconfigure)
