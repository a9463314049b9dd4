"""Helpers shared by the integration tests (run with /usr/bin/python3, standard library only).

Every test prints one line "FAIL: reason" and exits 1 on the first failed check
(see `fail` and `check`), kills only the processes it started, and removes its
temporary folder.
"""

import argparse
import json
import os
import re
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))

# Re-exported: the tests read logs with the same reader users get (python/dream_log.py).
from dream_log import LogFormatError, read_all, read_events  # noqa: E402,F401

LCM_GROUP = "239.255.76.67"
LCM_PORT = 7667


class TestFailure(Exception):
    pass


def fail(message):
    raise TestFailure(message)


def check(condition, message):
    if not condition:
        raise TestFailure(message)


def main(test):
    """Runs test(ctx) with a fresh Context; prints PASS or one FAIL line; exits 0/1."""
    ctx = Context()
    code = 1
    try:
        test(ctx)
        print(f"PASS ({time.monotonic() - ctx.started:.1f} s)")
        code = 0
    except TestFailure as error:
        print(f"FAIL: {error}")
        ctx.dump_outputs()
    finally:
        ctx.close()
    sys.exit(code)


def argument_parser(*, types_dir=False):
    """The options CMake gives every driver: --dream (the binary), --source (the
    checkout) and, with types_dir, --types-dir (build/python, the generated types)."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--dream", required=True)
    parser.add_argument("--source", required=True)
    if types_dir:
        parser.add_argument("--types-dir", required=True)
    return parser


def arguments(*, types_dir=False):
    """argument_parser(...).parse_args(), for drivers with no options of their own."""
    return argument_parser(types_dir=types_dir).parse_args()


def import_types(types_dir):
    """The generated Python package `dream` from types_dir (build/python)."""
    sys.path.insert(0, os.path.abspath(types_dir))
    import dream  # noqa: E402

    return dream


class Context:
    """A temporary folder and the child processes of one test."""

    def __init__(self):
        self.started = time.monotonic()
        self.dir = tempfile.mkdtemp(prefix="dream_it_")
        self.procs = {}  # name -> (Popen, output path)
        self.groups = []  # process groups led by children started with own_group
        self.keep = os.environ.get("DREAM_TEST_KEEP") == "1"

    def path(self, *parts):
        return os.path.join(self.dir, *parts)

    def start(self, name, argv, env=None, own_group=False, cwd=None):
        """Starts argv with stdout+stderr into <tmp>/<name>.out; returns the Popen. With own_group the
        child leads a new process group, and close() ends that whole group (for wrappers such as
        xvfb-run whose children could outlive them). `cwd`: where files the child writes by
        relative path land (the test's folder, never the source tree)."""
        check(name not in self.procs, f"internal: process name {name} used twice")
        out_path = self.path(name + ".out")
        out = open(out_path, "w")
        proc = subprocess.Popen(argv, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                env=env, start_new_session=own_group, cwd=cwd)
        out.close()
        self.procs[name] = (proc, out_path)
        if own_group:
            self.groups.append(proc.pid)
        return proc

    def stop(self, name, timeout=10):
        """Ends process `name` (its whole group when started with own_group) and waits for it, so
        what it held (a UDP port, a display) is free for the next process."""
        proc = self.procs[name][0]
        if proc.poll() is None:
            try:
                if proc.pid in self.groups:
                    os.killpg(proc.pid, signal.SIGTERM)
                else:
                    proc.terminate()
            except ProcessLookupError:
                pass
            try:
                proc.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        if proc.pid in self.groups:
            self.groups.remove(proc.pid)  # its group is gone; never signal a reused id in close()
            try:
                os.killpg(proc.pid, signal.SIGKILL)  # a child that ignored SIGTERM
            except ProcessLookupError:
                pass

    def output(self, name):
        with open(self.procs[name][1], errors="replace") as f:
            return f.read()

    def wait(self, name, timeout):
        """Exit code of process `name`; fails when it runs longer than timeout seconds."""
        proc = self.procs[name][0]
        try:
            return proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            fail(f"{name} ({' '.join(map(str, proc.args))}) still running after {timeout} s; "
                 f"last output: {tail(self.output(name))}")

    def wait_for_output(self, name, pattern, timeout):
        """Waits until process `name` prints a line matching regex `pattern`."""
        proc = self.procs[name][0]
        deadline = time.monotonic() + timeout
        regex = re.compile(pattern)
        while time.monotonic() < deadline:
            if regex.search(self.output(name)):
                return
            if proc.poll() is not None:
                fail(f"{name} exited ({proc.returncode}) before printing /{pattern}/: {tail(self.output(name))}")
            time.sleep(0.01)
        fail(f"{name} did not print /{pattern}/ within {timeout} s: {tail(self.output(name))}")

    def run(self, argv, timeout=30, expect=None, cwd=None):
        """Runs argv to completion (in the folder `cwd`, else this one); returns (exit code, stdout+stderr).
        `expect`: required exit code."""
        try:
            result = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                    timeout=timeout, stdin=subprocess.DEVNULL, cwd=cwd)
        except subprocess.TimeoutExpired:
            fail(f"`{' '.join(map(str, argv))}` still running after {timeout} s")
        if expect is not None and result.returncode != expect:
            fail(f"`{' '.join(map(str, argv))}` exited {result.returncode}, expected {expect}: "
                 f"{tail(result.stdout)}")
        return result.returncode, result.stdout

    def dump_outputs(self):
        for name, (proc, out_path) in self.procs.items():
            try:
                with open(out_path, errors="replace") as f:
                    text = f.read()
            except OSError:
                continue
            print(f"----- output of {name} (exit {proc.poll()}) -----\n{text[-3000:]}", file=sys.stderr)

    def close(self):
        for group in self.groups:
            try:
                os.killpg(group, signal.SIGTERM)
            except ProcessLookupError:
                pass
        for name, (proc, _) in self.procs.items():
            if proc.poll() is None:
                proc.terminate()
        for name, (proc, _) in self.procs.items():
            try:
                proc.wait(timeout=3)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        if self.keep:
            print(f"kept {self.dir}", file=sys.stderr)
        else:
            shutil.rmtree(self.dir, ignore_errors=True)


