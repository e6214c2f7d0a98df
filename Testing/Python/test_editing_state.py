"""Grasps with commits, undo, redo and reset, each run as the panel's buttons run it (the
command invoked on the proxy, nothing else); after every step SaveState, and a fresh
pvpython process that LoadStates each file gives the identical points (bit-exact)."""
import os
import shutil
import subprocess
import sys

import numpy as np

from geoshaping_testing import check, load, points, triangulated_plane
from paraview.simple import *  # noqa: F401,F403

TMP = os.environ["GEOSHAPING_TEST_TMP"]


# Each edit as the properties panel's buttons run it: the command invoked on the proxy and
# nothing else. The proxy (vtkSMChainMailDeformationProxy) keeps its EditHistory in step
# (docs/editing.md), so SaveState holds every edit whatever ran the command.
def invoke(chain, command):
    chain.SMProxy.InvokeCommand(command)


def commit(chain):
    invoke(chain, "CommitEdit")


def undo(chain):
    invoke(chain, "UndoEdit")


def redo(chain):
    invoke(chain, "RedoEdit")


def reset(chain):
    invoke(chain, "ResetEdits")


if len(sys.argv) > 1:  # the fresh session: load each state, write its points
    load(ns=globals())
    for path in sys.argv[1:]:
        ResetSession()
        load(ns=globals())
        LoadState(path)
        np.save(path + ".npy", points(FindSource("Chain")))
    sys.exit(0)

load(ns=globals())
surface = triangulated_plane(30)
# UTM-sized coordinates: bit-exactness must not rely on small numbers.
moved = Transform(registrationName="Moved", Input=surface)
moved.Transform.Translate = [512345.25, 4123456.5, 250.0]
paint = MalleabilityPaint(registrationName="Paint", Input=moved)  # noqa: F405
paint.InitialMalleability = 0.8
paint.Dabs = [512350.0, 4123460.0, 250.0, 4.0, 0.0, 1.0]  # a rigid block
chain = ChainMailDeformation(registrationName="Chain", Input=paint)  # noqa: F405
chain.MalleabilityArray = ["POINTS", "Malleability"]
rest = points(chain)

steps = []  # (label, points, state file)


def step(label):
    path = os.path.join(TMP, "editing-%02d.pvsm" % len(steps))
    SaveState(path)
    steps.append((label, points(chain), path))


def drag(grasp, d):
    chain.GraspPointId = grasp
    chain.Displacement = d
    return points(chain)


step("original")
first = drag(15 * 31 + 15, [0.0, 0.0, 3.0])
commit(chain)
check(np.array_equal(points(chain), first), "commit keeps the dragged shape")
step("one edit")
second = drag(15 * 31 + 16, [1.0, -0.5, 2.0])
check(second[15 * 31 + 15, 2] - rest[15 * 31 + 15, 2] >= 3.0,
      "the second grasp pulls from the committed shape")
commit(chain)
step("two edits")
drag(5 * 31 + 20, [0.0, 0.0, -4.0])
commit(chain)
step("three edits")
check(len(chain.EditHistory) == 3, "the proxy's EditHistory holds the three commits")
three = points(chain)
undo(chain)
check(np.array_equal(points(chain), steps[2][1]), "undo restores the previous points bit-exactly")
step("undone")
check(len(chain.EditHistory) == 2, "the proxy's EditHistory lost the undone edit")
undo(chain)
check(np.array_equal(points(chain), steps[1][1]), "a second undo goes one step further")
redo(chain)
check(np.array_equal(points(chain), steps[2][1]), "redo re-applies the edit bit-exactly")
step("redone")
redo(chain)
check(np.array_equal(points(chain), three), "redo again gives the third edit back")
step("redone twice")
drag(20 * 31 + 8, [0.5, 0.5, 1.5])
step("dragging, uncommitted")
chain.GraspPointId = -1
reset(chain)
check(np.array_equal(points(chain), rest), "reset gives the original points back")
step("reset")
redo(chain)
check(np.array_equal(points(chain), steps[1][1]), "after a reset the edits are redoable")
paint.InitialMalleability = 0.2  # repainted: the committed edits keep their result
check(np.array_equal(points(chain), steps[1][1]), "repainting does not alter committed edits")
step("repainted")

sizes = [len(r) for r in chain.EditHistory]
print("record sizes (characters):", sizes)

result = subprocess.run([shutil.which("pvpython"), "--force-offscreen-rendering", __file__] +
                        [s[2] for s in steps], capture_output=True, text=True, timeout=240)
print(result.stdout[-2000:], result.stderr[-2000:])
check(result.returncode == 0, "the fresh session loads every state")
for label, expected, path in steps:
    loaded = np.load(path + ".npy")
    check(np.array_equal(loaded, expected), "fresh LoadState, %s: identical points" % label)
