"""The plugin on a pvserver over loopback gives the builtin result; on 2 MPI ranks the
filter refuses with a message instead of a silently different shape."""
import os
import socket
import subprocess
import time

import numpy as np

from geoshaping_testing import check, load, points, triangulated_plane
from paraview.simple import *  # noqa: F401,F403

TMP = os.environ["GEOSHAPING_TEST_TMP"]


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def start_server(ranks):
    port = free_port()
    cmd = [os.environ["PVSERVER"], "--server-port=%d" % port, "--force-offscreen-rendering"]
    if ranks > 1:
        cmd = [os.environ["MPIEXEC"], "--allow-run-as-root", "--oversubscribe", "-n", str(ranks)] + cmd
    log = open(os.path.join(TMP, "pvserver-%d.log" % ranks), "w+")
    # pvpython is itself an MPI singleton: its Open MPI/PMIx variables would make the
    # child mpiexec believe it runs inside a job, so start it with a clean environment.
    env = {k: v for k, v in os.environ.items()
           if not (k.startswith("OMPI_") or k.startswith("PMIX_") or k.startswith("OPAL_"))}
    env["OMPI_MCA_orte_tmpdir_base"] = TMP
    proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
    deadline = time.time() + 60
    while time.time() < deadline:
        log.seek(0)
        if "Accepting connection" in log.read():
            return proc, port, log
        if proc.poll() is not None:
            break
        time.sleep(0.2)
    proc.kill()
    log.seek(0)
    raise RuntimeError("pvserver did not start: " + log.read())


def deformed(remote):
    load(remote=remote, ns=globals())
    surface = triangulated_plane(30)
    chain = ChainMailDeformation(Input=surface)  # noqa: F405
    chain.MalleabilityArray = ["POINTS", "None"]
    chain.DefaultMalleability = 0.7
    chain.GraspPointId = 15 * 31 + 15
    chain.Displacement = [1.0, 0.0, 4.0]
    result = points(chain), points(surface)
    chain.UpdatePropertyInformation()
    grasped = chain.GetProperty("LastGraspMalleability").GetData()
    if ranks_now[0] < 2:
        check(abs(grasped - 0.7) < 1e-6,
              "the grasp's malleability (0.7) reads back through the proxy (%s)"
              % ("remote" if remote else "builtin"))
    Delete(chain)
    Delete(surface)
    return result


ranks_now = [1]
builtin, rest = deformed(remote=False)
check(np.abs(builtin - rest).max() > 1.0, "builtin session deforms")

for ranks in (1, 2):
    ranks_now[0] = ranks
    proc, port, log = start_server(ranks)
    try:
        Connect("127.0.0.1", port)
        remote, remote_rest = deformed(remote=True)
        Disconnect()
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
    log.seek(0)
    server_log = log.read()
    order = np.lexsort(remote_rest.T)
    if ranks == 1:
        check(np.array_equal(remote, builtin), "pvserver (1 rank) result equals the builtin one")
    else:
        # Fetch gathers the pieces, so compare as sets of points (order may differ).
        check(np.array_equal(remote[order], remote_rest[order]),
              "pvserver (2 ranks): output is the undeformed input, not a different shape")
        check("cannot run on data split across 2 processes" in server_log,
              "pvserver (2 ranks): the filter says why")
