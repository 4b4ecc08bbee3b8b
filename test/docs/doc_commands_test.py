#!/usr/bin/env python3
"""Every command in README.md and doc/*.md works when pasted after `source devel/setup.bash`.

Each ```bash block of the documentation is preceded by a marker that says how it is tested:

    <!-- doc-test: live SETUP -->      the block runs for real, line by line, in a bash shell at
                                       the repository root, against SETUP (below); it must exit 0
                                       within its time limit
    <!-- doc-test: static REASON -->   the block cannot run here (it starts a system that runs
                                       until Ctrl-C, needs other machines, takes minutes, ...):
                                       it is only checked

SETUP: `none` (no master), `master` (roscore, /use_sim_time true), `all` (roomba_sim in the
furnished room at real-time factor 5, roomba_fsm, rrt_planner), `planner` (rrt_planner and
coverage_planner in the lab's room, as `scripts/run planner`), `nav`
(roomba_sim and rrt_planner in the furnished room, roomba_bt with the navigation tree).

Every block, live or static, is checked: the executables it names exist (`rosrun roomba_rrt X`,
`devel/lib/roomba_rrt/X`, `scripts/X`), their `--flags` are in their usage text, node parameters
(`_name:=`) are read by the node, files (`$(rospack find roomba_rrt)/...`, `config/...`) exist,
rostest files exist, and `plan_path` and `plan_coverage` requests name only fields of their .srv. A bash block
without a marker fails the test, so a new command cannot slip in untested.

Usage (ctest runs it): doc_commands_test.py REPO_ROOT DEVEL_DIR   (a ROS master URI on a free
port in ROS_MASTER_URI, the devel space sourced: test/docs/doc_commands_test.bash does both)
"""
import glob
import os
import re
import shlex
import signal
import socket
import tempfile
import subprocess
import sys
import time

import yaml

MARKER = re.compile(r"<!--\s*doc-test:\s*(live|static)\s*(.*?)\s*-->")
SETUPS = ("none", "master", "all", "planner", "nav")
BLOCK_SECONDS = 120


