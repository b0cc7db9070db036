"""Writes examples/modules/tracking_example.mp4, the movie the tracking examples play: the
astronaut of scikit-image's test data (a NASA photograph, public domain) seen by a camera
that pans, turns and zooms a little, 320 x 240, 36 frames that loop smoothly.

    python scripts/make_tracking_movie.py
"""
import os

import cv2
import imageio.v2 as imageio
import numpy as np
from skimage import data

FRAMES, WIDTH, HEIGHT = 36, 320, 240
OUT = os.path.join(os.path.dirname(__file__), "..", "examples", "modules",
                   "tracking_example.mp4")


def camera(k: int) -> np.ndarray:
    """The 2 x 3 affine map from the picture's pixels to frame k's: the picture turned,
    scaled and moved along a closed path (tests check the tracking examples against it)."""
    phase = 2 * np.pi * k / FRAMES
    angle = 6 * np.sin(phase)                                   # degrees
    scale = 0.55 * (1 + 0.06 * np.sin(2 * phase))
    centre = (256 + 40 * np.sin(phase), 230 + 25 * np.cos(phase))
    m = cv2.getRotationMatrix2D(centre, angle, scale)
    m[:, 2] += (WIDTH / 2 - centre[0], HEIGHT / 2 - centre[1])
    return m


def view(k: int, picture: np.ndarray) -> np.ndarray:
    """Frame k."""
    return cv2.warpAffine(picture, camera(k), (WIDTH, HEIGHT), flags=cv2.INTER_AREA,
                          borderMode=cv2.BORDER_REFLECT)


def main():
    picture = data.astronaut()
    with imageio.get_writer(OUT, fps=12, codec="libx264", quality=4,
                            macro_block_size=16) as writer:
        for k in range(FRAMES):
            writer.append_data(view(k, picture))


if __name__ == "__main__":
    main()
