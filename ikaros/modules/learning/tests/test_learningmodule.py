"""Tests of LearningModule: the interface and a subclass that learns."""
import numpy as np

from ikaros.testing import load_body as load


def test_the_template_passes_its_inputs_through_and_sizes_its_weights(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="I" data="1 2 3"/>'
                         '<module class="Constant" name="T" data="4 5"/>'
                         '<module class="Constant" name="A" data="7 8 9 10"/>'
                         '<module class="LearningModule" name="L"/>'
                         '<connection source="I.OUTPUT" target="L.INPUT"/>'
                         '<connection source="T.OUTPUT" target="L.T-INPUT"/>'
                         '<connection source="A.OUTPUT" target="L.AUX-T-INPUT"/>')
    try:
        net.step()
        assert net.output("L.OUTPUT").tolist() == [1, 2, 3]
        assert net.output("L.T-OUTPUT").tolist() == [4, 5]
        assert net.output("L.W").shape == (3, 3) and not net.output("L.W").any()
        assert net.output("L.U").shape == (3, 4)
        assert net.output("L.AUX-OUTPUT").tolist() == [0, 0, 0]
        assert net.parameter("L.learning_rate") == 0.1
    finally:
        net.close()


def test_a_subclass_inherits_the_interface(tmp_path):
    (tmp_path / "Hebb.py").write_text(
        "import numpy as np\n"
        "from ikaros.modules.learning.LearningModule import LearningModule\n\n\n"
        "class Hebb(LearningModule):\n"
        "    \"\"\"W += learning_rate * outer(INPUT, INPUT).\"\"\"\n\n"
        "    def tick(self):\n"
        "        self.W += self.learning_rate * np.outer(self.INPUT, self.INPUT)\n"
        "        np.dot(self.W, self.INPUT, out=self.OUTPUT)\n")
    net = load(tmp_path, '<module class="Constant" name="I" data="1 0 2"/>'
                         '<module class="Hebb" name="H" learning_rate="0.5"/>'
                         '<connection source="I.OUTPUT" target="H.INPUT"/>')
    try:
        net.run(ticks=2)
        x = np.float32([1, 0, 2])
        w = 2 * 0.5 * np.outer(x, x)
        assert net.output("H.W").tolist() == w.tolist()
        assert net.output("H.OUTPUT").tolist() == (w @ x).tolist()
    finally:
        net.close()
