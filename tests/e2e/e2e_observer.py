"""The observer view in the real window: O switches to a second camera that sees the lab camera
from outside. Its screenshot is raylab-render's picture from the observer's camera (the settings
keep the lab camera); the window draws the lab camera's frustum over it where the observer's
camera projects it; moving the observer (keys, a bookmark) leaves the lab camera as it was, and O
again returns to the lab camera's picture, byte for byte. The observer's settings file starts a
viewer in the observer view."""

import json
import math

from e2e_support import Viewer, check, same_pixels
from e2e_teach import FOREVER, has_colour_near
from pngread import read_png

LAB_CAMERA = {"position": [0.0, 0.0, -3.0], "yaw": 0.0, "pitch": 0.0, "fov": 53.1301}
FRUSTUM = (255, 255, 255)  # ray_overlay_geometry.h's overlayColour(OverlayRay::LabCamera)
LAB_BOX_CENTRE = (0.0, 0.0, 0.0)  # the lab's box spans [-1, 1] on each axis
LAB_BOX_SIZE = 2.0 * math.sqrt(3.0)  # its diagonal


def basis(camera):
    """core/camera.h's worldFromCamera: right, up, forward of a settings file's camera."""
    yaw, pitch = math.radians(camera["yaw"]), math.radians(camera["pitch"])
    forward = (math.sin(yaw) * math.cos(pitch), math.sin(pitch), math.cos(yaw) * math.cos(pitch))
    right = (-math.cos(yaw), 0.0, math.sin(yaw))
    up = (right[1] * forward[2] - right[2] * forward[1],
          right[2] * forward[0] - right[0] * forward[2],
          right[0] * forward[1] - right[1] * forward[0])
    return right, up, forward


def focal(camera, height):
    return 0.5 * height / math.tan(math.radians(camera["fov"]) / 2.0)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def project(point, camera, width, height):
    """Where `camera` sees the world `point` in a width x height picture: (x, y) in pixels, y
    down, and its depth."""
    right, up, forward = basis(camera)
    d = [p - o for p, o in zip(point, camera["position"])]
    cx, cy, cz = dot(d, right), dot(d, up), dot(d, forward)
    f = focal(camera, height)
    return (width / 2 + f * cx / cz, height / 2 - f * cy / cz), cz


def frustum_corners(camera, width, height):
    """observer_geometry.h's image plane corners for the lab's box: at half the depth of the box's
    centre (at least a quarter of its size), on the rays through the picture's corners."""
    right, up, forward = basis(camera)
    o = camera["position"]
    depth = max(0.5 * dot([c - p for c, p in zip(LAB_BOX_CENTRE, o)], forward),
                0.25 * LAB_BOX_SIZE)
    f = focal(camera, height)
    corners = []
    for px, py in ((0, 0), (width, 0), (width, height), (0, height)):
        a, b = (px - width / 2) / f, (height / 2 - py) / f
        corners.append([o[k] + depth * (forward[k] + a * right[k] + b * up[k]) for k in range(3)])
    return corners


def lerp(a, b, t):
    return [x + (y - x) * t for x, y in zip(a, b)]


def same_camera(a, b):
    return all(abs(x - y) < 1e-4 for x, y in zip(a["position"], b["position"])) and all(
        abs(a[k] - b[k]) < 1e-3 for k in ("yaw", "pitch", "fov"))


def render_from(env, settings, name):
    """raylab-render's picture from a screenshot's settings file."""
    with open(env.path(name + ".json"), "w") as f:
        json.dump(settings, f)
    env.run_ok(env.render, ["--settings", env.path(name + ".json"), "-o", env.path(name)])
    return read_png(env.path(name))


def at_cap(observer):
    """Whether a screenshot is of the observer view (or not) with its 2 samples."""
    return lambda png, s: s["image"]["samples"] == 2 and ("observer" in s) == observer


def press_o(viewer, observer, what):
    """O, then (png, settings) of the switched view's picture at the cap."""
    viewer.xdotool("key", "o")
    return viewer.shot_when(at_cap(observer), what)


