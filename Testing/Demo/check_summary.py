"""Checks what the demo wrote: every file, the mesh sizes, and the behaviour the paint
asks for (the frozen scarp and the black step stay rigid under FIFO Priority)."""
import json
import os
import sys

out = sys.argv[1]
summary = json.load(open(os.path.join(out, "summary.json")))
failures = []


def check(condition, message):
    print(("ok: " if condition else "FAILED: ") + message)
    if not condition:
        failures.append(message)


for name, vertices in (("jacksboro", 172 * 202), ("jacksboro_geotiff", None), ("fault_step", None)):
    scene = summary[name]
    for suffix in ("_deformed.vtp", "_deformed.ts", "_painted.vtp", "_before.png", "_after.png"):
        path = os.path.join(out, name + suffix)
        check(os.path.getsize(path) > 1000 if os.path.exists(path) else False, path + " written")
    if vertices:
        check(scene["vertices"] == vertices, "%s has %d vertices (DEM at stride 2)" % (name, vertices))
    fp = scene["queues"]["FIFO Priority"]
    check(fp["displaced_max"] > 100, "%s: FIFO Priority displaces vertices" % name)
    check(fp["E_rigid"] < 1e-9, "%s: rigid paint keeps its shape under FIFO Priority (E_rigid %g)"
          % (name, fp["E_rigid"]))
    for queue, r in scene["queues"].items():
        check(r["core_ms_median"] >= 0 and r["frames"] > 5, "%s/%s timed" % (name, queue))
sys.exit(1 if failures else 0)