def tail(text, chars=400):
    text = " | ".join(line.strip() for line in text.strip().splitlines()[-6:])
    return text[-chars:] if text else "(no output)"


def require_script_python():
    """Skips (exit 77) without what DREAM's rps needs in the tests' Python: numpy and cvxopt."""
    try:
        import cvxopt  # noqa: F401
        import numpy  # noqa: F401
    except ImportError:
        print("SKIP: needs numpy and cvxopt (Debian: python3-numpy python3-cvxopt)")
        sys.exit(77)


def script_under_test(ctx, name, text):
    """A Robotarium script for `dream run SCRIPT.py`, written into the test's folder, run by this
    Python (DREAM_PYTHON); skips without numpy and cvxopt. Returns its path."""
    require_script_python()
    os.environ["DREAM_PYTHON"] = sys.executable
    script = ctx.path(name)
    with open(script, "w") as f:
        f.write(text)
    return script


def script_run_test_setup():
    """What a test of `dream run SCRIPT.py` runs start with: its arguments (--dream, --source,
    --types-dir), a skip (exit 77) without numpy (what DREAM's rps needs), its private network
    namespace checked, and lcm-gen's Python types. Returns the arguments and the types."""
    args = argument_parser(types_dir=True).parse_args()
    try:
        import numpy  # noqa: F401 (only whether it is there)
    except ImportError:
        print("SKIP: needs numpy (Debian: python3-numpy)")
        sys.exit(77)
    require_private_netns()
    return args, import_types(args.types_dir)


def run_script(ctx, dream, script, name, timeout=300):
    """`dream run SCRIPT --out <name>_run -q` started as process `name`, the script run by this
    Python (DREAM_PYTHON); returns the run folder, the exit code and the output."""
    out_dir = ctx.path(name + "_run")
    ctx.start(name, [dream, "run", script, "--out", out_dir, "-q"], env=dict(os.environ, DREAM_PYTHON=sys.executable))
    return out_dir, ctx.wait(name, timeout), ctx.output(name)


