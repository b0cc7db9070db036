"""A recording's chunks as HDF5's shuffle and deflate filters store them: h5py reads back
what was written, with numba's shuffle and with NumPy's."""
import numpy as np
import pytest

h5py = pytest.importorskip("h5py")

from ikaros.experiments import chunks  # noqa: E402


@pytest.mark.parametrize("shuffle", ["numba", "numpy"])
def test_chunks_written_as_they_stand_read_back(tmp_path, monkeypatch, shuffle):
    if shuffle == "numba":
        pytest.importorskip("numba")
    else:
        monkeypatch.setattr(chunks, "_shuffle", [None])
    rows = (np.arange(10 * 7, dtype=np.float32).reshape(10, 7) * 1.5 - 20) ** 3
    with h5py.File(tmp_path / "x.h5", "w") as f:
        data = f.create_dataset("data", (0, 7), maxshape=(None, 7), dtype="<f4",
                                chunks=(4, 7), compression="gzip", shuffle=True)
        data.resize(10, axis=0)
        whole = np.zeros((12, 7), np.float32)        # the last chunk is only half used
        whole[:10] = rows
        payloads = chunks.shuffled_deflate(whole, 4)
        assert len(payloads) == 3
        for k, payload in enumerate(payloads):
            data.id.write_direct_chunk((4 * k, 0), payload)
    with h5py.File(tmp_path / "x.h5", "r") as f:
        np.testing.assert_array_equal(f["data"][()], rows)
