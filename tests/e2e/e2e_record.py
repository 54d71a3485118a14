"""--record and --replay in the real window: a session scripted with xdotool (keys, a Ctrl+click,
the split, the observer view, screenshots) is recorded; replaying the recording writes each of
its screenshots again, pixel for pixel, with the same settings files."""

import filecmp
import json
import os

from e2e_support import PANEL_COLUMN, Viewer, check, same_pixels
from pngread import read_png


def shot_files(folder):
    return sorted(name for name in os.listdir(folder) if name.startswith("raylab-"))


def inspections(output):
    return [json.loads(line) for line in output.splitlines() if line.startswith("{")]


# A floor and a pyramid on it: a mesh the session opens (dropped) after starting on the box.
MESH = """v -2 0 -2
v 2 0 -2
v 2 0 2
v -2 0 2
v -0.5 0 -0.5
v 0.5 0 -0.5
v 0.5 0 0.5
v -0.5 0 0.5
v 0 1 0
f 1 3 2
f 1 4 3
f 5 6 9
f 6 7 9
f 7 8 9
f 8 5 9
"""
CAP = 4096  # samples per pixel: far more than the session's seconds reach


def test_record(env):
    recording = env.path("session.json")
    mesh = env.path("pyramid.obj")
    with open(mesh, "w") as f:
        f.write(MESH)
    viewer = Viewer(env, ["--width", "240", "--height", "180", "--spp", str(CAP),
                          "--record", recording, "--drop", mesh])
    try:
        viewer.shot_when(lambda png, settings: settings.get("scene") == mesh,
                         "the dropped mesh did not open")
        viewer.key_shot("w", "Up", "Left")  # the light forward, the camera forward and turned
        viewer.xdotool("mousemove", "--window", viewer.window, str(PANEL_COLUMN + 150), "120")
        viewer.xdotool("keydown", "ctrl", "click", "1", "keyup", "ctrl")
        viewer.key_shot("v")  # the albedo view
        viewer.key_shot("shift+v", "k", "e")  # beauty; A kept and split; the light again
        viewer.key_shot("b", "o")  # the split off; the observer view
        viewer.key_shot("o", "ctrl+z")  # back to the lab camera; its last move undone
        viewer.quit()
    finally:
        viewer.kill()
    recorded = shot_files(viewer.shots)
    pngs = [n for n in recorded if n.endswith(".png")]
    check(len(pngs) >= 6, f"the session saved {recorded}")

    session = json.load(open(recording))
    events = session["events"]
    shots = [e["screenshot"] for e in events if "screenshot" in e]
    states = [e["state"] for e in events if "state" in e]
    check(len(shots) == len(pngs), f"the recording holds {len(shots)} screenshots, the session "
          f"saved {len(pngs)}")
    check([s["settings"]["scene"] for s in states][0] == "cornell" and
          states[-1]["settings"]["scene"] == mesh, "the recording does not open the mesh")
    check(any("compare" in s for s in states), "the split is not in the recording")
    check(any("lab_camera" in s["settings"].get("observer", {}) for s in states),
          "the observer view is not in the recording")
    check(any("inspected" in s for s in states), "the inspected pixel is not in the recording")
    frames = [e["frame"] for e in events]
    check(frames == sorted(frames) and frames[-1] <= session["frames"],
          f"frames out of order: {frames}, of {session['frames']}")

    replay_shots = env.path("replayed")
    os.makedirs(replay_shots)
    result = env.run(env.raylab, ["--replay", recording, "--screenshot-dir", replay_shots],
                     timeout=300)
    check(result.returncode == 0,
          f"the replay exited {result.returncode}: {result.stderr.strip()[-600:]}")
    replayed = shot_files(replay_shots)
    check(replayed == recorded, f"the replay wrote {replayed}, the session {recorded}")
    for name in recorded:
        mine, theirs = os.path.join(viewer.shots, name), os.path.join(replay_shots, name)
        if name.endswith(".png"):
            same_pixels(read_png(theirs), read_png(mine), f"replayed {name}")
        elif name.endswith(".json"):
            check(json.load(open(theirs)) == json.load(open(mine)),
                  f"replayed {name} differs from the session's")
        else:  # the linear pictures (.exr)
            check(filecmp.cmp(theirs, mine, shallow=False),
                  f"replayed {name} differs from the session's")
    samples = {json.load(open(os.path.join(viewer.shots, n)))["image"]["samples"]
               for n in recorded if n.endswith(".json")}
    check(len(samples) > 1 and max(samples) < CAP,
          f"the screenshots' samples {samples}: the replay's exact samples are not tested")
    seen = inspections(viewer.output())
    check(len(seen) == 1 and inspections(result.stdout) == seen,
          f"the replay printed the inspections {inspections(result.stdout)}, the session {seen}")

    # A broken or missing recording: one line, exit 1, no window.
    broken = env.path("broken.json")
    with open(broken, "w") as f:
        f.write(json.dumps({"raylab_recording": 1, "frames": 3,
                            "events": [{"frame": 0, "screenshot": {"samples": 1}}]}))
    for path in (broken, env.path("none.json")):
        result = env.run(env.raylab, ["--replay", path])
        lines = result.stderr.strip().splitlines()
        check(result.returncode == 1 and len(lines) == 1 and os.path.basename(path) in lines[0],
              f"--replay {os.path.basename(path)}: exit {result.returncode}, {result.stderr!r}")
    result = env.run(env.raylab, ["--record", env.path("no/such/folder/x.json")])
    check(result.returncode == 1 and len(result.stderr.strip().splitlines()) == 1,
          f"--record into a missing folder: exit {result.returncode}, {result.stderr!r}")