def read_summary(out_dir):
    path = os.path.join(out_dir, "summary.json")
    check(os.path.isfile(path), f"{path} is missing")
    with open(path) as f:
        return json.load(f)


VERDICT_NAMES = ("clean", "warning", "not_ready", "rejected")  # run_verdict_t.CLEAN .. REJECTED


def check_log_ends_on_verdict(dream_types, out_dir, exit_code):
    """The run's log holds one DREAM_VERDICT, its last event (issue 33), saying what summary.json
    says (run, verdict, reasons, goal) and the exit code of the command that wrote the run."""
    log_path = os.path.join(out_dir, "run.lcmlog")
    events = read_all(log_path)
    verdicts = [event for event in events if event.channel == "DREAM_VERDICT"]
    check(len(verdicts) == 1, f"{log_path}: {len(verdicts)} DREAM_VERDICT events, expected one")
    check(events[-1].channel == "DREAM_VERDICT", f"{log_path}: ends on {events[-1].channel}, not DREAM_VERDICT")
    verdict = dream_types.run_verdict_t.decode(verdicts[0].data)
    summary = read_summary(out_dir)
    check(f"{verdict.run_id & 0xFFFFFFFFFFFFFFFF:016x}" == summary["run_id"],
          f"{log_path}: the verdict of run {verdict.run_id:x}, summary.json's is {summary['run_id']}")
    said = VERDICT_NAMES[verdict.verdict] if 0 <= verdict.verdict < len(VERDICT_NAMES) else verdict.verdict
    check(said == summary["verdict"], f"{log_path}: the verdict says {said}, summary.json {summary['verdict']}")
    check(verdict.exit_code == exit_code, f"{log_path}: the verdict says exit code {verdict.exit_code}, "
                                          f"the command exited {exit_code}")
    reasons = [f"{reason['rule']}: {reason['problem']}" for reason in summary["verdict_reasons"]]
    logged = verdict.reasons.split("\n") if verdict.reasons else []
    # Each reason whole, or cut at 1000 characters with "..." (VerdictBroadcast::kMaxTextChars).
    same = len(logged) == len(reasons) and all(
        text == full or (text.endswith("...") and full.startswith(text[:-3])) for text, full in zip(logged, reasons))
    check(same, f"{log_path}: the verdict's reasons {logged} are not summary.json's {reasons}")
    return verdict


def config_with(base_path, out_path, steps=None, stop_when_done=None, **world):
    """Copies the run config at base_path to out_path with top-level steps / stop_when_done and
    keys of the world: section replaced (each must already be present in the file)."""
    with open(base_path) as f:
        text = f.read()

    def replace(pattern, value, what):
        nonlocal text
        text, count = re.subn(pattern, lambda m: m.group(1) + value, text, count=1, flags=re.MULTILINE)
        check(count == 1, f"internal: {base_path} has no `{what}` line to override")

    if steps is not None:
        replace(r"^(steps:\s*)\S+", str(steps), "steps:")
    if stop_when_done is not None:
        replace(r"^(stop_when_done:\s*)\S+", "true" if stop_when_done else "false", "stop_when_done:")
    for key, value in world.items():
        replace(r"^(  " + re.escape(key) + r":\s*)\S+", str(value), "world." + key)
    with open(out_path, "w") as f:
        f.write(text)
    return out_path


def require_private_netns():
    """Refuses to touch udpm unless this process is in a private network namespace holding only
    loopback (tests/integration/netns.sh) and LCM_DEFAULT_URL is a ttl=0 udpm URL."""
    with open("/proc/self/net/dev") as f:
        interfaces = {line.split(":")[0].strip() for line in f.readlines()[2:]}
    check(interfaces == {"lo"},
          f"refusing to use udpm outside a private network namespace (interfaces {sorted(interfaces)}); "
          f"run under tests/integration/netns.sh")
    url = os.environ.get("LCM_DEFAULT_URL", "")
    check(url.startswith("udpm://") and "ttl=0" in url, f"LCM_DEFAULT_URL must be a ttl=0 udpm URL, got {url!r}")


