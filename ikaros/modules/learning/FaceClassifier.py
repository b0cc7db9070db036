"""FaceClassifier: learns whose face an embedding is, and notices new faces."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class FaceClassifier(Module):
    """Recognises identities from face embeddings (such as the 128 values of a face
    recognition network, whose embeddings of one person lie within 0.6 of each other) and
    learns new ones as they come. Each class keeps up to ``vectors_per_class`` embeddings.
    On each tick the Euclidean distance from INPUT to every stored embedding is measured;
    DISTANCE is the smallest (0 while nothing is stored). Within ``threshold`` of a stored
    embedding the face is known: the class most frequent among the ``k`` nearest stored
    embeddings (ties: the nearest's) wins, OUTPUT is 1 at its index and 0 elsewhere, its
    COUNT goes up by one, and while learning the embedding is added to its class until the
    class is full. Further away the face is new: NOVELTY is 1 and OUTPUT all 0, and while
    learning it becomes a candidate; when ``confirmation_count`` new embeddings in a row lie
    within ``threshold`` of the first of them, they become a new class (its COUNT the number
    of them, OUTPUT 1 at it), if fewer than ``capacity`` classes exist (otherwise a warning
    says so once). An all-zero INPUT is no face: OUTPUT and NOVELTY are 0 and the candidate
    is dropped. Learning is on while LEARN is unconnected or above 0. CLASSES is the number
    of classes, VECTORS the embeddings stored per class; the classes are saved with the
    model's state. The original's class is known only by its interface: the rules are this
    project's reading of it (the k-nearest-neighbour vote, the threshold, and confirmation
    before a new class)."""

    capacity = Parameter(16, "the most classes", type="int", range=(1, None), fixed=True)
    threshold = Parameter(0.6, "the largest distance of an embedding of a known face from "
                          "its class", range=(0, None))
    confirmation_count = Parameter(3, "new embeddings in a row that make a class",
                                   type="int", range=(1, None))
    k = Parameter(3, "the nearest stored embeddings that vote", type="int", range=(1, None))
    vectors_per_class = Parameter(5, "the most embeddings kept per class", type="int",
                                  range=(1, None), fixed=True)

    INPUT = Input("a face embedding (all 0: no face)", flatten=True)
    LEARN = Input("above 0 (or unconnected): learn", optional=True)
    OUTPUT = Output("1 at the recognised class", shape="@capacity")
    NOVELTY = Output("1 for a face that is not known", shape="1")
    DISTANCE = Output("the distance to the nearest stored embedding", shape="1")
    CLASSES = Output("the number of classes", shape="1")
    COUNT = Output("how often each class was recognised", shape="@capacity")
    VECTORS = Output("the embeddings stored per class", shape="@capacity")

    state = ("stored", "candidates", "candidate_count", "warned")

    def init(self):
        size = self.INPUT.size
        self.stored = np.zeros((int(self.capacity), int(self.vectors_per_class), size))
        self.candidates = np.zeros((int(self.confirmation_count), size))
        self.candidate_count = 0
        self.warned = False

    def _nearest(self, vector):
        """Distances to the stored embeddings, with their classes, nearest first."""
        held = self.VECTORS.astype(int)
        classes = np.repeat(np.arange(len(held)), held)
        vectors = np.concatenate([self.stored[c, :n] for c, n in enumerate(held)]) \
            if held.any() else np.zeros((0, vector.size))
        distances = np.linalg.norm(vectors - vector, axis=1)
        order = np.argsort(distances, kind="stable")
        return distances[order], classes[order]

    def _vote(self, classes):
        votes = np.bincount(classes[:int(self.k)], minlength=int(self.capacity))
        best = np.flatnonzero(votes == votes.max())
        return next(c for c in classes if c in best)      # a tie goes to the nearest

    def _add(self, cls, vector):
        n = int(self.VECTORS[cls])
        if n < self.vectors_per_class:
            self.stored[cls, n] = vector
            self.VECTORS[cls] = n + 1

    def _candidate(self, vector):
        first = self.candidates[0]
        if self.candidate_count and np.linalg.norm(vector - first) > self.threshold:
            self.candidate_count = 0
        self.candidates[self.candidate_count] = vector
        self.candidate_count += 1
        if self.candidate_count < self.confirmation_count:
            return
        self.candidate_count = 0
        cls = int(self.CLASSES[0])
        if cls >= self.capacity:
            if not self.warned:
                self.warning(f"all {self.capacity} classes are taken: new faces are not "
                             f"learned")
                self.warned = True
            return
        for candidate in self.candidates:
            self._add(cls, candidate)
        self.CLASSES[0] = cls + 1
        self.COUNT[cls] = self.confirmation_count
        self.OUTPUT[cls] = 1

    def tick(self):
        vector = np.asarray(self.INPUT, np.float64).ravel()
        learning = self.LEARN is None or float(np.asarray(self.LEARN).flat[0]) > 0
        self.OUTPUT[...] = 0
        self.NOVELTY[0] = 0
        if not vector.any():
            self.candidate_count = 0
            return
        distances, classes = self._nearest(vector)
        self.DISTANCE[0] = distances[0] if len(distances) else 0.0
        if len(distances) and distances[0] <= self.threshold:
            cls = self._vote(classes)
            self.OUTPUT[cls] = 1
            self.COUNT[cls] += 1
            self.candidate_count = 0
            if learning:
                self._add(cls, vector)
            return
        self.NOVELTY[0] = 1
        if learning:
            self._candidate(vector)
