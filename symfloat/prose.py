"""Prose for readers: the ASCII mathematics of a derivation's notes typeset as ``$…$``.

The notes, assumptions and summaries of the derivation modules write mathematics in ASCII
(``T_1 (1 + tan^2/2) = V_1 e_1``, ``tan phi <= b(1-s)/u_m``, ``int u v df = 0``).  For a notebook
each maximal run of mathematical tokens — names with an index or exponent, Greek letters, the
functions, numbers, operators and the one-letter names between them — becomes one inline formula
in TeX; words stay words.  A run without a name with an index, a Greek letter, a function or a
relation sign stays text (``(i)`` is a label, ``a - c`` a slab), but a letter alone between words is a name
and a formula of its own, unless it is the article (``a box``, ``A`` opening a sentence), a chapter's numeral
or a letter of an abbreviation:

>>> typeset("A box with edges a, b, c; the centroid C of a face, the x axis, i.e. Scheeffer X")
'A box with edges $a$, $b$, $c$; the centroid $C$ of a face, the $x$ axis, i.e. Scheeffer X'

>>> typeset("the arm grows like phi (T_1/V_1 - e_1)")
'the arm grows like $\\\\varphi (T_{1}/V_{1} - e_{1})$'
>>> typeset("stable iff T_1^1 > T_1")
'stable iff $T_{1}^{1} > T_{1}$'
>>> typeset("the volume V1, its centroid at u = e1; AA1 perpendicular to A1B1")
'the volume $V_{1}$, its centroid at $u = e_{1}$; $AA_{1}$ perpendicular to $A_{1}B_{1}$'
>>> typeset("F'(3/4)/3 of the box, F'(z) - F'(3/4) >= 0 for S4 at v = -v4 (step e2-e3)")
"$F'(3/4)/3$ of the box, $F'(z) - F'(3/4) \\\\ge 0$ for $S_{4}$ at $v = -v_{4}$ (step e2-e3)"
>>> typeset("a solution of the equation")
'a solution of the equation'
>>> typeset("the regular n-gon F_1 r^2 (2 + cos 2pi/n)/12")
'the regular n-gon $F_{1} r^{2} (2 + \\\\cos 2\\\\pi/n)/12$'

A Greek name or ``lim`` in an index is its sign, a star after a name is a superscript, degrees are
degrees, and a bracket a run does not close ends the formula before it (the formula after it is set too);
an equation number in brackets is the source's, not a factor; a letter against a bracket is a function's value:

>>> typeset("stable iff (a/b)^2 > 6s(1 - s) (123), F(1) (141, 142)")
'stable iff $(a/b)^{2} > 6s(1 - s)$ (123), $F(1)$ (141, 142)'

A relation sign written in ASCII is never a word, nor is a sign named alone; an interval is a formula:

>>> typeset("of degree <= 3, c != 0; it counts with '>=' (not >), xi in [-1/2, 1/2]")
"of degree $\\\\le 3$, $c \\\\ne 0$; it counts with '$\\\\ge$' (not $>$), $\\\\xi$ in $[-1/2, 1/2]$"

A segment named by its points is a name inside a formula (``GZ``, ``BH``; ``Cc`` from a point to its
companion), but alone it stays text, as does a chapter's numeral:

>>> typeset("M (GZ - phi GM)/phi^3 from AB, by Scheeffer IX")
'$M (GZ - \\\\varphi GM)/\\\\varphi^{3}$ from AB, by Scheeffer IX'

Euler names his segments by a capital and a small letter or by two small ones (``Oc``, ``ce``, ``wq``), and
writes products the same way (``nx + my``); a word of two letters is a word, and a bracket after a space that
holds a relation is an aside, not a factor:

>>> typeset("at Oc = c from the middle O, if u = mx - ny and t = nx + my; so is ce (x = a), c = a/2 (Oc = AB/4)")
'at $Oc = c$ from the middle $O$, if $u = mx - ny$ and $t = nx + my$; so is ce $(x = a)$, $c = a/2$ $(Oc = AB/4)$'

Names listed before a relation are set with it, and names listed beside one apart from it:

>>> typeset("G, g, D, h > 0; the sections G, D, g and h = 2m; through A, x = 0; for x, y in the plane, z = 1")
'$G, g, D, h > 0$; the sections $G, D, g$ and $h = 2m$; through $A$, $x = 0$; for $x$, $y$ in the plane, $z = 1$'

A range of whole numbers is a range:

>>> typeset("checked for n = 3..12 (n = 1..4; the slabs pair off)")
'checked for $n = 3, \\\\ldots, 12$ ($n = 1, \\\\ldots, 4$; the slabs pair off)'

Arrows are arrows (``->`` a limit or a map, ``<->`` an exchange):

>>> typeset("phi -> 0, the duality s <-> 1 - s")
'$\\\\varphi \\\\to 0$, the duality $s \\\\leftrightarrow 1 - s$'

>>> typeset("B = (M_xi, M_eta)/V_t and tan phi_lim(45 deg), int_0^alpha t dt, omega* the axis")
'$B = (M_{\\\\xi}, M_{\\\\eta})/V_{t}$ and $\\\\tan \\\\varphi_{\\\\lim}(45 ^{\\\\circ})$, $\\\\int_{0}^{\\\\alpha} t dt$, $\\\\omega^{*}$ the axis'
"""
from __future__ import annotations

import itertools
import re

__all__ = ["typeset", "displayed", "without_program_names"]

