"""Shared by MarkerTracker and CalibrateCameraPosition: the layout of a marker table row and
the change from OpenCV's camera frame to the Ikaros frame."""
import numpy as np

# A row of MarkerTracker's MARKERS table: id, confidence, centre (x, y), four corners
# (x, y) and the marker's 4 x 4 pose, row by row.
ROW_ID, ROW_CONFIDENCE, ROW_CENTRE, ROW_CORNERS, ROW_MATRIX, ROW_LENGTH = 0, 1, 2, 4, 12, 28

# OpenCV's camera frame (x right, y down, z forward) to the Ikaros frame (x forward, y left,
# z up): x' = z, y' = -x, z' = -y.
OPENCV_TO_IKAROS = np.array([[0, 0, 1, 0], [-1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 0, 1]],
                            np.float64)
