#!/usr/bin/env python3
"""The rviz view for several named robots (scripts/run --robots N): the mode's own configuration
with, for every robot, its state text (its behaviour node's ~state_marker), its RobotModel
(tf prefix robotK) and its LDS scan (/robotK/scan), and, when a robot navigates, the navigation displays and rviz's 2D Nav Goal
tool pointed at the first robot that navigates.

usage: rviz_for_robots.py BASE.rviz OUT.rviz NAV_ROBOT ROBOT:NODE...
       (NAV_ROBOT: the robot the 2D Nav Goal sends to, e.g. robot3, or - for none)"""
import sys

import yaml


def main():
    base, out, nav_robot, specs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    with open(base, encoding="utf-8") as f:
        config = yaml.safe_load(f)
    displays = config["Visualization Manager"]["Displays"]
    template_model = next((d for d in displays if d.get("Class") == "rviz/RobotModel"), None)
    template_scan = next((d for d in displays if d.get("Class") == "rviz/LaserScan"), None)
    # The single robot's state texts, model and scan make no sense with named robots: one per
    # robot.
    displays[:] = [d for d in displays
                   if not str(d.get("Marker Topic", "")).endswith("/state_marker")
                   and d.get("Class") not in ("rviz/RobotModel", "rviz/LaserScan")]
    if nav_robot != "-":
        def point(value):
            if isinstance(value, str):
                return (value.replace("/move_base_simple/goal", "/%s/move_base_simple/goal" % nav_robot)
                        .replace("/roomba_bt/", "/%s/roomba_bt/" % nav_robot))
            if isinstance(value, dict):
                return {k: point(v) for k, v in value.items()}
            if isinstance(value, list):
                return [point(v) for v in value]
            return value
        config = point(config)
        displays = config["Visualization Manager"]["Displays"]
    for spec in specs:
        robot, node = spec.split(":")
        displays.append({
            "Class": "rviz/Marker", "Enabled": True, "Name": "%s: %s state" % (robot, node),
            "Marker Topic": "/%s/%s/state_marker" % (robot, node), "Namespaces": {},
            "Queue Size": 100, "Value": True})
        if template_model is not None:
            model = dict(template_model)
            model["Name"] = "%s (RobotModel)" % robot
            model["TF Prefix"] = robot
            displays.append(model)
        if template_scan is not None:
            scan = dict(template_scan)
            scan["Name"] = "%s scan" % robot
            scan["Topic"] = "/%s/scan" % robot
            displays.append(scan)
    with open(out, "w", encoding="utf-8") as f:
        yaml.safe_dump(config, f, default_flow_style=False, sort_keys=False)


if __name__ == "__main__":
    main()
