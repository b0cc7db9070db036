"""SpatialClustering's raster-order clustering, computed on many pixels at once.

Pixel by pixel the rule is: a pixel joins the nearest cluster whose running centroid lies
within the radius (the first such cluster on a tie), or else starts a new cluster (once
there are ``limit``, it starts the last one anew). Each decision depends on the centroids
the earlier pixels made, so the pixels are taken in windows: each pixel of the window is
given the cluster it would join if the centroids stayed as they are; the running sums
those choices make give every pixel its centroids; the pixels up to the first whose choice
those centroids change (or that starts a cluster) are settled at once, that pixel is
settled by its own rule, and the next window starts after it. Where such events come every
few pixels (scattered pixels, clusters that restart), a window costs more than it settles:
then the pixels are taken one by one, until a run of them has joined clusters without
starting one. The centroids and distances are the same float64 operations either way
(sums of whole numbers, one division), so the result is the same to the last bit.
"""
from __future__ import annotations

import numpy as np

# pixels x clusters worked on at once: at first and at most
FIRST_WINDOW, LARGEST_WINDOW = 1024, 1 << 16
# a window that settles fewer pixels than this hands over to pixels one by one, and this
# many pixels in a row that join clusters hand back to windows
RUN = 256


def raster_clusters(rows: np.ndarray, columns: np.ndarray, radius2: float,
                    limit: int) -> list[tuple[int, int, int]]:
    """The clusters of the pixels (``rows``, ``columns`` in raster order) as (sum of
    columns, sum of rows, count), in the order they were made."""
    pixels = np.stack([columns, rows, np.ones_like(rows)], axis=1).astype(np.int64)
    sums = np.zeros((limit, 3), np.int64)
    made, start, total = 0, 0, len(pixels)
    window, one_by_one = FIRST_WINDOW, True
    while start < total:
        if one_by_one:
            part = pixels[start:start + 8 * RUN]
            settled, made = _one_by_one(sums, made, part, radius2)
            one_by_one = settled == len(part)
        else:
            part = pixels[start:start + max(1, window // made)]
            settled, made = _window(sums, made, part, radius2)
            window = (min(2 * window, LARGEST_WINDOW) if settled == len(part) else
                      max(FIRST_WINDOW, 2 * settled))
            one_by_one = settled < min(RUN, len(part))
        start += settled
    return [(int(sx), int(sy), int(n)) for sx, sy, n in sums[:made]]


def _one_by_one(sums: np.ndarray, made: int, part: np.ndarray,
                radius2: float) -> tuple[int, int]:
    """The rule pixel by pixel (in Python numbers) over ``part``, until RUN pixels in a
    row have joined clusters; (pixels settled, clusters after them). All of ``part`` is
    settled only when no such run ended it."""
    limit = len(sums)
    clusters = sums[:made].tolist()
    settled, joined = 0, 0
    for col, row, _ in part.tolist():
        if joined == RUN:
            break
        settled += 1
        best, nearest = -1, radius2
        for i, (sx, sy, n) in enumerate(clusters):
            dx, dy = sx / n - col, sy / n - row
            d2 = dx * dx + dy * dy
            if d2 < nearest or (best < 0 and d2 == nearest):
                best, nearest = i, d2
        if best >= 0:
            cluster = clusters[best]
            cluster[0] += col
            cluster[1] += row
            cluster[2] += 1
            joined += 1
            continue
        joined = 0
        if len(clusters) < limit:
            clusters.append([col, row, 1])
        else:
            clusters[-1] = [col, row, 1]
    sums[:len(clusters)] = clusters
    return settled, len(clusters)


def _window(sums: np.ndarray, made: int, part: np.ndarray, radius2: float) -> tuple[int, int]:
    """Settle the pixels of ``part`` up to and with the first whose choice the running
    centroids change or that starts a cluster; (pixels settled, clusters after them)."""
    col, row = part[:, 0:1], part[:, 1:2]
    clusters = sums[:made]
    assumed = _nearest(_squared_distances(clusters[None], col, row), radius2)
    joins = (assumed[:, None] == np.arange(made))[:, :, None] * part[:, None, :]
    before = np.cumsum(joins, axis=0) - joins            # the sums of the earlier pixels
    actual = _nearest(_squared_distances(clusters[None] + before, col, row), radius2)
    wrong = (actual != assumed) | (actual < 0)
    if not wrong.any():
        clusters += before[-1] + joins[-1]
        return len(part), made
    settled = int(np.argmax(wrong))
    clusters += before[settled]
    chosen = actual[settled]
    if chosen >= 0:
        clusters[chosen] += part[settled]
    elif made < len(sums):
        sums[made] = part[settled]
        made += 1
    else:
        sums[made - 1] = part[settled]
    return settled + 1, made


def _nearest(d2: np.ndarray, radius2: float) -> np.ndarray:
    """For each row of squared distances (pixels x clusters), the first cluster at the
    least distance if that is at most ``radius2``, else -1."""
    best = np.argmin(d2, axis=1)
    best[~(np.take_along_axis(d2, best[:, None], axis=1)[:, 0] <= radius2)] = -1
    return best


def _squared_distances(sums: np.ndarray, columns: np.ndarray,
                       rows: np.ndarray) -> np.ndarray:
    """(sum of columns / count - column)² + (sum of rows / count - row)² in float64, as
    the rule computes it, for sums (..., clusters, 3) and pixels (..., 1)."""
    dx = sums[..., 0] / sums[..., 2] - columns
    dy = sums[..., 1] / sums[..., 2] - rows
    dx *= dx
    dy *= dy
    return dx + dy
