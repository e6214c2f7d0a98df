"""Plots of the error-against-run-time report (run by run-report.sh).

Reads report.csv, table1.csv and the per-vertex dumps in the output folder; writes
img/report-*.png there. Log-log axes cannot show 0: an error of exactly 0 is drawn on
the floor line (marked "= 0") so that FIFO Priority's exact rigid regions stay visible.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

OUT = sys.argv[1] if len(sys.argv) > 1 else "build/report"
IMG = os.path.join(OUT, "img")
os.makedirs(IMG, exist_ok=True)
QUEUES = ["FIFO", "Priority", "FIFO Priority", "Max Violation"]
COLOURS = {"FIFO": "tab:blue", "Priority": "tab:red", "FIFO Priority": "tab:green",
           "Max Violation": "tab:purple"}
METRICS = [("E_rigid", "E_rigid (rigid-region distortion)"), ("E_link", "E_link (worst link violation)"),
           ("E_temporal", "E_temporal (jump per unit drag)"), ("E_ref_max", "E_ref (distance to reference, max)"),
           ("roughness", "roughness (largest umbrella Laplacian of u)")]
FLOOR = 1e-6


def finish(fig, title, path, **title_options):
    """Titles, lays out, writes (90 dpi) and closes a report figure."""
    fig.suptitle(title, **title_options)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def read(name):
    with open(os.path.join(OUT, name)) as f:
        return list(csv.DictReader(f))


def kind(r):
    """'none', 'Dykstra', 'ADMM' or 'Envelope' from a row's refinement column; 'relaxed'
    when the variant relaxes after it (any refinement)."""
    if int(r.get("relaxation", "0")) > 0:
        return "relaxed"
    return r["refinement"].split()[0]


MARKERS = {"none": "o", "Dykstra": "s", "ADMM": "^", "Envelope": "D", "relaxed": "*"}


def draw_variants(ax, rows, key, front=False):
    """Every variant as one marker: colour = queue, shape = refinement, filled = Axes,
    hollow = Link; the Pareto front (column 'front') joined by a black step line."""
    for r in rows:
        t, e = float(r["median_ms"]), max(float(r[key]), FLOOR)
        filled = r["frame"] == "Axes"
        c = COLOURS[r["queue"]]
        ax.plot([t], [e], MARKERS[kind(r)], color=c, mfc=c if filled else "none", ms=5, mew=1)
    if front:
        pts = sorted((float(r["median_ms"]), max(float(r[key]), FLOOR), r) for r in rows if r["front"] == "1")
        ax.step([p[0] for p in pts], [p[1] for p in pts], where="post", color="k", lw=0.8)
        for t, e, r in pts:
            label = "%s, %s, %s" % (r["queue"], r["frame"], r["refinement"])
            if int(r.get("relaxation", "0")) > 0:
                label += ", relax %s" % r["relaxation"]
            ax.annotate(label, (t, e), fontsize=6, xytext=(4, 2), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.axhline(FLOOR, color="grey", lw=0.5, ls=":")
    ax.set_xlabel("run time per frame (ms, median)")
    ax.grid(True, which="both", lw=0.3)


def legend(ax):
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], color=COLOURS[q], marker="o", ls="", label=q) for q in QUEUES]
    handles += [Line2D([], [], color="k", marker=MARKERS[k], ls="", mfc="none", label=("refinement: " + k) if k != "relaxed" else "+ relaxation")
                for k in MARKERS]
    handles += [Line2D([], [], color="k", marker="o", ls="", label="Axes region (filled)"),
                Line2D([], [], color="k", marker="o", ls="", mfc="none", label="Link region (hollow)"),
                Line2D([], [], color="k", lw=0.8, label="Pareto front")]
    ax.legend(handles=handles, fontsize=6, loc="lower left")


def scene_plot(scene, rows, path):
    fig, axes = plt.subplots(2, 3, figsize=(16, 8.5))
    axes.flat[-1].axis("off")
    for ax, (key, label) in zip(axes.flat, METRICS):
        draw_variants(ax, rows, key, front=(key == "E_link"))
        ax.set_ylabel(label + " / mean edge")
    legend(axes[0, 0])
    finish(fig, "%s: every variant, error against run time (front on E_link)\n"
                "(0 drawn on the dotted floor %.0e)" % (scene, FLOOR), path, fontsize=11)


def front_plot(rows, path):
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    cols = 2
    fig, axes = plt.subplots((len(scenes) + 1) // cols, cols, figsize=(13, 5.2 * ((len(scenes) + 1) // cols)),
                             squeeze=False)
    for ax, scene in zip(axes.flat, scenes):
        draw_variants(ax, [r for r in rows if r["scene"] == scene], "E_link", front=True)
        ax.set_ylabel("E_link / mean edge (0 on the dotted floor)")
        ax.set_title(scene, fontsize=10)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    legend(axes.flat[0])
    finish(fig, "Pareto front of E_link against run time: queue x frame x refinement x relaxation "
                "(each marker one variant)", path, fontsize=11)


def key_of(title):
    for prefix, key in (("Fault-step", "fault_step"), ("Equal", "equal_malleability"),
                        ("CFM", "cfm_fault"), ("Tetra", "tet_slab")):
        if title.startswith(prefix):
            return key
    return title.replace(" ", "_")


def figure6():
    rows = read("dump_figure6.csv")
    x = np.array([float(r["x"]) for r in rows])
    y = np.array([float(r["y"]) for r in rows])
    m = np.array([float(r["malleability"]) for r in rows])
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    sc = axes[0].scatter(x, y, c=m, cmap="gist_heat", s=3, vmin=0, vmax=1)
    axes[0].set_facecolor("0.6")
    axes[0].set_title("malleability: black step, white border", fontsize=9)
    fig.colorbar(sc, ax=axes[0])
    vmax = max(max(float(r["dev_fifo"]) for r in rows), 1e-12)
    for ax, (col, name) in zip(axes[1:], (("dev_fifo", "FIFO"), ("dev_fifo_priority", "FIFO Priority"))):
        d = np.array([float(r[col]) for r in rows])
        sc = ax.scatter(x, y, c=d, cmap="viridis", s=3, vmin=0, vmax=vmax)
        ax.set_title("%s: rigid-edge distortion / mean edge, max %.3g" % (name, d.max()), fontsize=9)
        fig.colorbar(sc, ax=ax)
    for ax in axes:
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
    finish(fig, "Figure 6: FIFO lets soft vertices sponsor the rigid step (ripples); "
           "FIFO Priority keeps it exact", os.path.join(IMG, "report-figure6.png"))


def figure8():
    rows = read("dump_figure8.csv")
    queues = ["FIFO", "Priority", "FIFO Priority"]
    fig, axes = plt.subplots(2, 3, figsize=(13, 8))
    jmax = max(float(r["jump"]) for r in rows)
    for c, q in enumerate(queues):
        sel = [r for r in rows if r["queue"] == q]
        x = np.array([float(r["x"]) for r in sel])
        y = np.array([float(r["y"]) for r in sel])
        uz = np.array([float(r["uz"]) for r in sel])
        jump = np.array([float(r["jump"]) for r in sel])
        tri = mtri.Triangulation(x, y)
        a = axes[0, c].tricontourf(tri, uz, levels=24, cmap="gist_heat")
        axes[0, c].set_title("%s: height after the pull" % q)
        fig.colorbar(a, ax=axes[0, c])
        b = axes[1, c].tripcolor(tri, jump, cmap="magma", vmin=0, vmax=jmax, shading="gouraud")
        axes[1, c].set_title("%s: |X(1.01 d) - X(d)| / |0.01 d|, max %.3g" % (q, jump.max()), fontsize=9)
        fig.colorbar(b, ax=axes[1, c])
    for ax in axes.flat:
        ax.set_aspect("equal")
    finish(fig, "Figure 8: equal malleability, Priority (heap order) is vein-like and jumps "
           "under a 1% move", os.path.join(IMG, "report-figure8.png"))


def table1():
    rows = read("table1.csv")
    n = [int(r["displaced_fifo_priority"]) for r in rows]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    for q, col, paper in (("FIFO", "fifo_ms", "paper_fifo_ms"), ("Priority", "priority_ms", "paper_priority_ms"),
                          ("FIFO Priority", "fifo_priority_ms", "paper_fifo_priority_ms")):
        axes[0].plot(n, [float(r[col]) for r in rows], "-o", color=COLOURS[q], label=q + " (here)")
        axes[0].plot(n, [float(r[paper]) for r in rows], "--x", color=COLOURS[q], label=q + " (paper)")
        axes[1].plot(n, [float(r[col]) / float(r["bfs_ms"]) for r in rows], "-o", color=COLOURS[q], label=q)
    axes[0].plot(n, [float(r["bfs_ms"]) for r in rows], "-s", color="k", label="BFS floor (here)")
    axes[0].set_yscale("log")
    axes[0].set_ylabel("ms per frame")
    axes[1].plot(n, [float(r["max_violation_ms"]) / float(r["bfs_ms"]) for r in rows], "-o",
                 color=COLOURS["Max Violation"], label="Max Violation")
    axes[1].axhline(2.0, color="grey", ls=":", label="goal 2x")
    axes[1].set_ylabel("time / BFS floor")
    for ax in axes:
        ax.set_xlabel("vertices displaced")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
    finish(fig, "Table 1: per-frame time at the paper's displaced counts", os.path.join(IMG, "report-table1.png"))


rows = read("report.csv")
front_plot(rows, os.path.join(IMG, "report-front.png"))
for scene in dict.fromkeys(r["scene"] for r in rows):
    scene_plot(scene, [r for r in rows if r["scene"] == scene],
               os.path.join(IMG, "report-errors-%s.png" % key_of(scene)))
figure6()
figure8()
table1()
print("plots written to", IMG)
