"""A module file that imports a package that is not installed."""
import ikaros_no_such_package  # noqa: F401

from ikaros.module import Module


class NeedsPackage(Module):
    """Never imported."""
