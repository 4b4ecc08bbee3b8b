"""A client of Groot2's monitoring protocol (BehaviorTree.CPP 4.x, version 2), as Groot2 talks to
an executor: a ZeroMQ REQ socket, a 6-byte request header (protocol, type, id), a 22-byte reply
header (the same 6 bytes, then the tree's 16-byte UUID). Used by the rostests of roomba_bt's
Groot2 server; `python3 groot2_client.py [PORT]` prints the tree and its statuses once."""
import random
import struct
import sys
import xml.etree.ElementTree as ET

import zmq

PROTOCOL = 2
REQUEST_HEADER = 6
REPLY_HEADER = 22
STATUS_NAMES = {0: "IDLE", 1: "RUNNING", 2: "SUCCESS", 3: "FAILURE", 4: "SKIPPED",
                11: "IDLE_FROM_RUNNING", 12: "IDLE_FROM_SUCCESS", 13: "IDLE_FROM_FAILURE",
                14: "IDLE_FROM_SKIPPED"}


def request_header(kind, request_id, protocol=PROTOCOL):
    return struct.pack("<BcI", protocol, kind.encode() if isinstance(kind, str) else kind,
                       request_id)


def parse_reply_header(frame):
    """(protocol, type, id, uuid) of a reply's first frame."""
    if len(frame) != REPLY_HEADER:
        raise ValueError("reply header of %d bytes, not %d" % (len(frame), REPLY_HEADER))
    protocol, kind, request_id = struct.unpack("<BcI", frame[:REQUEST_HEADER])
    return protocol, kind.decode(), request_id, frame[REQUEST_HEADER:]


def parse_status(payload):
    """{uid: status} of a 'S' reply's payload (uint16 uid, uint8 status per node)."""
    if len(payload) % 3:
        raise ValueError("status payload of %d bytes is not 3 per node" % len(payload))
    return {uid: status for uid, status in struct.iter_unpack("<HB", payload)}


def unpack(data, offset=0):
    """(value, next offset) of the MessagePack value at `offset`: the types a blackboard dump
    holds (maps, strings, booleans, nil, integers, floats)."""
    b = data[offset]
    if b & 0xF0 == 0x80 or b in (0xDE, 0xDF):  # map
        if b & 0xF0 == 0x80:
            size, offset = b & 0x0F, offset + 1
        else:
            width = 2 if b == 0xDE else 4
            size = int.from_bytes(data[offset + 1:offset + 1 + width], "big")
            offset += 1 + width
        out = {}
        for _ in range(size):
            key, offset = unpack(data, offset)
            out[key], offset = unpack(data, offset)
        return out, offset
    if b & 0xE0 == 0xA0 or b in (0xD9, 0xDA, 0xDB):  # string
        if b & 0xE0 == 0xA0:
            size, offset = b & 0x1F, offset + 1
        else:
            width = {0xD9: 1, 0xDA: 2, 0xDB: 4}[b]
            size = int.from_bytes(data[offset + 1:offset + 1 + width], "big")
            offset += 1 + width
        return data[offset:offset + size].decode(), offset + size
    if b in (0xC0, 0xC2, 0xC3):
        return {0xC0: None, 0xC2: False, 0xC3: True}[b], offset + 1
    if b < 0x80 or b >= 0xE0:  # fixint
        return (b if b < 0x80 else b - 0x100), offset + 1
    if b == 0xD3:
        return struct.unpack(">q", data[offset + 1:offset + 9])[0], offset + 9
    if b == 0xCB:
        return struct.unpack(">d", data[offset + 1:offset + 9])[0], offset + 9
    raise ValueError("MessagePack type 0x%02x at %d is not one a blackboard dump holds" % (b, offset))


class Groot2Client:
    def __init__(self, port, host="127.0.0.1", timeout_ms=5000):
        self.context = zmq.Context.instance()
        self.address = "tcp://%s:%d" % (host, port)
        self.timeout_ms = timeout_ms
        self._connect()

    def _connect(self):
        self.socket = self.context.socket(zmq.REQ)
        self.socket.setsockopt(zmq.LINGER, 0)
        self.socket.setsockopt(zmq.RCVTIMEO, self.timeout_ms)
        self.socket.connect(self.address)

    def raw(self, frames):
        """Sends `frames` as one multipart request and returns the reply's frames."""
        self.socket.send_multipart(frames)
        try:
            return self.socket.recv_multipart()
        except zmq.Again:
            self.socket.close()
            self._connect()  # a REQ socket without its reply cannot send again
            raise

    def request(self, kind, *payload):
        """The reply to a well-formed request: (header fields, payload frames); checks the header
        echoes the request."""
        request_id = random.getrandbits(32)
        frames = self.raw([request_header(kind, request_id)] + list(payload))
        if frames[0] == b"error":
            raise RuntimeError("error reply: %r" % frames[1:])
        header = parse_reply_header(frames[0])
        if header[:3] != (PROTOCOL, kind, request_id):
            raise ValueError("reply header %r does not answer %r" % (header, (kind, request_id)))
        return header, frames[1:]

    def tree(self):
        """(uuid, XML root element) of the 'T' reply."""
        header, frames = self.request("T")
        return header[3], ET.fromstring(frames[0].decode())

    def blackboard(self, names):
        """{name: {key: value}} of the 'B' reply for the blackboards `names` (';'-separated)."""
        _, frames = self.request("B", names.encode())
        value, end = unpack(frames[0])
        if end != len(frames[0]):
            raise ValueError("%d bytes after the blackboard dump" % (len(frames[0]) - end))
        return value

    def status(self):
        """(uuid, {uid: status}) of the 'S' reply."""
        header, frames = self.request("S")
        return header[3], parse_status(frames[0])


def tree_nodes(root):
    """The nodes of a 'T' reply's <BehaviorTree>, in document order (preorder)."""
    tree = root.find("BehaviorTree")
    return [e for e in tree.iter() if e is not tree]


if __name__ == "__main__":
    client = Groot2Client(int(sys.argv[1]) if len(sys.argv) > 1 else 1667)
    _, xml_root = client.tree()
    _, statuses = client.status()
    for node in tree_nodes(xml_root):
        uid = int(node.get("_uid"))
        print("%3d %-20s %-16s %s" % (uid, node.tag, node.get("name"),
                                      STATUS_NAMES.get(statuses.get(uid), "?")))
