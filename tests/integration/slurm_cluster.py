"""A private one-node Slurm cluster for the sweep tests (run with /usr/bin/python3, as root).

`SlurmCluster(folder)` starts munged (as the munge user, with a fresh key and its own socket),
slurmctld and slurmd with a slurm.conf of its own in `folder`; `env` is the environment whose
SLURM_CONF points Slurm's commands (and dream's) at it. `stop()` cancels its jobs and stops every
daemon it started, by the pids they wrote, and is safe to call twice. The daemons talk to this
machine only: the controller and the node are 127.0.0.1 (the tests run it in a private network
namespace as well, tests/integration/netns.sh).
"""

import os
import pwd
import shutil
import signal
import socket
import subprocess
import time

DAEMONS = ("munged", "slurmctld", "slurmd")
CLIENTS = ("sbatch", "squeue", "scancel", "scontrol", "sinfo", "runuser")


def missing_requirements():
    """Why this machine cannot run the cluster ('' when it can)."""
    if os.geteuid() != 0:
        return "not root (the test starts slurmctld, slurmd and munged itself)"
    for program in DAEMONS + CLIENTS:
        if shutil.which(program) is None and not os.path.exists(os.path.join("/usr/sbin", program)):
            return f"{program} is not installed (Debian packages slurm-wlm and munge)"
    try:
        pwd.getpwnam("munge")
    except KeyError:
        return "no munge user (Debian package munge)"
    return ""


def program(name):
    return shutil.which(name) or os.path.join("/usr/sbin", name)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class SlurmCluster:
    def __init__(self, folder):
        self.folder = folder
        self.pid_files = []
        os.makedirs(folder, exist_ok=True)
        os.chmod(folder, 0o755)  # munged, as the munge user, must reach its socket folder
        self.conf = os.path.join(folder, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        try:
            self._start_munge()
            self._write_conf()
            for daemon in ("slurmctld", "slurmd"):
                pid_file = os.path.join(folder, daemon + ".pid")
                self.pid_files.append(pid_file)
                subprocess.run([program(daemon), "-f", self.conf], env=self.env, check=True, timeout=30,
                               stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
            self._wait_idle()
        except BaseException:
            self.stop()
            raise

    def _start_munge(self):
        munge = pwd.getpwnam("munge")
        run_dir = os.path.join(self.folder, "munge", "run")
        etc_dir = os.path.join(self.folder, "munge", "etc")
        os.makedirs(run_dir)
        os.makedirs(etc_dir)
        key = os.path.join(etc_dir, "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        for path, mode in ((os.path.join(self.folder, "munge"), 0o755), (run_dir, 0o755), (etc_dir, 0o700), (key, 0o400)):
            os.chown(path, munge.pw_uid, munge.pw_gid)
            os.chmod(path, mode)
        self.munge_socket = os.path.join(run_dir, "munge.socket")
        pid_file = os.path.join(run_dir, "munged.pid")
        self.pid_files.append(pid_file)
        subprocess.run(["runuser", "-u", "munge", "--", program("munged"), "--socket=" + self.munge_socket,
                        "--key-file=" + key, "--log-file=" + os.path.join(etc_dir, "munged.log"),
                        "--pid-file=" + pid_file, "--seed-file=" + os.path.join(etc_dir, "munged.seed")],
                       check=True, timeout=30, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)

    def _write_conf(self):
        host = socket.gethostname().split(".")[0]
        cpus = os.cpu_count() or 1
        f = self.folder
        lines = [
            "ClusterName=dreamtest",
            f"SlurmctldHost={host}(127.0.0.1)",
            f"SlurmctldPort={free_port()}",
            f"SlurmdPort={free_port()}",
            "SlurmUser=root", "SlurmdUser=root",
            "AuthType=auth/munge", "CredType=cred/munge", f"AuthInfo=socket={self.munge_socket}",
            f"StateSaveLocation={f}/state", f"SlurmdSpoolDir={f}/spool",
            f"SlurmctldPidFile={f}/slurmctld.pid", f"SlurmdPidFile={f}/slurmd.pid",
            f"SlurmctldLogFile={f}/slurmctld.log", f"SlurmdLogFile={f}/slurmd.log",
            "ProctrackType=proctrack/linuxproc", "TaskPlugin=task/none",
            "SchedulerType=sched/builtin", "SelectType=select/cons_tres", "SelectTypeParameters=CR_CPU",
            # Start tasks as soon as CPUs free up (the default batch delay is 3 s).
            "SchedulerParameters=batch_sched_delay=0,sched_min_interval=0",
            "AccountingStorageType=accounting_storage/none", "JobCompType=jobcomp/none",
            "JobAcctGatherType=jobacct_gather/none", "MpiDefault=none", "ReturnToService=2",
            "MailProg=/bin/true", "MinJobAge=300",
            f"NodeName={host} NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN",
            f"PartitionName=debug Nodes={host} Default=YES MaxTime=INFINITE State=UP",
        ]
        os.makedirs(os.path.join(f, "state"))
        os.makedirs(os.path.join(f, "spool"))
        with open(self.conf, "w") as out:
            out.write("\n".join(lines) + "\n")

    def _wait_idle(self):
        deadline = time.monotonic() + 30
        state = ""
        while time.monotonic() < deadline:
            result = subprocess.run(["sinfo", "-h", "-o", "%T"], env=self.env, stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, text=True, timeout=10)
            state = result.stdout.strip()
            if result.returncode == 0 and state == "idle":
                return
            time.sleep(0.2)
        raise RuntimeError(f"the Slurm node did not become idle within 30 s (sinfo: {state!r}); "
                           f"see {self.folder}/slurmctld.log and slurmd.log")

    def run(self, argv, timeout=60):
        """(exit code, output) of argv with this cluster's environment."""
        result = subprocess.run(argv, env=self.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                timeout=timeout, stdin=subprocess.DEVNULL)
        return result.returncode, result.stdout

    def queue(self):
        code, text = self.run(["squeue", "-h", "-r", "-o", "%i|%T"])
        return text.split() if code == 0 else []

    def wait_empty(self, timeout):
        """Waits until no job is queued or running; False on timeout."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if not self.queue():
                return True
            time.sleep(0.2)
        return False

    def stop(self):
        if not self.pid_files:
            return
        if os.path.exists(os.path.join(self.folder, "slurmctld.pid")):
            try:
                self.run(["scancel", "--user=root"], timeout=10)  # this cluster's jobs only (SLURM_CONF)
                self.wait_empty(10)
            except (OSError, subprocess.TimeoutExpired):
                pass
        # slurmd, slurmctld, then munged: the reverse of their start.
        for pid_file in reversed(self.pid_files):
            try:
                with open(pid_file) as f:
                    pid = int(f.read().split()[0])
            except (OSError, ValueError, IndexError):
                continue
            try:
                os.kill(pid, signal.SIGTERM)
            except ProcessLookupError:
                continue
            deadline = time.monotonic() + 10
            while time.monotonic() < deadline and os.path.exists(f"/proc/{pid}") and not _zombie(pid):
                time.sleep(0.05)
            if os.path.exists(f"/proc/{pid}") and not _zombie(pid):
                os.kill(pid, signal.SIGKILL)
        self.pid_files = []


def _zombie(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(") ")[1].startswith("Z")
    except (OSError, IndexError):
        return True
