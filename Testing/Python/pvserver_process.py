"""`[xvfb-run] [mpiexec -n N] pvserver` on a free loopback port, for the tests that connect
a client to it (Python.pvserver_loopback, GUI.pvserver_two_ranks_drag_commit_undo_state).
The server runs in its own process group, so stop() ends it all (xvfb-run, Xvfb,
mpiexec, every rank) and nothing else."""
import os
import signal
import socket
import subprocess
import time


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def stop(proc, seconds):
    """Waits `seconds` for `proc` (started by start()) to end, then kills its group."""
    try:
        proc.wait(timeout=seconds)
    except subprocess.TimeoutExpired:
        pass
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    proc.wait()


def wait_for(log, marker, proc, seconds):
    """True once `marker` is in the file `log` that `proc` writes; False if `proc` ends
    or `seconds` pass first (a limit: the wait is for the marker, not a fixed time)."""
    deadline = time.time() + seconds
    while time.time() < deadline and proc.poll() is None:
        log.seek(0)
        if marker in log.read():
            return True
        time.sleep(0.2)
    log.seek(0)
    return marker in log.read()


def start(ranks, log_path, plugin_path=None, display=False, seconds=120, reverse_port=None):
    """Starts pvserver on `ranks` MPI processes (no mpiexec for 1) and returns (process,
    port, log) once it accepts connections on a free port ("Accepting connection"), or,
    with `reverse_port`, once it has connected to the client listening there (a reverse
    connection: "Client connected."). The test's own pvpython is an MPI singleton: its
    Open MPI/PMIx variables would make the child mpiexec believe it runs inside a job, so
    the server gets a clean environment. `plugin_path`: its PV_PLUGIN_PATH. `display`:
    under its own xvfb-run (docs/mpi.md, "A display on the server ranks")."""
    tmp = os.path.dirname(os.path.abspath(log_path))
    env = {k: v for k, v in os.environ.items()
           if not (k.startswith("OMPI_") or k.startswith("PMIX_") or k.startswith("OPAL_"))}
    env["OMPI_MCA_orte_tmpdir_base"] = tmp
    if plugin_path is not None:
        env["PV_PLUGIN_PATH"] = plugin_path
    text = ""
    # Tried again when it ends before it is ready: the port taken between free_port()
    # and pvserver's bind, or xvfb-run -a of another test taking the same display.
    for _ in range(3):
        port = reverse_port or free_port()
        cmd = [os.environ.get("PVSERVER") or "pvserver", "--server-port=%d" % port,
               "--force-offscreen-rendering"]
        if reverse_port:
            cmd += ["--reverse-connection", "--client-host=localhost"]
        if ranks > 1:
            cmd = [os.environ.get("MPIEXEC") or "mpiexec", "--allow-run-as-root",
                   "--oversubscribe", "-n", str(ranks)] + cmd
        if display:
            cmd = ["xvfb-run", "-a", "-s", "-screen 0 640x480x24 -noreset"] + cmd
        log = open(log_path, "w+")
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=env,
                                start_new_session=True)
        ready = "Client connected." if reverse_port else "Accepting connection"
        if wait_for(log, ready, proc, seconds):
            return proc, port, log
        ended = proc.poll() is not None
        stop(proc, 0)
        log.seek(0)
        text = log.read()
        if not ended:
            break  # no answer in `seconds`: not tried again
    raise RuntimeError("pvserver did not start: " + text)
