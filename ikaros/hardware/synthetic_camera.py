"""A synthetic camera scene with a known answer, for tests, demonstrations and benchmarks.

``SyntheticScene(rows, cols, ...).frame(n)`` draws frame ``n`` as an RGB ``uint8`` image
(rows, cols, 3) and returns it with the truth: the centres of the coloured discs, the ids and
corners of the ArUco markers, and the box of the face. Everything moves on fixed paths, so
frame ``n`` is the same on every call. Used by the SyntheticCamera module and by
``python -m ikaros.hardware.mjpeg``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ._opencv import opencv

# Saturated colours that ColorClassifier-style hue tests tell apart (RGB, 0..255).
BLOB_COLOURS = [(230, 40, 40), (40, 200, 60), (50, 80, 230), (230, 210, 40), (200, 60, 210),
                (40, 210, 210)]
BACKGROUND = 60
MARKER_DICTIONARY = "DICT_4X4_50"


@dataclass
class Truth:
    """What a frame shows, in pixels: (x, y) = (column, row) of a pixel centre."""
    blob_centres: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))  # (n, 2)
    blob_radius: int = 0
    marker_ids: list[int] = field(default_factory=list)
    marker_corners: np.ndarray = field(default_factory=lambda: np.zeros((0, 4, 2)))
    face_box: tuple[int, int, int, int] | None = None   # x0, y0, x1, y1 (x1, y1 exclusive)


def face_image(size: int) -> np.ndarray:
    """A face, (size, size, 3) uint8: the astronaut from scikit-image's test data when
    scikit-image is installed, otherwise a drawn one."""
    cv2 = opencv()
    try:
        from skimage import data
        face = data.astronaut()[20:260, 120:360]        # head and shoulders, 240 x 240
    except ImportError:
        face = np.full((240, 240, 3), 200, np.uint8)
        cv2.ellipse(face, (120, 120), (80, 100), 0, 0, 360, (224, 180, 150), -1)
        for x in (90, 150):
            cv2.circle(face, (x, 100), 10, (40, 30, 30), -1)
        cv2.ellipse(face, (120, 165), (30, 12), 0, 0, 180, (120, 40, 40), -1)
    return cv2.resize(face, (size, size), interpolation=cv2.INTER_AREA)


class SyntheticScene:
    """Moving coloured discs on a gray floor, ArUco markers and optionally a face.

    The discs move on ellipses in the upper part of the image (the whole image when there are
    no markers and no face); the markers sit in a row in the lower part and drift sideways;
    the face is in the lower right corner.
    """

    def __init__(self, rows: int = 480, cols: int = 640, blobs: int = 3,
                 markers: list[int] | tuple[int, ...] = (), face: bool = False,
                 speed: float = 1.0, noise: float = 0.0, seed: int = 0):
        self.cv2 = opencv()
        if blobs > len(BLOB_COLOURS):
            raise ValueError(f"at most {len(BLOB_COLOURS)} blobs")
        self.rows, self.cols = rows, cols
        self.blobs, self.markers, self.speed, self.noise = blobs, list(markers), speed, noise
        self.rng = np.random.default_rng(seed)
        lower = bool(self.markers) or face
        self.blob_area_rows = int(rows * 0.55) if lower else rows
        self.radius = max(3, min(rows, cols) // 24)
        self.marker_size = max(24, min(rows, cols) // 6)
        self.face_size = int(min(rows * 0.42, cols * 0.3))
        self.face = face_image(self.face_size) if face else None
        if self.markers:
            aruco = self.cv2.aruco
            dictionary = aruco.getPredefinedDictionary(getattr(aruco, MARKER_DICTIONARY))
            self.marker_images = [aruco.generateImageMarker(dictionary, int(i),
                                                            self.marker_size)
                                  for i in self.markers]
        self.background = np.full((rows, cols, 3), BACKGROUND, np.uint8)

    def blob_centres(self, n: int) -> np.ndarray:
        """The disc centres of frame n, (blobs, 2) integer pixels (x, y)."""
        margin = self.radius + 2
        k = np.arange(self.blobs)
        phase = self.speed * n * 0.05 + k * 2 * np.pi / max(self.blobs, 1)
        cx, cy = self.cols / 2, self.blob_area_rows / 2
        ax, ay = cx - margin - 1, cy - margin - 1
        x = cx + ax * np.cos(phase) * (0.9 - 0.15 * k / max(self.blobs, 1))
        y = cy + ay * np.sin(phase * (1 + 0.5 * (k % 2)))
        return np.stack([np.rint(x), np.rint(y)], axis=1).astype(int)

    def marker_positions(self, n: int) -> list[tuple[int, int]]:
        """Top-left corners (x, y) of the markers in frame n."""
        s, gap = self.marker_size, self.marker_size // 2
        band = self.cols - (self.face_size + 10 if self.face is not None else 0)
        span = len(self.markers) * (s + gap)
        room = max(0, band - span - gap)
        shift = int(room / 2 * (1 + np.sin(self.speed * n * 0.03)))
        top = self.rows - s - max(gap, (self.rows - self.blob_area_rows - s) // 2)
        return [(gap + shift + i * (s + gap), top) for i in range(len(self.markers))]

    def frame(self, n: int, out: np.ndarray | None = None) -> tuple[np.ndarray, Truth]:
        """Frame n as (rows, cols, 3) RGB uint8, and its truth. With ``out`` (an array of
        that shape and type) the frame is drawn into it and it is returned."""
        if out is None:
            img = self.background.copy()
        else:
            img = out
            np.copyto(img, self.background)
        truth = Truth(blob_radius=self.radius)
        centres = self.blob_centres(n)
        for (x, y), colour in zip(centres, BLOB_COLOURS):
            self.cv2.circle(img, (int(x), int(y)), self.radius, colour, -1, self.cv2.LINE_8)
        truth.blob_centres = centres.astype(float)
        if self.markers:
            corners = []
            quiet = max(4, self.marker_size // 8)
            for (x, y), marker in zip(self.marker_positions(n), self.marker_images):
                s = self.marker_size
                img[y - quiet:y + s + quiet, x - quiet:x + s + quiet] = 255
                img[y:y + s, x:x + s] = marker[:, :, None]
                corners.append([(x, y), (x + s, y), (x + s, y + s), (x, y + s)])
            truth.marker_ids = list(self.markers)
            truth.marker_corners = np.array(corners, float) - 0.5   # pixel edges
        if self.face is not None:
            s = self.face_size
            x0, y0 = self.cols - s - 4, self.rows - s - 4
            img[y0:y0 + s, x0:x0 + s] = self.face
            truth.face_box = (x0, y0, x0 + s, y0 + s)
        if self.noise > 0:
            noisy = img + self.rng.normal(0, self.noise * 255, img.shape)
            np.copyto(img, np.clip(noisy, 0, 255), casting="unsafe")
        return img, truth
