"""The link protocol: arrays sent between kernels over ZeroMQ (through pyzmq).

``wire`` encodes arrays with their tick and time stamp into signed messages, ``endpoint``
checks addresses and keys, and ``peer`` holds the sockets of a link (a publisher and a
subscriber that reports a lost peer and reconnects). ``ikaros.links`` runs groups of a model
in other kernel processes over it; the IPCServer and IPCClient modules link two models.
"""
