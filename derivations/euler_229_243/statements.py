"""What Euler's §§229-243 say and how each formula is derived (see the package's docstring)."""

import sympy as sp
from sympy.core.cache import cacheit
from sympy.core.evalf import prec_to_dps

from symfloat import Derivation, Eq, Erratum, Holds
from symfloat.model.claim import as_printed
from symfloat.model.symbol_names import symbol
from symfloat.model.vocabulary import Compares, GrowsWith, Is

y, s, m = sp.symbols("y s m", positive=True)
a, b, c, n, k = sp.symbols("a b c n kappa", positive=True)
p, q = sp.symbols("p q", positive=True)
xk = sp.Symbol("x", positive=True)       # the letter x the transcription prints for the exponent κ
al = sp.Symbol("alpha", positive=True)   # the α it prints for a
c1, c2 = sp.symbols("c_1 c_2", real=True)
Ys = sp.Symbol("Y", real=True)           # the value Y(y) of the function at one ordinate
n1, k1 = sp.symbols("n_1 kappa_1", positive=True)
zl = sp.Symbol("z", positive=True)
Dprime = sp.Symbol("D'", positive=True)   # the stray D' of §241      # the letter z the transcription prints for the digit 2 of '2D'
aY, bY, gY = sp.symbols("alpha_Y beta_Y gamma_Y", positive=True)   # the coefficients of §231's Y


def _beta_value(P, Q, N_, B_):
    return B_ ** (P + 1) * sp.gamma((P + 1) / N_) * sp.gamma(Q + 1) / (N_ * sp.gamma((P + 1) / N_ + Q + 1))


def _dps(prec):
    return prec_to_dps(prec) + 5


_t = sp.Dummy("t", positive=True)       # the variable of integration of IY's expansion (one for every call)


@cacheit
def _beta_terms(j, P, Q, dY, N_, B_, C1, C2):
    """IY's expansion into Beta integrals, once per argument list: a claim's two sides, and the links of a
    chain, meet the same integrals at the same sampled point."""
    Yt = C1 * _t ** N_ / B_ ** N_ + C2 * _t ** (2 * N_) / B_ ** (2 * N_)
    w = sp.expand(Yt ** j * _t ** P * (sp.diff(Yt, _t) if dY else 1), power_base=False)
    total = 0
    for term in sp.Add.make_args(w):
        coeff, e = term.as_coeff_exponent(_t)
        total += coeff * _beta_value(e, Q, N_, B_)
    return total


class Ib(sp.Function):
    """∫₀ᵇ yᵖ (1 − yⁿ/bⁿ)^q dy, arguments (p, q, n, b); numerically its Beta closed form (step beta-integral)."""
    nargs = 4

    def _eval_evalf(self, prec):
        if not all(t.is_number for t in self.args):
            return None
        return sp.N(_beta_value(*self.args), _dps(prec))

    def _eval_rewrite_as_gamma(self, *args, **hints):
        """Its Beta closed form in Γ (step beta-integral proves it), for a rigorous enclosure."""
        return _beta_value(*args)

    def _latex(self, printer, exp=None):
        P, Q, N_, B_ = (printer._print(t) for t in self.args)
        yp = {"0": "", "1": "y"}.get(P, "y^{%s}" % P)
        tex = r"\int_0^{%s} %s\left(1-\frac{y^{%s}}{%s^{%s}}\right)^{%s}dy" % (B_, yp, N_, B_, N_, Q)
        return tex if exp is None else r"\left(%s\right)^{%s}" % (tex, exp)


class IY(sp.Function):
    """∫₀ᵇ Y^j yᵖ (1 − yⁿ/bⁿ)^q dy (dY = 0) or ... dY (dY = 1), arguments (j, p, q, dY, n, b, c_1, c_2),
    for Y = c_1 yⁿ/bⁿ + c_2 y²ⁿ/b²ⁿ: expanded into Beta integrals (checked in step Y-integrals)."""
    nargs = 8

    def fdiff(self, argindex=1):
        """d/dc_1 and d/dc_2 (arguments 7 and 8) under the integral: Y^j gives j Y^(j-1) y^(kn)/b^(kn) and dY
        gives k n y^(kn-1)/b^(kn) dy (k = 1, 2); the others have no rule here."""
        if argindex not in (7, 8):
            raise sp.ArgumentIndexError(self, argindex)
        j, P, Q, dY, N_, B_, C1, C2 = self.args
        k = argindex - 6
        scale = B_ ** (k * N_)
        out = j / scale * IY(j - 1, P + k * N_, Q, dY, N_, B_, C1, C2) if j != 0 else sp.Integer(0)
        if dY:
            out += k * N_ / scale * IY(j, P + k * N_ - 1, Q, 0, N_, B_, C1, C2)
        return out

    def _eval_evalf(self, prec):
        if not all(t.is_number for t in self.args):
            return None
        return sp.N(self._beta_terms(*self.args), _dps(prec))

    def _eval_rewrite_as_gamma(self, *args, **hints):
        """Its expansion into Beta integrals in Γ (step Y-integrals proves it), for a rigorous enclosure; only
        with numbers for its arguments (the power Y^j is expanded)."""
        return self._beta_terms(*args) if all(t.is_number for t in args) else None

    @staticmethod
    def _beta_terms(j, P, Q, dY, N_, B_, C1, C2):
        return _beta_terms(j, P, Q, dY, N_, B_, C1, C2)

    def _latex(self, printer, exp=None):
        j, P, Q, dY, N_, B_, C1, C2 = self.args
        pr = printer._print
        Yp = "" if j == 0 else ("Y" if j == 1 else "Y^{%s}" % pr(j))
        yp = "" if P == 0 else ("y" if P == 1 else "y^{%s}" % pr(P))
        at = "" if (C1, C2) == (c1, c2) else r"\Big|_{Y = %s y^{%s}/%s^{%s}}" % (pr(C1), pr(N_), pr(B_), pr(N_))
        tex = r"\int_0^{%s} %s %s\left(1-\frac{y^{%s}}{%s^{%s}}\right)^{%s} %s%s" % (
            pr(B_), Yp, yp, pr(N_), pr(B_), pr(N_), pr(Q), "dY" if dY else "dy", at)
        return tex if exp is None else r"\left(%s\right)^{%s}" % (tex, exp)


def quotient(p, q):
    """p / q kept as a quotient (at kappa = 1/2 numerator and denominator coincide: N = 1 is then checked,
    not made 1 on building)."""
    return sp.Mul(p, sp.Pow(q, -1, evaluate=False), evaluate=False)


def J(P, Q, N_=n):
    return Ib(P, Q, N_, b)


def JY(j, P, Q, dY=0, C1=c1, C2=c2):
    return IY(j, P, Q, dY, n, b, C1, C2)


R = (1 - y ** n / b ** n) ** k
Rx = (1 - y ** n / b ** n) ** xk          # as printed, with x for κ

XA, XB, D, IAB, MO, SO, XC, CO, KEF, Kc, N, K0g = sp.symbols("x_A x_B D I_{AEB} M_O S_O x_C CO K_{EF} K_c N K_0")
M, V, OG, EF, AB, Dw, CD, mu, nu = sp.symbols("M V OG EF AB D_w CD mu nu", positive=True)
Iw, Kw, SAB, SEF, SABp, Vpy, Vpr, Vwe = sp.symbols("I_w K_w S_{AB} S_{EF} S_{AB+} V_{pyr} V_{prism} V_{wedge}")
fb, Hh, Tq = sp.symbols("f H T", positive=True)   # §240: the share of ballast, the hull's height and draught

DERIVATION = d = Derivation(
    id="euler-229-243",
    source="euler",
    title="Waterplanes whose breadth is a power of 1 − yⁿ/bⁿ: the number μ, stability and displacement "
          "(Euler, Scientia navalis III §§229–243)",
    locator="§229–§243",
    summary="Area, moments and centroid of the waterplanes x = a + Y ± a(1 − yⁿ/bⁿ)^κ (§229–232); the "
            "moment about the latitudinal axis through the centroid, with Euler's N, and the tables of §233–234 rebuilt exactly from "
            "Beta integrals; the limits n → ∞ and the cases of §236; the numbers μ of §237 (rectangle, "
            "rhombus, ellipse, parabola, and the bounds 6 ≤ μ ≤ 12 over the admissible family); the "
            "stability M(EF²D/(μV) − OG) and the displacement bounds of §238–243.",
    requires=("euler-192-219",),
    domain={a: (1, 3), b: (1, 2), c: (sp.Rational(1, 10), 1), n: (1, 4), k: (sp.Rational(1, 2), 3),
            p: (0, 3), q: (sp.Rational(1, 2), 3), xk: (sp.Rational(1, 2), 3), al: (1, 3),
            c1: (-1, 1), c2: (-1, 1), Ys: (-1, 1), y: (0, 1), s: (0, 1), m: (0, 1),
            n1: (1, 8), k1: (sp.Rational(1, 10), 1),
            M: (1, 5), V: (1, 5), OG: (0, 2), EF: (1, 3), AB: (3, 12), Dw: (1, 10), CD: (1, 3),
            mu: (6, 12), nu: (6, 12), zl: (1, 3), Dprime: (1, 10), aY: (1, 2), bY: (1, 2), gY: (1, 2),
            fb: (0, 1), Hh: (2, 3), Tq: (sp.Rational(1, 2), 2)},
    assumptions=("a, b, c > 0; the exponents n > 0 and κ > 0 (the integrals converge); 0 < y < b",
                 "Y(y) is sampled as c_1 yⁿ/bⁿ + c_2 y²ⁿ/b²ⁿ (a function vanishing at y = 0, of the kind §231 "
                 "allows); the rules derived for it are linear or quadratic in Y and hold termwise",
                 "integrals ∫ … dy run from y = 0 to y = b (Euler: taken to vanish at y = 0, then y = b)",
                 "the ship of §238–243: weight M, displacement V, G at the height OG above the centre of "
                 "buoyancy O; D_w is Euler's D there (half the waterplane area), CD the depth of the keel",
                 "a Latin v in a denominator of §239–243 is read as the volume V (as in §203); ν as ν",
                 "§240's hull: height H, draught T < H, the share f of the weight as ballast on the keel, the "
                 "rest spread evenly over the height (0 < f < 1)"),
)


def claim(text):
    return "The paragraph claims: " + text


# ================================================================ Beta integrals
d.step("beta-integral", (Ib(p, q, n, b), sp.Integral(y ** p * (1 - y ** n / b ** n) ** q, (y, 0, b)),
                         _beta_value(p, q, n, b)), "integration",
       note="y = b t^{1/n} turns the integral into b^{p+1}/n · B((p+1)/n, q+1), the Beta function in Γ form")
d.step("Y-integrals", (sp.Matrix([JY(1, 0, k), JY(2, 0, k), JY(0, 1, k, 1), JY(1, n, k - 1)]),
                       sp.Matrix([c1 / b ** n * J(n, k) + c2 / b ** (2 * n) * J(2 * n, k),
                                  c1 ** 2 / b ** (2 * n) * J(2 * n, k) + 2 * c1 * c2 / b ** (3 * n) * J(3 * n, k)
                                  + c2 ** 2 / b ** (4 * n) * J(4 * n, k),
                                  n * c1 / b ** n * J(n, k) + 2 * n * c2 / b ** (2 * n) * J(2 * n, k),
                                  c1 / b ** n * J(2 * n, k - 1) + c2 / b ** (2 * n) * J(3 * n, k - 1)])),
       "integration", note="the integrals with Y = c_1 yⁿ/bⁿ + c_2 y²ⁿ/b²ⁿ (y dY = (nc_1 yⁿ/bⁿ + 2nc_2 y²ⁿ/b²ⁿ)dy) "
                           "are sums of the Beta integrals of beta-integral")
d.step("recurrence-power", (Ib(p + n, q, n, b), b ** n * (p + 1) * Ib(p, q, n, b) / (p + 1 + n * (q + 1))),
       "integration",
       note="R = 1 − yⁿ/bⁿ here: ∫y^p R^{q+1} = ∫y^p R^q − ∫y^{p+n}R^q/bⁿ, and by parts "
            "∫y^p R^{q+1} = (n(q+1)/((p+1)bⁿ))∫y^{p+n}R^q")
d.step("recurrence-exponent", (Ib(0, q + 1, n, b), n * (q + 1) * Ib(n, q, n, b) / b ** n,
                               Ib(0, q, n, b) - Ib(n, q, n, b) / b ** n), "integration",
       note="∫R^{q+1}dy = [yR^{q+1}] + (n(q+1)/bⁿ)∫yⁿR^q dy, and R^{q+1} = R^q(1 − yⁿ/bⁿ)")

# ================================================================ §229: the portions, the chord, the area
d.step("portion-Ace", Eq(XA, a + Ys - a * R), "definition", result=XA,
       note="§229: AP of the portion Ace at the ordinate PM = y; Y is Y(y)")
d.step("portion-Bce", Eq(XB, a + Ys + a * R), "definition", result=XB, note="Ap of the portion Bce")
d.step("chord", (XB - XA, 2 * a * R), "algebra", uses=("portion-Ace", "portion-Bce"),
       note="the chord Mm at the ordinate y: Y cancels")
d.step("PO", (a - XA, -Ys + a * R), "algebra", uses=("portion-Ace",), note="O is at x = a")
d.step("pO", (XB - a, Ys + a * R), "algebra", uses=("portion-Bce",))
d.step("strip-moment-O", (sp.Integral((s - a) ** 2, (s, XA, XB)), ((XB - a) ** 3 + (a - XA) ** 3) / 3,
                          2 * a ** 3 * R ** 3 / 3 + 2 * a * R * Ys ** 2), "integration",
       uses=("PO", "pO"), note="the chord's second moment about the normal to AB through O")
d.step("strip-first-moment-O", (sp.Integral(s - a, (s, XA, XB)), 2 * a * R * Ys), "integration")
d.step("strip-moment-C", (sp.Integral((s - a - m) ** 2, (s, XA, XB)),
                          sp.Integral((s - a) ** 2, (s, XA, XB)) - 2 * m * sp.Integral(s - a, (s, XA, XB))
                          + m ** 2 * (XB - XA)), "integration",
       note="about a parallel at the distance m from O (used with m = x_C − a)")
d.step("area", (D, sp.Integral(2 * a * R, (y, 0, b)), 2 * a * J(0, k)), "integration", uses=("chord",),
       result=D, note="D is the area of the half AEB (above AB): the chords Mm summed over 0 ≤ y ≤ b")
