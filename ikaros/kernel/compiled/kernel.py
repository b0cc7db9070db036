"""The one compiled function that runs instructions over the buffer arena (needs numba).

It is compiled once and cached on disk (numba ``cache=True``: in ``__pycache__`` beside this
file, or numba's user cache folder when that is not writable); every model reuses it, since
a model's instructions are data. Each operation gives the same float32 results as the
NumPy call of the module it stands for (the float64 sum adds in NumPy's pairwise order), except
``tanh``: libm's and NumPy's differ by up to 3 units in the last place. It keeps the GIL, as NumPy does on small
arrays: a call takes microseconds, and giving the GIL away in every call would let another
Python thread (the web UI's) hold up the next tick."""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .ops import (ABS, ADD, CONSTANT, COPY, DIVIDE, GATHER, INTEGRATE, MAXIMUM, MINIMUM,
                  MULTIPLY, SCALE, SUBTRACT, SUM, TANH, TAP, TAP_DUE, TAP_END, TAP_EVERY,
                  TAP_ROW, TAP_SIGNAL, TAP_STATE, TAP_TICK, THRESHOLD)

_BLOCK = 128           # NumPy's pairwise summation block
_BUFFER = 8192         # NumPy's casting buffer: a float32 array is summed in float64 chunks


@njit(cache=True)
def _pairwise(block, start, n):
    if n < 8:
        res = 0.0
        for i in range(n):
            res += np.float64(block[start + i])
        return res
    if n <= _BLOCK:
        r0 = np.float64(block[start])
        r1 = np.float64(block[start + 1])
        r2 = np.float64(block[start + 2])
        r3 = np.float64(block[start + 3])
        r4 = np.float64(block[start + 4])
        r5 = np.float64(block[start + 5])
        r6 = np.float64(block[start + 6])
        r7 = np.float64(block[start + 7])
        i = 8
        while i < n - (n % 8):
            r0 += np.float64(block[start + i])
            r1 += np.float64(block[start + i + 1])
            r2 += np.float64(block[start + i + 2])
            r3 += np.float64(block[start + i + 3])
            r4 += np.float64(block[start + i + 4])
            r5 += np.float64(block[start + i + 5])
            r6 += np.float64(block[start + i + 6])
            r7 += np.float64(block[start + i + 7])
            i += 8
        res = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
        while i < n:
            res += np.float64(block[start + i])
            i += 1
        return res
    half = n // 2
    half -= half % 8
    return _pairwise(block, start, half) + _pairwise(block, start + half, n - half)


@njit(cache=True)
def _sum(block, start, n):
    total = 0.0
    done = 0
    while done < n:
        k = min(_BUFFER, n - done)
        total += _pairwise(block, start + done, k)
        done += k
    return total


@njit(cache=True)
def execute(block, code, first, last, params, pool, flags):
    """Run instructions ``first`` to ``last - 1`` of ``code``; returns how many set their
    flag (a division by zero). Arrays are taken as slices of the arena so that loops over
    large arrays vectorise."""
    flagged = 0
    zero = np.float32(0.0)
    one = np.float32(1.0)
    for k in range(first, last):
        op = code[k, 0]
        out = code[k, 1]
        n = code[k, 2]
        a = code[k, 3]
        b = code[k, 4]
        p = code[k, 5]
        o = block[out:out + n]
        x = block[a:a + n]
        if op == COPY:
            for i in range(n):
                o[i] = x[i]
        elif op == GATHER:
            for i in range(n):
                block[pool[b + i]] = block[pool[a + i]]
        elif op == ADD:
            y = block[b:b + n]
            for i in range(n):
                o[i] = x[i] + y[i]
        elif op == SUBTRACT:
            y = block[b:b + n]
            for i in range(n):
                o[i] = x[i] - y[i]
        elif op == MULTIPLY:
            y = block[b:b + n]
            for i in range(n):
                o[i] = x[i] * y[i]
        elif op == DIVIDE:
            y = block[b:b + n]
            hit = 0
            for i in range(n):
                d = y[i]
                if d == zero:
                    o[i] = zero
                    hit = 1
                else:
                    o[i] = x[i] / d
            if hit:
                flags[k] = 1
                flagged += 1
        elif op == MAXIMUM:
            y = block[b:b + n]
            for i in range(n):
                u = x[i]
                v = y[i]
                o[i] = u if (u > v or u != u) else v
        elif op == MINIMUM:
            y = block[b:b + n]
            for i in range(n):
                u = x[i]
                v = y[i]
                o[i] = u if (u < v or u != u) else v
        elif op == SCALE:
            f = params[p]
            for i in range(n):
                o[i] = x[i] * f
            if b >= 0:
                s = block[b]
                for i in range(n):
                    o[i] = o[i] * s
        elif op == ABS:
            for i in range(n):
                o[i] = abs(x[i])
        elif op == TANH:
            for i in range(n):
                o[i] = math.tanh(x[i])
        elif op == THRESHOLD:
            t = params[p + 2]
            if params[p] != zero:
                for i in range(n):
                    o[i] = x[i]
            elif params[p + 1] != zero:
                for i in range(n):
                    d = x[i] - t
                    o[i] = zero if d < zero else d
            else:
                for i in range(n):
                    o[i] = one if x[i] > t else zero
        elif op == SUM:
            block[out] = np.float32(_sum(block, a, n))
        elif op == CONSTANT:
            c = params[p:p + n]
            for i in range(n):
                o[i] = c[i]
        elif op == INTEGRATE:
            alpha = params[p]
            beta = params[p + 1]
            low_on = params[p + 2] != zero
            low = params[p + 3]
            high_on = params[p + 4] != zero
            high = params[p + 5]
            for i in range(n):
                v = o[i] * alpha
                v = v + beta * x[i]
                if low_on and v < low:
                    v = low
                if high_on and v > high:
                    v = high
                o[i] = v
        elif op == TAP:
            t = pool[b + TAP_TICK]
            row = pool[b + TAP_ROW]
            end = pool[b + TAP_END]
            if t >= pool[b + TAP_DUE] and row < end and (row + 1) * n <= params.size:
                kept = params[row * n:row * n + n]
                index = pool[a:a + n]
                for i in range(n):
                    kept[i] = block[index[i]]
                pool[b + TAP_STATE + row] = t
                row += 1
                pool[b + TAP_ROW] = row
                pool[b + TAP_DUE] = t + pool[b + TAP_EVERY]
            pool[b + TAP_TICK] = t + 1
            if row == end or pool[b + TAP_SIGNAL] != 0:
                flags[k] = 1
                flagged += 1
    return flagged
