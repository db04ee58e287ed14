"""Compiled readings: the printed formulas a predictor evaluates, kept as JSON trees a scene reads without SymPy.

A predictor (``derivations/<pkg>/predictors.py``) is split in two steps:

* **compile**: :class:`Readings` names what the predictor needs (:func:`reading`: member *member*, component
  *row*, of the reading of printed formula *name* as :meth:`Derivation.evaluator` builds it, derived quantities
  replaced; :func:`derived`: anything built from the statements, such as a solved tilt or a polynomial's terms)
  and, only when no current compiled entry is at hand, imports the package's statements and builds them with
  SymPy;
* **predict**: the predictor evaluates the compiled readings at the scene's numbers (:class:`Compiled`), in exact
  rationals (:class:`fractions.Fraction`) where the tree is rational, else as an exact real (:class:`Real`) whose
  sign is decided by Arb balls and, only where no ball at 1024 bits excludes zero (exactly at a threshold), by
  SymPy's exact evaluation of the same tree.

A compiled entry is a JSON tree of whitelisted nodes (rationals, argument positions, sums, products, powers, the
few functions of :data:`FUNCTIONS`, pi; tuples, tables and polynomial terms around them), never pickle, never
``eval``/``sympify``.  It is kept under a key covering its derivation's package (the committed ``compiled.json``
excepted), the sibling statements the package imports and the formula model (:func:`key`), in two places: the
package's ``compiled.json`` (shipped, written by ``symfloat run``, held current by ``tests/test_compiled.py``)
and the cache (``$SYMFLOAT_CACHE/compiled/``).  An entry is judged when read: its key must match the current
sources and its payload (with its SHA-256) must parse under the whitelist; otherwise it is compiled again from
the statements, and the scene reads what the statements say.  An entry records the files its key covers
(``covers``), so that a scene judges it by hashing them again rather than by parsing the modules whose imports
found them (:func:`_recorded_key`).
"""
from __future__ import annotations

import ast
import hashlib
import importlib
import importlib.metadata
import json
import math
import os
import tempfile
from fractions import Fraction
from pathlib import Path

__all__ = ["reading", "derived", "Terms", "real_roots", "Readings", "Compiled", "Real", "exact_sqrt", "compile_expr",
           "key", "judged_current", "write_shipped", "FORMAT"]

FORMAT = "symfloat-compiled/1"
SHIPPED = "compiled.json"
FUNCTIONS = ("sin", "cos", "tan", "atan", "asin", "acos", "exp", "log", "sign", "Abs")      # the functions a tree may call
RELATIONS = {"<": lambda x, y: x < y, "<=": lambda x, y: x <= y, ">": lambda x, y: x > y, ">=": lambda x, y: x >= y,
             "==": lambda x, y: x == y, "!=": lambda x, y: x != y}    # the conditions of a Piecewise
_MODEL = Path(__file__).resolve().parent
_LIBRARY = _MODEL.parent
PRECISIONS = (64, 256, 1024)            # bits of the Arb balls tried before SymPy decides a sign
EXACT_BITS = 1 << 16                    # a rational power larger than this (numerator or denominator) is a Real


class CompiledError(ValueError):
    """A compiled entry that does not parse under the whitelist."""


# ==== what a predictor asks for =======================================================================================
def reading(name, symbols, member, corrected=False, row=None):
    """Member *member* (component *row*) of the reading of printed formula *name* (its correction, with
    *corrected*) as a function of the statements' symbols named *symbols* (attribute names of the statements
    module): :meth:`Derivation.evaluator`'s expression, compiled."""
    def build(st):
        syms = tuple(getattr(st, n) for n in symbols)
        return st.DERIVATION.evaluator(name, syms, member, corrected=corrected, row=row)(*syms), syms
    return build


def derived(build):
    """Something built from the statements module by ``build(st) -> (value, symbols)``: *value* an expression, a
    tuple of them (one reading whose value is a tuple), a dict of those, or :class:`Terms`, a function of the
    SymPy symbols *symbols*."""
    return build