class Udpm:
    """Raw LCM udpm on LCM_GROUP:LCM_PORT (small messages only), for injecting foreign packets and
    watching the bus without an LCM runtime. Packet: uint32 magic 'LC02', uint32 sequence number,
    channel, NUL, payload."""

    MAGIC_SHORT = 0x4C433032

    def __init__(self, receive=False):
        require_private_netns()
        self.sequence = 0
        self.send_socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
        self.send_socket.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 0)
        self.send_socket.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_LOOP, 1)
        self.recv_socket = None
        if receive:
            s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
            s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            s.bind(("", LCM_PORT))
            membership = struct.pack("4s4s", socket.inet_aton(LCM_GROUP), socket.inet_aton("0.0.0.0"))
            s.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
            self.recv_socket = s

    def send_raw(self, datagram):
        self.send_socket.sendto(datagram, (LCM_GROUP, LCM_PORT))

    def publish(self, channel, payload):
        header = struct.pack(">II", self.MAGIC_SHORT, self.sequence)
        self.sequence += 1
        self.send_raw(header + channel.encode() + b"\0" + payload)

    def receive(self, timeout):
        """(channel, payload) of the next small LCM message, or None after timeout seconds."""
        deadline = time.monotonic() + timeout
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return None
            self.recv_socket.settimeout(remaining)
            try:
                datagram = self.recv_socket.recv(65536)
            except socket.timeout:
                return None
            if len(datagram) < 9 or struct.unpack(">I", datagram[:4])[0] != self.MAGIC_SHORT:
                continue
            end = datagram.find(b"\0", 8)
            if end < 0:
                continue
            return datagram[8:end].decode(errors="replace"), datagram[end + 1:]

    def close(self):
        self.send_socket.close()
        if self.recv_socket:
            self.recv_socket.close()


def _publish_until_recorded(ctx, name, captured, channel):
    """Publishes a probe on `channel` until lcm-logger `name` has written it to `captured`; 30 s
    only turns a logger that never records into a failure."""
    logger = ctx.procs[name][0]
    bus = Udpm()
    deadline = time.monotonic() + 30
    while True:
        bus.publish(channel, b"probe")
        time.sleep(0.05)
        if os.path.exists(captured):
            with open(captured, "rb") as f:
                if channel.encode() in f.read():
                    break
        check(logger.poll() is None, f"lcm-logger exited ({logger.returncode}): {ctx.output(name).strip()}")
        check(time.monotonic() < deadline, f"lcm-logger did not record a {channel} message within 30 s")
    bus.close()


def start_lcm_logger(ctx, name, captured):
    """Starts lcm-logger (process `name`) recording LCM_DEFAULT_URL into `captured`, and returns
    once it records: a probe message published until it shows up in the file. Its socket gets
    4 MB, as dream's own receivers have, so a step's burst does not overflow it. It runs at a real-time
    priority (chrt --rr 1; the tests in a network namespace run as root): lcm-logger 1.3.1 keeps
    LCM's 30-message queue and drops a burst when it waits for a CPU, which a hog on every core made
    it do at nice -10 too; the recorder is the test's instrument, not what it tests."""
    url = os.environ["LCM_DEFAULT_URL"]
    logger_url = url + ("&" if "?" in url else "?") + "recv_buf_size=4194304"
    priority = ["chrt", "--rr", "1"] if os.geteuid() == 0 else []
    logger = ctx.start(name, priority + ["lcm-logger", "--lcm-url=" + logger_url, "--flush-interval=10",
                                         "-f", captured])
    _publish_until_recorded(ctx, name, captured, "PROBE_LOGGER_UP")
    return logger


def stop_lcm_logger(ctx, name, captured):
    """Stops lcm-logger `name` (started by start_lcm_logger) once it has written everything it
    received: a probe published after the last message it must hold, until the probe shows up in
    `captured` (it records in the order it receives, so what comes before has been written by
    then). A wait on that event, not a fixed pause, which a loaded machine can outlast."""
    _publish_until_recorded(ctx, name, captured, "PROBE_LOGGER_DRAINED")
    logger = ctx.procs[name][0]
    logger.send_signal(signal.SIGINT)
    code = ctx.wait(name, timeout=30)
    check(code == 0, f"lcm-logger exited {code} on SIGINT: {ctx.output(name).strip()}")
