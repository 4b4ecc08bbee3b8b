#!/usr/bin/env python3
"""Drives roomba_sim with roomba_teleop as a user at a terminal would: roomba_teleop runs on a
pseudo-terminal, the test types keys into it and watches /cmd_vel, /odom and the terminal.
Exits 0 when every check holds, 1 otherwise (each check prints ok/FAIL)."""
import os
import pty
import select
import subprocess
import sys
import time

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

failures = 0
commands, poses = [], []
screen = b""


def check(ok, what):
    global failures
    print(("ok: " if ok else "FAIL: ") + what, flush=True)
    failures += 0 if ok else 1


def last_command_is(v, w):
    return bool(commands) and abs(commands[-1][0] - v) < 1e-9 and abs(commands[-1][1] - w) < 1e-9


def read_screen(fd, seconds):
    """Collects what roomba_teleop prints for `seconds` (the pty master must be drained)."""
    global screen
    deadline = time.time() + seconds
    while time.time() < deadline:
        ready, _, _ = select.select([fd], [], [], 0.05)
        if ready:
            try:
                screen += os.read(fd, 4096)
            except OSError:
                return


def wait_for(predicate, fd, seconds):
    deadline = time.time() + seconds
    while time.time() < deadline:
        if predicate():
            return True
        read_screen(fd, 0.05)
    return predicate()


rospy.init_node("teleop_drive_test", anonymous=True, disable_signals=True)
rospy.Subscriber("/cmd_vel", Twist, lambda m: commands.append((m.linear.x, m.angular.z)))
rospy.Subscriber("/odom", Odometry, lambda m: poses.append(m.pose.pose.position.x))

# Without a terminal it refuses, saying why.
out = subprocess.run(["rosrun", "roomba_rrt", "roomba_teleop"], stdin=subprocess.DEVNULL,
                     capture_output=True, text=True, timeout=20)
check(out.returncode == 1 and "terminal" in out.stdout + out.stderr,
      "without a terminal: exit %d, says it needs one" % out.returncode)

master, slave = pty.openpty()
node = subprocess.Popen(["rosrun", "roomba_rrt", "roomba_teleop"], stdin=slave, stdout=slave,
                        stderr=slave, close_fds=True, start_new_session=True)
os.close(slave)
check(wait_for(lambda: b"w / up arrow" in screen and len(commands) > 0, master, 20),
      "prints its keys and publishes /cmd_vel")
check(wait_for(lambda: len(poses) > 0, master, 10), "roomba_sim publishes /odom")

os.write(master, b"www")
check(wait_for(lambda: last_command_is(0.3, 0.0), master, 3),
      "three presses of w command 0.3 m/s (last /cmd_vel %s)" % (commands[-1],))
x0 = poses[-1]
check(wait_for(lambda: poses[-1] - x0 > 0.15, master, 5), "the robot drives forwards")
check(b"v +0.30 m/s" in screen, "the terminal shows the command")

os.write(master, b"\x1b[D\x1b[D")  # left arrow twice
check(wait_for(lambda: last_command_is(0.3, 0.5), master, 3),
      "two left arrows turn at 0.5 rad/s (last /cmd_vel %s)" % (commands[-1],))
os.write(master, b" ")
check(wait_for(lambda: last_command_is(0.0, 0.0), master, 3), "space stops")

# Full speed ahead into the wall: the terminal shows the bumper pressed.
os.write(master, b"w" * 12)
check(wait_for(lambda: last_command_is(1.0, 0.0), master, 3),
      "presses beyond the limit stay at 1.0 m/s (last /cmd_vel %s)" % (commands[-1],))
check(wait_for(lambda: b"bumper: pressed" in screen, master, 15), "the terminal shows the bump")

# Losing the terminal (window closed, ssh dropped) stops the robot and ends the node.
os.write(master, b"s")
read_screen(master, 0.3)
os.close(master)
try:
    rc = node.wait(timeout=5)
except subprocess.TimeoutExpired:
    node.kill()
    rc = None
check(rc == 0, "a lost terminal ends roomba_teleop (exit %s)" % rc)
time.sleep(0.3)
check(last_command_is(0.0, 0.0), "and its last command is a stop (%s)" % (commands[-1],))
sys.exit(1 if failures else 0)
