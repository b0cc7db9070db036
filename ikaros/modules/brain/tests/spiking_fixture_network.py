"""The seeded spiking network whose raster, recorded with the code before issue 30 (dense
float64 weights, 1 ms ticks, the input value times the weight), is kept in
data/spiking_raster_before_issue30.json. Run this file to print the raster as JSON."""
import json
import sys

import numpy as np

from ikaros.testing import load_body

TICKS = 400
POPULATIONS = ("Src", "Exc", "Rec", "Fs")
BODY = (
    '<module class="Constant" name="C" data="0 3 4.5 5 6 8 10 13 17 25"/>'
    '<module class="Constant" name="D" data="2 4 6 8 2 4 6 8 2 4 6 8"/>'
    '<module class="SpikingPopulation" name="Src" population_size="10"/>'
    '<module class="SpikingPopulation" name="Exc" population_size="8" seed="3" '
    'synapse_min="0.1" synapse_max="0.4"/>'
    '<module class="SpikingPopulation" name="Rec" population_size="12" seed="7" '
    'neuron_type="chattering" substeps="4" synapse_min="0.02" synapse_max="0.3"/>'
    '<module class="SpikingPopulation" name="Fs" population_size="6" seed="11" '
    'neuron_type="fast_spiking" threshold="25" synapse_min="0.05" synapse_max="0.2"/>'
    '<connection source="C.OUTPUT" target="Src.DIRECT_IN" delay="0"/>'
    '<connection source="Src.OUTPUT" target="Exc.EXCITATION_IN" delay="0"/>'
    '<connection source="D.OUTPUT" target="Rec.DIRECT_IN" delay="0"/>'
    '<connection source="Src.OUTPUT" target="Rec.EXCITATION_IN" delay="1"/>'
    '<connection source="Rec.OUTPUT" target="Rec.EXCITATION_IN" delay="1"/>'
    '<connection source="Exc.OUTPUT" target="Rec.INHIBITION_IN" delay="1"/>'
    '<connection source="C.OUTPUT" target="Fs.DIRECT_IN" delay="0" size="6"/>'
    '<connection source="Rec.OUTPUT" target="Fs.EXCITATION_IN" delay="2"/>'
    '<connection source="Src.OUTPUT" target="Fs.INHIBITION_IN" delay="1"/>'
)


def raster(folder, **overrides) -> dict:
    """{population: [[tick, neuron], ...]} of every spike in TICKS ticks (keyword arguments
    set attributes of the top group, which its modules inherit)."""
    net = load_body(folder, BODY, **overrides)
    thresholds = {"Fs": 25.0}
    try:
        spikes = {p: [] for p in POPULATIONS}
        for t in range(TICKS):
            net.step()
            for p in POPULATIONS:
                v = net.output(f"{p}.OUTPUT")
                spikes[p] += [[t, int(i)] for i in np.flatnonzero(v >= thresholds.get(p, 30.0))]
        return spikes
    finally:
        net.close()


if __name__ == "__main__":
    import tempfile
    with tempfile.TemporaryDirectory() as folder:
        json.dump(raster(folder), sys.stdout, separators=(",", ":"))
