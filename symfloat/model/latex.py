r"""An allow-list reader of the transcriptions' TeX into SymPy.

It reads the formulas the sources print — relation chains of sums, products, quotients, powers,
roots, ``\frac``, proportions, the trigonometric functions under their old names, integrals as named
symbols — and refuses everything else with :class:`Unreadable` (sums, cases, function values ``F(z)``,
words).  Nothing is evaluated as
code: the text is cut into tokens by regular expressions, and each token is turned into a SymPy
object by an explicit constructor (``Symbol``, ``Integer``, ``Rational``, ``Add``, ``Mul``, ``Pow``,
``sin`` ...); there is no ``eval``, ``sympify`` or ``parse_expr`` on any part of the text.
(``sympy.parsing.latex.parse_latex(..., backend="lark")`` was examined: its transformer also builds
SymPy objects by constructors and evaluates no code, but its grammar rejects ``\operatorname{tg}``,
``\text{...}``, relation chains ``a = b = c`` and ``a < b < c``, and it reads ``\varrho`` as ``rho``,
so most excerpts would fail or lose distinctions; this reader is used instead, with no dependency.)

Nothing is computed beyond a bound, so that no text can make the reader run long: a number has at
most :data:`MAX_DIGITS` digits, a number in an exponent is at most :data:`MAX_EXPONENT` in size, and a
power of two numbers has at most :data:`MAX_DIGITS` digits; a formula past a bound is
:class:`Unreadable` (``10^{10^{10}}``, a 5,000-digit literal), read in no time.

Normalisations, each a named rule that the reader reports when it applies (:data:`RULES`).  Two
readings are not normalisations and are not reported: ``\bar z`` is the symbol ``zbar``, kept apart
from ``z`` (an ``\overline`` names a segment, ``\overline{OF}`` is ``OF``); and with ``integrals=True``
(a definition to check a print against) ``\int_a^b f \, dx`` is the integral of *f* over *x* from
*a* to *b*.
"""
from __future__ import annotations

import math
import re
import unicodedata
from dataclasses import dataclass, field

import sympy as sp

from ..errors import quoted

__all__ = ["Unreadable", "Reading", "read", "canonical", "token_spans", "RULES", "RELATIONS", "MAX_DIGITS",
           "MAX_EXPONENT"]

MAX_DIGITS = 100            # digits of a literal, and of a power of two numbers
MAX_EXPONENT = 100          # the size of a number in an exponent (the prints raise to 1/2 ... 4)

RULES = {
    "tg": r"\operatorname{tg}, \text{tg}, \tg read as tan; cotg, ctg as cot",
    "decimal-comma": "a comma between digits is a decimal point (0,245 = 0.245)",
    "implicit-product": "juxtaposed factors multiply (2 a b, 2 \\cos\\omega)",
    "function-argument": "a function's argument without parentheses runs over the juxtaposed factors "
                         "that follow it (\\sin 2\\mu, \\cos\\alpha\\cdot x is cos(alpha) x)",
    "implied-left-side": "a chain that opens with a relation (= a b) has lost its left side to the prose",
    "degrees": "n^\\circ is n pi/180",
    "dot-product": "a full stop between factors is a product, as the old prints write it (AB^2.D)",
    "proportion": "a : b is the ratio a / b of the sums on either side (a : b = c : d)",
    "segment": "a run of two or more capital letters without space is one segment or figure name (AB, GH), "
               "unless the hand reading has one of its letters as a symbol (ND, XV are products); so is any "
               "run of letters none of which the hand reading has (Euler's ef)",
    "continued-row": "a row that opens with & and states no relation continues the last member of the row "
                     "before: a sum when it opens with a sign, else a product (a formula broken over lines)",
    "joined-lines": "inline formulas separated only by a line break are one formula; words around the "
                    "math of an excerpt are dropped",
    "list": "formulas separated by a comma (or by words between dollars) are read as rows",
    "integral-as-name": "an integral is read as one symbol named by its text; it matches a hand symbol of "
                        "that name, and a member holding another is not compared; the same text twice in one "
                        "formula is two integrals (their domains are named in the prose: Scheeffer's "
                        "\\int x y df - \\int x y df = 0 over two triangles), the second named with #2",
    "element-integral": "an integral without a differential (Euler's \\int w \\cdot u^2) runs to the next sign "
                        "or relation",
    "layout": "dollars, \\displaystyle, \\left, \\right, spacing, an equation tag (78c), words in \\text "
              "at either end and closing punctuation are dropped",
}
RELATIONS = {"=": "=", "<": "<", ">": ">", r"\leq": "<=", r"\le": "<=", r"\geq": ">=", r"\ge": ">=",
             r"\neq": "!=", r"\approx": "~", r"\cong": "~"}

_GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta",
          "iota", "kappa", "lambda", "mu", "nu", "xi", "pi", "rho", "varrho", "sigma", "varsigma", "tau",
          "upsilon", "phi", "varphi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi",
          "Sigma", "Upsilon", "Phi", "Psi", "Omega"}
_FUNCTIONS = {"sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "tg": sp.tan, "cot": sp.cot, "cotg": sp.cot,
              "ctg": sp.cot, "sec": sp.sec, "csc": sp.csc, "arctan": sp.atan, "arcsin": sp.asin,
              "arccos": sp.acos, "log": sp.log, "ln": sp.log, "exp": sp.exp}
_IGNORED = {"displaystyle", "left", "right", "bigl", "bigr", "Bigl", "Bigr", "big", "Big", "quad", "qquad",
            "limits", "mathrm", "mathit", "operatorname", "textstyle"}
_REFUSED = {"iint", "sum", "prod", "lim", "begin", "end", "cases", "infty", "partial", "pm", "mp",
            "lessgtr", "gtrless", "sim", "equiv", "perp", "parallel", "S"}

_TOKEN = re.compile(r"""
    (?P<space>\s+|\\[,;:!]|\\\s|~)
  | (?P<number>\d+(?:[.,]\d+)?)
  | (?P<text>\\(?:text|mathrm|operatorname)\s*\{[^{}]*\})
  | (?P<command>\\[A-Za-z]+|\\[{}|])
  | (?P<letter>[A-Za-zÀ-žΑ-ω])
  | (?P<prime>'+)
  | (?P<symbol>[-+*/=<>^_(){}\[\]|,.:;&])
""", re.X)


class Unreadable(ValueError):
    """The text is outside what the reader accepts; the message says what."""


@dataclass
class Reading:
    """A formula read: rows, each ``(members, relations)``; the rules that applied; the names read
    as segments."""

    rows: list[tuple[list, list[str]]]
    rules: set[str] = field(default_factory=set)
    segments: set[str] = field(default_factory=set)


def canonical(name: str) -> str:
    r"""A symbol name without TeX dress: no backslashes, braces, ``\text``, accents or ``var`` of a Greek
    letter, so that ``E_0^{\text{hasáb}}`` and ``E_0^{hasab}`` agree.

    >>> canonical(r"E_{0}^{\text{hasáb}}"), canonical("varrho"), canonical(r"\overline{OF}")
    ('E_0^hasab', 'rho', 'OF')
    """
    s = re.sub(r"\\(?:text|mathrm|operatorname|overline|bar|mathit)\b", "", name)
    s = s.replace("\\", "").replace("{", "").replace("}", "").replace(" ", "")
    s = "".join(c for c in unicodedata.normalize("NFKD", s) if not unicodedata.combining(c))
    return re.sub(r"var(phi|rho|theta|epsilon|sigma|pi)", r"\1", s)


