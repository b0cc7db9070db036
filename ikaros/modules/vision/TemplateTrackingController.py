"""TemplateTrackingController: chooses between detecting a template and tracking it."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._template import MEAN_ERROR, RESULT_SIZE, TEMPLATE, found, identity

SEARCHING, DETECTED, TRACKING = 0, 1, 2


class TemplateTrackingController(Module):
    """Combines a detector (RobustTransformEstimator, slow, finds a template anywhere) and a
    tracker (PyramidalLucasKanadeTracker, fast, follows it once found). Each tick the
    tracking is trusted when TRACKING_RESULT says found and its mean forward-backward error
    (its fifth value) is at most ``tracking_fb_threshold`` pixels: TRANSFORM and RESULT are
    then the tracker's and STATUS is 2 (tracking). Otherwise a detection (DETECTION_RESULT
    found) gives the detector's, with STATUS 1 (detected); with neither, STATUS is 0
    (searching), TRANSFORM the identity and RESULT all 0 (template -1). MATCH_ENABLE, meant
    for the detector's ENABLE, is 1 while the target is not tracked and, while it is, once
    every ``detection_interval`` ticks (a check that the track has not drifted; 0 or less:
    never while tracking), else 0. This is this project's reading of the Ikaros 3
    interface, which only names the ports (docs/vision-tracking.md)."""

    detection_interval = Parameter(10, "while tracking, run the detector once every this "
                                   "many ticks (0: never)", type="int")
    tracking_fb_threshold = Parameter(1.5, "the largest mean forward-backward error in "
                                      "pixels of a trusted track", range=(0, None))

    DETECTION_TRANSFORM = Input("the detector's transform (HOMOGRAPHY)", size="3, 3")
    DETECTION_RESULT = Input("the detector's RESULT")
    TRACKING_TRANSFORM = Input("the tracker's TRANSFORM", size="3, 3")
    TRACKING_RESULT = Input("the tracker's RESULT")
    MATCH_ENABLE = Output("1 when the detector should run", shape="1")
    TRANSFORM = Output("the transform chosen", shape="3, 3")
    RESULT = Output("the RESULT chosen (8 values, as RobustTransformEstimator's)",
                    shape=str(RESULT_SIZE))
    STATUS = Output("0 searching, 1 detected, 2 tracking", shape="1")

    state = ("since_detection",)

    def init(self):
        self.since_detection = 0
        self.MATCH_ENABLE[0] = 1
        identity(self.TRANSFORM)
        self.RESULT[TEMPLATE] = -1

    def _take(self, transform, result, status):
        values = np.asarray(result).ravel()[:RESULT_SIZE]
        self.TRANSFORM[...] = np.asarray(transform).reshape(3, 3)
        self.RESULT[...] = 0
        self.RESULT[:len(values)] = values
        self.STATUS[0] = status

    def tick(self):
        tracked = np.asarray(self.TRACKING_RESULT).ravel()
        if found(tracked) and tracked.size > MEAN_ERROR and (
                tracked[MEAN_ERROR] <= self.tracking_fb_threshold):
            self._take(self.TRACKING_TRANSFORM, tracked, TRACKING)
        elif found(self.DETECTION_RESULT):
            self._take(self.DETECTION_TRANSFORM, self.DETECTION_RESULT, DETECTED)
        else:
            identity(self.TRANSFORM)
            self.RESULT[...] = 0
            self.RESULT[TEMPLATE] = -1
            self.STATUS[0] = SEARCHING
        self.since_detection += 1
        due = self.detection_interval > 0 and self.since_detection >= self.detection_interval
        enable = self.STATUS[0] != TRACKING or due
        if enable:
            self.since_detection = 0
        self.MATCH_ENABLE[0] = float(enable)