GREEK = ("alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu",
         "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "varphi", "chi", "psi", "omega",
         "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega")
FUNCTIONS = ("sin", "cos", "tan", "cot", "tg", "cotg", "sqrt", "arctan", "atan", "log", "exp", "int", "lim", "max",
             "min")
_TEX = {"phi": r"\varphi", "varphi": r"\varphi", "epsilon": r"\varepsilon", "atan": r"\arctan",
        "tg": r"\operatorname{tg}", "cotg": r"\operatorname{cotg}",
        "sqrt": r"\sqrt", "int": r"\int", "√": r"\sqrt", "∫": r"\int", "·": r"\cdot", "−": "-",
        "<=": r"\le", ">=": r"\ge", "!=": r"\ne", ">>": r"\gg", "<<": r"\ll", "≤": r"\le", "≥": r"\ge",
        "≠": r"\ne", "±": r"\pm", "+-": r"\pm", "-+": r"\mp", "∓": r"\mp", "oo": r"\infty",
        "*": r"\cdot", "×": r"\times", "π": r"\pi", "θ": r"\theta", "φ": r"\varphi", "ω": r"\omega", "μ": r"\mu",
        "≈": r"\approx", "→": r"\to", "->": r"\to", "<->": r"\leftrightarrow", "↔": r"\leftrightarrow",
        "≫": r"\gg", "≪": r"\ll", "∞": r"\infty", "...": r"\ldots", "…": r"\ldots", "{": r"\{", "}": r"\}",
        # Greek letters written as themselves (Euler's κ, μ, ν in the notes of §§229-243)
        "α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "ε": r"\varepsilon", "κ": r"\kappa",
        "λ": r"\lambda", "ν": r"\nu", "ξ": r"\xi", "ρ": r"\rho", "σ": r"\sigma", "τ": r"\tau", "ψ": r"\psi",
        "Γ": r"\Gamma", "Δ": r"\Delta"}
_SUPER = {"²": "2", "³": "3", "⁴": "4", "¹": "1", "⁰": "0", "⁵": "5", "⁶": "6", "⁷": "7", "⁸": "8", "⁹": "9",
          "ⁿ": "n"}
_SIGNS = "πθφωμαβγδεκλνξρστψΓΔ"      # the Greek letters above
_SECTION = re.compile(r"[IVX]+\.[A-Z](?:[-–][A-Z])?")        # a section of a chapter: VI.C, VI.C-F
# what typeset() does not set as ASCII: mathematics already in dollars, a code span, a quotation, a section
_CODE = r"``[^`]+``|`[^`]+`"                 # a code span
_FORMULA = re.compile(r"(\$[^$]*\$)")        # a formula already set: split on it, it stays as it is
_KEPT = re.compile(rf"(\$[^$]*\$|{_CODE}|(?:(?<=[\s(\[])|^)'(?:[^'\n$]|\$[^$]*\$)+?'(?![\w'])"
                   rf"|\b{_SECTION.pattern}\b)")     # a quotation holds whole formulas: '$F'(z)$ zunimmt'
_ROMAN = ("I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X", "XI", "XII")      # a chapter's numeral

_TOKEN = re.compile(r"""
    (?P<space>[ ]+)
  | (?P<locator>(?<![^\s])\(\d{1,3}[a-z]?(?:[ ]?[-–,][ ]?\d{1,3}[a-z]?)*\)(?:/\(\d{1,3}[a-z]?\))*(?![\w(/^*²³]))
                                                                        # (123), (164a-166), (77)/(78a)
  | (?P<degrees>(?:(?<=\d)|(?<=\d[ ]))deg\b)                                        # 45 deg
  | (?P<starred>\b[A-Za-z]+\*(?![\w(*]))                                           # omega*, s*
  | (?P<compound>\b[A-Za-z]-(?!(?:sin|cos|tan|cot|log|exp|sqrt)\b)[a-z]{3,}\b)        # n-gon, x-axis: a word
  | (?P<name>[A-Za-z][A-Za-z0-9]*(?:[_^](?:\{[^{}$]+\}|\d+(?=[A-Z]\w*[_^])|[A-Za-z0-9*κν]+|[+-](?![\w(])))+'?)
                                                                          # T_1^1, y^{p+1}, z_+
  | (?P<indexed>(?<!\w-)(?<!\w)(?:[A-Za-z]\d|(?=[A-Z\d]*\d)[A-Z]\d?(?:[A-Z]\d?)+)\b(?!-\w)'?)
                                                       # V1, x0': V_1, x_0'; AA1, A1B1 (not a step's name, e2-e3)
  | (?P<word>[A-Za-z](?:'{2,3}(?![\w'])|[A-Za-z]*'?(?:s\b)?))                             # y'', v''' too
  | (?P<index>[_^](?:\{[^{}$]+\}|[A-Za-z0-9*κν]+))                                   # ∫_0^b, s^*, )^κ, )^{3κ-1}
  | (?P<range>(?<![\w.])\d+\.\.\d+(?![\w.]))                                        # n = 3..12
  | (?P<number>\d+(?:\.\d+)?)
  | (?P<relation><->|<=|>=|!=|>>|<<|[=<>≤≥≠≈↔≫≪]|->|→)
  | (?P<ratio>(?<=[ ]):(?=[ ]))                                                    # I : K = EF^2 : AB^2
  | (?P<power>[²³⁴¹⁰⁵⁶⁷⁸⁹ⁿ]+)                                                       # y²ⁿ
  | (?P<operator>\+-|-\+|\.\.\.|…|[-+*/(){}±∓·×−√∫∞πθφωμαβγδεκλνξρστψΓΔ]         # a + ... + g, {a + b}
                 |\|(?=[A-Za-z0-9(√∫])|(?<=[A-Za-z0-9)'}])\|)                   # |u_x|: a bar against what it holds
  | (?P<other>.)
""", re.X | re.S)


