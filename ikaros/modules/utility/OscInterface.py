"""OscInterface: sends and receives Open Sound Control messages over UDP."""
import re
import socket
import struct

import numpy as np

from ikaros.module import Module, Parameter

# --- OSC 1.0 encoding and decoding (pure Python) ------------------------------------------

_BUNDLE = b"#bundle\0"
_PATTERN_CHARS = set("?*[]{}")


def _pad(data: bytes) -> bytes:
    """``data`` followed by 1 to 4 NUL bytes, to a multiple of 4 (OSC strings)."""
    return data + b"\0" * (4 - len(data) % 4)


def _blob(data: bytes) -> bytes:
    return struct.pack(">i", len(data)) + data + b"\0" * (-len(data) % 4)


def encode_message(address: str, args=()) -> bytes:
    """An OSC message: ``address`` and arguments (float -> f, int -> i, str -> s,
    bytes -> b, True/False -> T/F, None -> N)."""
    tags, payload = [","], []
    for a in args:
        if a is True or a is False:
            tags.append("T" if a else "F")
        elif a is None:
            tags.append("N")
        elif isinstance(a, (int, np.integer)):
            tags.append("i")
            payload.append(struct.pack(">i", int(a)))
        elif isinstance(a, (float, np.floating)):
            tags.append("f")
            payload.append(struct.pack(">f", float(a)))
        elif isinstance(a, str):
            tags.append("s")
            payload.append(_pad(a.encode("utf-8")))
        elif isinstance(a, (bytes, bytearray)):
            tags.append("b")
            payload.append(_blob(bytes(a)))
        else:
            raise TypeError(f"no OSC type for {type(a).__name__}")
    return _pad(address.encode("utf-8")) + _pad("".join(tags).encode()) + b"".join(payload)


def encode_floats(address: str, values) -> bytes:
    """An OSC message with one float32 argument per value (fast path for arrays)."""
    values = np.asarray(values, dtype=">f4").reshape(-1)
    return (_pad(address.encode("utf-8")) + _pad(("," + "f" * values.size).encode())
            + values.tobytes())


def encode_bundle(contents, timetag: int = 1) -> bytes:
    """An OSC bundle of encoded messages or bundles (timetag 1 means "immediately")."""
    return _BUNDLE + struct.pack(">Q", timetag) + b"".join(
        struct.pack(">i", len(c)) + c for c in contents)


def _read_string(data: bytes, pos: int):
    end = data.index(b"\0", pos)
    text = data[pos:end].decode("utf-8")
    return text, pos + (end - pos) // 4 * 4 + 4


def decode_message(data: bytes):
    """(address, type tags without the comma, arguments) of one OSC message."""
    address, pos = _read_string(data, 0)
    if not address.startswith("/"):
        raise ValueError(f"not an OSC address: {address!r}")
    if pos >= len(data):                  # old-style message without a type tag string
        return address, "", []
    tags, pos = _read_string(data, pos)
    if not tags.startswith(","):
        raise ValueError(f"bad OSC type tag string {tags!r}")
    tags = tags[1:]
    args = []
    for t in tags:
        if t in "if":
            args.append(struct.unpack_from(">i" if t == "i" else ">f", data, pos)[0])
            pos += 4
        elif t in "hd":
            args.append(struct.unpack_from(">q" if t == "h" else ">d", data, pos)[0])
            pos += 8
        elif t == "t":
            args.append(struct.unpack_from(">Q", data, pos)[0])
            pos += 8
        elif t in "sS":
            s, pos = _read_string(data, pos)
            args.append(s)
        elif t == "b":
            n = struct.unpack_from(">i", data, pos)[0]
            if n < 0 or pos + 4 + n > len(data):
                raise ValueError("OSC blob runs past the end of the packet")
            args.append(bytes(data[pos + 4:pos + 4 + n]))
            pos += 4 + n + (-n % 4)
        elif t in "crm":
            raw = data[pos:pos + 4]
            args.append(chr(struct.unpack(">I", raw)[0]) if t == "c" else bytes(raw))
            pos += 4
        elif t in "TF":
            args.append(t == "T")
        elif t in "NI":
            args.append(None)             # nil, and impulse (infinitum): no value
        elif t in "[]":
            continue                      # array delimiters: flatten the array
        else:
            raise ValueError(f"unknown OSC type tag {t!r}")
        if pos > len(data):
            raise ValueError("OSC arguments run past the end of the packet")
    return address, tags, args


