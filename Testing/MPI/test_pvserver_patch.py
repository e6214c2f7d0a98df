"""The contact patch from the ranks (issue 39 item 2, docs/haptics.md "The contact patch on
a server"): a client on `mpiexec -n 2 pvserver` (loopback) with remote rendering forced
(Remote Render Threshold 0, checked: the client's view renders remotely and holds no
geometry) asks the GeoShapingContactPatch proxy for the triangles of the deformed
fault-step horizon near stylus points over both ranks' pieces and across their seam; each
patch must be a builtin session's, the same triangles (each once: no ghost copy), bit for
bit, in any order. The client's round trip per patch (ms, bytes through its socket) is
printed for docs/benchmarks.md.
Usage: test_pvserver_patch.py (the driver); test_pvserver_patch.py client PORT OUT."""
import json
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Python"))

from test_pvserver_pick import builtin_and_served, remote_scene, socket_bytes  # noqa: E402

# Stylus points (x, y, z, box half-size): on rank 0's upper plateau, across the seam
# (x = 50), on rank 1's lower plateau (z = 0 beyond the step), under the grasp's bump
# (lifted 8 above it: nothing) and off the surface; the half-size 13.4 is the GUI tests'
# reach (ContactReachMetres at their camera's scale).
CENTRES = [(20.0, 30.0, 20.0, 13.4), (44.0, 30.0, 20.0, 5.0), (50.0, 30.0, 10.0, 6.0),
           (51.0, 12.0, 8.0, 13.4), (70.0, 30.0, 0.0, 13.4), (90.0, 50.0, 0.0, 2.5),
           (10.0, 5.0, 18.0, 3.0), (200.0, 30.0, 0.0, 5.0)]
REPEATS = 10  # each centre this many times, moved a little (so each re-executes)
NEAREST = 256  # MaxTriangles as the interactor sets it (MaxContactTriangles)
FRAMES = 40  # frames rendered with and without a patch, for the frame rate


def client(port, out):
    from paraview import servermanager
    from paraview.simple import Disconnect, Render

    chain, view, remote_rendering = remote_scene(port)
    patch = servermanager.ProxyManager().SMProxyManager.NewProxy("misc", "GeoShapingContactPatch")
    servermanager.vtkSMPropertyHelper(patch, "Input").Set(chain.SMProxy, 0)
    patch.UpdateVTKObjects()

    def ask(x, y, z, radius, most=0):
        servermanager.vtkSMPropertyHelper(patch, "Center").Set([x, y, z], 3)
        servermanager.vtkSMPropertyHelper(patch, "Radius").Set(radius)
        servermanager.vtkSMPropertyHelper(patch, "MaxTriangles").Set(most)
        patch.UpdateVTKObjects()
        patch.UpdatePipeline()
        patch.UpdatePropertyInformation()
        values = patch.GetProperty("Triangles")
        return [values.GetElement(i) for i in range(values.GetNumberOfElements())]

    patches = [ask(*c) for c in CENTRES]
    nearest = [ask(*c, most=NEAREST) for c in CENTRES]
    # The round trip, every triangle of the box and the NEAREST nearest interleaved (each
    # ask a moved centre, so each re-executes): seconds, bytes, triangles per kind.
    cost = {0: [0.0, 0, 0], NEAREST: [0.0, 0, 0]}
    for r in range(REPEATS):
        for x, y, z, radius in CENTRES:
            for most in (0, NEAREST):
                before = socket_bytes(port)
                start = time.perf_counter()
                got = ask(x + 1e-3 * (r + 1), y, z, radius, most)
                cost[most][0] += time.perf_counter() - start
                cost[most][1] += socket_bytes(port) - before
                cost[most][2] += len(got) // 9
    # What it costs the frame rate: frames of the remote-rendering view (a render after a
    # camera step) with and without a patch asked (the nearest 256 at the GUI tests'
    # reach), interleaved.
    frames = {False: 0.0, True: 0.0}
    if port:
        for r in range(FRAMES):
            for with_patch in (False, True):
                start = time.perf_counter()
                if with_patch:
                    ask(70.0 + 1e-3 * r, 30.0, 0.0, 13.4, NEAREST)
                view.CameraPosition = [50.0, -90.0 + 1e-3 * (2 * r + with_patch), 170.0]
                Render(view)
                frames[with_patch] += time.perf_counter() - start
    asked = REPEATS * len(CENTRES)
    with open(out, "w") as f:
        json.dump({"patches": patches, "nearest": nearest, "remote_rendering": remote_rendering,
                   "cost": {str(k): [1e3 * v[0] / asked, v[1] / asked, v[2] / asked]
                            for k, v in cost.items()},
                   "fps": [FRAMES / frames[w] if frames[w] else 0.0 for w in (False, True)]}, f)
    if port:
        Disconnect()