class Terms(tuple):
    """The terms ``((k, e_1, ..., e_m), c)`` of a polynomial with rational coefficients
    (:func:`symfloat.engine.roots.polynomial_terms`), kept as they are."""

    def at(self, values):
        """The polynomial in the unknown (exponent ``k``) at the exact parameter *values* (ints or Fractions, in
        the order of the parameters), a FLINT ``fmpq_poly``."""
        from flint import fmpq, fmpq_poly
        coefficients: dict[int, Fraction] = {}
        for (k, *powers), c in self:
            for q, e in zip(values, powers):
                c *= Fraction(q) ** e
            coefficients[k] = coefficients.get(k, 0) + c
        top = max(coefficients, default=0)
        return fmpq_poly([fmpq(Fraction(coefficients.get(k, 0)).numerator, Fraction(coefficients.get(k, 0)).denominator)
                          for k in range(top + 1)])


def real_roots(poly, bits: int) -> list[tuple[Fraction, int]]:
    """The distinct real roots of the FLINT polynomial *poly* (rational coefficients, not zero) with their
    multiplicities, ascending: isolated exactly by FLINT (``complex_roots``: square-free factorisation, certified
    isolation; a real root comes with an exactly zero imaginary part) and refined to *bits* bits, each as the
    dyadic midpoint of its ball (a Fraction)."""
    from flint import ctx
    if poly.degree() < 1:
        return []
    old, ctx.prec = ctx.prec, bits
    try:
        roots = poly.complex_roots()
    finally:
        ctx.prec = old
    out = []
    for r, multiplicity in roots:
        if r.imag.is_zero():
            man, exp = r.real.mid().man_exp()
            out.append((Fraction(int(man)) * Fraction(2) ** int(exp), multiplicity))
    return sorted(out)


# ==== trees: SymPy -> JSON (compile step) =============================================================================
def _tree(e, symbols):
    """The JSON tree of SymPy expression *e* in the arguments *symbols*; anything outside the whitelist raises."""
    import sympy as sp
    if e in symbols:
        return ["x", symbols.index(e)]
    if e is sp.pi:
        return ["pi"]
    if isinstance(e, (sp.Integer, sp.Rational)):
        return ["q", int(e.p), int(e.q)]
    if isinstance(e, sp.Add):
        return ["+", *(_tree(a, symbols) for a in e.args)]
    if isinstance(e, sp.Mul):
        return ["*", *(_tree(a, symbols) for a in e.args)]
    if isinstance(e, sp.Pow):
        return ["^", _tree(e.base, symbols), _tree(e.exp, symbols)]
    if isinstance(e, sp.Piecewise):
        return ["pw", *([_tree(c, symbols), _tree(v, symbols)] for v, c in e.args)]
    if e is sp.true or e is sp.false:
        return [str(bool(e)).lower()]
    if isinstance(e, sp.core.relational.Relational) and e.rel_op in RELATIONS:
        return [e.rel_op, _tree(e.lhs, symbols), _tree(e.rhs, symbols)]
    if isinstance(e, (sp.And, sp.Or)):
        return [type(e).__name__.lower(), *(_tree(a, symbols) for a in e.args)]
    if isinstance(e, sp.Not):
        return ["not", _tree(e.args[0], symbols)]
    name = type(e).__name__
    if name in FUNCTIONS and len(e.args) == 1:
        return ["f", name, _tree(e.args[0], symbols)]
    raise CompiledError(f"cannot compile {type(e).__name__} ({e}): not among the whitelisted nodes")


def _payload(value, symbols):
    import sympy as sp
    if isinstance(value, Terms):
        return {"terms": [[list(map(int, m)), [c.numerator, c.denominator]] for m, c in value]}
    if isinstance(value, dict):
        return {"table": {str(k): _payload(v, symbols) for k, v in value.items()}}
    if isinstance(value, sp.MatrixBase):
        value = tuple(value)
    if isinstance(value, (tuple, list)):                # the members of a matrix: one reading of a tuple
        return {"expr": ["tuple", *(_tree(sp.sympify(v), list(symbols)) for v in value)]}
    return {"expr": _tree(sp.sympify(value), list(symbols))}


def compile_expr(value, symbols):
    """*value* (as :func:`derived` builds it) compiled at once: what a compiled entry holds for it."""
    return _parse(_payload(value, tuple(symbols)), len(symbols))


