"""CSOM: a convolutional self-organising map."""
from ikaros.module import Parameter

from ._csom import StreamSOM


class CSOM(StreamSOM):
    """A convolutional self-organising map: one map of som_size_y x som_size_x units, each
    with a weight vector the size of a receptive field, is applied to every rf_size_y x
    rf_size_x receptive field of INPUT (stepping ``rf_inc_x``, ``rf_inc_y``; a field may be
    split into blocks of ``block_size`` with ``span_size`` input elements between them); with
    rf_size equal to the input size it is an ordinary SOM. At every field the best unit is the
    one whose weights are nearest (Euclidean distance, weighted by a quadratic arbor that
    falls to 0 at the field's edge when ``use_arbor`` is set), and a unit's activity is
    1 / (1 + d), d its mean squared difference from the field. When ``update_weights`` is set,
    every unit moves towards each field by alpha * exp(-g^2 / 2 s^2) / (number of fields), g
    its distance on the map (wrapping around on a torus) to that field's best unit and s =
    sigma * hypot(som_size_x/2, som_size_y/2); after each tick alpha and sigma are multiplied
    by their decay and kept between their min and max. Nearby units so come to respond to
    similar fields: a topographic map. Several input streams (``upstreams``) share the
    weights. RECONSTRUCTION puts back at every field the weights of the unit with the largest
    TOP_DOWN activity. With ``load_state`` the weights (and, unless ``load_weights_only``, the
    learning rate, radius and statistics) are read at the start from ``filename``, a text file
    of one number per line; with ``save_state`` they are written there at the end. Extensions
    of Ikaros 2: the sigma parameters (the catalogue lists no neighbourhood parameters for
    Ikaros 2's CSOM) and ``seed``; ``border_multiplier`` and ``device_id`` (CUDA) have no
    effect here. The class is not in Ikaros 3, and the golden files have no case of it (its
    weights are random): these formulas are this project's reading of the catalogue's
    summary, and the random numbers come from NumPy's generator, not the original's."""

    border_multiplier = Parameter(2, "no effect here (Ikaros 2: a border for spans)")
    use_arbor = Parameter(True, "weight the receptive field with a quadratic arbor function "
                          "that falls to 0 at its edge")
    save_state = Parameter(False, "write the state to filename at the end")
    load_state = Parameter(False, "read the state from filename at the start")
    save_weights_only = Parameter(False, "save only the weights")
    load_weights_only = Parameter(False, "load only the weights")
    update_weights = Parameter(True, "learn (otherwise the weights stay fixed)")
    filename = Parameter("CSOM.dat", "the file the state is saved to and loaded from")
    device_id = Parameter(0, "no effect here (Ikaros 2: the CUDA device)")

    def learning(self):
        return self.update_weights

    def _load(self):
        if self.load_state:
            self._load_text(self.filename, self.load_weights_only)

    def stop(self):
        if self.save_state:
            self._save_text(self.filename, self.save_weights_only)
