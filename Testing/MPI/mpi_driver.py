"""What the MPI test drivers (test_mpi_*.py) share: run a pvbatch script on n ranks, read
the rows the ranks wrote, and compare n ranks with 1 rank. (mpi_pipeline.py is the other
side: what the scripts run by pvbatch share.)"""
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ENV = dict(os.environ)
ENV.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")  # 3 ranks on 2 cores


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def run_ranks(n, script, args, timeout=240, expected=()):
    """Run Testing/MPI/`script` with `args` on `mpiexec -n n pvbatch --sym`: (cmd, the
    finished process, its error lines). An error line is one with "ERR|" that contains
    none of the `expected` strings."""
    cmd = [ENV.get("MPIEXEC", "mpiexec"), "--allow-run-as-root", "--oversubscribe", "-n", str(n),
           ENV.get("PVBATCH", "pvbatch"), "--sym", os.path.join(HERE, script)] + list(args)
    done = subprocess.run(cmd, env=ENV, capture_output=True, text=True, timeout=timeout)
    errors = [line for line in (done.stdout + done.stderr).splitlines()
              if "ERR|" in line and not any(e in line for e in expected)]
    return cmd, done, errors


def run_clean(n, script, args, timeout=240, expected=()):
    """run_ranks, failing the test (with the command and its output's end) when the run
    exits non-zero or prints an error line. Returns the finished process."""
    cmd, done, errors = run_ranks(n, script, args, timeout, expected)
    if done.returncode != 0 or errors:
        show(cmd, done)
        fail("%d ranks: exit %d, %d error lines" % (n, done.returncode, len(errors)))
    return done


def show(cmd, done):
    """Print a run's command and the end of its output (for a failure)."""
    print(" ".join(cmd))
    print(done.stdout[-3000:], done.stderr[-3000:])


def one_row_per_point(rows, n, label=""):
    """`rows` (first column a global id) with one row per id: a point held by two ranks as
    owned (or twice by one) must agree with itself, bit for bit."""
    ids, first = np.unique(rows[:, 0], return_index=True)
    for i in range(len(rows)):
        if not np.array_equal(rows[i], rows[first[np.searchsorted(ids, rows[i, 0])]]):
            fail("%d ranks%s: copies of point %d differ" % (n, label, rows[i, 0]))
    return rows[first]


def expect_same(rows, one, n, what="1 rank"):
    """Fail unless the rows of `n` ranks equal `one`'s bit for bit."""
    if rows.shape != one.shape or not np.array_equal(rows, one):
        diff = np.abs(rows - one).max() if rows.shape == one.shape else (
            "shape %s vs %s" % (rows.shape, one.shape))
        fail("%d ranks differ from %s (max difference %s)" % (n, what, diff))


def write_dem(path):
    """A 41 x 31 UTM (EPSG:32616) elevation GeoTIFF with a fault scarp, 30 m pixels, at
    `path`: an Esri ASCII grid turned into a GeoTIFF by gdal_translate."""
    y, x = np.mgrid[0:31, 0:41].astype(float)
    z = 200.0 + 3.0 * np.sin(0.3 * x) * np.cos(0.2 * y) + 25.0 / (1.0 + np.exp(-(x - 0.4 * y - 15.0)))
    grid = path[:-4] + ".asc"
    with open(grid, "w") as f:
        f.write("ncols 41\nnrows 31\nxllcorner 500000\nyllcorner 3600000\ncellsize 30\n")
        for row in z:
            f.write(" ".join("%.17g" % v for v in row) + "\n")
    subprocess.run(["gdal_translate", "-q", "-a_srs", "EPSG:32616", "-ot", "Float64", grid, path],
                   check=True)


def plain_parameters(bounds, pull=None):
    """The plain pipeline's parameters (mpi_pipeline.plain_pipeline) from the scene's
    `bounds` (xmin, xmax, ...) into ENV: grasp at the top middle, pull up by `pull` or 8 %
    of the size, geodesic dabs: one across the middle (rank borders), one rigid spot off it."""
    lo, hi = np.array(bounds[0::2]), np.array(bounds[1::2])
    ENV["PLAIN_GRASP"] = " ".join(repr(x) for x in lo + np.array([0.5, 0.5, 1.0]) * (hi - lo))
    pull = 0.08 * float((hi - lo).max()) if pull is None else pull
    ENV["PLAIN_PULL"] = " ".join(repr(x) for x in [0.0, 0.0, pull])
    c, r = lo + 0.5 * (hi - lo), float((hi - lo).max())
    ENV["PLAIN_DABS"] = " ".join(repr(float(x)) for x in
                                 list(c) + [0.3 * r, 1.0, 0.7] + list(lo + 0.3 * (hi - lo)) + [0.15 * r, 0.0, 1.0])


def run_client(script, port, out, env, display=False, timeout=240):
    """(result, why): pvpython runs `script` as "client PORT OUT" (PORT 0: builtin session)
    and writes its answer to the JSON file OUT; None and why on a hang, an exit, an ERR|
    line or no answer. `display`: under xvfb-run (a client view showing the server's image)."""
    cmd = [sys.executable if sys.executable.endswith("pvpython") else "pvpython",
           "--no-mpi", os.path.abspath(script), "client", str(port), out]
    if display:
        cmd = ["xvfb-run", "-a", "-s", "-noreset"] + cmd
    try:
        done = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "no answer in %d s (the server hangs)" % timeout
    errors = [line for line in (done.stdout + done.stderr).splitlines() if "ERR|" in line]
    if done.returncode != 0 or errors or not os.path.exists(out):
        return None, "exit %d: %s" % (done.returncode, (done.stdout + done.stderr)[-2000:])
    with open(out) as f:
        return json.load(f), ""