def _tokens(tex: str) -> list[tuple[str, str]]:
    out, pos = [], 0
    while pos < len(tex):
        m = _TOKEN.match(tex, pos)
        if not m:
            raise Unreadable(f"unexpected character {quoted(tex[pos])}")
        kind = m.lastgroup
        value = m.group(0)
        pos = m.end()
        if kind == "command" and value[1:] in _IGNORED:
            continue
        if kind == "letter" and (command := _greek_command(value)) is not None:
            kind, value = "command", command
        out.append((kind, value))
    return out


def _greek_command(letter: str) -> str | None:
    r"""The TeX command of a Greek letter typed as itself (π is ``\pi``, ς ``\varsigma``), or ``None`` for a
    letter that is not one or has no command of its own (capital alpha is written A in TeX).

    >>> _greek_command("π"), _greek_command("Δ"), _greek_command("ς"), _greek_command("Α"), _greek_command("x")
    ('\\pi', '\\Delta', '\\varsigma', None, None)
    """
    words = unicodedata.name(letter, "").split()
    if words[:1] != ["GREEK"] or len(words) < 4:
        return None
    name = "varsigma" if words[-2:] == ["FINAL", "SIGMA"] else words[-1].lower()
    name = name.capitalize() if words[1] == "CAPITAL" else name
    return "\\" + name if name in _GREEK else None


def token_spans(tex: str) -> list[tuple[str, str, int, int]]:
    r"""The tokens of *tex* as ``(kind, text, start, end)``, spaces and layout included (where an edit of
    the print may fall); a character the reader does not know is a token of kind ``other``.

    >>> [t[1] for t in token_spans(r"x_s = \frac{3}{4}")]
    ['x', '_', 's', ' ', '=', ' ', '\\frac', '{', '3', '}', '{', '4', '}']
    """
    out, pos = [], 0
    while pos < len(tex):
        m = _TOKEN.match(tex, pos)
        kind, end = (m.lastgroup, m.end()) if m else ("other", pos + 1)
        out.append((kind, tex[pos:end], pos, end))
        pos = end
    return out


_TAG = re.compile(r"\s+\(\d+\s?[a-z]?\)\s*$")                    # an equation's number at the end: (118), (78 c)
_BEFORE_NO_TAG = re.compile(r"(?:[-=+*/<>(,]|\\cdot|\\times)$")     # what a factor (2), not a number, follows


def _without_tag(s: str) -> str:
    r"""*s* without its equation number: a bracketed number set apart by space at the end, after \quad or
    after a formula that is complete (not after an operator: ``y = (2)``, ``h \cdot (2)`` keep it as a factor;
    ``h(2)``, with no space, is a product).

    >>> _without_tag(r"V = a b c \quad (12)"), _without_tag("V = abc (12a)"), _without_tag("y = h(2)")
    ('V = a b c', 'V = abc', 'y = h(2)')
    >>> print(_without_tag("y = (2)"), "|", _without_tag(r"y = h \cdot (2)"))
    y = (2) | y = h \cdot (2)
    """
    m = _TAG.search(s)
    if m is None:
        return s
    before = s[:m.start()].rstrip()
    if before.endswith(r"\quad") or (before and not _BEFORE_NO_TAG.search(before)):
        return re.sub(r"\\quad$", "", before).rstrip()
    return s


def _strip_layout(tex: str, rules: set[str]) -> str:
    s = tex.strip().strip("$").strip()
    s2 = _without_tag(s).strip()
    s2 = re.sub(r"^(?:\\text\{[^{}]*\}\s*)+|(?:\s*\\text\{[^{}]*\})+$", "", s2).strip()
    s2 = re.sub(r"(?:\\quad|\\qquad|\\,|\\;|\s)*[.,;:]?\s*-?\s*$", "", s2)
    s2 = re.sub(r"\\left\.|\\right\.|(?<=\\end\{aligned\})\s*\\right\\\}", "", s2)
    s2 = re.sub(r"[.,;]\s*(?=\\\\|\\end\{aligned\})", " ", s2)
    s2 = re.sub(r"\\(?:displaystyle|left|right)(?![A-Za-z])", "", s2)
    if s2 != s:
        rules.add("layout")
    return s2


