"""What the MPI test drivers (test_mpi_*.py) share: run a pvbatch script on n ranks, read
the rows the ranks wrote, and compare n ranks with 1 rank. (mpi_pipeline.py is the other
side: what the scripts run by pvbatch share.)"""
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
