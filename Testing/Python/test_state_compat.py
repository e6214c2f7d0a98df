"""A state file saved by an earlier version loads and gives the same shape.

Data/States/chainmail_2026-12-05.pvsm was saved by main of 2026-12-05 (before the
ChainMail panel was trimmed: it holds ExactRigidAtZero, since removed, and values for
properties now advanced or hidden): painted Fault Step Horizon, Link region, ranges,
Smooth curve, refinement, relaxation, FIFO, one committed grasp and one pending. Loading
it must give, bit for bit, the points of the same pipeline built here property by property,
given the state's edit record (a committed edit is data: its offsets are replayed as saved,
not recomputed, so a later change of ChainMail's order leaves it as the user made it)."""
import os

import numpy as np

from geoshaping_testing import check, load, points
from paraview.simple import *  # noqa: F401,F403

STATE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data", "States",
                     "chainmail_2026-12-05.pvsm")
check("ExactRigidAtZero" in open(STATE).read(), "the state holds a property since removed")

load(ns=globals())
LoadState(STATE)
loaded = points(FindSource("Chain"))
history = list(FindSource("Chain").EditHistory)
check(len(history) > 0 and history[0] != "", "the state holds one committed edit")

ResetSession()
load(ns=globals())
src = FaultStepHorizon()  # noqa: F405
paint = MalleabilityPaint(Input=src)  # noqa: F405
paint.InitialMalleability = 0.7
paint.Dabs = [20.0, 10.0, 0.0, 6.0, 0.0, 1.0, 30.0, 10.0, 0.0, 5.0, 1.0, 0.6]
chain = ChainMailDeformation(Input=paint)  # noqa: F405
chain.MalleabilityArray = ["POINTS", "Malleability"]
chain.ValidRegionFrame = "Link"
chain.StretchRange = [1.02, 1.6]
chain.CompressionRange = [0.98, 0.6]
chain.ShearRange = [0.05, 0.9]
chain.TransferCurveShape = "Smooth"
chain.RefinementIterations = 4
chain.RelaxationIterations = 2
chain.CandidateQueue = "FIFO"
chain.EditHistory = history
chain.GraspPointId = 500
chain.Displacement = [2.0, 0.0, -3.0]
built = points(chain)
check(loaded.shape == built.shape and np.array_equal(loaded, built),
      "the old state gives the shape bit for bit (max diff %g)"
      % (np.abs(loaded - built).max() if loaded.shape == built.shape else -1))
check(np.abs(built - points(src)).max() > 1.0, "and the shape is not the rest shape")
