"""The code cells of a derivation notebook: each step and each printed formula in plain SymPy.

A step's cell states its chain of members (:class:`~symfloat.report.notebook_code.Code`), puts in
the values earlier steps established (``insert``), runs the strategy of the step's proof
certificate on the difference of each link and asserts that it gives 0, evaluates the members at a
small rational point inside the assumptions and, for a step that establishes a quantity, records
its value in ``derived``.  A link the engine confirmed by sampling only is asserted at that point;
a printed formula the engine refuted is shown at a small point where its members differ, both
values printed, and its correction is checked like a step.  The notebook runs with SymPy alone:
a changed member that no longer holds stops it with an ``AssertionError``.  A step whose expressions
no SymPy source states (a function the derivation defines itself, as Euler's Beta integrals) gets a
comment instead, and so does every later step and reading that needs its value: the kernel has no
value for it, and the engine's check in the Markdown above stands.
"""
from __future__ import annotations

import re
import textwrap

import sympy as sp

from ..engine.identity import Domain
from ..model.claim import identical_links, members
from ..model.relation import is_relation
from .notebook_code import HELPERS, STRATEGY_WORDS, Code, agree, bound_names, defined_functions, \
    definitions_source, finite, functions_of, point_source, proof_source, small_point, strategy_helper

__all__ = ["CellWriter"]


def _expressions(d) -> list:
    """Every SymPy object the notebook states: members of steps, readings and corrections, conditions of
    relations."""
    out = []
    for s in d.steps:
        out += list(members(s.claim))
    for p in d.printed:
        for reading in (p.reading, p.erratum.corrected_reading if p.erratum is not None else None):
            if reading is None:
                continue
            out += list(reading.parts() if is_relation(reading) else members(reading))
    return out


def _symbols(exprs) -> set:
    """The symbols of *exprs*, without the direction of a limit (a symbol ``+`` to SymPy)."""
    found = set()
    for e in exprs:
        if isinstance(e, (sp.Basic, sp.MatrixBase)):
            found |= e.atoms(sp.Symbol) - {lim.args[3] for lim in e.atoms(sp.Limit)}
    return found


