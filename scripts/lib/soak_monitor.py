#!/usr/bin/env python3
"""The checks of scripts/soak; prints one summary line and exits 0 (PASS) or 1 (FAIL).

drive:   watches /odom until --hours of robot time (header stamps) have passed: the robot's disc
         never leaves the room, the pose never stays unchanged for more than 10 s of robot time.
planner: sends a steady stream of mixed good and bad plan_path requests for --wall seconds: good
         ones must be answered success: true, bad ones success: false with a message.
navigate: random free goals one after another through move_base's action (roomba_bt with the
         navigation tree) for --hours of robot time: every goal ends, the bumper is never pressed,
         the robot never stands still for more than 10 s of robot time while a goal is active.
Both:    the watched processes (--pid NAME=PID) stay alive, and none grows its resident memory by
         more than 10 % between the end of the warm-up (first 10 % of the run) and the end.
"""
import argparse
import math
import os
import random
import sys
import threading
import time

import rospy
import yaml

MAX_STUCK = 10.0  # s of robot time
MAX_GROWTH = 0.10


def rss_kb(pid):
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


class Processes:
    def __init__(self, specs):
        self.pids = {}
        for spec in specs:
            name, pid = spec.split("=")
            self.pids[name] = int(pid)
        self.base = {}

    def dead(self):
        return [n for n, p in self.pids.items() if rss_kb(p) is None]

    def mark_base(self):
        self.base = {n: rss_kb(p) for n, p in self.pids.items()}

    def growth(self):
        out = {}
        for n, p in self.pids.items():
            now, base = rss_kb(p), self.base.get(n)
            if now is not None and base:
                out[n] = (now - base) / base
        return out


def drive(args, procs):
    from nav_msgs.msg import Odometry
    with open(args.world) as f:
        world = yaml.safe_load(f)
    width, height = world["room"]["width"], world["room"]["height"]
    r = world["robot"]["radius"]
    tol = 1e-6
    s = {"t0": None, "t": 0.0, "last": None, "changed": None, "stuck": 0.0, "outside": 0,
         "n": 0, "worst": None, "wall0": None}
    lock = threading.Lock()

    def on_odom(msg):
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        t = msg.header.stamp.to_sec()
        pose = (p.x, p.y, q.z, q.w)
        with lock:
            if s["last"] is not None and s["t0"] is None and pose != s["last"]:
                s["t0"] = s["changed"] = t  # the run starts when the robot first moves
                s["wall0"] = time.time()
            s["t"], s["n"] = t, s["n"] + 1
            if not (r - tol <= p.x <= width - r + tol and r - tol <= p.y <= height - r + tol):
                s["outside"] += 1
                s["worst"] = (p.x, p.y)
            if s["t0"] is not None:
                if any(abs(a - b) > 1e-9 for a, b in zip(pose, s["last"])):
                    s["changed"] = t
                s["stuck"] = max(s["stuck"], t - s["changed"])
            s["last"] = pose

    rospy.Subscriber("/odom", Odometry, on_odom, queue_size=1, tcp_nodelay=True)
    goal = args.hours * 3600.0
    wall0 = time.time()
    while time.time() - wall0 < args.wall_limit and not procs.dead():
        if s["wall0"] is None and time.time() - wall0 > 60:
            break  # never moved
        with lock:
            done = s["t"] - s["t0"] if s["t0"] is not None else 0.0
        # Memory baseline: after 10 % of the run and at least 2 s of wall time of driving.
        started = s.get("wall0")
        if not procs.base and done >= 0.1 * goal and started and time.time() - started >= 2:
            procs.mark_base()
        if done >= goal:
            break
        time.sleep(0.2)
    wall = time.time() - (s["wall0"] or wall0)
    with lock:
        done = s["t"] - s["t0"] if s["t0"] is not None else 0.0
        stuck, outside, n = s["stuck"], s["outside"], s["n"]
    dead = procs.dead()
    growth = procs.growth()
    ok = (done >= goal and outside == 0 and stuck <= MAX_STUCK and not dead and
          all(g <= MAX_GROWTH for g in growth.values()))
    print("soak %s: %.2f h robot time in %.0f s wall (rtf %.0f), %d /odom samples, left the room %d"
          ", longest stuck %.1f s, memory %s, crashes %d: %s"
          % (args.name, done / 3600.0, wall, done / wall if wall else 0, n, outside, stuck,
             " ".join("%s %+.1f %%" % (k, 100 * v) for k, v in sorted(growth.items())) or "?",
             len(dead), "PASS" if ok else "FAIL"))
    return ok