def _kind(token: str, group: str, quoted: bool = False) -> str:
    """``strong`` (certainly mathematics), ``weak`` (mathematics inside a run), ``relation``, ``space`` or
    ``text``."""
    if group == "starred":
        return "strong" if token[:-1] in GREEK or len(token) == 2 else "text"
    if group in ("degrees", "range", "ratio"):
        return "weak"
    if group == "name":
        base = re.match(r"[A-Za-z][A-Za-z0-9]*", token).group(0)
        return "strong" if len(base) <= 3 or base in GREEK or base in FUNCTIONS else "text"
    if group == "indexed":
        return "strong"
    if group == "word":
        if token in GREEK or token in FUNCTIONS:
            return "strong"
        if len(token.rstrip("'")) == 1 or re.fullmatch(r"d[A-Za-z]", token) or token == "oo" or _differential(token) \
                or _points(token) and not quoted:
            return "weak"
        return "text"
    if group == "power":
        return "strong" if re.search("[²³⁴]", token) else "weak"
    if group in ("index", "number", "operator"):
        return "strong" if token in ("√", "∫", "²", "³", "⁴") or token in _SIGNS or group == "index" else "weak"
    return {"relation": "relation", "space": "space"}.get(group, "text")


# Words of two letters (English, the Latin and German of the sources), which a pair of points never is
_TWO_LETTER_WORDS = frozenset("ad am an as at be by da de do du eg er es et ex go he ie if im in is it me my "
                              "no ob of oh ok on or so to um up us ut vs we zu".split())


def _points(token: str) -> bool:
    """A segment or a length named by its two points (``GZ``, ``BH``; ``Cc``, ``Pp`` from a point to its
    companion; Euler's ``Oc``, ``ce``, ``wq``), not a chapter's Roman numeral (``IX``) nor a word of two
    letters (``In``, ``of``).  Alone it stays text; beside a relation sign or a formula it is a name."""
    token = token.rstrip("'")                            # GZ': a segment's derivative
    return bool(re.fullmatch(r"[A-Z]{2}", token) and token not in _ROMAN
                or re.fullmatch(r"[A-Za-z]{2}", token) and token.lower() not in _TWO_LETTER_WORDS)


def _script(text: str) -> str:
    """An index or exponent as TeX: a Greek name or an operator name at its start as its sign
    (``eta`` -> ``\\eta``, ``lim45`` -> ``\\lim 45``, ``omegac`` -> ``\\omega c``), a word upright (``rect`` ->
    ``\\text{rect}``), anything else as written."""
    for n in range(len(text), 1, -1):
        word, rest = text[:n], text[n:]
        if (word in GREEK or word in ("lim", "max", "min")) and re.fullmatch(r"\d*|[A-Za-z]", rest):
            return _TEX.get(word, "\\" + word) + (" " + rest if rest else "")
    return rf"\text{{{text}}}" if re.fullmatch(r"[a-z]{3,}", text) else text


def _scripts(text: str) -> str:
    """``_1^alpha`` -> ``_{1}^{\\alpha}``, ``^{3κ-1}`` -> ``^{3\\kappa -1}``."""
    def one(m: re.Match) -> str:
        inner = "".join(_TEX[ch] + " " if ch in _SIGNS else _TEX.get(ch, ch) if ch in "−·" else ch
                        for ch in (m.group(2) or m.group(3)))
        return f"{m.group(1)}{{{_script(inner) if m.group(3) else inner}}}"
    return re.sub(r"([_^])(?:\{([^{}$]+)\}|([A-Za-z0-9*κν]+))", one, text)


def _differential(token: str) -> bool:
    """``dmu``, ``dphi``: the differential of a Greek variable."""
    return token[0] == "d" and token[1:] in GREEK


def _tex(token: str) -> str:
    if _differential(token):
        return "d" + _tex(token[1:])
    if token in _TEX:
        return _TEX[token]
    if all(ch in _SUPER for ch in token):
        return "^{" + "".join(_SUPER[ch] for ch in token) + "}"
    if token == "deg":
        return r"^{\circ}"
    indexed = _TOKEN.fullmatch(token)
    if indexed and indexed.lastgroup == "range":                  # 3..12: from 3 to 12
        return token.replace("..", r", \ldots, ")
    if indexed and indexed.lastgroup == "indexed":                # a name or points with indices: V1, A1B1
        return re.sub(r"([A-Za-z])(\d)", r"\1_{\2}", token)
    if re.fullmatch(r"[A-Za-z]+\*", token):
        return _tex(token[:-1]) + "^{*}"
    m = re.fullmatch(r"([A-Za-z][A-Za-z0-9]*)((?:[_^](?:\{[^{}$]+\}|[A-Za-z0-9*κν]+))*)('?)", token)
    if m and (m.group(2) or m.group(1) in GREEK or m.group(1) in FUNCTIONS):
        base = m.group(1)
        base = _TEX.get(base, "\\" + base if base in GREEK or base in FUNCTIONS else base)
        scripts = _scripts(m.group(2))
        if m.group(3) and "^" in scripts:               # x_3^1', x^1_3': the prime joins the exponent
            exponent = list(re.finditer(r"\^\{(?:[^{}]|\{[^{}]*\})*\}", scripts))[-1]
            return base + scripts[:exponent.end() - 1] + r"\prime}" + scripts[exponent.end():]
        return base + scripts + m.group(3)
    if re.fullmatch(r"[_^](?:\{[^{}$]+\}|[A-Za-z0-9*κν]+)", token):
        return _scripts(token)
    return token


