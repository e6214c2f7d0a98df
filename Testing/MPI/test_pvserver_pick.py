"""The pick that asks the ranks (issue 39 item 1, docs/interactor.md "The pick"): a client
on `mpiexec -n 2 pvserver` (loopback) with remote rendering forced (Remote Render
Threshold 0, checked: the client's view renders remotely and holds no geometry) meets
view rays with the deformed fault-step horizon through the GeoShapingRayPick proxy, which
each rank answers for its piece and reduces; the answers over both ranks' pieces must
equal a builtin session's (hit, point GlobalIds and owner-independent figures: the point
id bit for bit, the point and normal within 1e-9 of the surface size). The client's
round trip per pick (ms, bytes through its socket) is printed for docs/benchmarks.md.
Usage: test_pvserver_pick.py (the driver); test_pvserver_pick.py client PORT OUT."""
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Python"))

# Rays: a 9 x 7 grid of origins 40 above the 100 x 60 horizon, slanted as a perspective
# view's are, so some cross the seam between the pieces and some miss.
RAYS = [((-5.0 + 110.0 * i / 8, -5.0 + 70.0 * j / 6, 60.0), (0.05 * (i - 4), -0.04 * (j - 3), -1.0))
        for i in range(9) for j in range(7)]
REPEATS = 5  # each ray this many times (a changed ray each pick, so each re-executes)


def socket_bytes(port):
    """Bytes sent and received on the client's connections to the server at `port` (the
    kernel's TCP counters, `ss -ti`): 0 when there is no server or no `ss`."""
    try:
        text = subprocess.run(["ss", "-tinH", "state", "established", "( dport = :%d )" % port],
                              capture_output=True, text=True, timeout=30).stdout
    except OSError:
        return 0
    total = 0
    for word in text.split():
        if word.startswith("bytes_sent:") or word.startswith("bytes_received:"):
            total += int(word.split(":")[1])
    return total


def remote_scene(port):
    """In a client (port 0: builtin session): the deformed fault-step horizon, distributed
    over the server's ranks, and with a server its render view rendering remotely
    (Remote Render Threshold 0). Returns (the deformation, the view or None, whether the
    view renders remotely)."""
    from paraview.simple import Connect, GetActiveViewOrCreate, LoadPlugin, Render, Show
    import paraview.simple as simple

    if port:
        Connect("127.0.0.1", port)
    for remote in ((False, True) if port else (False,)):
        LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], remote=remote, ns=vars(simple))
    from mpi_pipeline import distributed
    _, upstream = distributed(vars(simple)["FaultStepHorizon"]())
    chain = vars(simple)["ChainMailDeformation"](Input=upstream)
    chain.GraspMode = "Nearest To Position"
    chain.GraspPosition = [10.0, 5.0, 10.0]
    chain.Displacement = [0.0, 0.0, 8.0]
    chain.OutputPointsPrecision = "Double"
    chain.UpdatePipeline()
    if not port:  # the builtin session needs no view
        return chain, None, False
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [400, 300]
    view.RemoteRenderThreshold = 0.0
    Show(chain, view)
    Render(view)
    return chain, view, bool(view.GetClientSideObject().GetUseDistributedRenderingForRender())


def builtin_and_served(script):
    """`script`'s client run in a builtin session and on a new `mpiexec -n 2 pvserver`
    (its view rendering remotely, checked): (its builtin answer, its served answer), or
    the test fails."""
    import tempfile
    import pvserver_process
    from mpi_driver import ENV, fail, run_client

    env = {k: v for k, v in ENV.items()
           if not (k.startswith("OMPI_") or k.startswith("PMIX_") or k.startswith("OPAL_"))}
    with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
        def client_answer(port, name):  # the client's view shows the server's image in a window
            return run_client(script, port, os.path.join(tmp, name + ".json"), env,
                              display=bool(port))

        builtin, why = client_answer(0, "builtin")
        if builtin is None:
            fail("builtin: " + why)
        proc, port, log = pvserver_process.start(2, os.path.join(tmp, "pvserver.log"), display=True)
        try:
            served, why = client_answer(port, "pvserver")
        finally:
            pvserver_process.stop(proc, 20)
            log.seek(0)
            server_log = log.read()
        if served is None:
            fail("2-rank pvserver: %s\nserver log: %s" % (why, server_log[-2000:]))
        if "ERR|" in server_log:
            fail("the server logged an error: " + server_log[-2000:])
        if not served["remote_rendering"]:
            fail("the view on the 2-rank pvserver does not render remotely")
    return builtin, served


