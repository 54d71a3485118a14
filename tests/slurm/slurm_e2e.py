#!/usr/bin/env python3
"""raylab's Slurm scripts on a real Slurm cluster (slurm_cluster.py starts one on this machine):

- a path-traced picture split into sample ranges over an array job, merged by the dependent job,
  is the single machine's picture byte for byte;
- a task that fails leaves no part; the merge then names the missing samples, exits 1 and writes
  nothing; submitting that task again completes the picture;
- a task cancelled while it renders leaves no part;
- a turntable split into frames gives each frame as raylab-render draws it.

    slurm_e2e.py --render RAYLAB_RENDER --merge RAYLAB_MERGE --scripts scripts/slurm

exits 0 (pass), 1 (fail) or 77 (skip: Slurm cannot start here, with the reason)."""

import argparse
import glob
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from slurm_cluster import Cluster, Unavailable  # noqa: E402

SKIP = 77
SIZE = ["--width", "96", "--height", "72"]
FLAGS = ["cornell", "--integrator", "path", "--light-radius", "0.05"] + SIZE


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def run_ok(args):
    result = subprocess.run(args, capture_output=True, text=True, timeout=300)
    check(result.returncode == 0, f"{' '.join(args)}: exit {result.returncode}: "
          f"{result.stderr.strip()}")
    return result


def test(cluster, work, render, merge, scripts):
    tools = {"RAYLAB_RENDER": render, "RAYLAB_MERGE": merge}
    render_script = os.path.join(scripts, "render.sbatch")
    merge_script = os.path.join(scripts, "merge.sbatch")
    log = os.path.join(work, "slurm-%A-%a.txt")

    # The single machine's picture.
    single = os.path.join(work, "single.pfm")
    run_ok([render] + FLAGS + ["--spp", "12", "-o", single])

    # The array job and the dependent merge: the two commands of the README.
    parts = os.path.join(work, "parts")
    merged = os.path.join(work, "merged.pfm")
    job = cluster.submit(["--array=0-3", f"--output={log}", render_script, "samples", parts,
                          "12", "4"] + FLAGS, **tools)
    merge_job = cluster.submit([f"--dependency=afterok:{job}", f"--output={log}", merge_script,
                                parts, merged], **tools)
    cluster.wait(job)
    cluster.wait(merge_job)
    check(sorted(os.listdir(parts)) == [f"part-{k}.exr" for k in range(4)],
          f"parts written: {sorted(os.listdir(parts))}")
    check(os.path.exists(merged), f"the merge job wrote nothing: {logs(work)}")
    check(read(merged) == read(single), "the merged picture differs from the single render")

    # A task that fails (its part's path is a folder) leaves no part; the merge names what is
    # missing and writes nothing; task 2 submitted again completes the picture.
    parts2 = os.path.join(work, "parts2")
    os.makedirs(os.path.join(parts2, "part-2.exr"))
    job = cluster.submit(["--array=0-3", f"--output={log}", render_script, "samples", parts2,
                          "12", "4"] + FLAGS, **tools)
    cluster.wait(job)
    os.rmdir(os.path.join(parts2, "part-2.exr"))
    check(sorted(os.listdir(parts2)) == ["part-0.exr", "part-1.exr", "part-3.exr"],
          f"after a failed task: {sorted(os.listdir(parts2))}")
    merged2 = os.path.join(work, "merged2.pfm")
    result = subprocess.run([merge] + sorted(glob.glob(os.path.join(parts2, "part-*.exr"))) +
                            ["-o", merged2], capture_output=True, text=True)
    check(result.returncode == 1 and "samples 6:9" in result.stderr and
          result.stderr.count("\n") == 1, f"merge with a task missing: {result.stderr!r}")
    check(not os.path.exists(merged2), "a failed merge left a picture")
    job = cluster.submit(["--array=2", f"--output={log}", render_script, "samples", parts2, "12",
                          "4"] + FLAGS, **tools)
    cluster.wait(job)
    job = cluster.submit([f"--output={log}", merge_script, parts2, merged2], **tools)
    cluster.wait(job)
    check(os.path.exists(merged2) and read(merged2) == read(single),
          f"re-submitting the missing task did not complete the picture: {logs(work)}")

    # A task cancelled while it renders leaves no part (and no temporary file).
    parts3 = os.path.join(work, "parts3")
    job = cluster.submit(["--array=0", f"--output={log}", render_script, "samples", parts3,
                          "65536", "1", "cornell", "--integrator", "path", "--width", "640",
                          "--height", "480"], **tools)
    deadline = time.monotonic() + 60
    while "RUNNING" not in cluster.states(job):
        check(time.monotonic() < deadline, f"the long task never ran: {cluster.states(job)}")
        time.sleep(0.2)
    time.sleep(1.0)
    cluster.run(["scancel", job])
    cluster.wait(job)
    left = os.listdir(parts3) if os.path.isdir(parts3) else []
    check(left == [], f"a cancelled task left {left}")

    # Frames: a turntable of 3 frames, one per task, each as raylab-render draws it.
    frames = os.path.join(work, "frames")
    job = cluster.submit(["--array=0-2", f"--output={log}", render_script, "frames", frames,
                          "cornell", "--turntable", "3"] + SIZE, **tools)
    cluster.wait(job)
    for k in range(3):
        expected = os.path.join(work, f"expected-{k}.png")
        run_ok([render, "cornell", "--turntable", "3", "--frame", str(k)] + SIZE +
               ["-o", expected])
        got = os.path.join(frames, f"frame-{k:04d}.png")
        check(os.path.exists(got), f"no {got}: {logs(work)}")
        check(read(got) == read(expected), f"frame {k} differs from raylab-render's")


def logs(work):
    text = []
    for path in sorted(glob.glob(os.path.join(work, "slurm-*.txt"))):
        content = open(path).read().strip()
        if content:
            text.append(f"{os.path.basename(path)}: {content}")
    return " | ".join(text)[-600:]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--render", required=True)
    parser.add_argument("--merge", required=True)
    parser.add_argument("--scripts", required=True)
    args = parser.parse_args()
    try:
        cluster = Cluster()
    except Unavailable as why:
        print(f"SKIP slurm: {why}")
        return SKIP
    try:
        with tempfile.TemporaryDirectory(prefix="raylab-slurm-work-") as work:
            os.chmod(work, 0o755)
            test(cluster, work, os.path.abspath(args.render), os.path.abspath(args.merge),
                 os.path.abspath(args.scripts))
    except Failure as failure:
        print(f"FAIL slurm: {failure}")
        return 1
    finally:
        cluster.stop()
    print("PASS slurm")
    return 0


if __name__ == "__main__":
    sys.exit(main())
