"""The SymPy a derivation notebook runs: its symbols, each step's claim and check, as source code.

A notebook cell states a step in plain SymPy a reader can change and run again: the members of
its chain printed as Python (:class:`SymPyCode`, SymPy's string printer with the derivation's
symbols under Python names), the values earlier steps established put in (:data:`HELPERS`), the
strategy of the step's proof certificate applied to the difference (:func:`proof_source`,
the same calls as :func:`symfloat.engine.identity.check_identity` replays), and both members
evaluated at a small rational point inside the assumptions (:func:`small_point`).  Every printed
member is read back and must give the object the derivation built (:meth:`Code.source`), so a
notebook never shows code that states something else than what the engine checked.
"""
from __future__ import annotations

import ast
import functools
import importlib
import inspect
import itertools
import keyword
import re
from fractions import Fraction

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.printing.repr import ReprPrinter
from sympy.printing.str import StrPrinter

from ..engine.identity import AGREEMENT, DIGITS

__all__ = ["SymPyCode", "Code", "HELPERS", "STRATEGY_WORDS", "proof_source", "strategy_helper", "small_point",
           "point_source", "agree", "finite", "functions_of", "defined_functions", "definitions_source", "bound_names"]

HELPERS = '''\
derived = {}   # symbol -> the value a step established for it (its last member)
done = {}      # expression -> the expression with its integrals, limits, ... carried out (each done once)


def insert(expr):
    """expr with the values established so far put in for their symbols, then its integrals,
    limits, derivatives and sums carried out."""
    for _ in range(12):
        new = expr.xreplace(derived)
        if new == expr:
            break
        expr = new
    key = expr.as_immutable() if isinstance(expr, MatrixBase) else expr
    if key not in done:
        done[key] = expr.doit()
    return done[key]


def at(point, *exprs):
    """The values of exprs at point: exact where they are rational, else to 30 digits."""
    values = []
    for e in exprs:
        v = e.xreplace(point).doit()
        exact = all(c.is_Rational for c in v) if isinstance(v, MatrixBase) else v.is_Rational
        values.append(v if exact else v.evalf(30, chop=True))
    return values


def same(x, y):
    """Are the values x, y equal: exactly where both are rational, else to 25 of their 30 digits?"""
    pairs = zip(x, y) if isinstance(x, MatrixBase) else [(x, y)]
    return all(a == b if a.is_Rational and b.is_Rational else abs(a - b) <= 10**-25 * max(abs(a), 1)
               for a, b in pairs)
'''

# the strategies of symfloat.engine.identity, as code applied to the difference ``{d}`` of two members
# (``squares``: to the members ``{a}``, ``{b}`` themselves)
_STRATEGY_CODE = {
    "cancel": "cancel(together({d}))",
    "expand": "expand(powsimp(expand({d}), force=True))",
    "radsimp": "cancel(radsimp(together({d})))",
    "pythagoras": "pythagoras({d})",
    "branches": "branches({d})",
    "simplify": "simplify({d})",
    "squares": "cancel(together(expand({a}**2 - {b}**2)))",
}

STRATEGY_WORDS = {
    "cancel": "brought over one denominator and cancelled",
    "expand": "expanded",
    "radsimp": "rationalised and cancelled",
    "pythagoras": "reduced by the Pythagorean identity (the squares of a sine and its cosine add up to 1)",
    "branches": "split into its cases, each brought over one denominator and cancelled",
    "simplify": "simplified by SymPy's simplify",
    "squares": "squared (both members are non-negative, so equal squares mean equal members) and cancelled",
}


def strategy_helper(strategy: str) -> tuple[str, set]:
    """The definition a notebook needs before it can call *strategy* (``""`` for a SymPy call), with the SymPy
    names it uses: the own function's source of ``pythagoras`` (:mod:`symfloat.engine.pythagoras`) and of
    ``branches`` (:mod:`symfloat.engine.branches`), so the notebook runs the very function the engine runs."""
    if strategy not in ("pythagoras", "branches"):
        return "", set()
    module = importlib.import_module(f"symfloat.engine.{strategy}")
    source = inspect.getsource(getattr(module, strategy))
    return source, {n for n in re.findall(r"[A-Za-z_]+", source) if n in module.__dict__ and n != strategy}