d.quote("chord", "§229", "erit ergo $Mm =$\n $2a\\left(1 - \\frac{y^n}{b^n}\\right)^x$, vnde area",
        reading=(XB - XA, 2 * a * Rx),
        erratum=Erratum("transcription", "high", r"Mm = 2a\left(1 - \frac{y^n}{b^n}\right)^\kappa",
                        r"The portions are $x = a + Y \mp aR$ with the exponent $\kappa$ ($\kappa$ is printed in "
                        r"§231–236); the $x$ of the transcription is the Greek $\kappa$ misread ($x$ is the abscissa "
                        "$AP$).",
                        corrected_reading=(XB - XA, 2 * a * R),
                        objection=r"The exponent is printed $x$ in all seven formulas of §229–230 and never $\kappa$ "
                                  "there; a letter that runs the same way through two paragraphs may be Euler's own in "
                                  r"the print ($\kappa$ first named in §231), not a glyph the scan lost once.",
                        answer=("The same sentence defines $AP = x$, and Euler would not give the exponent the "
                                "letter of the abscissa in the very equation that defines it ($x = a + Y - "
                                r"a(\dots)^x = AP$); §231 speaks of $\kappa$ as a letter already in play ('et "
                                r"$\kappa$ denotet vel numerum integrum vel fractum'), and §232–236 print $\kappa$ "
                                r"where these formulas return. The old form of the letter, $\varkappa$, has the shape of an $x$, a "
                                "glyph the scan confuses, and one misread glyph repeats on consecutive lines: high.")),
        note=claim("the chord between the two portions is Mm = 2a(1 − yⁿ/bⁿ)^κ."))
d.quote("area", "§229", r"area AEB prodibit $= 2a \int dy \left(1 - \frac{y^n}{b^n}\right)^x = D$",
        reading=(D, 2 * a * J(0, xk)),
        erratum=Erratum("transcription", "high", r"= 2a \int dy \left(1 - \frac{y^n}{b^n}\right)^\kappa = D",
                        r"$x$ for $\kappa$, as in the chord $Mm$.", corrected_reading=(D, 2 * a * J(0, k)),
                        objection="As for the chord: $x$ may be the print's letter for the exponent in §229–230.",
                        answer=(r"$D = 2a\int dy\, (1 - y^n/b^n)^\kappa$ returns with $\kappa$ in §231 ('$\int dy\, "
                                r"(1 - y^n/b^n)^\kappa = D/2a$') and §233 ('$= ND/2a$'), and $x$ is the abscissa AP "
                                r"of the same sentence; the $\varkappa$ read as $x$, high.")),
        note=claim("the area of AEB is D = 2a∫dy(1 − yⁿ/bⁿ)^κ, whatever Y (the chord does not contain Y)."))

KAPPA_AS_X = "euler-229-243/chord"
d.quote("portion-Ace", "§229", r"$x = a + Y - a\left(1 - \frac{y^n}{b^n}\right)^x = AP$",
        reading=(XA, a + Ys - a * Rx),
        erratum=Erratum("transcription", "high", r"x = a + Y - a\left(1 - \frac{y^n}{b^n}\right)^\kappa = AP",
                        (r"The exponent of the family is $\kappa$ (§231–236 print it and tabulate $\kappa = \tfrac12, "
                         r"1, \tfrac32, \dots$); $x$ is the abscissa $AP$ itself and cannot be its own exponent. Only "
                         r"with $\kappa$ in both portions is $Ap - AP$ the chord $Mm = 2a(1 - y^n/b^n)^\kappa$ the "
                         r"text derives next. The Greek $\kappa$ read as $x$, the fault booked at the chord $Mm$."),
                        corrected_reading=(XA, a + Ys - a * R), same_as=KAPPA_AS_X,
                        objection="As for the chord: $x$ may be the print's letter for the exponent.",
                        answer=(r"Here $x$ stands on both sides of one equation ($x = \dots (\dots)^x = AP$), which "
                                r"Euler would not write for an explicit curve; §231 and §236 treat $\kappa$ as the "
                                r"exponent of these portions (cusps at $e$ for $\kappa > 1$). The $\varkappa$ read as "
                                "$x$, the fault booked at the chord: high.")),
        note=claim("the portion Ace is x = a + Y − a(1 − yⁿ/bⁿ)^κ = AP."))
d.quote("portion-Bce", "§229", r"aequatio $x = a + Y + a\left(1 - \frac{y^n}{b^n}\right)^x = Ap$",
        reading=(XB, a + Ys + a * Rx),
        erratum=Erratum("transcription", "high", r"x = a + Y + a\left(1 - \frac{y^n}{b^n}\right)^\kappa = Ap",
                        (r"$\kappa$ read as $x$, the fault booked at the chord $Mm$: the portion $Bce$ is $x = a + Y "
                         r"+ a(1 - y^n/b^n)^\kappa$, and $Ap - AP = 2a(1 - y^n/b^n)^\kappa$."),
                        corrected_reading=(XB, a + Ys + a * R), same_as=KAPPA_AS_X,
                        objection="As for the chord: $x$ may be the print's letter for the exponent.",
                        answer=r"As for the portion Ace: $x$ on both sides of the equation, $\kappa$ in §231–236 for "
                               r"this exponent; the $\varkappa$ read as $x$, high."),
        note=claim("the portion Bce is x = a + Y + a(1 − yⁿ/bⁿ)^κ = Ap."))

# ================================================================ §230: moments about AB and about the normal through O
MO_val = 2 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1) + 2 * a * JY(2, 0, k)
d.step("moment-AB", (IAB, sp.Integral(y ** 2 * 2 * a * R, (y, 0, b)), 2 * a * J(2, k)), "integration",
       uses=("chord",), result=IAB, note="each chord Mm at the distance y from AB contributes y²·Mm dy")
d.step("moment-O", (MO, sp.Integral(2 * a ** 3 * R ** 3 / 3, (y, 0, b)) + 2 * a * JY(2, 0, k),
                    2 * a ** 3 / 3 * J(0, 3 * k) + 2 * a * JY(2, 0, k), MO_val), "integration",
       uses=("strip-moment-O", "recurrence-exponent", "Y-integrals"), result=MO,
       note="half figure AEB; ∫R³dy = (3nκ/bⁿ)∫yⁿ(1 − yⁿ/bⁿ)^{3κ−1}dy by parts")
d.quote("moment-AB", "§230", "erit momentum respectu axis $AB = 2a \\int y dy$\n\n"
        "$\\left(1 - \\frac{y^n}{b^n}\\right)^x$",
        reading=(IAB, 2 * a * J(1, xk)),
        erratum=Erratum("transcription", "medium", r"= 2a \int yy dy \left(1 - \frac{y^n}{b^n}\right)^\kappa",
                        r"The chord Mm at the distance $y$ from AB gives $y^2 \cdot Mm \cdot dy$; $\int y \cdot Mm\, "
                        "dy$ would be the first moment, which vanishes for the whole figure and is not what §237 calls "
                        r"momentum. A '$yy$' read as '$y$' and $\kappa$ read as $x$; the transcription alone cannot "
                        "exclude a slip of 1749, hence medium.", corrected_reading=(IAB, 2 * a * J(2, k)),
                        objection="'Momentum' may mean the static moment here (weight times distance, the usual sense "
                                  r"in mechanics), and $2a\int y\, dy\, R$ is the first moment of AEB about AB, so the "
                                  "print is right in that sense.",
                        answer="In this chapter 'momentum respectu axis' is the second moment: §237 gives it as $EF^2 "
                               r"D/\mu$ with $\mu = 6$ for the rectangle, which only $\int y^2 \cdot Mm\, dy$ gives, "
                               "and §233's moment about EF is $2a^2 D$ times a number, a fourth power of a length. So "
                               "one $y$ of '$yy$' is lost; a letter lost by the scan or by the compositor cannot be "
                               "told apart from the text, and the correction itself is certain: medium."),
        note=claim("the moment of AEB about AB is 2a∫y²dy(1 − yⁿ/bⁿ)^κ, independent of Y."))
d.quote("PO", "§230", r"$PO = -Y + a\left(1 - \frac{y^n}{b^n}\right)^x$",
        reading=(a - XA, -Ys + a * Rx),
        erratum=Erratum("transcription", "high", r"PO = -Y + a\left(1 - \frac{y^n}{b^n}\right)^\kappa",
                        r"$x$ for $\kappa$.", corrected_reading=(a - XA, -Ys + a * R),
                        objection="As for the chord: $x$ may be the print's letter for the exponent.",
                        answer=r"$PO = a - AP$ of the portion Ace, whose exponent §231–236 call $\kappa$; the "
                               r"$\varkappa$ read as $x$ on the same line as the chord's, high."),
        note=claim("the distance of M (on Ace) from the normal through O is PO = −Y + aR."))
d.quote("pO", "§230", "et $pO =$\n\n$Y + a\\left(1 - \\frac{y^n}{b^n}\\right)^x$",
        reading=(XB - a, Ys + a * Rx),
        erratum=Erratum("transcription", "high", r"pO = Y + a\left(1 - \frac{y^n}{b^n}\right)^\kappa",
                        r"$x$ for $\kappa$.", corrected_reading=(XB - a, Ys + a * R),
                        objection="As for the chord: $x$ may be the print's letter for the exponent.",
                        answer=r"$pO = Ap - a$ of the portion Bce; the $\varkappa$ read as $x$, high."),
        note=claim("and that of m (on Bce) is pO = Y + aR."))
MO_print = (2 * n * n * a ** 3 / b ** n * Ib(n, 3 * n - 1, n, b) + 2 * a * JY(2, 0, xk))
d.quote("moment-O", "§230",
        r"$\frac{2nna^3}{b^n} \int y^n dy \left(1 - \frac{y^n}{b^n}\right)^{3n-1} + 2a \int Y^2 dy "
        r"\left(1 - \frac{y^n}{b^n}\right)^x$",
        reading=(MO, MO_print),
        erratum=Erratum("transcription", "medium",
                        r"\frac{2n\kappa a^3}{b^n} \int y^n dy \left(1 - \frac{y^n}{b^n}\right)^{3\kappa-1} + "
                        r"2a \int Y^2 dy \left(1 - \frac{y^n}{b^n}\right)^\kappa",
                        (r"$\tfrac13\int((pO)^3 + (PO)^3)\,dy = \tfrac{2a^3}{3}\int R^3 dy + 2a\int Y^2 R\, dy$, and "
                         r"by parts $\tfrac{2a^3}{3}\int R^3 dy = \tfrac{2n\kappa a^3}{b^n}\int y^n (1 - "
                         r"y^n/b^n)^{3\kappa-1} dy$. $\kappa$ read as $n$ (twice) and as $x$; §232 prints the whole "
                         r"figure's term with the exponent $3\kappa-1$."), corrected_reading=(MO, MO_val),
                        objection=r"$n$ stands for $\kappa$ four times in §230 ($2nn$ and $3n - 1$ in both lines) and "
                                  "again in §232 ($n(n + 1) + 1$): a letter wrong the same way in several places of "
                                  "Euler's working is his own, not the scan's.",
                        answer=r"It is not carried on: §232 prints the same term with the exponent $3\kappa - 1$ and "
                               r"p. 118 with $4n\kappa$ and $3\kappa - 1$, and §233's $2n\kappa a^2 ND/(1 + 3n\kappa)$ "
                               r"and the tables of §234 (checked against §236's rhombus and ellipse) need $\kappa$, so "
                               r"Euler computed with $\kappa$. The page also reads $\kappa$ as $x$ and $\alpha$, the "
                               r"marks of a scan that cannot tell this glyph; but a lost $\kappa$ in the print is not "
                               "excluded: medium."),
        note=claim("the moment of AEB about the normal to AB through O is (2nκa³/bⁿ)∫yⁿdy(1 − yⁿ/bⁿ)^{3κ−1} "
                   "+ 2a∫Y²dy(1 − yⁿ/bⁿ)^κ."))
d.quote("moment-O-whole", "§230",
        "$= \\frac{4nna^3}{b^n} \\int y^n dy \\left(1 - \\frac{y^n}{b^n}\\right)^{3n-1} + 4a \\int Y^2 dy$\n\n"
        "$\\left(1 - \\frac{y^n}{b^n}\\right)^x$",
        reading=(2 * MO, 2 * MO_print),
        erratum=Erratum("transcription", "medium",
                        r"= \frac{4n\kappa a^3}{b^n} \int y^n dy \left(1 - \frac{y^n}{b^n}\right)^{3\kappa-1} + "
                        r"4a \int Y^2 dy \left(1 - \frac{y^n}{b^n}\right)^\kappa",
                        r"Twice the half figure's moment (AFB is equal to AEB); the same $\kappa$ read as $n$ and $x$.",
                        corrected_reading=(2 * MO, 2 * MO_val),
                        objection=r"As for the half figure: $n$ for $\kappa$ recurs in Euler's working and may be his.",
                        answer="Twice the half figure's moment, with the same letters; §232 and p. 118 print the term "
                               r"with $\kappa$ and §233 builds on it, so the fault is not carried on: medium, as for "
                               "the half figure."),
        note=claim("the whole figure's moment about the normal through O is twice that."))

# ================================================================ §231: centroid and the moment about EF
SO_val = 2 * a * JY(1, 0, k)
d.step("first-moment-O", (SO, 2 * a * (c1 / b ** n * J(n, k) + c2 / b ** (2 * n) * J(2 * n, k)), 2 * a * JY(1, 0, k)),
       "integration", uses=("strip-first-moment-O", "Y-integrals"), result=SO,
       note="S_O = ∫∫(x − a) over AEB")
d.step("centroid", Eq(XC, a + SO / D), "definition", result=XC,
       note="the centroid's abscissa (both halves have the same)")
d.step("CO", (CO, a - XC, -SO / D), "algebra", uses=("centroid",), result=CO,
       note="CO counted from O towards A")
d.step("centroid-by-parts", (-2 * a * JY(1, 0, k),
                             2 * a * JY(0, 1, k, 1) - 2 * n * k * a / b ** n * JY(1, n, k - 1)), "integration",
       uses=("Y-integrals",),
       note=r"$\int yR\,dY = [yRY] - \int Y (yR)'\,dy$, $(yR)' = R - (n\kappa/b^n) y^n (1 - y^n/b^n)^{\kappa - 1}$")
