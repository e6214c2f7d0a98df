"""Checks of the GUI pull test (run_gui_test.py pull; TestHook/pqPullTestDriver): mouse
pulls measured against the cursor's world motion at two data scales and two cameras."""
import math

FREE = ("unit_perspective", "unit_parallel", "km_perspective", "km_parallel")
PIXEL = 1.0  # the grasped vertex shows within a pixel of the cursor


def vector(results, key):
    return [float(v) for v in results[key].split()]


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def check_pull(results):
    """Free pulls: the grasped vertex shows within a pixel of the cursor after the drag, and
    its displacement is the cursor's motion on the plane through it parallel to the view
    (whatever the scale: 1 or 1,000 km). Shift: a tenth of the same pull. Vertical (the
    dock's Pull row): x and y kept, the vertex shows at the cursor's foot on the vertical.
    Normal: along the surface's normal at the grasp."""
    print("pull                  error px  offset at press px  |displacement|  data size")
    for name in FREE + ("km_perspective_shift", "km_parallel_vertical", "unit_parallel_normal"):
        key = "pull_%s_" % name
        assert results.get(key + "grasp", "none") != "none", (name, results)
        offset = [a - b for a, b in zip(vector(results, key + "vertex_px_at_press"),
                                        vector(results, key + "press_px"))]
        print("%-21s %8.4f  %18.4f  %14.6g  %9.6g" % (
            name, float(results[key + "error_px"]), norm(offset),
            norm(vector(results, key + "displacement")), float(results[key + "data_size"])))
    for name in FREE:
        key = "pull_%s_" % name
        error = float(results[key + "error_px"])
        d, motion = vector(results, key + "displacement"), vector(results, key + "cursor_motion")
        assert norm(motion) > 1e-3 * float(results[key + "data_size"]), (name, motion)
        assert error <= PIXEL, "%s: the grasped vertex is %.3f px from the cursor" % (name, error)
        assert norm([a - b for a, b in zip(d, motion)]) <= 1e-6 * norm(motion), (name, d, motion)
    assert results["pull_row"] == "1", "the dock has no Pull row (PullConstraint)"
    assert results["labels_without_tooltip"] == "", results["labels_without_tooltip"]
    free = vector(results, "pull_km_perspective_displacement")
    fine = vector(results, "pull_km_perspective_shift_displacement")
    print("Shift: displacement / free displacement =", norm(fine) / norm(free))
    assert norm([a - 0.1 * b for a, b in zip(fine, free)]) <= 1e-6 * norm(free), (fine, free)
    key = "pull_km_parallel_vertical_"
    d = vector(results, key + "displacement")
    print("vertical: displacement", d, "error to the vertical's image %s px"
          % results[key + "error_to_vertical_px"])
    assert abs(d[0]) <= 1e-9 * norm(d) and abs(d[1]) <= 1e-9 * norm(d) and d[2] > 0, d
    assert float(results[key + "error_to_vertical_px"]) <= PIXEL, results
    key = "pull_unit_parallel_normal_"
    d, n = vector(results, key + "displacement"), vector(results, key + "view_normal")
    surface = vector(results, key + "surface_normal")
    cross = [d[1] * n[2] - d[2] * n[1], d[2] * n[0] - d[0] * n[2], d[0] * n[1] - d[1] * n[0]]
    angle = math.degrees(math.acos(min(1.0, abs(sum(a * b for a, b in zip(n, surface))) / norm(n))))
    print("normal: displacement", d, "normal at the press", n, "%.2f deg from the surface's"
          % angle)
    assert norm(d) > 0 and norm(cross) <= 1e-9 * norm(d) * norm(n), (d, n)
    assert angle < 1.0, (n, surface)