# ==== trees: JSON -> values (predict step) ============================================================================
def _check_tree(t, nargs, top=True):
    """*t* if it is a tree of the whitelist over *nargs* arguments (a tuple of trees at its top), else
    :class:`CompiledError`."""
    if top and isinstance(t, list) and t[:1] == ["tuple"]:
        for sub in t[1:]:
            _check_tree(sub, nargs, False)
        return t
    if not (isinstance(t, list) and t and isinstance(t[0], str)):
        raise CompiledError(f"not a node: {t!r:.60}")
    op, rest = t[0], t[1:]
    ok = {"x": lambda: len(rest) == 1 and type(rest[0]) is int and 0 <= rest[0] < nargs,
          "pi": lambda: not rest,
          "q": lambda: len(rest) == 2 and all(type(v) is int for v in rest) and rest[1] > 0,
          "+": lambda: len(rest) >= 1, "*": lambda: len(rest) >= 1, "^": lambda: len(rest) == 2,
          "f": lambda: len(rest) == 2 and rest[0] in FUNCTIONS,
          "pw": lambda: len(rest) >= 1 and all(isinstance(c, list) and len(c) == 2 for c in rest),
          "true": lambda: not rest, "false": lambda: not rest, "not": lambda: len(rest) == 1,
          "and": lambda: len(rest) >= 1, "or": lambda: len(rest) >= 1,
          **{r: (lambda: len(rest) == 2) for r in RELATIONS}}.get(op)
    if ok is None or not ok():
        raise CompiledError(f"not a whitelisted node: {t!r:.60}")
    subs = rest[1:] if op == "f" else [x for c in rest for x in c] if op == "pw" else \
        rest if op in ("+", "*", "^", "not", "and", "or", *RELATIONS) else ()
    for sub in subs:
        _check_tree(sub, nargs, False)
    return t


def _parse(p, nargs):
    """The value a payload stands for: a :class:`Compiled`, a dict of them, or :class:`Terms`."""
    if not (isinstance(p, dict) and len(p) == 1):
        raise CompiledError(f"not a payload: {p!r:.60}")
    (kind, v), = p.items()
    if kind == "expr":
        return Compiled(_check_tree(v, nargs), nargs)
    if kind == "table" and isinstance(v, dict):
        return {k: _parse(x, nargs) for k, x in v.items()}
    if kind == "terms" and isinstance(v, list):
        out = []
        for m, c in v:
            if not (isinstance(m, list) and all(type(e) is int and e >= 0 for e in m) and len(c) == 2
                    and all(type(x) is int for x in c) and c[1] > 0):
                raise CompiledError(f"not a term: {[m, c]!r:.60}")
            out.append((tuple(m), Fraction(c[0], c[1])))
        return Terms(out)
    raise CompiledError(f"unknown payload kind {kind!r}")


def _sympy_of(t, args):
    """The SymPy expression of tree *t* at the exact *args* (the fallback of :class:`Real`)."""
    import sympy as sp
    op = t[0]
    if op == "x":
        v = args[t[1]]
        return v._sympy_() if isinstance(v, Real) else sp.Rational(v.numerator, v.denominator) \
            if isinstance(v, Fraction) else sp.sympify(v)
    if op == "pi":
        return sp.pi
    if op == "q":
        return sp.Rational(t[1], t[2])
    if op == "f":
        return getattr(sp, t[1])(_sympy_of(t[2], args))
    if op == "pw":
        return sp.Piecewise(*((_sympy_of(v, args), _sympy_of(c, args)) for c, v in t[1:]))
    if op in ("true", "false"):
        return sp.true if op == "true" else sp.false
    if op in RELATIONS:
        return sp.Rel(_sympy_of(t[1], args), _sympy_of(t[2], args), op)
    if op in ("and", "or", "not"):
        return {"and": sp.And, "or": sp.Or, "not": sp.Not}[op](*(_sympy_of(c, args) for c in t[1:]))
    parts = [_sympy_of(s, args) for s in t[1:]]
    return sp.Add(*parts) if op == "+" else sp.Mul(*parts) if op == "*" else sp.Pow(*parts)