KEF_val = 4 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1) + 4 * a * JY(2, 0, k) - 8 * a ** 2 * JY(1, 0, k) ** 2 / D
d.step("moment-EF", (KEF, 2 * (MO - 2 * (XC - a) * SO + (XC - a) ** 2 * D), 2 * MO - 2 * SO ** 2 / D, KEF_val),
       "integration", uses=("strip-moment-C", "moment-O", "first-moment-O", "centroid"), result=KEF,
       note="both halves about EF (x = x_C): the chord moments about a parallel at m = x_C − a from O")
d.quote("centroid-moment", "§231",
        r"D. $CO = 2 \alpha \int y dy (1 - \frac{y^n}{b^n})^{\kappa} - \frac{2n\alpha a}{b^n} \int y^n Y dy "
        r"(1 - \frac{y^n}{b^n})^{\kappa-1} = -2 \alpha \int Y dy (1 - \frac{y^n}{b^n})^{\kappa}$",
        reading=(D * CO, 2 * al * J(1, k) - 2 * n * al * a / b ** n * JY(1, n, k - 1), -2 * al * JY(1, 0, k)),
        erratum=Erratum("transcription", "low",
                        r"D \cdot CO = 2a \int y dY (1 - \frac{y^n}{b^n})^{\kappa} - \frac{2n\kappa a}{b^n} \int "
                        r"y^n Y dy (1 - \frac{y^n}{b^n})^{\kappa-1} = -2a \int Y dy (1 - \frac{y^n}{b^n})^{\kappa}",
                        (r"$D \cdot CO = -\iint (x - a) = -2a\int YR\, dy$; integrating by parts $\int yR\, dY - "
                         r"\tfrac{n\kappa}{b^n}\int y^n Y (\dots)^{\kappa-1} dy = -\int YR\, dy$. So the first "
                         r"integral is $\int y\, dY$ (not $\int y\, dy$, which has no $Y$ and cannot give a "
                         r"$Y$-dependent centroid), the factor of the second is $2n\kappa a$, and $\alpha$ stands for "
                         r"$a$ (as in $CO = -2\alpha\int\dots/D$ next). Several letters at once: low."),
                        corrected_reading=(D * CO, 2 * a * JY(0, 1, k, 1) - 2 * n * k * a / b ** n * JY(1, n, k - 1),
                                           -2 * a * JY(1, 0, k)),
                        objection=r"The first integral $\int y\, dy\, R$ may be the print's (Euler's slip while "
                                  r"integrating by parts), and $\alpha$ may be a letter of the print, since §231 has "
                                  r"just introduced $\alpha$ as the first coefficient of $Y$.",
                        answer=r"The line's own end, $-2\alpha\int Y\, dy\, R$, and the next formula $CO = "
                               r"-2\alpha\int\dots/D$ need $\int y\, dY$ and the factor $a$: $\int y\, dy\, R$ has no "
                               "$Y$ and could not give a centroid that depends on $Y$. Several letters at once, some "
                               r"the scan's ($\alpha$ for $a$ and $\kappa$) and the $dY$ perhaps the print's, cannot "
                               "be told apart: low stands."),
        note=claim("the centroid C satisfies D·CO = 2a∫y dY R − (2nκa/bⁿ)∫yⁿY dy(1 − yⁿ/bⁿ)^{κ−1} = −2a∫Y dy R."))
d.quote("CO", "§231", r"$CO = \frac{-2 \alpha \int Y dy (1 - \frac{y^n}{b^n})^{\kappa}}{D}$",
        reading=(CO, -2 * al * JY(1, 0, k) / D),
        erratum=Erratum("transcription", "high", r"CO = \frac{-2a \int Y dy (1 - \frac{y^n}{b^n})^{\kappa}}{D}",
                        r"$\alpha$ for $a$: the half-length $a$ multiplies the chord $2aR$; no $\alpha$ is defined "
                        r"before §231's $Y = \alpha y^n + \dots$.", corrected_reading=(CO, -2 * a * JY(1, 0, k) / D),
                        objection=r"$\alpha$ stands for $a$ in seven formulas of §231–232, consistently: by the rule "
                                  "for a fault running through the author's working, Euler's or the print's, not the "
                                  r"scan's; and $\alpha$ is a letter of the paragraph ($Y = \alpha y^n + \dots$).",
                        answer=r"It is not carried on: §233 writes $ND/2a$ and $2n\kappa a^2 ND/(1 + 3n\kappa)$, which "
                               r"need the half-length $a$, and the same pages print $\alpha$ also where $\kappa$ "
                               r"belongs ($4n\alpha a^3$), where neither author nor compositor would set the "
                               r"coefficient of $Y$; italic $a$ and $\alpha$ differ by a stroke. The scan's reading of "
                               "p. 117, against the author's own later use: high."),
        note=claim("hence CO = −2a∫Y dy R / D."))
d.quote("moment-EF", "§231",
        r"$= \frac{4n\alpha a^3}{b^n} \int y^n dy (1 - \frac{y^n}{b^n})^{\kappa-1} + 4 \alpha \int Y^2 dy "
        r"(1 - \frac{y^n}{b^n})^{\kappa} - 8 \alpha a (\int Y dy (1 - \frac{y^n}{b^n})^{\kappa})^2$",
        reading=(KEF, 4 * n * al * a ** 3 / b ** n * J(n, k - 1) + 4 * al * JY(2, 0, k) - 8 * al * a * JY(1, 0, k) ** 2),
        erratum=Erratum("transcription", "medium",
                        r"= \frac{4n\kappa a^3}{b^n} \int y^n dy (1 - \frac{y^n}{b^n})^{3\kappa-1} + 4a \int Y^2 dy "
                        r"(1 - \frac{y^n}{b^n})^{\kappa} - \frac{8aa}{D} (\int Y dy (1 - \frac{y^n}{b^n})^{\kappa})^2",
                        (r"The moment about EF is the moment about the parallel through $O$, $2M_O$, less $2D \cdot "
                         r"CO^2$ (§217) $= 8a^2 (\int YR)^2/D$. Printed: $\alpha$ for $\kappa$ and for $a$, the "
                         r"exponent $\kappa-1$ for $3\kappa-1$ (§232 repeats the term with $3\kappa-1$) and the "
                         "divisor $D$ of the last term lost (the term must be a fourth power of a length)."), corrected_reading=(KEF, KEF_val),
                        objection=r"The fix needs three different changes ($\alpha$ for $\kappa$ and $a$, $\kappa - 1$ "
                                  r"for $3\kappa - 1$, the divisor $D$ lost), more than one slip of the scan: the line "
                                  "may be Euler's own wrong formula.",
                        answer="Euler's next results are computed from the right one: §232 repeats the first term with "
                               r"$3\kappa - 1$, and its $c$-terms $2(n + 1)c^2 D/(\dots) - 2c^2 D/(n(\kappa + 1) + "
                               r"1)^2$ come from $8a^2(\int YR)^2/D$, so the divisor $D$ was in his working. $\alpha$ "
                               r"for $\kappa$ and $a$ is the scan's fault of this page; a lost $3$ and a lost fraction "
                               "bar are faults of either. Medium."),
        note=claim("the moment of the whole figure about EF through C is (4nκa³/bⁿ)∫yⁿ(…)^{3κ−1} + 4a∫Y²R "
                   "− 8a²(∫YR)²/D."))
d.quote("axis-EF-named", "§230", r"Ad momentum autem huius figurae respectu axis longitudinalis EF",
        reading=(2 * IAB, 2 * MO - 2 * SO ** 2 / D),
        erratum=Erratum("misprint", "medium", r"\text{respectu axis latitudinalis EF}",
                        ("EF is the latitudinal axis throughout (§198, §203, §220; §231 'momentum totius figurae "
                         "respectu axis latitudinalis EF'); the longitudinal axis is AB, whose moment the sentence "
                         "before found. The moment determined next, from the normal to AB through O moved to the "
                         "parallel through C, is the one about EF. Read as printed, the moment about the "
                         "longitudinal axis ($2 I_{AEB}$) would be $2M_O - 2S_O^2/D$, which it is not. A word of the "
                         "print (a scan does not exchange 'latitudinalis' for 'longitudinalis'); medium."),
                        corrected_reading=(KEF, 2 * MO - 2 * SO ** 2 / D),
                        objection="'Axis longitudinalis' may be the axis of longitudinal rotation: the moment about "
                                  "EF governs pitching, which later usage calls longitudinal stability; in that "
                                  "sense 'longitudinalis EF' is right.",
                        answer="Euler's adjective names the direction of the axis itself: §237 'AB designet axem "
                               "longitudinalem EF latitudinalem', §231 'respectu axis latitudinalis EF', §241 "
                               "'stabilitas respectu axis longitudinalis' for the stability about AB. So the print "
                               "names EF with AB's word. A scan that models words could exchange one '-tudinalis' "
                               "for the other, the alternative left: medium."),
        note=claim("the moment about the axis EF through the centroid C is found from the moment about the "
                   "parallel through O (read with the names of §231: 2M_O less 2S_O²/D)."))
Y_printed = aY * y ** n + bY * y ** (n - 1) + gY * y ** (n - 2)
Y_corrected = aY * y ** n + bY * y ** (2 * n) + gY * y ** (3 * n)
d.quote("Y-family", "§231", r"$Y = \alpha y^n + \beta y^{n-1} + \gamma y^{n-2} + \dots + \text{etc.}$",
        reading=(sp.Subs(Y_printed, (y, n), (0, 2)), 0),
        erratum=Erratum("transcription", "low", r"Y = \alpha y^n + \beta y^{2n} + \gamma y^{3n} + \dots",
                        ("The curve must meet AB at A and B: $AP = Y(0)$ at $y = 0$, so $Y$ vanishes there (§221: "
                         "'quae euaneat posito $y = 0$'). The printed terms $y^{n-1}$, $y^{n-2}$ do not: at $n = 2$ "
                         r"(the ellipse of §236) $\gamma y^{n-2} = \gamma$ at $y = 0$ (read so, the '+ etc.' dropped), "
                         r"at $n = 1$ $\beta y^0 = \beta$ and $y^{-1}$ is infinite. Nor do they reduce to the area "
                         r"integral $\int dy\, (1 - y^n/b^n)^\kappa = D/(2a)$, as the sentence claims: at $n = 2$, "
                         r"$\kappa = \tfrac12$, $\int y (1 - y^2/b^2)^{1/2} dy \big/ \int (1 - y^2/b^2)^{1/2} dy = "
                         r"(b^2/3)/(\pi b/4) = 4b/(3\pi)$, no rational multiple of $b$, while the powers $y^{jn}$ "
                         "reduce by the rational factors of the recurrence (§232 uses $y^n$ and $y^{2n}$). The "
                         "exponents $2n$, $3n$ read as the descending $n - 1$, $n - 2$ of an ordinary polynomial; the "
                         "change is no glyph a scan confuses, and the print cannot be seen (a slip of 1749 is not "
                         "excluded): low."),
                        corrected_reading=(sp.Subs(Y_corrected, (y, n), (0, 2)), 0),
                        objection=(r"A descending polynomial $\alpha y^n + \beta y^{n-1} + \gamma y^{n-2} + \dots$ is "
                                   "the most ordinary way of writing a general function, and the change to $y^{2n}$, "
                                   "$y^{3n}$ is no glyph the scan confuses ($2n$ does not look like $n - 1$): if "
                                   "wrong, the slip is as likely Euler's own pen or the compositor's."),
                        answer=("The correction stands: $Y$ must vanish at $y = 0$, and only powers $y^{jn}$ reduce "
                                r"to $\int dy\, (1 - y^n/b^n)^\kappa$ as the sentence claims (§232 uses $y^n$). But "
                                "the fault is not a glyph confusion and Euler's later working shows only $y^n$, not "
                                "$y^{2n}$, so print and scan cannot be told apart: lowered to low.")),
        note=claim("Y is a sum of powers of y vanishing at y = 0; read at n = 2, y = 0 (the point A)."))
d.quote("area-integral", "§231", r"$\int dy (1 - \frac{y^n}{b^n})^{\kappa} = \frac{D}{2\alpha}$",
        reading=(J(0, k), D / (2 * al)),
        erratum=Erratum("transcription", "high", r"\int dy (1 - \frac{y^n}{b^n})^{\kappa} = \frac{D}{2a}",
                        r"$\alpha$ for $a$ (§229: $D = 2a\int R\, dy$).", corrected_reading=(J(0, k), D / (2 * a)),
                        objection=r"$\alpha$ may be meant: §231 has just introduced $\alpha$ as the first coefficient "
                                  r"of $Y$, and the print may write $D/2\alpha$.",
                        answer=(r"$D = 2a\int dy\, R$ (§229) gives $D/2a$, and §233 prints $\int dy\, (\dots)^\kappa "
                                r"= ND/2a$ with $a$; the coefficient $\alpha$ of $Y$ has no place in the area. "
                                r"$\alpha$ for $a$, the scan's reading of this page: high.")),
        note=claim("the integral to which the others reduce is ∫dy R = D/(2a)."))

# ================================================================ §232: Y = −c yⁿ/bⁿ
cY = {c1: -c, c2: 0}
m1, m2 = n * (k + 1) + 1, n * (k + 2) + 1
d.step("Y-c-first", (JY(1, 0, k, 0, -c, 0), -c / b ** n * J(n, k), -c * J(0, k) / m1), "integration",
       uses=("recurrence-power",))
d.step("Y-c-second", (JY(2, 0, k, 0, -c, 0), c ** 2 / b ** (2 * n) * J(2 * n, k),
                      (n + 1) * c ** 2 * J(0, k) / (m1 * m2)), "integration", uses=("recurrence-power",))
Kc_val = 4 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1) + 2 * n ** 2 * (k + 1) * c ** 2 * D / (m1 ** 2 * m2)
d.step("moment-EF-c", (Kc, KEF_val.xreplace(cY),
                       4 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1) + 2 * (n + 1) * c ** 2 * D / (m1 * m2)
                       - 2 * c ** 2 * D / m1 ** 2, Kc_val), "integration",
       uses=("moment-EF", "Y-c-first", "Y-c-second", "area"), result=Kc)
