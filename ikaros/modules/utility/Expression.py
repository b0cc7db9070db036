"""Expression: evaluates a formula of its inputs.

The formula is parsed by a small, safe parser into a tree of Python closures that evaluate
with NumPy, element by element over whole arrays. Nothing is passed to Python's eval.
Grammar, lowest precedence first::

    expr    := logic ['?' expr ':' expr]
    logic   := conj {('or' | '||' | 'xor' | 'nor') conj}
    conj    := compare {('and' | '&&' | 'nand') compare}
    compare := sum {('<' | '<=' | '>' | '>=' | '==' | '=' | '!=' | '<>') sum}
    sum     := product {('+' | '-') product}
    product := unary {('*' | '/' | '%') unary}
    unary   := ('-' | '+' | 'not' | '!') unary | power
    power   := primary ['^' unary]                       (right-associative)
    primary := number [power] | name | name '(' [expr {',' expr}] ')' | '(' expr ')'

A number directly followed by a name or a parenthesis multiplies it (``2x``). Comparisons
and logical operators give 1 or 0. Names are case-insensitive for functions and constants.
"""
from __future__ import annotations

import re

import numpy as np

from ikaros.module import RESERVED, Module, Output, Parameter, attribute_name


class ExpressionError(ValueError):
    """The expression text cannot be parsed."""


_TOKEN = re.compile(r"""\s*(?:
      (?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)
    | (?P<name>[A-Za-z_][A-Za-z0-9_]*)
    | (?P<op><=|>=|==|!=|<>|&&|\|\||[-+*/%^()<>=!?:,])
    )""", re.VERBOSE)

_WORD_OPS = {"and", "or", "xor", "nor", "nand", "not"}


def _tokenize(text: str) -> list[tuple[str, str, int]]:
    tokens, pos = [], 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise ExpressionError(f'unexpected character "{text[pos:].strip()[:1]}" at '
                                  f'position {pos + 1} of "{text}"')
        kind = m.lastgroup
        value = m.group(kind)
        if kind == "name" and value.lower() in _WORD_OPS:
            kind, value = "op", value.lower()
        tokens.append((kind, value, m.start(kind)))
        pos = m.end()
    tokens.append(("end", "", len(text)))
    return tokens


def _b(x):
    return np.asarray(x) != 0


def _round(x):                      # halves away from zero, as in C
    return np.sign(x) * np.floor(np.abs(x) + 0.5)


def _roundn(x, n):
    scale = np.power(10.0, _round(n))
    return _round(np.asarray(x) * scale) / scale


def _variadic(reduce):
    def f(*args):
        result = args[0]
        for a in args[1:]:
            result = reduce(result, a)
        return result
    return f


def _avg(*args):
    total = args[0]
    for a in args[1:]:
        total = total + a
    return total / len(args)