class Real:
    """An exact real number given by a tree at exact arguments: its value as an Arb ball at any precision, its
    sign decided by the ball where the ball excludes zero (:data:`PRECISIONS`), else by SymPy's exact
    evaluation.  Arithmetic with ints, Fractions and other Reals gives Reals; comparisons decide signs."""

    __slots__ = ("_ball", "_sym")

    def __init__(self, ball, sym):
        self._ball, self._sym = ball, sym          # prec -> arb;  () -> SymPy expression

    def ball(self, prec: int):
        from flint import ctx
        old, ctx.prec = ctx.prec, prec
        try:
            return self._ball(prec)
        finally:
            ctx.prec = old

    def _sympy_(self):
        return self._sym()

    def sign(self) -> int:
        for prec in PRECISIONS:
            b = self.ball(prec)
            if b > 0:
                return 1
            if b < 0:
                return -1
        e = self._sym()                             # exactly at (or within 2^-1000 of) zero: SymPy decides
        if e.equals(0):
            return 0
        return 1 if e.is_positive else -1 if e.is_negative else _undecided(e)

    def __float__(self):
        return float(self.ball(128).mid())

    def _op(self, other, f, g):
        o = _real(other)
        if o is None:
            return NotImplemented
        return Real(lambda p: f(self._ball(p), o._ball(p)), lambda: g(self._sym(), o._sym()))

    def __add__(self, o): return self._op(o, lambda x, y: x + y, lambda x, y: x + y)
    def __radd__(self, o): return self._op(o, lambda x, y: y + x, lambda x, y: y + x)
    def __sub__(self, o): return self._op(o, lambda x, y: x - y, lambda x, y: x - y)
    def __rsub__(self, o): return self._op(o, lambda x, y: y - x, lambda x, y: y - x)
    def __mul__(self, o): return self._op(o, lambda x, y: x * y, lambda x, y: x * y)
    def __rmul__(self, o): return self._op(o, lambda x, y: y * x, lambda x, y: y * x)
    def __truediv__(self, o): return self._op(o, lambda x, y: x / y, lambda x, y: x / y)
    def __rtruediv__(self, o): return self._op(o, lambda x, y: y / x, lambda x, y: y / x)
    def __neg__(self): return Real(lambda p: -self._ball(p), lambda: -self._sym())

    def __pow__(self, o):
        if not isinstance(o, int):
            return NotImplemented
        return Real(lambda p: self._ball(p) ** o, lambda: self._sym() ** o)

    def _cmp(self, other):
        d = self - other
        if d is NotImplemented:
            raise TypeError(f"cannot compare an exact real with {type(other).__name__}")
        return d.sign()

    def __lt__(self, o): return self._cmp(o) < 0
    def __le__(self, o): return self._cmp(o) <= 0
    def __gt__(self, o): return self._cmp(o) > 0
    def __ge__(self, o): return self._cmp(o) >= 0
    def __eq__(self, o): return isinstance(o, (int, Fraction, Real)) and self._cmp(o) == 0
    __hash__ = None

    def __repr__(self):
        return f"Real({self.ball(64)})"


def _undecided(e):
    raise ArithmeticError(f"the sign of {e} is decided neither by Arb balls nor by SymPy")


def _rational_ball(q: Fraction):
    from flint import arb, fmpq
    return arb(fmpq(q.numerator, q.denominator))


def _real(v):
    """*v* (int, Fraction or Real) as a :class:`Real`; ``None`` for anything else."""
    if isinstance(v, Real):
        return v
    if isinstance(v, (int, Fraction)) and not isinstance(v, bool):
        q = Fraction(v)
        return Real(lambda p: _rational_ball(q), lambda: _sympy_of(["x", 0], (q,)))
    return None


def exact_sqrt(q):
    """The square root of the non-negative rational *q*: a Fraction where it is one, else a :class:`Real`."""
    return _pow_exact(Fraction(q), Fraction(1, 2))


def _huge(b: Fraction, e: int) -> bool:
    """Whether ``b^e`` has more than :data:`EXACT_BITS` bits in its numerator or denominator (2^(2^100), the value
    of ``h^{h^{100}}`` at h = 2, has more than any memory holds)."""
    n, d = abs(b.numerator), b.denominator
    return (n > 1 or d > 1) and abs(e) * max(n.bit_length(), d.bit_length()) > EXACT_BITS