d.quote("Y-c-first", "§232",
        r"$\int Y dy (1 - \frac{y^n}{b^n})^{\kappa} = -\frac{c}{b^n} \int y^n dy (1 - \frac{y^n}{b^n})^{\kappa} = "
        r"\frac{-c}{n(n+1)+1} \int dy (1 - \frac{y^n}{b^n})^{\kappa} = \frac{-cD}{2\alpha(n(n+1)+1)}$",
        reading=(JY(1, 0, k, 0, -c, 0), -c / b ** n * J(n, k), -c / (n * (n + 1) + 1) * J(0, k),
                 -c * D / (2 * al * (n * (n + 1) + 1))),
        erratum=Erratum("transcription", "high",
                        r"= \frac{-c}{n(\kappa+1)+1} \int dy (1 - \frac{y^n}{b^n})^{\kappa} = \frac{-cD}{2a(n(\kappa+1)+1)}",
                        r"$\int y^n R\, dy/b^n = \int R\, dy/(n(\kappa+1)+1)$ by parts; the display at the top of p. "
                        r"118 prints $n(\kappa+1)+1$ in the same place: $\kappa$ read as $n$, and $\alpha$ for $a$.",
                        corrected_reading=(JY(1, 0, k, 0, -c, 0), -c / b ** n * J(n, k), -c / m1 * J(0, k),
                                           -c * D / (2 * a * m1)),
                        objection="$n(n + 1) + 1$ stands in four places of §232 (both integrals and their values), "
                                  "consistently: by the rule for a repeated fault, Euler's working rather than the "
                                  "scan's.",
                        answer="The display at the top of p. 118, which combines exactly these terms, prints "
                               r"$n(\kappa + 1) + 1$ and $n(\kappa + 2) + 1$ and its combined $c$-term is right, so "
                               r"Euler computed with $\kappa$; the $n$ is the scan's reading of $\kappa$ on p. 117, "
                               r"where it also reads $\kappa$ as $x$ and $\alpha$. High: the author's own next line "
                               "shows the form."),
        note=claim("with Y = −cyⁿ/bⁿ (Oc = c), ∫Y dy R = −cD/(2a(n(κ+1)+1))."))
d.quote("Y-c", "§232", r"Sit primum antequam pro κ valores definitos accipiamus, $Y = \frac{-cy^n}{b^n}$",
        reading=(sp.Subs(a - XA, (Ys, y), (-c * y ** n / b ** n, b)), c),
        note=claim("with Y = −cyⁿ/bⁿ the two portions meet at y = b at the distance c from O (towards A)."))
d.quote("Ac-Oc", "§232", r"$A_c = a - c$ et $O_c = c$",
        reading=(sp.Matrix([sp.Subs(XA, (Ys, y), (-c, b)), a - sp.Subs(XA, (Ys, y), (-c, b))]), sp.Matrix([a - c, c])),
        note=claim("with Y = −cyⁿ/bⁿ the greatest breadth ef (y = b, where both portions meet) lies at Ac = a − c, "
                   "Oc = c (A_c, O_c of the transcription are the distances Ac, Oc)."))
d.quote("Y-c-second", "§232",
        r"$\int Y^2 dy (1 - \frac{y^n}{b^n})^{\kappa} = \frac{cc}{b^{2n}} \int y^{2n} dy (1 - \frac{y^n}{b^n})^{\kappa} "
        r"= \frac{(n+1)cc}{(n(n+1)+1)(n(n+2)+1)}$, $\int dy (1 - \frac{y^n}{b^n})^{\kappa} = "
        r"\frac{(n+1)ccD}{2\alpha(n(n+1)+1)(n(n+2)+1)}$",
        reading=(JY(2, 0, k, 0, -c, 0), c ** 2 / b ** (2 * n) * J(2 * n, k),
                 (n + 1) * c ** 2 / ((n * (n + 1) + 1) * (n * (n + 2) + 1)) * J(0, k),
                 (n + 1) * c ** 2 * D / (2 * al * (n * (n + 1) + 1) * (n * (n + 2) + 1))),
        erratum=Erratum("transcription", "high",
                        r"= \frac{(n+1)cc}{(n(\kappa+1)+1)(n(\kappa+2)+1)} \int dy (1 - \frac{y^n}{b^n})^{\kappa} = "
                        r"\frac{(n+1)ccD}{2a(n(\kappa+1)+1)(n(\kappa+2)+1)}",
                        (r"Two steps of the recurrence $\int y^{p+n} R = \tfrac{b^n (p+1)}{p+1+n(\kappa+1)} \int y^p "
                         r"R$. Read with the comma of the transcription as the product it interrupts; $\kappa$ read "
                         r"as $n$ (twice) and $\alpha$ for $a$, as in the line before; p. 118 prints "
                         r"$(n(\kappa+1)+1)(n(\kappa+2)+1)$."),
                        corrected_reading=(JY(2, 0, k, 0, -c, 0), c ** 2 / b ** (2 * n) * J(2 * n, k),
                                           (n + 1) * c ** 2 / (m1 * m2) * J(0, k),
                                           (n + 1) * c ** 2 * D / (2 * a * m1 * m2)),
                        objection=r"The fix needs several changes ($\kappa$ for $n$ twice, $a$ for $\alpha$, the comma "
                                  "taken as part of a product), more than the one slip that high asks for; and the "
                                  "comma may be the print's, closing one equation and opening another.",
                        answer=r"As separate equations the first ends in $\int Y^2 R = (n + 1)c^2/(\dots)$, a square "
                               r"of a length where the integral is a cube, and the second makes $\int dy\, R$ depend "
                               "on $c$; read as one product its value is the one p. 118 uses, $(n + 1)c^2 "
                               r"D/(2a(\dots)(\dots)) \text{ times } 4a = 2(n + 1)c^2 D/((n(\kappa + 1) + 1)(n(\kappa "
                               r"+ 2) + 1))$. Each change is the page's known misreading ($\kappa$ as $n$, $a$ as "
                               r"$\alpha$) and p. 118 prints the result: high."),
        note=claim("∫Y²dy R = (n+1)c²D/(2a(n(κ+1)+1)(n(κ+2)+1))."))
d.quote("moment-EF-c", "§232",
        r"$= \frac{4n\alpha a^3}{b^n} \int y^n dy (1 - \frac{y^n}{b^n})^{3\kappa-1} + "
        r"\frac{2(n+1)}{2\alpha(n(n+1)+1)(n(n+2)+1)}$",
        reading=(Kc, 4 * n * al * a ** 3 / b ** n * J(n, 3 * k - 1)
                 + 2 * (n + 1) / (2 * al * (n * (n + 1) + 1) * (n * (n + 2) + 1))),
        erratum=Erratum("transcription", "medium",
                        r"= \frac{4n\kappa a^3}{b^n} \int y^n dy (1 - \frac{y^n}{b^n})^{3\kappa-1} + "
                        r"\frac{2(n+1)ccD}{(n(\kappa+1)+1)(n(\kappa+2)+1)} - \frac{2ccD}{(n(\kappa+1)+1)^2}",
                        "The line breaks at the foot of p. 117 and the display heading p. 118 continues it with "
                        r"$2(n+1)ccD/((n(\kappa+1)+1)(n(\kappa+2)+1)) - 2ccD/(n(\kappa+1)+1)^2$; the transcription's "
                        r"last fraction is a garbled start of that term ($ccD$ lost, $2\alpha$ and $n$ for $\kappa$). "
                        r"$\alpha$ for $\kappa$ in $4n\kappa a^3$.",
                        corrected_reading=(Kc, 4 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1)
                                           + 2 * (n + 1) * c ** 2 * D / (m1 * m2) - 2 * c ** 2 * D / m1 ** 2),
                        objection="The line ends the page; the print itself may break the formula there with an "
                                  "incomplete fraction, so that what stands is Euler's and only its continuation is "
                                  "on p. 118.",
                        answer="That is the reading the erratum makes: p. 118 continues with $2(n + "
                               r"1)ccD/(\dots)(\dots) - 2ccD/(\dots)^2$, so the page's last fraction is its start; but "
                               r"$2\alpha$ in the denominator and the lost $ccD$ are not a compositor's break, and "
                               r"$\alpha$ for $\kappa$ in $4n\alpha a^3$ is the scan's. Whether the print set the "
                               "whole term on p. 117 cannot be seen: medium."),
        note=claim("for Y = −cyⁿ/bⁿ the moment about EF is (4nκa³/bⁿ)∫yⁿ(…)^{3κ−1}dy + "
                   "2(n+1)c²D/((n(κ+1)+1)(n(κ+2)+1)) − 2c²D/(n(κ+1)+1)², continued on p. 118."))
d.quote("moment-EF-c-p118", "§232",
        "$$\\frac{2(n+1)ccD}{(n(\\kappa+1)+1)(n(\\kappa+2)+1)} - \\frac{2ccD}{(n(\\kappa+1)+1)^2} = "
        "\\frac{4n\\kappa a^2}{b^n}$$\n\n$$\\int y^n dy \\left(1 - \\frac{y^n}{b^n}\\right)^{3\\kappa-1} + "
        "\\frac{2nn(\\kappa+1)ccD}{(n(\\kappa+1)+1)^2(n(\\kappa+2)+1)} : \\text{ vnde}$$",
        reading=(Kc, 4 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1) + 2 * (n + 1) * c ** 2 * D / (m1 * m2)
                 - 2 * c ** 2 * D / m1 ** 2,
                 4 * n * k * a ** 2 / b ** n * J(n, 3 * k - 1) + 2 * n ** 2 * (k + 1) * c ** 2 * D / (m1 ** 2 * m2)),
        erratum=Erratum("transcription", "medium",
                        r"= \frac{4n\kappa a^3}{b^n} \int y^n dy \left(1 - \frac{y^n}{b^n}\right)^{3\kappa-1} + "
                        r"\frac{2nn(\kappa+1)ccD}{(n(\kappa+1)+1)^2(n(\kappa+2)+1)}",
                        r"The $c$-terms combine to $2n^2(\kappa+1)c^2 D/((n(\kappa+1)+1)^2(n(\kappa+2)+1))$ (checked); "
                        "the first term is carried unchanged from the line before, where it has $a^3$ (a moment is a "
                        r"fourth power of a length; §233 turns it into $2n\kappa a^2 ND/(1+3n\kappa)$ with $D = 2a\int "
                        "R$). $a^2$ for $a^3$: an exponent misread, or a misprint of 1749; medium.",
                        corrected_reading=(Kc, 4 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1)
                                           + 2 * (n + 1) * c ** 2 * D / (m1 * m2) - 2 * c ** 2 * D / m1 ** 2,
                                           Kc_val),
                        objection=r"$a^2$ may be the print's: §233 carries $a^2$ on ($2n\kappa a^2 ND/(1 + "
                                  r"3n\kappa)$), so the square may be Euler's own through two places of his working.",
                        answer=(r"§233's $a^2$ is right there, since $D = 2a\int R$ absorbs one $a$: $\tfrac{4n\kappa "
                                r"a^3}{b^n}\int y^n (\dots)^{3\kappa-1} = 2n\kappa a^2 ND/(1 + 3n\kappa)$ needs $a^3$ "
                                "in the line before. So the $a^2$ of p. 118 is not carried on; a $3$ read as $2$ "
                                "(the scan) or set as $2$ (the compositor) cannot be told apart: medium.")),
        note=claim("the two c-terms combine: the moment about EF is (4nκa³/bⁿ)∫yⁿ(…)^{3κ−1}dy + "
                   "2n²(κ+1)c²D/((n(κ+1)+1)²(n(κ+2)+1)) (read with the first term of the line before)."))
d.quote("moment-grows-with-c", "§232",
        "iterum intelligitur hoc momentum maius esse, quo maius fuerit inter Iallum c inter punctum axis "
        "longitudinalis medium O et latitudinem maximam ef",
        reading=(sp.Derivative(Kc, c), 4 * n ** 2 * (k + 1) * c * D / (m1 ** 2 * m2)),
        note=claim("the moment grows with the distance c of the greatest breadth from the middle O: its "
                   "derivative in c is 4n²(κ+1)cD/((n(κ+1)+1)²(n(κ+2)+1)) > 0 (read so; D does not depend on c)."))

# ================================================================ §233: N and the moment about EF
d.step("N", Eq(N, J(0, 3 * k - 1) / J(0, k)), "definition", result=N,
       note="Euler's N: ∫dy(1 − yⁿ/bⁿ)^{3κ−1} = N∫dy(1 − yⁿ/bⁿ)^κ = ND/(2a)")
d.step("moment-EF-N", (Kc, 2 * n * k * a ** 2 * N * D / (1 + 3 * n * k)
                       + 2 * n ** 2 * (k + 1) * c ** 2 * D / (m1 ** 2 * m2)), "integration",
       uses=("moment-EF-c", "recurrence-exponent", "N", "area"))
d.quote("by-parts-3k", "§233",
        "\\frac{\\int y^n dy}{b^n} \\left(1 - \\frac{y^n}{b^n}\\right)^{3\\kappa-1} = \\frac{1}{1+3n\\kappa} \\\\ & "
        "\\int dy \\left(1 - \\frac{y^n}{b^n}\\right)^{3\\kappa-1}",
        reading=(J(n, 3 * k - 1) / b ** n, J(0, 3 * k - 1) / (1 + 3 * n * k)),
        note=claim("∫yⁿdy(1 − yⁿ/bⁿ)^{3κ−1}/bⁿ = ∫dy(1 − yⁿ/bⁿ)^{3κ−1}/(1 + 3nκ)."))
d.quote("N-definition", "§233",
        "\\int dy \\left(1 - \\frac{y^n}{b^n}\\right)^{\\kappa} = N \\int dy \\left(1 - \\frac{y^n}{b^n}\\right)^{\\kappa} "
        "\\\\ & = \\frac{ND}{2a}",
        reading=(J(0, k), N * J(0, k), N * D / (2 * a)),
        erratum=Erratum("transcription", "medium",
                        r"\int dy \left(1 - \frac{y^n}{b^n}\right)^{3\kappa-1} = N \int dy "
                        r"\left(1 - \frac{y^n}{b^n}\right)^{\kappa} = \frac{ND}{2a}",
                        (r"As transcribed $N$ would be $1$. The integral being replaced is the $\int dy\, "
                         r"(\dots)^{3\kappa-1}$ of the line before, and the table of $N$ ($\kappa = 1$: $4n/(2+4n) = "
                         r"\int (1-u^n)^2 / \int (1-u^n)$) confirms it: the exponent $3\kappa-1$ of the first "
                         "integral is lost."),
                        corrected_reading=(J(0, 3 * k - 1), N * J(0, k), N * D / (2 * a)),
                        objection="The print may have lost the exponent itself (a compositor's omission), the kind "
                                  "then the printer's.",
                        answer=("The line defines $N$, and as transcribed $N$ would be $1$, while the table of $N$ "
                                "that follows gives values other than $1$ and §234's rows are built from them; the "
                                r"integral replaced is the $\int dy\, (\dots)^{3\kappa-1}$ of the line before. A lost "
                                "superscript is the scan's commonest fault in displays and a printer's rarer one: "
                                "medium.")),
        note=claim("N is defined by ∫dy(1 − yⁿ/bⁿ)^{3κ−1} = N∫dy(1 − yⁿ/bⁿ)^κ = ND/(2a)."))
