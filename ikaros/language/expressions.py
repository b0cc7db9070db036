"""Arithmetic expressions (``+ - * /``, unary minus, parentheses) evaluated safely."""
from __future__ import annotations

import re

from ..limits import current as current_limits

_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|(.))")


class ExpressionError(ValueError):
    """An expression that cannot be evaluated."""


def is_arithmetic(text: str) -> bool:
    """Whether the text is made only of numbers, operators and parentheses (and has one)."""
    s = text.strip()
    return bool(re.fullmatch(r"[\d.eE+\-*/()\s]+", s)) and bool(re.search(r"[+\-*/]", s[1:]))


def evaluate_arithmetic(text: str) -> float:
    """Evaluate numbers joined by + - * / and parentheses. Errors raise ExpressionError."""
    tokens = []
    for m in _TOKEN.finditer(text.strip()):
        if m.group(1) is not None:
            tokens.append(float(m.group(1)))
        elif m.group(2) is not None:
            if m.group(2) not in "+-*/()":
                raise ExpressionError(f'unexpected "{m.group(2)}" in "{text}"')
            tokens.append(m.group(2))
    if not tokens:
        raise ExpressionError("empty expression")
    _check_nesting(tokens, text)
    pos = 0

    def peek():
        return tokens[pos] if pos < len(tokens) else None

    def take():
        nonlocal pos
        pos += 1
        return tokens[pos - 1]

    def expr():
        value = term()
        while peek() in ("+", "-"):
            value = value + term() if take() == "+" else value - term()
        return value

    def term():
        value = unary()
        while peek() in ("*", "/"):
            op = take()
            rhs = unary()
            if op == "*":
                value *= rhs
            elif rhs == 0:
                raise ExpressionError(f'division by zero in "{text}"')
            else:
                value /= rhs
        return value

    def unary():
        if peek() == "-":
            take()
            return -unary()
        if peek() == "+":
            take()
            return unary()
        return atom()

    def atom():
        tok = take() if pos < len(tokens) else None
        if tok == "(":
            value = expr()
            if peek() != ")":
                raise ExpressionError(f'unmatched parenthesis in "{text}"')
            take()
            return value
        if isinstance(tok, float):
            return tok
        raise ExpressionError(f'"{text}" is not an arithmetic expression')

    value = expr()
    if pos != len(tokens):
        raise ExpressionError(f'"{text}" is not an arithmetic expression')
    return value


def _check_nesting(tokens: list, text: str) -> None:
    """Refuse parentheses or signs nested deeper than the limit (before the recursive parse)."""
    limit = current_limits().max_expression_depth
    depth = run = 0
    for tok in tokens:
        depth += tok == "("
        depth -= tok == ")"
        run = run + 1 if tok in ("-", "+", "(") else 0
        if depth > limit or run > limit:
            raise ExpressionError(f"the expression nests deeper than {limit} levels: "
                                  f"\"{text[:40]}...\"")