# name -> (smallest, largest number of arguments (None: any), function)
FUNCTIONS = {
    "abs": (1, 1, np.abs), "sqrt": (1, 1, np.sqrt), "exp": (1, 1, np.exp),
    "log": (1, 1, np.log), "log10": (1, 1, np.log10), "log2": (1, 1, np.log2),
    "log1p": (1, 1, np.log1p), "expm1": (1, 1, np.expm1),
    "sin": (1, 1, np.sin), "cos": (1, 1, np.cos), "tan": (1, 1, np.tan),
    "asin": (1, 1, np.arcsin), "acos": (1, 1, np.arccos), "atan": (1, 1, np.arctan),
    "sinh": (1, 1, np.sinh), "cosh": (1, 1, np.cosh), "tanh": (1, 1, np.tanh),
    "asinh": (1, 1, np.arcsinh), "acosh": (1, 1, np.arccosh), "atanh": (1, 1, np.arctanh),
    "cot": (1, 1, lambda x: 1.0 / np.tan(x)), "sec": (1, 1, lambda x: 1.0 / np.cos(x)),
    "csc": (1, 1, lambda x: 1.0 / np.sin(x)),
    "d2r": (1, 1, np.radians), "r2d": (1, 1, np.degrees),
    "ceil": (1, 1, np.ceil), "floor": (1, 1, np.floor), "round": (1, 1, _round),
    "trunc": (1, 1, np.trunc), "frac": (1, 1, lambda x: x - np.trunc(x)),
    "sgn": (1, 1, np.sign), "sign": (1, 1, np.sign),
    "sigmoid": (1, 1, lambda x: 1.0 / (1.0 + np.exp(-np.asarray(x)))),
    "pow": (2, 2, np.power), "atan2": (2, 2, np.arctan2), "hypot": (2, 2, np.hypot),
    "hyp": (2, 2, np.hypot), "root": (2, 2, lambda x, n: np.power(x, 1.0 / np.asarray(n))),
    "logn": (2, 2, lambda x, n: np.log(x) / np.log(n)), "roundn": (2, 2, _roundn),
    "min": (1, None, _variadic(np.minimum)), "max": (1, None, _variadic(np.maximum)),
    "sum": (1, None, _variadic(np.add)), "mul": (1, None, _variadic(np.multiply)),
    "avg": (1, None, _avg),
    "clamp": (3, 3, lambda lo, x, hi: np.minimum(np.maximum(x, lo), hi)),
    "inrange": (3, 3, lambda lo, x, hi: ((np.asarray(lo) <= x) & (x <= np.asarray(hi)))
                .astype(np.float32)),
    "if": (3, 3, lambda c, a, b: np.where(_b(c), a, b)),
}

CONSTANTS = {"pi": np.pi, "epsilon": np.finfo(np.float32).eps}

_COMPARE = {"<": np.less, "<=": np.less_equal, ">": np.greater, ">=": np.greater_equal,
            "==": np.equal, "=": np.equal, "!=": np.not_equal, "<>": np.not_equal}


class Compiled:
    """A parsed expression: call it to evaluate with the current variable values."""

    def __init__(self, text: str, evaluate, names: set[str]):
        self.text = text
        self.names = names              # the variables the expression uses
        self._evaluate = evaluate

    def __call__(self):
        return self._evaluate()


def compile_expression(text: str, variables: dict, on_divide_by_zero=None) -> Compiled:
    """Parse ``text``. ``variables`` maps names to zero-argument callables that return the
    current value (an array or a number). ``on_divide_by_zero`` is called when a division or
    remainder by zero happens (the result there is 0)."""
    return _Parser(text, variables, on_divide_by_zero).parse()