class _Parser:
    """Recursive descent over the tokens; names of several letters are taken from *names*."""

    def __init__(self, tokens, names: frozenset[str], rules: set[str], segments: set[str], integrate=False):
        self.integrals = {}             # how often each integral's text occurred in the formula so far
        self.integrate = integrate      # read a bounded integral with its differential as an integral
        self.t = [tok for tok in tokens if tok[0] != "space"]
        self.spaced = self._spacing(tokens)
        self.i = 0
        self.names = names
        self.rules = rules
        self.segments = segments

    @staticmethod
    def _spacing(tokens):
        """For each non-space token, whether white space preceded it."""
        flags, before = [], False
        for kind, _ in tokens:
            if kind == "space":
                before = True
                continue
            flags.append(before)
            before = False
        return flags

    # -- token helpers
    def peek(self, k=0):
        j = self.i + k
        return self.t[j] if j < len(self.t) else ("end", "")

    def take(self, value=None):
        tok = self.peek()
        if value is not None and tok[1] != value:
            raise Unreadable(f"expected {quoted(value)}, found {quoted(tok[1])}")
        self.i += 1
        return tok

    # -- grammar
    def chain(self):
        members, relations = [], []
        if self.peek()[1] in RELATIONS:
            members.append(None)
            self.rules.add("implied-left-side")
        else:
            members.append(self.expr())
        while self.peek()[1] in RELATIONS:
            relations.append(RELATIONS[self.take()[1]])
            members.append(self.expr())
        if self.peek()[0] != "end":
            raise Unreadable(f"cannot read on from {quoted(self.peek()[1])}")
        return members, relations

    def expr(self):
        """A sum, or the ratio ``a : b`` of two sums (the ratio binds weakest: ``h : h - h/m``)."""
        value = self.sum()
        if self.peek()[1] == ":":
            self.take()
            self.rules.add("proportion")
            value = value / self.sum()
        return value

    def sum(self):
        if self.peek()[1] in ("-", "+"):
            sign = -1 if self.take()[1] == "-" else 1
            value = sign * self.term()
        else:
            value = self.term()
        while self.peek()[1] in ("+", "-"):
            op = self.take()[1]
            rhs = self.term()
            value = value + rhs if op == "+" else value - rhs
        return value

    def _starts_factor(self):
        kind, v = self.peek()
        if kind in ("number", "letter", "text"):
            return True
        if kind == "command":
            name = v[1:]
            return name in _GREEK or name in _FUNCTIONS or name in ("frac", "tfrac", "dfrac", "sqrt", "{",
                                                                     "overline", "bar", "int")
        return v in ("(", "[", "{")

    def _starts_argument(self):
        """Whether the next token continues a function's argument: a number, a letter or a Greek letter
        written right after (not a function, a parenthesis, a fraction or a root)."""
        kind, v = self.peek()
        return kind in ("number", "letter") or (kind == "command" and v[1:] in _GREEK)

    def term(self):
        value = self.factor()
        while True:
            v = self.peek()[1]
            if v in (r"\cdot", r"\times", "*", "."):
                if v == ".":
                    self.rules.add("dot-product")
                self.take()
                value = value * self.factor()
            elif v == "/":
                self.take()
                value = value / self.factor()
            elif self._starts_factor():
                self.rules.add("implicit-product")
                value = value * self.factor()
            else:
                return value

    def factor(self):
        base = self.primary()
        return self.postfix(base)

    def postfix(self, base):
        while self.peek()[1] == "^":
            self.take()
            if self.peek()[1] == r"\circ":
                self.take()
                self.rules.add("degrees")
                base = base * sp.pi / 180
                continue
            exponent = self.group_or_atom()
            base = _power(base, exponent)
        return base

    def group_or_atom(self):
        kind, v = self.peek()
        if v == "{":
            self.take()
            inner = self.expr()
            self.take("}")
            return inner
        if kind == "number":
            if not v.isdigit():
                raise Unreadable("a decimal exponent without braces")
            if len(v) > 1:      # x^23 is x^2 3 in TeX: the exponent is one digit
                self.t[self.i] = ("number", v[1:])
            else:
                self.take()
            return sp.Integer(int(v[0]))
        if kind in ("letter", "command"):
            return self.primary(single=True)
        raise Unreadable(f"cannot read an exponent from {quoted(v)}")

    def _number(self, v):
        if len(v) > MAX_DIGITS:
            raise Unreadable(f"a number of {len(v)} digits (the reader takes at most {MAX_DIGITS})")
        if "," in v:
            self.rules.add("decimal-comma")
        whole, _, frac = v.replace(",", ".").partition(".")
        if frac:
            return sp.Rational(int(whole + frac), 10 ** len(frac))
        return sp.Integer(int(whole))

    def _index(self):
        """The text of a sub- or superscript: a braced group or one character."""
        if self.peek()[1] == "{":
            depth, parts = 0, []
            while True:
                kind, v = self.take()
                if kind == "end":
                    raise Unreadable("unclosed brace")
                depth += (v == "{") - (v == "}")
                parts.append(v)
                if depth == 0:
                    break
            return "".join(parts)
        kind, v = self.take()
        if kind == "end":
            raise Unreadable("an index is missing")
        return v

    def _symbol(self, name):
        """A symbol *name* with the indices and primes that follow it."""
        while True:
            v = self.peek()[1]
            if v == "_":
                self.take()
                name += "_" + self._index()
            elif v == "^" and self._name_goes_on(canonical(name + "^" + self._peek_group())):
                self.take()
                name += "^" + self._index()
            elif self.peek()[0] == "prime" and not self.spaced[self.i]:
                name += self.take()[1]
            else:
                return sp.Symbol(canonical(name))

    def _name_goes_on(self, name: str) -> bool:
        """Whether a name of the reading's vocabulary is *name* or *name* with an index added."""
        return any(n == name or n.startswith(name) for n in self.names)

    def _peek_group(self):
        if self.peek(1)[1] != "{":
            return self.peek(1)[1]
        depth, parts, j = 0, [], self.i + 1
        while j < len(self.t):
            v = self.t[j][1]
            depth += (v == "{") - (v == "}")
            parts.append(v)
            j += 1
            if depth == 0:
                break
        return "".join(parts)

    def _refuse_function_value(self):
        """``F(z)``, ``F'(z)``, ``F(2\\sigma)``: a function of the text applied, which is not read
        (``D(a - c)`` with a sum inside is a product)."""
        j = self.i + 1
        while j < len(self.t) and self.t[j][0] == "prime":
            j += 1
        if j < len(self.t) and self.t[j][1] == "(" and not self.spaced[j] and self.t[self.i][1].isupper():
            depth, k = 0, j
            while k < len(self.t):
                v = self.t[k][1]
                depth += (v == "(") - (v == ")")
                if depth == 1 and v in ("+", "-") and k > j + 1:
                    return
                if depth == 0:
                    break
                k += 1
            raise Unreadable(f"a function value {self.t[self.i][1]}(...)")

    def _letters(self):
        """A run of letters with no space between: one name when the reading's vocabulary has it
        (a segment ``AB`` or ``Pp``), else the first letter alone."""
        self._refuse_function_value()
        j, run = self.i, ""
        while j < len(self.t) and self.t[j][0] == "letter" and (j == self.i or not self.spaced[j]):
            run += self.t[j][1]
            j += 1
        for n in range(len(run), 1, -1):
            if canonical(run[:n]) in self.names and not (j - self.i > n and self.t[self.i + n][1] == "_"):
                self.i += n
                return self._symbol(run[:n])
        capitals = len(run) - len(run.lstrip("ABCDEFGHIJKLMNOPQRSTUVWXYZ"))
        if self.names and len(run) >= 2 and not any(c in self.names for c in run):
            capitals = len(run)         # no letter of the run is a symbol of the reading: a segment (ef)
        if capitals >= 2 and not any(c in self.names for c in run[:capitals]):
            self.rules.add("segment")
            self.i += capitals
            segment = self._symbol(run[:capitals])
            self.segments.add(segment.name)
            return segment
        self.i += 1
        return self._symbol(run[0])

    def function(self, fn):
        power = None
        if self.peek()[1] == "^":
            self.take()
            power = self.group_or_atom()
        if self.peek()[1] in ("(", "[") or (self.peek()[1] == "{"):
            arg = self.primary()
        else:
            self.rules.add("function-argument")
            arg = self.factor()
            while self._starts_argument():
                arg = arg * self.factor()
        value = fn(arg)
        return value ** power if power is not None else value

    def primary(self, single=False):
        kind, v = self.peek()
        if kind == "number":
            self.take()
            return self._number(v)
        if kind == "letter":
            return self._letters()
        if kind == "text":
            self.take()
            fn = _text_function(v)
            if fn is None:
                raise Unreadable(f"words in the formula: {quoted(v)}")
            self.rules.add("tg")
            return self.function(fn)
        if kind == "command":
            name = v[1:]
            if name == "int":
                return self.integral()
            if name == "pi" and self.peek(1)[1] != "_":
                self.take()
                return sp.pi
            if name in _GREEK:
                self.take()
                return self._symbol(v)
            if name == "overline":
                self.take()
                return self._symbol(self._index())
            if name == "bar":
                self.take()
                return self._symbol(canonical(self._index()) + "bar")
            if name in _FUNCTIONS:
                self.take()
                if name in ("tg", "cotg", "ctg"):
                    self.rules.add("tg")
                return self.function(_FUNCTIONS[name])
            if name in ("frac", "tfrac", "dfrac"):
                self.take()
                num = self.braced()
                den = self.braced()
                return num / den
            if name == "sqrt":
                self.take()
                if self.peek()[1] == "[":
                    self.take()
                    n = self.expr()
                    self.take("]")
                    return sp.root(self.braced(), n)
                return sp.sqrt(self.braced() if self.peek()[1] == "{" else self.primary(single=True))
            if name == "{":
                self.take()
                inner = self.expr()
                self.take(r"\}")
                return inner
            if single:
                raise Unreadable(f"cannot read {quoted(v)} here")
            raise Unreadable(f"{v} is not read" if name in _REFUSED else f"unknown command {v}")
        if v in ("(", "["):
            self.take()
            inner = self.expr()
            self.take(")" if v == "(" else "]")
            return inner
        if v == "{":
            return self.braced()
        raise Unreadable(f"cannot read {quoted(v)}" if v else "the formula ends too early")

    def integral(self):
        """``\\int_3 x^2 df`` as one opaque symbol named by its text (``int_3x^2df``): the reader does not
        integrate; a hand reading that names the same integral the same way matches it.  Without a
        differential (Euler's ``\\int w \\cdot u^2``, the element ``w`` standing for it) the integral runs to
        the next sign, relation or closing bracket at its level."""
        if self.integrate:
            return self.definite_integral()
        self.take()
        self.rules.add("integral-as-name")
        parts, depth = [r"\int"], 0
        while True:
            kind, v = self.peek()
            if depth == 0 and v == "d" and self.peek(1)[0] == "letter" and len(parts) > 1:
                parts += [self.take()[1], self.take()[1]]
                return self._integral_symbol(canonical("".join(parts)))
            if kind == "end" or depth == 0 and (v in RELATIONS or v in ("+", "-", r"\pm", ")", "}", r"\}")
                                                and len(parts) > 1 and parts[-1] not in ("^", "_")):
                if len(parts) < 2 or depth:
                    raise Unreadable("an integral without its integrand")
                self.rules.add("element-integral")
                return self._integral_symbol(canonical("".join(parts)))
            depth += (v in ("{", "(")) - (v in ("}", ")"))
            parts.append(self.take()[1])

    def definite_integral(self):
        """``\\int_a^b f \\, dx``: the integral of *f* over *x* from *a* to *b* (both bounds and the
        differential are required: an integral is checked as a definite number or function)."""
        self.take()
        bounds = {}
        while self.peek()[1] in ("_", "^"):
            which = self.take()[1]
            bounds[which] = self.group_or_atom()
        if set(bounds) != {"_", "^"}:
            raise Unreadable("an integral needs both bounds, \\int_a^b")
        start, depth = self.i, 0
        while True:
            kind, v = self.peek()
            if kind == "end":
                raise Unreadable("an integral without its differential (dx)")
            if depth == 0 and v == "d" and self.peek(1)[0] == "letter" and self.i > start:
                break
            depth += (v in ("{", "(", "[")) - (v in ("}", ")", "]"))
            self.take()
        inner = _Parser([], self.names, self.rules, self.segments, integrate=True)
        inner.t, inner.spaced = self.t[start:self.i], self.spaced[start:self.i]     # the integrand's tokens
        integrand = inner.chain()
        if len(integrand[0]) != 1:
            raise Unreadable("a relation inside an integral")
        self.take()
        variable = self._symbol(self.take()[1])
        return sp.Integral(integrand[0][0], (variable, bounds["_"], bounds["^"]))

    def _integral_symbol(self, name):
        """The integral named *name*; a repeat of the same text in the formula is another integral."""
        self.integrals[name] = self.integrals.get(name, 0) + 1
        return sp.Symbol(name if self.integrals[name] == 1 else f"{name}#{self.integrals[name]}")

    def braced(self):
        if self.peek()[1] != "{":
            return self.primary(single=True)
        self.take("{")
        inner = self.expr()
        self.take("}")
        return inner


