"""A private X display for one end-to-end test: Xvfb started with -displayfd, so the server itself
picks a display number that is free and tells it back once it accepts connections. (xvfb-run -a
picks the number by looking for lock files first, which races with a server that is still
shutting down: a client can connect to the dying server and die of SIGPIPE.) Standard library
only."""

import os
import select
import shutil
import subprocess
import tempfile
import time

SCREEN = "1280x800x24"


class DisplayError(Exception):
    pass


def end_process(proc, timeout=10):
    """SIGTERM, then SIGKILL after `timeout` seconds; returns once the process has ended."""
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


class Display:
    """Xvfb on a display of its own; DISPLAY names it while the object is entered."""

    def __init__(self, timeout=30):
        program = shutil.which("Xvfb")
        if program is None:
            raise DisplayError("Xvfb is not installed: run scripts/install-deps.sh")
        self.log = tempfile.TemporaryFile(mode="w+")
        read_end, write_end = os.pipe()
        try:
            self.proc = subprocess.Popen(
                [program, "-displayfd", str(write_end), "-screen", "0", SCREEN, "-nolisten",
                 "tcp", "-noreset"], pass_fds=(write_end,), stdout=self.log,
                stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        finally:
            os.close(write_end)
        try:
            self.number = self._read_number(read_end, timeout)
        finally:
            os.close(read_end)

    def _read_number(self, read_end, timeout):
        deadline = time.monotonic() + timeout
        text = b""
        while not text.endswith(b"\n"):
            left = deadline - time.monotonic()
            ready, _, _ = select.select([read_end], [], [], max(left, 0))
            chunk = os.read(read_end, 64) if ready else b""
            if not chunk:
                self.stop()
                self.log.seek(0)
                reason = "did not start in time" if not ready else "ended"
                raise DisplayError(f"Xvfb {reason}: {self.log.read().strip()}")
            text += chunk
        return int(text.strip())

    def __enter__(self):
        self.previous = os.environ.get("DISPLAY")
        os.environ["DISPLAY"] = f":{self.number}"
        return self

    def __exit__(self, *exception):
        if self.previous is None:
            os.environ.pop("DISPLAY", None)
        else:
            os.environ["DISPLAY"] = self.previous
        self.stop()
        return False

    def alive(self):
        return self.proc.poll() is None

    def stop(self):
        """Ends the server and waits for it, so its display number is free when this returns."""
        end_process(self.proc)
