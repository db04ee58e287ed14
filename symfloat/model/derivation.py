"""Derivations: ordered steps from stated assumptions to results.

A derivation module builds one :class:`Derivation` at import time; building
only assembles SymPy objects, the engine does all the checking.
"""
from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp

from ..manifest import PROVIDED_KINDS
from .claim import Eq, members
from .erratum import Erratum
from .prediction import Predictor
from .relation import is_relation
from .source import get_source
from .vocabulary import quantity_named, verdict_named, vocabulary

__all__ = ["Step", "Printed", "Derivation", "JUSTIFICATIONS", "PRINTED_DIGITS", "printed_tolerance"]

JUSTIFICATIONS = (
    "definition",      # introduces a quantity or the body: not checked, stated
    "algebra",         # rearrangement; checked as an identity
    "substitution",    # an earlier result or value inserted; checked as an identity
    "integration",     # an integral evaluated; checked as an identity
    "geometry",        # a geometric fact computed in coordinates; checked as an identity
    "lemma",           # a result of another derivation applied; checked as an identity
    "limit",           # a limit taken; checked as an identity
    "series",          # a series to a given order; checked as an identity
)


@dataclass(frozen=True)
class Step:
    """One step: a claim, why it holds, and what it uses.

    ``result`` names the quantity (a SymPy symbol) whose value the step
    establishes: its last member is substituted for that symbol when printed
    formulas are checked.
    """

    name: str
    claim: object
    why: str
    uses: tuple[str, ...] = ()
    note: str = ""
    result: sp.Symbol | None = None

    def __post_init__(self):
        if self.why not in JUSTIFICATIONS:
            raise ValueError(f"step {self.name!r}: justification {self.why!r} not in {JUSTIFICATIONS}")
        members(self.claim)


@dataclass(frozen=True)
class Printed:
    """A printed formula: the verbatim excerpt and its reading as printed.

    ``reading`` is the SymPy claim as printed, faults included, or ``None``
    when the print cannot be read as a formula (then ``unreadable`` says why)
    or when the transcription lost it (then ``lost`` says what is missing).
    ``tolerance`` marks a printed *number* (a worked example): the reading
    then holds when its members, closed numbers, agree within the tolerance
    (half a unit of the last printed digit); a correction uses the same one.
    Write it as :data:`PRINTED_DIGITS` and :meth:`Derivation.quote` takes it
    from the decimal numbers of the excerpt (:func:`printed_tolerance`).

    Three declarations for the check of the reading against the automatic one
    (:mod:`symfloat.report.readings`), each with its reason: ``symbols``, triples
    ``(printed TeX, the derivation's symbol or expression, why)`` (the print's
    ``x`` is the module's ``X``); ``condition``, why the printed ``A = B`` is a
    condition imposed, read as the identity it is imposed on; ``not_compared``,
    why the automatic reading cannot be compared (an assignment, an instruction).
    """

    name: str
    locator: str
    excerpt: str
    reading: object = None
    erratum: Erratum | None = None
    unreadable: str = ""
    lost: str = ""
    note: str = ""
    tolerance: object = None
    symbols: tuple = ()
    condition: str = ""
    not_compared: str = ""

    def __post_init__(self):
        if self.reading is None and not (self.unreadable or self.lost):
            raise ValueError(f"printed {self.name!r}: no reading, and no reason why")
        if any(len(b) != 3 or not (isinstance(b[0], str) and b[0] and isinstance(b[2], str) and b[2])
               for b in self.symbols):
            raise ValueError(f"printed {self.name!r}: a declared symbol is (printed TeX, symbol or expression, why)")
        if self.unreadable and self.erratum is None:
            raise ValueError(f"printed {self.name!r}: unreadable print needs an erratum")


PRINTED_DIGITS = "printed digits"
_DECIMAL = re.compile(r"(?<![\d,])(\d+),(\d+)(?![\d,]*\d)")     # 0,7735 (the decimal comma of the print)


def printed_tolerance(excerpt: str, reading) -> sp.Rational:
    """Half a unit of the last digit of the printed decimals of *excerpt* that *reading* states,
    the largest if several: ``0,7735`` -> 1/20000.

    >>> printed_tolerance(r"$> 0,2265$", (sp.Symbol("s"), sp.Rational("0.2265")))
    1/20000
    """
    values = {m for m in members(reading) if isinstance(m, sp.Rational)}
    halves = [sp.Rational(1, 2 * 10 ** len(frac)) for whole, frac in _DECIMAL.findall(excerpt)
              if sp.Rational(f"{whole}.{frac}") in values]
    if not halves:
        raise ValueError(f"no decimal number of the excerpt {excerpt[:60]!r} is a member of the reading: "
                         f"give the tolerance explicitly")
    return max(halves)




