"""Which vertices the GUI markers test puts markers over (gui_setup_markers.py) and how
far above: shared with markers_checks.py, which reads them from the snapshot's rest
points."""
STRIDE = 7
OFFSET = 0.5


def markers(rest):
    """[(vertex, (x, y, z + OFFSET))] for every STRIDE-th vertex strictly inside the xy
    bounds of the rest points `rest` (a sequence of x, y, z)."""
    xs = [p[0] for p in rest]
    ys = [p[1] for p in rest]
    chosen = []
    for v in range(0, len(rest), STRIDE):
        x, y, z = rest[v][0], rest[v][1], rest[v][2]
        if min(xs) < x < max(xs) and min(ys) < y < max(ys):
            chosen.append((v, (x, y, z + OFFSET)))
    return chosen
