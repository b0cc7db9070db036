"""LearningModule: the common interface of the Ikaros learning modules, as a base class."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class LearningModule(Module):
    """The interface the Ikaros 2 learning modules share (INPUT; the training pair T-INPUT /
    T-TARGET and DELAYED-T-INPUT; top-down input and error; learning and activation gains; an
    auxiliary channel; the weights W and U), with no learning of its own: a template to
    subclass. As it is, OUTPUT is a copy of INPUT, T-OUTPUT of T-INPUT, ERROR-OUTPUT of
    TOP-DOWN-ERROR and AUX-OUTPUT of AUX-INPUT (each 0 while its input is unconnected), and W
    (one row and one column per INPUT element) and U (one row per INPUT element, one column
    per AUX-T-INPUT element) stay 0. A Python subclass (``class Hebb(LearningModule)``)
    inherits the ports and parameter and overrides ``tick``. The catalogue gives the Ikaros 2
    template's ports and says it does no learning; the copies it makes here are this
    project's reading (no golden case covers it)."""

    learning_rate = Parameter(0.1, "the learning rate, for subclasses' learning rules")

    INPUT = Input("the input pattern")
    T_INPUT = Input("the training input", optional=True, name="T-INPUT")
    T_TARGET = Input("the training target for T-INPUT", optional=True, name="T-TARGET")
    DELAYED_T_INPUT = Input("the training input of an earlier tick, to learn sequences",
                            optional=True, name="DELAYED-T-INPUT")
    TOP_DOWN_INPUT = Input("input from higher levels", optional=True, name="TOP-DOWN-INPUT")
    TOP_DOWN_ERROR = Input("error from higher levels", optional=True, name="TOP-DOWN-ERROR")
    LEARNING_GAIN = Input("scales learning (its first element)", optional=True,
                          name="LEARNING-GAIN")
    ACTIVATION_GAIN = Input("scales activation (its first element)", optional=True,
                            name="ACTIVATION-GAIN")
    AUX_INPUT = Input("auxiliary input", optional=True, name="AUX-INPUT")
    AUX_T_INPUT = Input("auxiliary training input: the columns of U", optional=True,
                        name="AUX-T-INPUT")
    AUX_T_OUTPUT = Input("auxiliary training output", optional=True, name="AUX-T-OUTPUT")

    OUTPUT = Output("the response to INPUT (here: INPUT)", shape="INPUT.shape")
    T_OUTPUT = Output("the response to T-INPUT (here: T-INPUT); only when T-INPUT is "
                      "connected", optional=True, name="T-OUTPUT")
    ERROR_OUTPUT = Output("the error passed to lower levels (here: TOP-DOWN-ERROR); only "
                          "when TOP-DOWN-ERROR is connected", optional=True,
                          name="ERROR-OUTPUT")
    AUX_OUTPUT = Output("the auxiliary response: the size of AUX-INPUT, or of INPUT while "
                        "AUX-INPUT is unconnected", name="AUX-OUTPUT")
    W = Output("the weights: one row and one column per INPUT element",
               size_set_x="INPUT", size_set_y="INPUT")
    U = Output("the auxiliary weights: one row per INPUT element, one column per AUX-T-INPUT "
               "element; only when AUX-T-INPUT is connected", optional=True)

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        aux = self.input_shape("AUX-INPUT")
        if aux is None:
            return
        self.set_output_shape("AUX-OUTPUT", aux if aux else shape)
        for output, source in (("T-OUTPUT", "T-INPUT"), ("ERROR-OUTPUT", "TOP-DOWN-ERROR")):
            if self.input_shape(source):
                self.set_output_shape(output, self.input_shape(source))
        aux_t = self.input_shape("AUX-T-INPUT")
        if aux_t:
            self.set_output_shape("U", (int(np.prod(shape)), int(np.prod(aux_t))))

    def tick(self):
        self.OUTPUT[...] = self.INPUT
        for out, source in ((self.T_OUTPUT, self.T_INPUT),
                            (self.ERROR_OUTPUT, self.TOP_DOWN_ERROR),
                            (self.AUX_OUTPUT, self.AUX_INPUT)):
            if out is not None and source is not None and out.size == source.size:
                out[...] = source.reshape(out.shape)