def test_observer(env):
    width, height = 320, 240
    size = ["--width", str(width), "--height", str(height), "--spp", "2"]
    viewer = Viewer(env, size + ["--no-panel", "--readback", "back.png"] + FOREVER)

    try:
        lab_png, lab = viewer.shot_when(at_cap(False), "no lab picture at the cap")
        check(same_camera(lab["camera"], LAB_CAMERA), f"not the lab's camera: {lab['camera']}")
        seen_png, seen = press_o(viewer, True, "O did not switch to the observer")
        viewer.xdotool("key", "--delay", "80", "Up", "Up")
        moved_png, moved = viewer.shot_when(
            lambda png, s: s["camera"] != seen["camera"] and s["image"]["samples"] == 2,
            "Up did not move the observer")
        # A bookmark in the observer view keeps and restores the observer's camera.
        viewer.xdotool("key", "--delay", "80", "ctrl+1", "Up")
        viewer.shot_when(lambda png, s: s["camera"] != moved["camera"],
                         "Up did not move the observer again")
        _, marked = viewer.key_shot("1")
        back_png, back = press_o(viewer, False, "O did not return to the lab camera")
        again_png, again = press_o(viewer, True, "O did not return to the observer")
        viewer.quit()
    finally:
        viewer.kill()

    # The observer's picture is the tracer's, from the observer's camera in the settings.
    check(seen["observer"]["lab_camera"] == lab["camera"],
          f"the observer's settings keep {seen['observer']['lab_camera']}, not the lab camera "
          f"{lab['camera']}")
    check(seen["camera"] != lab["camera"], "the observer view renders from the lab camera")
    same_pixels(seen_png, render_from(env, seen, "observer.png"),
                "the observer's screenshot vs raylab-render from its settings")
    check(seen_png.rgba != lab_png.rgba, "the observer's picture is the lab camera's")
    # It sees the lab camera from behind and above.
    (x, y), depth = project(LAB_CAMERA["position"], seen["camera"], width, height)
    check(depth > 0 and 0 <= x < width and 0 <= y < height,
          f"the observer does not see the lab camera: ({x:.1f}, {y:.1f}), depth {depth:.2f}")

    # Moving the observer keeps the lab camera; O returns to it, its picture byte for byte.
    check(moved["observer"]["lab_camera"] == lab["camera"],
          f"moving the observer changed the lab camera to {moved['observer']['lab_camera']}")
    check(moved["camera"]["position"][2] > seen["camera"]["position"][2],
          "Up did not move the observer forward")
    check(marked["camera"] == moved["camera"] and marked["bookmarks"][0] == moved["camera"],
          f"1 returned the observer to {marked['camera']}, not its bookmark {moved['camera']}")
    check(marked["observer"]["lab_camera"] == lab["camera"], "the bookmark moved the lab camera")
    check(back["camera"] == lab["camera"], f"O returned to {back['camera']}, not the lab camera")
    same_pixels(back_png, lab_png, "the lab camera's picture after the observer view vs before")
    check(again["camera"] == moved["camera"], "the observer did not come back where it was left")
    same_pixels(again_png, moved_png, "the observer's picture after returning vs before")

    # The window shows the lab camera's frustum edges and image plane where the observer's
    # camera projects them.
    window = read_png(env.path("back.png"))
    corners = frustum_corners(lab["camera"], width, height)
    points = []
    for i, corner in enumerate(corners):
        points += [lerp(lab["camera"]["position"], corner, t) for t in (0.5, 0.8)]
        points += [lerp(corner, corners[(i + 1) % 4], t) for t in (0.3, 0.7)]
    checked = 0
    for point in points:
        (x, y), depth = project(point, again["camera"], width, height)
        if depth > 0.05 and 2 <= x < width - 2 and 2 <= y < height - 2:
            check(has_colour_near(window, x, y, FRUSTUM, reach=3),
                  f"the frustum's point {[round(c, 3) for c in point]} projects to "
                  f"({x:.1f}, {y:.1f}) but the window has no frustum line there")
            checked += 1
    check(checked >= 12, f"the observer sees only {checked} of the frustum's points")

    # The observer's settings file starts a viewer in the observer view with both cameras; O
    # then returns to the lab camera it kept.
    viewer = Viewer(env, ["--settings", env.path("observer.png.json"), "--no-panel"])
    try:
        restored_png, restored = viewer.shot_when(at_cap(True), "--settings did not restore it")
        _, lab_again = press_o(viewer, False, "O did not return to the lab camera")
        viewer.quit()
    finally:
        viewer.kill()
    check(restored["camera"] == seen["camera"] and restored["observer"] == seen["observer"],
          f"--settings restored {restored['camera']} and {restored['observer']}")
    same_pixels(restored_png, seen_png, "the restored observer view vs the screenshot")
    check(lab_again["camera"] == lab["camera"], f"O returned to {lab_again['camera']}")
