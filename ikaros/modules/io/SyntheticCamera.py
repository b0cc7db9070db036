"""SyntheticCamera: a camera without hardware, whose frames have a known answer."""
import numpy as np

from ikaros.module import Module, Output, Parameter

from ikaros.hardware.synthetic_camera import BLOB_COLOURS, SyntheticScene

# each 8-bit level as a float32 value 0..1: level * float32(1/255)
LEVELS = np.multiply(np.arange(256, dtype=np.uint8), np.float32(1 / 255))


class SyntheticCamera(Module):
    """A camera for tests and demonstrations: coloured discs that move on fixed paths over a
    gray floor, ArUco markers (dictionary DICT_4X4_50) with the ids in `markers`, and with
    `face` a face (the astronaut of scikit-image's test data, or a drawn face without
    scikit-image). Tick k shows frame k (init shows frame 0). Besides the image outputs it
    gives the truth: the disc centres, the markers' ids and corners and the face's box, all
    as image coordinates in 0..1 (x from the left edge, y from the top edge; the centre of
    pixel (row r, column c) is ((c + 0.5) / cols, (r + 0.5) / rows))."""

    size_x = Parameter(640, "columns of the frames", type="int")
    size_y = Parameter(480, "rows of the frames", type="int")
    blobs = Parameter(3, f"number of coloured discs (0 to {len(BLOB_COLOURS)}), in the order "
                      "red, green, blue, yellow, magenta, cyan", type="int")
    markers = Parameter("", "ids of the ArUco markers to show (DICT_4X4_50, 0..49)",
                        type="array")
    face = Parameter(False, "show a face in the lower right corner")
    speed = Parameter(1.0, "how fast the discs and markers move (0: still)")
    noise = Parameter(0.0, "standard deviation of Gaussian noise added to each pixel (0..1)")

    OUTPUT = Output("the colour frame, (3, rows, cols), planes red, green, blue in 0..1",
                    shape="3, @size_y, @size_x")
    RED = Output("the red plane (rows, cols)", alias="OUTPUT[0]")
    GREEN = Output("the green plane (rows, cols)", alias="OUTPUT[1]")
    BLUE = Output("the blue plane (rows, cols)", alias="OUTPUT[2]")
    INTENSITY = Output("the intensity (rows, cols): the mean of red, green and blue",
                       shape="@size_y, @size_x")
    POSITIONS = Output("the disc centres, one row (x, y) per disc, in 0..1 (empty without "
                       "discs)", optional=True)
    MARKER_IDS = Output("the ids of the markers shown (empty without markers)", optional=True)
    MARKER_CORNERS = Output("the corners of each marker, one row (x0 y0 x1 y1 x2 y2 x3 y3) "
                            "per marker: top-left, top-right, bottom-right, bottom-left, in "
                            "0..1 (empty without markers)", optional=True)
    FACE_BOUNDS = Output("the face's box (x0, y0, x1, y1) in 0..1; all 0 without `face`",
                         size="4")

    def configure(self):
        if not 0 <= self.blobs <= len(BLOB_COLOURS):
            raise ValueError(f"blobs must be 0 to {len(BLOB_COLOURS)}, not "
                              f"{self.blobs}")
        ids = [int(i) for i in np.ravel(self.markers)]
        if any(not 0 <= i < 50 for i in ids):
            raise ValueError(f"marker ids must be 0..49 (DICT_4X4_50), not {ids}")
        if self.size_x < 32 or self.size_y < 32:
            raise ValueError("size_x and size_y must be at least 32")
        self.scene = SyntheticScene(self.size_y, self.size_x, self.blobs, ids, self.face,
                                    self.speed, self.noise)
        if self.blobs:
            self.set_output_shape("POSITIONS", (self.blobs, 2))
        if ids:
            self.set_output_shape("MARKER_IDS", (len(ids),))
            self.set_output_shape("MARKER_CORNERS", (len(ids), 8))

    def init(self):
        self._scale = np.array([self.size_x, self.size_y], np.float32)
        self._frame = np.zeros((self.size_y, self.size_x, 3), np.uint8)
        self._levels = [np.zeros((self.size_y, self.size_x), np.uint8) for _ in range(3)]
        self._show(0)

    def _show(self, n):
        img, truth = self.scene.frame(n, self._frame)
        cv2 = self.scene.cv2
        cv2.mixChannels([img], self._levels, [0, 0, 1, 1, 2, 2])    # planes of 8-bit levels
        for levels, plane in zip(self._levels, self.OUTPUT):
            cv2.LUT(levels, LEVELS, dst=plane)
        red, green, blue = self.OUTPUT
        # the mean of the planes, as np.mean(axis=0) makes it: (red + green) + blue, / 3
        np.add(red, green, out=self.INTENSITY)
        self.INTENSITY += blue
        self.INTENSITY /= np.float32(3)
        if self.blobs:
            self.POSITIONS[...] = (truth.blob_centres + 0.5) / self._scale
        if truth.marker_ids:
            self.MARKER_IDS[...] = truth.marker_ids
            corners = (truth.marker_corners + 0.5) / self._scale
            self.MARKER_CORNERS[...] = corners.reshape(len(truth.marker_ids), 8)
        if truth.face_box is not None:
            self.FACE_BOUNDS[...] = np.array(truth.face_box) / np.tile(self._scale, 2)

    def tick(self):
        self._show(self.clock.tick)