class _Parser:
    def __init__(self, text, variables, on_divide_by_zero):
        self.text = text
        self.tokens = _tokenize(text)
        self.i = 0
        self.variables = variables
        self.used = set()
        self.on_zero = on_divide_by_zero or (lambda: None)

    # --- token helpers ----------------------------------------------------------------
    def peek(self):
        return self.tokens[self.i]

    def take(self):
        tok = self.tokens[self.i]
        self.i += 1
        return tok

    def at(self, *ops):
        kind, value, _ = self.peek()
        return kind == "op" and value in ops

    def expect(self, op):
        kind, value, pos = self.take()
        if kind != "op" or value != op:
            raise self.error(f'expected "{op}"', pos, value)

    def error(self, what, pos, found):
        found = f'"{found}"' if found else "the end"
        return ExpressionError(f'{what} at position {pos + 1} of "{self.text}", found {found}')

    # --- grammar ----------------------------------------------------------------------
    def parse(self) -> Compiled:
        if self.peek()[0] == "end":
            raise ExpressionError("the expression is empty")
        node = self.expr()
        kind, value, pos = self.peek()
        if kind != "end":
            raise self.error("unexpected text", pos, value)
        return Compiled(self.text, node, self.used)

    def expr(self):
        cond = self.logic()
        if self.at("?"):
            self.take()
            a = self.expr()
            self.expect(":")
            b = self.expr()
            return lambda: np.where(_b(cond()), a(), b())
        return cond

    def logic(self):
        left = self.conj()
        while self.at("or", "||", "xor", "nor"):
            op = self.take()[1]
            right = self.conj()
            left = self._logical(op, left, right)
        return left

    def conj(self):
        left = self.compare()
        while self.at("and", "&&", "nand"):
            op = self.take()[1]
            right = self.compare()
            left = self._logical(op, left, right)
        return left

    @staticmethod
    def _logical(op, f, g):
        if op in ("or", "||"):
            return lambda: (_b(f()) | _b(g())).astype(np.float32)
        if op == "xor":
            return lambda: (_b(f()) ^ _b(g())).astype(np.float32)
        if op == "nor":
            return lambda: (~(_b(f()) | _b(g()))).astype(np.float32)
        if op == "nand":
            return lambda: (~(_b(f()) & _b(g()))).astype(np.float32)
        return lambda: (_b(f()) & _b(g())).astype(np.float32)

    def compare(self):
        left = self.sum()
        while self.at(*_COMPARE):
            fn = _COMPARE[self.take()[1]]
            right = self.sum()
            left = (lambda f, g, fn: lambda: fn(f(), g()).astype(np.float32))(left, right, fn)
        return left

    def sum(self):
        left = self.product()
        while self.at("+", "-"):
            fn = np.add if self.take()[1] == "+" else np.subtract
            right = self.product()
            left = (lambda f, g, fn: lambda: fn(f(), g()))(left, right, fn)
        return left

    def product(self):
        left = self.unary()
        while self.at("*", "/", "%"):
            op = self.take()[1]
            right = self.unary()
            if op == "*":
                left = (lambda f, g: lambda: np.multiply(f(), g()))(left, right)
            else:
                left = self._guarded(np.divide if op == "/" else np.fmod, left, right)
        return left

    def _guarded(self, fn, f, g):
        on_zero = self.on_zero

        def evaluate():
            a, b = np.asarray(f()), np.asarray(g())
            zero = b == 0
            if not zero.any():
                return fn(a, b)
            on_zero()
            return np.where(zero, 0.0, fn(a, np.where(zero, 1.0, b)))
        return evaluate

    def unary(self):
        if self.at("-", "+", "not", "!"):
            op = self.take()[1]
            operand = self.unary()
            if op == "-":
                return lambda: np.negative(operand())
            if op == "+":
                return operand
            return lambda: (~_b(operand())).astype(np.float32)
        return self.power()

    def power(self):
        base = self.primary()
        if self.at("^"):
            self.take()
            exponent = self.unary()
            return lambda: np.power(base(), exponent())
        return base

    def primary(self):
        kind, value, pos = self.take()
        if kind == "number":
            number = float(value)
            nxt = self.peek()
            if nxt[0] == "name" or (nxt[0] == "op" and nxt[1] == "("):   # 2x, 3(x+1)
                factor = self.power()
                return lambda: np.multiply(number, factor())
            return lambda: number
        if kind == "name":
            if self.at("("):
                return self.call(value, pos)
            if value in self.variables:
                self.used.add(value)
                return self.variables[value]
            if value.lower() in CONSTANTS:
                constant = float(CONSTANTS[value.lower()])
                return lambda: constant
            known = ", ".join(sorted(self.variables)) or "none"
            raise ExpressionError(f'unknown name "{value}" in "{self.text}" (the inputs are '
                                  f'{known})')
        if kind == "op" and value == "(":
            node = self.expr()
            self.expect(")")
            return node
        raise self.error("expected a number, a name or (", pos, value)

    def call(self, name, pos):
        entry = FUNCTIONS.get(name.lower())
        if entry is None:
            raise ExpressionError(f'unknown function "{name}" in "{self.text}"')
        low, high, fn = entry
        self.expect("(")
        args = []
        if not self.at(")"):
            args.append(self.expr())
            while self.at(","):
                self.take()
                args.append(self.expr())
        self.expect(")")
        if len(args) < low or (high is not None and len(args) > high):
            wanted = str(low) if low == high else f"{low} or more" if high is None else \
                f"{low} to {high}"
            raise ExpressionError(f'{name} takes {wanted} arguments, not {len(args)}, in '
                                  f'"{self.text}"')
        if len(args) == 1:
            (a,) = args
            return lambda: fn(a())
        if len(args) == 2:
            a, b = args
            return lambda: fn(a(), b())
        return lambda: fn(*(a() for a in args))


