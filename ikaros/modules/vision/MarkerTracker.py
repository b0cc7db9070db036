"""MarkerTracker: fiducial markers (ArUco and AprilTag) with their ids, corners and poses."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, Uint8Image, check_image, opencv
from ._markers import (OPENCV_TO_IKAROS, ROW_CENTRE, ROW_CONFIDENCE, ROW_CORNERS, ROW_ID,
                       ROW_LENGTH, ROW_MATRIX)

DICTIONARIES = ("DICT_4X4_50/DICT_4X4_100/DICT_4X4_250/DICT_4X4_1000/DICT_5X5_50/"
                "DICT_5X5_100/DICT_5X5_250/DICT_5X5_1000/DICT_6X6_50/DICT_6X6_100/"
                "DICT_6X6_250/DICT_6X6_1000/DICT_7X7_50/DICT_7X7_100/DICT_7X7_250/"
                "DICT_7X7_1000/DICT_ARUCO_ORIGINAL/DICT_APRILTAG_16h5/DICT_APRILTAG_25h9/"
                "DICT_APRILTAG_36h10/DICT_APRILTAG_36h11")


class MarkerTracker(Module):
    """Finds square fiducial markers with OpenCV's ArUco detector and estimates each one's
    pose from the camera calibration and the markers' real size. Ikaros 2 used
    ARToolKitPlus and its BCH markers; here the markers come from an ArUco or AprilTag
    `dictionary` (print them with cv2.aruco.generateImageMarker), so ids are those of the
    dictionary, and the BCH ids of old models name different markers.

    Image coordinates are in 0..1 (x from the left edge, y from the top); poses are 4 × 4
    homogeneous matrices with translations in the unit of `marker_size` (mm), in the Ikaros
    frame (x forward from the camera, y left, z up) or, with coordinate_system="artoolkit",
    in the camera frame (x right, y down, z forward). A marker's own frame has x to the
    right and y up on the marker and z out of it. MARKERS has one row per marker:
    id, confidence, centre (x, y), the four corners (x, y) clockwise from the top-left of the
    printed marker, and the 16 elements of its pose row by row (28 values); the other
    outputs repeat parts of it. `calibration` is in the ARToolKit camera-file order:
    width, height, cx, cy, fx, fy, then the distortion k1, k2, p1, p2 (and k3); it is scaled
    to the input's size. A numeric `threshold` (0..255) binarises the image before detection
    (auto: ArUco's adaptive thresholds); `use_history` starts each pose from the marker's
    pose on the previous tick; `sort` orders the markers by id. Confidence is 1 for every
    detected marker."""

    max_markers = Parameter(10, "the largest number of markers reported", type="int")
    marker_size = Parameter(45.0, "the side of the markers' black square, in mm (the unit of "
                            "the poses)")
    sort = Parameter(True, "order the markers by id")
    use_history = Parameter(False, "start each pose estimate from the previous tick's pose")
    threshold = Parameter("auto", "auto, or a level 0..255 that binarises the image first")
    calibration = Parameter("640 426 294.458 161.609 675.381 681.446 -0.160115 -0.067107 "
                            "0.016423 -0.001641 0 0 10", "camera calibration: width height "
                            "cx cy fx fy k1 k2 p1 p2 [k3 ...]")
    coordinate_system = Parameter("ikaros", "frame of the poses", options="artoolkit/ikaros")
    dictionary = Parameter("DICT_4X4_50", "the marker dictionary", options=DICTIONARIES)
    frame_id = Parameter(0, "the value written to FRAME_ID (names the camera's frame)",
                         type="int")

    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    MARKERS = Output("one row of 28 values per marker: id, confidence, centre x y, corners "
                     "x0 y0 ... x3 y3, pose (16)", shape="@max_markers, 28")
    MARKER_COUNT = Output("the number of markers found", size="1")
    PROJECTION = Output("the camera matrix (fx 0 cx; 0 fy cy; 0 0 1) in pixels of INPUT, as "
                        "a 4 x 4 matrix", shape="4, 4")
    MODEL_VIEW = Output("the pose of the first marker (identity when none)", shape="4, 4")
    MATRIX = Output("the pose of each marker, 16 values row by row",
                    shape="@max_markers, 16")
    OBJECT_ID = Output("the id of each marker", shape="@max_markers, 1")
    FRAME_ID = Output("frame_id for each marker found", shape="@max_markers, 1")
    CONFIDENCE = Output("1 for each marker found", shape="@max_markers, 1")
    IMAGE_POSITION = Output("the centre (x, y) of each marker in 0..1",
                            shape="@max_markers, 2")
    EDGES = Output("the four corners (x, y) of each marker in 0..1", shape="@max_markers, 8")

    def configure(self):
        cv2 = self.cv2 = opencv()
        if self.max_markers < 1:
            raise ValueError("max_markers must be at least 1")
        aruco = cv2.aruco
        params = aruco.DetectorParameters()
        params.cornerRefinementMethod = aruco.CORNER_REFINE_SUBPIX
        self._detector = aruco.ArucoDetector(
            aruco.getPredefinedDictionary(getattr(aruco, self.dictionary)), params)
        values = [float(v) for v in str(self.calibration).replace(",", " ").split()]
        if len(values) < 6:
            raise ValueError(f"calibration needs at least width height cx cy fx fy, not "
                             f"{self.calibration!r}")
        self._calibration = values
        if self.threshold != "auto":
            try:
                self._level = float(self.threshold)
            except ValueError:
                raise ValueError(f"threshold must be auto or a number, not "
                                 f"{self.threshold!r}") from None

    def init(self):
        check_image(self.INPUT.shape)
        rows, cols = self.INPUT.shape[-2:]
        w, h, cx, cy, fx, fy = self._calibration[:6]
        sx, sy = cols / w, rows / h
        self._camera = np.array([[fx * sx, 0, cx * sx], [0, fy * sy, cy * sy], [0, 0, 1]])
        self._distortion = np.array((self._calibration[6:11] + [0] * 5)[:5])
        self.PROJECTION[...] = np.eye(4)
        self.PROJECTION[:3, :3] = self._camera
        self._size = np.array([cols, rows], np.float32)
        self._gray = GrayImage(self.INPUT)
        self._levels = Uint8Image((rows, cols))
        self._binary = np.zeros((rows, cols), np.uint8)
        s = self.marker_size / 2
        self._object = np.array([[-s, s, 0], [s, s, 0], [s, -s, 0], [-s, -s, 0]], np.float64)
        self._frame = OPENCV_TO_IKAROS if self.coordinate_system == "ikaros" else np.eye(4)
        self._previous = {}
        self.MODEL_VIEW[...] = np.eye(4)

    def _pose(self, marker_id, corners):
        cv2 = self.cv2
        guess = self._previous.get(marker_id) if self.use_history else None
        if guess is not None:
            ok, rvec, tvec = cv2.solvePnP(self._object, corners, self._camera,
                                          self._distortion, guess[0].copy(), guess[1].copy(),
                                          True, cv2.SOLVEPNP_ITERATIVE)
        else:
            ok, rvec, tvec = cv2.solvePnP(self._object, corners, self._camera,
                                          self._distortion, flags=cv2.SOLVEPNP_IPPE_SQUARE)
        self._previous[marker_id] = (rvec, tvec)
        pose = np.eye(4)
        pose[:3, :3] = cv2.Rodrigues(rvec)[0]
        pose[:3, 3] = tvec.ravel()
        return self._frame @ pose

    def tick(self):
        levels = self._levels(self._gray())
        if self.threshold != "auto":
            self.cv2.threshold(levels, self._level, 255, self.cv2.THRESH_BINARY,
                               dst=self._binary)
            levels = self._binary
        corners, ids, _ = self._detector.detectMarkers(levels)
        found = [] if ids is None else sorted(
            zip(ids.ravel().tolist(), corners), key=lambda m: m[0] if self.sort else 0)
        found = found[:self.max_markers]
        for out in (self.MARKERS, self.MATRIX, self.OBJECT_ID, self.FRAME_ID,
                    self.CONFIDENCE, self.IMAGE_POSITION, self.EDGES):
            out.fill(0)
        self.MODEL_VIEW[...] = np.eye(4)
        seen = set()
        for i, (marker_id, c) in enumerate(found):
            pixels = c.reshape(4, 2).astype(np.float64)
            pose = self._pose(marker_id, pixels)
            seen.add(marker_id)
            edges = (pixels + 0.5) / self._size
            row = self.MARKERS[i]
            row[ROW_ID], row[ROW_CONFIDENCE] = marker_id, 1.0
            row[ROW_CENTRE:ROW_CENTRE + 2] = edges.mean(axis=0)
            row[ROW_CORNERS:ROW_CORNERS + 8] = edges.ravel()
            row[ROW_MATRIX:ROW_LENGTH] = pose.ravel()
            self.MATRIX[i] = pose.ravel()
            self.OBJECT_ID[i], self.FRAME_ID[i], self.CONFIDENCE[i] = marker_id, self.frame_id, 1
            self.IMAGE_POSITION[i] = edges.mean(axis=0)
            self.EDGES[i] = edges.ravel()
            if i == 0:
                self.MODEL_VIEW[...] = pose
        self.MARKER_COUNT[0] = len(found)
        self._previous = {k: v for k, v in self._previous.items() if k in seen}
