"""Checking one derivation: its steps, its printed formulas, its witnesses.

The verdict of a printed formula follows from three pieces of evidence:

* the identity check of its reading against the derivation's results
  (``verified`` when it holds, refuted when a sample disagrees); a reading
  whose members are identical as built checks nothing and is ``trivial``;
* the declared erratum, whose corrected reading must itself hold;
* the first-principles witnesses, which must agree with whatever is
  accepted as right and disagree with what is refuted.

Anything that contradicts the declarations — a refuted step, an undeclared
fault, a declared fault that is not there, a witness at odds with the
algebra — is a *failure*: it is reported with the locator and makes
``symfloat verify`` exit non-zero.
"""
from __future__ import annotations

import json
import time
from dataclasses import asdict, dataclass, field
from functools import cache, lru_cache
from importlib.resources import files

import fastjsonschema
import flint
import sympy as sp

from ..model.claim import as_latex, identical_links, members
from ..model.derivation import Derivation, Printed
from ..model.evidence_tex import shown_value, tex_error, tex_number, tex_point
from ..model.relation import is_relation
from .beta_integral import beta_closed
from .definitions import DefinitionRoute, route_readings
from .print_corrections import print_corrections, smallest_correction
from .identity import Domain, IdentityResult, check_identity, check_rounded
from .proof_words import PROOF_WORDS
from .proofs import ProofBook
from .relation import check_relation
from .witness import record_decision, undecided_reason

__all__ = ["StepReport", "FormulaReport", "DerivationReport", "check_derivation", "carried_out", "judge",
           "step_failure", "rejudged", "Unsound"]


@dataclass
class StepReport:
    name: str
    why: str
    uses: list
    latex: str
    note: str
    status: str                       # definition | applied | proved | sampled | refuted | undecided | trivial
    identity: dict | None = None


@dataclass
class FormulaReport:
    id: str
    source: str
    locator: str
    verdict: str                      # verified | erratum | unverifiable | trivial
    evidence: str | None
    numeric: list
    excerpt: str
    latex: str
    reason: str = ""
    identity: dict | None = None
    erratum: dict | None = None
    witness_notes: list = field(default_factory=list)
    corrected_numeric: list = field(default_factory=list)
    numeric_content: bool = True      # False: no witness measured it and the definition route found it a definition
    lost: str = ""                    # what the transcription lost of it
    corrected_identity: dict | None = None    # the check of the declared correction
    against: list = field(default_factory=list)             # witnesses at odds with the printed reading
    against_correction: list = field(default_factory=list)  # ... and with the declared correction


@dataclass
class DerivationReport:
    id: str
    source: str
    title: str
    locator: str
    key: str
    seconds: float
    steps: list
    formulas: list
    failures: list
    cached: bool = False
    proofs: dict = field(default_factory=dict)
    timing: dict = field(default_factory=dict)   # seconds by kind: sampling, proofs, witnesses, other

    def searched(self) -> list[str]:
        """The claims whose proof was searched in this check (no certificate for their present form)."""
        return [k for k, c in self.proofs.items() if c["how"] == "searched"]

    def certificates(self) -> dict:
        """Claim -> certificate, as :class:`~symfloat.engine.proofs.ProofBook` stores them."""
        return {k: {f: v for f, v in c.items() if f != "how"} for k, c in self.proofs.items()}

    def to_json(self) -> dict:
        return asdict(self)

    @classmethod
    def from_json(cls, data: dict) -> "DerivationReport":
        data = dict(data)
        data["steps"] = [StepReport(**s) for s in data["steps"]]
        data["formulas"] = [FormulaReport(**f) for f in data["formulas"]]
        return cls(**data)


def _substitute(expr, results):
    """Insert derived values for result symbols until none is left."""
    if not results:
        return expr
    for _ in range(12):
        new = expr.xreplace(results) if hasattr(expr, "xreplace") else expr
        if new == expr:
            return new
        expr = new
    return expr


def _evaluated(expr):
    """*expr* with its arithmetic carried out: a reading keeps the print's arithmetic
    unevaluated (``evaluate=False``, ``UnevaluatedExpr``) until it is compared.  A SymPy expression
    is carried out once (:func:`carried_out`): a printed formula's members are met again by the
    witnesses' readings, by the next link of a chain and by every edit the correction search tries."""
    if isinstance(expr, sp.Basic):
        return carried_out(expr)
    if isinstance(expr, sp.MatrixBase):         # a vector's components, each carried out once
        return expr.applyfunc(carried_out)
    return expr.doit() if hasattr(expr, "doit") else expr