# the arithmetic of each kind of argument: ("exact": ints, Fractions, Reals; "mpmath"; "numpy"; "float")
def _pow_exact(b, e):
    if isinstance(e, int) or (isinstance(e, Fraction) and e.denominator == 1):
        e = int(e)
        if isinstance(b, Fraction) and (e >= 0 or b != 0) and not _huge(b, e):
            return b ** e
        return _real(b) ** e if e >= 0 else 1 / _real(b) ** -e
    if isinstance(b, Fraction) and isinstance(e, Fraction) and e.denominator == 2 and b >= 0:
        r = _rational_sqrt(b)
        if r is not None:
            return r ** e.numerator if e.numerator >= 0 else 1 / r ** -e.numerator
    rb, re = _real(b), _real(e)
    return Real(lambda p: rb._ball(p) ** re._ball(p), lambda: rb._sym() ** re._sym())


def _rational_sqrt(q: Fraction):
    """The square root of *q* if it is rational, else ``None``."""
    n, d = math.isqrt(q.numerator), math.isqrt(q.denominator)
    return Fraction(n, d) if n * n == q.numerator and d * d == q.denominator else None


def _sign(x):
    return (x > 0) - (x < 0)


def _func_exact(name, x):
    if name == "sign":
        return Fraction(x.sign() if isinstance(x, Real) else _sign(x))
    if name == "Abs":
        return abs(x) if isinstance(x, Fraction) else x if x.sign() >= 0 else -x
    if isinstance(x, Fraction) and x == 0 and name in ("sin", "tan", "atan", "asin"):
        return Fraction(0)
    rx = _real(x)
    return Real(lambda p: getattr(rx._ball(p), name)(), lambda: _sympy_function(name)(rx._sym()))


def _arb_pi(prec):
    from flint import arb
    return arb.pi()


def _sympy_function(name):
    """SymPy's *name* (a function of :data:`FUNCTIONS`, or pi), imported only for the rare exact fallback."""
    import sympy as sp
    return getattr(sp, name)


def _kind(args) -> str:
    if any(type(v).__module__.startswith("sympy") for v in args):
        return "sympy"
    if all(isinstance(v, (int, Fraction, Real)) and not isinstance(v, bool) for v in args):
        return "exact"
    if any(type(v).__module__.startswith("mpmath") for v in args):
        return "mpmath"
    if any(type(v).__module__ == "numpy" and getattr(v, "ndim", 0) for v in args):
        return "numpy"
    return "float"


def _library(kind):
    if kind == "mpmath":
        import mpmath
        return mpmath.mpf, lambda b, e: b ** e, lambda n, x: getattr(mpmath, {"Abs": "fabs"}.get(n, n))(x), \
            lambda: +mpmath.pi
    if kind == "numpy":
        import numpy as np
        names = {"atan": "arctan", "asin": "arcsin", "acos": "arccos", "Abs": "abs"}
        return float, lambda b, e: b ** e, lambda n, x: getattr(np, names.get(n, n))(x), lambda: math.pi
    return float, lambda b, e: b ** e, lambda n, x: float(_sign(x)) if n == "sign" else abs(x) if n == "Abs" else \
        getattr(math, n)(x), lambda: math.pi


def _piecewise(ev, t, args):
    """The first piece whose condition holds (scalars); for NumPy arrays, piece by piece elementwise."""
    conds = []
    for c, v in t[1:]:
        cond = ev(c, args)
        if type(cond).__module__ == "numpy" and getattr(cond, "ndim", 0):
            conds.append((cond, v))
            continue
        if cond and not conds:
            return ev(v, args)
        if cond:
            conds.append((cond, v))
            break
    if not conds:
        raise ValueError("no piece of a Piecewise holds")
    import numpy as np
    return np.select([np.broadcast_to(c, np.shape(conds[0][0])) for c, _ in conds], [ev(v, args) for _, v in conds],
                     default=np.nan)


