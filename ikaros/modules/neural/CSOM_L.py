"""CSOM_L: a convolutional self-organising map with a decaying neighbourhood and salience."""

from ikaros.module import Output, Parameter

from ._csom import SOMBase


class CSOM_L(SOMBase):
    """A convolutional self-organising map with a neighbourhood radius that shrinks as it
    learns: one map of som_size_y x som_size_x units, each with a weight vector the size of a
    receptive field, is applied to every rf_size_y x rf_size_x receptive field of INPUT
    (stepping ``rf_inc_x``, ``rf_inc_y``); with rf_size equal to the input size it is an
    ordinary SOM. At every field the best unit is the one whose weights are nearest (Euclidean
    distance, weighted by a quadratic arbor when ``use_arbor`` is set) and a unit's activity is
    1 / (1 + d), d its mean squared difference from the field. Every unit moves towards each
    field by alpha * exp(-g^2 / 2 s^2) / (number of fields), g its distance on the map
    (wrapping on a torus) to the field's best unit and s = sigma * hypot(som_size_x/2,
    som_size_y/2); after each tick alpha and sigma are multiplied by their decay and kept
    between their min and max, so the map first orders itself and then refines. SALIENCE is
    the summed activity of all units at each field. ``read_file`` names a text file of
    weights (one number per line, unit by unit, row by row) read at the start, ``write_file``
    one written at the end. The map size is (input - rf_size) / rf_inc + 1 fields across.
    ``assoc_radius_x`` and ``assoc_radius_y`` (lateral associations: no output in the
    catalogue's list shows them) have no effect; ``seed`` is an extension. The class is not
    in Ikaros 3, and the golden files have no case of it (its weights are random): these
    formulas are this project's reading of the catalogue's summary, and the random numbers
    come from NumPy's generator, not the original's."""

    assoc_radius_x = Parameter(1, "no effect here (Ikaros 2: range of lateral associations)")
    assoc_radius_y = Parameter(1, "no effect here (Ikaros 2: range of lateral associations)")
    use_arbor = Parameter(True, "weight the receptive field with a quadratic arbor function "
                          "that falls to 0 at its edge")
    read_file = Parameter("", "a file of weights to read at the start (empty: none)")
    write_file = Parameter("", "a file to write the weights to at the end (empty: none)")

    SALIENCE = Output("the summed activity of all units at each receptive field")

    salience = True

    def _load(self):
        if self.read_file:
            self._load_text(self.read_file, True)

    def stop(self):
        if self.write_file:
            self._save_text(self.write_file, True)
