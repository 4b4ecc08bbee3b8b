#!/usr/bin/env python3
"""roomba_bt's Groot2 server through a real master (test/behavior/groot2_monitor.test), as Groot2
talks to it: modelled on BehaviorTree.CPP's gtest_groot2_publisher_integration.cpp, with
groot2_client.py speaking the protocol."""
import os
import random
import re
import socket
import struct
import threading
import time
import unittest
import xml.etree.ElementTree as ET

import rospy
import rosunit
import zmq
from geometry_msgs.msg import Twist
from roomba_rrt.msg import BtTreeStatus
from std_msgs.msg import String
from visualization_msgs.msg import Marker, MarkerArray

from groot2_client import (PROTOCOL, REPLY_HEADER, Groot2Client, parse_reply_header,
                           parse_status, request_header, tree_nodes)

VALID_STATUSES = {0, 1, 2, 3, 4, 11, 12, 13, 14}
V3_SPELLINGS = {"Selector": "Fallback", "ReactiveSelector": "ReactiveFallback",
                "Retry": "RetryUntilSuccessful", "RetryUntilSuccesful": "RetryUntilSuccessful",
                "SequenceStar": "SequenceWithMemory"}


def file_nodes(path):
    """(type, name) of every node the tree file's main tree runs, in preorder, SubTrees expanded
    in place (includes followed): what the 'T' reply must list."""
    trees = {}
    main = [None]

    def load(file_path):
        with open(file_path) as f:
            # Our files' comments hold "--", which tinyxml2 (roomba_bt, BT.CPP) reads and expat
            # does not: drop the comments first.
            root = ET.fromstring(re.sub(r"<!--.*?-->", "", f.read(), flags=re.S))
        for include in root.findall("include"):
            load(os.path.join(os.path.dirname(file_path), include.get("path")))
        for tree in root.findall("BehaviorTree"):
            trees[tree.get("ID")] = tree
        return root

    root = load(path)
    main_id = root.get("main_tree_to_execute") or root.find("BehaviorTree").get("ID")
    out = []

    def walk(element):
        if element.tag == "SubTree":
            walk(list(trees[element.get("ID")])[0])
            return
        kind = V3_SPELLINGS.get(element.tag, element.tag)
        out.append((kind, element.get("name", element.tag)))
        for child in element:
            walk(child)

    walk(list(trees[main_id])[0])
    return main_id, out