def free_goal(rng, world, clearance):
    """A random pose where the robot's disc (plus clearance) touches no wall or furniture."""
    width, height = world["room"]["width"], world["room"]["height"]
    reach = world["robot"]["radius"] + clearance
    furniture = world.get("furniture") or {}
    while True:
        x, y = rng.uniform(reach, width - reach), rng.uniform(reach, height - reach)
        if any(math.hypot(x - c["x"], y - c["y"]) < c["radius"] + reach
               for c in furniture.get("circles") or []):
            continue
        if any(math.hypot(max(b["min_x"] - x, 0, x - b["max_x"]), max(b["min_y"] - y, 0, y - b["max_y"]))
               < reach for b in furniture.get("rectangles") or []):
            continue
        return x, y, rng.uniform(-math.pi, math.pi)


def navigate(args, procs):
    """Goals one after another through move_base's action for --hours of robot time: every goal
    ends (reached or aborted with a reason), the bumper is never pressed, the robot is never still
    for more than MAX_STUCK s of robot time while a goal is active."""
    import actionlib
    from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
    from nav_msgs.msg import Odometry
    from roomba_rrt.msg import Bumper
    with open(args.world) as f:
        world = yaml.safe_load(f)
    s = {"t": 0.0, "t0": None, "last": None, "changed": None, "stuck": 0.0, "presses": 0,
         "pressed": False, "active": False}
    lock = threading.Lock()

    def on_odom(msg):
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        pose, t = (p.x, p.y, q.z, q.w), msg.header.stamp.to_sec()
        with lock:
            if s["t0"] is None:
                s["t0"] = s["changed"] = t
            s["t"] = t
            if s["last"] is None or any(abs(a - b) > 1e-9 for a, b in zip(pose, s["last"])):
                s["changed"] = t
            if s["active"]:
                s["stuck"] = max(s["stuck"], t - s["changed"])
            s["last"] = pose

    def on_bumper(msg):
        with lock:
            if msg.pressed and not s["pressed"]:
                s["presses"] += 1
            s["pressed"] = msg.pressed

    rospy.Subscriber("/odom", Odometry, on_odom, queue_size=1, tcp_nodelay=True)
    rospy.Subscriber("/bumper", Bumper, on_bumper, queue_size=1000, tcp_nodelay=True)
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    if not client.wait_for_server(rospy.Duration(30)):
        print("soak %s: no move_base action server: FAIL" % args.name)
        return False
    rng = random.Random(7)
    goal_time = args.hours * 3600.0
    counts = {"reached": 0, "aborted": 0, "unfinished": 0}
    wall0 = time.time()
    while time.time() - wall0 < args.wall_limit and not procs.dead():
        with lock:
            done = s["t"] - s["t0"] if s["t0"] is not None else 0.0
            s["changed"] = s["t"]  # a new goal: the robot may stand while it plans
            s["active"] = True
        if not procs.base and done >= 0.1 * goal_time:
            procs.mark_base()
        if done >= goal_time:
            break
        x, y, theta = free_goal(rng, world, 0.06)
        goal = MoveBaseGoal()
        goal.target_pose.header.frame_id = "map"
        goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = x, y
        goal.target_pose.pose.orientation.z = math.sin(theta / 2)
        goal.target_pose.pose.orientation.w = math.cos(theta / 2)
        client.send_goal(goal)
        # rospy waits in ROS time, the simulator's: a goal gets --goal-timeout s of robot time.
        if not client.wait_for_result(rospy.Duration(args.goal_timeout)):
            counts["unfinished"] += 1
            client.cancel_goal()
        elif client.get_state() == actionlib.GoalStatus.SUCCEEDED:
            counts["reached"] += 1
        else:
            counts["aborted"] += 1
        with lock:
            s["active"] = False
    wall = time.time() - wall0
    with lock:
        done = s["t"] - s["t0"] if s["t0"] is not None else 0.0
        stuck, presses = s["stuck"], s["presses"]
    dead = procs.dead()
    growth = procs.growth()
    ok = (done >= goal_time and presses == 0 and stuck <= MAX_STUCK and not dead and
          counts["unfinished"] == 0 and all(g <= MAX_GROWTH for g in growth.values()))
    print("soak %s: %.2f h robot time in %.0f s wall, goals %s, bumper presses %d, longest still "
          "%.1f s, memory %s, crashes %d: %s"
          % (args.name, done / 3600.0, wall, ", ".join("%s %d" % kv for kv in counts.items()),
             presses, stuck,
             " ".join("%s %+.1f %%" % (k, 100 * v) for k, v in sorted(growth.items())) or "?",
             len(dead), "PASS" if ok else "FAIL"))
    return ok


