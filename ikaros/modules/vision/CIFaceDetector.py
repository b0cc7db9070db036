"""CIFaceDetector: faces with positions, features and identities kept from tick to tick."""
from ikaros.module import Output, Parameter

from ._faces import FaceDetectorBase, overlap

# Where the eyes and the mouth lie in a frontal face box of this cascade, as fractions of it.
LEFT_EYE, RIGHT_EYE, MOUTH = (0.3, 0.38), (0.7, 0.38), (0.5, 0.78)


class CIFaceDetector(FaceDetectorBase):
    """Finds frontal faces and follows them from tick to tick. Ikaros 2 used macOS Core
    Image; this one runs OpenCV's LBP frontal-face cascade (the copy shipped inside
    scikit-image, so nothing is downloaded) with scikit-image's multi-scale detector, for
    faces at least `min_size` of the image's shorter side. Positions, sizes and bounds are
    in 0..1 image coordinates, largest face first; rows past FACE_COUNT are 0. The cascade
    finds faces, not their parts: the eye and mouth positions are where they lie in an
    average frontal face of that box (eyes at 30 % and 70 % across and 38 % down, the mouth
    at 78 % down; "left" is the eye on the left of the image), ROTATION is 0 (only upright
    faces are found), and SMILE and BLINK are always 0 (detect_smiles, detect_blinks and
    mouth_correction are read for compatibility). With use_tracking a face that overlaps
    one of the previous tick (intersection over union above 0.3) keeps its OBJECT_ID and
    its LIFE (ticks seen in a row) grows; a new face gets a new id, and NOVELTY 1 on its
    first tick. Without tracking every face is new each tick. Detection takes about
    0.2 s on a 640 × 480 image with the default min_size (the small faces cost the most):
    give the module async="yes" in a real-time model, or a larger min_size."""

    min_size = Parameter(0.1, "the smallest face, as a fraction of the image's shorter side")
    use_tracking = Parameter(True, "keep the identities of faces from tick to tick")
    detect_smiles = Parameter(True, "compatibility only: smiles are not detected (SMILE 0)")
    detect_blinks = Parameter(True, "compatibility only: blinks are not detected (BLINK 0)")
    mouth_correction = Parameter(True, "compatibility only")

    EYE_LEFT_POSITION = Output("the left eye's (x, y) in 0..1, placed by the face's box",
                               shape="@max_faces, 2")
    EYE_RIGHT_POSITION = Output("the right eye's (x, y) in 0..1, placed by the face's box",
                                shape="@max_faces, 2")
    MOUTH_POSITION = Output("the mouth's (x, y) in 0..1, placed by the face's box",
                            shape="@max_faces, 2")
    ROTATION = Output("the face's rotation in the image plane (always 0: upright faces)",
                      shape="@max_faces")
    SMILE = Output("1 for a smile (always 0: not detected)", shape="@max_faces")
    BLINK_LEFT = Output("1 for a closed left eye (always 0: not detected)",
                        shape="@max_faces")
    BLINK_RIGHT = Output("1 for a closed right eye (always 0: not detected)",
                         shape="@max_faces")
    NOVELTY = Output("1 on the first tick a face is seen, otherwise 0", shape="@max_faces")
    OBJECT_ID = Output("an id that a tracked face keeps (1, 2, ...; 0 for no face)",
                       shape="@max_faces")
    LIFE = Output("the number of ticks in a row a face has been seen", shape="@max_faces")

    @property
    def smallest_face(self):
        return self.min_size

    def init(self):
        super().init()
        self._previous = []          # (box, id, life) of the last tick
        self._next_id = 1

    def tick(self):
        boxes = self.detect()
        self.write_faces(boxes)
        for out in (self.EYE_LEFT_POSITION, self.EYE_RIGHT_POSITION, self.MOUTH_POSITION,
                    self.NOVELTY, self.OBJECT_ID, self.LIFE):
            out.fill(0)
        n = len(boxes)
        if n:
            b = self.FACE_BOUNDS[:n]
            x0, y0, w, h = b[:, 0], b[:, 1], b[:, 2] - b[:, 0], b[:, 5] - b[:, 1]
            for out, (fx, fy) in ((self.EYE_LEFT_POSITION, LEFT_EYE),
                                  (self.EYE_RIGHT_POSITION, RIGHT_EYE),
                                  (self.MOUTH_POSITION, MOUTH)):
                out[:n, 0], out[:n, 1] = x0 + fx * w, y0 + fy * h
        current, taken = [], set()
        for i, box in enumerate(boxes):
            match = None
            if self.use_tracking:
                scores = [(overlap(box, p[0]), k) for k, p in enumerate(self._previous)
                          if k not in taken]
                best = max(scores, default=(0.0, None))
                if best[0] > 0.3:
                    match = best[1]
                    taken.add(match)
            if match is None:
                face_id, life = self._next_id, 1
                self._next_id += 1
                self.NOVELTY[i] = 1
            else:
                face_id, life = self._previous[match][1], self._previous[match][2] + 1
            self.OBJECT_ID[i], self.LIFE[i] = face_id, life
            current.append((box, face_id, life))
        self._previous = current
