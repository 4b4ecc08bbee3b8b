#!/usr/bin/env python3
"""Exits 0 once /odom shows the robot's pose changing (position or heading) within --timeout wall
seconds, 1 otherwise. A fresh process per check: it registers with whichever master runs now."""
import argparse
import sys
import time

import rospy
from nav_msgs.msg import Odometry

parser = argparse.ArgumentParser()
parser.add_argument("--timeout", type=float, default=5.0)
args = parser.parse_args()

poses = []


def on_odom(msg):
    p, q = msg.pose.pose.position, msg.pose.pose.orientation
    poses.append((p.x, p.y, q.z, q.w))


rospy.init_node("odom_moving_probe", anonymous=True, disable_signals=True)
rospy.Subscriber("/odom", Odometry, on_odom, queue_size=100)
deadline = time.time() + args.timeout
while time.time() < deadline:
    if len(poses) >= 2 and any(abs(a - b) > 1e-6 for a, b in zip(poses[0], poses[-1])):
        print("moving: %d /odom messages, from (%.3f, %.3f) to (%.3f, %.3f)"
              % (len(poses), poses[0][0], poses[0][1], poses[-1][0], poses[-1][1]))
        sys.exit(0)
    time.sleep(0.05)
print("not moving: %d /odom messages in %.1f s" % (len(poses), args.timeout))
sys.exit(1)