_LOGIC = {"pw": _piecewise, "true": lambda ev, t, args: True, "false": lambda ev, t, args: False,
          "not": lambda ev, t, args: not ev(t[1], args),
          "and": lambda ev, t, args: all(ev(c, args) for c in t[1:]),
          "or": lambda ev, t, args: any(ev(c, args) for c in t[1:]),
          **{r: (lambda ev, t, args, f=f: f(ev(t[1], args), ev(t[2], args))) for r, f in RELATIONS.items()}}


class Compiled:
    """A compiled reading: callable on exact arguments (ints, Fractions, :class:`Real`: an exact result, a
    Fraction where the tree is rational, else a :class:`Real`), on SymPy numbers or symbols (a SymPy expression),
    on mpmath numbers (mpmath), on NumPy arrays (elementwise) and on floats (a float), like
    :meth:`Derivation.evaluator`."""

    __slots__ = ("tree", "nargs")

    def __init__(self, tree, nargs):
        self.tree, self.nargs = tree, nargs

    def __call__(self, *args):
        if len(args) != self.nargs:
            raise TypeError(f"a compiled reading of {self.nargs} arguments called with {len(args)}")
        if self.tree[0] == "tuple":
            return tuple(Compiled(t, self.nargs)(*args) for t in self.tree[1:])
        kind = _kind(args)
        if kind == "sympy":                             # an argument is a SymPy number or symbol: SymPy's value
            return _sympy_of(self.tree, args)
        if kind == "exact":
            args = tuple(Fraction(v) if isinstance(v, int) else v for v in args)
            return self._exact(self.tree, args)
        number, power, func, pi = _library(kind)
        if kind == "float":
            args = tuple(float(v) for v in args)
        return self._numeric(self.tree, args, number, power, func, pi)

    def _exact(self, t, args):
        op = t[0]
        if op == "x":
            return args[t[1]]
        if op == "q":
            return Fraction(t[1], t[2])
        if op == "pi":
            return Real(_arb_pi, lambda: _sympy_function("pi"))
        if op == "f":
            return _func_exact(t[1], self._exact(t[2], args))
        if op in _LOGIC:
            return _LOGIC[op](self._exact, t, args)
        parts = [self._exact(s, args) for s in t[1:]]
        if op == "^":
            return _pow_exact(*parts)
        out = parts[0]
        for v in parts[1:]:
            out = out + v if op == "+" else out * v
        return out

    def _numeric(self, t, args, number, power, func, pi):
        op = t[0]
        if op == "x":
            return args[t[1]]
        if op == "q":
            return number(t[1]) / number(t[2]) if t[2] != 1 else number(t[1])
        if op == "pi":
            return pi()
        if op == "f":
            return func(t[1], self._numeric(t[2], args, number, power, func, pi))
        if op in _LOGIC:
            return _LOGIC[op](lambda u, a: self._numeric(u, a, number, power, func, pi), t, args)
        if op == "^" and t[2] == ["q", 1, 2]:
            return func("sqrt", self._numeric(t[1], args, number, power, func, pi))
        parts = [self._numeric(s, args, number, power, func, pi) for s in t[1:]]
        if op == "^":
            return power(*parts)
        out = parts[0]
        for v in parts[1:]:
            out = out + v if op == "+" else out * v
        return out


# ==== the key and the two stores ======================================================================================
def _imported_files(path: Path) -> list[Path]:
    """The files of the modules *path* imports that compiling can run: statements of sibling packages
    (``from ..pkg.statements import``) and library modules (``symfloat.x.y``, an import inside a function too)."""
    out = []
    for node in ast.walk(ast.parse(path.read_bytes())):
        names = []
        if isinstance(node, ast.ImportFrom) and node.level == 2 and node.module:
            out.append(path.parent.parent.joinpath(*node.module.split(".")).with_suffix(".py"))
        elif isinstance(node, ast.ImportFrom) and not node.level and node.module:
            names = [node.module] + [f"{node.module}.{a.name}" for a in node.names]
        elif isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        for name in names:
            parts = name.split(".")
            if parts[0] == "symfloat" and len(parts) > 1:
                base = _LIBRARY.joinpath(*parts[1:])
                out += [f for f in (base.with_suffix(".py"), base / "__init__.py")]
    return [f for f in out if f.is_file()]


