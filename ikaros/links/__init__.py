"""Kernels linked across processes and machines (ZeroMQ through pyzmq).

``wire`` encodes arrays with their tick and time stamp into signed messages, ``endpoint``
checks addresses and keys, ``peer`` holds the sockets of a link (a publisher and a
subscriber that reports a lost peer and reconnects), ``split`` runs groups of one model in
other kernel processes, and ``worker`` is the ``ikaros worker`` server those groups run in.
"""
