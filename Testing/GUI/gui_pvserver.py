"""GUI test against `mpiexec -n 2 pvserver` on the loopback (docs/mpi.md, "The GUI client
on a distributed server"): paraview connects (forward connection, --url=cs://), loads
the pipeline a user builds (write_state) and the Haptics dock's mouse hand drags,
commits (the release), undoes and redoes through the test hook's mouse script, then saves
the state; a second paraview, to which a new 2-rank server connects (reverse connection,
--url=csrc://), loads that state and undoes through the dock. After each step every server rank writes its piece ("dump"). Checked here:
both ranks hold owned points, every copy of a point (owned or ghost, on either rank)
equals its owner's bit for bit, and the gathered points equal what one process computes
(this pvpython, builtin) from the same grasp, displacement and EditHistory, bit for bit;
the drag moved points, the commit kept them, undo gave the rest points exactly, the
loaded state shows the committed shape. The harness (write_state, session, gathered,
one_process, check_shape) serves the dock's other hands too (gui_pvserver_hands.py)."""
import os
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "Python"), os.path.join(HERE, "..", "MPI")]
import pvserver_process  # noqa: E402
from gui_files import read_results as read_figures  # noqa: E402
from mpi_pipeline import COORDINATE_RANKS  # noqa: E402

RANKS = 2
# Generous limits, never waited out when all goes well: each step waits for a marker.
SERVER_START_SECONDS = 120  # until pvserver prints "Accepting connection"
HOOK_SECONDS = 240  # the test hook's own time-out in paraview
CLIENT_SECONDS = 360  # paraview must have ended by then
# Press on the horizon's upper side (the GUI test's camera), drag 60 px up, release =
# commit; then the dock's Undo and Redo; a dump of every rank after each step.
SESSION1 = ("press 0.3 0.5; move 0.3 0.52; move 0.3 0.54; move 0.3 0.56; move 0.3 0.58; "
            "move 0.3 0.6; wait; dump drag; release; wait; dump commit; undo; wait; dump undo; "
            "redo; wait; dump redo; savestate")
SESSION2 = "wait; dump loaded; undo; wait; dump loaded_undo"
# The brush's settings on the paint that the ranks run on their pieces (write_state's
# paint_pieces): geodesic, so that a dab near the seam paints across it.
PAINT = dict(DistanceMode="Geodesic", Falloff="Smooth")
DUMP = """name = 'start'
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkParallelCore import vtkMultiProcessController
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
data = self.GetInputDataObject(0, 0)
self.GetOutputDataObject(0).ShallowCopy(data)
n = data.GetNumberOfPoints()
def column(array, kind):
    return vtk_to_numpy(array).astype(kind) if array is not None else np.zeros(n, kind)
np.savez(%r + '-' + name + '-rank%%d.npz' %% rank,
         xyz=vtk_to_numpy(data.GetPoints().GetData()).astype(float).reshape(n, 3),
         gid=column(data.GetPointData().GetGlobalIds(), np.int64),
         ghost=column(data.GetPointData().GetArray('vtkGhostType'), np.int64),
         m=column(data.GetPointData().GetArray('Malleability'), float))
"""


def write_state(path, out, paint_pieces=False):
    """The scene of a session as a state file (written here, in pvpython): the pipeline a
    user builds (docs/mpi.md), the painted fault-step horizon through RedistributeDataSet
    into ChainMailDeformation (`paint_pieces`: the MalleabilityPaint after the
    redistribution, so that each rank paints its piece, geodesically, PAINT), and after
    it the ProgrammableFilter that the test hook's "dump NAME" runs again: each server
    rank writes its piece of the deformation's output (points, global ids, ghost flags,
    malleability) to <out>-NAME-rank<r>.npz. A state, so that File > Load State on the
    server is what sets the scene up (--script works there too)."""
    from paraview import simple
    import geoshaping_presets
    from gui_setup_camera import CAMERA
    horizon = simple.FaultStepHorizon(PaintFigure5C=1)
    if paint_pieces:
        paint = simple.MalleabilityPaint(Input=simple.RedistributeDataSet(Input=horizon), **PAINT)
        deformation = simple.ChainMailDeformation(Input=paint)
    else:
        paint = simple.MalleabilityPaint(Input=horizon)
        deformation = simple.ChainMailDeformation(Input=simple.RedistributeDataSet(Input=paint))
    deformation.MalleabilityArray = ["POINTS", "Malleability"]
    deformation.OutputPointsPrecision = "Double"
    simple.ProgrammableFilter(Input=deformation, Script=DUMP % out, CopyArrays=0)
    view = simple.GetActiveViewOrCreate("RenderView")
    geoshaping_presets.show_malleability(simple.Show(deformation, view))
    view.OrientationAxesVisibility = 0
    view.CameraPosition = CAMERA["position"]
    view.CameraFocalPoint = CAMERA["focal_point"]
    view.CameraViewUp = CAMERA["view_up"]
    view.CameraViewAngle = CAMERA["view_angle"]
    simple.SetActiveSource(deformation)
    simple.SaveState(path)