def decode_packet(data: bytes, depth: int = 0):
    """The messages of an OSC packet (a message or a bundle, nested bundles flattened in
    order), each as (address, type tags, arguments). Timetags are ignored: everything is
    handled at once."""
    if data.startswith(_BUNDLE):
        if depth > 16:
            raise ValueError("OSC bundles nested too deeply")
        pos, messages = 16, []
        while pos < len(data):
            (n,) = struct.unpack_from(">i", data, pos)
            if n <= 0 or n % 4 or pos + 4 + n > len(data):
                raise ValueError("bad OSC bundle element size")
            messages.extend(decode_packet(data[pos + 4:pos + 4 + n], depth + 1))
            pos += 4 + n
        return messages
    if len(data) % 4:
        raise ValueError("an OSC packet has a size that is a multiple of 4")
    return [decode_message(data)]


def _pattern_regex(pattern: str):
    """A compiled regular expression for an OSC address pattern (? * [..] [!..] {a,b})."""
    out, i = [], 0
    while i < len(pattern):
        ch = pattern[i]
        if ch == "?":
            out.append("[^/]")
        elif ch == "*":
            out.append("[^/]*")
        elif ch == "[":
            end = pattern.find("]", i)
            if end < 0:
                out.append(re.escape(ch))
            else:
                body = pattern[i + 1:end]
                neg = body.startswith("!")
                body = body[1:] if neg else body
                body = "".join("\\" + c if c in "\\^[]" else c for c in body)
                out.append(f"[{'^' if neg else ''}{body}]")
                i = end
        elif ch == "{":
            end = pattern.find("}", i)
            if end < 0:
                out.append(re.escape(ch))
            else:
                out.append("(?:" + "|".join(re.escape(p) for p in
                                           pattern[i + 1:end].split(",")) + ")")
                i = end
        else:
            out.append(re.escape(ch))
        i += 1
    return re.compile("".join(out) + r"\Z")


def parse_addresses(text: str):
    """[(address, count)] from ``"/a;/b:2"``: the count after a colon, or None when none
    is given (which means 1)."""
    result = []
    for item in re.split(r"[;\s]+", text or ""):
        if not item:
            continue
        address, _, count = item.partition(":")
        if not address.startswith("/"):
            raise ValueError(f'an OSC address starts with "/": "{item}"')
        try:
            n = int(count) if count else None
        except ValueError:
            raise ValueError(f'bad value count in OSC address "{item}"') from None
        if n is not None and n < 1:
            raise ValueError(f'an OSC address needs at least one value: "{item}"')
        result.append((address, n))
    return result


_NUMERIC = (int, float, bool)


