"""Kernels linked across processes and machines (ZeroMQ through pyzmq).

``split`` runs groups of one model in other kernel processes, and ``worker`` is the
``ikaros worker`` server those groups run in. They talk the link protocol of
``ikaros.hardware.link`` (signed array messages, addresses and keys, the sockets of a link).
"""
