"""Every test's files go to temporary folders: what would be written to the user's data
folder by default (the web UI's recordings, platformdirs) goes to one made for the run."""
import os
import tempfile

_DATA = tempfile.mkdtemp(prefix="ikaros-test-data-")
os.environ["XDG_DATA_HOME"] = _DATA     # read by platformdirs; inherited by subprocesses
