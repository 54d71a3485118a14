"""Meshes read by raylab-import, in the real window: a load whose helper crashes or needs more than
its memory limit fails with one line in the panel (and on stderr) while the viewer keeps its
scene, settings and picture and goes on drawing; Escape cancels a load that hangs at once (the
helper is killed); quitting during a load is prompt. The helper's misbehaviour comes from its
test hook, RAYLAB_IMPORT_TEST_CRASH (src/import/test_hooks.h)."""

import glob
import os
import time

from e2e_scene_path import type_path
from e2e_support import Viewer, check, same_pixels

TRIANGLE_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
# 309 bytes whose header claims 353,535,235,358 vertices (issue 15).
FORGED_OFF = ("OFF\n353535235358 1 0\n").ljust(309)
HOOK = "RAYLAB_IMPORT_TEST_CRASH"


def write(env, name, text):
    with open(env.path(name), "w") as f:
        f.write(text)
    return env.path(name)


def start_viewer(env, hook):
    """A viewer on the lab's box whose mesh imports misbehave as `hook` says (None: not at all)."""
    if hook is None:
        os.environ.pop(HOOK, None)
    else:
        os.environ[HOOK] = hook
    try:
        return Viewer(env, ["--width", "400", "--height", "300", "--spp", "2"])
    finally:
        os.environ.pop(HOOK, None)


def children(pid):
    """The process ids of pid's children (the helper, while a load runs)."""
    found = []
    for path in glob.glob(f"/proc/{pid}/task/*/children"):
        try:
            with open(path) as f:
                found += f.read().split()
        except OSError:
            pass
    return found


def wait_output(viewer, text, seconds):
    deadline = time.monotonic() + seconds
    while text not in viewer.output():
        viewer.check_running()
        check(time.monotonic() < deadline, f"no '{text}' within {seconds} s: {viewer.output()}")
        time.sleep(0.05)


def wait_helper(viewer, seconds=10):
    deadline = time.monotonic() + seconds
    while not children(viewer.proc.pid):
        viewer.check_running()
        check(time.monotonic() < deadline, f"no helper process within {seconds} s")
        time.sleep(0.05)


def check_kept(viewer, before, settings):
    """The scene, its settings and its picture are those of before the failed load."""
    again, kept = viewer.key_shot()
    check(kept.get("scene") == "cornell", f"the scene became {kept.get('scene')}")
    for part in ("camera", "light", "image"):
        check(kept[part] == settings[part], f"{part} changed: {kept[part]} != {settings[part]}")
    same_pixels(again, before, "the picture after the failed load")


def test_import_failures(env):
    """A helper that dies of SIGSEGV and a file past the memory limit: one line each, naming the
    file, and the viewer keeps its scene, settings and picture and goes on drawing."""
    write(env, "tri.obj", TRIANGLE_OBJ)
    viewer = start_viewer(env, "segv")
    try:
        before, settings = viewer.shot_when(lambda png, s: s["image"]["samples"] == 2,
                                            "no finished picture")
        type_path(viewer, env.path("tri.obj"))
        wait_output(viewer, f"cannot load mesh '{env.path('tri.obj')}': the importer crashed "
                    "(SIGSEGV)", 20)
        check_kept(viewer, before, settings)
        viewer.quit()
    finally:
        viewer.kill()
    write(env, "forged.off", FORGED_OFF)
    viewer = start_viewer(env, None)
    try:
        before, settings = viewer.shot_when(lambda png, s: s["image"]["samples"] == 2,
                                            "no finished picture")
        start = time.monotonic()
        type_path(viewer, env.path("forged.off"))
        wait_output(viewer, f"cannot load mesh '{env.path('forged.off')}': needed more than", 20)
        check(time.monotonic() - start < 10, "refusing the forged header took 10 s or more")
        check_kept(viewer, before, settings)
        viewer.quit()
    finally:
        viewer.kill()


def test_import_cancel(env):
    """Escape while a load hangs kills its helper at once; the viewer keeps its scene and picture,
    goes on, and the next Escape quits."""
    write(env, "tri.obj", TRIANGLE_OBJ)
    viewer = start_viewer(env, "hang")
    try:
        before, settings = viewer.shot_when(lambda png, s: s["image"]["samples"] == 2,
                                            "no finished picture")
        type_path(viewer, env.path("tri.obj"))
        wait_helper(viewer)
        time.sleep(0.5)
        start = time.monotonic()
        viewer.xdotool("key", "Escape")
        wait_output(viewer, f"cancelled loading {env.path('tri.obj')}", 5)
        while children(viewer.proc.pid):
            check(time.monotonic() - start < 2, "the helper still runs 2 s after Escape")
            time.sleep(0.02)
        check_kept(viewer, before, settings)
        check("took longer than" not in viewer.output(), "the load ran into its time limit")
        viewer.quit()
    finally:
        viewer.kill()


def test_import_quit(env):
    """Quitting while a load hangs (the helper's time limit is 60 s) takes well under a second
    more than the frames asked for, leaves no helper behind and exits 0."""
    write(env, "tri.obj", TRIANGLE_OBJ)
    os.environ[HOOK] = "hang"
    try:
        start = time.monotonic()
        result = env.run(env.raylab, ["--width", "160", "--height", "120", "--spp", "1",
                                      "--no-panel", "--drop", env.path("tri.obj"), "--frames",
                                      "60"], timeout=60)
        seconds = time.monotonic() - start
    finally:
        os.environ.pop(HOOK, None)
    check(result.returncode == 0, f"the viewer exited {result.returncode}: {result.stderr}")
    check(seconds < 10, f"quitting during the load took {seconds:.1f} s")
    check("took longer than" not in result.stderr, f"the viewer waited for the load: "
          f"{result.stderr}")
    mesh = env.path("tri.obj").encode()
    leftover = [p for p in os.listdir("/proc") if p.isdigit() and mesh in _command_line(p)]
    check(not leftover, f"processes left behind: {leftover}")


def _command_line(pid):
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            return f.read()
    except OSError:
        return b""
