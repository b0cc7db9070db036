"""The version of this package (what state files and recordings say wrote them)."""

__version__ = "0.1.0"