@lru_cache(maxsize=8192, typed=True)
def carried_out(expr):
    """``expr.doit()``, once per expression (SymPy expressions are immutable and ``doit`` gives the same
    result every time); an integral over a quarter of a circle or an ellipse closed by the Beta function first
    (:func:`~symfloat.engine.beta_integral.beta_closed`: SymPy takes a third of a second for each)."""
    if expr.has(sp.Integral):
        expr = expr.replace(lambda e: isinstance(e, sp.Integral), lambda e: beta_closed(e) or e)
    return expr.doit()


def _resolved(chain, results, closed=None):
    """The chain with derived values inserted for the result symbols, every defining integral
    of *closed* replaced by its derived closed form (witnesses never integrate it again), evaluated."""
    return tuple(_evaluated(_substitute(m, results).xreplace(closed or {})) for m in members(chain))


def _check_chain(chain, names, results, domain, seed, book, proofs, tolerance=None, prove=True,
                 timing=None, kind="printed") -> IdentityResult:
    """Check every link of a chain; the weakest link decides.  With a
    *tolerance* the links are closed numbers compared to printed precision.
    Each link's proof certificate comes from (or is searched for) *book*, under
    the key ``"<kind> <seed>#<link>"`` (*kind*: ``step`` or ``printed``, as a
    step and a printed formula may share a name); the certificates used are
    collected in *proofs*.

    A link whose two members are identical as built (before the derived values are
    inserted) is not checked: it holds by construction.  A chain of such links only
    is ``trivial``."""
    ms = [m for m in members(chain) if not (isinstance(m, sp.Symbol) and m in names)]
    if len(ms) < 2:
        raise ValueError(f"{seed}: nothing to check once the named quantity is removed")
    same = identical_links(ms)
    if all(same):
        return IdentityResult("trivial", tried=["none: the members are identical as built"])
    t0 = time.perf_counter()
    ms = [_evaluated(_substitute(m, results)) for m in ms]
    if timing is not None:
        timing["evaluation"] += time.perf_counter() - t0
    order = {"refuted": 0, "undecided": 1, "agrees": 2, "sampled": 2, "proved": 3}
    worst = None
    total = 0.0
    for i, (a, b) in enumerate(zip(ms, ms[1:])):
        if same[i]:
            continue
        claim = f"{kind} {seed}#{i}"
        r = (check_rounded(a, b, tolerance, f"{seed}#{i}") if tolerance is not None else
             check_identity(a, b, domain, f"{seed}#{i}", prove=prove, book=book, claim=claim))
        if r.certificate is not None:
            proofs[claim] = {"how": r.proof, **r.certificate}
        if timing is not None:
            timing["proofs"] += r.proof_seconds
            timing["sampling"] += r.seconds - r.proof_seconds
        total += r.seconds
        if worst is None or order[r.status] < order[worst.status]:
            worst = r
        if r.status == "refuted":
            break
    worst.seconds = total
    worst.tried += [f"link {i + 1} not checked: its members are identical as built"
                    for i, t in enumerate(same) if t]
    return worst


def _relation(reading, results, domain, seed, timing) -> IdentityResult:
    """A relation's check (:mod:`symfloat.engine.relation`), its time counted as sampling or proof."""
    r = check_relation(reading, results, domain, seed)
    timing["proofs" if r.status == "proved" else "sampling"] += r.seconds
    return r


def _latex(p: Printed) -> str:
    return as_latex(p.reading) if p.reading is not None else ""