@dataclass(frozen=True)
class Report:
    """A document a derivation adds to the main job's output: ``docs/<filename>``, rewritten only when
    ``stamp()`` (a line naming what it depends on) differs from the stamp in the committed file;
    ``build(progress)`` returns its Markdown, stamp included."""

    filename: str
    stamp: Callable[[], str]
    build: Callable[..., str]


@dataclass(frozen=True)
class Figure:
    """A picture of the main job, ``docs/figures/<filename>`` (PNG): ``draw(*data)`` gets the JSON files
    ``data`` (paths under ``docs/``, written by a :class:`Report` or the phase diagrams) parsed and returns
    a Matplotlib figure; ``code`` are the source files that decide its look (with the data, its
    fingerprint); ``caption(*data)`` is the site's caption under ``title``."""

    filename: str
    data: tuple[str, ...]
    draw: Callable[..., object]
    code: tuple = ()
    title: str = ""
    caption: Callable[..., str] | None = None


@dataclass
class Derivation:
    """An ordered derivation of the printed formulas of one source section.

    ``domain`` maps each free symbol to the rational interval ``(lo, hi)``
    its sampled values are drawn from; ``constraints`` are SymPy relations
    the samples must satisfy in addition (the stated assumptions).
    """

    id: str
    source: str
    title: str
    locator: str
    summary: str = ""
    requires: tuple[str, ...] = ()
    domain: dict = field(default_factory=dict)
    constraints: tuple = ()
    assumptions: tuple[str, ...] = ()
    steps: list[Step] = field(default_factory=list)
    printed: list[Printed] = field(default_factory=list)
    witnesses: list = field(default_factory=list)
    predictor: Predictor | None = None
    names: list = field(default_factory=list)
    provided: dict = field(default_factory=dict)
    definitions: dict = field(default_factory=dict)

    def __post_init__(self):
        get_source(self.source)

    # -- builders used by the derivation modules --------------------------
    def step(self, name, claim, why, uses=(), note="", result=None) -> Step:
        """Append a step; ``uses`` must name earlier steps or ``derivation-id:step``."""
        known = {s.name for s in self.steps}
        for u in uses:
            if ":" not in u and u not in known:
                raise ValueError(f"step {name!r} uses {u!r}, which is not an earlier step")
        if name in known:
            raise ValueError(f"duplicate step name {name!r} in {self.id}")
        s = Step(name, claim, why, tuple(uses), note, result)
        self.steps.append(s)
        return s

    def solve(self, name, equation, unknown, result, pick=0, uses=(), note="", **options) -> Step:
        """A solve-and-check pair of steps.  ``result`` is established as a solution of ``equation`` (an
        :func:`~symfloat.model.claim.Eq`) for ``unknown``, found by ``sp.solve(equation, unknown, **options)``
        (``pick``: an index into its solutions, or a function of the list returning one): a definition,
        since the solver is not the proof.  The step ``<name>-check`` is the proof: the solution put back,
        ``Subs(lhs - rhs, unknown, result) = 0``, checked as an identity like any algebra step."""
        solutions = sp.solve(equation, unknown, **options)
        if not solutions:
            raise ValueError(f"step {name!r}: sp.solve finds no solution of {equation} for {unknown}")
        chosen = pick(solutions) if callable(pick) else solutions[pick]
        first = self.step(name, Eq(result, chosen), "definition", uses=uses, result=result,
                          note=note or f"a solution of {equation} for {unknown} (sympy.solve)")
        self.step(f"{name}-check", (sp.Subs(equation.lhs - equation.rhs, unknown, result), 0), "algebra",
                  uses=(name,), note="the solution of the step before put back into its equation")
        return first

    def quote(self, name, locator, excerpt, reading=None, erratum=None, unreadable="", lost="", note="",
              tolerance=None, symbols=None, condition="", not_compared=""):
        """Append a printed formula; the excerpt must be verbatim in the source.  *symbols* maps a printed
        letter (TeX, as in the excerpt) to ``(the derivation's symbol or expression, why)``."""
        if not get_source(self.source).contains(excerpt):
            raise ValueError(f"{self.id}/{name}: excerpt is not verbatim in {self.source}: {excerpt[:60]!r}")
        if any(p.name == name for p in self.printed):
            raise ValueError(f"duplicate printed name {name!r} in {self.id}")
        if erratum is not None and erratum.fault and erratum.fault not in excerpt:
            raise ValueError(f"{self.id}/{name}: the erratum's fault {erratum.fault!r} is not in its excerpt")
        if tolerance == PRINTED_DIGITS:
            tolerance = printed_tolerance(excerpt, reading)
        bound = tuple((tex, *target) for tex, target in (symbols or {}).items())
        p = Printed(name, locator, excerpt, reading, erratum, unreadable, lost, note, tolerance, bound, condition,
                    not_compared)
        self.printed.append(p)
        return p

    def defines(self, quantity, definition):
        """Tie *quantity* of the source's vocabulary (:mod:`symfloat.model.vocabulary`) to the formula that
        defines it here: a result symbol or an expression of them.  A sentence that names the quantity is
        read from it (:meth:`says`)."""
        known = vocabulary()[self.source]["quantities"]
        if quantity not in known:
            raise ValueError(f"{self.id}: {quantity!r} is not a quantity of {self.source}'s vocabulary; "
                             f"known: {', '.join(known)}")
        if quantity in self.definitions:
            raise ValueError(f"{self.id}: {quantity!r} is defined twice")
        self.definitions[quantity] = sp.sympify(definition)
        return self.definitions[quantity]

    def reads(self, words, statement):
        """The reading of a sentence whose *words* name a quantity (or, for a verdict, the equilibrium's
        stability) and say *statement* of it, built from the quantity's definition in this derivation."""
        if getattr(statement, "verdicts", False):
            quantity, verdict = "stability", verdict_named(self.source, words)
        else:
            quantity, verdict = quantity_named(self.source, words), None
        if quantity not in self.definitions:
            raise ValueError(f"{self.id}: the words {words!r} name the {quantity}, which this derivation does "
                             f"not define (Derivation.defines)")
        q = self.definitions[quantity]
        results = self.results()

        def derived(expr):
            for _ in range(len(results) + 1):
                done = expr.xreplace(results)
                if done == expr:
                    break
                expr = done
            return expr
        return statement.reading(q, derived, verdict) if verdict else statement.reading(q, derived)

    def says(self, name, locator, excerpt, words, statement, erratum=None, note="", **options):
        """Quote a sentence whose *words* (verbatim in *excerpt*) name a quantity and say *statement* of it
        (:mod:`symfloat.model.vocabulary`): its reading is built from the quantity's definition, so the
        words, not a hand-typed formula, decide what the engine checks."""
        if words not in excerpt:
            raise ValueError(f"{self.id}/{name}: the words {words!r} are not in the excerpt")
        if getattr(statement, "verdicts", False):
            meaning = vocabulary()[self.source]["quantities"]["stability"]["meaning"]
            said = (f"'{words}' calls the equilibrium {verdict_named(self.source, words)}: the sentence is read "
                    f"from the sign of {meaning}. ")
        else:
            meaning = vocabulary()[self.source]["quantities"][quantity_named(self.source, words)]["meaning"]
            said = f"'{words}' names {meaning}; the sentence is read from its definition. "
        return self.quote(name, locator, excerpt, reading=self.reads(words, statement), erratum=erratum,
                          note=said + note, **options)

    def name(self, symbol, value, text=""):
        """Name a helper expression (a vector, a triple product) for display: the notebook
        shows ``symbol = value`` once and writes *value* by its name wherever a claim
        contains it.  Display only: the engine checks the claims as built."""
        if any(symbol == s for s, _, _ in self.names):
            raise ValueError(f"duplicate name {symbol} in {self.id}")
        self.names.append((symbol, value, text))
        return symbol

    def witness(self, w):
        """Attach a first-principles witness (see :mod:`symfloat.engine.witness`)."""
        names = {p.name for p in self.printed}
        missing = [t for t in w.targets if t not in names]
        if missing:
            raise ValueError(f"witness {w.name!r} targets unknown printed formulas {missing}")
        tables = [p.name for p in self.printed if p.name in w.targets and is_relation(p.reading)
                  and p.reading.indicators() is None]
        if tables:
            raise ValueError(f"witness {w.name!r} targets case tables {tables}: the relation check samples them")
        self.witnesses.append(w)
        return w

    def predicts(self, bodies, predict):
        """Register ``predict(scene) -> [Prediction]`` for scenes of ``bodies`` (see
        :mod:`symfloat.model.prediction`); each prediction names printed formulas of this module."""
        if self.predictor is not None:
            raise ValueError(f"{self.id} already has a predictor")
        self.predictor = Predictor(tuple(bodies), predict)
        return self.predictor

    def provides(self, kind, value):
        """Hand the library something it reads from this derivation; the library knows no derivation
        by name, it asks the registry which modules provide a *kind* (read from the literal
        ``provides("kind", ...)`` in their source) and imports only those.  Kinds:

        * ``"thresholds"``: names of result symbols that are closed-form densities (a phase diagram
          names a threshold it finds by the closed form it meets);
        * ``"forms"``: a function returning closed forms for the float64 study
          (:class:`symfloat.numerics.forms.Form`);
        * ``"report"``: a :class:`Report`, a document the main job writes beside the record;
        * ``"figure"``: a :class:`Figure`, a picture the main job draws from such a document;
        * ``"tables"``: a function ``(ratio, s) -> prediction`` of printed case tables of the long
          rectangular box (the atlas compares its long cells with them)."""
        if kind not in PROVIDED_KINDS:
            raise ValueError(f"{self.id}: unknown kind {kind!r}; known: {', '.join(PROVIDED_KINDS)}")
        self.provided.setdefault(kind, []).append(value)
        return value

    # -- queries ----------------------------------------------------------
    def get_step(self, name) -> Step:
        for s in self.steps:
            if s.name == name:
                return s
        raise KeyError(f"{self.id} has no step {name!r}")

    def get_printed(self, name) -> Printed:
        for p in self.printed:
            if p.name == name:
                return p
        raise KeyError(f"{self.id} quotes no printed formula {name!r}")

    def evaluator(self, name, symbols, member, corrected=False, row=None):
        """Member *member* (its component *row*, for a matrix) of the reading of printed formula *name* (of
        its correction, with *corrected*), derived quantities replaced by their derived values, as a
        function of *symbols*: exact (a SymPy number) when every argument is exact (int, Fraction, a
        SymPy number such as a Rational or sqrt(2)), a SymPy expression when an argument holds a symbol (a
        predictor solving for it), in mpmath when one is an mpmath number, elementwise for NumPy arrays,
        else a float.  A predictor decides with the readings the print is checked by instead of typing them
        again, so a reading that changes changes the prediction (tests/test_predictors_read.py)."""
        p = self.get_printed(name)
        reading = p.erratum.corrected_reading if corrected else p.reading
        if reading is None:
            raise ValueError(f"{self.id}/{name}: no {'corrected ' if corrected else ''}reading to evaluate")
        expr = sp.sympify(members(reading)[member])
        if row is not None:
            expr = expr[row]
        results = self.results()
        for _ in range(len(results) + 1):                       # derived values may use derived values
            done = expr.xreplace(results)
            if done == expr:
                break
            expr = done
        expr = expr.replace(lambda e: isinstance(e, sp.Subs), lambda e: e.doit())
        symbols = tuple(symbols)
        free = expr.free_symbols - set(symbols)
        if free:
            raise ValueError(f"{self.id}/{name}: member {member} depends on {sorted(map(str, free))} as well")
        rows = list(expr) if isinstance(expr, sp.MatrixBase) else None
        target = rows if rows is not None else expr
        compiled = {}

        def numeric(kind, args):
            if kind not in compiled:
                compiled[kind] = sp.lambdify(symbols, target, kind)
            v = compiled[kind](*args)
            return tuple(v) if rows is not None else v

        def value(*args):
            if all(isinstance(x, (int, Fraction, sp.Expr)) for x in args):   # exact, or symbolic in SymPy symbols
                at = {q: sp.Rational(x.numerator, x.denominator) if isinstance(x, Fraction) else sp.sympify(x)
                      for q, x in zip(symbols, args)}
                return tuple(r.xreplace(at) for r in rows) if rows is not None else expr.xreplace(at)
            if any(type(x).__module__.startswith("mpmath") for x in args):
                return numeric("mpmath", args)
            if any(type(x).__module__ == "numpy" and getattr(x, "ndim", 0) for x in args):
                return numeric("numpy", args)
            return numeric("math", tuple(float(x) for x in args))
        return value

    def results(self) -> dict:
        """Quantity symbol -> derived value, from the steps that establish results."""
        return {s.result: members(s.claim)[-1] for s in self.steps if s.result is not None}

    def formula_id(self, printed: Printed) -> str:
        return f"{self.id}/{printed.name}"
