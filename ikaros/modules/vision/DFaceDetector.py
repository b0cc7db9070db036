"""DFaceDetector: frontal faces with their positions, sizes and bounds."""
from ._faces import FaceDetectorBase


class DFaceDetector(FaceDetectorBase):
    """Finds frontal faces. Ikaros 2 used dlib's detector; this one runs OpenCV's LBP
    frontal-face cascade (the copy shipped inside scikit-image, so nothing is downloaded) with
    scikit-image's multi-scale cascade detector, for faces at least a tenth of the image's
    shorter side (and 24 pixels). Faces are listed largest first; rows past FACE_COUNT are 0.
    Positions, sizes and bounds are in 0..1 image coordinates. Detection takes about
    0.2 s on a 640 × 480 image: give the module async="yes" in a real-time model."""

    def tick(self):
        self.write_faces(self.detect())