def session(out, tag, steps, state, reverse=False, hand="mouse", ranks=RANKS,
            remote_render=False, env=None):
    """One paraview client on a new `ranks`-process server: it connects (--url=cs://),
    or with `reverse` listens and the server connects to it (--url=csrc://, pvserver
    --reverse-connection); ranks=0: a builtin session (one process, no server). The test
    hook loads `state` once connected to every rank, starts the dock with hand 1 `hand`
    (the mouse, or a trace it replays) and plays `steps`. `remote_render`: the hook sets
    the view's Remote Render Threshold to 0 after loading the state, so the server renders
    and the client holds no geometry (checked here in the client's log). `env`: more
    environment for the client. Returns the output prefix. The client and the server are
    stopped whatever happens."""
    prefix = out + "-" + tag
    env = dict(os.environ, **(env or {}), GEOSHAPING_HAPTICS_TEST_OUTPUT=prefix,
               GEOSHAPING_HAPTICS_REPLAY=hand, GEOSHAPING_HAPTICS_SCRIPT=steps,
               GEOSHAPING_GUI_STATE=state, GEOSHAPING_GUI_SERVER_PROCESSES=str(ranks),
               GEOSHAPING_HAPTICS_TEST_TIMEOUT=str(HOOK_SECONDS))
    if remote_render:
        env["GEOSHAPING_GUI_REMOTE_RENDER"] = "1"
    client_log = open(prefix + ".client.log", "w+")
    server_log = prefix + ".server.log"
    # Under xvfb-run: a pvserver without a display makes paraview 5.11 show "Server
    # DISPLAY not accessible" in a modal box at the connection, which waits for a click.
    server_options = dict(plugin_path=os.environ["PV_PLUGIN_PATH"].split(":")[0],  # no hook
                          display=True, seconds=SERVER_START_SECONDS)

    def start_client(url):
        command = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24 -noreset",
                   os.environ["PARAVIEW"], "--dr"] + (["--url=" + url] if url else [])
        return subprocess.Popen(command, env=env, stdout=client_log, stderr=subprocess.STDOUT,
                                start_new_session=True)

    server = client = log = None
    try:
        if not ranks:
            client = start_client(None)
        elif reverse:
            port = pvserver_process.free_port()
            client = start_client("csrc://localhost:%d" % port)
            assert pvserver_process.wait_for(client_log, "Accepting connection", client,
                                             SERVER_START_SECONDS), "paraview does not listen"
            server, _, log = pvserver_process.start(RANKS, server_log, reverse_port=port,
                                                    **server_options)
        else:
            server, port, log = pvserver_process.start(RANKS, server_log, **server_options)
            client = start_client("cs://127.0.0.1:%d" % port)
        try:
            client.wait(timeout=CLIENT_SECONDS)
        except subprocess.TimeoutExpired:
            raise AssertionError("paraview (%s) did not end in %d s" % (tag, CLIENT_SECONDS))
    finally:
        for proc, seconds in ((client, 0), (server, 30)):  # pvserver ends with its client
            if proc:
                pvserver_process.stop(proc, seconds)
        client_log.seek(0)
        print("paraview (%s):" % tag, client_log.read()[-3000:])
        if log:
            log.seek(0)
            print("server (%s):" % tag, log.read()[-2000:])
    if remote_render:
        with open(prefix + ".client.log") as f:
            assert "GeoShaping test: remote rendering = 1" in f.read(), \
                "%s: the view does not render remotely" % tag
        print("%s: the view renders remotely (the client holds no geometry)" % tag)
    return prefix


