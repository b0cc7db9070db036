"""ConvolutionalVariationalAutoEncoder (PyTorch): its latent has the shape the Ikaros 3
interface gives, its losses are the formulas written out in NumPy on its own outputs, and
its reconstruction loss falls as it learns a small set of synthetic images."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body

pytest.importorskip("torch")

CLASS = "ConvolutionalVariationalAutoEncoder"


def bars(size=8):
    """Six images: three horizontal and three vertical bars, two pixels wide."""
    images = []
    for k in (1, 3, 5):
        h = np.zeros((size, size), np.float32)
        h[k:k + 2] = 1
        images += [h, h.T.copy()]
    return images


def network(tmp_path, images, cls=CLASS, extra="", **params):
    """A model that shows the images one a tick, round and round, to the module M."""
    images = np.asarray(images, np.float32)
    rows = "; ".join(" ".join(str(float(v)) for v in image.ravel()) for image in images)
    if len(images) == 1:                   # a list of one row would be stepped by element
        rows += "; " + rows
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = (f'<module class="ListIterator" name="List" listdata="{rows}" repeat="yes"/>'
            f'<module class="ArrayToMatrix" name="In" array_length="{images.shape[-1]}"/>'
            '<connection source="List.OUTPUT" target="In.INPUT" delay="0"/>'
            f'<module class="{cls}" name="M" seed="3" {attrs}/>'
            '<connection source="In.OUTPUT" target="M.INPUT" delay="0"/>' + extra)
    return load_body(tmp_path, body)


@pytest.mark.parametrize("params, shape", [
    ({}, (8,)),
    ({"latent_size": "5"}, (5,)),
    ({"latent_mode": "spatial"}, (4, 8 - 2, 10 - 2)),
    ({"latent_mode": "spatial", "latent_kernel_size": "3", "kernel_size": "5",
      "latent_maps": "2"}, (2, 8 - 6, 10 - 6)),
    ({"latent_mode": "spatial", "padding": "same", "latent_kernel_size": "3"}, (4, 8, 10)),
])
def test_the_latent_has_the_shape_of_the_interface(tmp_path, params, shape):
    with network(tmp_path, [np.zeros((8, 10))], **params) as net:
        net.step()
        for name in ("LATENT_MEAN", "LATENT_LOG_VARIANCE", "LATENT_SAMPLE"):
            assert net.output(f"M.{name}").shape == shape
        assert net.output("M.OUTPUT").shape == (8, 10)


@pytest.mark.parametrize("params", [{}, {"latent_mode": "spatial", "beta": "0.5"}])
def test_the_losses_are_the_formulas_of_the_outputs(tmp_path, params):
    image = bars()[0]
    with network(tmp_path, [image], **params) as net:
        for _ in range(3):
            net.step()
            out = {n: net.output(f"M.{n}").astype(np.float64) for n in
                   ("OUTPUT", "LATENT_MEAN", "LATENT_LOG_VARIANCE", "LATENT_SAMPLE", "LOSS",
                    "RECONSTRUCTION_LOSS", "KL_LOSS")}
            mean, log_var = out["LATENT_MEAN"], out["LATENT_LOG_VARIANCE"]
            kl = -0.5 * np.sum(1 + log_var - mean ** 2 - np.exp(log_var)) / image.size
            reconstruction = np.mean((out["OUTPUT"] - image) ** 2)
            beta = float(params.get("beta", 1))
            assert out["KL_LOSS"][0] == pytest.approx(kl, rel=1e-4, abs=1e-7)
            assert out["RECONSTRUCTION_LOSS"][0] == pytest.approx(reconstruction, rel=1e-4)
            assert out["LOSS"][0] == pytest.approx(reconstruction + beta * kl, rel=1e-4)
            assert not np.allclose(out["LATENT_SAMPLE"], mean)      # a sample, not the mean


def test_the_reconstruction_loss_falls_as_it_learns(tmp_path):
    with network(tmp_path, bars(), learning_rate="0.01", output_activation="sigmoid",
                 latent_size="4", beta="0.1") as net:
        losses = []
        for _ in range(600):
            net.step()
            losses.append(float(net.output("M.RECONSTRUCTION_LOSS")[0]))
    first, last = np.mean(losses[:30]), np.mean(losses[-30:])
    assert first > 0.2 and last < 0.1 * first, (first, last)


def test_without_sample_or_training_it_is_the_same_function_every_tick(tmp_path):
    with network(tmp_path, [bars()[0]], sample="no", train="no") as net:
        net.step()
        first = {n: net.output(f"M.{n}").copy() for n in ("OUTPUT", "LATENT_MEAN", "LOSS")}
        assert np.array_equal(net.output("M.LATENT_SAMPLE"), first["LATENT_MEAN"])
        net.run(ticks=5)
        for name, value in first.items():
            assert np.array_equal(net.output(f"M.{name}"), value)


def test_effort_zero_learns_nothing(tmp_path):
    extra = ('<module class="Constant" name="E" data="0"/>'
             '<connection source="E.OUTPUT" target="M.EFFORT" delay="0"/>')
    with network(tmp_path, [bars()[0]], extra=extra, sample="no") as net:
        net.step()
        first = net.output("M.LOSS").copy()
        net.run(ticks=5)
        assert np.array_equal(net.output("M.LOSS"), first)


def test_top_down_decodes_the_latent_it_is_given(tmp_path):
    # B decodes A's mean given from outside; A decodes its own mean: the same weights (the
    # same seed, no training) give the same image
    extra = (f'<module class="{CLASS}" name="B" seed="3" train="no" '
             'reconstruction_source="top_down"/>'
             '<connection source="In.OUTPUT" target="B.INPUT" delay="0"/>'
             '<connection source="M.LATENT_MEAN" target="B.TOP_DOWN" delay="0"/>')
    with network(tmp_path, bars(), extra=extra, train="no",
                 reconstruction_source="mean") as net:
        for _ in range(3):
            net.step()
            assert np.allclose(net.output("B.OUTPUT"), net.output("M.OUTPUT"), atol=1e-6)


def test_top_down_without_the_input_is_refused(tmp_path):
    with pytest.raises(ModelError, match="top_down needs TOP_DOWN connected"):
        network(tmp_path, [bars()[0]], reconstruction_source="top_down")


def test_kernels_that_do_not_fit_are_refused(tmp_path):
    with pytest.raises(ModelError):
        network(tmp_path, [np.zeros((4, 4))], kernel_size="7")


def test_it_steps_every_train_interval_ticks(tmp_path):
    with network(tmp_path, [bars()[0]], sample="no", train_interval="3") as net:
        losses = []
        for _ in range(7):
            net.step()
            losses.append(float(net.output("M.LOSS")[0]))
    # steps after ticks 0, 3 and 6: the loss (before each tick's step) changes on 1 and 4
    changed = [a != b for a, b in zip(losses, losses[1:])]
    assert changed == [True, False, False, True, False, False]