def proof_source(strategy: str, a: str, b: str, matrix: bool) -> str:
    """The SymPy call of *strategy* on the members named *a* and *b* (elementwise for matrices)."""
    if strategy == "squares":
        body = _STRATEGY_CODE["squares"].format(a="p", b="q")
        return (f"Matrix([{body} for p, q in zip({a}, {b})])" if matrix
                else _STRATEGY_CODE["squares"].format(a=a, b=b))
    if matrix:
        return f"({a} - {b}).applyfunc(lambda e: {_STRATEGY_CODE[strategy].format(d='e')})"
    return _STRATEGY_CODE[strategy].format(d=f"{a} - {b}")


class SymPyCode(StrPrinter):
    """SymPy's string printer with symbols under their Python names, rationals that stay exact when
    run (``Rational(1, 3)``, never ``1/3``), and, for a member kept as printed (``unevaluated``),
    integers as SymPy integers so that ``with evaluate(False)`` keeps the print's arithmetic."""

    def __init__(self, names: dict, unevaluated: bool = False):
        super().__init__({"order": "none"})
        self.names = names
        self.unevaluated = unevaluated

    def _print_Symbol(self, expr):
        return self.names[expr]

    def _print_Integer(self, expr):
        return f"S({expr.p})" if self.unevaluated else str(expr.p)

    def _print_Rational(self, expr):
        return f"Rational({expr.p}, {expr.q})"

    def _print_Half(self, expr):
        return "Rational(1, 2)"

    def _print_Pow(self, expr, rational=False):
        if expr.exp.is_Rational and not expr.exp.is_Integer and expr.exp not in (sp.S.Half, -sp.S.Half):
            return f"{self.parenthesize(expr.base, 1000)}**{self._print(expr.exp)}"
        return super()._print_Pow(expr, rational)

    def _print_Mul(self, expr):
        if len(expr.args) > 2 and expr.args[0] == -1:      # -(a*b*c): run as written, -a would enter a sum a
            return "-(" + self._print(sp.Mul._from_args(expr.args[1:])) + ")"
        return super()._print_Mul(expr)

    def _print_Limit(self, expr):
        e, z, z0, direction = expr.args
        return f"Limit({self._print(e)}, {self._print(z)}, {self._print(z0)}, dir={str(direction)!r})"

    def _print_UnevaluatedExpr(self, expr):
        return f"UnevaluatedExpr({self._print(expr.args[0])})"


def _python_name(name: str, taken: set) -> str:
    n = re.sub(r"\W+", "_", name.replace("^", "_").replace("'", "_prime")).strip("_") or "q"
    if n[0].isdigit():
        n = "q_" + n
    while keyword.iskeyword(n) or hasattr(sp, n) or n in taken or n in _RESERVED:
        n += "_"
    taken.add(n)
    return n


# the names the cells assign (the helpers' own names are local to them)
_RESERVED = {"derived", "done", "insert", "at", "same", "chain", "values", "proof", "point", "left", "right", "gap",
             "conditions"}