def driver():
    import numpy as np
    from mpi_driver import fail

    builtin, served = builtin_and_served(__file__)
    def triangles(values):
        return sorted(tuple(values[i:i + 9]) for i in range(0, len(values), 9))
    for centre, one, two in zip(CENTRES, builtin["patches"], served["patches"]):
        a, b = triangles(one), triangles(two)
        print("centre %s: %d triangles on one process, %d from 2 ranks" % (centre, len(a), len(b)))
        if len(one) % 9 or len(two) % 9:
            fail("centre %s: a patch is not whole triangles" % (centre,))
        if a != b:
            fail("centre %s: the ranks' patch differs from one process's" % (centre,))
    counts = [len(p) // 9 for p in builtin["patches"]]
    if min(counts[:6]) == 0 or counts[-1] != 0:
        fail("patches %s: the centres on the surface must meet it, the one off it not" % counts)
    # MaxTriangles: the NEAREST triangles nearest the centre, the ranks' each kept
    # theirs then the first process again; the same distances as one process's (the
    # set may differ where distances tie at the last kept one), distances by vtkTriangle.
    for centre, every, one, two in zip(CENTRES, builtin["patches"], builtin["nearest"],
                                       served["nearest"]):
        a, b = distances(centre, one), distances(centre, two)
        inside = set(triangles(two)) <= set(triangles(every))
        if len(b) != min(NEAREST, len(every) // 9) or not inside:
            fail("centre %s: %d nearest from 2 ranks of %d" % (centre, len(b), len(every) // 9))
        if np.abs(np.subtract(a, b)).max(initial=0.0) > 1e-9:
            fail("centre %s: the nearest triangles' distances differ" % (centre,))
    print("ok: %d patches equal to one process (%s triangles), the %d nearest too"
          % (len(CENTRES), counts, NEAREST))
    for most, name in ((0, "every triangle of the box"), (NEAREST, "the %d nearest" % NEAREST)):
        ms, transferred, count = served["cost"][str(most)]
        print("round trip per patch, 2 ranks, loopback, %s: %.2f ms, %.0f bytes, %.0f "
              "triangles (builtin %.2f ms)" % (name, ms, transferred, count,
                                              builtin["cost"][str(most)][0]))
    print("frames of the remote-rendering view: %.1f frames/s, %.1f with a patch a frame"
          % tuple(served["fps"]))


def distances(centre, values):
    """The sorted squared distances from `centre` to the triangles of `values`."""
    from vtkmodules.vtkCommonCore import reference
    from vtkmodules.vtkCommonDataModel import vtkTriangle
    triangle, out = vtkTriangle(), []
    for i in range(0, len(values), 9):
        for k in range(3):
            triangle.GetPoints().SetPoint(k, values[i + 3 * k:i + 3 * k + 3])
        closest, pcoords, weights = [0.0] * 3, [0.0] * 3, [0.0] * 3
        sub, d2 = reference(0), reference(0.0)
        triangle.EvaluatePosition(centre[:3], closest, sub, pcoords, d2, weights)
        out.append(float(d2))
    return sorted(out)


if __name__ == "__main__":
    if sys.argv[1:2] == ["client"]:
        client(int(sys.argv[2]), sys.argv[3])
    else:
        driver()
