"""The example model examples/conditioning.ikg reproduces acquisition and extinction."""
import os

import numpy as np

import ikaros

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))))
MODEL = os.path.join(ROOT, "examples", "conditioning.ikg")


def conditioned_responses(trials):
    """The amygdala's response to the first CS tick of every 10-tick trial, run headless: E
    two ticks later (E(t) is computed from the nodes of tick t-2, as in Ikaros 2)."""
    net = ikaros.load(MODEL)
    try:
        cr = []
        for t in range(10 * trials):
            net.step()
            if t % 10 == 0:
                assert net.output("CS.OUTPUT")[0] == 1
            if t % 10 == 2:
                cr.append(float(net.output("Amygdala.E")[0]))
        return np.array(cr)
    finally:
        net.close()


def test_acquisition_then_extinction():
    cr = conditioned_responses(120)        # 30 acquisition, 30 extinction, then again
    acq, ext = cr[:30], cr[30:60]
    # acquisition: no response to the novel CS, then a rise of at least 0.99 within 10 trials
    assert acq[0] == 0
    assert np.all(np.diff(acq[:10]) > 0)
    assert acq[10] - acq[0] > 0.99 and acq[29] > 0.999
    # extinction: the response falls by at least 0.99 within 15 trials, and keeps falling
    assert ext[0] - ext[15] > 0.99
    assert np.all(np.diff(ext[:15]) < 0)
    assert ext[29] < 1e-3
    # By hand: the amygdala sees the CS twice (sensory cortex and thalamus), so sum A = 2v,
    # and each of the 2 CS ticks of a trial is followed by a reward of 1: the gap 1 - 2v
    # shrinks by (1 - 2 * 0.2) = 0.6 per tick, 0.36 per trial, so the response on trial k is
    # 1 - 0.36^k. In extinction the OFC weight w (EO = w) grows by 0.2 * (1 - w) after each
    # unrewarded CS tick, so the response 1 - w is 0.8^2 = 0.64 times smaller each trial.
    k = np.arange(10)
    assert np.allclose(acq[:10], 1 - 0.36 ** k, atol=1e-4)
    assert np.allclose(ext[:10], 0.64 ** k, atol=1e-4)
    # reacquisition after extinction: the response rises again, and extinguishes again
    assert cr[60] < 1e-3 and cr[89] > 0.999
    assert cr[90] > 0.999 and cr[119] < 1e-3