class Code:
    """Python names for the symbols and undefined functions of a derivation, and the SymPy source of its
    expressions in those names."""

    def __init__(self, symbols, functions=(), preferred=None, defined=()):
        preferred = preferred or {}
        self.defined = {f.__name__: f for f in defined}     # the derivation's own function classes, by name
        taken: set = set(self.defined)
        self.names: dict = {}
        # a dummy after the symbol of its name, dummies by creation: the same names whatever the sets' order
        ordered = sorted(symbols, key=lambda s: (s.name, str(s.assumptions0), isinstance(s, sp.Dummy),
                                                 getattr(s, "dummy_index", 0)))
        for s in ordered:                      # names that are identifiers already keep them
            if s.name.isidentifier() and s not in preferred:
                self.names[s] = _python_name(s.name, taken)
        for s in ordered:
            if s not in self.names:
                self.names[s] = _python_name(preferred.get(s, s.name), taken)
        self.functions = {f: _python_name(f.__name__, taken) for f in sorted(functions, key=lambda f: f.__name__)}
        self.namespace = {k: getattr(sp, k) for k in dir(sp) if not k.startswith("_")}
        self.namespace.update({v: k for k, v in self.names.items()})
        self.namespace.update({v: k for k, v in self.functions.items()})
        self.namespace.update(self.defined)
        self.used: set = set()

    def source(self, expr) -> str:
        """*expr* as SymPy source that, run, gives *expr* again."""
        text, evaluated = self.member(expr)
        if not evaluated:
            raise ValueError(f"{expr} keeps arithmetic unevaluated: use Code.member")
        return text

    def member(self, expr) -> tuple[str, bool]:
        """*expr* as SymPy source and whether it reads back as built when run as it is (``True``) or only
        under ``with evaluate(False)`` (``False``: a member that keeps the print's arithmetic).  Tried in turn:
        SymPy's printing, the same kept unevaluated, the expression tree, and SymPy's printing with the nodes
        SymPy would rearrange kept as built (:class:`_Kept`)."""
        text = _FunctionNames(self.names, self.functions).doprint(expr)
        if isinstance(expr, sp.Integer):           # a SymPy integer, not Python's
            text = f"S({text})"
        if self._reads_back(text, expr, evaluate=True):
            return text, True
        text = _FunctionNames(self.names, self.functions, unevaluated=True).doprint(expr)
        if self._reads_back(text, expr, evaluate=False):
            return text, False
        text = _Tree({**self.names, **self.functions}).doprint(expr)     # the expression tree, node by node
        if self._reads_back(text, expr, evaluate=False):
            return text, False
        text = _Kept(self.names, self.functions, self.namespace).doprint(expr)
        if self._reads_back(text, expr, evaluate=True):
            return text, True
        raise ValueError(f"no SymPy source reads back as {sp.srepr(expr)[:200]}")

    def _reads_back(self, text: str, expr, evaluate: bool) -> bool:
        try:
            with sp.evaluate(evaluate):
                # the text was printed here from the derivation's SymPy objects, and runs with SymPy's names only
                back = eval(text, {"__builtins__": {}, **self.namespace})      # noqa: S307
        except Exception:                                   # a form SymPy cannot read back: try the next one
            return False
        if not (back == expr or isinstance(expr, sp.MatrixBase) and isinstance(back, sp.MatrixBase)
                and back.shape == expr.shape and all(x == y for x, y in zip(back, expr))):
            return False
        self.used |= {n for n in re.findall(r"[A-Za-z_]\w*", text) if n in self.namespace
                      and n not in self._own()}
        return True

    def _own(self) -> set:
        return set(self.names.values()) | set(self.functions.values()) | set(self.defined)

    def declarations(self) -> str:
        """The cell that declares every symbol by name, with the assumptions the derivation gave it; a dummy
        as a ``Dummy``, which is no other symbol (``Symbol('k')`` beside the symbol ``k`` would be ``k``)."""
        groups: dict = {}
        single = []
        for s, n in self.names.items():
            given = {k: v for k, v in sorted(s._assumptions_orig.items())}
            if re.fullmatch(r"[A-Za-z]\w*", s.name) and n == s.name and not isinstance(s, sp.Dummy):
                groups.setdefault(tuple(given.items()), []).append(s)
            else:
                single.append((s, n, given))
        lines = []
        for given, group in sorted(groups.items(), key=lambda g: str(g[0])):
            kw = "".join(f", {k}={v}" for k, v in given)
            for i in range(0, len(group), 10):              # ten to a line: a line the cell shows whole
                syms = group[i:i + 10]
                names = ", ".join(self.names[s] for s in syms)
                lines.append(f"{names} = Symbol({syms[0].name!r}{kw})" if len(syms) == 1 else
                             f"{names} = symbols({' '.join(s.name for s in syms)!r}{kw})")
        for s, n, given in single:
            kw = "".join(f", {k}={v}" for k, v in given.items())
            lines.append(f"{n} = {'Dummy' if isinstance(s, sp.Dummy) else 'Symbol'}({s.name!r}{kw})")
        for f, n in self.functions.items():
            lines.append(f"{n} = Function({f.__name__!r})")
        return "\n".join(lines)


class _FunctionNames(SymPyCode):
    """:class:`SymPyCode` with the derivation's undefined functions under their Python names."""

    def __init__(self, names, functions, unevaluated=False):
        super().__init__(names, unevaluated)
        self.functions = functions

    def _print_Function(self, expr):
        if isinstance(expr, AppliedUndef) and expr.func in self.functions:
            return f"{self.functions[expr.func]}({', '.join(self._print(a) for a in expr.args)})"
        return super()._print_Function(expr)