def check_derivation(d: Derivation, key: str = "", *, book: ProofBook | None = None, prove: bool = True,
                     trust_steps: bool = False, progress=None) -> DerivationReport:
    """Check *d* completely and return its report (see the module docstring).

    Proofs replay the certificates of *book* (by default the derivation's
    committed ones); a claim without one is searched.  ``prove=False`` stops at
    sampling (mutation tests, where only refutation matters); ``trust_steps``
    takes the steps as checked and judges the printed formulas alone (mutation
    tests of a printed formula, whose steps the full check covers)."""
    t0 = time.perf_counter()
    # FLINT keeps pi and its quadrature nodes at the highest precision asked so far and rounds later requests
    # from them: emptied, so that a derivation's enclosures do not depend on what the process computed before
    flint.ctx.cleanup()
    book = book if book is not None else ProofBook.load(d.id)
    domain = Domain(d.domain, tuple(d.constraints))
    from ..registry import cross_use_problems       # the registry imports the derivations: only when checking
    failures: list[str] = [f"{d.source} {d.locator}: {m}" for m in cross_use_problems(d)]
    proofs: dict = {}
    results: dict = {}
    closed: dict = {}       # a defining integral -> its closed form, once an integration step derived it
    # seconds by kind: carrying out the claims' integrals, derivatives and sums (evaluation), sampling the
    # links, replaying or searching their proofs, the witnesses
    timing = {"evaluation": 0.0, "sampling": 0.0, "proofs": 0.0, "witnesses": 0.0}
    step_reports = []
    for s in d.steps:
        names = {s.result} if s.result is not None else set()
        checkable = len([m for m in members(s.claim) if not (isinstance(m, sp.Symbol) and m in names)]) >= 2
        if s.why == "definition" or (s.why == "lemma" and not checkable) or trust_steps:
            status = "definition" if s.why == "definition" else "applied" if s.why == "lemma" else "trusted"
            rep = StepReport(s.name, s.why, list(s.uses), as_latex(s.claim), s.note, status)
        else:
            r = _check_chain(s.claim, names, results, domain, f"{d.id}/{s.name}", book, proofs, prove=prove,
                             timing=timing, kind="step")
            rep = StepReport(s.name, s.why, list(s.uses), as_latex(s.claim), s.note, r.status, r.to_json())
            if step_failure(rep):
                failures.append(f"{d.source} {d.locator}: {step_failure(rep)}")
        if s.result is not None:
            results[s.result] = _substitute(members(s.claim)[-1], results)
        first, last = members(s.claim)[0], members(s.claim)[-1]
        if s.why == "integration" and isinstance(first, sp.Symbol) and first in results \
                and results[first].has(sp.Integral) \
                and rep.status in ("proved", "sampled", "trusted") and not last.has(sp.Integral):
            closed[results[first]] = _substitute(last, results)
        step_reports.append(rep)
        if progress:
            progress()

    readings, identities, corrected = {}, {}, {}
    for p in d.printed:      # witnesses evaluate closed forms, never a defining integral again
        if is_relation(p.reading):
            identities[p.name] = _relation(p.reading, results, domain, f"{d.id}/{p.name}", timing)
            if p.reading.indicators() is not None:       # what a witness measuring a truth compares with
                readings[p.name] = _resolved(p.reading.indicators(), results, closed)
        elif p.reading is not None:
            t0 = time.perf_counter()
            readings[p.name] = _resolved(p.reading, results, closed)
            timing["evaluation"] += time.perf_counter() - t0
            identities[p.name] = _check_chain(p.reading, set(), results, domain,
                                              f"{d.id}/{p.name}", book, proofs, p.tolerance, prove, timing)
        if p.erratum is not None and is_relation(p.erratum.corrected_reading):
            corrected[p.name] = _relation(p.erratum.corrected_reading, results, domain,
                                          f"{d.id}/{p.name}#corrected", timing)
            if p.erratum.corrected_reading.indicators() is not None:
                readings[p.name + "#corrected"] = _resolved(p.erratum.corrected_reading.indicators(), results, closed)
        elif p.erratum is not None and p.erratum.corrected_reading is not None:
            t0 = time.perf_counter()
            readings[p.name + "#corrected"] = _resolved(p.erratum.corrected_reading, results, closed)
            timing["evaluation"] += time.perf_counter() - t0
            corrected[p.name] = _check_chain(p.erratum.corrected_reading, set(), results, domain,
                                             f"{d.id}/{p.name}#corrected", book, proofs, p.tolerance, prove,
                                             timing)
        if progress:
            progress()

    t_witnesses = time.perf_counter()
    outcomes: dict = {}
    allowances = {p.name: sp.Rational(p.tolerance) for p in d.printed if p.tolerance is not None}
    for w in d.witnesses:
        for target, out in w.run(readings, allowances).items():
            outcomes.setdefault(target, []).append(out)
    route = DefinitionRoute(d.steps, domain, d.id)       # every formula no declared witness measures
    for p, target, reading in route_readings(d):
        if is_relation(reading):      # its sides from the definitions, at the relation check's counterexample too
            check = identities.get(p.name) if target == p.name else corrected.get(p.name)
            outcomes.setdefault(target, []).append(route.relation_outcome(target, reading, results, check))
        else:
            outcomes.setdefault(target, []).append(route.outcome(target, reading, p.tolerance))
    timing["witnesses"] = time.perf_counter() - t_witnesses
    for p in d.printed:          # printed numbers agree with a witness to their printed precision
        if p.tolerance is not None:
            for target in (p.name, p.name + "#corrected"):
                for out in outcomes.get(target, []):
                    for r in out.records:      # a certified record carries the print's rounding already
                        if not r.get("certified") and not r.get("proven"):
                            r["abs_tolerance"] = float(p.tolerance) * (1 + 1e-9)
                    out.judged()
                    out.note = "" if out.agrees else out.note or f"{out.witness}: differs by more than the printed precision"

    def correction(p) -> str:           # the smallest edit of a refuted print that makes it hold
        found = print_corrections(p, results, domain, f"{d.id}/{p.name}", lambda chain: _check_chain(
            chain, set(), results, domain, f"{d.id}/{p.name}#edit", None, {}, p.tolerance, prove), limit=1)
        if not found:
            return "no single small edit of the print makes it hold"
        c = found[0]
        return f"the smallest correction found is {c.text} ({c.change}: {c.what}, {c.kind}; {c.status})"

    def searched(p) -> str:     # a declared erratum's refuted print: the search's sentence, decided by sampling
        return smallest_correction(p, results, domain, f"{d.id}/{p.name}", lambda chain: _check_chain(
            chain, set(), results, domain, f"{d.id}/{p.name}#edit", None, {}, p.tolerance, False),
            p.erratum.corrected)

    formulas = [_verdict(d, p, identities.get(p.name), corrected.get(p.name), outcomes, failures, correction,
                         searched) for p in d.printed]
    failures += [f"{d.source} {d.locator}: {m}" for m in _proof_failures(d.id, proofs)]
    return DerivationReport(d.id, d.source, d.title, d.locator, key, time.perf_counter() - t0,
                            step_reports, formulas, failures, proofs=proofs, timing=timing)