d.quote("moment-EF-N", "§233",
        "\\text{ erit momentum respectu axis EF} = \\frac{2n\\kappa a^2 ND}{1+3n\\kappa} \\\\ & + "
        "\\frac{2nn(\\kappa+1)ccD}{(n(\\kappa+1)+1)^2(n(\\kappa+2)+1)}",
        reading=(Kc, 2 * n * k * a ** 2 * N * D / (1 + 3 * n * k) + 2 * n * n * (k + 1) * c * c * D / (m1 ** 2 * m2)),
        note=claim("the moment about EF is 2nκa²ND/(1 + 3nκ) + 2n²(κ+1)c²D/((n(κ+1)+1)²(n(κ+2)+1))."))

# ---------------------------------------------------------------- the tables of §233–234, rebuilt
KAPPAS = (sp.Rational(1, 2), sp.Integer(1), sp.Rational(3, 2), sp.Integer(2), sp.Rational(5, 2), sp.Integer(3))


def _label(kv):
    return str(kv).replace("/", "_")


def N_factors(kv):
    """N = Π_{j = κ+1, κ+2, …, 3κ−1} jn/(jn + 1) (from Γ(s+1) = sΓ(s)), as Euler writes it: the numerator
    factors 2jn and the denominator factors 2 + 2jn, given by their coefficients 2j."""
    cs_ = []
    j = kv + 1
    while j <= 3 * kv - 1:
        cs_.append(int(2 * j))
        j += 1
    return cs_, cs_


def K0_factors(kv):
    """nκN/(1 + 3nκ): N's factors and 2κn/(2 + 6κn)."""
    nums, dens = N_factors(kv)
    return [int(2 * kv)] + nums, dens + [int(6 * kv)]


def euler_product(nums, dens):
    """(Π (num·n) / Π (2 + den·n), its LaTeX in Euler's form)."""
    expr = sp.Mul(*[cn * n for cn in nums]) / sp.Mul(*[2 + cd * n for cd in dens])
    if not nums:
        return expr, "1"
    return expr, r"\frac{%s}{%s}" % (r" \cdot ".join("%dn" % cn if cn != 1 else "n" for cn in nums), "".join("(2+%dn)" % cd for cd in dens))


def N_rebuilt(kv):
    return euler_product(*N_factors(kv))


def K0_rebuilt(kv):
    return euler_product(*K0_factors(kv))


Nk, Dk, Kk = {}, {}, {}
for kv in KAPPAS:
    Nk[kv] = sp.Symbol("N_{%s}" % kv)
    Dk[kv] = sp.Symbol("D_{%s}" % kv)
    Kk[kv] = sp.Symbol("K_{%s}" % kv)
    d.step("N-%s" % _label(kv), (Nk[kv], quotient(J(0, 3 * kv - 1), J(0, kv)),
                                  quotient(_beta_value(0, 3 * kv - 1, n, b), _beta_value(0, kv, n, b)),
                                  N_rebuilt(kv)[0]),
           "integration", uses=("N", "beta-integral"), result=Nk[kv],
           note="N at κ = %s: the Γ quotient reduces by Γ(s+1) = sΓ(s) to the product" % kv)
    d.step("D-%s" % _label(kv), (Dk[kv], sp.Subs(D, k, kv), 2 * a * J(0, kv)), "substitution", uses=("area",), result=Dk[kv],
           note="the half area at κ = %s" % kv)
    d.step("K0-%s" % _label(kv), (Kk[kv], (4 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1)).subs(k, kv),
                                   2 * n * kv * a ** 2 * Nk[kv] * Dk[kv] / (1 + 3 * n * kv),
                                   2 * a ** 2 * Dk[kv] * K0_rebuilt(kv)[0]), "substitution",
           uses=("moment-EF-c", "moment-EF-N"), result=Kk[kv], note="c = 0, κ = %s" % kv)

N_PRINTED = {
    sp.Rational(1, 2): (r"$\kappa = \frac{1}{2}$	$N = \frac{1}{2}$", sp.Rational(1, 2), "low",
                        (r"$N = \int (1-u^n)^{1/2} \big/ \int (1-u^n)^{1/2} = 1$ ($3\kappa - 1 = \kappa$), and the row "
                         r"$\kappa = \tfrac12$ of §234, $2a^2 D \cdot n/(2+3n) = 2n\kappa a^2 ND/(1+3n\kappa)$, needs $N = 1$. "
                         r"Perhaps a $1$ read as the $\tfrac12$ of the $\kappa$ column beside it."),
                        r"The $1/2$ may be the print's: the compositor setting the $\kappa$ column's $1/2$ again in "
                        "the $N$ column beside it, or Euler's slip, since nothing in §233 is computed from this row.",
                        r"$N = 1$ here ($3\kappa - 1 = \kappa$), and §234's row $\kappa = 1/2$, $2a^2 D \cdot n/(2 + "
                        "3n)$, is computed with $N = 1$, so Euler had the value. But a whole fraction copied from the "
                        "next column is no glyph the scan confuses with $1$, and the compositor's copy cannot be told "
                        "from the transcription's: lowered to low."),
    sp.Integer(1): (r"$\kappa = 1$	$N = \frac{4n}{2+4n}$", 4 * n / (2 + 4 * n), None, "", "", ""),
    sp.Rational(3, 2): (r"$\kappa = \frac{3}{2}$	$N = \frac{5n}{(2+1)n}(2+7n)$", 5 * n / ((2 + 1) * n) * (2 + 7 * n),
                        "medium", r"The rebuilt $N$ is $5n \cdot 7n/((2+5n)(2+7n))$; the transcription keeps $5n$, "
                                  r"$2+\dots n$ and $(2+7n)$ of it but loses the factor $7n$ and scrambles the "
                                  "denominator.",
                        "The row may be garbled in the print itself, a compositor's muddle of a two-line fraction, "
                        "the kind then the printer's.",
                        r"§234's row $\kappa = 3/2$, $3n \cdot 5n \cdot 7n$ over $(2 + 5n)(2 + 7n)(2 + 9n)$, is $3n/(2 "
                        "+ 9n)$ times this $N$ rebuilt, so Euler had it; the pieces kept ($5n$, $(2 + 7n)$, '$(2+1)n$' "
                        "with a $5$ read as $1$) are those of a two-line fraction flattened. The compositor's muddle "
                        "is the alternative left: medium."),
    sp.Integer(2): (r"$\kappa = 2$	$N = \frac{6n}{(2+6n)(2+8n)(2+10n)}$", 6 * n / ((2 + 6 * n) * (2 + 8 * n) * (2 + 10 * n)),
                    "medium", r"The denominator is right; the numerator $6n \cdot 8n \cdot 10n$ lost its last two "
                              "factors (the pattern of every row: one factor $jn$ over each $2 + jn$).",
                    r"The same loss, only the first numerator factor kept, runs through the rows $\kappa = 2$, $5/2$ "
                    "and $3$: a fault consistent through a table is the print's (Euler's abbreviation of the product "
                    "by its first factor, or the compositor's), not the scan's.",
                    r"§234's row $\kappa = 2$, built from $N$, prints every factor: $4n \cdot 6n \cdot 8n \cdot 10n$ "
                    "over $(2 + 6n)(2 + 8n)(2 + 10n)(2 + 12n)$, $4n/(2 + 12n)$ times $N$ rebuilt, so Euler had the "
                    r"whole product and the loss is not carried on; the row $\kappa = 1$, with one factor, is printed "
                    "whole. Whether the print abbreviated or the transcription dropped the rest of a long numerator "
                    "cannot be seen: medium."),
    sp.Rational(5, 2): (r"$\kappa = \frac{5}{2}$	$N = \frac{7n}{(2+7n)(2+9n)(2+11n)(2+13n)}$",
                        7 * n / ((2 + 7 * n) * (2 + 9 * n) * (2 + 11 * n) * (2 + 13 * n)), "medium",
                        r"Denominator right, numerator $7n \cdot 9n \cdot 11n \cdot 13n$ lost three factors.",
                        r"As for $\kappa = 2$: the same loss through three rows may be the print's abbreviation.",
                        r"§234's row $\kappa = 5/2$ prints the numerators $5n \cdot 7n \cdot 9n \cdot 11n \cdot 13n$, "
                        "$5n/(2 + 15n)$ times $N$ rebuilt: Euler had the whole product; print or transcription cannot "
                        "be seen, medium."),
    sp.Integer(3): (r"$\kappa = 3$	$N = \frac{8n}{(2+8n)(2+10n)(2+12n)(2+14n)(2+16n)}$",
                    8 * n / ((2 + 8 * n) * (2 + 10 * n) * (2 + 12 * n) * (2 + 14 * n) * (2 + 16 * n)), "medium",
                    r"Denominator right, numerator $8n \cdot 10n \cdot 12n \cdot 14n \cdot 16n$ lost four factors.",
                    r"As for $\kappa = 2$: the same loss through three rows may be the print's abbreviation.",
                    r"§234's row $\kappa = 3$ prints the numerators $6n \cdot 8n \cdot 10n \cdot 12n \cdot 14n \cdot "
                    "16n$, $6n/(2 + 18n)$ times $N$ rebuilt: Euler had the whole product; print or transcription "
                    "cannot be seen, medium."),
}


def _prod_pairs(nums, dens):
    """The transcription's rows of §234: Π num_i / (den_i · den_{i+1})."""
    out = sp.Integer(1)
    for i, num in enumerate(nums):
        out *= num / (dens[i] * dens[i + 1])
    return out


def _row(start, count):
    nums = [(start + 2 * i) * n for i in range(count)]
    dens = [2 + (start + 2 + 2 * i) * n for i in range(count + 1)]
    return nums, dens


K_PRINTED = {
    sp.Rational(1, 2): (r"$\kappa = \frac{1}{2}$	$2a^2 D \cdot \frac{n}{2+3n}$", n / (2 + 3 * n)),
    sp.Integer(1): (r"$\kappa = 1$	$2a^2 D \cdot \frac{2n}{(2+4n)(2+6n)} \cdot \frac{4n}{(2+6n)(2+8n)}$",
                    _prod_pairs(*_row(2, 2))),
    sp.Rational(3, 2): (r"$\kappa = \frac{3}{2}$	$2a^2 D \cdot \frac{3n}{(2+5n)(2+7n)} \cdot \frac{5n}{(2+7n)(2+9n)} \cdot "
                        r"\frac{7n}{(2+9n)(2+11n)}$", _prod_pairs(*_row(3, 3))),
    sp.Integer(2): (r"$\kappa = 2$	$2a^2 D \cdot \frac{4n}{(2+6n)(2+8n)} \cdot \frac{6n}{(2+8n)(2+10n)} \cdot "
                    r"\frac{8n}{(2+10n)(2+12n)} \cdot \frac{10n}{(2+12n)(2+14n)}$", _prod_pairs(*_row(4, 4))),
    sp.Rational(5, 2): (r"$\kappa = \frac{5}{2}$	$2a^2 D \cdot \frac{5n}{(2+7n)(2+9n)} \cdot \frac{7n}{(2+9n)(2+11n)} \cdot "
                        r"\frac{9n}{(2+11n)(2+13n)} \cdot \frac{11n}{(2+13n)(2+15n)} \cdot \frac{13n}{(2+15n)(2+17n)}$",
                        _prod_pairs(*_row(5, 5))),
    sp.Integer(3): (r"$\kappa = 3$	$2a^2 D \cdot \frac{6n}{(2+8n)(2+10n)} \cdot \frac{8n}{(2+10n)(2+12n)} \cdot "
                    r"\frac{10n}{(2+12n)(2+14n)} \cdot \frac{12n}{(2+14n)(2+16n)} \cdot \frac{14n}{(2+16n)(2+18n)} \cdot "
                    r"\frac{16n}{(2+18n)(2+20n)}$", _prod_pairs(*_row(6, 6))),
}

for kappa in KAPPAS:
    n_excerpt, n_printed, conf, why, n_objection, n_answer = N_PRINTED[kappa]
    n_value, n_tex = N_rebuilt(kappa)
    d.quote("N-table-%s" % _label(kappa), "§233", n_excerpt, reading=(Nk[kappa], n_printed),
            erratum=None if conf is None else Erratum("transcription", conf, "N = " + n_tex, why,
                                                      corrected_reading=(Nk[kappa], n_value),
                                                      objection=n_objection, answer=n_answer),
            note=claim("for κ = %s, N = ∫(1 − yⁿ/bⁿ)^{3κ−1}dy / ∫(1 − yⁿ/bⁿ)^κ dy is the printed entry; rebuilt "
                       "from the Beta integrals: $N = %s$." % (kappa, n_tex)))
    k_excerpt, k_printed = K_PRINTED[kappa]
    k_value, k_tex = K0_rebuilt(kappa)
    d.quote("K-table-%s" % _label(kappa), "§234", k_excerpt, reading=(Kk[kappa], 2 * a ** 2 * Dk[kappa] * k_printed),
            erratum=None if kappa == sp.Rational(1, 2) else Erratum(
                "transcription", "medium", r"2a^2 D \cdot " + k_tex,
                r"$2n\kappa a^2 ND/(1+3n\kappa)$ with the rebuilt $N$ is $2a^2 D$ times the product of the printed "
                "numerators over the first factor of each printed denominator pair. The transcription gives every "
                r"fraction a second factor, the first of the next fraction (a pattern, not arithmetic: with it $\kappa "
                "= 1$, $n = 1$ would give $2a^2 D/480$, against the rhombus' $2a^2 D/6$ that §236 prints).",
                corrected_reading=(Kk[kappa], 2 * a ** 2 * Dk[kappa] * k_value),
                objection="Every fraction of the five rows carries the same second factor, the first of the next "
                          "fraction: a pattern consistent through the whole table is the print's (Euler's or the "
                          "compositor's), not a glyph the scan confused.",
                answer="Euler's later values are computed without it: §236's rhombus $2a^2 D/6$ and $16a^2 D/35$ are "
                       r"the row $\kappa = 1$ at $n = 1$ and $2$ with one factor $2 + jn$ under each numerator (with "
                       "the printed pairs $n = 1$ gives $2a^2 D/480$). The pairs bring in factors foreign to the value "
                       r"($2 + 8n$ in the row $\kappa = 1$), which a compositor following a right manuscript would not "
                       "add to every fraction and a transcription that continues a pattern does; the print cannot be "
                       "seen: medium."),
            note=claim("for c = 0 and κ = %s the moment about EF is the printed entry; rebuilt: $2a^2 D \\cdot %s$."
                       % (kappa, k_tex)))