# Relation signs written in ASCII, never words (degree <= 3); a comparison before a number or a name opens a
# formula (and < 2c - d), and one named alone (counts it with '>=') is set too
_ASCII_SIGNS = ("<=", ">=", "!=")
_COMPARISONS = ("<", ">", "≤", "≥", "≠") + _ASCII_SIGNS


def _leading_sign(run: list, equals: bool = True) -> bool:
    """Does *run* open with a comparison or (*equals*) an equals sign that a number or a name follows (``<= 3``,
    ``!= 0``, ``and < 2c - d``, ``= 0 neutral``)?"""
    signs = (*_COMPARISONS, "=") if equals else _COMPARISONS
    return bool(run) and run[0][0] in signs and any(k not in ("space", "relation") for _, k in run[1:])


def _trim(run: list, equals: bool = True) -> list:
    """Drop spaces and unmatched brackets at the ends of a run, and a relation sign left at an end (but a sign
    that opens the run before a number or a name, ``<= 3``: see :func:`_leading_sign`)."""
    changed = True
    while run and changed:
        changed = False
        opened = sum(t == "(" for t, _ in run) - sum(t == ")" for t, _ in run)
        if run[-1][1] in ("space", "relation") or run[-1][0] == "(" or (run[-1][0] == ")" and opened < 0):
            run.pop()
            changed = True
        elif (run[0][1] in ("space", "relation") and not _leading_sign(run, equals) or run[0][0] == ")"
              or (run[0][0] == "(" and opened > 0)):
            run.pop(0)
            changed = True
    return run


def _unmatched(run: list) -> int | None:
    """The index of the first bracket of *run* that has no partner, or ``None``."""
    opened = []
    for i, (t, _) in enumerate(run):
        if t == "(":
            opened.append(i)
        elif t == ")":
            if not opened:
                return i if i > 0 else None
            opened.pop()
    return opened[0] if opened else None


def _joined(tokens) -> str:
    """TeX of the tokens, a space after a command that a letter follows (``\\int y``, not ``\\inty``), a
    root's bracket as its argument (``sqrt(b^2 - y^2)`` is ``\\sqrt{b^{2} - y^{2}}``)."""
    tokens = list(tokens)
    out, i = "", 0
    while i < len(tokens):
        t = tokens[i]
        if t in ("sqrt", "√") and i + 1 < len(tokens) and tokens[i + 1] == "(":
            depth, j = 0, i + 1
            while j < len(tokens):
                depth += {"(": 1, ")": -1}.get(tokens[j], 0)
                if depth == 0:
                    break
                j += 1
            if j < len(tokens):
                out += r"\sqrt{" + _joined(tokens[i + 2:j]) + "}"
                i = j + 1
                continue
        tex = r"\surd" if t in ("sqrt", "√") else _tex(t)       # a root sign without its bracket
        if re.search(r"\\[A-Za-z]+$", out) and re.match(r"[A-Za-z0-9]", tex):
            out += " "
        out += tex
        i += 1
    return out.strip()


def _attached(tokens: list) -> list:
    """A short word written against an operator, an index or a number (``cy²``, ``-cy``) is mathematics, and so is
    one of two letters after a plus sign that follows mathematics (Euler's ``nx + my``; not ``from - to + at``)."""
    out = list(tokens)
    for i, (t, k, g) in enumerate(tokens):
        if k == "text" and g == "word" and len(t) <= 3:
            near = [tokens[j] for j in (i - 1, i + 1) if 0 <= j < len(tokens)]
            if any(n[2] in ("operator", "power", "index", "number") and n[0] not in "()" for n in near) \
                    or len(t) == 2 and _after_sum(tokens[:i]):
                out[i] = (t, "weak", g)
    return out


def _three_points(tokens: list) -> list:
    """A name of three points (Euler's angle ACP and arc AEB, Scheeffer's angle BHG) is mathematics after a
    function (``cos ACP``) or before a relation sign (``AEB = ...``); alone it stays text, as a chapter's
    numeral (``VII``) always does."""
    out = list(tokens)
    solid = [i for i, (t, _, _) in enumerate(tokens) if not t.isspace()]
    for n, i in enumerate(solid):
        t, k, g = tokens[i]
        if k != "text" or not re.fullmatch(r"[A-Z]{3}'*", t) or t.rstrip("'") in _ROMAN:
            continue
        before = tokens[solid[n - 1]][0] if n else ""
        after = tokens[solid[n + 1]] if n + 1 < len(solid) else ("", "", "")
        if before in FUNCTIONS or after[1] == "relation":
            out[i] = (t, "weak", g)
    return out