class OscInterface(Module):
    """Sends and receives Open Sound Control (OSC 1.0) messages over UDP. Each address in
    ``inadresses`` (separated by ``;``) gives an output OUTPUT_1, OUTPUT_2, ... and each
    address in ``outadresses`` an input INPUT_1, INPUT_2, .... An address may end with
    ``:n`` for n values (``/2/faderB:2``); the default is 1. On every tick the module first
    sends, for every connected input, one message to ``outhost``:``outport`` with the
    input's elements as float32 arguments, then reads every packet that has arrived on
    ``inport`` (without waiting): a message (also inside bundles, whose timetags are
    ignored) whose address is one of the input addresses, or an OSC pattern matching it,
    writes its numeric arguments (int, float, double, true/false) to that output; an output
    keeps its values until a new message arrives. Messages for other addresses are ignored
    (printed with ``show_unhandled``). A port that cannot be opened is reported as an error
    and the run goes on without it. The sockets are closed when the run stops. (Ikaros 2
    spelled the address parameters ``inadresses`` and ``outadresses``; ``inaddresses`` and
    ``outaddresses`` are accepted too. No golden file holds OscInterface: the message
    handling is this project's reading of the reference.)"""

    outhost = Parameter("127.0.0.1", "the host messages are sent to")
    outport = Parameter(12001, "the UDP port messages are sent to", type="int")
    inport = Parameter(12000, "the UDP port to listen on", type="int")
    inhost = Parameter("", "the local address to listen on; empty means every interface "
                       "(use 127.0.0.1 to accept messages from this computer only)")
    inadresses = Parameter("", "the addresses to receive, separated by ;, each optionally "
                           "with :n for n values; each gives an output OUTPUT_i")
    outadresses = Parameter("", "the addresses to send to, separated by ;, one per input "
                            "INPUT_i")
    inaddresses = Parameter("", "another name for inadresses; used when given")
    outaddresses = Parameter("", "another name for outadresses; used when given")
    debug = Parameter(False, "print every message sent and received")
    show_unhandled = Parameter(False, "print received messages that match no address")

    # --- build time -----------------------------------------------------------------------
    def configure(self):
        self._in = parse_addresses(self.inaddresses or self.inadresses)
        self._out = parse_addresses(self.outaddresses or self.outadresses)
        for i, (address, n) in enumerate(self._in, 1):
            self.add_output(f"OUTPUT_{i}", (n or 1,),
                            description=f"the values last received at {address}")
        for i, (address, n) in enumerate(self._out, 1):
            self.add_input(f"INPUT_{i}", optional=True,
                           description=f"the values sent to {address} on every tick")

    # --- run time -------------------------------------------------------------------------
    def init(self):
        self._recv_sock = None
        self._send_sock = None
        self._warned = set()
        self._outputs = [getattr(self, f"OUTPUT_{i}") for i in range(1, len(self._in) + 1)]
        for out in self._outputs:
            out.fill(0)
        self._exact = {}
        for i, (address, _) in enumerate(self._in):
            self._exact.setdefault(address, []).append(i)
        self._patterns = {}
        self._inputs = []
        for i, (address, n) in enumerate(self._out, 1):
            x = getattr(self, f"INPUT_{i}")
            if x is None:
                continue
            if n is not None and x.size != n:
                self.warning(f"INPUT_{i} has {x.size} values but {address} expects {n}; "
                             f"all {x.size} are sent")
            self._inputs.append((address, x))
        if self._in:
            sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
            try:
                sock.bind((self.inhost, self.inport))
            except OSError as e:
                sock.close()
                self.error(f"cannot listen on UDP port {self.inport}: {e.strerror or e}")
            else:
                sock.setblocking(False)
                self._recv_sock = sock
        if self._inputs:
            self._send_sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
            self._target = (self.outhost, self.outport)

    def _warn_once(self, key, message):
        if key not in self._warned:
            self._warned.add(key)
            self.warning(message)

    def tick(self):
        if self._send_sock is not None:
            self._send()
        if self._recv_sock is not None:
            self._receive()

    def _send(self):
        for address, x in self._inputs:
            packet = encode_floats(address, x)
            try:
                self._send_sock.sendto(packet, self._target)
            except OSError as e:
                self._warn_once("send", f"cannot send to {self.outhost}:{self.outport}: "
                                        f"{e.strerror or e}")
                return
            if self.debug:
                self.print(f"sent {address} {' '.join(f'{v:g}' for v in x.reshape(-1))}")

    def _receive(self):
        for _ in range(10000):             # a bound on the packets handled in one tick
            try:
                data, origin = self._recv_sock.recvfrom(65536)
            except (BlockingIOError, InterruptedError):
                return
            except OSError as e:
                self._warn_once("receive", f"receive error: {e.strerror or e}")
                return
            try:
                messages = decode_packet(data)
            except (ValueError, struct.error, UnicodeDecodeError) as e:
                self._warn_once("malformed", f"ignored a malformed OSC packet from "
                                             f"{origin[0]}:{origin[1]}: {e}")
                continue
            for address, tags, args in messages:
                self._handle(address, tags, args)

    def _targets(self, address):
        if address in self._exact:
            return self._exact[address]
        if not _PATTERN_CHARS.intersection(address):
            return ()
        if address not in self._patterns:
            regex = _pattern_regex(address)
            self._patterns[address] = [i for i, (a, _) in enumerate(self._in)
                                       if regex.match(a)]
        return self._patterns[address]

    def _handle(self, address, tags, args):
        values = [float(a) for a in args if isinstance(a, _NUMERIC)]
        targets = self._targets(address) if values else ()
        if not targets:
            if self.show_unhandled:
                self.print(f"unhandled message {address} ,{tags} {args}")
            return
        if self.debug:
            self.print(f"received {address} {' '.join(f'{v:g}' for v in values)}")
        for i in targets:
            out = self._outputs[i]
            n = min(out.size, len(values))
            out[:n] = values[:n]

    def stop(self):
        for name in ("_recv_sock", "_send_sock"):
            sock = getattr(self, name, None)
            if sock is not None:
                sock.close()
                setattr(self, name, None)
