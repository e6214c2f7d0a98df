"""Writes grasp_drag.trace (Haptics trace format: t x y z qw qx qy qz buttons).

The stylus rests 3 cm left of the workspace centre, presses button 1 at 0.3 s, moves
(0, +1.5 cm, +1 cm) (screen up and toward the viewer) with a smooth-step profile until
1.3 s, holds until 1.6 s, releases and rests until 1.8 s. 60 samples per second.
Run: python3 make_grasp_drag.py > grasp_drag.trace
"""

START = (-0.03, 0.0, 0.0)
MOVE = (0.0, 0.015, 0.010)
PRESS, MOVE_END, RELEASE, END = 0.3, 1.3, 1.6, 1.8


def smoothstep(u):
    u = min(max(u, 0.0), 1.0)
    return u * u * (3.0 - 2.0 * u)


print("# grasp_drag: stylus trace (t x y z qw qx qy qz buttons, metres, device frame), made by make_grasp_drag.py")
print("# press at %.1f s, drag by %s m until %.1f s, release at %.1f s" % (PRESS, MOVE, MOVE_END, RELEASE))
n = int(round(END * 60))
for i in range(n + 1):
    t = i / 60.0
    s = smoothstep((t - PRESS) / (MOVE_END - PRESS))
    x, y, z = (a + s * b for a, b in zip(START, MOVE))
    buttons = 1 if PRESS <= t + 1e-9 < RELEASE else 0
    print("%.6f %.6f %.6f %.6f 1 0 0 0 %d" % (t, x, y, z, buttons))