class _Kept(_FunctionNames):
    """:class:`SymPyCode` that keeps a product, sum or power as built where SymPy would rearrange it when run:
    ``Mul(2, t - sin(t), evaluate=False)`` for the print's 2(t - sin t), which SymPy multiplies out; everything
    else is evaluated as usual, so that the rest reads as plain SymPy."""

    def __init__(self, names, functions, namespace):
        super().__init__(names, functions)
        self.namespace = namespace

    def _kept(self, expr, text: str) -> str:
        try:
            # the text was printed here from the derivation's SymPy objects, and runs with SymPy's names only
            same = eval(text, {"__builtins__": {}, **self.namespace}) == expr      # noqa: S307
        except Exception:                                   # a form SymPy cannot read back: keep the node
            same = False
        if same:
            return text
        return f"{type(expr).__name__}({', '.join(self._print(a) for a in expr.args)}, evaluate=False)"

    def _print_Mul(self, expr):
        return self._kept(expr, super()._print_Mul(expr))

    def _print_Add(self, expr, order=None):
        return self._kept(expr, super()._print_Add(expr, order))

    def _print_Pow(self, expr, rational=False):
        return self._kept(expr, super()._print_Pow(expr, rational))


class _Tree(ReprPrinter):
    """SymPy's tree printer (``Mul(Integer(-1), ...)``) with the derivation's names: the last resort for
    an expression whose arithmetic neither form above keeps."""

    def __init__(self, names):
        super().__init__({"order": "none"})
        self.names = names

    def _print_Symbol(self, expr):
        # a limit's direction is a symbol ('+') of SymPy's, not the derivation's
        return self.names[expr] if expr in self.names else super()._print_Symbol(expr)

    def _print_Function(self, expr):
        if isinstance(expr, AppliedUndef) and expr.func in self.names:
            return f"{self.names[expr.func]}({', '.join(self._print(a) for a in expr.args)})"
        return super()._print_Function(expr)


def defined_functions(exprs) -> set:
    """The function classes of the derivation's own (a SymPy ``Function`` subclass defined outside SymPy,
    as Euler's Beta integral ``Ib``) the expressions apply."""
    out = set()
    for e in exprs:
        if isinstance(e, (sp.Basic, sp.MatrixBase)):
            out |= {type(a) for a in e.atoms(sp.Function)
                    if not isinstance(a, AppliedUndef) and not type(a).__module__.startswith("sympy.")}
    return out