def requests(rng):
    """(request fields, expect success)"""
    from geometry_msgs.msg import Point
    from roomba_rrt.msg import CircleObstacle
    algorithm = rng.choice(["rrt", "rrt_connect", "rrt_star"])
    kind = rng.randrange(10)
    if kind < 5:  # good: a lab scenario with some options
        return dict(scenario=rng.choice("abcd"), algorithm=algorithm, seed=rng.randrange(1, 10**6),
                    max_iterations=20000, smooth=rng.random() < 0.5,
                    collision_check=rng.choice(["points", "segments"])), True
    if kind == 5:  # good: a random free problem in the default bounds
        return dict(start=Point(1, 1, 0), goal=Point(rng.uniform(2, 9), rng.uniform(2, 9), 0),
                    algorithm=algorithm, max_iterations=20000), True
    bad = [dict(scenario="zz"), dict(step=-1.0), dict(step=float("nan")),
           dict(goal_bias=2.0), dict(max_iterations=10**9), dict(algorithm="dijkstra"),
           dict(collision_check="voxels"), dict(start=Point(float("inf"), 1, 0)),
           dict(obstacles=[CircleObstacle(Point(5, 5, 0), -1.0)]),
           dict(x_min=5.0, x_max=1.0, y_min=0.0, y_max=10.0)]
    return rng.choice(bad), False


def planner(args, procs):
    from roomba_rrt.srv import PlanPath, PlanPathRequest
    rospy.wait_for_service("/rrt_planner/plan_path", timeout=30)
    call = rospy.ServiceProxy("/rrt_planner/plan_path", PlanPath, persistent=True)
    rng = random.Random(11)
    counts = {"good ok": 0, "good failed": 0, "bad refused": 0, "bad accepted": 0, "errors": 0}
    wall0 = time.time()
    slowest = 0.0
    while time.time() - wall0 < args.wall and not procs.dead():
        if not procs.base and time.time() - wall0 >= 0.1 * args.wall:
            procs.mark_base()
        fields, good = requests(rng)
        t = time.time()
        try:
            response = call(PlanPathRequest(**fields))
        except (rospy.ServiceException, rospy.ROSException) as e:
            counts["errors"] += 1
            call = rospy.ServiceProxy("/rrt_planner/plan_path", PlanPath, persistent=True)
            continue
        slowest = max(slowest, time.time() - t)
        if good:
            counts["good ok" if response.success else "good failed"] += 1
        else:
            counts["bad refused" if not response.success and response.message else
                   "bad accepted"] += 1
    wall = time.time() - wall0
    dead = procs.dead()
    growth = procs.growth()
    ok = (not dead and counts["good failed"] == 0 and counts["bad accepted"] == 0 and
          counts["errors"] == 0 and all(g <= MAX_GROWTH for g in growth.values()))
    print("soak %s: %d requests in %.0f s wall (%s), slowest %.2f s, memory %s, crashes %d: %s"
          % (args.name, sum(counts.values()), wall,
             ", ".join("%s %d" % kv for kv in counts.items()), slowest,
             " ".join("%s %+.1f %%" % (k, 100 * v) for k, v in sorted(growth.items())) or "?",
             len(dead), "PASS" if ok else "FAIL"))
    return ok