def gathered(out, name, column="xyz"):
    """Every rank's piece of dump `name` (<out>-NAME-rank<r>.npz), `column` its points
    ("xyz") or malleability ("m"): ({global id: value} of the owned points, the pieces as
    (global ids, values, owned mask) per rank), after checking that both ranks own
    points and every copy (ghosts) equals its owner's, bit for bit."""
    owned, pieces = {}, []
    for r in range(RANKS):
        piece = np.load("%s-%s-rank%d.npz" % (out, name, r))
        mine = (piece["ghost"] & 1) == 0  # vtkDataSetAttributes::DUPLICATEPOINT
        assert mine.any(), "%s: rank %d owns no point (not distributed)" % (name, r)
        for g, x in zip(piece["gid"][mine], piece[column][mine]):
            assert int(g) not in owned, "%s: point %d owned twice" % (name, g)
            owned[int(g)] = x
        pieces.append((piece["gid"], piece[column], mine))
    for gid, values, _ in pieces:
        for g, x in zip(gid, values):
            assert np.array_equal(owned[int(g)], x), "%s: a copy of point %d differs" % (name, g)
    return owned, pieces


def one_process(figures):
    """The same deformation in this (one) process: the builtin pipeline with the points
    numbered by coordinates (as the filter numbers them on several processes), the
    proxy's grasp, displacement and EditHistory."""
    from paraview import simple
    from vtkmodules.util.numpy_support import vtk_to_numpy
    horizon = simple.FaultStepHorizon(PaintFigure5C=1)
    paint = simple.MalleabilityPaint(Input=horizon)
    ids = simple.ProgrammableFilter(Input=paint, Script=COORDINATE_RANKS)
    chain = simple.ChainMailDeformation(Input=ids)
    chain.MalleabilityArray = ["POINTS", "Malleability"]
    chain.OutputPointsPrecision = "Double"
    chain.SMProxy.GetProperty("GraspMode").SetElement(0, int(figures["grasp_mode"]))
    chain.GraspPointId = int(figures["grasp_point_id"])
    chain.GraspPosition = [float(v) for v in figures["GraspPosition"].split()]
    chain.Displacement = [float(v) for v in figures["Displacement"].split()]
    chain.EditHistory = [figures["edit_%d" % i] for i in range(int(figures["edit_history"]))]
    chain.UpdatePipeline()
    chain.UpdatePropertyInformation()
    data = chain.GetClientSideObject().GetOutputDataObject(0)
    gid = vtk_to_numpy(data.GetPointData().GetGlobalIds())
    xyz = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    malleability = chain.GetProperty("LastGraspMalleability").GetData()
    rest = vtk_to_numpy(ids.GetClientSideObject().GetOutputDataObject(0).GetPoints().GetData())
    points = {int(g): x for g, x in zip(gid, xyz)}
    rest = {int(g): x for g, x in zip(gid, rest.astype(float))}
    for proxy in (chain, ids, paint, horizon):
        simple.Delete(proxy)
    return points, rest, malleability


def same(a, b):
    return a.keys() == b.keys() and all(np.array_equal(a[g], b[g]) for g in a)


def prepare(out):
    """Skips (exit 77) without mpiexec; removes the files of an earlier run of `out`;
    loads the plugin into this pvpython (the one-process answers)."""
    if not shutil.which(os.environ.get("MPIEXEC") or "mpiexec"):
        print("SKIP: no mpiexec (MPIEXEC=%r): the 2-rank pvserver cannot be started"
              % os.environ.get("MPIEXEC", ""))
        sys.exit(77)  # SKIP_RETURN_CODE (Testing/GUI/CMakeLists.txt)
    tmp = os.environ["GEOSHAPING_TEST_TMP"]
    for name in os.listdir(tmp):  # no file of an earlier run may pass for this one's
        if name.startswith(os.path.basename(out) + "-"):
            os.remove(os.path.join(tmp, name))
    from paraview import simple
    simple.LoadPlugin(os.path.join(os.environ["PV_PLUGIN_PATH"].split(":")[0], "GeoShaping.so"),
                      remote=False)


def check_session(results, edits, ranks=RANKS):
    """The hook ran to its end on a `ranks`-process server (0: builtin), and the dock
    counts `edits`."""
    print("results:", results)
    assert results["started"] == "1" and results["timed_out"] == "0", results
    assert results["server_remote"] == str(int(ranks > 0)), results
    assert results["server_processes"] == str(max(ranks, 1)), results
    assert results["label_Edits"] == edits, results