def _free_names(node) -> set:
    """The names *node* reads that it does not bind itself (its arguments and assignments are its own)."""
    if isinstance(node, ast.Assign):
        return {n.id for n in ast.walk(node.value) if isinstance(n, ast.Name)}
    read = {n.id for n in ast.walk(node) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}
    bound = {n.id for n in ast.walk(node) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
    bound |= {a.arg for n in ast.walk(node) if isinstance(n, ast.arguments)
              for a in (*n.posonlyargs, *n.args, *n.kwonlyargs, n.vararg, n.kwarg) if a is not None}
    return read - bound


def bound_names(source: str) -> set:
    """The names the top-level statements of *source* bind."""
    out = set()
    for node in ast.parse(source).body:
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            out |= {a.asname or a.name.split(".")[0] for a in node.names}
        elif isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            out.add(node.name)
        elif isinstance(node, ast.Assign):
            out |= {n.id for t in node.targets for n in ast.walk(t) if isinstance(n, ast.Name)}
    return out


def definitions_source(classes) -> str | None:
    """The source that defines *classes* in a notebook: the statements of their modules they need (SymPy
    imports, functions, classes, assignments), followed name by name and kept in the modules' order;
    ``None`` when they need an import from anything but SymPy."""
    chosen = {}
    for module in sorted({inspect.getmodule(c) for c in classes}, key=lambda m: m.__name__):
        text = inspect.getsource(module)
        body = ast.parse(text).body
        defines = {}
        for node in body:
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                for alias in node.names:
                    defines[alias.asname or alias.name.split(".")[0]] = node
            elif isinstance(node, (ast.FunctionDef, ast.ClassDef)):
                defines[node.name] = node
            elif isinstance(node, ast.Assign):
                for target in node.targets:
                    for n in ast.walk(target):
                        if isinstance(n, ast.Name):
                            defines[n.id] = node
        todo = [c.__name__ for c in classes if inspect.getmodule(c) is module]
        seen = set()
        while todo:
            name = todo.pop()
            if name in seen or name not in defines:
                continue
            seen.add(name)
            node = defines[name]
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                root = node.module if isinstance(node, ast.ImportFrom) else node.names[0].name
                if (root or "").split(".")[0] != "sympy":
                    return None
            chosen[(module.__name__, node.lineno)] = ast.get_source_segment(text, node)
            todo += sorted(_free_names(node))
    imports = [src for _, src in sorted(chosen.items()) if src.startswith(("import ", "from "))]
    rest = [src for _, src in sorted(chosen.items()) if not src.startswith(("import ", "from "))]
    return "\n".join(imports) + "\n\n\n" + "\n\n\n".join(rest) + "\n"


def functions_of(exprs) -> set:
    """The undefined functions (``Y(y)``) the expressions apply."""
    out = set()
    for e in exprs:
        if isinstance(e, sp.Basic):
            out |= {a.func for a in e.atoms(AppliedUndef)}
    return out


# ---- a small point inside the assumptions ------------------------------------------------------------------------
@functools.lru_cache(maxsize=None)
def _candidates(lo, hi) -> tuple:
    """Rationals of small denominator strictly inside (lo, hi), the simplest and most central first
    (remembered: every small point searches the same intervals)."""
    lo, hi = Fraction(str(lo)), Fraction(str(hi))
    mid = (lo + hi) / 2
    out = set()
    for q in (1, 2, 3, 4, 5, 6, 8, 10):
        for p in range(int(lo * q) - 1, int(hi * q) + 2):
            x = Fraction(p, q)
            if lo < x < hi:
                out.add(x)
    return tuple(sorted(out, key=lambda x: (x.denominator, abs(x - mid), x))[:6])


def _indices(sizes: list[int], total: int):
    """Every tuple of indices below *sizes* that sums to *total*, in lexicographic order."""
    if not sizes:
        if total == 0:
            yield ()
        return
    for first in range(min(sizes[0] - 1, total), -1, -1):
        for rest in _indices(sizes[1:], total - first):
            yield (first, *rest)


def small_point(symbols, domain, accept, tries: int = 1500):
    """A point of small rationals inside *domain* (:class:`~symfloat.engine.identity.Domain`) for
    *symbols*, distinct values where it can, at which ``accept(point)`` holds; ``None`` if none is found
    among the first *tries* candidates (ordered by how simple they are).  The symbols a constraint ties
    to *symbols* are drawn too, so that the point keeps the constraint, and left out of the answer."""
    own = set(symbols)
    symbols = set(symbols)
    for c in domain.constraints:
        if sp.sympify(c).free_symbols & symbols:
            symbols |= sp.sympify(c).free_symbols
    symbols = sorted(symbols, key=lambda s: s.name)
    if any(s not in domain.intervals for s in symbols):
        return None
    lists = [_candidates(*domain.intervals[s]) for s in symbols]
    if any(not c for c in lists):
        return None
    combos = itertools.chain.from_iterable(_indices([len(c) for c in lists], total)
                                           for total in range(sum(len(c) - 1 for c in lists) + 1))
    for n, idx in enumerate(combos):
        if n >= tries:
            break
        values = [lists[i][j] for i, j in enumerate(idx)]
        point = {s: sp.Rational(v.numerator, v.denominator) for s, v in zip(symbols, values)}
        if len(set(values)) < len(values) and n < tries // 2:      # distinct values first: no coincidence
            continue
        if domain.admits(point) and accept(point):
            return {k: v for k, v in point.items() if k in own}
    return None


def agree(a, b) -> bool:
    """Do the values *a*, *b* agree: exactly when rational, else to the sampling's relative tolerance
    at :data:`~symfloat.engine.identity.DIGITS` digits (as :mod:`symfloat.engine.identity` samples)."""
    pairs = list(zip(a, b)) if isinstance(a, sp.MatrixBase) else [(a, b)]
    for x, y in pairs:
        if x.is_Rational and y.is_Rational:
            if x != y:
                return False
            continue
        vx, vy = sp.N(x, DIGITS), sp.N(y, DIGITS)
        if not (vx.is_number and vy.is_number) or vx.has(sp.zoo, sp.nan, sp.oo):
            return False
        if abs(vx - vy) > AGREEMENT * max(abs(vx), abs(vy), 1):
            return False
    return True


def finite(v) -> bool:
    """Is *v* (a number or a matrix of numbers) finite and real?"""
    entries = list(v) if isinstance(v, sp.MatrixBase) else [v]
    for x in entries:
        if not getattr(x, "is_number", False):
            return False
        n = sp.N(x, 20)
        if n.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or not n.is_real:
            return False
    return True


def point_source(code: Code, point: dict) -> str:
    """``{b: 2, s: Rational(1, 3)}``: a point as SymPy source."""
    return "{" + ", ".join(f"{code.names[s]}: {code.source(v)}" for s, v in point.items()) + "}"
