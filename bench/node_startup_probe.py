#!/usr/bin/env python3
"""Start-up cost of the nodes: process start to first answer, and the shared libraries loaded.

    bench/node_startup_probe.py BIN_DIR CONFIG_DIR [--runs 10]

Needs a running master (ROS_MASTER_URI). For each node it starts the process RUNS times and takes
the median wall time from the fork to the node's first answer, as a user's client sees it:
  rrt_planner        the first ~plan_path (scenario a) answered;
  coverage_planner   the first ~plan_coverage (the lab's room) answered;
  roomba_sim         the first /odom received (the furnished room, real-time factor 1);
  roomba_fsm         the first /cmd_vel received, beside a roomba_sim already running;
  roomba_bt          the same, with the lab's tree (config/roomba_tree.xml).
The probe asks every 2 ms, so the figure includes up to 2 ms of polling and the master's
registration round trips. It counts the shared libraries each executable loads (ldd).
Prints one JSON line: {"nodes": [{"name", "answer", "median_ms", "libraries"}, ...]}.
scripts/bench uses it for the nodes' start-up rows.
"""
import json
import os
import statistics
import subprocess
import sys
import threading
import time

POLL_S = 0.002
TIMEOUT_S = 30.0


def libraries(executable):
    out = subprocess.run(["ldd", executable], capture_output=True, text=True).stdout
    return sum(1 for line in out.splitlines() if line.strip())


def stop(process):
    process.terminate()
    try:
        process.wait(timeout=10)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


def until_service_answers(rospy, service, srv_type, request):
    """Seconds until `service` answers `request` (polling every POLL_S), or raises."""
    deadline = time.perf_counter() + TIMEOUT_S
    while time.perf_counter() < deadline:
        try:
            proxy = rospy.ServiceProxy(service, srv_type)
            proxy(request)
            return
        except (rospy.ServiceException, OSError):
            time.sleep(POLL_S)
    raise RuntimeError(f"{service} did not answer within {TIMEOUT_S:.0f} s")


class FirstMessage:
    """Waits for the first message on a topic (a subscription made before the node starts)."""

    def __init__(self, rospy, topic, msg_type):
        self.event = threading.Event()
        self.subscriber = rospy.Subscriber(topic, msg_type, lambda _: self.event.set())

    def wait(self):
        if not self.event.wait(TIMEOUT_S):
            raise RuntimeError(f"{self.subscriber.name}: nothing within {TIMEOUT_S:.0f} s")

    def close(self):
        self.subscriber.unregister()


def median_ms(command, until, runs, log):
    times = []
    for _ in range(runs):
        started = time.perf_counter()
        process = subprocess.Popen(command, stdout=log, stderr=log)
        try:
            until()
            times.append((time.perf_counter() - started) * 1000)
        finally:
            stop(process)
    return statistics.median(times)


def main(argv):
    if len(argv) < 3 or argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 0 if len(argv) >= 2 and argv[1] in ("-h", "--help") else 2
    bin_dir, config = argv[1], argv[2]
    runs = int(argv[argv.index("--runs") + 1]) if "--runs" in argv else 10

    import rospy
    from geometry_msgs.msg import Point, Twist
    from nav_msgs.msg import Odometry
    from roomba_rrt.srv import PlanCoverage, PlanCoverageRequest, PlanPath, PlanPathRequest

    rospy.init_node("node_startup_probe", anonymous=True, disable_signals=True)
    rospy.set_param("/use_sim_time", False)
    furnished = os.path.join(config, "roomba_world_furnished.yaml")
    log = open(os.devnull, "w")
    out = []

    def add(name, answer, args, until):
        executable = os.path.join(bin_dir, name)
        out.append({"name": name, "answer": answer,
                    "median_ms": median_ms([executable] + args, until, runs, log),
                    "libraries": libraries(executable)})

    add("rrt_planner", "first ~plan_path (scenario a) answered", [],
        lambda: until_service_answers(rospy, "/rrt_planner/plan_path", PlanPath,
                                      PlanPathRequest(scenario="a")))
    add("coverage_planner", "first ~plan_coverage (the lab's room) answered", [],
        lambda: until_service_answers(rospy, "/coverage_planner/plan_coverage", PlanCoverage,
                                      PlanCoverageRequest(start=Point(x=1.0, y=1.0))))

    # Topic answers: the subscription is made, and registered at the master, before the node
    # starts, so the first message cannot be missed.
    def run_with_waiter(name, answer, args, make_waiter):
        executable = os.path.join(bin_dir, name)
        times = []
        for _ in range(runs):
            waiter = make_waiter()
            time.sleep(0.2)  # the subscription registered at the master
            started = time.perf_counter()
            process = subprocess.Popen([executable] + args, stdout=log, stderr=log)
            try:
                waiter.wait()
                times.append((time.perf_counter() - started) * 1000)
            finally:
                stop(process)
                waiter.close()
        out.append({"name": name, "answer": answer, "median_ms": statistics.median(times),
                    "libraries": libraries(executable)})

    run_with_waiter("roomba_sim", "first /odom received (furnished room)",
                    [f"_world_file:={furnished}"], lambda: FirstMessage(rospy, "/odom", Odometry))
    sim = subprocess.Popen([os.path.join(bin_dir, "roomba_sim"), f"_world_file:={furnished}"],
                           stdout=log, stderr=log)
    try:
        FirstMessage(rospy, "/odom", Odometry).wait()
        run_with_waiter("roomba_fsm", "first /cmd_vel received (beside roomba_sim)", [],
                        lambda: FirstMessage(rospy, "/cmd_vel", Twist))
        run_with_waiter("roomba_bt", "first /cmd_vel received (beside roomba_sim; the lab's tree)",
                        [f"_tree_file:={os.path.join(config, 'roomba_tree.xml')}"],
                        lambda: FirstMessage(rospy, "/cmd_vel", Twist))
    finally:
        stop(sim)
    print(json.dumps({"nodes": out}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