class Doc:
    def __init__(self, root, devel):
        self.root, self.devel = root, devel
        self.bin = os.path.join(devel, "lib", "roomba_rrt")
        self.failures = []
        self.help_cache = {}
        # What the checks compare against, read once.
        self.node_sources = "".join(
            open(f, encoding="utf-8").read()
            for folder in ("nodes", "ros")  # the mains and the adapters that read parameters
            for f in glob.glob(os.path.join(root, "src", folder, "*.*")))
        self.request_fields = {}  # service -> (srv file, its request's fields)
        for service, name in (("/rrt_planner/plan_path", "PlanPath"),
                              ("/coverage_planner/plan_coverage", "PlanCoverage")):
            srv = open(os.path.join(root, "srv", name + ".srv"), encoding="utf-8").read()
            self.request_fields[service] = (
                name + ".srv", set(re.findall(r"^\S+\s+(\w+)", srv.split("---")[0], re.M)))

    def fail(self, where, message):
        self.failures.append(f"{where}: {message}")
        print(f"FAIL {where}: {message}", flush=True)

    # --- reading the pages ---------------------------------------------------------------------
    def blocks(self, path):
        """(line, language, marker, text) of every fenced block."""
        lines = open(path, encoding="utf-8").read().split("\n")
        out, i = [], 0
        while i < len(lines):
            m = re.match(r"^```(\w*)\s*$", lines[i])
            if not m:
                i += 1
                continue
            start, language = i + 1, m.group(1)
            marker = None
            j = i - 1
            while j >= 0 and not lines[j].strip():
                j -= 1
            if j >= 0:
                mm = MARKER.search(lines[j])
                if mm:
                    marker = (mm.group(1), mm.group(2))
            i += 1
            body = []
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            out.append((start, language, marker, "\n".join(body)))
            i += 1
        return out

    @staticmethod
    def commands(text):
        """The block's commands: continuation lines and multi-line quotes joined."""
        out, pending = [], ""
        for line in text.split("\n"):
            pending = pending + "\n" + line if pending else line
            if pending.rstrip().endswith("\\"):
                continue
            try:
                shlex.split(pending, comments=True)
            except ValueError:  # an open quote: the command goes on
                continue
            if pending.strip() and not pending.strip().startswith("#"):
                out.append(pending)
            pending = ""
        if pending.strip():
            out.append(pending)
        return out

    # --- static checks ---------------------------------------------------------------------
    def usage(self, exe):
        if exe not in self.help_cache:
            try:
                r = subprocess.run([exe, "--help"], capture_output=True, text=True, timeout=10)
                self.help_cache[exe] = r.stdout + r.stderr
            except subprocess.TimeoutExpired as e:
                self.help_cache[exe] = (e.stdout or b"").decode() + (e.stderr or b"").decode()
        return self.help_cache[exe]

    def check_program(self, where, name, args):
        exe = os.path.join(self.bin, name)
        if not os.access(exe, os.X_OK):
            # Benchmarks are built by scripts/bench (`--target benchmarks`), not by the test build.
            benchmarks = open(os.path.join(self.root, "cmake", "benchmarks.cmake")).read()
            if not re.search(rf"\b{re.escape(name)}\b", benchmarks):
                self.fail(where, f"{name}: no such executable in {self.bin}")
            return
        flags = [a.split("=")[0] for a in args if a.startswith("--")]
        if flags:
            text = self.usage(exe)
            for flag in flags:
                if flag not in text:
                    self.fail(where, f"{name} {flag}: not in `{name} --help`")
        for a in args:
            m = re.match(r"^_([A-Za-z0-9][A-Za-z0-9_/]*):=", a)  # not __ns, __name
            if m:
                first = m.group(1).split("/")[0]
                if f'"{m.group(1)}"' not in self.node_sources and \
                        f'"{first}"' not in self.node_sources:
                    self.fail(where, f"{name} _{m.group(1)}: no node reads that parameter")

    def check_request(self, where, service, request):
        srv, fields = self.request_fields[service]
        try:
            data = yaml.safe_load(request)
        except yaml.YAMLError as e:
            self.fail(where, f"{service} request is not YAML: {e}")
            return
        if not isinstance(data, dict):
            self.fail(where, f"{service} request is not a mapping")
            return
        for key in data:
            if key not in fields:
                self.fail(where, f"{service} request: no field '{key}' in {srv}")

    def check_command(self, where, command):
        for rel in re.findall(r"\$\(rospack find roomba_rrt\)/([\w./-]+)", command):
            if not os.path.exists(os.path.join(self.root, rel)):
                self.fail(where, f"{rel}: no such file in the package")
        try:
            words = shlex.split(command, comments=True)
        except ValueError as e:
            self.fail(where, f"cannot parse: {e}")
            return
        segment = []
        for w in words + [";"]:
            if w in ("|", "||", "&&", ";", "&"):
                if segment:
                    self.check_segment(where, segment)
                segment = []
            else:
                segment.append(w)

    def check_segment(self, where, words):
        while words and re.match(r"^\w+=", words[0]):  # VAR=value prefixes
            words = words[1:]
        if not words:
            return
        head, args = words[0], words[1:]
        if head == "rosrun" and args[:1] == ["roomba_rrt"] and len(args) >= 2:
            self.check_program(where, args[1], args[2:])
        elif head == "rosrun" and len(args) >= 2:
            r = subprocess.run(["rospack", "find", args[0]], capture_output=True, text=True)
            if r.returncode != 0:
                self.fail(where, f"rosrun {args[0]}: package not found")
        elif re.match(r"^(devel/lib/roomba_rrt|\$b)/", head):
            self.check_program(where, head.split("/")[-1], args)
        elif head.startswith("scripts/"):
            script = os.path.join(self.root, head)
            if not os.access(script, os.X_OK):
                self.fail(where, f"{head}: no such script")
                return
            text = open(script, encoding="utf-8").read()
            for flag in [a for a in args if a.startswith("--")]:
                if flag not in text:
                    self.fail(where, f"{head} {flag}: the script does not know it")
        elif head == "rostest" and len(args) >= 2:
            if not glob.glob(os.path.join(self.root, "test", "**", args[1]), recursive=True):
                self.fail(where, f"rostest {args[1]}: no such file under test/")
        elif head == "rosservice" and args[:1] == ["call"] and args[1:2] and \
                args[1] in self.request_fields:
            self.check_request(where, args[1], args[2] if len(args) > 2 else "{}")
        elif head in ("rosparam",) and args[:1] == ["load"] and len(args) > 1:
            if not os.path.exists(os.path.join(self.root, args[1])):
                self.fail(where, f"{args[1]}: no such file")

    # --- live runs -------------------------------------------------------------------------
    def start(self, setup):
        """Starts SETUP's nodes; returns their processes."""
        furnished = os.path.join(self.root, "config", "roomba_world_furnished.yaml")
        nodes = {
            "none": [],
            "master": [],
            "all": [["roomba_sim", f"_world_file:={furnished}", "_real_time_factor:=5"],
                    ["roomba_fsm"], ["rrt_planner"]],
            "planner": [["rrt_planner"], ["coverage_planner"]],
            "nav": [["roomba_sim", f"_world_file:={furnished}", "_real_time_factor:=5"],
                    ["rrt_planner", f"_world_file:={furnished}"],
                    ["roomba_bt", "_tree_file:=" +
                     os.path.join(self.root, "config", "roomba_nav_tree.xml"),
                     f"_world_file:={furnished}"]],
        }[setup]
        procs = []
        if setup == "none":
            return procs
        # A master of its own per block, on a port of its own: a previous block's master that is
        # still shutting down must not take this block's nodes with it.
        with socket.socket() as s:
            s.bind(("", 0))
            port = s.getsockname()[1]
        os.environ["ROS_MASTER_URI"] = f"http://localhost:{port}"
        self.logs = os.path.join(os.environ.get("ROS_HOME", "/tmp"), f"doc-{setup}-{port}")
        os.makedirs(self.logs, exist_ok=True)

        def launch(args, name):
            log = open(os.path.join(self.logs, name + ".log"), "w")
            return subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT,
                                    start_new_session=True)

        procs.append(launch(["roscore", "-p", str(port)], "roscore"))
        for _ in range(200):
            if subprocess.run(["rosparam", "set", "/use_sim_time", "true"],
                              capture_output=True).returncode == 0:
                break
            time.sleep(0.1)
        for args in nodes:
            procs.append(launch([os.path.join(self.bin, args[0])] + args[1:], args[0]))
        expected = {"all": ["/roomba_sim", "/roomba_fsm", "/rrt_planner"],
                    "planner": ["/rrt_planner", "/coverage_planner"],
                    "nav": ["/roomba_sim", "/rrt_planner", "/roomba_bt"]}.get(setup, [])
        deadline = time.time() + 30
        while expected and time.time() < deadline:
            r = subprocess.run(["rosnode", "list"], capture_output=True, text=True)
            if all(n in r.stdout.split() for n in expected):
                break
            time.sleep(0.2)
        if expected:
            time.sleep(2)  # the first /clock, tf and a plan-ready planner
        return procs

    @staticmethod
    def stop(procs):
        for p in reversed(procs):
            try:
                os.killpg(p.pid, signal.SIGINT)
            except ProcessLookupError:
                pass
        for p in reversed(procs):
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()

    def run_live(self, where, setup, commands):
        script = ["set -eo pipefail", f"cd {shlex.quote(self.root)}", "__bg=()",
                  "trap '((${#__bg[@]})) && kill -INT ${__bg[@]} 2>/dev/null; wait' EXIT"]
        for k, c in enumerate(commands):
            script.append(f"echo '@@ {k}' >&2")
            script.append(c.rstrip())
            if shlex.split(c, comments=True)[-1:] == ["&"]:  # a trailing comment is dropped
                script.append("__bg+=($!); sleep 3")
        self.logs = None
        procs = self.start(setup)
        began = time.time()
        # Output to a file, not a pipe: a process the block leaves behind must not keep us waiting.
        with tempfile.TemporaryFile("w+") as out:
            block = subprocess.Popen(["bash", "-c", "\n".join(script)], stdout=out,
                                     stderr=subprocess.STDOUT, text=True, start_new_session=True)
            try:
                rc = block.wait(timeout=BLOCK_SECONDS)
            except subprocess.TimeoutExpired:
                rc = f"timeout after {BLOCK_SECONDS} s"
            finally:
                try:
                    os.killpg(block.pid, signal.SIGKILL)  # whatever the block left running
                except ProcessLookupError:
                    pass
                block.wait()
                self.stop(procs)
            out.seek(0)
            err = out.read()
        seconds = time.time() - began
        if rc == 0:
            print(f"ok   {where} (live {setup}, {len(commands)} commands, {seconds:.1f} s)",
                  flush=True)
            return
        marks = re.findall(r"^@@ (\d+)$", err, re.M)
        last = commands[int(marks[-1])].strip() if marks else "?"
        tail = "\n".join(l for l in err.splitlines() if not l.startswith("@@"))[-800:]
        for log in sorted(glob.glob(os.path.join(self.logs or "/nonexistent", "*.log"))):
            tail += f"\n--- {os.path.basename(log)}:\n" + open(log).read()[-600:]
        self.fail(where, f"exit {rc} at `{last}`\n{tail}")

    def check(self, path):
        rel = os.path.relpath(path, self.root)
        for line, language, marker, text in self.blocks(path):
            if language != "bash":
                continue
            where = f"{rel}:{line}"
            commands = self.commands(text)
            for c in commands:
                self.check_command(where, c)
            if marker is None:
                self.fail(where, "bash block without a <!-- doc-test: live|static ... --> marker")
            elif marker[0] == "live":
                if marker[1] not in SETUPS:
                    self.fail(where, f"unknown setup '{marker[1]}' (one of {', '.join(SETUPS)})")
                else:
                    self.run_live(where, marker[1], commands)
            else:
                if not marker[1]:
                    self.fail(where, "a static block says why it cannot run")
                print(f"ok   {where} (static: {marker[1]})", flush=True)


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    doc = Doc(os.path.abspath(argv[1]), os.path.abspath(argv[2]))
    pages = [os.path.join(doc.root, "README.md")] + sorted(
        glob.glob(os.path.join(doc.root, "doc", "*.md")))
    for page in pages:
        doc.check(page)
    if doc.failures:
        print(f"\n{len(doc.failures)} failure(s):\n" + "\n".join(doc.failures))
        return 1
    print(f"\nall commands of {len(pages)} pages work")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