class Expression(Module):
    """Evaluates the formula ``expression`` element by element on every tick. ``inputs``
    names the variables, separated by commas; each becomes an input of that name, and all
    inputs must have the same number of elements (several connections into one are laid end
    to end). The output has the shape of the inputs (one element when there are none). The
    formula may use numbers, the variables, the constants pi and epsilon, the operators
    + - * / % ^ (power), comparisons < <= > >= == != (giving 1 or 0), and, or, xor, not,
    the conditional c ? a : b, and the functions abs sqrt exp log log10 log2 sin cos tan asin
    acos atan atan2 sinh cosh tanh cot sec csc d2r r2d ceil floor round roundn trunc frac sgn
    sigmoid pow root logn hypot min max sum avg mul clamp(lo, x, hi) inrange(lo, x, hi) and
    if(c, a, b), a subset of the ExprTk syntax of Ikaros 2. The text is parsed, never run as
    Python. Division or remainder by zero gives 0, and any other result that is not a finite
    number (such as sqrt(-1)) is output as 0; both give a warning once."""

    expression = Parameter("x", "the formula, in the variables named by inputs",
                           type="string")
    inputs = Parameter("x", "the names of the variables (and inputs), separated by commas",
                       type="string")
    debug = Parameter(False, "print the output on every tick")
    OUTPUT = Output("the value of the expression for each element of the inputs")

    def configure(self):
        names = [n.strip() for n in re.split(r"[,;]", self.inputs or "") if n.strip()]
        taken = set(RESERVED) | {"expression", "inputs", "debug", "OUTPUT"}
        for name in names:
            if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
                raise ValueError(f'"{name}" is not a valid variable name')
            if name in taken or name.startswith("_") or name.lower() in FUNCTIONS or \
                    name.lower() in _WORD_OPS:
                raise ValueError(f'"{name}" cannot be used as a variable name')
        if len(set(names)) != len(names):
            raise ValueError(f'inputs "{self.inputs}" names a variable twice')
        self._names = names
        for name in names:
            self.add_input(name, description=f"the variable {name}")
        self._views = {}
        variables = {name: (lambda n=name: self._views[n]) for name in names}
        self._formula = compile_expression(self.expression, variables, self._divided_by_zero)
        unused = [n for n in names if n not in self._formula.names]
        if unused and self.debug:
            self.print(f"inputs not used by the expression: {', '.join(unused)}")

    def set_sizes(self):
        shapes = [self.input_shape(n) for n in self._names]
        if any(s is None for s in shapes):
            return
        if not shapes:
            self.set_output_shape("OUTPUT", (1,))
            return
        sizes = {int(np.prod(s)) for s in shapes}
        if len(sizes) != 1:
            detail = ", ".join(f"{n} {s}" for n, s in zip(self._names, shapes))
            raise ValueError(f"the inputs must have the same size; they have shapes {detail}")
        if all(s == shapes[0] for s in shapes):
            self.set_output_shape("OUTPUT", shapes[0])
        else:
            self.set_output_shape("OUTPUT", (sizes.pop(),))

    def init(self):
        shape = self.OUTPUT.shape
        for name in self._names:
            self._views[name] = getattr(self, attribute_name(name)).reshape(shape)
        self._warned_zero = False
        self._warned_nonfinite = False

    def _divided_by_zero(self):
        if not self._warned_zero:
            self._warned_zero = True
            self.warning(f'division by zero in "{self.expression}"; the result is 0 there')

    def tick(self):
        with np.errstate(all="ignore"):
            result = np.asarray(self._formula(), dtype=np.float64)
        self.OUTPUT[...] = result                # broadcasts a constant result
        bad = ~np.isfinite(self.OUTPUT)
        if bad.any():
            self.OUTPUT[bad] = 0
            if not self._warned_nonfinite:
                self._warned_nonfinite = True
                self.warning(f'"{self.expression}" is not a finite number for some elements; '
                             f'they are output as 0')
        if self.debug:
            self.print(" ".join(f"{v:g}" for v in self.OUTPUT.flat))