def _applied(tokens: list) -> list:
    """A letter written against a bracket of mathematics is a function at its argument (``A(z)``, ``Y(y)``,
    ``F(1)``, ``A(z + h)``): a name, not a word, as its bracket holds no word."""
    out = list(tokens)
    for i, (t, k, g) in enumerate(tokens):
        if g != "word" or len(t.rstrip("'")) != 1 or i + 1 == len(tokens) or tokens[i + 1][0] != "(" \
                or i and re.fullmatch(r"[\w']", tokens[i - 1][0][-1]):
            continue
        depth = 0
        for u, kind, _ in tokens[i + 1:]:
            depth += {"(": 1, ")": -1}.get(u, 0)
            if depth == 0 or kind == "text" and u != ",":
                break
        if depth == 0 and u == ")" and any(kind not in ("space", "text") for _, kind, _ in tokens[i + 2:i + 3]):
            out[i] = (t, "strong", g)
    return out


def _after_sum(tokens: list) -> bool:
    """Do *tokens* end, spaces aside, in a plus sign after mathematics (``nx +``, not ``to +``)?"""
    last = [(t, k) for t, k, g in itertools.islice(reversed(tokens), 4) if g != "space"][:2]
    return len(last) == 2 and last[0][0] == "+" and last[1][1] != "text"


_ARITHMETIC = ("+", "-", "*", "/", "·", "×", "−")


def _arithmetic(run: list) -> bool:
    """A sum, difference, product or quotient with a letter or a differential among its terms (``n + 1/n``,
    ``x/b``, ``S - 2``, ``b(1-s)``, ``dE/dt``); a hyphen between words (the slab ``a-c``, sections ``I-III``,
    ``e2-e3``) is no minus: a minus is spaced or inside the formula's bracket."""
    letters = [t.rstrip("'") for t, _ in run if re.fullmatch("[A-Za-z]+'*", t)]      # F' is a letter
    named = any(len(t) == 1 or re.fullmatch(r"d[A-Za-z]", t) and t not in _TWO_LETTER_WORDS for t in letters)
    if not named or all(t in _ROMAN for t in letters) and any(len(t) > 1 for t in letters):
        return False
    depth = 0
    for i, (t, k) in enumerate(run):
        depth += {"(": 1, ")": -1}.get(t, 0)
        if t not in _ARITHMETIC or not 0 < i < len(run) - 1:
            continue
        left = next((u for u, j in run[i - 1::-1] if j != "space"), "(")
        right = next((u for u, j in run[i + 1:] if j != "space"), ")")
        spaced = run[i - 1][1] == "space" and run[i + 1][1] == "space"
        if left not in ("(", *_ARITHMETIC) and right not in (")", *_ARITHMETIC) and (
                t not in ("-", "−") or spaced or depth > 0):
            return True
    return False


def _aside(tokens: list, i: int) -> bool:
    """Does the bracket opened at *tokens[i]* hold a relation (``(x = a)``, ``(Oc = AB/4)``)?  After a space such
    a bracket is an aside to the formula before it, never a factor of it."""
    depth = 0
    for token, kind in tokens[i:]:
        depth += {"(": 1, ")": -1}.get(token, 0)
        if depth == 0:
            return False
        if kind == "relation" and depth == 1:
            return True
    return False


_CHAPTER_WORDS = frozenset({"Scheeffer", "section", "sections", "Section", "chapter", "Chapter", "part", "row", "rows"})


# what follows a name a, never the article ("edges a, b", "from a to c")
_AFTER_A = frozenset(",;:.") | {"to"}
# what follows a point A opening a sentence ("A lies on", "A at x = 0"), never the article
_AFTER_A_POINT = frozenset(",;:.") | frozenset("and or is lies at to on in of has moves with from are".split())


def _names(tokens: list, followed: bool = False) -> list:
    """A letter alone between words is a name (the centroid C, the edges a, b, c, the x axis), a formula of its
    own; not the article (``a box``, ``A`` opening a sentence), a chapter's numeral (Scheeffer X, section V), a
    label in brackets (``(b)``), a letter of an abbreviation (``i.e.``) or the ``s`` after a curly apostrophe
    (``Euler’s``).  *followed*: a formula follows the tokens (``a $Y$-dependent centroid``).  A name after a sign in
    brackets and a space (``above (-) B``) is of kind ``name``: it starts a formula of its own."""
    out = list(tokens)
    solid = [i for i, (t, _, _) in enumerate(tokens) if not t.isspace()]
    for n, i in enumerate(solid):
        t, k, g = tokens[i]
        if g != "word" or k != "weak" or len(t.rstrip("'")) != 1:
            continue
        before = out[solid[n - 1]] if n else None           # an article before it is a word
        after = tokens[solid[n + 1]] if n + 1 < len(solid) else None
        listed = after is not None and after[0] in ("and", "or", "for") and n + 2 < len(solid) \
            and re.fullmatch(r"[A-Za-z]'?", tokens[solid[n + 2]][0])          # a and c; a for x (read instead)
        among_words = (before is None or before[1] == "text" or before[0] == "(") and (
            after is None and followed or after is not None and (after[1] == "text" or t == "A" and after[2] == "word"))
        if t == "a" and not listed and (among_words and (after is None or after[0] not in _AFTER_A) or (
                before is None or before[1] == "text") and after is not None and after[2] == "number"):
            out[i] = (t, "text", g)                      # the article: a box, a $Y$-dependent centroid, a 3 × 3 grid
            continue
        if t == "A" and among_words and (before is None or before[0] in ".:;!?") and not listed and (
                after is None or after[0] not in _AFTER_A_POINT):
            out[i] = (t, "text", g)                      # the article opening a sentence: A box, A '$yy$'
            continue
        opens, closes = before is not None and before[0] == "(", after is not None and after[0] == ")"
        aside = after is not None and after[0] == "(" and tokens[i + 1][0].isspace()       # c (density s)
        behind = before is not None and before[0] == ")" and tokens[i - 1][0].isspace() and n >= 3 \
            and tokens[solid[n - 2]][0] in "+-−±" and tokens[solid[n - 3]][0] == "("    # a sign: above (-) B
        if opens and closes or any(x is not None and x[1] != "text" for x in (before, after)
                                   if not (x is before and (opens or behind) or x is after and (closes or aside))):
            continue                                     # a label (b); beside mathematics: in a run already
        if i > 0 and not tokens[i - 1][0].isspace() and not opens:
            continue                                     # Euler’s, —a
        if i + 1 < len(tokens) and not tokens[i + 1][0].isspace() and not closes and (
                tokens[i + 1][0] not in ",;:." or i + 2 < len(tokens) and not tokens[i + 2][0].isspace()):
            continue                                     # i.e., a label a)
        if t in _ROMAN:
            words = [x[0] for x in tokens[:i] if x[2] in ("word", "name", "indexed")
                     and x[0] not in ("and", "or") and x[0] not in _ROMAN]
            cited = n >= 2 and tokens[solid[n - 1]][0] == "of" and tokens[solid[n - 2]][2] in ("number", "locator")
            if words and words[-1] in _CHAPTER_WORDS or cited or after is not None and after[0] == ".":
                continue                    # Scheeffer 1902, X; section V; rows I and V; (171) of X; II. as a heading
        out[i] = (t, "name" if behind else "strong", g)
    return out


