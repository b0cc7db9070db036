"""The Python API page: the public names of ``ikaros`` from their docstrings
(mkdocstrings)."""

# objects whose inherited members are theirs to the user (the public Network adds to the
# kernel's)
INHERITED = {"ikaros.Network"}
# (heading, the objects documented under it)
SECTIONS = (
    ("Loading and running models", ["ikaros.load", "ikaros.Network", "ikaros.classes"]),
    ("Models built in code", ["ikaros.Group"]),
    ("Writing modules", ["ikaros.Module", "ikaros.Parameter", "ikaros.Input", "ikaros.Output",
                         "ikaros.State"]),
    ("Recordings and sweeps", ["ikaros.experiments.reading.open_recording",
                               "ikaros.experiments.sweeps.sweep"]),
    ("Errors and warnings", ["ikaros.ModelError", "ikaros.RunError", "ikaros.ModelWarning",
                             "ikaros.StateError"]),
)


def api_page() -> str:
    lines = ["# Python API", "",
             "The public names of the `ikaros` package, from their docstrings. "
             "[Python and notebooks](python-api.md) shows them at work; "
             "[writing modules](writing-modules.md) explains the module API.", ""]
    for title, names in SECTIONS:
        lines += [f"## {title}", ""]
        for name in names:
            lines += [f"::: {name}", "    options:", "      heading_level: 3"]
            if name in INHERITED:
                lines.append("      inherited_members: true")
            lines.append("")
    return "\n".join(lines)