def client(port, out):
    from paraview import servermanager
    from paraview.simple import Disconnect

    chain, _, remote_rendering = remote_scene(port)
    pick = servermanager.ProxyManager().SMProxyManager.NewProxy("misc", "GeoShapingRayPick")
    servermanager.vtkSMPropertyHelper(pick, "Input").Set(chain.SMProxy, 0)
    pick.UpdateVTKObjects()

    def ask(origin, direction):
        servermanager.vtkSMPropertyHelper(pick, "RayOrigin").Set(origin, 3)
        servermanager.vtkSMPropertyHelper(pick, "RayDirection").Set(direction, 3)
        pick.UpdateVTKObjects()
        pick.UpdatePipeline()
        pick.UpdatePropertyInformation()
        get = lambda name, n: [pick.GetProperty(name).GetElement(i) for i in range(n)]
        return {"hit": get("Hit", 1)[0], "point": get("HitPoint", 3), "normal": get("HitNormal", 3),
                "rank": get("HitRank", 1)[0], "id": get("HitPointId", 1)[0]}

    picks = [ask(*ray) for ray in RAYS]
    before, start = socket_bytes(port), time.perf_counter()
    for r in range(REPEATS):
        for origin, direction in RAYS:
            ask([x + 1e-3 * (r + 1) for x in origin], direction)
    seconds, transferred = time.perf_counter() - start, socket_bytes(port) - before
    bounds = chain.GetDataInformation().GetBounds()
    with open(out, "w") as f:
        json.dump({"picks": picks, "remote_rendering": remote_rendering, "bounds": list(bounds),
                   "ms": 1e3 * seconds / (REPEATS * len(RAYS)),
                   "bytes": transferred / (REPEATS * len(RAYS))}, f)
    if port:
        Disconnect()


def driver():
    import numpy as np
    from mpi_driver import fail

    builtin, served = builtin_and_served(__file__)
    b = np.array(builtin["bounds"])
    size = np.linalg.norm(b[1::2] - b[0::2])
    ranks = [0, 0]
    for ray, one, two in zip(RAYS, builtin["picks"], served["picks"]):
        if one["hit"] != two["hit"]:
            fail("ray %s: hit %d on one process, %d on two" % (ray, one["hit"], two["hit"]))
        if not one["hit"]:
            continue
        ranks[two["rank"]] += 1
        if one["id"] != two["id"]:
            fail("ray %s: point %d on one process, %d on two" % (ray, one["id"], two["id"]))
        for key in ("point", "normal"):
            scale = size if key == "point" else 1.0
            if np.abs(np.subtract(one[key], two[key])).max() > 1e-9 * scale:
                fail("ray %s: %s %s on one process, %s on two" % (ray, key, one[key], two[key]))
    print("surface bounds %s" % b)
    if min(ranks) < 5:
        fail("hits per rank %s: the rays must cross both pieces" % ranks)
    print("ok: %d hits over rank 0's piece, %d over rank 1's, %d misses: equal to one process"
          % (ranks[0], ranks[1], len(RAYS) - sum(ranks)))
    print("round trip per pick, 2 ranks, loopback: %.2f ms, %.0f bytes (builtin %.2f ms)"
          % (served["ms"], served["bytes"], builtin["ms"]))


if __name__ == "__main__":
    if sys.argv[1:2] == ["client"]:
        client(int(sys.argv[2]), sys.argv[3])
    else:
        driver()
