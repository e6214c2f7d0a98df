"""MalleabilityPaint with Geodesic distance on distributed data (docs/painting.md), with
point GlobalIds and without (numbered by coordinates by the filter):
`mpiexec -n 1/2/3 pvbatch --sym` runs mpi_paint.py; the owned points' malleability of 2
and 3 ranks must equal the 1-rank array bit for bit, with the same figures (dabs applied
and rejected, values painted)."""
import json
import os
import tempfile

import numpy as np
from mpi_driver import expect_same, fail, run_clean


def run(mode):
    """{ranks: rows}, {ranks: figures} of mpi_paint.py on 1, 2 and 3 ranks."""
    results, stats = {}, {}
    with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
        for n in (1, 2, 3):
            out = os.path.join(tmp, "n%d" % n)
            os.makedirs(out)
            # The invalid dab is reported on every rank; nothing else may be.
            run_clean(n, "mpi_paint.py", [out] + ([mode] if mode else []),
                      expected=("dabs were skipped",))
            rows = np.load(os.path.join(out, "result.npy"))
            if mode == "noids":
                # A seam point is in both pieces and owned by both by vtkGhostType (the
                # filter decides its owner itself): its copies must agree, bit for bit.
                rows = np.unique(rows, axis=0)
            keys = np.unique(rows[:, :-1], axis=0)
            if len(keys) != len(rows):
                fail("%d ranks: a point owned twice" % n)
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
        fail("1 rank painted %d points, %s" % (changed, stats[1]))
    print("ok: 1 rank painted %d of %d points" % (changed, len(one)))
    for n in (2, 3):
        expect_same(results[n], one, n)
        for key in ("applied", "rejected", "painted"):
            if stats[n][key] != stats[1][key]:
                fail("%d ranks: %s %s, 1 rank %s" % (n, key, stats[n][key], stats[1][key]))
        print("ok: %d ranks equal 1 rank bit for bit (%d values painted)" % (n, stats[n]["painted"]))