# ================================================================ §235: n → ∞, the rectangle
Klim = sp.Symbol("K_{inf}")
Ngam = sp.gamma(3 * k) * sp.gamma(k + 1 + m) / (sp.gamma(k + 1) * sp.gamma(3 * k + m))
d.step("N-gamma", (N, _beta_value(0, 3 * k - 1, n, b) / _beta_value(0, k, n, b), sp.Subs(Ngam, m, 1 / n)),
       "integration", uses=("N", "beta-integral"), note="Γ(1/n) cancels; m = 1/n")
d.step("rectangle-limit", (Klim, 2 * a ** 2 * D * sp.Limit(k * Ngam / (m + 3 * k), m, 0, "+"), 2 * a ** 2 * D / 3),
       "limit", uses=("moment-EF-N", "N-gamma"), result=Klim,
       note="c = 0: K = 2a²D·nκN/(1 + 3nκ) = 2a²D·κN/(1/n + 3κ); n → ∞ is m = 1/n → 0, where N → 1")
d.quote("rectangle-limit", "§235", r"$= \frac{2a^2D}{3} = \frac{AB^2D}{6}$",
        reading=as_printed(lambda: (Klim, 2 * a ** 2 * D / 3, (2 * a) ** 2 * D / 6)),
        note=claim("as n → ∞ the figure becomes the rectangle and the moment about EF tends to 2a²D/3 = AB²D/6, "
                   "for every κ > 0."))
slope = sp.diff(a * (1 - (1 - y ** n / b ** n) ** k), y)   # dx/dy of Ace for c = 0
d.quote("angle-n-1", "§235", r"Si pro his curuis ponatur $n=1$, tum anguli, quos curua in A et B cum axe AB "
        r"constituit erunt obliqui",
        reading=(sp.Limit(slope.subs(n, 1), y, 0, "+"), a * k / b),
        note=claim("for n = 1 the curve meets AB at A at an oblique angle: dx/dy → aκ/b, finite and non-zero "
                   "(read for c = 0)."))
d.quote("angle-n-small", "§235", r"sin autem $n < 1$ tum hi anguli euanescent",
        reading=(sp.Limit(1 / slope.subs(n, sp.Rational(1, 2)), y, 0, "+"), 0),
        note=claim("for n < 1 the angle at A vanishes: dy/dx → 0 (read at n = 1/2, c = 0)."))

d.quote("capacity-grows", "§235", r"crescente autem littera n , crescat capacitas figurae",
        reading=(sp.sign(sp.diff(2 * a * _beta_value(0, k, n, b), n)), 1),
        note=claim("the area (capacity) grows with n: D = 2a∫R dy in its Γ form (beta-integral) has a positive "
                   "derivative in n (sampled over 1 < n < 4); so n = 1 gives the least."))
d.quote("kappa-negative", "§235", r"negatiuos enim valores substituere non licet, eo quod curvae tum non "
        r"clatidantur, sed in infinitum extendantur",
        reading=(sp.Limit(1 / (a * (1 - y ** n / b ** n) ** sp.Rational(-1, 2)), y, b, "-"), 0),
        note=claim("for κ < 0 the curves do not close: aR → ∞ as y → b (read at κ = −1/2: 1/(aR) → 0)."))

# ================================================================ §236: the cases
CASES236 = as_printed(lambda: (
    ("rhombus", 1, 1, r"$= \frac{2a^2D}{6} = \frac{AB^2.D}{12}$", 2 * a ** 2 / 6, (2 * a) ** 2 / 12),
    ("parabolas", 1, 2, r"$= \frac{16a^2D}{35} = \frac{4AB^2.D}{35}$", 16 * a ** 2 / 35, 4 * (2 * a) ** 2 / 35),
    ("half-n1", sp.Rational(1, 2), 1, r"$= \frac{2a^2D}{5} = \frac{AB^2.D}{10}$", 2 * a ** 2 / 5, (2 * a) ** 2 / 10),
    ("ellipse", sp.Rational(1, 2), 2, r"$= \frac{a^2D}{2} = \frac{AB^2.D}{8}$", a ** 2 / 2, (2 * a) ** 2 / 8)))
for case_name, case_kv, case_nv, case_excerpt, f1, f2 in CASES236:
    d.quote("case-" + case_name, "§236", case_excerpt,
            reading=(sp.Subs(Kk[case_kv], n, case_nv), *as_printed(lambda: (sp.Subs(f1 * Dk[case_kv], n, case_nv), sp.Subs(f2 * Dk[case_kv], n, case_nv)))),
            note=claim("for κ = %s, n = %s (c = 0) the moment about EF is %s·D, D the half area of that figure."
                       % (case_kv, case_nv, sp.sstr(f1).replace("**", "^").replace("*", " "))))
d.quote("kappa-above-1", "§236", r"posito enim $\kappa > 1$ tum curua in e et f habebit cuspides ac tangentes "
        r"ad AB normales", reading=(sp.Limit(slope.subs({k: 2, n: 2}), y, b, "-"), 0),
        note=claim("for κ > 1 the two portions meet at e with dx/dy → 0, a common tangent normal to AB: a cusp "
                   "(read at κ = 2, n = 2, c = 0)."))
quad_portions = sp.Matrix([sp.Subs(XA, (Ys, n, k), (-c * y / b, 1, 1)), sp.Subs(XB, (Ys, n, k), (-c * y / b, 1, 1))])
ANGLE_E = sp.atan(sp.Derivative(quad_portions[0], y)) + sp.atan(-sp.Derivative(quad_portions[1], y))
d.quote("kappa-1-acute", "§236", r"Quodsi autem sit $\kappa = 1$ anguli ad e et f erunt acuti",
        reading=Holds(sp.And(ANGLE_E > 0, ANGLE_E < sp.pi)),
        note=claim("for κ = 1 the figure has corners ('anguli acuti', sharp angles) at e and f: the two straight "
                   "portions towards A and B meet there at an interior angle above 0, the cusp of κ > 1, and below "
                   "two right angles, the smooth end of κ < 1. Read in the sense the paragraph's division of the "
                   "cases gives the word (cusps with tangents normal to AB for κ > 1, tangents parallel to AB for "
                   "κ < 1); each portion also meets the breadth ef at an acute angle. Read as an angle below 90° "
                   "the sentence would fail for every figure longer than broad ((a − c)(a + c) > b²: 152° for the "
                   "rhombus with AB = 4EF), which Euler, who calls the case n = 1 the rhombus two sentences on, "
                   "cannot have meant; the erratum once booked on that reading is withdrawn."))
d.quote("kappa-1-quadrilateral", "§236", r"hocque casu continetur figura rectilinea quadrilatera quam §. 215. "
        r"considerauimus", reading=(quad_portions.applyfunc(lambda e: sp.Derivative(e, y, 2)), sp.zeros(2, 1)),
        note=claim("κ = 1 (with n = 1 and Y = −cy/b) gives the rectilinear quadrilateral of §215: both portions "
                   "are straight (second derivative 0). The 'anguli acuti' at e and f before it are read at "
                   "kappa-1-acute."))
d.quote("kappa-below-1", "§236", r"At si ponatur $\kappa < 1$ tum curuae in e et f habebunt tangentes axi AB "
        r"parallelas", reading=(sp.Limit(1 / slope.subs({k: sp.Rational(1, 2), n: 2}), y, b, "-"), 0),
        note=claim("for κ < 1 dy/dx → 0 at e: the tangent is parallel to AB (read at κ = 1/2, n = 2)."))

# ================================================================ §237: the number μ
def istep(name, S, integral, note=""):
    """S is the integral over the figure; the closed value (checked by the engine) becomes S's value."""
    return d.step(name, (S, integral, sp.factor(integral.doit())), "integration", result=S, note=note)


Dr, Ir, Kr, Dp, Ip, Kp = sp.symbols("D_r I_r K_r D_p I_p K_p")
Drh, Irh, Krh = (symbol(f"{q}_{{rh}}", rf"{q}_{{\text{{rhombus}}}}") for q in "DIK")
xx = sp.Symbol("xi", real=True)
istep("rect-area", Dr, sp.Integral(b, (xx, -a, a)), note="half area, ordinate b")
istep("rect-I", Ir, sp.Integral(2 * b ** 3 / 3, (xx, -a, a)),
       note="(2/3)∫y³dx over both sides of AB")
istep("rect-K", Kr, sp.Integral(2 * b * xx ** 2, (xx, -a, a)))
hr = b * (1 - xx / a)
istep("rhombus-area", Drh, 2 * sp.Integral(hr, (xx, 0, a)))
istep("rhombus-I", Irh, 2 * sp.Integral(2 * hr ** 3 / 3, (xx, 0, a)))
istep("rhombus-K", Krh, 2 * sp.Integral(2 * hr * xx ** 2, (xx, 0, a)))
hp = b * (1 - xx ** 2 / a ** 2)
istep("parabola-area", Dp, sp.Integral(hp, (xx, -a, a)),
       note="§237: the parabola y = b(1 − x²/a²), its axis on the latitudinal axis EF, both sides of AB")
istep("parabola-I", Ip, sp.Integral(2 * hp ** 3 / 3, (xx, -a, a)))
istep("parabola-K", Kp, sp.Integral(2 * hp * xx ** 2, (xx, -a, a)))


def _mu_pair(D_, I_, K_):
    return sp.Matrix([(2 * b) ** 2 * D_ / I_, (2 * a) ** 2 * D_ / K_])


D_val, IAB_val, N_val = 2 * a * J(0, k), 2 * a * J(2, k), J(0, 3 * k - 1) / J(0, k)
muAB_fam = (2 * b) ** 2 * D_val / (2 * IAB_val)                                  # EF²D/I, I = 2·I_{AEB}
muEF_fam = (2 * a) ** 2 * D_val / (2 * n * k * a ** 2 * N_val * D_val / (1 + 3 * n * k))   # AB²D/K, c = 0
d.quote("mu-rectangle", "§237", r"si sectio aquae sit rectangulum, fiat $\mu = 6$",
        reading=(_mu_pair(Dr, Ir, Kr), sp.Matrix([6, 6])),
        note=claim("the rectangle has μ = 6 about both axes (I = EF²D/μ, K = AB²D/μ, 2D the area)."))
d.quote("mu-rhombus", "§237", r"si rhombus, $\mu = 12$", reading=(_mu_pair(Drh, Irh, Krh), sp.Matrix([12, 12])),
        note=claim("the rhombus has μ = 12."))
d.quote("mu-ellipse", "§237", r"si sectio aquae fuerit ellipsis fore $\mu = 8$",
        reading=(sp.Matrix([sp.Subs(v, (n, k), (2, sp.Rational(1, 2))) for v in (muAB_fam, muEF_fam)]),
                 sp.Matrix([8, 8])),
        note=claim("the ellipse has μ = 8 (the member n = 2, κ = 1/2 of the family)."))
d.quote("mu-parabola-AB", "§237", r"pro momento respectu axis longitudinalis $\mu = \frac{35}{4}$",
        reading=((2 * b) ** 2 * Dp / Ip, sp.Rational(35, 4)),
        note=claim("the parabola with its axis along EF has μ = 35/4 for the moment about AB."))
d.quote("mu-parabola-EF", "§237", r"at respectu axis latitudinalis erit $\mu = 10$",
        reading=((2 * a) ** 2 * Dp / Kp, 10), note=claim("and μ = 10 about EF."))
mu_adm = sp.Matrix([muAB_fam, muEF_fam]).xreplace({n: n1, k: k1})
d.quote("mu-bounds", "§237", r"ubi μ est numerus inter limites 6 et 12 contentus",
        reading=(mu_adm.applyfunc(lambda v: sp.Min(sp.Max(v, 6), 12)), mu_adm),
        note=claim("μ lies between 6 and 12. Read over the waterplanes of the family that §235–236 admit, "
                   "n ≥ 1 and 0 < κ ≤ 1 (convex, c = 0), for both axes: μ clipped to [6, 12] is μ. Outside "
                   "them the bound fails (κ = 3, n = 1 gives μ = 15 about EF; n = 1/2, κ = 1 gives 20), "
                   "figures Euler excludes as waterplanes."))
d.step("moment-EF-c0", (K0g, sp.Subs(Kc, c, 0), 4 * n * k * a ** 3 / b ** n * J(n, 3 * k - 1)), "substitution",
       uses=("moment-EF-c",), result=K0g, note="the figure with c = 0 (the same n, κ, a, b)")
d.quote("unequal-halves", "§237", r"hac ipsa inaequalitate momentum respectu axis latitudinalis augebitur",
        reading=(Kc - K0g, 2 * n ** 2 * (k + 1) * c ** 2 * D / (m1 ** 2 * m2)),
        note=claim("unequal fore and aft halves increase the moment about EF: in the family the excess over "
                   "c = 0 is 2n²(κ+1)c²D/((n(κ+1)+1)²(n(κ+2)+1)) ≥ 0."))

# ================================================================ §§238–241: stability
d.step("I-mu", Eq(Iw, EF ** 2 * Dw / mu), "definition", result=Iw, note="§238: μ defined by I = EF²D/μ")
d.step("K-nu", Eq(Kw, AB ** 2 * Dw / nu), "definition", result=Kw, note="§238: ν defined by K = AB²D/ν")
E192 = "euler-192-219:"
d.step("stability-AB", Eq(SAB, M * (Iw / V - OG)), "lemma", result=SAB,
       uses=(E192 + "stability-definition-G-above", E192 + "metacentric-height-G-above"),
       note="§201/§203: M(I/V − b) with b = OG, G above O")
