"""Device protocols and their simulators (serial ports, sockets); nothing here knows the
kernel."""
