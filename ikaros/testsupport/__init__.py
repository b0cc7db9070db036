"""Test-only classes for the Ikaros 3 kernel test models (tests/kernel_v3).

They are not part of the standard library: a model reaches them with a ``path`` attribute
that names this folder. Every class here is internal, so it is left out of class listings
and of docs/modules.md.
"""