d.step("stability-EF", Eq(SEF, M * (Kw / V - OG)), "lemma", result=SEF,
       uses=(E192 + "stability-definition-EF-G-above", E192 + "metacentric-height-EF-G-above"))
# the quantities §§238-240 name in words (symfloat/model/vocabulary.json), by the formulas that define them: the
# stability about AB (G the height OG above O; a sentence on G below O puts -OG for OG), the moment I = EF²D/μ of
# the waterplane about AB (a sentence on the axis EF puts AB for EF and ν for μ: the moment K = AB²D/ν)
d.defines("stability", SAB)
d.defines("moment", Iw)
d.step("stability-AB-G-below", Eq(SABp, M * (Iw / V + OG)), "lemma", result=SABp,
       uses=(E192 + "stability-definition", E192 + "metacentric-height-G-below"))
d.quote("stability-AB", "§239", r"$AB = M (\frac{EF^2 \cdot D}{\mu v} - OG)$",
        reading=(SAB, M * (EF ** 2 * Dw / (mu * V) - OG)),
        note=claim("the stability about AB is M(EF²D/(μV) − OG) (v read as V)."),
        symbols={"v": (V, "the volume V of §238 (the transcription writes it v, as it writes ν)")})
d.quote("stability-EF", "§239", r"$= M (\frac{AB^2 \cdot D}{v \mu} - OG)$",
        reading=(SEF, M * (AB ** 2 * Dw / (V * mu) - OG)),
        erratum=Erratum("transcription", "low", r"= M (\frac{AB^2 \cdot D}{\nu V} - OG)",
                        r"About EF the moment is $K = AB^2 D/\nu$ (§238), so the number is $\nu$; the $\mu$ may be the "
                        "scan's or Euler's (he swaps the two letters in §241).",
                        corrected_reading=(SEF, M * (AB ** 2 * Dw / (nu * V) - OG)),
                        objection=r"$\mu$ about EF may be the print's: §237 gave both moments with the one letter "
                                  r"$\mu$, and Euler's own pen mixes $\mu$ and $\nu$ in §241 (five places), so the "
                                  "letter here may be his slip rather than the scan's.",
                        answer="The correction stands: §238, the sentence before, names the number of the moment about "
                               r"EF $\nu$ ('diversas autem litteras $\mu$ et $v$ assumpsimus'). But the scan renders "
                               r"$\nu$ as $v$ in §238 and Euler swaps the two letters in §241, so whether the print "
                               r"has $\mu$ here or the scan made it cannot be told: lowered to low."),
        note=claim("the stability about EF is M(AB²D/(νV) − OG)."))
d.quote("stability-G-below", "§239", r"$- OG$ scribi deberet $+ OG$",
        reading=(SABp, M * (EF ** 2 * Dw / (mu * V) + OG)),
        note=claim("with G below O, −OG becomes +OG (read for the axis AB)."),
        not_compared="an instruction (−OG is to be written +OG in the formula before); the reading is that formula "
                     "so changed")
d.quote("stability-AB-241", "§241", r"$= M \left(\frac{EF^2.D}{\nu v} - OG \right)$",
        reading=(SAB, M * (EF ** 2 * Dw / (nu * V) - OG)),
        erratum=Erratum("misprint", "medium", r"= M \left(\frac{EF^2.D}{\mu V} - OG \right)",
                        r"The number of the moment about AB is $\mu$ (§238, §239); §241 has $\nu$ for it and $\mu$ for "
                        "the latitudinal one consistently, in all five places of the paragraph: Euler's swap.",
                        corrected_reading=(SAB, M * (EF ** 2 * Dw / (mu * V) - OG)),
                        objection=r"Euler may mean $\nu$ here: from §241 on he writes $\nu$ for the number of the "
                                  "moment about AB in every place (five in §241), a relettering of his own, not a "
                                  "fault; and he says the two numbers hardly differ.",
                        answer=r"§238 defines $I = EF^2 D/\mu$ and $K = AB^2 D/\nu$ and keeps the letters apart on "
                               "purpose ('quia non semper aequales valores habent'); §239 uses them so. §241 swaps "
                               "them consistently in five places (this stability, the two conditions and both sides of "
                               "the ratio of sixteen), the author's slip and not a glyph the scan confuses: misprint, "
                               "medium (was booked as the scan's at low)."),
        note=claim("the stability about AB is M(EF²D/(μV) − OG)."))
d.quote("EF-exceeds-AB", "§241", r"$\frac{EF^2.D}{\nu v} > OG$ multo magis erit $\frac{AB^2.D'}{\mu v} > OG$",
        reading=(sp.Subs(AB ** 2 * Dw / (mu * V) - EF ** 2 * Dw / (nu * V), nu, mu), Dw * (AB ** 2 - EF ** 2) / (mu * V)),
        note=claim("if the quantity for AB exceeds OG, the one for EF does so much more, AB being much longer than "
                   "EF: at μ = ν (the numbers 'differ little') the excess is D(AB² − EF²)/(μV) > 0 (D' read as D)."))
d.says("G-below-positive", "§239", "hocque casu nauis semper haberet stabilitatem affirmativam",
       "stabilitatem", Compares(">", 0, at={OG: -OG}),
       note=claim("with G below O (−OG written +OG) the stability about AB is positive for every ship: "
                  "M(EF²D/(μV) + OG) > 0."))
d.says("wider-waterplane-more-stable", "§239", "Ratione autem sectionis aquae stabilitas augebitur quo amplior ea "
       "accipiatur", "stabilitas", GrowsWith(Dw, EF),
       note=claim("the stability about AB grows with the waterplane: M(EF²D/(μV) − OG) grows with its half area D "
                  "and with its breadth EF, the 'duplex ratio' the sentence goes on to give."))
d.quote("deeper-G-more-stable", "§239",
        r"Stabilitas porro hoc casu eo erit maior, quo profundius centrum grauitatis G infra centrum magnitudinis O cadet.",
        reading=(sp.Derivative(SABp, OG), M),
        note=claim("with G below O the stability M(EF²D/(μV) + OG) grows with the depth OG of G below O: its "
                   "derivative in OG is M > 0."))
NU_FOR_MU = "euler-229-243/stability-AB-241"
d.quote("EF-condition-241", "§241", r"cum enim fuerit $\frac{EF^2.D}{\nu v} > OG$",
        reading=(SAB / M + OG, EF ** 2 * Dw / (nu * V)),
        erratum=Erratum("misprint", "medium", r"\frac{EF^2.D}{\mu V} > OG",
                        r"The stability about AB is positive when $EF^2 D/(\mu V)$ exceeds $OG$ (§239); §241 writes "
                        r"$\nu$ for the number of the longitudinal moment here, the swap of $\mu$ and $\nu$ booked at "
                        "its first place ('stability-AB-241': consistent through §241, Euler's).",
                        corrected_reading=(SAB / M + OG, EF ** 2 * Dw / (mu * V)), same_as=NU_FOR_MU,
                        objection=r"As at 'stability-AB-241': $\nu$ may be Euler's relettering in §241.",
                        answer="The condition is the one for the stability about AB just written, whose number §238 "
                               r"calls $\mu$; the same swap as at 'stability-AB-241', running through §241, is "
                               "Euler's: misprint, medium."),
        note=claim("the condition for stability about AB is EF²D/(μV) > OG."))
d.quote("AB-condition-241", "§241", r"multo magis erit $\frac{AB^2.D'}{\mu v} > OG$",
        reading=(SEF / M + OG, AB ** 2 * Dprime / (mu * V)),
        erratum=Erratum("misprint", "medium", r"\frac{AB^2.D}{\nu V} > OG",
                        r"About EF the number is $\nu$ (§238: $K = AB^2 D/\nu$); §241 writes $\mu$, the swap of $\mu$ "
                        r"and $\nu$ booked at 'stability-AB-241'. The prime of $D'$ is the scan's: $D$ (half the "
                        "waterplane area) carries none anywhere else, and the same fraction is printed with $D$ in the "
                        "next sentence.",
                        corrected_reading=(SEF / M + OG, AB ** 2 * Dw / (nu * V)), same_as=NU_FOR_MU,
                        objection=r"As at 'stability-AB-241': $\mu$ may be Euler's relettering; and $D'$ may be a mark "
                                  "of the print (a second area).",
                        answer=r"The number of the moment about EF is $\nu$ (§238), and §241 swaps the two letters in "
                               "all five places: Euler's slip, misprint, medium. The prime is a second, smaller fault "
                               "booked with it, the scan's: $D$ carries no prime anywhere else and the same fraction "
                               "stands with $D$ in the next sentence."),
        note=claim("the condition for stability about EF is AB²D/(νV) > OG."))
SIXTEEN = sp.Subs(Kw / Iw, (AB, nu), (4 * EF, mu))            # K/I with AB = 4EF and μ = ν, 'circiter'
d.quote("ratio-16", "§241", r"$\frac{AB^2.D}{\mu v}$ circiter decies et sexies maius fit quam $\frac{EF^2.D}{\nu v}$",
        reading=(sp.Matrix([Kw / V, Iw / V, SIXTEEN]), sp.Matrix([AB ** 2 * Dw / (mu * V), EF ** 2 * Dw / (nu * V), 16])),
        erratum=Erratum("misprint", "medium", r"\frac{AB^2.D}{\nu V} \text{ circiter decies et sexies maius fit quam } "
                        r"\frac{EF^2.D}{\mu V}",
                        r"The two quantities compared are $K/V$ and $I/V$, $K = AB^2 D/\nu$ and $I = EF^2 D/\mu$ "
                        r"(§238); the sentence gives $AB^2$ the number $\mu$ and $EF^2$ the number $\nu$, the swap of "
                        r"$\mu$ and $\nu$ booked at its first place ('stability-AB-241'), at its fourth and fifth "
                        r"places. The claim itself stands with either lettering: with $AB = 4EF$ and $\mu = \nu$ the "
                        r"ratio is $16$ (third entry), and the print's ratio is $16\nu/\mu$ where the right one is "
                        r"$16\mu/\nu$, both 'circiter' $16$ as $\mu$ and $\nu$ 'nullo casu a se inuicem multum "
                        "discrepant'.",
                        corrected_reading=(sp.Matrix([Kw / V, Iw / V, SIXTEEN]),
                                           sp.Matrix([AB ** 2 * Dw / (nu * V), EF ** 2 * Dw / (mu * V), 16])),
                        same_as=NU_FOR_MU,
                        objection="The sentence claims a ratio of about sixteen, which holds whichever letter stands "
                                  r"where, since Euler adds that $\mu$ and $\nu$ hardly differ: the letters do not "
                                  "matter to what is said.",
                        answer="The ratio holds, but the letters name the numbers of §238, and here each stands with "
                               "the other's moment, as in the three places before in §241; the places are one fault,"
                               " Euler's swap: misprint, medium, as at 'stability-AB-241'."),
        note=claim("with AB = 4EF and μ ≈ ν the quantity for EF, AB²D/(νV) = K/V, is about 16 times that for AB, "
                   "EF²D/(μV) = I/V (the ratio read at μ = ν)."))

# ================================================================ §243: displacement
d.step("pyramid", (Vpy, sp.Integral(2 * Dw * (s / CD) ** 2, (s, 0, CD)), 2 * Dw * CD / 3), "integration",
       result=Vpy, note="sections parallel to the base 2D scale with (depth from the apex / CD)²")
d.step("prism", (Vpr, sp.Integral(2 * Dw, (s, 0, CD)), 2 * Dw * CD), "integration", result=Vpr)
d.step("wedge-section", (sp.Integral(2 * y * (1 - s / CD), (s, 0, CD)), y * CD), "integration",
       note="the section across the keel at PM = y: a triangle of base 2y (the chord) and apex on the keel")
d.step("wedge", Eq(Vwe, CD * Dw), "definition", uses=("wedge-section",), result=Vwe,
       note="the sections y·CD summed along the length: CD·∫y dx = CD·D")
d.quote("V-pyramid", "§243", r"$V > \frac{2}{3}D.CD$", reading=(Vpy, sp.Rational(2, 3) * Dw * CD),
        note=claim("V exceeds the pyramid over the waterplane 2D with height CD, (2/3)D·CD."))
d.quote("V-prism", "§243", r"$V < \frac{2}{3}D.CD$", reading=(Vpr, sp.Rational(2, 3) * Dw * CD),
        erratum=Erratum("transcription", "medium", r"V < 2D.CD",
                        r"The prism of base $2D$ and height $CD$ has the volume $2D \cdot CD$, three times the "
                        r"pyramid; the print repeats the pyramid's $2/3$, and $V \approx D \cdot CD$ of the next "
                        r"sentence lies between the bounds only with $2D \cdot CD$. A copied fraction of the "
                        "transcription or of the composing stick: the correction is proved and the line reads without "
                        "doubt, the cause is open: medium (was low).", corrected_reading=(Vpr, 2 * Dw * CD),
                        objection="The repeated $2/3$ may be the print's: a compositor's eye skipping to the line "
                                  "above, or Euler's own slip, since nothing later is computed from this bound.",
                        answer=r"The prism on the base $2D$ with the height $CD$ has $2D \cdot CD$, and $V = D \cdot "
                               "CD$ of the next sentence lies between the bounds only then; the correction is certain. "
                               "A fraction copied from the line above is as likely the compositor's as the "
                               "transcription's, so the cause cannot be told; the printed line itself is read without "
                               "doubt, which makes it medium, not low (low is for a reading in doubt)."),
        note=claim("V is less than the prism of the same base and height."))
d.quote("V-wedge", "§243", r"accipi posse $V = D.CD$", reading=(Vwe, Dw * CD),
        note=claim("the solid of straight lines from the waterplane's rim normal to the keel has V = D·CD."))
