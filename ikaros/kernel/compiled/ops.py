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
TAP = 16        # when pool[B] = r >= 0: p[r * N + i] = arena[pool[A + i]] (row r of p), then
                # pool[B] = -1