def _power(base, exponent):
    """``base ** exponent``, unless it would be too large to compute: a number in the exponent larger than
    :data:`MAX_EXPONENT`, or a number raised to one with more than :data:`MAX_DIGITS` digits.

    >>> _power(sp.Integer(10), sp.Integer(3))
    1000
    >>> _power(sp.Integer(10), sp.Integer(10) ** 10)
    Traceback (most recent call last):
    ...
    symfloat.model.latex.Unreadable: an exponent of 10000000000 (the reader takes at most 100)
    """
    numbers = [abs(n) for n in exponent.atoms(sp.Number) if n.is_finite]
    if numbers and max(numbers) > MAX_EXPONENT:
        raise Unreadable(f"an exponent of {max(numbers) if max(numbers) < 10 ** 30 else 'more than 1e30'} "
                         f"(the reader takes at most {MAX_EXPONENT})")
    if base.is_Rational and exponent.is_Number and base not in (0, 1, -1):
        digits = max(abs(base.p).bit_length(), base.q.bit_length()) * math.log10(2)
        if float(abs(exponent)) * max(digits, 1.0) > MAX_DIGITS:
            raise Unreadable(f"a power of more than {MAX_DIGITS} digits")
    return sp.Pow(base, exponent)


def _text_function(token: str):
    word = re.sub(r"^\\(?:text|mathrm|operatorname)\s*\{|\}$", "", token).strip()
    return _FUNCTIONS.get(word)