def check_shape(out, prefix, name):
    """Dump `name` of the session `prefix`: every rank's points, ghosts included, equal
    one process's from the same grasp, Displacement and EditHistory, bit for bit.
    Returns (the gathered points, the dump's figures, the number of moved points, the
    one-process LastGraspMalleability, the moved points each rank owns)."""
    figures = read_figures("%s-%s.txt" % (prefix, name))
    shape, pieces = gathered(out, name)
    expected, rest, malleability = one_process(figures)
    owned_moved = []
    for r, (gid, xyz, mine) in enumerate(pieces):
        same_points = all(np.array_equal(expected[int(g)], x) for g, x in zip(gid, xyz))
        moved_here = np.array([not np.array_equal(rest[int(g)], x) for g, x in zip(gid, xyz)])
        owned_moved.append(int((moved_here & mine).sum()))
        print("  %s rank %d: %d points (%d owned), %d moved (%d owned), equal to one process: %s"
              % (name, r, len(gid), mine.sum(), moved_here.sum(), owned_moved[-1], same_points))
        assert same_points, "%s: rank %d's points differ from one process" % (name, r)
    moved = sum(not np.array_equal(shape[g], rest[g]) for g in rest)
    print("%s: %d points on %d ranks, %d moved, edits %s, grasp %s, LastGraspMalleability %s"
          % (name, len(shape), RANKS, moved, figures["edit_history"],
             figures["last_grasp_point_id"], figures["last_grasp_malleability"]))
    assert same(shape, expected), "%s: the ranks' points differ from one process" % name
    return shape, figures, moved, malleability, owned_moved


# A pull grasped over rank 1's piece (the lower plateau, x > 50); with remote rendering
# the pick asks the ranks (docs/mpi.md, "Picking on several ranks").
RANK1_PULL = ("press 0.62 0.5; move 0.62 0.52; move 0.62 0.54; move 0.62 0.56; "
               "move 0.62 0.58; wait; dump drag; release; wait; dump commit")


def run_pull_rank1(out, read_results, remote_render):
    """run_gui_test.py pvserver_pull_rank1 / pvserver_remote_pull_rank1: the mouse grasps
    a point of rank 1's piece, the client rendering or the server (Remote Render
    Threshold 0), pulls it 40 px up and lets go. Every rank's points equal one process's
    from the same grasp, Displacement and EditHistory, bit for bit, after the drag and
    after the commit; the grasped point is rank 1's and both ranks' pieces moved."""
    prepare(out)
    write_state(out + "-scene.pvsm", out)
    prefix = session(out, "pull", RANK1_PULL, out + "-scene.pvsm", remote_render=remote_render)
    check_session(read_results(prefix + ".txt"), "Edits: 1, redoable 0")
    _, figures, moved, malleability, by_rank = check_shape(out, prefix, "drag")
    grasp = int(figures["last_grasp_point_id"])
    _, pieces = gathered(out, "drag")
    owner = [r for r, (gid, _, mine) in enumerate(pieces) if grasp in set(gid[mine].tolist())]
    print("drag: grasp %d owned by rank %s, %d moved (%s owned per rank)"
          % (grasp, owner, moved, by_rank))
    assert owner == [1], "the grasp is not on rank 1's piece: %s" % owner
    assert moved > 20 and min(by_rank) > 0, "the pull must move points of both ranks"
    assert float(figures["last_grasp_malleability"]) == malleability, figures
    _, committed, moved_after, _, _ = check_shape(out, prefix, "commit")
    assert committed["edit_history"] == "1" and moved_after == moved, committed
    print("GUI pull over rank 1 (%s rendering) on a %d-rank pvserver passed"
          % ("remote" if remote_render else "local", RANKS))


def run(out, read_results):
    prepare(out)
    write_state(out + "-scene.pvsm", out)
    first = session(out, "edit", SESSION1, out + "-scene.pvsm", reverse=False)
    assert os.path.exists(first + ".pvsm"), "the first session saved no state"
    second = session(out, "loaded", SESSION2, first + ".pvsm", reverse=True)
    # The dock's own count after each session: the drag committed, undone, redone; the
    # loaded edit undone.
    check_session(read_results(first + ".txt"), "Edits: 1, redoable 0")
    check_session(read_results(second + ".txt"), "Edits: 0, redoable 1")
    shapes = {}
    for name, prefix in (("drag", first), ("commit", first), ("undo", first), ("redo", first),
                         ("loaded", second), ("loaded_undo", second)):
        shapes[name], figures, moved, malleability, _ = check_shape(out, prefix, name)
        if name == "drag":
            assert moved > 50 and int(figures["last_grasp_point_id"]) >= 0, figures
            grasped = float(figures["last_grasp_malleability"])
            assert grasped == malleability, (figures, malleability)
        if name in ("undo", "loaded_undo"):
            assert moved == 0 and figures["edit_history"] == "0", name + " left a shape"
        if name in ("commit", "redo", "loaded"):
            assert figures["edit_history"] == "1", figures
            assert same(shapes[name], shapes["drag"]), name + " is not the dragged shape"
    print("GUI test on a %d-rank pvserver passed" % RANKS)
