"""The Pareto front shared by the plot scripts (bench.py, adaptive.py)."""


def pareto(points):
    """Indices of the (x, y) points no other point beats in both, in increasing x."""
    best, front = float("inf"), []
    for i in sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1])):
        if points[i][1] < best:
            best = points[i][1]
            front.append(i)
    return front
