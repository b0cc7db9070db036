"""TemplateFeatureBank: learns templates, each the features of one view of an object."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._template import (central_region, flag, inside, rectangle_corners, rows)


class TemplateFeatureBank(Module):
    """Stores templates to be found again later: on the tick LEARN rises above 0, the
    feature points of KEYPOINTS that lie in the central learning region (``learning_region``
    of the frame's width and of its height) become a new template, with their DESCRIPTORS
    and SCORES, provided there are at least ``min_features`` of them (otherwise a warning
    says how many there were). The region's corners are the template's outline
    (TEMPLATE_CORNERS). A CLEAR above 0 forgets every template (before learning, when both
    come on one tick). When ``max_templates`` templates are stored, or a new one would take
    the stored points past ``max_stored_features``, the oldest are forgotten first. The
    templates are the outputs: TEMPLATE_KEYPOINTS, TEMPLATE_DESCRIPTORS and TEMPLATE_SCORES
    hold the points of all templates one after the other, TEMPLATE_RANGES one row (first,
    count) per template, TEMPLATE_CORNERS one row of corners (x, y) per template (top-left,
    top-right, bottom-right, bottom-left, pixels), and they are saved with the model's state.
    The layouts are this project's reading of the Ikaros 3 interface
    (docs/vision-tracking.md). Points are pixels of an ``image_width`` x ``image_height``
    frame; descriptors of any length (ORB's 32 bytes, ALIKED's 128 values) are kept as
    they come."""

    image_width = Parameter(320, "the width of the frame the points are given in",
                            range=(1, None))
    image_height = Parameter(240, "the height of that frame", range=(1, None))
    learning_region = Parameter(0.5, "the part of the frame's width and height, centred, "
                                "whose points are learned", range=(0, 1))
    min_features = Parameter(6, "the fewest points a template is learned from", type="int",
                             range=(1, None))
    max_templates = Parameter(16, "the most templates kept", type="int", range=(1, None),
                              fixed=True)
    max_stored_features = Parameter(8192, "the most points kept over all templates",
                                    type="int", range=(1, None), fixed=True)

    KEYPOINTS = Input("the current points, one row (x, y) each, in pixels")
    DESCRIPTORS = Input("the descriptor of each point, one row each")
    SCORES = Input("the score of each point")
    LEARN = Input("learn a template on the tick this rises above 0", size="1")
    CLEAR = Input("above 0: forget every template", size="1")
    TEMPLATE_KEYPOINTS = Output("the templates' points, one row (x, y) each", dynamic=True,
                                capacity="@max_stored_features, 2")
    TEMPLATE_DESCRIPTORS = Output("the templates' descriptors, one row each", dynamic=True,
                                  capacity="@max_stored_features, DESCRIPTORS.cols")
    TEMPLATE_SCORES = Output("the templates' point scores", dynamic=True,
                             capacity="@max_stored_features")
    TEMPLATE_RANGES = Output("one row (first, count) per template", dynamic=True,
                             capacity="@max_templates, 2")
    TEMPLATE_CORNERS = Output("one row of corners x0 y0 ... x3 y3 per template", dynamic=True,
                              capacity="@max_templates, 8")

    state = ("learning",)

    def init(self):
        self.learning = False          # LEARN was above 0 on the last tick
        self._width = self.TEMPLATE_DESCRIPTORS.capacity[1]

    def _templates(self):
        """The stored templates as (points, descriptors, scores, corners) each."""
        keypoints, descriptors = np.asarray(self.TEMPLATE_KEYPOINTS), np.asarray(
            self.TEMPLATE_DESCRIPTORS)
        scores, corners = np.asarray(self.TEMPLATE_SCORES), np.asarray(self.TEMPLATE_CORNERS)
        return [(keypoints[a:a + n], descriptors[a:a + n], scores[a:a + n], corners[t])
                for t, (a, n) in enumerate(np.asarray(self.TEMPLATE_RANGES, np.int64))]

    def _store(self, templates):
        first = np.cumsum([0] + [len(t[0]) for t in templates])[:-1]
        self.TEMPLATE_RANGES.set(np.column_stack([first, [len(t[0]) for t in templates]])
                                 if templates else np.zeros((0, 2)))
        self.TEMPLATE_CORNERS.set(np.array([t[3] for t in templates]).reshape(-1, 8))
        self.TEMPLATE_KEYPOINTS.set(np.concatenate([t[0] for t in templates]).reshape(-1, 2)
                                    if templates else np.zeros((0, 2)))
        self.TEMPLATE_DESCRIPTORS.set(
            np.concatenate([t[1] for t in templates]).reshape(-1, self._width)
            if templates else np.zeros((0, self._width)))
        self.TEMPLATE_SCORES.set(np.concatenate([t[2] for t in templates])
                                 if templates else np.zeros(0))

    def _learn(self):
        points = rows(self.KEYPOINTS, 2, "KEYPOINTS")
        descriptors = rows(self.DESCRIPTORS, self._width, "DESCRIPTORS")[:len(points)]
        scores = np.asarray(self.SCORES, np.float64).ravel()[:len(points)]
        scores = np.pad(scores, (0, len(points) - len(scores)))
        region = central_region(self.image_width, self.image_height, self.learning_region)
        keep = inside(points, region)[:len(descriptors)]
        if keep.sum() < self.min_features:
            self.warning(f"a template needs at least {self.min_features} points in the "
                         f"learning region, and there were {int(keep.sum())}: nothing was "
                         f"learned")
            return
        keep = np.flatnonzero(keep)[:int(self.max_stored_features)]
        new = (points[keep], descriptors[keep], scores[keep],
               rectangle_corners(region).ravel())
        templates = self._templates() + [new]
        while (len(templates) > self.max_templates
               or sum(len(t[0]) for t in templates) > self.max_stored_features):
            templates.pop(0)
        self._store(templates)

    def tick(self):
        if flag(self.CLEAR):
            self._store([])
        learn = flag(self.LEARN)
        if learn and not self.learning:
            self._learn()
        self.learning = learn