def key(folder: Path) -> str:
    """The key of the compiled readings of the derivation package in *folder*: what compiling runs, and nothing
    a check alone reads (witnesses, certificates): its ``statements.py`` and ``predictors.py``, the statements of
    other packages they import (followed to the end), the library modules any of these import (not followed
    further), the whole formula model, and :data:`FORMAT`.  Editing a witness leaves the shipped readings
    current."""
    return _hash(_key_files(folder))


def _key_files(folder: Path) -> list[Path]:
    """The files :func:`key` covers, sorted (finding them parses every module followed: tenths of a second)."""
    files, todo = set(), [folder / "statements.py", folder / "predictors.py"]
    while todo:
        f = todo.pop()
        if f in files or not f.is_file():
            continue
        files.add(f)
        if not f.is_relative_to(_LIBRARY):                  # a module of a derivation package: followed
            todo += _imported_files(f)
    files |= _fixed(folder)
    return sorted(files)


def _fixed(folder: Path) -> set[Path]:
    """The files every key of the package in *folder* covers, whatever it imports."""
    return set(_MODEL.glob("*.py")) | {_LIBRARY / "__init__.py", _LIBRARY / "manifest.py", folder / "statements.py",
                                       folder / "predictors.py"}


def _hash(files) -> str:
    """The hash of *files* (by name and content), :data:`FORMAT` and the SymPy version (another SymPy may shape
    a compiled tree otherwise; read from the installed metadata, so that no scene imports SymPy)."""
    named = sorted((f"{p.parent.name}/{p.name}", p) for p in files)
    h = hashlib.sha256(f"{FORMAT} sympy {importlib.metadata.version('sympy')}".encode())
    for name, p in named:
        h.update(name.encode())
        h.update(p.read_bytes())
    return h.hexdigest()[:32]


def _covers(files, folder: Path) -> list[str]:
    """Where the files of a key lie, as an entry records them: ``symfloat/...`` in the library, else relative to
    the folder of the derivation packages."""
    return sorted(f"symfloat/{p.relative_to(_LIBRARY).as_posix()}" if p.is_relative_to(_LIBRARY)
                  else p.relative_to(folder.parent).as_posix() for p in files)


def _entry(path: Path):
    """The JSON in *path*, or ``None`` where there is none (an entry is judged by :func:`_judged`)."""
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def _recorded_key(entry, folder: Path) -> str | None:
    """The key of *entry* (of the package in *folder*), hashed again over the files it records it covers
    (``covers``), when that gives its key and the set is complete (every file any key covers, the formula model as
    it is now); else ``None``.  Then the sources are those :func:`key` would find, without parsing a module: the
    files it follows imports from are among them, byte for byte as when the key was made, so their imports are
    too."""
    covers = entry.get("covers") if isinstance(entry, dict) else None
    if not (isinstance(covers, list) and all(isinstance(c, str) and ".." not in c.split("/") for c in covers)):
        return None
    files = {_LIBRARY.joinpath(c.partition("/")[2]) if c.startswith("symfloat/") else folder.parent / c
             for c in covers}
    if not (all(f.is_file() for f in files) and _fixed(folder) <= files
            and {f for f in files if f.parent == _MODEL} == set(_MODEL.glob("*.py"))):
        return None
    k = _hash(files)
    return k if k == entry.get("key") else None


