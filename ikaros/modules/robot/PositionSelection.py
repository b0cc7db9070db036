"""PositionSelection: the best ranked of several position vectors (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output


class PositionSelection(Module):
    """Chooses, of several candidate goal-position vectors, the one ranked highest, as the
    compliant-robot models of Ikaros 3 use it to arbitrate between behaviours. PositionInput
    holds one candidate a row (a vector is one candidate); InputRanking has either one value a
    row (the row ranked highest is chosen whole) or one value per element of PositionInput
    (for each servo, the candidate ranked highest for it). A ranking of 0 or less, or NaN, never
    wins; where nothing wins, PositionOutput keeps its last value (0 at the start); ties go to
    the first row. PositionOutput has 19 elements, the Epi's servos: the first 19 of a row
    (missing ones 0). This project's reading: Ikaros 3 gives the interface only."""

    PositionInput = Input("candidate goal positions, one row each")
    InputRanking = Input("the ranking of each row, or of each element")

    PositionOutput = Output("the chosen positions (the Epi's 19 servos)", size="19")

    def _rows(self) -> np.ndarray:
        return self.PositionInput.reshape(-1, self.PositionInput.shape[-1])

    def init(self):
        rows = self._rows()
        if self.InputRanking.size not in (rows.shape[0], rows.size):
            raise ValueError(f"InputRanking has {self.InputRanking.size} values: give one per row of PositionInput "
                             f"({rows.shape[0]}) or one per element ({rows.size})")

    def tick(self):
        rows = self._rows()
        ranking = np.nan_to_num(self.InputRanking.reshape(-1), nan=0.0)
        n = min(19, rows.shape[1])
        out = self.PositionOutput
        if ranking.size == rows.shape[0]:
            best = int(np.argmax(ranking))
            if ranking[best] > 0:
                out[:n] = rows[best, :n]
                out[n:] = 0.0
            return
        per_element = ranking.reshape(rows.shape)
        best = np.argmax(per_element, axis=0)
        wins = per_element[best, np.arange(rows.shape[1])] > 0
        chosen = rows[best, np.arange(rows.shape[1])]
        out[:n] = np.where(wins[:n], chosen[:n], out[:n])
