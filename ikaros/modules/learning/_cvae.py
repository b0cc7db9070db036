"""The network of ConvolutionalVariationalAutoEncoder: a convolutional encoder to a dense
or spatial Gaussian latent, and the mirrored decoder."""
from __future__ import annotations

from ._torch import activation


def build(torch, channels: int, rows: int, cols: int, spatial: bool, latent_size: int,
          latent_maps: int, latent_kernel: int, feature_maps: int, kernel: int,
          same: bool, output_activation: str):
    """The encoder and decoder layers as a ModuleDict, with the shapes of the feature maps
    and of the latent. ``ValueError`` when a kernel does not fit the image."""
    nn = torch.nn
    pad, latent_pad = (kernel // 2, latent_kernel // 2) if same else (0, 0)
    if same and (kernel % 2 == 0 or latent_kernel % 2 == 0):
        raise ValueError("padding \"same\" needs odd kernel_size and latent_kernel_size")
    feature = (rows + 2 * pad - kernel + 1, cols + 2 * pad - kernel + 1)
    latent_rows = feature[0] + 2 * latent_pad - latent_kernel + 1
    latent_cols = feature[1] + 2 * latent_pad - latent_kernel + 1
    if min(feature) < 1 or (spatial and min(latent_rows, latent_cols) < 1):
        raise ValueError(f"the kernels ({kernel} and {latent_kernel}) do not fit the "
                         f"{rows} x {cols} image with padding \"valid\"")
    flat = feature_maps * feature[0] * feature[1]
    layers = {"encode": nn.Sequential(nn.Conv2d(channels, feature_maps, kernel, padding=pad),
                                      nn.ReLU()),
              "decode_out": nn.Sequential(nn.ConvTranspose2d(feature_maps, channels, kernel,
                                                             padding=pad),
                                          activation(torch, output_activation))}
    if spatial:
        layers["latent"] = nn.Conv2d(feature_maps, 2 * latent_maps, latent_kernel,
                                     padding=latent_pad)
        layers["decode_in"] = nn.Sequential(
            nn.ConvTranspose2d(latent_maps, feature_maps, latent_kernel, padding=latent_pad),
            nn.ReLU())
        latent_shape = (latent_maps, latent_rows, latent_cols)
    else:
        layers["latent"] = nn.Sequential(nn.Flatten(), nn.Linear(flat, 2 * latent_size))
        layers["decode_in"] = nn.Sequential(nn.Linear(latent_size, flat), nn.ReLU(),
                                            nn.Unflatten(1, (feature_maps, *feature)))
        latent_shape = (latent_size,)
    return nn.ModuleDict(layers), latent_shape


def dense_names(spatial: bool) -> tuple[str, ...]:
    """The parts whose parameters are the dense layers (trained every dense_train_interval
    steps): the latent layer and the first decoder layer in the dense mode, none in the
    spatial one."""
    return () if spatial else ("latent", "decode_in")