_SUBSCRIPTS = dict(zip("₀₁₂₃₄₅₆₇₈₉", "0123456789"))
_LETTER_POWERS = dict(zip("ᵃᵇᶜᵈᵉᵏᵐᵖᵗˣʸ", "abcdekmptxy"))
# a Unicode index or a power of letters written against a name (not a number's superscript digits, which
# the tokenizer reads as powers): K₀, tan² φ₀, ∫₀ᵇ yᵖ dy
_UNICODE_SCRIPT = re.compile(rf"(?<=[A-Za-z0-9)\u0370-\u03ff∫{''.join(_SUBSCRIPTS)}])(?:([{''.join(_SUBSCRIPTS)}]+)"
                             rf"|([{''.join(_LETTER_POWERS)}]+))")


def _ascii_script(m: re.Match) -> str:
    """A Unicode index or letter power as the ASCII the tokenizer reads (``₀`` -> ``_0``, ``ᵇ`` -> ``^b``)."""
    if m.group(1):
        return "_" + "".join(_SUBSCRIPTS[c] for c in m.group(1))
    return "^" + "".join(_LETTER_POWERS[c] for c in m.group(2))


def _typeset_plain(text: str, quoted: bool = False, followed: bool = False) -> str:
    """*text* typeset; *quoted*: the source's words in quotation marks, where a segment's name or a difference of
    letters stays as the source wrote it (``'h/3{2D - (G+g)/2}'``, ``'Ac = a - c'``); *followed*: more of the
    text (a formula, a quotation) follows it."""
    text = re.sub(r"((?<![\w.])[A-Za-z]|\))\.(?=\()", r"\1·", text)     # u.(G - B), (du).(G - B): a product
    text = re.sub(r"(?<=[\w)])\*\*(?=[\w(])", "^", text)                 # a**2: a power
    text = re.sub(r"\bsqrt\{([^{}$]*)\}", r"sqrt(\1)", text)              # sqrt{2}: a root
    text = _UNICODE_SCRIPT.sub(_ascii_script, text)                   # K₀, φ₀, ∫₀ᵇ yᵖ: an index, a power
    text = re.sub(r"(?<![\w.])(\d+(?:/\d+)?) x (?=\d)", r"\1 × ", text)     # the box 1 x 1 x 2: a product
    tokens = [(m.group(0), _kind(m.group(0), m.lastgroup, quoted), m.lastgroup) for m in _TOKEN.finditer(text)]
    tokens = _three_points(_applied(_attached(tokens)))
    tokens = [(t, k) for t, k, _ in (tokens if quoted else _names(tokens, followed))]
    out, run = [], []

    def flush():
        nonlocal run
        if [t for t, k in run if k != "space" and t not in "()"] in ([sign] for sign in _COMPARISONS):   # '>='
            out.append("".join(f"${_tex(t)}$" if k == "relation" else t for t, k in run))
            run = []
            return
        lead = []
        # in a quotation an equals sign opens a formula only where the quotation opens: '= 0', not 'Ac = a - c'
        equals = not quoted or not "".join(out).strip()
        while run and (run[0][1] in ("space", "relation") or run[0][0] in (")", "×")) \
                and not _leading_sign(run, equals):
            lead.append(run.pop(0)[0])
        tail = []
        while run and (run[-1][1] in ("space", "relation") or run[-1][0] in ("(", ",", "×")):    # (a) × (words)
            tail.insert(0, run.pop()[0])
        core = _trim(list(run), equals)
        cut = _unmatched(core)
        if cut is not None:                      # a bracket the run does not close: the formula ends before it
            at = run.index(core[0]) + cut
            bracket, rest = run[at][0], run[at + 1:] + [(t, "space") for t in tail]
            run = run[:at]
            out.append("".join(lead))
            flush()
            out.append(bracket)
            run = rest                           # and the formula after it is one of its own
            flush()
            return
        if core and (any(k == "strong" for _, k in core) or not quoted and _arithmetic(core)
                     or any(k == "relation" for _, k in core) and len([k for _, k in core if k == "weak"]) >= 2
                     or any(t in _ASCII_SIGNS for t, _ in core) or _leading_sign(core, equals)):
            start = run.index(core[0])
            end = start + len(core)
            before = "".join(t for t, _ in run[:start])
            after = "".join(t for t, _ in run[end:])
            out.append("".join(lead) + before + "$" + _joined(t for t, _ in core) + "$" + after
                       + "".join(tail))
        else:
            out.append("".join(lead) + "".join(t for t, _ in run) + "".join(tail))
        run = []

    for i, (token, kind) in enumerate(tokens):
        if token == "(" and run and run[-1][1] == "space" and _aside(tokens, i):
            flush()                              # ef (x = a), c = a/2 (Oc = AB/4): an aside, not a factor
        if kind == "name":                       # a name after a bracket and a space: above (-) B
            flush()
            kind = "strong"
        if token == "," and sum({"(": 1, ")": -1}.get(t, 0) for t, _ in run) > 0:
            run.append((token, "weak"))          # B((p+1)/n, q+1): a comma inside the formula's bracket
        elif kind == "text":
            flush()
            out.append(token)
        else:
            run.append((token, kind))
    flush()
    return "".join(out) if quoted else _listed("".join(out))


