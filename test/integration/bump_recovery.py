#!/usr/bin/env python3
"""Exits 0 once /odom and /bumper show a behaviour at work within --timeout wall seconds: the robot
drives (its position changes), its bumper is pressed, and afterwards it gets away from where the
bump happened (bumper released, position more than --away metres from the bump); 1 otherwise,
saying which of the three did not happen."""
import argparse
import math
import sys
import threading
import time

import rospy
from nav_msgs.msg import Odometry
from roomba_rrt.msg import Bumper

parser = argparse.ArgumentParser()
parser.add_argument("--timeout", type=float, default=30.0)
parser.add_argument("--away", type=float, default=0.1)
args = parser.parse_args()

lock = threading.Lock()
seen = {"first": None, "last": None, "moved": False, "bump_at": None, "pressed": False,
        "recovered_at": None, "odom": 0, "bumper": 0}


def on_odom(msg):
    p = msg.pose.pose.position
    with lock:
        seen["odom"] += 1
        if seen["first"] is None:
            seen["first"] = (p.x, p.y)
        seen["last"] = (p.x, p.y)
        if math.hypot(p.x - seen["first"][0], p.y - seen["first"][1]) > 0.05:
            seen["moved"] = True
        bump = seen["bump_at"]
        if (bump and not seen["pressed"] and seen["recovered_at"] is None
                and math.hypot(p.x - bump[0], p.y - bump[1]) > args.away):
            seen["recovered_at"] = (p.x, p.y)


def on_bumper(msg):
    with lock:
        seen["bumper"] += 1
        seen["pressed"] = msg.pressed
        if msg.pressed and seen["bump_at"] is None and seen["last"] is not None:
            seen["bump_at"] = seen["last"]


rospy.init_node("bump_recovery_probe", anonymous=True, disable_signals=True)
rospy.Subscriber("/odom", Odometry, on_odom, queue_size=1000)
rospy.Subscriber("/bumper", Bumper, on_bumper, queue_size=1000)
deadline = time.time() + args.timeout
while time.time() < deadline:
    with lock:
        if seen["recovered_at"] is not None:
            break
    time.sleep(0.05)
with lock:
    s = dict(seen)
print("%d /odom, %d /bumper received" % (s["odom"], s["bumper"]))
if not s["moved"]:
    print("FAIL: the robot did not drive (%s)" % ("no /odom" if s["first"] is None else
                                                  "stays at (%.2f, %.2f)" % s["first"]))
    sys.exit(1)
print("drives: from (%.2f, %.2f)" % s["first"])
if s["bump_at"] is None:
    print("FAIL: the bumper was never pressed within %.0f s" % args.timeout)
    sys.exit(1)
print("bumps: pressed at (%.2f, %.2f)" % s["bump_at"])
if s["recovered_at"] is None:
    print("FAIL: the robot did not get %.2f m away from the bump (last at (%.2f, %.2f))"
          % ((args.away,) + s["last"]))
    sys.exit(1)
print("recovers: bumper released, at (%.2f, %.2f)" % s["recovered_at"])
