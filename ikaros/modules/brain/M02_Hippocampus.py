"""M02_Hippocampus: the context-processing hippocampus of Morén's (2002) model."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

MATCH_DISTANCE = 0.5        # a pattern farther than this from every binding is new


class M02_Hippocampus(Module):
    """The context-processing hippocampus of Morén's (2002) model of emotional learning
    (Balkenius & Morén 2000), as Ikaros 2 computes it (Ikaros 3 has no such class). Each
    tick the STIMULUS and LOCATION vectors together form a pattern, matched to the stored
    bindings (Euclidean distance); if none is within 0.5 and there is room (``bindsize``),
    it is stored as a new binding. Novelty: each context remembers the stimulus last seen at
    each location (the largest element of LOCATION); if an element remembered for the
    current context and location is larger than the present stimulus, something expected
    is missing: RESET is 1 for this tick and, if the binding is new, a new context is
    created for it (a fatal error when all ``contextsize`` contexts are used). Otherwise the
    current context adds the binding to its set. CONTEXT is one-hot for the context: it
    stays while its set holds the binding, else it becomes the first context whose set
    does; the stimulus is remembered there. BIND, with ``bind`` = ``context`` (Ikaros 2),
    holds every binding of that context (1 for each); with ``current`` it is one-hot for the
    binding of this tick. BIND_DELTA is 1 for a binding of BIND that was not in BIND on the
    previous tick. When both inputs are all 0, BIND, BIND_DELTA and RESET are 0 and nothing
    else changes. The golden files of Ikaros 2 show the bindings, BIND, BIND_DELTA, the
    novelty resets, the new contexts and a context that keeps a binding it takes; the
    distance 0.5, the memory per location and the fatal error when the contexts run out
    are this project's reading of the model (no reference gives them)."""

    bindsize = Parameter(4, "number of binding nodes (distinct stimulus-location patterns)",
                         type="int", range=(1, None))
    contextsize = Parameter(4, "number of context nodes", type="int", range=(1, None))
    bind = Parameter("context", "what BIND shows: context, every binding of the current "
                     "context (Ikaros 2); current, the binding of this tick",
                     options="context/current")
    STIMULUS = Input("the observed stimuli", flatten=True)
    LOCATION = Input("the observed location (its largest element is the place)", flatten=True)
    BIND = Output("the bindings of the current context, or the current binding (see bind)",
                  size_param="bindsize")
    BIND_DELTA = Output("bindings that became active on this tick", size_param="bindsize")
    CONTEXT = Output("the current context, one-hot", size_param="contextsize")
    RESET = Output("1 on a tick where an expected stimulus was missing", size="1")

    def init(self):
        n_s, n_l = self.STIMULUS.size, self.LOCATION.size
        self._protos = np.zeros((self.bindsize, n_s + n_l))
        self._used_binds = 0
        self._cx_binds = np.zeros((self.contextsize, self.bindsize))
        self._cx_memory = np.zeros((self.contextsize, max(n_l, 1), n_s))
        self._used_contexts = 1
        self._context = 0
        self._bind_last = np.zeros(self.bindsize)
        for out in (self.BIND, self.BIND_DELTA, self.CONTEXT, self.RESET):
            out[...] = 0

    def _categorize(self, pattern):
        """Index of the matching binding (storing a new one if needed) and whether it is new."""
        used = self._used_binds
        if used:
            d = np.linalg.norm(self._protos[:used] - pattern, axis=1)
            best = int(np.argmin(d))
            if d[best] <= MATCH_DISTANCE or used == self.bindsize:
                return best, False
        if self.bindsize == 0:
            return None, False
        self._protos[used] = pattern
        self._used_binds += 1
        return used, True

    def tick(self):
        stim = self.STIMULUS.astype(np.float64)
        loc = self.LOCATION.astype(np.float64)
        pattern = np.concatenate([stim, loc])
        self.RESET[0] = 0
        if not np.any(pattern):
            self.BIND[...] = 0
            self.BIND_DELTA[...] = 0
            self._bind_last[...] = 0
            return
        place = int(np.argmax(loc)) if loc.size else 0
        best, new = self._categorize(pattern)
        bind = np.zeros(self.bindsize)
        if best is not None:
            bind[best] = 1
        novelty = bool(np.any(self._cx_memory[self._context, place] > stim))
        if novelty:
            self.RESET[0] = 1
            if new:
                if self._used_contexts >= self.contextsize:
                    self.fatal_error("not enough context nodes: increase contextsize")
                else:
                    self._cx_binds[self._used_contexts] = bind
                    self._used_contexts += 1
        else:
            np.maximum(self._cx_binds[self._context], bind, out=self._cx_binds[self._context])
        activity = self._cx_binds[:self._used_contexts] @ bind
        if not activity[self._context] > 0:
            self._context = int(np.argmax(activity))
        self.CONTEXT[...] = 0
        self.CONTEXT[self._context] = 1
        self._cx_memory[self._context, place] = stim
        shown = self._cx_binds[self._context].copy() if self.bind == "context" else bind
        self.BIND[...] = shown
        self.BIND_DELTA[...] = np.clip(shown - self._bind_last, 0, 1)
        self._bind_last = shown
