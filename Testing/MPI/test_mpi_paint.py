"""MalleabilityPaint with Geodesic distance on distributed data (docs/painting.md), with
point GlobalIds and without (numbered by coordinates by the filter):
`mpiexec -n 1/2/3 pvbatch --sym` runs mpi_paint.py; the owned points' malleability of 2
and 3 ranks must equal the 1-rank array bit for bit, with the same figures (dabs applied
and rejected, values painted)."""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
env = dict(os.environ)
env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
def run(mode):
    """{ranks: rows}, {ranks: figures} of mpi_paint.py on 1, 2 and 3 ranks."""
    results, stats = {}, {}
    with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
        for n in (1, 2, 3):
            out = os.path.join(tmp, "n%d" % n)
            os.makedirs(out)
            cmd = [env.get("MPIEXEC", "mpiexec"), "--allow-run-as-root", "--oversubscribe", "-n",
                   str(n), env.get("PVBATCH", "pvbatch"), "--sym", os.path.join(here, "mpi_paint.py"),
                   out] + ([mode] if mode else [])
            run = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=240)
            lines = (run.stdout + run.stderr).splitlines()
            # The invalid dab is reported on every rank; nothing else may be.
            errors = [line for line in lines if "ERR|" in line and "dabs were skipped" not in line]
            if run.returncode != 0 or errors:
                print(" ".join(cmd)); print(run.stdout[-3000:], run.stderr[-3000:])
                print("FAILED: %d ranks: exit %d, %d error lines" % (n, run.returncode, len(errors)))
                sys.exit(1)
            rows = np.load(os.path.join(out, "result.npy"))
            if mode == "noids":
                # A seam point is in both pieces and owned by both by vtkGhostType (the
                # filter decides its owner itself): its copies must agree, bit for bit.
                rows = np.unique(rows, axis=0)
            keys = np.unique(rows[:, :-1], axis=0)
            if len(keys) != len(rows):
                print("FAILED: %d ranks: a point owned twice" % n)
                sys.exit(1)
            results[n] = rows
            with open(os.path.join(out, "stats.json")) as text:
                stats[n] = json.load(text)
            print("%s %d ranks: %d points, %s" % (mode or "ids", n, len(rows), stats[n]))
    return results, stats


for mode in ("", "noids"):
    results, stats = run(mode)
    one = results[1]
    changed = int(np.count_nonzero(one[:, -1] != np.float32(0.4)))
    if changed < 100 or stats[1]["applied"] != 12 or stats[1]["rejected"] != 1:
        print("FAILED: 1 rank painted %d points, %s" % (changed, stats[1]))
        sys.exit(1)
    print("ok: 1 rank painted %d of %d points" % (changed, len(one)))
    for n in (2, 3):
        if results[n].shape != one.shape or not np.array_equal(results[n], one):
            diff = np.abs(results[n] - one).max() if results[n].shape == one.shape else "shape"
            print("FAILED: %d ranks differ from 1 rank (max difference %s)" % (n, diff))
            sys.exit(1)
        for key in ("applied", "rejected", "painted"):
            if stats[n][key] != stats[1][key]:
                print("FAILED: %d ranks: %s %s, 1 rank %s" % (n, key, stats[n][key], stats[1][key]))
                sys.exit(1)
        print("ok: %d ranks equal 1 rank bit for bit (%d values painted)" % (n, stats[n]["painted"]))