d.quote("stability-CD", "§243", r"prodit $= M(\frac{EF^2}{vCD} - OG)$",
        reading=(M * (Iw / Vwe - OG), M * (EF ** 2 / (V * CD) - OG)),
        erratum=Erratum("transcription", "low", r"= M(\frac{EF^2}{\mu CD} - OG)",
                        r"With $V = D \cdot CD$, $EF^2 D/(\mu V) = EF^2/(\mu \cdot CD)$: the $v$ left in the "
                        r"denominator is $\mu$ ($V$ is gone).",
                        corrected_reading=(M * (Iw / Vwe - OG), M * (EF ** 2 / (mu * CD) - OG)),
                        objection=r"The $v$ may be a $\nu$ the scan renders as $v$ (as it does in §238, '$\mu$ et $v$ "
                                  r"numeros'): the print would then have $EF^2/(\nu \cdot CD)$, Euler's own letter of "
                                  "§241 for the number of the moment about AB, so the fault is his swap booked at "
                                  "'stability-AB-241' and not the scan's.",
                        answer=r"The correction stands: with $V = D \cdot CD$ the stability about AB is $M(EF^2/(\mu "
                               r"\cdot CD) - OG)$, and $v$ as the volume would leave $V$ and $CD$ both in the "
                               r"denominator. But the $v$ is as well a $\nu$ carried on from §241 as a $\mu$ garbled "
                               "by the scan, so which fault it is cannot be told: lowered to low."),
        note=claim("with V = D·CD the stability about AB is M(EF²/(μ·CD) − OG)."))


# the rectangle of §213 (half-length a, half-breadth b, D_r half its area) tells the factor of D in the area
rect_whole = sp.Integral(2 * b, (xx, -a, a))
d.quote("waterplane-area", "§238", r"Denique sit area sectionis aquae $= z D$",
        reading=(sp.Matrix([rect_whole, Ir]), sp.Matrix([zl * Dr, (2 * b) ** 2 * (rect_whole / zl) / 6])),
        erratum=Erratum("transcription", "high", r"\text{Denique sit area sectionis aquae } = 2D",
                        "$D$ is half the waterplane area throughout (§212: 'aream ... ponamus $= 2D$, quam "
                        "designationem semper ... adhibebimus'; §237: '$D$ semissim areae sectionis aquae'), and the "
                        r"same sentence's $I = EF^2 D/\mu$ with $\mu = 6$ for the rectangle (§237) needs the area "
                        r"$2D$: for the rectangle of §213 the area $4ab$ is $2 \cdot D$, and with the area $z \cdot "
                        "D$, $I = EF^2 D/6$ would give $(8/(3z))ab^3$ instead of $(4/3)ab^3$ (read with the "
                        "rectangle). No $z$ is defined in the text: the digit $2$ read as the letter $z$; high.",
                        corrected_reading=(sp.Matrix([rect_whole, Ir]), sp.Matrix([2 * Dr, (2 * b) ** 2 * Dr / 6])),
                        objection="$z$ may be a number of Euler's own, the area being $z$ times $D$ for a $z$ left "
                                  r"open, and $I = EF^2 D/\mu$ a second definition independent of it.",
                        answer="No $z$ is defined or used anywhere in the text; §212 names the area $2D$ 'quam "
                               "designationem semper ad aream cuiusvis sectionis aquae designandam adhibebimus' and "
                               r"§237 calls $D$ half the area, and with the area $zD$ the rectangle's $\mu = 6$ of "
                               "§237 would not hold. The digit $2$ read as $z$, a glyph the scan confuses: high."),
        note=claim("the waterplane has the area 2D (D half of it), I = EF²D/μ and K = AB²D/ν; read with the "
                   "rectangle of §213, for which μ = 6."))
d.quote("waterplane-area-grows", "§239", r"tum enim non solum area eius $z D$ eo fiet maior",
        reading=(rect_whole, zl * Dr),
        erratum=Erratum("transcription", "high", r"\text{tum enim non solum area eius } 2D \text{ eo fiet maior}",
                        "The area of the waterplane is $2D$ (§212, §237, and the sentence of §238 with the same '$z "
                        "D$', booked at 'waterplane-area'): the digit $2$ read as $z$. The claim itself holds: at "
                        r"fixed $M$ and $V$ a larger waterplane raises $EF^2 D/(\mu V)$ through $D$ and through $EF$.",
                        corrected_reading=(rect_whole, 2 * Dr), same_as="euler-229-243/waterplane-area",
                        objection="As at 'waterplane-area': $z$ may be a number of Euler's.",
                        answer="The same '$z D$' for the area $2D$ (§212, §237), the digit $2$ read as $z$: high, as "
                               "at 'waterplane-area'."),
        note=claim("the waterplane's area 2D grows with the waterplane (read with the rectangle of §213)."))
d.says("stability-EF-named", "§239", r"atque momentum respectu axis latitudinalis", "momentum",
       Is(M * (Kw / V - OG), at={EF: AB, mu: nu}),
       erratum=Erratum("misprint", "medium", r"\text{atque stabilitas respectu axis latitudinalis}",
                       "The sentence gives two quantities in parallel, 'stabilitas nauis respectu axis longitudinalis "
                       r"$AB = M(EF^2 D/(\mu V) - OG)$ atque momentum respectu axis latitudinalis $= M(AB^2 D/(\nu V) "
                       "- OG)$'; the second, with the factor $M$ and the term $-OG$, is the stability about EF (§201, "
                       r"§203), not the moment: the moment of the waterplane about EF is $K = AB^2 D/\nu$ (§238, the "
                       "sentence before). Read as printed the moment $K$ would equal $M(K/V - OG)$, which it does not "
                       "($K = 1$, $M = 2$, $V = 1$, $OG = 1/4$: $K = 1$, $M(K/V - OG) = 3/2$). A scan of glyphs does "
                       "not turn 'stabilitas' into 'momentum': a word of the print. But this transcription is a "
                       "model's reading, which writes words and may take one from the sentence before (§238's "
                       "'momentum'), as §230's 'longitudinalis' for 'latitudinalis' may be (medium there too): "
                       "medium.",
                       corrected_reading=d.reads("stabilitas", Is(M * (Kw / V - OG), at={EF: AB, mu: nu})),
                       objection="'Momentum' may be meant in the older sense of the moment of the righting forces "
                                 "(§194: 'momentum virium … quae ad restituendam nauem tendunt'), which is what "
                                 "the stability measures.",
                       answer=r"From §203 on Euler keeps 'momentum' for the waterplane's $\int y^2\, dA$ ($I$, $K$, "
                              r"'momenta earum figurarum') and 'stabilitas' for $M(\cdot/V \pm b)$; the parallel "
                              "clause of the same sentence and §241 ('stabilitas respectu axis latitudinalis') name "
                              "this expression the stability."),
       note=claim("the second quantity of the sentence, M(AB²D/(νV) − OG), is the stability about EF (read "
                  "about the axis EF: AB for EF and ν for μ, so the moment K = AB²D/ν for I = EF²D/μ)."))
MU_AS_V = "euler-229-243/stability-CD"
for excess_name, locator, excess_excerpt in (
        ("excess-maximal", "§242", r"excessus quantitatis $\frac{EF^2.D}{vv}$ supra OG"),
        ("excess-notable", "§242", r"ut quantitas $\frac{EF^2.D}{vv}$ notabiliter intervallum OG superet"),
        ("excess-estimate", "§243", r"haec quantitas $\frac{EF^2.D}{vv}$ circiter praebeat")):
    d.quote(excess_name, locator, excess_excerpt,
            reading=(SAB / M + OG, EF ** 2 * Dw / (V * V)),
            erratum=Erratum("transcription", "low", r"\frac{EF^2.D}{\mu V}",
                            r"The quantity whose excess over $OG$ is the stability about AB is $EF^2 D/(\mu V)$ (§239: "
                            r"$M(EF^2 D/(\mu V) - OG)$). Read with $v$ as the volume $V$ (the module's reading of "
                            r"§239–243), '$vv$' makes it $EF^2 D/V^2$, not even a length. The $v$ stands for $\mu$, "
                            r"the confusion of $\mu$, $\nu$ and $v$ booked at §243's $EF^2/(v \cdot CD)$ "
                            r"('stability-CD'); with $V = D \cdot CD$ the quantity becomes $EF^2/(\mu \cdot CD)$ "
                            "there.",
                            corrected_reading=(SAB / M + OG, EF ** 2 * Dw / (mu * V)), same_as=MU_AS_V,
                            objection=r"'$vv$' may be the scan's rendering of '$\nu v$' (it writes $\nu$ as $v$ in "
                                      r"§238): the print would then have $EF^2 D/(\nu V)$, Euler's letter of §241 for "
                                      "the number of the moment about AB, and the fault his swap booked at "
                                      "'stability-AB-241', not the scan's.",
                            answer="The correction stands: the quantity whose excess over $OG$ is the stability about "
                                   r"AB is $EF^2 D/(\mu V)$, and $EF^2 D/V^2$ is not even a length. But whether the "
                                   r"first $v$ is a $\nu$ carried on from §241 or a $\mu$ the scan garbled cannot be "
                                   "told: low, as at 'stability-CD'."),
            note=claim("the stability about AB is M times the excess of EF²D/(μV) over OG."))
d.quote("c-zero-suffices", "§234",
        r"Ponamus esse $c=0$, quia si hoc casu momentum respectu axis EF fuerit cognitum, ex eo idem momentum pro "
        r"valore quocunque ipsius c inueniri potest",
        reading=(Kc, K0g + 2 * n ** 2 * (k + 1) * c ** 2 * D / (m1 ** 2 * m2)),
        note=claim("the moment about EF for any c is that for c = 0 plus the term of §232 in c alone."))


# ---- §237, §240–241: the claims in words ---------------------------------------------------------------------
d.quote("moment-AB-mu", "§237", r"$AB = \frac{EF^2 \cdot D}{\mu}$",
        reading=(sp.Matrix([Ir, Irh, Ip]), sp.Matrix([(2 * b) ** 2 * Dr / 6, (2 * b) ** 2 * Drh / 12,
                                                      (2 * b) ** 2 * Dp / sp.Rational(35, 4)])),
        note=claim("the moment about AB is EF²D/μ, with the μ the paragraph gives each figure (rectangle 6, "
                   "rhombus 12, the parabola 35/4 about AB). The same letter μ stands here for the number of "
                   "either axis, and the paragraph itself gives the parabola two values (35/4 about AB, 10 about "
                   "EF); §238 then names them μ and ν 'quia non semper aequales valores habent'. So μ in both "
                   "formulas of §237 is the print's usage, not a fault of print or scan: nothing booked."))
d.quote("moment-EF-mu", "§237", r"$EF = \frac{AB^2 \cdot D}{\mu}$",
        reading=(sp.Matrix([Kr, Krh, Kp]), sp.Matrix([(2 * a) ** 2 * Dr / 6, (2 * a) ** 2 * Drh / 12,
                                                      (2 * a) ** 2 * Dp / 10])),
        note=claim("the moment about EF is AB²D/μ (rectangle 6, rhombus 12, the parabola 10 about EF); the "
                   "letter is shared with the other axis as in the formula before (see 'moment-AB-mu')."))
d.quote("mu-near-cases", "§237", r"Provt igitur figura proposita ad aliquem horum quatuor casuum proxime accedit, "
        r"ita valorem litterae μ vero proxime definire licebit",
        reading=(sp.Matrix([sp.Limit(muAB_fam.subs(k, sp.Rational(1, 2)), n, 2),
                            sp.Limit(muEF_fam.subs(k, sp.Rational(1, 2)), n, 2)]), sp.Matrix([8, 8])),
        note=claim("a figure close to one of the four cases has μ close to that case's: in the family of "
                   "§229–236 with c = 0 and κ = 1/2, μ about both axes tends to the ellipse's 8 as n → 2."))
yGs, yBs = sp.symbols("y_G y_B")
d.step("ballast-G", (yGs, fb * 0 + (1 - fb) * sp.Integral(s, (s, 0, Hh)) / Hh, (1 - fb) * Hh / 2), "integration",
       result=yGs, note="§240: the share f of the weight on the keel (height 0), the rest spread evenly over the "
                        "height H; heights above the keel")
d.step("box-B", (yBs, sp.Integral(s, (s, 0, Tq)) / Tq, Tq / 2), "integration", result=yBs,
       note="the centre of buoyancy of the wall-sided hull at the draught T")
d.defines("centre of gravity", yGs)
d.says("even-load-G-at-B", "§240", "si enim tota nauis moles per carinam aequabiliter distribuatur, tum centrum "
       "grauitatis in ipsum centrum magnitudinis caderet", "centrum grauitatis",
       Is(yBs, at={fb: 0, Hh: Tq}),
       note=claim("a ship whose whole mass is spread evenly through the carina, the immersed part (§238: 'carinam "
                  "nauis seu partem aquae immersam'), has its G at the centre of buoyancy: no ballast (f = 0) and "
                  "the height H the draught T give y_G = T/2 = y_B."))
hf = sp.Symbol("h_f", positive=True)             # §240: the height of the hull above the water, H - T
d.says("freeboard-raises-G", "§240", "spicuum est ob partem extra aquam eminentem centrum gravitatis altius esse "
       "positum", "centrum gravitatis", Compares(">", yBs, at={fb: 0, Hh: Tq + hf}, domain={hf: (sp.Rational(1, 10), 2)}),
       note=claim("the part of the hull above the water raises G above the centre of buoyancy: with the mass spread "
                  "evenly over the height H = T + h (h > 0 above the water) and no ballast, y_G = (T + h)/2 > T/2 = "
                  "y_B."))
d.quote("ballast-lowers-G", "§240", r"Quamuis enim maxime ponderosis oneribus in imum carinae collocandis centrum "
        r"gravitatis deorsum et quidem infra centrum magnitudinis deduci posset",
        reading=(yGs - yBs, ((1 - fb) * Hh - Tq) / 2),
        note=claim("heavy loads laid low in the hull can bring G below the centre of buoyancy: for a wall-sided "
                   "hull of height H and draught T with the share f of its weight as ballast on the keel, G lies "
                   "((1 − f)H − T)/2 above B, below it once f > 1 − T/H. The rest of the sentence (warships carry "
                   "so much above the water that G can hardly be brought below the waterline) reports practice, "
                   "which no formula checks."))
d.quote("EF-multo-maior", "§241", r"Quanquam enim stabilitas nauium respectu axis latitudinalis multo maior esse "
        r"debet, quam stabilitas respectu axis longitudinalis, tamen ea satis fiet in gens, si modo stabilitas "
        r"respectu axis longitudinalis sit aliqua",
        reading=(sp.Subs(SEF - SAB, (AB, nu), (4 * EF, mu)), 15 * M * EF ** 2 * Dw / (mu * V)),
        note=claim("the stability about EF exceeds that about AB by much, so it is ample once that about AB is "
                   "positive: with AB = 4EF and ν = μ (§241) the excess is 15MEF²D/(μV) > 0, fifteen times the "
                   "part M·EF²D/(μV) of the stability about AB; 'in gens' is ingens."))