def _digest(payload) -> str:
    return hashlib.sha256(json.dumps(payload, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


def _cache_root() -> Path:
    env = os.environ.get("SYMFLOAT_CACHE")
    if env:
        return Path(env) / "compiled"
    from ..project import outputs_root
    return (outputs_root() or Path.cwd()) / ".symfloat-cache" / "compiled"


def _judged(entry, package: str, k: str):
    """``(readings, printed)`` of *entry* (:func:`_entry`) if it is one of *package* under key *k* whose content
    hash matches and whose payload parses under the whitelist, else ``None``."""
    if not (isinstance(entry, dict) and entry.get("format") == FORMAT and entry.get("package") == package
            and entry.get("key") == k and isinstance(entry.get("readings"), dict)
            and entry.get("sha256") == _digest({"readings": entry["readings"], "printed": entry.get("printed")})):
        return None
    try:
        return _parsed(entry)
    except (CompiledError, KeyError, TypeError, ValueError):
        return None


def _printed(p):
    """The printed formulas' metadata of an entry, checked: ``[{name, locator, erratum, lost, corrected}]`` in the
    derivation's order."""
    if not isinstance(p, list):
        raise CompiledError("no printed formulas")
    for m in p:
        if not (isinstance(m, dict) and isinstance(m.get("name"), str) and isinstance(m.get("locator"), str)
                and isinstance(m.get("erratum"), bool) and isinstance(m.get("lost"), bool)
                and (m.get("corrected") is None or isinstance(m["corrected"], str))):
            raise CompiledError(f"printed formula {m!r:.60}: malformed")
    return p


class Readings:
    """The compiled readings of the predictor module whose ``__file__`` is *module_file* (package
    *package*, dotted), by name: read from the shipped ``compiled.json`` or the cache where an entry is current
    and parses, else compiled from the statements (SymPy) and stored in the cache."""

    def __init__(self, module_file, package: str, spec: dict):
        self.folder, self.package, self.spec = Path(module_file).resolve().parent, package, spec
        shipped = _entry(self.folder / SHIPPED)
        self.key = _recorded_key(shipped, self.folder) or key(self.folder)
        self.source = "shipped"
        found = _judged(shipped, self.package.rpartition(".")[2], self.key)
        if found is None:
            self.source = "cache"
            found = _judged(_entry(self._cache_file()), self.package.rpartition(".")[2], self.key)
        if found is None:
            self.source = "statements"
            entry = self.compile()
            self._store(self._cache_file(), entry)
            found = _parsed(entry)
        self.values, self.printed = found

    def __getitem__(self, name):
        return self.values[name]

    def _cache_file(self) -> Path:
        return _cache_root() / f"{self.package.rpartition('.')[2]}.{self.key}.json"

    def compile(self) -> dict:
        """The entry: every reading of the spec built from the statements, and the printed formulas' metadata."""
        st = importlib.import_module(f"{self.package}.statements")
        readings = {}
        for name, build in self.spec.items():
            value, symbols = build(st)
            readings[name] = {"nargs": len(symbols), "value": _payload(value, tuple(symbols))}
        printed = [{"name": p.name, "locator": p.locator, "erratum": p.erratum is not None, "lost": bool(p.lost),
                    "corrected": p.erratum.corrected if p.erratum is not None else None}
                   for p in st.DERIVATION.printed]
        return {"format": FORMAT, "package": self.package.rpartition(".")[2], "key": self.key,
                "covers": _covers(_key_files(self.folder), self.folder),
                "sha256": _digest({"readings": readings, "printed": printed}), "readings": readings,
                "printed": printed}

    @staticmethod
    def _store(path: Path, entry: dict) -> None:
        """Write *entry* to *path* atomically; a cache that cannot be written is left alone (the readings are
        compiled again next time)."""
        tmp = None
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                f.write(json.dumps(entry, ensure_ascii=False, sort_keys=True, indent=1) + "\n")
            mask = os.umask(0o022)
            os.umask(mask)
            os.chmod(tmp, 0o666 & ~mask)          # the umask's mode, not mkstemp's 0600
            os.replace(tmp, path)
            tmp = None
        except OSError:
            pass
        finally:
            if tmp is not None:
                Path(tmp).unlink(missing_ok=True)


def _parsed(entry):
    """``(readings, printed)`` of an entry, every payload parsed under the whitelist."""
    readings = {}
    for name, p in entry["readings"].items():
        if not (isinstance(p, dict) and type(p.get("nargs")) is int and p["nargs"] >= 0):
            raise CompiledError(f"reading {name!r}: no argument count")
        readings[name] = _parse(p["value"], p["nargs"])
    return readings, _printed(entry["printed"])


def judged_current(readings: Readings) -> bool:
    """Whether the package's shipped ``compiled.json`` is current (its key) and parses."""
    return _judged(_entry(readings.folder / SHIPPED), readings.package.rpartition(".")[2], readings.key) is not None


def write_shipped(readings: Readings) -> None:
    """Write the package's ``compiled.json`` afresh from the statements."""
    readings._store(readings.folder / SHIPPED, readings.compile())