def step_failure(step: StepReport) -> str:
    """The failure a step's status makes (a refuted step), or ``""``."""
    if step.status != "refuted":
        return ""
    return f"step {step.name!r} is refuted: {(step.identity or {}).get('counterexample')}"


def _proof_failures(derivation_id: str, proofs: dict) -> list[str]:
    """A certificate that no longer proves its claim is a failure of the derivation."""
    return [f"the proof certificate of {k} ({c['strategy']}) no longer proves it; search anew with "
            f"`symfloat verify {derivation_id} --search-proofs`" for k, c in proofs.items() if c["how"] == "replay failed"]


def judge(f: FormulaReport, erratum_declared: bool) -> tuple[str, str | None, list[str]]:
    """The verdict, evidence and failures that the recorded evidence of *f* gives: the check of its
    reading (``f.identity``), of the declared correction (``f.corrected_identity``), the witness records
    (each decided by the bound it carries, :func:`~symfloat.engine.witness.record_decision`: an undecided
    record neither agrees nor refutes) and the witnesses
    found at odds (``f.against``, ``f.against_correction``).  The checker decides every verdict here, and
    a cached report is judged again by the same function when it is read (:func:`rejudged`)."""
    ident = IdentityResult.from_json(f.identity) if f.identity else None
    corr = IdentityResult.from_json(f.corrected_identity) if f.corrected_identity else None
    printed = {record_decision(r) for r in f.numeric}
    corrected = {record_decision(r) for r in f.corrected_numeric}
    printed_refuted = bool(f.against) or "refuted" in printed      # undecided records neither agree nor refute
    printed_agree = not printed_refuted and printed <= {"agrees"}
    corrected_refuted = bool(f.against_correction) or "refuted" in corrected
    if f.lost:
        return "unverifiable", None, []
    if ident is not None and ident.status == "trivial":
        return "trivial", None, ["an erratum is declared but the reading compares a thing with itself"] \
            if erratum_declared else []
    if ident is not None and ident.status == "undecided":
        return "unverifiable", None, []
    failures = []
    if ident is not None and ident.holds:
        if erratum_declared:
            failures.append("an erratum is declared but the print holds")
        if printed_refuted:
            failures.append("derived and printed agree but a witness disagrees")
        return "verified", ident.evidence, failures
    if not erratum_declared:       # refuted (or unreadable) print
        failures.append(f"the print is refuted ({ident.counterexample if ident else None}) and no erratum is "
                        f"declared")
        return "erratum", "sampled", failures
    if f.numeric and printed_agree:
        failures.append("the print is refuted but the witnesses agree with it")
    if corr is not None and corr.status == "trivial":
        failures.append("the reading of the correction compares a thing with itself")
    elif corr is not None and not corr.holds:
        failures.append(f"the declared correction does not hold ({corr.status}: "
                        f"{corr.counterexample or corr.residual})")
    if corrected_refuted:
        failures.append("a witness disagrees with the declared correction")
    return "erratum", corr.evidence if corr is not None and corr.holds else "sampled", failures


