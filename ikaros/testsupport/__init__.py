"""Test-only classes for the Ikaros 3 kernel test models (tests/kernel_v3).

They are not part of the standard library, but a model names them like any class: the class
registry looks here last (after the model's folders, plugins and the standard library).
Every class here is internal, so it is left out of class listings and of docs/modules.md.
"""