# a list of one-letter names before a formula that starts with a name and a relation: ``a, b, $c > 0$`` (two names
# at least: one is as likely the end of a phrase, ``through A, $x = 0$``)
_ONE = r"(?:[A-Za-z]|\$[A-Za-z]'?\$)"       # a one-letter name, set by _names as a formula of its own
_LISTED = re.compile(rf"(?<![\w$'’])((?:{_ONE}, ){{2,}}|(?:{_ONE}, )+(?={_ONE} and ))"
                     rf"(?:\$|({_ONE}) and \$)"
                     r"(?=(?:[A-Za-z]|\\[A-Za-z]+)(?:_\{[^{}$]*\}|_[A-Za-z0-9])?'? (?:[<>=]|\\(?:le|ge|ne)\b))")


def _listed(text: str) -> str:
    """The names listed before a relation set with it: ``a, b, $c > 0$`` is ``$a, b, c > 0$``; names joined to the
    relation's by "and" are a formula of their own (``$G, D, g$ and $h = 2m$``).  A single letter followed by a
    comma is no article."""
    def one(m: re.Match) -> str:
        names = m.group(1).replace("$", "")
        if m.group(2) is None:
            return "$" + names
        return "$" + names + m.group(2).replace("$", "") + "$ and $"
    return _LISTED.sub(one, text)


def _code_formula(code: str) -> str | None:
    r"""A code span whose every token is mathematics, as one formula: a letter (``b``, ``x'``), a list of them
    (``a, b, …, g``), points naming a plane (``ABC``), a coefficient and a letter (``2m``), a relation of them
    (``x < x'``); ``None`` for anything with a word in it or a name of the program.

    >>> [_code_formula(c) for c in ("a, b, …, g", "ABC", "2m", "x < x'", "A(u)", "graefe-s4-ship-centroid", "IX")]
    ['$a, b, \\ldots, g$', '$ABC$', '$2m$', "$x < x'$", '$A(u)$', None, None]
    """
    if _program_name(code) or code.strip() in _ROMAN:
        return None
    tokens = [m.group(0) for m in _TOKEN.finditer(code)]
    kinds = [_kind(m.group(0), m.lastgroup) for m in _TOKEN.finditer(code)]
    mathematics = all(k != "text" or t in ",[]" or re.fullmatch(r"[A-Za-z]'|[A-Z]{2,4}", t)
                      for t, k in zip(tokens, kinds))
    return f"${_joined(tokens)}$" if mathematics and any(k != "space" for k in kinds) else None


_MEMBER = r"(?:\$[^$\n]*\$|[^\[\]$,\n]){1,40}?"
_INTERVAL = re.compile(rf"\[({_MEMBER}), ({_MEMBER})\](?!\()")         # [-1/2, 1/2], [$s_{-}$, $s_{+}$]
_PRODUCT = re.compile(r"\$(\[[^$]*\])\$ x \$(\[[^$]*\])\$")                 # [-a, a] x [-b, b]: a product


def _intervals(text: str) -> str:
    """An interval written in brackets, both ends mathematics (numbers, names, formulas), as one formula; the
    letter x between two intervals is their product:

    >>> _intervals("xi in [-1/2, 1/2], outside [$s_{-}$, $s_{+}$], [x_1, x_2] x [y_1, y_2]; [see, §4], `[0, 1]`")
    'xi in $[-1/2, 1/2]$, outside $[s_{-}, s_{+}]$, $[x_{1}, x_{2}] \\\\times [y_{1}, y_{2}]$; [see, §4], `[0, 1]`'
    """
    def member(piece: str) -> str | None:
        if re.fullmatch(r"\$[^$]*\$", piece):
            return piece[1:-1]
        formula = _code_formula(piece)
        return formula[1:-1] if formula else None

    code = [c.span() for c in re.finditer(_CODE, text)]

    def one(m: re.Match) -> str:
        if text[:m.start()].count("$") % 2 or any(a < m.end() and m.start() < b for a, b in code):
            return m.group(0)                           # inside a formula or a code span already
        ends = [member(piece) for piece in m.groups()]
        return m.group(0) if None in ends else f"$[{ends[0]}, {ends[1]}]$"
    done = _INTERVAL.sub(one, text)
    return _PRODUCT.sub(lambda m: f"${m.group(1)} \\times {m.group(2)}$", done)


