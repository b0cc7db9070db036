"""FaceClassifier on synthetic embeddings: three identities, 128 values each, whose
embeddings lie within 0.2 of the identity's centre and 1.4 or more from the others'."""
import numpy as np
import pytest

from ikaros.testing import load_body

SIZE = 128


def identities(count=3, seed=1):
    rng = np.random.default_rng(seed)
    centres = rng.normal(size=(count, SIZE))
    return centres / np.linalg.norm(centres, axis=1, keepdims=True)   # about 1.41 apart


def embedding(centre, rng, spread=0.1):
    noise = rng.normal(size=SIZE)
    return centre + spread * noise / np.linalg.norm(noise)


def rows_text(rows):
    return "; ".join(" ".join(repr(float(v)) for v in np.ravel(row)) for row in rows)


def classify(tmp_path, inputs, learn=None, **params):
    """Run the classifier on one embedding per tick; return the outputs of each tick."""
    learn = np.ones(len(inputs)) if learn is None else np.asarray(learn, float)
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = (f'<module class="ListIterator" name="In" listdata="{rows_text(inputs)}"/>'
            f'<module class="ListIterator" name="Learn" '
            f'listdata="{rows_text(learn.reshape(-1, 1))}"/>'
            f'<module class="FaceClassifier" name="M" {attrs}/>'
            '<connection source="In.OUTPUT" target="M.INPUT" delay="0"/>'
            '<connection source="Learn.OUTPUT" target="M.LEARN" delay="0"/>')
    names = ("OUTPUT", "NOVELTY", "DISTANCE", "CLASSES", "COUNT", "VECTORS")
    ticks = []
    with load_body(tmp_path, body) as net:
        for _ in range(len(inputs)):
            net.step()
            ticks.append({n: net.output(f"M.{n}").copy() for n in names})
        log = "\n".join(str(entry) for entry in net.log)
    return ticks, log


def recognised(tick):
    hits = np.flatnonzero(tick["OUTPUT"])
    return int(hits[0]) if len(hits) else None


def test_new_faces_become_classes_after_confirmation_and_are_recognised(tmp_path):
    rng = np.random.default_rng(2)
    a, b, c = identities()
    people = [a, a, a, b, b, b, a, b, a, c, b]
    inputs = [embedding(p, rng) for p in people]
    ticks, _ = classify(tmp_path, inputs)
    assert [recognised(t) for t in ticks] == [None, None, 0, None, None, 1, 0, 1, 0, None, 1]
    assert [int(t["NOVELTY"][0]) for t in ticks] == [1, 1, 1, 1, 1, 1, 0, 0, 0, 1, 0]
    assert [int(t["CLASSES"][0]) for t in ticks] == [0, 0, 1, 1, 1, 2, 2, 2, 2, 2, 2]
    assert ticks[-1]["COUNT"][:3].tolist() == [5, 5, 0]          # 3 + 2 and 3 + 2
    assert ticks[-1]["VECTORS"][:3].tolist() == [5, 5, 0]
    # DISTANCE: to the nearest embedding stored before the tick
    assert ticks[0]["DISTANCE"][0] == 0
    stored_a = np.array(inputs[:3])
    assert ticks[3]["DISTANCE"][0] == pytest.approx(
        np.linalg.norm(stored_a - inputs[3], axis=1).min(), rel=1e-5)
    assert ticks[6]["DISTANCE"][0] == pytest.approx(
        np.linalg.norm(stored_a - inputs[6], axis=1).min(), rel=1e-5)


def test_an_interrupted_candidate_starts_again(tmp_path):
    rng = np.random.default_rng(3)
    a, b, _ = identities()
    ticks, _ = classify(tmp_path, [embedding(p, rng) for p in [a, a, b, a, a, a]])
    assert [int(t["CLASSES"][0]) for t in ticks] == [0, 0, 0, 0, 0, 1]
    ticks, _ = classify(tmp_path, [embedding(p, rng) for p in [a, a, 0 * a, a, a]])
    assert int(ticks[-1]["CLASSES"][0]) == 0                     # no face in between


def test_the_k_nearest_vote_decides(tmp_path):
    # class 0 holds three embeddings near x = 1 (made by the first, joined by the next
    # two), class 1 one embedding nearer still to the probe; with k = 3 the three of class
    # 0 outvote it, with k = 1 the nearest wins
    e = np.eye(SIZE)
    zero = [e[0] + 0.05 * e[i] for i in (1, 2, 3)]
    one = [e[0] + 0.5 * e[4]]                      # 0.5025 from class 0: a new class
    probe = e[0] + 0.4 * e[4]                       # 0.1 from class 1, 0.403 from class 0
    for k, expected in (("3", 0), ("1", 1)):
        ticks, _ = classify(tmp_path, zero + one + [probe], k=k, threshold="0.45",
                            confirmation_count="1")
        assert ticks[-2]["VECTORS"][:2].tolist() == [3, 1]
        assert recognised(ticks[-1]) == expected


def test_nothing_is_learned_while_learn_is_off_and_capacity_is_kept(tmp_path):
    rng = np.random.default_rng(4)
    a, b, c = identities()
    ticks, _ = classify(tmp_path, [embedding(a, rng) for _ in range(4)], learn=[0] * 4)
    assert int(ticks[-1]["CLASSES"][0]) == 0 and ticks[-1]["NOVELTY"][0] == 1
    people = [a] * 3 + [b] * 3 + [c] * 3
    ticks, log = classify(tmp_path, [embedding(p, rng) for p in people], capacity="2")
    assert int(ticks[-1]["CLASSES"][0]) == 2 and ticks[-1]["OUTPUT"].shape == (2,)
    assert "all 2 classes are taken" in log