def clean(args, procs):
    """One cleaning run (roomba_bt with the cleaning tree): waits until ~coverage_path is empty
    after the plan was published (the floor done), ~state reads Idle and ~coverage_report came,
    then reads the simulator's ~coverage. Passes when it reaches --min-coverage and ~state never
    read Idle before the end (an Idle followed by another state once the plan was out)."""
    from nav_msgs.msg import Path
    from roomba_rrt.msg import Bumper, CoverageReport
    from std_msgs.msg import Float32, String
    s = {"planned": False, "done": None, "coverage": None, "presses": 0, "pressed": False,
         "early_idle": 0, "state": "", "active": False, "report": None}
    lock = threading.Lock()

    def on_path(msg):
        with lock:
            if msg.poses:
                s["planned"] = True
            elif s["planned"] and s["done"] is None:
                s["done"] = rospy.get_time()

    def on_state(msg):
        # An Idle the robot drives on from was early (the topics ~state and ~coverage_path are
        # separate connections: the last Idle may come in before the empty path).
        with lock:
            if s["state"] == "Idle" and msg.data != "Idle" and s["active"]:
                s["early_idle"] += 1
            s["active"] = s["active"] or msg.data != "Idle"
            s["state"] = msg.data

    def on_coverage(msg):
        with lock:
            s["coverage"] = msg.data

    def on_bumper(msg):
        with lock:
            if msg.pressed and not s["pressed"]:
                s["presses"] += 1
            s["pressed"] = msg.pressed

    def on_report(msg):
        where = ", ".join("(%.2f, %.2f)-(%.2f, %.2f)" % (a.x, a.y, b.x, b.y)
                          for a, b in zip(msg.skipped_from, msg.skipped_to))
        with lock:
            s["report"] = ("swept %.1f %%, %d bumps, %d rows given up%s, latency up to %.3f s, "
                           "speeds down to %.0f %%"
                           % (100.0 * msg.coverage, msg.bumps, msg.skipped_rows,
                              (" " + where) if where else "", msg.latency,
                              100.0 * msg.slowest_speed_scale))

    rospy.Subscriber("/roomba_bt/coverage_path", Path, on_path, queue_size=100)
    rospy.Subscriber("/roomba_bt/state", String, on_state, queue_size=1000)
    rospy.Subscriber("/roomba_sim/coverage", Float32, on_coverage, queue_size=1)
    rospy.Subscriber("/bumper", Bumper, on_bumper, queue_size=1000, tcp_nodelay=True)
    rospy.Subscriber("/roomba_bt/coverage_report", CoverageReport, on_report, queue_size=1)
    wall0 = time.time()
    finished = False
    while time.time() - wall0 < args.wall_limit and not procs.dead():
        with lock:
            if s["done"] is not None and s["state"] == "Idle" and s["report"] is not None:
                finished = True
                break
        time.sleep(0.2)
    if finished:  # the simulator's next ~coverage (2 Hz of wall time) counts the last rows
        with lock:
            s["coverage"] = None
        deadline = time.time() + 5.0
        while time.time() < deadline:
            with lock:
                if s["coverage"] is not None:
                    break
            time.sleep(0.1)
    wall = time.time() - wall0
    with lock:
        coverage = s["coverage"] if s["coverage"] is not None else 0.0
        done, presses, early, report = s["done"], s["presses"], s["early_idle"], s["report"]
    dead = procs.dead()
    ok = finished and coverage >= args.min_coverage and early == 0 and not dead
    print("soak %s: coverage %.1f %% at %s s robot time, %.0f s wall, bumps %d, Idle before the "
          "end %d, crashes %d%s: %s"
          % (args.name, 100.0 * coverage, "%.0f" % done if done is not None else "never",
             wall, presses, early, len(dead),
             ("; report: " + report) if report else "",
             "PASS" if ok else "FAIL"))
    return ok


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=["drive", "planner", "navigate", "clean"])
    parser.add_argument("--name", required=True)
    parser.add_argument("--hours", type=float, default=1.0)
    parser.add_argument("--wall", type=float, default=60.0)
    parser.add_argument("--wall-limit", type=float, default=3600.0)
    parser.add_argument("--world")
    parser.add_argument("--pid", action="append", default=[])
    parser.add_argument("--min-coverage", type=float, default=0.95)
    parser.add_argument("--goal-timeout", type=float, default=300.0)  # s of robot time
    args = parser.parse_args()
    rospy.init_node("soak_monitor", anonymous=True, disable_signals=True)
    procs = Processes(args.pid)
    modes = {"drive": drive, "planner": planner, "navigate": navigate, "clean": clean}
    ok = modes[args.mode](args, procs)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