class CellWriter:
    """The SymPy source of the cells of one derivation's notebook, from the derivation *d* and the
    engine's *report* on it (which link each proof certificate proves, and how).  Steps must be asked
    for in order: each step's value enters ``derived`` as in the notebook."""

    def __init__(self, d, report):
        self.d, self.report = d, report
        exprs = _expressions(d)
        preferred = {s.result: s.name.replace("-", "_") for s in d.steps
                     if s.result is not None and not s.result.name.isidentifier()}
        symbols, functions = _symbols(exprs) | set(d.domain), functions_of(exprs)
        defined = defined_functions(exprs)
        self.definitions = definitions_source(defined) if defined else ""
        self.code = Code(symbols, functions, preferred, defined if self.definitions else ())
        if self.definitions and bound_names(self.definitions) & (set(self.code.names.values())
                                                                 | set(self.code.functions.values())):
            self.definitions = None        # they would rebind a name of the notebook's: not stated
        if not self.definitions:
            self.code = Code(symbols, functions, preferred)
        self.domain = Domain(d.domain, tuple(d.constraints))
        self.derived: dict = {}
        self.missing: dict = {}     # symbol -> the number of the step that established it without SymPy source
        self.number = {st.name: i for i, st in enumerate(d.steps, 1)}
        self.calls: set = set()     # the SymPy functions the checks call
        self.helpers: dict = {}     # strategy -> the definition its proofs call (``pythagoras``)
        self._values: dict = {}     # (value, point) -> the value at the point (:meth:`at`)

    # -- the notebook's helpers, mirrored at build time --------------------------------------------------------------
    def insert(self, expr):
        """*expr* with the values established so far put in, as the notebook's ``insert`` puts them in, but
        its integrals, limits and derivatives not carried out: they are carried out at a point
        (:meth:`at`), where they are integrals of numbers, not symbolic ones."""
        for _ in range(12):
            new = expr.xreplace(self.derived)
            if new == expr:
                break
            expr = new
        return expr

    def at(self, value, point: dict):
        """*value* (from :meth:`insert`) at *point*, carried out: the notebook's ``at`` before its rounding,
        remembered (the point search tries a value at the same points for several links).  Limits are taken
        first (a limit's variable is no symbol to put a number in for), then the point is put in."""
        key = (value.as_immutable() if isinstance(value, sp.MatrixBase) else value,
               tuple(sorted(point.items(), key=lambda kv: kv[0].name)))
        if key not in self._values:
            if value.has(sp.Limit):
                value = value.replace(lambda e: isinstance(e, sp.Limit), lambda e: e.doit())
            self._values[key] = value.subs(point).doit()
        return self._values[key]

    def setup(self) -> str:
        """The first code cell: SymPy's names the cells use, every symbol declared, the helpers."""
        used = sorted(self.code.used | self.calls | {"Symbol", "symbols", "Function", "MatrixBase", "evaluate",
                                                     "S", "N", "Rational"}
                      | ({"Dummy"} if any(isinstance(s, sp.Dummy) for s in self.code.names) else set()))
        names = textwrap.fill(", ".join(used), width=96, initial_indent="    ", subsequent_indent="    ")
        own = ("# the functions the derivation defines itself, as its package defines them (SymPy only)\n"
               + self.definitions + "\n\n") if self.definitions else ""
        return ("from sympy import (\n" + names + ",\n)\n" + own + "\n"
                + "# the symbols of the derivation, with the assumptions it states\n"
                + self.code.declarations() + "\n\n" + HELPERS
                + "".join("\n\n" + self.helpers[k] for k in sorted(self.helpers)))

    # -- one chain ---------------------------------------------------------------------------------------------------
    def _chain(self, ms, name: str = "chain") -> list[str]:
        """``chain = [...]`` (or *name*): the members as SymPy; a member that keeps the print's arithmetic is built
        under ``evaluate(False)`` first."""
        lines, shown = [], []
        kept = [(m, *self.code.member(m)) for m in ms]
        if any(not ok for _, _, ok in kept):
            lines.append("with evaluate(False):   # the print's arithmetic, kept as printed")
        n = 0
        for m, text, ok in kept:
            if ok:
                shown.append(text)
            else:
                n += 1
                lines.append(f"    as_printed_{n} = {text}")
                shown.append(f"as_printed_{n}")
        lines.append(f"{name} = [\n" + "".join(f"    {t},\n" for t in shown) + "]")
        return lines

    def _point(self, values, accept_pair=None):
        """A small point at which every value is finite (and *accept_pair* holds), or ``None``."""
        free = set()
        for v in values:
            free |= v.free_symbols
        if not free:
            return {}

        def accept(point):
            try:
                vs = [self.at(v, point) for v in values]
            except (ArithmeticError, TypeError, ValueError):
                return False
            return all(finite(v) for v in vs) and (accept_pair is None or accept_pair(vs))
        return small_point(free, self.domain, accept)

    def _links(self, ms, key: str, tolerance=None) -> tuple[list[str], list, list[int]]:
        """Check lines for each link of *ms* not identical as built (a proof certificate's strategy, or the
        printed precision), the values of the members, and the links that rest on sampling alone."""
        same = identical_links(ms)
        values = [self.insert(m) for m in ms]
        lines = ["values = [insert(e) for e in chain]"]
        matrix = any(isinstance(v, sp.MatrixBase) for v in values)
        sampled = []
        for i, _ in enumerate(zip(ms, ms[1:])):
            if same[i]:
                continue
            a, b = f"values[{i}]", f"values[{i + 1}]"
            label = "the difference" if len(ms) == 2 else f"member {i + 1} minus member {i + 2}"
            if tolerance is not None:
                lines.append(f"gap = abs(N({a} - {b}, 60))")
                lines.append(f"print({label!r} + ', at 60 digits:', gap.evalf(5), "
                             f"'(printed precision {tolerance})')")
                lines.append(f"assert gap <= {self.code.source(sp.sympify(tolerance))}")
                continue
            strategy = (self.report.proofs.get(f"{key}#{i}") or {}).get("strategy")
            if strategy:
                call = proof_source(strategy, a, b, matrix)
                self.calls |= {n for n in re.findall(r"([a-z]+)\(", call) if n in self.code.namespace}
                helper, names = strategy_helper(strategy)
                if helper:
                    self.helpers[strategy] = helper
                    self.calls |= names
                lines.append(f"proof = {call}")
                lines.append(f"print({label + ', ' + STRATEGY_WORDS[strategy] + ':'!r}, proof)")
                lines.append("assert proof.is_zero_matrix" if matrix else "assert proof == 0")
            else:
                sampled.append(i)
        return lines, values, sampled

    def _evaluation(self, values, sampled, lines):
        """The members at a small point; the links without a proof asserted there."""
        point = self._point(values, lambda vs: all(agree(vs[i], vs[i + 1]) for i in sampled))
        if point is None:
            if sampled:
                lines.append("# no small point inside the assumptions where every member is finite: "
                             "these links rest on the engine's sampling alone")
            return
        if not point:
            lines.append("print('the values:', at({}, *values))")
            return
        lines.append(f"point = {point_source(self.code, point)}   # inside the assumptions")
        lines.append("print('at', point, ':', at(point, *values))")
        for i in sampled:
            lines.append(f"left, right = at(point, values[{i}], values[{i + 1}])   # no symbolic proof: "
                         f"equal at the point")
            lines.append("assert same(left, right)")

    # -- the cells ---------------------------------------------------------------------------------------------------
    def step(self, s) -> str:
        """The code of step *s* (the next one in order).  A step whose expressions have no SymPy source that
        reads back (:meth:`Code.member`), or that needs the value of such a step, gets a comment that says so;
        the notebook's ``derived`` lacks its value, and the later cells that need it are comments too."""
        needs = self._needs_missing(members(s.claim))
        if needs:
            self._record(s, missing=True)
            return f"# this step needs {needs}: the engine's check is above"
        try:
            return self._step(s)
        except ValueError:
            self._record(s, missing=True)
            return f"# {self._unstated(members(s.claim), 'this step')}: the engine's check is above"

    def _needs_missing(self, exprs) -> str:
        """The values without SymPy source that *exprs* need (through the values established so far), in words,
        or ``""``."""
        found, seen = set(), set()
        todo = [e for e in exprs if isinstance(e, (sp.Basic, sp.MatrixBase))]
        while todo:
            e = todo.pop()
            for sym in _symbols([e]) - seen:
                seen.add(sym)
                if sym in self.missing:
                    found.add(sym)
                elif sym in self.derived:
                    todo.append(self.derived[sym])
        if not found:
            return ""
        ordered = sorted(found, key=lambda sym: self.missing[sym])
        return "the value" + ("s" if len(found) > 1 else "") + " of " + ", ".join(
            f"{self.code.names.get(sym, sym.name)} (step {self.missing[sym]})" for sym in ordered) \
            + ", which plain SymPy does not state here"

    @staticmethod
    def _unstated(exprs, what: str) -> str:
        """Why no SymPy source states *exprs*: the functions of the derivation's own they use, if any."""
        own = sorted({type(a).__name__ for e in exprs if isinstance(e, (sp.Basic, sp.MatrixBase))
                      for a in e.atoms(sp.Function) if not type(a).__module__.startswith("sympy")})
        if own:
            return (f"{what} uses {', '.join(own)}, defined by the derivation itself (not a function of SymPy's), "
                    "so no plain SymPy states it")
        return f"no SymPy source reads back as {what}'s expressions"

    def _step(self, s) -> str:
        rep = next(r for r in self.report.steps if r.name == s.name)
        ms = list(members(s.claim))
        name = self.code.names.get(s.result) if s.result is not None else None
        out = []
        if rep.status in ("definition", "applied"):
            what = ("a definition: stated, not checked" if rep.status == "definition"
                    else "a lemma applied: checked where the lemma is derived")
            if s.result is not None and ms[0] == s.result and len(ms) == 2:
                text, ok = self.code.member(ms[1])
                if ok:
                    out.append(f"derived[{name}] = {text}   # {what}")
                else:
                    out += ["with evaluate(False):   # the print's arithmetic, kept as printed",
                            f"    as_printed_1 = {text}", f"derived[{name}] = as_printed_1   # {what}"]
            else:
                out += self._chain(ms) + [f"# {what}"]
                if s.result is not None:
                    out.append(f"derived[{name}] = chain[-1]")
            out.append(f"print({name}, '=', insert(derived[{name}]))" if s.result is not None else "")
            self._record(s)
            return "\n".join(line for line in out if line)
        checked = [m for m in ms if not (s.result is not None and m == s.result)]
        out += self._chain(checked)
        links, values, sampled = self._links(checked, f"step {self.d.id}/{s.name}")
        out += links
        self._evaluation(values, sampled, out)
        if s.result is not None:
            out.append(f"derived[{name}] = chain[-1]   # the value this step establishes for {name}")
        self._record(s)
        return "\n".join(out)

    def _record(self, s, missing: bool = False):
        if s.result is not None:
            self.derived[s.result] = members(s.claim)[-1]
            if missing:
                self.missing[s.result] = self.number[s.name]

    def formula(self, p) -> str | None:
        """The code of printed formula *p*: its reading, the check of the print, the correction (a comment
        when its expressions have no SymPy source that reads back)."""
        readings = [r for r in (p.reading, p.erratum.corrected_reading if p.erratum is not None else None)
                    if r is not None]
        exprs = [e for r in readings for e in (r.parts() if is_relation(r) else members(r))]
        needs = self._needs_missing(exprs)
        if needs:
            return f"# this reading needs {needs}: the engine's check is above"
        try:
            return self._formula(p)
        except ValueError:
            return f"# {self._unstated(exprs, 'this reading')}: the engine's check is above"

    def _formula(self, p) -> str | None:
        f = next(f for f in self.report.formulas if f.id == self.d.formula_id(p))
        if p.reading is None or f.verdict == "trivial":
            return None
        key = f"printed {self.d.id}/{p.name}"
        if is_relation(p.reading):
            return self._relation(p.reading, f)
        out = ["# read as printed"] + self._chain(members(p.reading))
        if f.verdict == "erratum":
            out += self._refutation(list(members(p.reading)), p.tolerance, (f.identity or {}).get("counterexample"))
            corrected = p.erratum.corrected_reading if p.erratum is not None else None
            if corrected is not None and not is_relation(corrected):
                out += ["", "# the correction, checked as a step is"] + self._chain(members(corrected))
                links, values, sampled = self._links(list(members(corrected)), key + "#corrected", p.tolerance)
                out += links
                self._evaluation(values, sampled, out)
            return "\n".join(out)
        links, values, sampled = self._links(list(members(p.reading)), key, p.tolerance)
        out += links
        if f.verdict == "verified":
            self._evaluation(values, sampled, out)
        else:
            out.append(f"# {f.verdict}: {f.reason}")
            point = self._point(values)
            if point:
                out.append(f"point = {point_source(self.code, point)}")
                out.append("print('at', point, ':', at(point, *values))")
        return "\n".join(out)

    def _refutation(self, ms, tolerance, counterexample=None) -> list[str]:
        """A small point where two members of the refuted reading differ, both values shown; failing one,
        the engine's *counterexample* (its random point)."""
        values = [self.insert(m) for m in ms]
        free = set().union(*(v.free_symbols for v in values))
        engine = {s: sp.Rational(counterexample["point"][s.name]) for s in sorted(free, key=lambda s: s.name)
                  if counterexample and s.name in counterexample.get("point", {})}
        out = ["values = [insert(e) for e in chain]"]
        for i in range(len(ms) - 1):
            if tolerance is not None:
                gap = abs(sp.N(self.at(values[i] - values[i + 1], {}), 60))
                if gap.is_number and gap > sp.N(tolerance, 60):
                    return out + [f"print('member {i + 1}:', N(values[{i}], 15), '  member {i + 2}:', "
                                  f"N(values[{i + 1}], 15))",
                                  f"assert abs(N(values[{i}] - values[{i + 1}], 60)) > "
                                  f"{self.code.source(sp.sympify(tolerance))}   # the print is refuted"]
                continue
            point = self._point(values[i:i + 2], lambda vs: not agree(vs[0], vs[1]))
            where = "inside the assumptions"
            if point is None and len(engine) == len(free) and not agree(
                    *(self.at(v, engine) for v in values[i:i + 2])):
                point, where = engine, "the engine's random point: no small one shows the difference"
            if point is not None:
                return out + [f"point = {point_source(self.code, point)}   # {where}",
                              f"left, right = at(point, values[{i}], values[{i + 1}])",
                              f"print('at', point, ': member {i + 1} =', left, ', member {i + 2} =', right)",
                              "assert not same(left, right)   # the print is refuted"]
        return out + ["# no point found where two members differ: the erratum above says why the print is wrong"]

    def _relation(self, reading, f) -> str:
        lines = ["# the conditions the relation states; the engine's relation check decides it (see above)"]
        lines += self._chain(list(reading.parts()), "conditions")
        lines.append("print(conditions)")
        return "\n".join(lines)
