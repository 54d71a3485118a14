"""The panel over the picture, drawn from its cached pixels (src/viewer/panel_cache.h): what the
window shows (--readback) is the CPU image outside the panel, exactly, and the panel inside it;
hovering the panel's button shows at once; F1 hides it and shows it again."""

import time

from e2e_support import PANEL_BUTTON, Viewer, check
from pngread import read_png

SIZE = ["--width", "480", "--height", "360"]
PANEL_RIGHT = 8 + 340  # kPanelX + kPanelWidth
BUTTON_BACKGROUND = (20, 44)  # inside the screenshot button, left of its text
BUTTON_HOVERED = (66, 150, 250)  # Dear ImGui's dark style, ButtonHovered (opaque)


def near(a, b, tolerance=3):
    return all(abs(x - y) <= tolerance for x, y in zip(a, b))


def test_panel(env):
    """Scripted run with the panel: outside the panel the window is the screenshot, pixel for
    pixel; inside, the panel shows (most pixels differ). Then a real window: the mouse on the
    screenshot button highlights it in the very frames that follow. Last, F1 three times (hide,
    show, hide): the window is the picture again, pixel for pixel."""
    env.run_ok(env.raylab, SIZE + ["--spp", "2", "--frames", "5", "--screenshot", "s.png",
                                   "--readback", "r.png"])
    image, window = read_png(env.path("s.png")), read_png(env.path("r.png"))
    check((window.width, window.height) == (image.width, image.height) == (480, 360),
          f"sizes {window.width}x{window.height}, {image.width}x{image.height}")
    margin = PANEL_RIGHT + 8
    for y in range(window.height):
        for x in range(margin, window.width):
            if window.pixel(x, y) != image.pixel(x, y):
                check(False, f"outside the panel, window pixel ({x}, {y}) = {window.pixel(x, y)}"
                      f" but the picture has {image.pixel(x, y)}")
    inside = [(x, y) for y in range(10, 200) for x in range(10, PANEL_RIGHT - 2)]
    differ = sum(window.pixel(x, y) != image.pixel(x, y) for x, y in inside)
    check(differ > 0.9 * len(inside),
          f"only {differ} of {len(inside)} pixels of the panel's area show the panel")
    idle_button = window.pixel(*BUTTON_BACKGROUND)[:3]
    check(not near(idle_button, BUTTON_HOVERED),
          f"the button looks hovered with no mouse over it: {idle_button}")

    # 240 frames take 4 s: the mouse reaches the button well before the last one, read back.
    viewer = Viewer(env, SIZE + ["--spp", "4", "--frames", "240", "--readback", "hover.png"])
    try:
        viewer.xdotool("mousemove", "--window", viewer.window, str(PANEL_BUTTON[0]),
                       str(PANEL_BUTTON[1]))
        start = time.monotonic()
        code = viewer.proc.wait(timeout=60)
        check(code == 0, f"the viewer exited {code}: {viewer.output()}")
        check(time.monotonic() - start > 0.5, "the run ended too soon after the mouse moved")
    finally:
        viewer.kill()
    hovered = read_png(env.path("hover.png"))
    button = hovered.pixel(*BUTTON_BACKGROUND)[:3]
    check(near(button, BUTTON_HOVERED),
          f"the mouse on the button: pixel {BUTTON_BACKGROUND} = {button}, expected the hovered "
          f"colour {BUTTON_HOVERED}")

    viewer = Viewer(env, SIZE + ["--spp", "4", "--frames", "240", "--screenshot", "f1.png",
                                 "--readback", "f1-window.png"])
    try:
        for _ in range(3):
            viewer.xdotool("key", "F1")
            time.sleep(0.3)
        code = viewer.proc.wait(timeout=60)
        check(code == 0, f"the viewer exited {code}: {viewer.output()}")
    finally:
        viewer.kill()
    image, window = read_png(env.path("f1.png")), read_png(env.path("f1-window.png"))
    for y in range(window.height):
        for x in range(window.width):
            if window.pixel(x, y) != image.pixel(x, y):
                check(False, f"after F1 hid the panel, window pixel ({x}, {y}) = "
                      f"{window.pixel(x, y)} but the picture has {image.pixel(x, y)}")
