"""The instruction set of the compiled tick: operation codes and the layout of one
instruction. An instruction is one row of an int64 array; offsets are in elements of the
float32 buffer arena, ``param`` is the first of the instruction's slots in the float32
parameter array, and ``a``/``b`` of the gather are positions in the int64 index pool."""

# the columns of one instruction
OP, OUT, N, A, B, PARAM = range(6)
WIDTH = 6

COPY = 1        # OUT[i] = A[i]
GATHER = 2      # arena[pool[B + i]] = arena[pool[A + i]]
ADD = 3         # OUT[i] = A[i] + B[i]
SUBTRACT = 4    # OUT[i] = A[i] - B[i]
MULTIPLY = 5    # OUT[i] = A[i] * B[i]
DIVIDE = 6      # OUT[i] = A[i] / B[i], 0 where B[i] == 0 (and the instruction is flagged)
MAXIMUM = 7     # OUT[i] = A[i] if A[i] > B[i] else B[i]; NaN when either is NaN (as NumPy)
MINIMUM = 8     # OUT[i] = A[i] if A[i] < B[i] else B[i]; NaN when either is NaN (as NumPy)
SCALE = 9       # OUT[i] = A[i] * p[0], then * arena[B] when B >= 0
ABS = 10        # OUT[i] = |A[i]|
TANH = 11       # OUT[i] = tanh(A[i])
THRESHOLD = 12  # p = bypass, linear, threshold
SUM = 13        # OUT[0] = the sum of A[0:N] in float64, as NumPy adds (pairwise)
CONSTANT = 14   # OUT[i] = p[i]
INTEGRATE = 15  # OUT = OUT * p[0] + p[1] * A, clipped to p[3] when p[2], to p[5] when p[4]
TAP = 16        # an output tap (kernel/taps.py); pool[B:] is its state (TAP_* below) and
                # the tick of each row: when the arena's tick is due and there is room,
                # row ROW of p (N values each) = arena[pool[A + i]]; flagged when the room
                # is full or SIGNAL is set

# the state of a tap, at pool[B + ...]; the tick of row r at pool[B + TAP_STATE + r]
TAP_TICK = 0        # the tick whose values the arena holds
TAP_DUE = 1         # the next tick to keep
TAP_EVERY = 2
TAP_ROW = 3         # the row the next kept tick goes into
TAP_END = 4         # the row past the room given
TAP_SIGNAL = 5      # 1: flag at the next call whatever happens
TAP_STATE = 6