def _refutation(cx: dict) -> str:
    """A counterexample with labelled sides: ``at h=1, r=2 (printed: 9/5, derived: 27/20)``."""
    point = ", ".join(f"{k}={v}" for k, v in cx["point"].items())
    within = f", allowed difference {cx['tolerance']}" if "tolerance" in cx else ""
    return f"{'at ' + point + ' ' if point else ''}(printed: {cx['rhs']}, derived: {cx['lhs']}{within})"


def _verdict(d, p, ident, corr, outcomes, failures, correction, searched) -> FormulaReport:
    where = f"{d.source} {p.locator} ({p.name})"
    # an outcome without records (the definition route found nothing to measure) only adds its note
    printed_out = [o for o in outcomes.get(p.name, []) if o.records]
    corrected_out = [o for o in outcomes.get(p.name + "#corrected", []) if o.records]
    every = outcomes.get(p.name, []) + outcomes.get(p.name + "#corrected", [])
    rep = FormulaReport(d.formula_id(p), d.source, p.locator, "unverifiable", None,
                        [r for o in printed_out for r in o.records], p.excerpt, _latex(p),
                        identity=ident.to_json() if ident else None,
                        corrected_numeric=[r for o in corrected_out for r in o.records],
                        witness_notes=[o.note for o in every if o.note],
                        numeric_content=bool(printed_out or corrected_out) or all(o.measurable for o in every),
                        lost=p.lost or "", corrected_identity=corr.to_json() if corr else None,
                        against=[o.witness for o in printed_out if not o.agrees and not o.undecided],
                        against_correction=[o.witness for o in corrected_out if not o.agrees and not o.undecided])
    rep.verdict, rep.evidence, found = judge(rep, p.erratum is not None)
    if p.erratum is None and rep.verdict == "erratum":       # a refuted print: its sides labelled, a correction offered
        shown = _refutation(ident.counterexample) if ident is not None and ident.counterexample else ""
        found = [f"the print is refuted {shown} and no erratum is declared; {correction(p)}"
                 if m.startswith("the print is refuted") else m for m in found]
    failures += [f"{where}: {m}" for m in found]
    if rep.verdict == "erratum" and p.erratum is not None and corr is None and p.erratum.corrected_reading is not None:
        failures.append(f"{where}: the correction was not checked")
    if p.lost:
        rep.reason = f"text lost in the transcription: {p.lost}"
    elif rep.verdict == "trivial":
        rep.reason = "the reading's members are identical as built: the comparison proves nothing"
    elif rep.verdict == "unverifiable":
        rep.reason = (f"the checks could not decide: {ident.samples} valid samples, and the recorded proof "
                      f"search found no symbolic proof (details in the identity record)")
    elif rep.verdict == "erratum" and p.erratum is not None:
        rep.erratum = _erratum(p, ident, corr, corrected_out)
        sentence = searched(p) if ident is not None and ident.status == "refuted" else ""
        if sentence:            # the correction search's sentence, after the engine's findings
            rep.erratum["evidence"] += " " + sentence
    return rep