class Groot2MonitorTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("groot2_monitor_test")
        cls.port = rospy.get_param("~port")
        cls.tree_file = rospy.get_param("~tree_file")
        cls.other_trees = rospy.get_param("~other_trees")
        cls.lock = threading.Lock()
        cls.state = None
        cls.state_changes = 0
        cls.tree_status = None
        cls.cmd_count = 0
        cls.markers = None
        rospy.Subscriber("/roomba_bt/state", String, cls.on_state, queue_size=10)
        rospy.Subscriber("/roomba_bt/tree_status", BtTreeStatus, cls.on_tree_status,
                         queue_size=10)
        rospy.Subscriber("/cmd_vel", Twist, cls.on_cmd, queue_size=100)
        rospy.Subscriber("/roomba_bt/tree_markers", MarkerArray, cls.on_markers, queue_size=10)
        cls.client = Groot2Client(cls.port, timeout_ms=10000)
        # The server answers as soon as roomba_bt has built its tree.
        deadline = time.time() + 60
        while True:
            try:
                cls.client.tree()
                break
            except zmq.Again:
                if time.time() > deadline:
                    raise

    @classmethod
    def on_state(cls, msg):
        with cls.lock:
            if msg.data != cls.state:
                cls.state_changes += 1
            cls.state = msg.data

    @classmethod
    def on_tree_status(cls, msg):
        with cls.lock:
            cls.tree_status = msg

    @classmethod
    def on_markers(cls, msg):
        with cls.lock:
            cls.markers = msg

    @classmethod
    def on_cmd(cls, _):
        with cls.lock:
            cls.cmd_count += 1

    def check_tree(self, client, tree_file):
        """The 'T' reply against the tree file; returns {uid: (type, name)}."""
        uuid, root = client.tree()
        self.assertEqual(len(uuid), 16)
        self.assertEqual(root.tag, "root")
        self.assertEqual(root.get("BTCPP_format"), "4")
        main_id, expected = file_nodes(tree_file)
        self.assertEqual(root.find("BehaviorTree").get("ID"), main_id)
        nodes = tree_nodes(root)
        self.assertEqual([(n.tag, n.get("name")) for n in nodes], expected)
        uids = [int(n.get("_uid")) for n in nodes]
        self.assertEqual(uids, list(range(1, len(nodes) + 1)))
        # The model Groot2 draws our nodes with (roomba_bt --tree-nodes-model).
        model = root.find("TreeNodesModel")
        self.assertIsNotNone(model, "no <TreeNodesModel> in the 'T' reply")
        modelled = {e.get("ID") for e in model}
        for kind, _ in expected:
            if kind in ("MoveForward", "FollowPath", "FollowCoverage", "HasGoal"):
                self.assertIn(kind, modelled)
        return {uid: (n.tag, n.get("name")) for uid, n in zip(uids, nodes)}

    def test_full_tree_lists_every_node_of_the_tree_file_with_a_uid(self):
        self.check_tree(self.client, self.tree_file)

    def test_navigation_and_cleaning_trees_are_served_too(self):
        for port, tree_file in self.other_trees:
            client = Groot2Client(int(port), timeout_ms=10000)
            nodes = self.check_tree(client, tree_file)
            _, statuses = client.status()
            self.assertEqual(set(statuses), set(nodes), tree_file)

    def test_blackboard_dump_names_the_tree(self):
        dump = self.client.blackboard("Unknown;Roomba")
        self.assertEqual(list(dump), ["Roomba"])
        self.assertIsInstance(dump["Roomba"], dict)
        # A tree that is not ticked (no bumper in its namespace) has no blackboard to give.
        port, _ = self.other_trees[0]
        reply = Groot2Client(int(port), timeout_ms=10000).raw(
            [request_header("B", 3), b"CleanAndNavigate"])
        self.assertEqual(reply[0], b"error")

    def test_the_tree_uuid_is_fixed_while_the_node_runs(self):
        uuids = {self.client.tree()[0]}
        for _ in range(5):
            uuids.add(self.client.status()[0])
        self.assertEqual(len(uuids), 1)

    def stable_sample(self):
        """(statuses, ~state, ~tree_status) when two 'S' replies and the topics agree in time."""
        with self.lock:
            state, changes, topic = self.state, self.state_changes, self.tree_status
        _, first = self.client.status()
        time.sleep(0.1)
        _, second = self.client.status()
        time.sleep(0.1)  # a ~state published with the first reply's statuses has arrived
        with self.lock:
            same = (changes == self.state_changes and topic is self.tree_status)
        return (first, state, topic) if same and first == second else None

    def test_status_shows_the_running_leaf_that_state_names(self):
        nodes = self.check_tree(self.client, self.tree_file)
        leaves = {uid for uid, (kind, _) in nodes.items()
                  if kind in ("MoveForward", "MoveInSpiral", "GoBack", "Rotate")}
        seen = set()
        deadline = time.time() + 90
        while seen != {"MoveForward", "MoveInSpiral"} and time.time() < deadline:
            sample = self.stable_sample()
            if sample is None or sample[1] is None or sample[2] is None:
                continue
            statuses, state, topic = sample
            self.assertEqual(set(statuses), set(nodes))
            self.assertTrue(set(statuses.values()) <= VALID_STATUSES, statuses)
            running = [uid for uid in leaves if statuses[uid] == 1]
            if not running:
                continue  # the idle tick between two runs of the root
            self.assertEqual(len(running), 1, statuses)
            self.assertEqual(nodes[running[0]][1], state)
            # ~tree_status carries the same statuses as Groot2's 'S'.
            self.assertEqual({n.uid: n.status for n in topic.nodes}, statuses)
            self.assertEqual([n.path.split("/")[-1] for n in topic.nodes],
                             [nodes[uid][1] for uid in sorted(nodes)])
            if state in ("MoveForward", "MoveInSpiral"):
                seen.add(state)
            # A leaf that ran before in this run of the root shows its SUCCESS.
            if state == "MoveInSpiral":
                forward = [uid for uid, (kind, _) in nodes.items() if kind == "MoveForward"][0]
                self.assertEqual(statuses[forward], 2)
        self.assertEqual(seen, {"MoveForward", "MoveInSpiral"})

    def test_rviz_draws_every_node_beside_the_robot_coloured_by_status(self):
        nodes = self.check_tree(self.client, self.tree_file)
        deadline = time.time() + 30
        while time.time() < deadline:
            with self.lock:
                markers = self.markers
            if markers is not None:
                break
            time.sleep(0.1)
        self.assertIsNotNone(markers, "nothing on ~tree_markers")
        labels = sorted((m for m in markers.markers if m.type == Marker.TEXT_VIEW_FACING),
                        key=lambda m: m.id)
        self.assertEqual([m.text for m in labels], [nodes[uid][1] for uid in sorted(nodes)])
        boxes = [m for m in markers.markers if m.type == Marker.CUBE_LIST]
        self.assertEqual(len(boxes), 1)
        self.assertEqual(len(boxes[0].points), len(nodes))
        self.assertEqual(boxes[0].header.frame_id, "odom")
        # The root runs or just finished: never the grey of a node that was never ticked.
        root = boxes[0].colors[0]
        self.assertNotEqual((root.r, root.g, root.b), (0.5, 0.5, 0.5))
        edges = [m for m in markers.markers if m.type == Marker.LINE_LIST]
        self.assertEqual(len(edges[0].points), 2 * (len(nodes) - 1))

    def test_fuzzed_requests_get_error_replies_and_never_stop_the_tree(self):
        rng = random.Random(46)
        client = Groot2Client(self.port, timeout_ms=10000)
        with self.lock:
            cmds_before, changes_before = self.cmd_count, self.state_changes
        _, statuses_before = client.status()

        def expect_error(frames, why=None):
            reply = client.raw(frames)
            self.assertEqual(len(reply), 2, reply[:1])
            self.assertEqual(reply[0], b"error")
            if why is not None:
                self.assertEqual(reply[1].decode(), why)

        for _ in range(20):
            # Wrong protocol: BehaviorTree.CPP answers anyway, as version 2.
            protocol = rng.choice([0, 1, 3, 255])
            reply = client.raw([request_header("S", 7, protocol)])
            self.assertEqual(parse_reply_header(reply[0])[:3], (PROTOCOL, "S", 7))
            self.assertEqual(len(reply[1]) % 3, 0)
            # Short and long headers.
            for size in (0, 1, 5, 7, 22):
                expect_error([bytes(rng.getrandbits(8) for _ in range(size))],
                             "wrong request header")
            # Unknown types.
            kind = rng.choice([b"\x00", b"Z", b"\xff", b"s", b"N"])
            expect_error([struct.pack("<Bc", 2, kind) + b"\x01\x02\x03\x04"],
                         "Request not recognized")
            # Breakpoints, blackboard, recording: not served, answered with an error.
            expect_error([request_header(rng.choice("IRUrt"), 9), b"{}"])
            expect_error([request_header("B", 9)], "must be 2 parts message")
            # Random frames.
            frames = [bytes(rng.getrandbits(8) for _ in range(rng.randint(0, 40)))
                      for _ in range(rng.randint(1, 3))]
            reply = client.raw(frames)
            self.assertTrue(reply[0] == b"error" or len(reply[0]) == REPLY_HEADER)
        # 1 MB frames: as the header, an error; after a good header, ignored.
        expect_error([rng.randbytes(1 << 20)], "wrong request header")
        reply = client.raw([request_header("S", 8), rng.randbytes(1 << 20)])
        self.assertEqual(parse_reply_header(reply[0])[:3], (PROTOCOL, "S", 8))
        # Not ZeroMQ at all: a raw TCP stream of garbage.
        raw = socket.create_connection(("127.0.0.1", self.port))
        raw.sendall(rng.randbytes(4096))
        raw.close()

        # The server still answers, and the tree kept ticking throughout.
        self.check_tree(client, self.tree_file)
        deadline = time.time() + 60
        while time.time() < deadline:
            _, statuses = client.status()
            with self.lock:
                ticking = self.cmd_count > cmds_before + 10
                changed = self.state_changes > changes_before
            if ticking and changed and statuses != statuses_before:
                break
            time.sleep(0.2)
        with self.lock:
            self.assertGreater(self.cmd_count, cmds_before + 10, "no /cmd_vel after the fuzz")
            self.assertGreater(self.state_changes, changes_before, "~state stopped changing")


if __name__ == "__main__":
    rosunit.unitrun("roomba_rrt", "groot2_monitor", Groot2MonitorTest)
