"""Writes grasp_drag.trace (Haptics trace format: t x y z qw qx qy qz buttons).

The stylus rests 3 cm left of the workspace centre (0.9 cm up, 1.2 cm toward the user: in the
GUI test's camera, on the horizon's upper side), presses button 1 at 1 s, keeps still
until 1.5 s, moves (0, +1.5 cm, +1 cm) (screen up and toward the viewer) with a
smooth-step profile until 2.5 s, holds until 4 s, releases and rests until 4.2 s. 60
samples per second. The interactor samples the stylus at its frame rate, so the rests
let a slow renderer (llvmpipe under xvfb, a few frames per second) grasp where the press
happened and see the end of the drag.
Run: python3 make_grasp_drag.py > grasp_drag.trace
"""

START = (-0.03, 0.009, 0.012)  # on the upper side of the step in the test camera
MOVE = (0.0, 0.015, 0.010)
PRESS, MOVE_START, MOVE_END, RELEASE, END = 1.0, 1.5, 2.5, 4.0, 4.2


def smoothstep(u):
    u = min(max(u, 0.0), 1.0)
    return u * u * (3.0 - 2.0 * u)


print("# grasp_drag: stylus trace (t x y z qw qx qy qz buttons, metres, device frame), made by make_grasp_drag.py")
print("# press at %.1f s, drag by %s m from %.1f s to %.1f s, release at %.1f s"
      % (PRESS, MOVE, MOVE_START, MOVE_END, RELEASE))
n = int(round(END * 60))
for i in range(n + 1):
    t = i / 60.0
    s = smoothstep((t - MOVE_START) / (MOVE_END - MOVE_START))
    x, y, z = (a + s * b for a, b in zip(START, MOVE))
    buttons = 1 if PRESS <= t + 1e-9 < RELEASE else 0
    print("%.6f %.6f %.6f %.6f 1 0 0 0 %d" % (t, x, y, z, buttons))