MAX_DEPTH = 50         # brackets within brackets (the sources nest 3 deep at most); the parser recurses per level


def _depth(tokens) -> int:
    """The deepest nesting of (), [] and {} among *tokens*.

    >>> _depth(_tokens("((a)+{b})"))
    2
    """
    depth = deepest = 0
    for _, t in tokens:
        if t in ("(", "[", "{"):
            depth += 1
            deepest = max(deepest, depth)
        elif t in (")", "]", "}"):
            depth -= 1
    return deepest


def _tree_depth(expr) -> int:
    """The depth of a SymPy expression's tree, counted without recursion (SymPy's own walks recurse)."""
    deepest, level = 0, [expr]
    while level:
        deepest += 1
        level = [a for e in level for a in getattr(e, "args", ())]
    return deepest


def read(tex: str, names=frozenset(), *, integrals=False) -> Reading:
    r"""Read *tex* (an excerpt's math, dollars allowed) into rows of members and relations.

    *names* are the canonical symbol names of the hand reading: a run of letters forms one of them when
    it can (``AB``, ``Pp``), a superscript stays in a name that continues with it (``T_2^1``); otherwise
    juxtaposed letters multiply, except a run none of whose letters the hand reading has (a segment
    ``GH``, ``ef``; capitals are a segment also without a hand reading).  With *integrals*, an integral
    with both bounds and its differential is read as the integral (a definition to check against);
    otherwise it is one opaque symbol named by its text.

    >>> r = read(r"$$x = \varrho + 1/2 \text{tg } \alpha,$$")
    >>> r.rows, sorted(r.rules)
    ([([x, rho + tan(alpha)/2], ['='])], ['function-argument', 'implicit-product', 'layout', 'tg'])
    >>> read(r"$\sqrt{0,06} = 0,245$").rows
    [([sqrt(6)/10, 49/200], ['='])]
    >>> read(r"\begin{cases} 1 & x \end{cases}")
    Traceback (most recent call last):
    ...
    symfloat.model.latex.Unreadable: \begin is not read
    >>> read(r"\bar z = \int_0^h x \, dx", integrals=True).rows
    [([zbar, Integral(x, (x, 0, h))], ['='])]
    """
    rules: set[str] = set()
    body = _strip_layout(tex, rules)
    if "$" in body:
        raise Unreadable("several formulas with words between them")
    body = re.sub(r"\\begin\{(?:aligned|align\*?)\}|\\end\{(?:aligned|align\*?)\}", r"\\\\", body)
    rows, segments = [], set()
    for part in re.split(r"\\\\", body):
        continued = part.lstrip().startswith("&") and rows and rows[-1][1]
        part = part.replace("&", "").strip()
        for tokens in _split_list(_tokens(part)):
            if _depth(tokens) > MAX_DEPTH:
                raise Unreadable(f"brackets nested more than {MAX_DEPTH} deep")
            try:
                members, relations = _Parser(tokens, frozenset(names), rules, segments, integrals).chain()
            except RecursionError:                # powers of powers, roots of roots without brackets
                raise Unreadable("the formula nests too deeply to be read") from None
            if any(m is not None and _tree_depth(m) > 2 * MAX_DEPTH for m in members):
                raise Unreadable("the formula nests too deeply to be checked")
            if continued and not relations and members[0] is not None:
                rules.add("continued-row")        # "= a \\ & + b" is a + b, "= a \\ & b" is a b
                last = rows[-1][0][-1]
                rows[-1][0][-1] = last + members[0] if part.startswith(("+", "-")) else last * members[0]
            else:
                rows.append((members, relations))
            continued = False
    if not rows:
        raise Unreadable("no formula")
    if len(rows) > 1 and len(re.split(r"\\\\", body)) == 1:
        rules.add("list")
    return Reading(rows, rules, segments)


def _split_list(tokens):
    """The token list cut at commas outside all brackets; empty pieces dropped."""
    pieces, current, depth = [], [], 0
    for tok in tokens:
        v = tok[1]
        depth += (v in ("{", "(", "[", r"\{")) - (v in ("}", ")", "]", r"\}"))
        if v == "," and depth == 0:
            pieces.append(current)
            current = []
        else:
            current.append(tok)
    pieces.append(current)
    return [p for p in pieces if any(kind != "space" for kind, _ in p)]
