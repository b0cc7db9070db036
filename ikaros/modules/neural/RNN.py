"""RNN: the template of a recurrent network module."""
from ikaros.module import Input, Module, Output


class RNN(Module):
    """The template that recurrent network modules start from: it declares the ports such a
    network has (a main input, a training input and target, top-down and auxiliary inputs from
    other networks) but on its own only copies INPUT to OUTPUT; STATE-OUT, the state a
    subclass would show, stays 0, as in Ikaros 2 (the golden files show it; the class is not
    in Ikaros 3). The optional inputs are accepted and unused."""

    INPUT = Input("the main input")
    T_INPUT = Input("the training input (unused by the template)", optional=True,
                    name="T-INPUT")
    T_OUTPUT = Input("the target output for supervised learning (unused by the template)",
                     optional=True, name="T-OUTPUT")
    TOP_DOWN = Input("input from higher levels (unused by the template)", optional=True,
                     name="TOP-DOWN")
    AUX = Input("input from other networks (unused by the template)", optional=True)
    T_AUX = Input("training input from other networks (unused by the template)",
                  optional=True, name="T-AUX")
    OUTPUT = Output("the main output: a copy of INPUT", size_set="INPUT")
    STATE_OUT = Output("the state of the network (0 in the template)", size_set="INPUT",
                       name="STATE-OUT")

    def tick(self):
        self.OUTPUT[...] = self.INPUT