def typeset(text: str) -> str:
    """*text* with its ASCII mathematics typeset as ``$…$``; existing ``$…$`` spans and code spans are left alone,
    except a code span holding mathematics (````tan phi_1````), which becomes a formula; in a quotation (``'…'``,
    the source's words) only what is certainly mathematics is set; an interval in brackets is a formula."""
    parts = _KEPT.split(_intervals(text))
    out = []
    for i, part in enumerate(parts):
        if part.startswith("$") or _SECTION.fullmatch(part):      # mathematics, a section (VI.C-F): as they are
            out.append(part)
        elif part.startswith("'"):                  # the marks are no prime of the quotation's last name
            out.append("'" + "".join(piece if piece.startswith("$") else _typeset_plain(piece, quoted=True)
                                     for piece in _FORMULA.split(part[1:-1])) + "'")
        elif part.startswith("`"):
            inner = part.strip("`")
            done = _typeset_plain(inner)
            if not (done.startswith("$") and done.endswith("$") and done.count("$") == 2):
                done = _code_formula(inner) or part
            out.append(done)
        else:
            out.append(_signs_in_words(_typeset_plain(part, followed=i + 1 < len(parts) and bool(parts[i + 1]))))
    return "".join(out)


_WORD_SIGNS = {"+-": "±", "-+": "∓"}


def _signs_in_words(text: str) -> str:
    """Signs written in ASCII among words, outside any formula: an angle (``at 45 deg``, ``20 deg 3' 34.50''``)
    with its sign, ``45°`` (in a formula the degrees are ``^{\\circ}``), and a sign named alone (``the +- read
    through the square``) as itself, ``±``."""
    def words(piece: str) -> str:
        piece = re.sub(r"(?<=\d) deg\b", "°", piece)
        return re.sub(r"(?<!\S)(\+-|-\+)(?!\S)", lambda m: _WORD_SIGNS[m.group(1)], piece)
    return "".join(piece if piece.startswith("$") else words(piece) for piece in _FORMULA.split(text))


# a name of the program: dotted (``symfloat.geometry.floating``, ``Body.cylinder``), or in a code span a word
# of four letters or more, words joined by underscores or a slug (``crossing``, ``potential_slope``,
# ``righting-moment-12``), with the word that says what it names
_DOTTED = r"[A-Za-z_][A-Za-z0-9_]*(?:\.\n?[a-z_][A-Za-z0-9_]{2,})+"        # a line may break after a dot
_PROGRAM = re.compile(rf"(?:(?:function|module|class|steps?|method)\s+)?"
                      rf"(?:``?(?:{_DOTTED}|[A-Za-z]{{4,}}|[a-z]+(?:_[a-z]{{3,}})+|[a-z0-9]+(?:-[a-z0-9]+)+)``?"
                      rf"|(?<![\w.`]){_DOTTED}(?![\w`]))")


def _program_name(text: str) -> bool:
    """Is *text* (a bracket's item) a name of the program, not mathematics (``Omega``) or words?"""
    m = _PROGRAM.fullmatch(text.strip())
    return m is not None and m.group(0).split()[-1].strip("`") not in GREEK + FUNCTIONS


_INDENTED = re.compile(r"^[ \t]{4,}(\S.*)$", re.M)
_ONE_FORMULA = re.compile(r"\$([^$]+)\$([.,;:]?)")


def displayed(markdown: str) -> str:
    r"""*markdown* (a docstring, typeset) with its indented lines, a formula set apart in plain text, made
    displayed formulas: Markdown would show an indented line as code, its TeX as written.  A line that is one
    formula becomes a display (its punctuation inside); a line of several is set in the text.

    >>> displayed("their sum is\n\n    $X V = m^{2}/3$.\n\nwith\n\n    $G = A(0)$, $g = A(h)$,\n")
    'their sum is\n\n$$X V = m^{2}/3 .$$\n\nwith\n\n$G = A(0)$, $g = A(h)$,\n'
    """
    def line(m: re.Match) -> str:
        one = _ONE_FORMULA.fullmatch(m.group(1).rstrip())
        return f"$${one.group(1)}{' ' + one.group(2) if one.group(2) else ''}$$" if one else m.group(1)
    return _INDENTED.sub(line, markdown)


def without_program_names(text: str) -> str:
    """*text* without the names of the program it cites (a module, a class, a function, a step): such a name
    goes from the bracket that holds it, and a bracket left empty goes.

    >>> without_program_names("clip the polyhedra (symfloat.geometry.floating) and the cylinder "
    ...                        "(Body.cylinder, exact slices); (12) (section II, steps ``moment-12``, ``m-13``)")
    'clip the polyhedra and the cylinder (exact slices); (12) (section II)'
    """
    def bracket(m: re.Match) -> str:
        items = m.group(2).split(", ")
        kept = [item for item in items if not _program_name(item)]
        if len(kept) == len(items):
            return m.group(0)
        return f"{m.group(1)}({', '.join(kept)})" if kept else ""

    return re.sub(r"(\s*)\(([^()]*)\)", bracket, text)
