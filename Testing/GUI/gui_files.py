"""The files a GUI test writes and reads: the stylus traces the replay device plays (and
their mapping into the scene through the test camera) and the figures the plugin's test
hook writes (`key = value` lines)."""
import math

from gui_setup_camera import CAMERA

WORKSPACE_RADIUS = 0.08  # m, the default DeviceLimits of the replay device


def read_trace(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    return [(float(r[0]), [float(v) for v in r[1:4]], int(r[8])) for r in rows]


def device_axes():
    """The workspace -> scene mapping of HapticsControl.h, computed independently:
    scene = focal + scale * (x p_x + y p_y + z p_z)."""
    pos, foc, up = CAMERA["position"], CAMERA["focal_point"], CAMERA["view_up"]
    z = [p - f for p, f in zip(pos, foc)]
    dist = math.sqrt(sum(c * c for c in z))
    z = [c / dist for c in z]
    x = [up[1] * z[2] - up[2] * z[1], up[2] * z[0] - up[0] * z[2], up[0] * z[1] - up[1] * z[0]]
    n = math.sqrt(sum(c * c for c in x))
    x = [c / n for c in x]
    y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]]
    scale = dist * math.tan(math.radians(CAMERA["view_angle"] / 2)) / WORKSPACE_RADIUS
    return x, y, z, scale


DEPTH = 0.002  # m, how far the stylus ends below the surface (device coordinates)


def write_trace(path, title, seconds, sample):
    """A 60 Hz stylus trace of `seconds`: sample(t) gives (position, buttons) or
    (position, buttons, quaternion w x y z)."""
    with open(path, "w") as f:
        f.write("# t x y z qw qx qy qz buttons: %s\n" % title)
        for k in range(int(seconds * 60) + 1):
            t = k / 60.0
            p, b, *q = sample(t)
            q = q[0] if q else (1.0, 0.0, 0.0, 0.0)
            f.write("%.6f %.9f %.9f %.9f %.12f %.12f %.12f %.12f %d\n" % (t, *p, *q, b))


def read_results(path):
    """The `key = value` lines of a figures file, as a dict (other lines are skipped)."""
    rows = [line.rstrip("\n").split(" = ", 1) for line in open(path) if " = " in line]
    return {k.strip(): v.strip() for k, v in rows}
