"""A real single-node Slurm cluster for one test: munged, slurmctld and slurmd on localhost, each
with its configuration, state, logs and sockets in a folder of its own and on ports nobody else
uses, so it never touches a Slurm the machine may already run. Needs root (slurmd starts jobs as
their users) and Debian's slurm-wlm and munge. Standard library only."""

import os
import shutil
import socket
import subprocess
import tempfile
import time

PROGRAMS = ["munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scancel"]


class Unavailable(Exception):
    """Slurm cannot run here; the message says why (the test then skips)."""


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Cluster:
    def __init__(self):
        missing = [p for p in PROGRAMS if shutil.which(p) is None]
        if missing:
            raise Unavailable(f"not installed: {', '.join(missing)} (Debian's slurm-wlm, munge)")
        if os.geteuid() != 0:
            raise Unavailable("slurmd must run as root to start jobs")
        self.dir = tempfile.mkdtemp(prefix="raylab-slurm-")
        os.chmod(self.dir, 0o755)  # munge wants its socket's folder readable by all
        for sub in ("state", "spool", "log"):
            os.makedirs(os.path.join(self.dir, sub))
        self.pids = []
        try:
            self._start()
        except Exception:
            self.stop()
            raise

    def path(self, name):
        return os.path.join(self.dir, name)

    def env(self, **extra):
        env = dict(os.environ, SLURM_CONF=self.path("slurm.conf"))
        env.update(extra)
        return env

    def run(self, args, timeout=60, **extra):
        return subprocess.run(args, env=self.env(**extra), capture_output=True, text=True,
                              timeout=timeout)

    def _start(self):
        key = self.path("munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o600)
        socket_path = self.path("munge.sock")
        started = subprocess.run(
            ["munged", "--force", f"--socket={socket_path}", f"--key-file={key}",
             f"--log-file={self.path('log/munged.log')}", f"--pid-file={self.path('munged.pid')}",
             f"--seed-file={self.path('munged.seed')}"], capture_output=True, text=True)
        if started.returncode != 0:
            raise Unavailable(f"munged did not start: {started.stderr.strip()}")
        self.pids.append(self._wait_for_pid("munged.pid", "munged"))
        host = socket.gethostname().split(".")[0]
        conf = f"""ClusterName=raylabtest
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
AuthType=auth/munge
AuthInfo=socket={socket_path}
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation={self.path('state')}
SlurmdSpoolDir={self.path('spool')}
SlurmctldPidFile={self.path('slurmctld.pid')}
SlurmdPidFile={self.path('slurmd.pid')}
SlurmctldLogFile={self.path('log/slurmctld.log')}
SlurmdLogFile={self.path('log/slurmd.log')}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
NodeName={host} NodeAddr=127.0.0.1 CPUs={os.cpu_count()} State=UNKNOWN
PartitionName=raylab Nodes=ALL Default=YES MaxTime=INFINITE State=UP
"""
        with open(self.path("slurm.conf"), "w") as f:
            f.write(conf)
        for daemon, pid in (("slurmctld", "slurmctld.pid"), ("slurmd", "slurmd.pid")):
            result = self.run([daemon, "-f", self.path("slurm.conf")])
            if result.returncode != 0:
                raise Unavailable(f"{daemon} did not start: {result.stderr.strip()} "
                                  f"{self.log_tail(daemon)}")
            self.pids.append(self._wait_for_pid(pid, daemon))
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            state = self.run(["sinfo", "--noheader", "--format=%t"]).stdout.strip()
            if state in ("idle", "mix", "alloc"):
                return
            time.sleep(0.5)
        raise Unavailable(f"the node did not come up (state {state!r}) "
                          f"{self.log_tail('slurmd')}")

    def _wait_for_pid(self, name, daemon):
        """The pid in the daemon's pid file, once the file exists and holds it (the daemon
        creates the file before it writes the number)."""
        deadline = time.monotonic() + 20
        while True:
            try:
                with open(self.path(name)) as f:
                    words = f.read().split()
                if words and words[0].isdigit():
                    return int(words[0])
            except OSError:
                pass
            if time.monotonic() > deadline:
                raise Unavailable(f"{daemon} wrote no pid file {self.log_tail(daemon)}")
            time.sleep(0.1)

    def log_tail(self, daemon):
        try:
            with open(self.path(f"log/{daemon}.log")) as f:
                return "| " + " | ".join(f.read().strip().splitlines()[-3:])
        except OSError:
            return ""

    def submit(self, args, **extra):
        """sbatch --parsable ARGS; returns the job id."""
        result = self.run(["sbatch", "--parsable"] + args, **extra)
        if result.returncode != 0:
            raise RuntimeError(f"sbatch {' '.join(args)}: {result.stderr.strip()}")
        return result.stdout.strip().split(";")[0]

    def states(self, job):
        """The states of a job's tasks still known to squeue (empty once all have ended)."""
        result = self.run(["squeue", "--noheader", "--jobs", job, "--format=%T"])
        return result.stdout.split() if result.returncode == 0 else []

    def wait(self, job, timeout=180):
        deadline = time.monotonic() + timeout
        while self.states(job):
            if time.monotonic() > deadline:
                raise RuntimeError(f"job {job} still queued after {timeout} s")
            time.sleep(0.5)

    def stop(self):
        if os.path.exists(self.path("slurm.conf")):
            self.run(["scancel", "--full", "--user=root"])
        for pid in reversed(self.pids):
            try:
                os.kill(pid, 15)
            except ProcessLookupError:
                continue
            for _ in range(100):
                try:
                    os.kill(pid, 0)
                except ProcessLookupError:
                    break
                time.sleep(0.1)
        self.pids = []
        shutil.rmtree(self.dir, ignore_errors=True)
