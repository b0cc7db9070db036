"""ConvolutionalVariationalAutoEncoder: learns to encode images as a small Gaussian latent."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cvae import build, dense_names
from ._torch import generator, optimizer, pytorch, set_rate

LATENT = ("optional((1-@latent_mode)*@latent_size),optional(@latent_mode*@latent_maps),"
          "optional(@latent_mode*(INPUT.rows-(1-@padding)*(@kernel_size+@latent_kernel_size-2))),"
          "optional(@latent_mode*(INPUT.cols-(1-@padding)*(@kernel_size+@latent_kernel_size-2)))")


class ConvolutionalVariationalAutoEncoder(Module):
    """A variational autoencoder (Kingma & Welling 2014) with convolutional layers, trained
    on line with PyTorch (the ``deep`` extra, ``pip install 'ikaros[deep]'``; CPU). INPUT is
    a gray image (rows, cols) or one of several planes (planes, rows, cols). The encoder is a
    convolution of ``feature_maps`` maps with ``kernel_size`` kernels and ReLU; with
    ``latent_mode`` dense a fully connected layer gives the mean and log variance of
    ``latent_size`` latent values, with spatial a convolution of ``latent_kernel_size``
    gives ``latent_maps`` latent maps of each. ``padding`` valid lets each convolution
    shrink the image by its kernel size less one; same keeps the size (odd kernels). The
    decoder mirrors the encoder with transposed convolutions, its last activation
    ``output_activation``.

    Each tick the latent's mean and log variance for INPUT are LATENT_MEAN and
    LATENT_LOG_VARIANCE; LATENT_SAMPLE is a sample, mean + exp(log variance / 2) times
    standard normal noise (with ``sample``; otherwise the mean). OUTPUT decodes the sample,
    the mean or TOP_DOWN (a latent given from outside, shaped like LATENT_MEAN) as
    ``reconstruction_source`` says. RECONSTRUCTION_LOSS is the mean squared error of the
    sample's reconstruction, KL_LOSS the Kullback-Leibler divergence of the latent from a
    standard normal, summed over the latent and divided by the number of input elements,
    and LOSS their sum with KL_LOSS weighted by ``beta`` (a beta-VAE for beta other than 1).
    With ``train`` the network then takes a step on LOSS every ``train_interval`` ticks
    (Adam with ``adam_beta1``, ``adam_beta2`` and ``adam_epsilon``, or SGD), of step size
    ``learning_rate`` times EFFORT when EFFORT is connected (no step at 0 or less); in the
    dense mode the dense layers step only on every ``dense_train_interval``-th of those
    steps. The losses and outputs are those before the step. ``seed`` makes a run
    repeatable. The original's class is known only by its interface: the layers and the
    losses are this project's reading of it."""

    latent_mode = Parameter("dense", "a latent vector (dense) or latent maps (spatial)",
                            options="dense,spatial", fixed=True)
    latent_size = Parameter(8, "the latent values (dense)", type="int", range=(1, None),
                            fixed=True)
    latent_maps = Parameter(4, "the latent maps (spatial)", type="int", range=(1, None),
                            fixed=True)
    latent_kernel_size = Parameter(1, "the kernel of the latent convolution (spatial)",
                                   type="int", range=(1, None), fixed=True)
    feature_maps = Parameter(4, "the encoder's feature maps", type="int", range=(1, None),
                             fixed=True)
    kernel_size = Parameter(3, "the encoder's kernel", type="int", range=(1, None),
                            fixed=True)
    padding = Parameter("valid", "valid: convolutions shrink the image; same: they keep it",
                        options="valid,same", fixed=True)
    learning_rate = Parameter(0.001, "the step size", range=(0, None))
    optimizer = Parameter("adam", "the optimizer", options="adam,sgd", fixed=True)
    adam_beta1 = Parameter(0.9, "Adam's decay of the mean gradient", range=(0, 1),
                           fixed=True)
    adam_beta2 = Parameter(0.999, "Adam's decay of the squared gradient", range=(0, 1),
                           fixed=True)
    adam_epsilon = Parameter(0.00000001, "Adam's epsilon", range=(0, None), fixed=True)
    beta = Parameter(1.0, "the weight of KL_LOSS in LOSS", range=(0, None))
    train = Parameter(True, "learn from each INPUT")
    train_interval = Parameter(1, "take a step every this many ticks", type="int",
                               range=(1, None))
    dense_train_interval = Parameter(1, "step the dense layers on every this many steps",
                                     type="int", range=(1, None))
    sample = Parameter(True, "draw LATENT_SAMPLE (otherwise it is the mean)")
    reconstruction_source = Parameter("sample", "what OUTPUT decodes",
                                      options="sample,mean,top_down")
    output_activation = Parameter("linear", "the decoder's last activation",
                                  options="linear,sigmoid", fixed=True)
    seed = Parameter(None, "seed of the initial weights and the noise; unset (or 0): a "
                     "different run every time", type="int", fixed=True)

    INPUT = Input("the image: (rows, cols) or (planes, rows, cols)")
    TOP_DOWN = Input("a latent to decode (reconstruction_source top_down)", optional=True)
    EFFORT = Input("the step size is learning_rate times this", optional=True)
    OUTPUT = Output("the reconstruction", shape="INPUT.shape")
    LATENT_MEAN = Output("the latent's mean", shape=LATENT)
    LATENT_LOG_VARIANCE = Output("the latent's log variance", shape=LATENT)
    LATENT_SAMPLE = Output("a sample of the latent (the mean without sample)", shape=LATENT)
    LOSS = Output("RECONSTRUCTION_LOSS + beta KL_LOSS", shape="1")
    RECONSTRUCTION_LOSS = Output("the mean squared error of the reconstruction", shape="1")
    KL_LOSS = Output("the KL divergence per input element", shape="1")

    def configure(self):
        self.torch = pytorch()

    def init(self):
        torch = self.torch
        shape = self.INPUT.shape
        if len(shape) not in (2, 3):
            raise ValueError(f"INPUT must be an image (rows, cols) or (planes, rows, cols), "
                             f"not shape {shape}")
        self._image_shape = (1,) * (3 - len(shape)) + tuple(shape)
        spatial = self.latent_mode == "spatial"
        self._generator = generator(torch, self.seed)
        with torch.random.fork_rng(devices=[]):
            torch.manual_seed(int(self._generator.initial_seed()))
            self.network, latent_shape = build(
                torch, *self._image_shape, spatial, self.latent_size, self.latent_maps,
                self.latent_kernel_size, self.feature_maps, self.kernel_size,
                self.padding == "same", self.output_activation)
        assert latent_shape == self.LATENT_MEAN.shape, (latent_shape, self.LATENT_MEAN.shape)
        if self.reconstruction_source == "top_down" and (
                self.TOP_DOWN is None or self.TOP_DOWN.size != self.LATENT_MEAN.size):
            raise ValueError(f"reconstruction_source top_down needs TOP_DOWN connected with "
                             f"{self.LATENT_MEAN.size} values, the latent's")
        dense = set(dense_names(spatial))
        parts = {"dense": [], "other": []}
        for name, part in self.network.items():
            parts["dense" if name in dense else "other"] += list(part.parameters())
        betas = (self.adam_beta1, self.adam_beta2)
        self._optimizers = {key: optimizer(torch, self.optimizer, params, self.learning_rate,
                                           betas, self.adam_epsilon)
                            for key, params in parts.items() if params}
        self._ticks = 0
        self._steps = 0

    def _decode(self, z):
        return self.network["decode_out"](self.network["decode_in"](z))

    def tick(self):
        torch = self.torch
        x = torch.from_numpy(np.asarray(self.INPUT, np.float32).reshape(1, *self._image_shape))
        statistics = self.network["latent"](self.network["encode"](x))
        mean, log_variance = statistics.chunk(2, dim=1)
        if self.sample:
            noise = torch.randn(mean.shape, generator=self._generator)
            z = mean + torch.exp(0.5 * log_variance) * noise
        else:
            z = mean
        reconstruction = self._decode(z)
        recon_loss = torch.mean((reconstruction - x) ** 2)
        kl = -0.5 * torch.sum(1 + log_variance - mean ** 2 - torch.exp(log_variance)) / x.numel()
        loss = recon_loss + self.beta * kl
        with torch.no_grad():
            if self.reconstruction_source == "mean":
                reconstruction = self._decode(mean)
            elif self.reconstruction_source == "top_down":
                reconstruction = self._decode(torch.from_numpy(np.asarray(
                    self.TOP_DOWN, np.float32).reshape(mean.shape)))
            for out, value in ((self.OUTPUT, reconstruction), (self.LATENT_MEAN, mean),
                               (self.LATENT_LOG_VARIANCE, log_variance),
                               (self.LATENT_SAMPLE, z)):
                out[...] = value.numpy().reshape(out.shape)
        self.RECONSTRUCTION_LOSS[0] = float(recon_loss.detach())
        self.KL_LOSS[0] = float(kl.detach())
        self.LOSS[0] = float(loss.detach())
        self._train(loss)

    def _train(self, loss):
        effort = 1.0 if self.EFFORT is None else float(np.asarray(self.EFFORT).ravel()[0])
        self._ticks += 1
        if not self.train or effort <= 0 or (self._ticks - 1) % self.train_interval:
            return
        for opt in self._optimizers.values():
            set_rate(opt, self.learning_rate * effort)
            opt.zero_grad()
        loss.backward()
        self._optimizers["other"].step()
        if "dense" in self._optimizers and self._steps % self.dense_train_interval == 0:
            self._optimizers["dense"].step()
        self._steps += 1