def _erratum(p, ident, corr, corrected_out) -> dict:
    """The erratum's entry: its declaration, with what the engine found, its mathematics in TeX between
    dollars (:mod:`symfloat.model.evidence_tex`)."""
    found = []
    if ident is not None and ident.counterexample:
        cx = ident.counterexample
        where_ = f"at ${tex_point(cx['point'])}$ " if cx["point"] else ""
        within = f" (allowed difference ${tex_number(cx['tolerance'])}$)" if "tolerance" in cx else ""
        found.append(f"{where_}the print gives {shown_value(cx['rhs'])} where the derivation gives "
                     f"{shown_value(cx['lhs'])}{within}")
    if p.unreadable:
        found.append(f"as printed: {p.unreadable}")
    if corr is not None and corr.holds:
        found.append(f"the correction is {'proved' if corr.status == 'proved' else 'confirmed by sampling'}"
                     + (f" ({PROOF_WORDS[corr.strategy]})" if corr.strategy else ""))
    for o in corrected_out:
        who = "the definition route" if o.witness == DefinitionRoute.name else "a first-principles witness"
        certified = [r for r in o.records if r.get("certified")]
        if certified and record_decision(certified[0]) == "undecided":
            found.append(f"{who} cannot decide the correction ({undecided_reason(certified[0])})")
        elif certified:
            found.append(f"{who} agrees with the correction to ${tex_error(certified[0]['rel_error'])}$, proven "
                         f"({certified[0]['method']}, {certified[0]['bits']} bits)")
        elif o.records:
            best = min(o.records, key=lambda r: r["rel_error"])
            found.append(f"{who} agrees with the correction to ${tex_error(best['rel_error'])}$ "
                         f"({best['method']})")
    return {
        "kind": p.erratum.kind, "confidence": p.erratum.confidence, "corrected": p.erratum.corrected,
        "evidence": p.erratum.evidence + (" Engine: " + "; ".join(found) + "." if found else ""),
        **({"places": list(p.erratum.places)} if p.erratum.places else {}),
        **({"objection": p.erratum.objection, "answer": p.erratum.answer} if p.erratum.objection else {}),
    }


class Unsound(ValueError):
    """A stored report that the checker's rules do not give back (see :func:`rejudged`)."""


@cache
def _report_schema():
    """The report schema compiled to a validator (fastjsonschema: a cached report is read in about a
    millisecond, where jsonschema would take twenty)."""
    text = files("symfloat").joinpath("schemas", "report.schema.json").read_text(encoding="utf-8")
    return fastjsonschema.compile(json.loads(text))


def rejudged(data, derivation_id: str, key: str) -> DerivationReport:
    """The report *data* (as :meth:`DerivationReport.to_json` wrote it, read back from the cache) when it
    stands up to the checker's own rules, else :class:`Unsound` saying why: it follows the report schema
    (``symfloat/schemas/report.schema.json``), it is the report of *derivation_id* under the cache *key*
    it was stored under, every step's status is its identity check's, no step is refuted and no
    certificate failed, and every formula's verdict and evidence are those :func:`judge` gives from its
    own recorded checks, witness records and erratum, with no failure.  A stored report never has
    failures: a report with any is not cached."""
    try:
        _report_schema()(data)
    except fastjsonschema.JsonSchemaException as exc:
        message = exc.message.replace("data", "the report", 1)
        raise Unsound(message if len(message) < 160 else message[:160] + " ...") from None
    report = DerivationReport.from_json(data)
    if report.id != derivation_id or report.key != key:
        raise Unsound(f"it is the report of {report.id} under key {report.key}, not of {derivation_id} under {key}")
    if report.failures:
        raise Unsound("it records failures")
    for step in report.steps:
        if step.identity is not None and step.identity["status"] != step.status:
            raise Unsound(f"step {step.name!r} is {step.status!r} but its check says {step.identity['status']!r}")
        if step_failure(step):
            raise Unsound(step_failure(step))
    for problem in _proof_failures(report.id, report.proofs):
        raise Unsound(problem)
    for f in report.formulas:
        if not f.id.startswith(f"{report.id}/"):
            raise Unsound(f"formula {f.id} is not one of {report.id}")
        verdict, evidence, problems = judge(f, f.erratum is not None)
        if (verdict, evidence) != (f.verdict, f.evidence):
            raise Unsound(f"{f.id} is recorded {f.verdict!r} ({f.evidence}) where its own evidence gives "
                          f"{verdict!r} ({evidence})")
        if problems:
            raise Unsound(f"{f.id}: {problems[0] if len(problems[0]) < 160 else problems[0][:160] + ' ...'}")
    return report
