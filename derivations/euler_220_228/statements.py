"""What Euler's §§220-228 say and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum, Holds
from symfloat.model.claim import as_printed
from symfloat.model.symbol_names import symbol
from symfloat.model.vocabulary import IndependentOf

y = sp.Symbol("y", real=True)
th = sp.Symbol("theta", real=True)
a, b, c = sp.symbols("a b c", positive=True)
p, q = sp.symbols("p q", real=True)

DERIVATION = d = Derivation(
    id="euler-220-228",
    source="euler",
    title="Curved waterplanes of the ellipse's area with the greatest breadth off the middle "
          "(Euler, Scientia navalis III §§220–228)",
    locator="§220–§228",
    summary="The curves x = a + Y ± a√(1 − y²/b²): area and moment about the longitudinal axis independent "
            "of Y (§221–223); the moment about the latitudinal axis through the centroid (§224–226); for "
            "Y = −cy²/b² it is a²D/2 + c²D/8, growing as the greatest breadth moves off the middle, with "
            "c ≤ a/2 (§227–228). Every area and moment is derived by integration over the figure and "
            "witnessed by two-dimensional quadrature.",
    domain={a: (1, 3), b: (sp.Rational(1, 2), 2), c: (sp.Rational(1, 10), sp.Rational(1, 2)),
            p: (sp.Rational(-1, 2), sp.Rational(1, 2)), q: (sp.Rational(-1, 4), sp.Rational(1, 4)),
            y: (0, sp.Rational(1, 2))},
    assumptions=("AO = BO = a, ce = cf = b, Oc = c; A at x = 0, O at x = a, B at x = 2a; y >= 0 on the half "
                 "AEB (0 < y < b wherever y is sampled)",
                 "the general Y is checked as Y = p y + q y^2 on the half y >= 0, i.e. the even function "
                 "p|y| + q y^2 with Y(0) = 0, any p, q; Euler's case of §227 is p = 0, q = -c/b^2",
                 "the portion Ace is the region 0 <= y <= b, x_L(y) <= x <= x_c, Bce the region "
                 "x_c <= x <= x_R(y), AEB their union, with x_L, x_R the two branches of §221 and "
                 "x_c = a + Y(b) the abscissa of ce; AFB is the mirror image of AEB (Y even)",
                 "Euler's integrals are taken from y = 0 to y = b, or from b to 0 where he says so "
                 "('integralibus contrario modo acceptis')",
                 "0 < c <= a/2 for the figures of §227 (the limit is Euler's claim of §228, checked there)"),
)

R = sp.sqrt(b ** 2 - y ** 2)


def integral_symbol(name, latex):
    """The symbol *name* (``int_...``, what the integral integrates), typeset as Euler's integral taken from 0
    to b; its value is stated by one step."""
    return symbol(name, r"{\int_{0}^{b} " + latex + "}")


# pairs (a strip's integrand, the same as written for integration): the step "integrands" checks each pair equal
REWRITTEN = []


def integral_step(name, S, f, integrand, value, note="", theta=None):
    """S := ∫_0^b f dy, stated with its integrand and its closed value (and, with theta, the integrand
    under y = b sin θ, integrated over 0 <= θ <= π/2, between).  The integrand is f written as a
    polynomial plus P(y)/√(b² - y²), every odd power of √(b² - y²) a power of (b - y)(b + y) over
    √(b² - y²): SymPy integrates this form several times faster.  The engine checks the closed value
    against its own evaluation of the integrals; the step "integrands" checks the integrand against f."""
    REWRITTEN.append((f, integrand))
    chain = (S, sp.Integral(integrand, (y, 0, b)))
    chain += (sp.Integral(theta, (th, 0, sp.pi / 2)),) if theta is not None else ()
    d.step(name, chain + (value,), "integration", note=note, result=S)
    return value


def named(name, latex, f, integrand, value, note="", called=None):
    """A printed integral ∫_0^b f dy as a quantity of its own (its symbol, *called* or the step's name, prints
    as the integral), stated once with its closed value; the readings use the symbol, the witnesses its value."""
    python = called or name.replace("-", "_")
    S = symbol(python, "{" + latex + "}") if latex.startswith(r"\left(") else integral_symbol(python, latex)
    integral_step(name, S, f, integrand, value, note=note)
    return S


def claim(text):
    return "The paragraph claims: " + text


# ================================================================ the integrals with √(bb - yy), once each
U0, U2, U4, V2, V4 = (integral_symbol(*t) for t in (("int_R_dy", r"dy \sqrt{bb-yy}"),
                                                    ("int_y2_R_dy", r"yy\,dy \sqrt{bb-yy}"),
                                                    ("int_y4_R_dy", r"y^4 dy \sqrt{bb-yy}"),
                                                    ("int_y2_dy_over_R", r"\frac{yy\,dy}{\sqrt{bb-yy}}"),
                                                    ("int_y4_dy_over_R", r"\frac{y^4 dy}{\sqrt{bb-yy}}")))
D = sp.Symbol("D", positive=True)
integral_step("U0", U0, R,
              -((y + b) * (y - b) / sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * b ** 2 / 4, theta=b ** 2 * sp.cos(th) ** 2, note="∫_0^b √(b²-y²) dy, by y = b sin θ")
integral_step("U2", U2, y ** 2 * R,
              -(y ** 2 * (y + b) * (y - b) / sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * b ** 4 / 16, theta=b ** 4 * sp.cos(th) ** 2 * sp.sin(th) ** 2, note="∫_0^b y² √(b²-y²) dy")
integral_step("U4", U4, y ** 4 * R,
              -(y ** 4 * (y + b) * (y - b) / sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * b ** 6 / 32, theta=b ** 6 * sp.cos(th) ** 2 * sp.sin(th) ** 4, note="∫_0^b y⁴ √(b²-y²) dy")
integral_step("V2", V2, y ** 2 / R,
              y ** 2 / sp.sqrt(b ** 2 - y ** 2),
              sp.pi * b ** 2 / 4, theta=b ** 2 * sp.sin(th) ** 2, note="∫_0^b y² dy/√(b²-y²)")
integral_step("V4", V4, y ** 4 / R,
              y ** 4 / sp.sqrt(b ** 2 - y ** 2),
              3 * sp.pi * b ** 4 / 16, theta=b ** 4 * sp.sin(th) ** 4, note="∫_0^b y⁴ dy/√(b²-y²)")
integral_step("semi-ellipse", D, 2 * a * R / b,
              -2 * a * (y + b) * (y - b) / (b * sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * a * b / 2,
              note="D: the area of the half ellipse with semi-axes a (along AB) and b, by chords "
                   "2a√(1 - y²/b²) at the height y; the figures below have the area 2D (§222)")

# ================================================================ §221: the curves
Yg = p * y + q * y ** 2
dYg = sp.diff(Yg, y)
Yc = -c * y ** 2 / b ** 2
x21 = sp.Matrix([a + Yg - a * sp.sqrt(1 - y ** 2 / b ** 2), a + Yg + a * sp.sqrt(1 - y ** 2 / b ** 2)])
xL, xR, xc = a + Yg - a * R / b, a + Yg + a * R / b, a + Yg.subs(y, b)
d.step("branches", (x21, sp.Matrix([xL, xR])), "algebra",
       note="§221: x = a + Y ± a√(1 - y²/b²), the branch with - bounding Ace, with + bounding Bce; "
            "a√(1 - y²/b²) = (a/b)√(b² - y²) for b > 0, the form of §§224-227. x_c = a + Y(b) is the abscissa "
            "Ac of the greatest breadth ce, where both branches meet")
d.quote("curve", "§221", r"haec aequatio $x = a + Y \pm a \sqrt{1 - \frac{y^2}{b^2}}$, ubi Y denotat",
        reading=(x21, sp.Matrix([xL, xR])),
        note=claim("the curves are x = a + Y ± a√(1 − y²/b²) (read as the two branches, − and +)."))
d.quote("portions", "§222",
        r"valor $x = a + Y - a \sqrt{1 - \frac{y^2}{b^2}}$ valebit pro portione Ace , alter autem valor "
        r"$x = a + Y + a \sqrt{1 - \frac{y^2}{b^2}}$ pro portione Bce",
        reading=(sp.Matrix([sp.Subs(e, y, 0) for e in x21]), sp.Matrix([0, 2 * a])),
        note=claim("the branch with − bounds the portion Ace (it runs through A, x = 0 at y = 0), the branch with "
                   "+ the portion Bce (through B, x = 2a)."))
d.quote("ends", "§221", r"Posito namque $y = 0$, fit x vel $= 0$ vel $= 2a$",
        reading=(sp.Matrix([sp.Subs(e, y, 0) for e in x21]), sp.Matrix([0, 2 * a])),
        note=claim("at y = 0 the two branches give x = 0 and x = 2a (Y vanishes at y = 0)."))
d.quote("axis-AB", "§221", r"erit $AB = 2a$", reading=(sp.Subs(x21[1] - x21[0], y, 0), 2 * a),
        note=claim("the transverse axis of the curve is AB = 2a."))
d.quote("breadth-b", "§221", r"maxima huius curvae latitudo est $= b$",
        reading=(sp.Subs(x21[1] - x21[0], y, b), 0),
        note=claim("the greatest ordinate (half-breadth) of the curve is b: there the two branches meet "
                   "(their distance 2a√(1 - y²/b²) vanishes), and beyond it the root is not real."))
d.quote("greatest-breadth", "§221", r"respondetque abscissae $x = a + Y$, posito in Y loco y valore b",
        reading=(sp.Matrix([sp.Subs(e, y, b) for e in x21]), sp.Matrix([a + Yg.subs(y, b), a + Yg.subs(y, b)])),
        note=claim("the greatest breadth b (where √(1 - y²/b²) vanishes) lies at the abscissa a + Y(b), "
                   "both branches meeting there."))
d.quote("Oc-general", "§221", r"ponamus $Y = -\frac{cyy}{b^2}$, quo fiat interuallum $Oc = c$",
        reading=(sp.Subs(a - (a + Yc), y, b), c),
        note=claim("with Y = -cy²/b² the breadth ce stands at the distance Oc = a - Ac = c from the "
                   "middle O (towards A)."))

# ================================================================ §222: areas
AAce, ABce, AAEB, Awhole = sp.symbols("A_{Ace} A_{Bce} A_{AEB} A_{AEBF}")
integral_step("area-Ace", AAce, xc - xL,
              p * b + q * b ** 2 - p * y - q * y ** 2 - (a * (y + b) * (y - b) / (b * sp.sqrt(b ** 2 - y ** 2))),
              b * (3 * sp.pi * a + 6 * p * b + 8 * q * b ** 2) / 12, note="horizontal strips of Ace from the curve to ce")
integral_step("area-Bce", ABce, xR - xc,
              p * y + q * y ** 2 - p * b - q * b ** 2 - (a * (y + b) * (y - b) / (b * sp.sqrt(b ** 2 - y ** 2))),
              -b * (-3 * sp.pi * a + 6 * p * b + 8 * q * b ** 2) / 12)
integral_step("area-AEB", AAEB, xR - xL,
              -2 * a * (y + b) * (y - b) / (b * sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * a * b / 2, note="the strip width 2(a/b)√(b²-y²) does not contain Y")
d.step("area-whole", Eq(Awhole, 2 * AAEB), "definition", result=Awhole,
       note="AFB is the mirror image of AEB (Y even)")
Yd1 = named("int-y-dY", r"y\,dY", y * dYg,
              p * y + 2 * q * y ** 2,
              b ** 2 * (3 * p + 4 * q * b) / 6)
CA = named("int-y-dx-Ace", r"y\,dx_{Ace}", y * sp.diff(xL, y),
              p * y + 2 * q * y ** 2 + a * y ** 2 / (b * sp.sqrt(b ** 2 - y ** 2)),
              b * (3 * sp.pi * a + 6 * p * b + 8 * q * b ** 2) / 12,
           note="Euler's ∫y dx along the curve Ace (x = x_L) from A to e")
CB = named("int-y-dx-Bce", r"y\,dx_{Bce}", y * sp.diff(xR, y),
              p * y + 2 * q * y ** 2 - a * y ** 2 / (b * sp.sqrt(b ** 2 - y ** 2)),
              b * (-3 * sp.pi * a + 6 * p * b + 8 * q * b ** 2) / 12, note="the same along Bce, from 0 to b")
d.step("by-parts-Ace", (CA, b * xc - sp.Integral(xL, (y, 0, b)), AAce), "integration", uses=("area-Ace",),
       note="∫y dx along the curve is the area of the strips, by parts (x_L(b) = x_c)")
d.step("by-parts-Bce", (-CB, ABce), "integration", uses=("area-Bce",),
       note="∫_b^0 y dx_R = -∫_0^b y dx_R is the area of Bce, by parts")
d.quote("area-Ace", "§222", r"$= \int y dx = \int y dY + \frac{a}{b} \int \frac{yy dy}{\sqrt{b^2 - yy}}$",
        reading=(AAce, CA, Yd1 + a / b * V2),
        note=claim("the portion Ace has the area ∫y dx = ∫y dY + (a/b)∫y²dy/√(b² - y²), from y = 0 to b."))
d.quote("area-Bce", "§222", r"$= \int y dY - \frac{a}{b} \int \frac{yy dy}{\sqrt{b^2 - yy}}$",
        reading=(ABce, -CB, -Yd1 - a / b * (-V2)),
        note=claim("the portion Bce has the area ∫y dY - (a/b)∫y²dy/√(b² - y²), integrals from y = b to 0 "
                   "(each ∫_b^0 read as -∫_0^b)."))
d.quote("area-AEB", "§222", r"$= \frac{2a}{b} \int \frac{yy dy}{\sqrt{b^2 - yy}}$ $= D$",
        reading=(AAEB, 2 * a / b * V2, D),
        note=claim("the half AEB has the area (2a/b)∫y²dy/√(b² - y²) = D, the area of the half ellipse, "
                   "whatever Y is (Y = p|y| + qy² here)."))
d.quote("area-ellipse", "§222",
        r"aream huius curvae $AEBF$ aequalem esse areae ellipsis, cuius axes sint $2a$ et $2b$",
        reading=(Awhole, sp.pi * a * b),
        note=claim("for every single-valued Y the whole figure AEBF has the area of the ellipse with the "
                   "axes 2a and 2b, πab."))

# ================================================================ §223: moment about AB
IAce, IBce, IAEB, Iwhole = sp.symbols("I_{Ace} I_{Bce} I_{AEB} I_{AEBF}")
integral_step("AB-Ace", IAce, y ** 2 * (xc - xL),
              -p * y ** 3 - q * y ** 4 + p * b * y ** 2 + q * y ** 2 * b ** 2
              - (a * y ** 2 * (y + b) * (y - b) / (b * sp.sqrt(b ** 2 - y ** 2))),
              b ** 3 * (15 * sp.pi * a + 20 * p * b + 32 * q * b ** 2) / 240, note="∫∫ y² over Ace, horizontal strips")
integral_step("AB-Bce", IBce, y ** 2 * (xR - xc),
              p * y ** 3 + q * y ** 4 - p * b * y ** 2 - q * y ** 2 * b ** 2
              - (a * y ** 2 * (y + b) * (y - b) / (b * sp.sqrt(b ** 2 - y ** 2))),
              -b ** 3 * (-15 * sp.pi * a + 20 * p * b + 32 * q * b ** 2) / 240)
integral_step("AB-AEB", IAEB, y ** 2 * (xR - xL),
              -2 * a * y ** 2 * (y + b) * (y - b) / (b * sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * a * b ** 3 / 8)
d.step("AB-whole", Eq(Iwhole, 2 * IAEB), "definition", result=Iwhole, note="AFB mirrors AEB")
Yd3 = named("int-y3-dY", r"y^3\,dY", y ** 3 * dYg,
              p * y ** 3 + 2 * q * y ** 4,
              b ** 4 * (5 * p + 8 * q * b) / 20)
CIA = named("int-y3-dx-Ace", r"y^3\,dx_{Ace}", y ** 3 * sp.diff(xL, y),
              p * y ** 3 + 2 * q * y ** 4 + a * y ** 4 / (b * sp.sqrt(b ** 2 - y ** 2)),
              b ** 3 * (15 * sp.pi * a + 20 * p * b + 32 * q * b ** 2) / 80)
CIB = named("int-y3-dx-Bce", r"y^3\,dx_{Bce}", y ** 3 * sp.diff(xR, y),
              p * y ** 3 + 2 * q * y ** 4 - a * y ** 4 / (b * sp.sqrt(b ** 2 - y ** 2)),
              b ** 3 * (-15 * sp.pi * a + 20 * p * b + 32 * q * b ** 2) / 80)
d.step("AB-by-parts", (CIA / 3, IAce), "integration", uses=("AB-Ace",),
       note="(1/3)∫y³dx along the curve (vertical strips of height y) is the strip integral")
d.step("AB-by-parts-Bce", (-CIB / 3, IBce), "integration", uses=("AB-Bce",))
BAR = (r"The integral is $\int y^4\,dy/\sqrt{bb-yy}$, as the two lines before it require: $dx = dY + "
       r"(a/b)\,y\,dy/\sqrt{bb-yy}$ on $Ace$, so $(1/3)\int y^3\,dx$ carries $(a/3b)\int y^4\,dy/\sqrt{bb-yy}$; and "
       r"only with the division does the sum $(2a/3b)\int y^4\,dy/\surd = \pi ab^3/8$ give the $Dbb/2$ Euler concludes "
       r"with. The transcription writes the same integral three times as a product with $\sqrt{bb-yy}$: a fraction bar "
       "(or Euler's ':') lost each time, while §222 and §225 keep theirs; medium, since only the transcription is "
       "available.")
d.quote("ellipse-at-Y0", "§223", r"posito enim $Y = 0$ curua nostra habet in ellipsis",
        reading=(sp.Matrix([sp.Subs((e - a) ** 2 / a ** 2 + y ** 2 / b ** 2, (p, q), (0, 0)) for e in x21]),
                 sp.Matrix([1, 1])),
        note=claim("for Y = 0 the curve goes over into ('abit in', transcribed 'habet in') the ellipse "
                   "(x - a)²/a² + y²/b² = 1 of §219."))
d.quote("AB-Ace", "§223",
        r"$= \frac{1}{3} \int y^3 dx = \frac{1}{3} \int y^3 dY + \frac{a}{3b} \int y^4 dy \sqrt{bb-yy}$",
        reading=(IAce, CIA / 3, Yd3 / 3 + a / (3 * b) * U4),
        erratum=Erratum("transcription", "medium",
                        r"= \frac{1}{3} \int y^3 dx = \frac{1}{3} \int y^3 dY + \frac{a}{3b} \int \frac{y^4 dy}{\sqrt{bb-yy}}",
                        BAR, corrected_reading=(IAce, CIA / 3, Yd3 / 3 + a / (3 * b) * V4),
                        objection="The product form stands three times in this paragraph, the same way each time; a "
                                  "form that runs through several places is the print's or Euler's own, not a glyph "
                                  "the scan lost once.",
                        answer=r"Euler's own result needs the quotient: with $y^4\,dy/\sqrt{bb-yy}$ the moment of AEB "
                               r"is $(2a/3b) \cdot 3\pi b^4/16 = \pi ab^3/8$, and twice it is the $Dbb/2$ he concludes "
                               "with; with the product it is not. The three places are one integral carried from Ace "
                               "to Bce to their sum, so one lost sign of division (a bar or Euler's ':') in the scan's "
                               "reading explains all three; §222 keeps its bars. The print cannot be seen, so medium "
                               "stands."),
        note=claim("the portion Ace has the moment (1/3)∫y³dx = (1/3)∫y³dY + (a/3b)∫y⁴dy/√(bb-yy) about AB."))
d.quote("AB-Bce", "§223", r"$= \frac{1}{3} \int y^3 dY - \frac{a}{3b} \int y^4 dy \sqrt{bb-yy}$",
        reading=(IBce, -CIB / 3, -Yd3 / 3 - a / (3 * b) * (-U4)),
        erratum=Erratum("transcription", "medium",
                        r"= \frac{1}{3} \int y^3 dY - \frac{a}{3b} \int \frac{y^4 dy}{\sqrt{bb-yy}}", BAR,
                        corrected_reading=(IBce, -CIB / 3, -Yd3 / 3 - a / (3 * b) * (-V4)),
                        objection="As for Ace: the same product form three times in one paragraph may be the "
                                  "print's.",
                        answer="The same integral as Ace's, with the opposite sign; the conclusion $Dbb/2$ needs the "
                               "quotient, so Euler had it. Medium, since the print cannot be seen."),
        note=claim("the portion Bce has the moment (1/3)∫y³dY - (a/3b)∫y⁴dy/√(bb-yy), integrals from b to 0 (read "
                   "as -∫_0^b)."))
d.quote("AB-AEB", "§223", r"$= \frac{2a}{3b} \int y^4 dy \sqrt{bb-yy}$, in quo quantitas Y non ineft",
        reading=(IAEB, 2 * a / (3 * b) * U4),
        erratum=Erratum("transcription", "medium", r"= \frac{2a}{3b} \int \frac{y^4 dy}{\sqrt{bb-yy}}", BAR,
                        corrected_reading=(IAEB, 2 * a / (3 * b) * V4),
                        objection="As for Ace: the product may be the print's; and 'in quo quantitas Y non inest' is"
                                  " true of either form.",
                        answer="The remark on Y holds for both forms, but the next sentence's moment $Dbb/2 = ef^2D/8$ "
                               r"of the whole figure is twice $(2a/3b)\int y^4\,dy/\sqrt{bb-yy} = \pi ab^3/8$ ($D = "
                               r"\pi ab/2$), and the product does not give it. Medium, since the print cannot be "
                               "seen."),
        note=claim("AEB has the moment (2a/3b)∫y⁴dy/√(bb-yy) about AB, free of Y."))
# the quantity §223 names in words (symfloat/model/vocabulary.json): the figure's moment about AB, the two
# portions of the half AEB taken apart and AFB its mirror image, so that Y enters each portion's part
d.defines("moment", 2 * (IAce + IBce))
d.says("AB-free-of-Y", "§223", "Deinde dico huius figurae momentum respectu axis longitudinalis AB idem prodire, "
       "quicquid sit functio Y", "momentum", IndependentOf(p, q),
       note=claim("the moment of the figure about AB is the same whatever the function Y: the moments of the "
                  "portions Ace and Bce each change with Y = p|y| + qy², their sum does not (derivatives in p and "
                  "q zero)."))
d.quote("AB-whole", "§223", r"$= \frac{Dbb}{2} = \frac{ef^2 D}{8}$",
        reading=as_printed(lambda: (Iwhole, D * b ** 2 / 2, (2 * b) ** 2 * D / 8)),
        note=claim("the whole figure has, like the ellipse, the moment Db²/2 = ef²D/8 about AB (ef = 2b)."))

# ================================================================ §224: moment about aAa (x = 0)
KAce, KBce, KAEB, Kwhole = sp.symbols("K_{Ace} K_{Bce} K_{AEB} K_{AEBF}")
integral_step("Aa-Ace", KAce, (xc ** 3 - xL ** 3) / 3,
              -a ** 3 - p ** 3 * y ** 3 / 3 - q ** 3 * y ** 6 / 3 + p ** 3 * b ** 3 / 3 + q ** 3 * b ** 6 / 3
              + p * b * a ** 2 + p * q ** 2 * b ** 5 + q * p ** 2 * b ** 4 + q * a ** 2 * b ** 2
              + a * p ** 2 * b ** 2 + a * q ** 2 * b ** 4 + y ** 2 * a ** 3 / b ** 2 - p * q ** 2 * y ** 5
              - q * p ** 2 * y ** 4 - a * p ** 2 * y ** 2 - a * q ** 2 * y ** 4 - 2 * p * y * a ** 2
              - 2 * q * y ** 2 * a ** 2 + p * y ** 3 * a ** 2 / b ** 2 + q * y ** 4 * a ** 2 / b ** 2
              - 2 * p * q * a * y ** 3 + 2 * p * q * a * b ** 3
              - a * (y + b) * (y - b) * (-y ** 2 * a ** 2 + 4 * a ** 2 * b ** 2 + 3 * p ** 2 * y ** 2 * b ** 2
              + 3 * q ** 2 * y ** 4 * b ** 2 + 6 * p * q * y ** 3 * b ** 2 + 6 * p * y * a * b ** 2
              + 6 * q * a * y ** 2 * b ** 2) / (3 * b ** 3 * sp.sqrt(b ** 2 - y ** 2)),
              b * (-2240 * a ** 3 + 840 * p ** 3 * b ** 3 + 960 * q ** 3 * b ** 6 + 1050 * sp.pi * a ** 3
              + 1792 * q * a ** 2 * b ** 2 + 2240 * a * p ** 2 * b ** 2 + 2688 * q * p ** 2 * b ** 4
              + 2688 * a * q ** 2 * b ** 4 + 2800 * p * q ** 2 * b ** 5 + 3080 * p * b * a ** 2
              + 105 * sp.pi * a * q ** 2 * b ** 4 + 210 * sp.pi * a * p ** 2 * b ** 2
              + 420 * sp.pi * q * a ** 2 * b ** 2 + 5936 * p * q * a * b ** 3) / 3360, note="∫∫ x² over Ace, horizontal strips")
integral_step("Aa-Bce", KBce, (xR ** 3 - xc ** 3) / 3,
              a ** 3 - p ** 3 * b ** 3 / 3 - q ** 3 * b ** 6 / 3 + p ** 3 * y ** 3 / 3 + q ** 3 * y ** 6 / 3
              + p * q ** 2 * y ** 5 + q * p ** 2 * y ** 4 + a * p ** 2 * y ** 2 + a * q ** 2 * y ** 4
              - p * b * a ** 2 - p * q ** 2 * b ** 5 - q * p ** 2 * b ** 4 - q * a ** 2 * b ** 2
              - a * p ** 2 * b ** 2 - a * q ** 2 * b ** 4 - y ** 2 * a ** 3 / b ** 2 + 2 * p * y * a ** 2
              + 2 * q * y ** 2 * a ** 2 - p * y ** 3 * a ** 2 / b ** 2 - q * y ** 4 * a ** 2 / b ** 2
              - 2 * p * q * a * b ** 3 + 2 * p * q * a * y ** 3
              - a * (y + b) * (y - b) * (-y ** 2 * a ** 2 + 4 * a ** 2 * b ** 2 + 3 * p ** 2 * y ** 2 * b ** 2
              + 3 * q ** 2 * y ** 4 * b ** 2 + 6 * p * q * y ** 3 * b ** 2 + 6 * p * y * a * b ** 2
              + 6 * q * a * y ** 2 * b ** 2) / (3 * b ** 3 * sp.sqrt(b ** 2 - y ** 2)),
              -b * (-2240 * a ** 3 - 1050 * sp.pi * a ** 3 + 840 * p ** 3 * b ** 3 + 960 * q ** 3 * b ** 6
              - 1400 * p * b * a ** 2 + 1792 * q * a ** 2 * b ** 2 + 2240 * a * p ** 2 * b ** 2
              + 2688 * q * p ** 2 * b ** 4 + 2688 * a * q ** 2 * b ** 4 + 2800 * p * q ** 2 * b ** 5
              - 420 * sp.pi * q * a ** 2 * b ** 2 - 210 * sp.pi * a * p ** 2 * b ** 2
              - 105 * sp.pi * a * q ** 2 * b ** 4 + 4144 * p * q * a * b ** 3) / 3360)
integral_step("Aa-AEB", KAEB, (xR ** 3 - xL ** 3) / 3,
              -2 * a * (y + b) * (y - b) * (-y ** 2 * a ** 2 + 4 * a ** 2 * b ** 2 + 3 * p ** 2 * y ** 2 * b ** 2
              + 3 * q ** 2 * y ** 4 * b ** 2 + 6 * p * q * y ** 3 * b ** 2 + 6 * p * y * a * b ** 2
              + 6 * q * a * y ** 2 * b ** 2) / (3 * b ** 3 * sp.sqrt(b ** 2 - y ** 2)),
              a * b * (150 * sp.pi * a ** 2 + 15 * sp.pi * q ** 2 * b ** 4 + 30 * sp.pi * p ** 2 * b ** 2
              + 128 * p * q * b ** 3 + 320 * p * a * b + 60 * sp.pi * q * a * b ** 2) / 240)
d.step("Aa-whole", Eq(Kwhole, 2 * KAEB), "definition", result=Kwhole, note="AFB mirrors AEB")
T2 = integral_symbol("int_y_aY_R_dY", r"y\,dY (a+Y) \sqrt{bb-yy}")
T4 = integral_symbol("int_y2_aY2_dy_over_R", r"\frac{yy\,dy (a+Y)^2}{\sqrt{bb-yy}}")
integral_step("T2", T2, y * (a + Yg) * R * dYg,
              -(y * (p + 2 * q * y) * (y + b) * (y - b) * (a + p * y + q * y ** 2) / sp.sqrt(b ** 2 - y ** 2)),
              b ** 3 * (80 * p * a + 15 * sp.pi * b * p ** 2 + 15 * sp.pi * q ** 2 * b ** 3 + 96 * p * q * b ** 2
              + 30 * sp.pi * q * a * b) / 240, note="Euler's ∫y dY (a+Y)√(bb-yy), from 0 to b")
integral_step("T4", T4, y ** 2 * (a + Yg) ** 2 / R,
              y ** 2 * (a + p * y + q * y ** 2) ** 2 / sp.sqrt(b ** 2 - y ** 2),
              b ** 2 * (120 * sp.pi * a ** 2 + 75 * sp.pi * q ** 2 * b ** 4 + 90 * sp.pi * p ** 2 * b ** 2
              + 512 * p * q * b ** 3 + 640 * p * a * b + 180 * sp.pi * q * a * b ** 2) / 480, note="∫yy dy (a+Y)²/√(bb-yy)")
BY_PARTS = (p ** 3 * y ** 3 + 2 * q ** 3 * y ** 6 - 2 * y ** 2 * a ** 3 / b ** 2 + 2 * p * y * a ** 2
            + 2 * a * p ** 2 * y ** 2 + 4 * q * p ** 2 * y ** 4 + 4 * q * y ** 2 * a ** 2 + 4 * a * q ** 2 * y ** 4
            + 5 * p * q ** 2 * y ** 5 - 4 * q * y ** 4 * a ** 2 / b ** 2 - 3 * p * y ** 3 * a ** 2 / b ** 2
            + 6 * p * q * a * y ** 3
            + y * a * (-y ** 3 * a ** 2 - 4 * q ** 2 * y ** 3 * b ** 4 - 2 * p * a * b ** 4 - 2 * y * p ** 2 * b ** 4
                       + 2 * y * a ** 2 * b ** 2 + 3 * p ** 2 * y ** 3 * b ** 2 + 5 * q ** 2 * y ** 5 * b ** 2
                       - 6 * p * q * y ** 2 * b ** 4 - 4 * q * y * a * b ** 4 + 4 * p * a * y ** 2 * b ** 2
                       + 6 * q * a * y ** 3 * b ** 2 + 8 * p * q * y ** 4 * b ** 2) / (b ** 3 * sp.sqrt(b ** 2 - y ** 2)))
REWRITTEN.append((y * xL ** 2 * sp.diff(xL, y), BY_PARTS))
d.step("Aa-Ace-by-parts", (sp.Integral(BY_PARTS, (y, 0, b)), KAce), "integration",
       uses=("Aa-Ace",), note="Euler's ∫y x² dx along the curve (vertical strips) is the strip integral")
X2L = (a + Yg) ** 2 - 2 * a * (a + Yg) / b * R + a * a - a * a * y ** 2 / b ** 2
d.step("x-squared", (xL ** 2, X2L), "algebra", note="the square of x = a + Y - (a/b)√(bb-yy)")


P1 = named("int-P1", r"y (a+Y)^2\,dY", y * (a + Yg) ** 2 * dYg,
              p ** 3 * y ** 3 + 2 * q ** 3 * y ** 6 + p * y * a ** 2 + 2 * q * y ** 2 * a ** 2
              + 2 * a * p ** 2 * y ** 2 + 4 * q * p ** 2 * y ** 4 + 4 * a * q ** 2 * y ** 4
              + 5 * p * q ** 2 * y ** 5 + 6 * p * q * a * y ** 3,
              b ** 2 * (105 * p ** 3 * b ** 2 + 120 * q ** 3 * b ** 5 + 210 * p * a ** 2 + 280 * q * b * a ** 2
              + 280 * a * b * p ** 2 + 336 * q * p ** 2 * b ** 3 + 336 * a * q ** 2 * b ** 3
              + 350 * p * q ** 2 * b ** 4 + 630 * p * q * a * b ** 2) / 420)
P3 = named("int-P3", r"y (bb-yy)\,dY", y * (b * b - y * y) * dYg,
              -p * y ** 3 - 2 * q * y ** 4 + p * y * b ** 2 + 2 * q * y ** 2 * b ** 2,
              b ** 4 * (15 * p + 16 * q * b) / 60)
P5 = named("int-P5", r"yy (a+Y)\,dy", y * y * (a + Yg),
              p * y ** 3 + q * y ** 4 + a * y ** 2,
              b ** 3 * (20 * a + 12 * q * b ** 2 + 15 * p * b) / 60)
E4 = named("int-E4", r"\frac{y^4 (a+Y)^2\,dy}{\sqrt{bb-yy}}", y ** 4 * (a + Yg) ** 2 / R,
              y ** 4 * (a + p * y + q * y ** 2) ** 2 / sp.sqrt(b ** 2 - y ** 2),
              b ** 4 * (5040 * sp.pi * a ** 2 + 3675 * sp.pi * q ** 2 * b ** 4 + 4200 * sp.pi * p ** 2 * b ** 2
              + 24576 * p * q * b ** 3 + 28672 * p * a * b + 8400 * sp.pi * q * a * b ** 2) / 26880,
           note="the fourth integral of §224 as transcribed")


def six_terms(sign, reverse):
    """Euler's six integrals for Ace (sign = -1, from 0 to b) or Bce (sign = +1, from b to 0, each read
    as -∫_0^b)."""
    rv = -1 if reverse else 1
    return rv * (P1 + sign * 2 * a / b * T2 + a * a / b ** 2 * P3 - sign * a / b * T4
                 - 2 * a * a / b ** 2 * P5 - sign * a ** 3 / b ** 3 * U2)


d.quote("Aa-Ace-product", "§224",
        "$= \\int y (dY + \\frac{aydy}{b\\sqrt{bb-yy}})$\n $(a+Y)^2 - \\frac{2a(a+Y)}{b} V(bb-yy) + aa - "
        "\\frac{aayy}{bb}",
        reading=(KAce, sp.Integral(y * (dYg + a * y / (b * R)) * (a + Yg) ** 2, (y, 0, b))
                 - 2 * a * (a + Yg) / b * R + a * a - a * a * y ** 2 / b ** 2),
        erratum=Erratum(
            "transcription", "medium",
            r"= \int y \left(dY + \frac{ay\,dy}{b\sqrt{bb-yy}}\right)\left((a+Y)^2 - \frac{2a(a+Y)}{b}\sqrt{bb-yy} + aa - \frac{aayy}{bb}\right)",
            r"The moment of Ace about aAa is $\int y\,x^2\,dx$, with $dx = dY + ay\,dy/(b\sqrt{bb-yy})$ and $x^2 = "
            r"(a+Y)^2 - 2a(a+Y)\sqrt{bb-yy}/b + aa - aayy/bb$: the whole four-term square multiplies $y\,dx$, as the "
            "six integrals that follow show. As transcribed only $(a+Y)^2$ stands under the integral and three loose "
            "terms in $y$ follow; the vinculum (or brackets) over the second factor is lost.",
            corrected_reading=(KAce, sp.Integral(y * (dYg + a * y / (b * R)) * X2L, (y, 0, b))),
                        objection="Euler's page may set the second factor on its own line without brackets, the line"
                                  " break (and perhaps a vinculum the scan cannot render) showing the product, so "
                                  "that the print is right in its own notation.",
                        answer=r"That is the reading the erratum makes: the six integrals that follow multiply $y\,dx$ "
                               "by all four terms of $x^2$, so Euler meant the product, and the fault is the "
                               "transcription's, which flattens the two lines into a sum with three loose terms. "
                               "Whether the print marked the factor with a vinculum or by its layout cannot be seen; "
                               "medium."),
        note=claim("the portion Ace has the moment ∫y(dY + ay dy/(b√(bb-yy)))·x² about aAa, "
                   "x² = (a+Y)² - 2a(a+Y)√(bb-yy)/b + aa - aa yy/bb."))
d.quote("Aa-Ace-expanded", "§224",
        r"= \int y (a+Y)^2 dY - \frac{2a}{b} "
        r"\int y dY (a+Y) V(bb-yy) + \frac{aa}{bb} \int y dY (bb-yy) + \frac{a}{b} \int \frac{yy^2 y(a+Y)^2}"
        r"{\sqrt{bb-yy}} - \frac{2aa}{bb} \int yy dy (a+Y) + \frac{a^3}{b^3} \int yy dy V(bb-yy)$",
        reading=(KAce, six_terms(-1, False) - a / b * T4 + a / b * E4),
        erratum=Erratum(
            "transcription", "high",
            r"\ldots + \frac{a}{b} \int \frac{yy\,dy\,(a+Y)^2}{\sqrt{bb-yy}} - \ldots",
            (r"The fourth integral comes from $(a/b) \cdot y \cdot y\, dy/\sqrt{bb-yy}$ times $(a+Y)^2$: $\int yy\, "
             r"dy\, (a+Y)^2/\sqrt{bb-yy}$, printed so for Bce in the same paragraph. '$yy^2 y$' has no differential "
             "and reads as $y^4$: the '$dy$' garbled into '${}^2 y$'. The other five terms are right."),
            corrected_reading=(KAce, six_terms(-1, False)),
                        objection="The slip may be the print's: a compositor setting the fourth integrand wrongly in"
                                  " one place.",
                        answer=("'$yy^2 y$' is a superscript 2 where the d of 'dy' stands, a glyph the scan "
                                "confuses, not a sort a compositor would take; the same integral is printed right "
                                r"for Bce in the same paragraph, and §225 carries it on as $\int "
                                r"yy\,dy\,(a+Y)^2/\sqrt{bb-yy}$ with $2a/b$. High.")),
        note=claim("the moment of Ace about aAa is the sum of the six integrals, taken from y = 0 to b "
                   "(the excerpt continues the product quoted above)."))
d.quote("Aa-Bce-expanded", "§224",
        r"$= \int y (a+Y)^2 dY + \frac{2a}{b} \int y dY (a+Y) V(bb-yy) + \frac{aa}{bb} \int y dY (bb-yy) - "
        r"\frac{a}{b} \int \frac{yy dy (a+Y)^2}{\sqrt{bb-yy}} - \frac{2aa}{bb} \int yy dy (a+Y) - "
        r"\frac{a^3}{b^3} \int yy dy V(bb-yy)$ integralibus contrario modo acceptis",
        reading=(KBce, six_terms(1, True)),
        note=claim("the portion Bce has the moment given by the six integrals with the signs of the odd "
                   "powers of √(bb-yy) changed, from y = b to 0 (each read as -∫_0^b)."))

# ================================================================ §225: AEB about aAa
G2 = integral_symbol("int_y_R_d_aY2", r"y\,d.(a+Y)^2 \sqrt{bb-yy}")
S2 = integral_symbol("int_aY2_R_dy", r"(a+Y)^2 dy \sqrt{bb-yy}")
E1 = named("int-E1", r"y\,dy (a+Y) \sqrt{bb-yy}", y * (a + Yg) * R,
              -(y * (y + b) * (y - b) * (a + p * y + q * y ** 2) / sp.sqrt(b ** 2 - y ** 2)),
              b ** 3 * (80 * a + 32 * q * b ** 2 + 15 * sp.pi * p * b) / 240, note="the first integral of §225 as transcribed",
           called="int_y_aY_R_dy")
integral_step("G2", G2, y * sp.diff((a + Yg) ** 2 * R, y),
              -(y * (a + p * y + q * y ** 2) * (y * a - 2 * p * b ** 2 + 3 * p * y ** 2 + 5 * q * y ** 3
              - 4 * q * y * b ** 2) / sp.sqrt(b ** 2 - y ** 2)),
              -b ** 2 * (120 * sp.pi * a ** 2 + 15 * sp.pi * q ** 2 * b ** 4 + 30 * sp.pi * p ** 2 * b ** 2
              + 128 * p * q * b ** 3 + 320 * p * a * b + 60 * sp.pi * q * a * b ** 2) / 480, note="∫y d.(a+Y)²√(bb-yy), from 0 to b")
integral_step("S2", S2, (a + Yg) ** 2 * R,
              -((a + p * y + q * y ** 2) ** 2 * (y + b) * (y - b) / sp.sqrt(b ** 2 - y ** 2)),
              b ** 2 * (120 * sp.pi * a ** 2 + 15 * sp.pi * q ** 2 * b ** 4 + 30 * sp.pi * p ** 2 * b ** 2
              + 128 * p * q * b ** 3 + 320 * p * a * b + 60 * sp.pi * q * a * b ** 2) / 480, note="∫(a+Y)² dy √(bb-yy)")
F2 = y * (a + Yg) ** 2 * R
d.step("G2-by-parts", (G2, sp.Subs(F2, y, b) - sp.Subs(F2, y, 0) - S2, -S2), "integration", uses=("G2", "S2"))
d.quote("Aa-AEB", "§225",
        "$aAa = -\\frac{4a}{b} \\int y dy (a+Y) V(bb-yy)$\n $+ \\frac{2a}{b} \\int \\frac{yydy(a+Y)^2}"
        "{\\sqrt{bb-yy}} + \\frac{2a^3}{b^3} \\int yy dy V(bb-yy) = \\frac{2a^3}{b^3} \\int yy dy V(bb-yy) - "
        "\\frac{2a}{b} \\int yd.(a+Y)^2 V(bb-yy) = \\frac{2a^3}{b^3} \\int yy dy V(bb-yy)$\n $+ \\frac{2a}{b} "
        "\\int (a+Y)^2 dy V(bb-yy);$",
        reading=(KAEB, -4 * a / b * E1 + 2 * a / b * T4
                 + 2 * a ** 3 / b ** 3 * U2, 2 * a ** 3 / b ** 3 * U2 - 2 * a / b * G2,
                 2 * a ** 3 / b ** 3 * U2 + 2 * a / b * S2),
        erratum=Erratum(
            "transcription", "medium",
            r"aAa = -\frac{4a}{b} \int y\,dY (a+Y) \sqrt{bb-yy} + \ldots",
            r"The first integral is the sum of the terms $\mp(2a/b)\int y\,dY\,(a+Y)\sqrt{bb-yy}$ of Ace and Bce (§224 "
            r"prints $dY$ there), and only with $dY$ does $-(4a/b)\int y\,dY\,(a+Y)\surd + (2a/b)\int "
            r"yy\,dy\,(a+Y)^2/\surd$ equal $-(2a/b)\int y\,d.(a+Y)^2\sqrt{bb-yy}$, the next member. The capital Y of "
            "'$dY$' read as a small y, as again in §226; a misprint of 1749 cannot be excluded, hence medium. The "
            "other members hold.",
            corrected_reading=(KAEB, -4 * a / b * T2 + 2 * a / b * T4 + 2 * a ** 3 / b ** 3 * U2,
                               2 * a ** 3 / b ** 3 * U2 - 2 * a / b * G2, 2 * a ** 3 / b ** 3 * U2 + 2 * a / b * S2),
                        objection="$dy$ for $dY$ stands also in §226; the same swap in two paragraphs of Euler's "
                                  "working would be his own (or the print's), not the scan's.",
                        answer=r"In both places the very next member, $-(2a/b)\int y\,d.(a+Y)^2\surd$ here and "
                               r"$-(2a/b)\int y\,d.(a+Y)\surd$ in §226, equals the line only with $dY$, and the values "
                               "Euler goes on to use hold, so the swap is not carried on in his working. Y and y of "
                               "one italic fount differ by size, a confusion of the scan as of a compositor; medium."),
        note=claim("adding the two portions, AEB has the moment -(4a/b)∫y dY(a+Y)√ + (2a/b)∫yy dy(a+Y)²/√ "
                   "+ (2a³/b³)∫yy dy√ = (2a³/b³)∫yy dy√ - (2a/b)∫y d.(a+Y)²√ = (2a³/b³)∫yy dy√ "
                   "+ (2a/b)∫(a+Y)²dy√ about aAa (√ = √(bb-yy), integrals from 0 to b)."))
d.quote("boundary-term", "§225", r"$y(a+Y)^2 V(bb-yy)$ fit $= 0;$ tam si $y=0,$ quam si $y=b.$",
        reading=(sp.Matrix([sp.Subs(F2, y, 0), sp.Subs(F2, y, b)]), sp.Matrix([0, 0])),
        note=claim("the integrated part y(a+Y)²√(bb-yy) vanishes at y = 0 and at y = b."))
DCUBE = (r"$D^3$ cannot stand in an area or a length (the integral $\int yy\,dy\sqrt{bb-yy} = \pi b^4/16$ is of the "
         r"fourth dimension, $b^3D/8a$ with $D = \pi ab/2$); §226 prints the same value as $b^3D/8a$, and $a^2D/4 + "
         r"\ldots$ follows. The transcription turned $D$ into $D^3$ three times in this paragraph (a mark after D read "
         "as an exponent); high.")
d.quote("U2-value", "§225",
        r"$\int yy dy V(bb-yy) = \frac{bb}{4} \int \frac{yydy}{\sqrt{bb-yy}} = \frac{b^3 D^3}{8a},$",
        reading=(U2, b * b / 4 * V2, b ** 3 * D ** 3 / (8 * a)),
        erratum=Erratum("transcription", "high",
                        r"\int yy dy \sqrt{bb-yy} = \frac{bb}{4} \int \frac{yydy}{\sqrt{bb-yy}} = \frac{b^3 D}{8a}",
                        DCUBE, corrected_reading=(U2, b * b / 4 * V2, b ** 3 * D / (8 * a)),
                        objection="$D^3$ may be the print's: a compositor's stray superscript, or a mark of Euler's "
                                  "after D.",
                        answer="A compositor's slip does not recur, and $D^3$ stands in three formulas of this "
                               "paragraph; §226 prints the same value as $b^3D/8a$ and starts its moment about EF from "
                               "$aaD/2$, twice the corrected $aaD/4$, so in Euler's working $D$ carried no exponent. A "
                               "mark after D read as an exponent is the scan's; high."),
        note=claim("from y = 0 to b, ∫yy dy√(bb-yy) = (bb/4)∫yy dy/√(bb-yy) = b³D/8a (by §222)."))
d.quote("Aa-AEB-value", "§225", r"$= \frac{aaD^3}{4} + \frac{2a}{b} \int (a+Y)^2 dy V(bb-yy);$",
        reading=(KAEB, a * a * D ** 3 / 4 + 2 * a / b * S2),
        erratum=Erratum("transcription", "high", r"= \frac{aaD}{4} + \frac{2a}{b} \int (a+Y)^2 dy \sqrt{bb-yy}",
                        DCUBE, corrected_reading=(KAEB, a * a * D / 4 + 2 * a / b * S2),
                        objection=r"As for the value of $\int yy\,dy\sqrt{bb-yy}$: $D^3$ may be the print's.",
                        answer=r"$aaD/4$ is $(2a^3/b^3) \cdot b^3D/8a$, the value §226 prints without the cube, and "
                               "§226 starts its moment about EF from $aaD/2$, twice this; $D^3$ in three formulas of "
                               "one paragraph is the scan's reading of one mark; high."),
        note=claim("AEB has the moment a²D/4 + (2a/b)∫(a+Y)²dy√(bb-yy) about aAa."))
d.quote("Aa-whole", "§225", r"$= \frac{aaD^3}{2} + \frac{2a}{b} \int (a+Y)^2 dy V(bb-yy),$",
        reading=(Kwhole, a * a * D ** 3 / 2 + 2 * a / b * S2),
        erratum=Erratum(
            "misprint", "medium", r"= \frac{aaD}{2} + \frac{4a}{b} \int (a+Y)^2 dy \sqrt{bb-yy}",
            r"The whole figure has twice the moment of AEB, $a^2D/2 + (4a/b)\int (a+Y)^2\,dy\sqrt{bb-yy}$: the first "
            "term is doubled in the print, the second is not. $D^3$ for $D$ is the transcription's (as above); the "
            "$2a/b$ is repeated in the moment about EF of §226, so it stood in the print (or in Euler's manuscript). "
            "§227's result $a^2D/2 + c^2D/8$ needs $4a/b$, so the slip did not enter the calculation; medium.",
            corrected_reading=(Kwhole, a * a * D / 2 + 4 * a / b * S2),
                        objection="The $2a/b$ is repeated in §226, so it runs through two places of Euler's working: a "
                                  "fault of his calculation rather than a misprint.",
                        answer="It is not carried on: §227's $a^2D/2 + c^2D/8$ follows only from $4a/b$ (with $2a/b$ "
                               "and the rest corrected the moment about EF would be $(ac - a^2)D/2$, negative for $c < "
                               "a$), so Euler computed with the right factor and the $2a/b$ is a slip in writing the "
                               "formula out, restated in §226; a fault of the original, the author's pen or the "
                               "compositor's, hence misprint at medium."),
        note=claim("with the half AFB equal to AEB, the whole figure has the moment a²D/2 + (2a/b)∫(a+Y)²dy√ "
                   "about aAa."))

# ================================================================ §226: centroid and the moment about EF
FAEB, AC, KEF = sp.symbols("F_{AEB} AC K_{EF}")
W1, Z1, G1, S1 = (integral_symbol(*t) for t in (("int_y2_aY_dy_over_R", r"\frac{y^2 dy (a+Y)}{\sqrt{bb-yy}}"),
                                                ("int_y_R_dY", r"y\,dY \sqrt{bb-yy}"),
                                                ("int_y_R_d_aY", r"y\,d.(a+Y) \sqrt{bb-yy}"),
                                                ("int_aY_R_dy", r"(a+Y) dy \sqrt{bb-yy}")))
integral_step("first-moment", FAEB, (xR ** 2 - xL ** 2) / 2,
              -2 * a * (y + b) * (y - b) * (a + p * y + q * y ** 2) / (b * sp.sqrt(b ** 2 - y ** 2)),
              a * b * (12 * sp.pi * a + 16 * p * b + 3 * sp.pi * q * b ** 2) / 24, note="∫∫ x over AEB (moment about aAa)")
d.step("centroid", Eq(AC, FAEB / AAEB), "definition", result=AC,
       note="the abscissa of the centroid C of AEB, and of the whole figure (AFB mirrors AEB)")
integral_step("W1", W1, y ** 2 * (a + Yg) / R,
              y ** 2 * (a + p * y + q * y ** 2) / sp.sqrt(b ** 2 - y ** 2),
              b ** 2 * (12 * sp.pi * a + 32 * p * b + 9 * sp.pi * q * b ** 2) / 48, note="∫y²dy(a+Y)/√(bb-yy), from 0 to b")
integral_step("Z1", Z1, y * R * dYg,
              -(y * (p + 2 * q * y) * (y + b) * (y - b) / sp.sqrt(b ** 2 - y ** 2)),
              b ** 3 * (8 * p + 3 * sp.pi * q * b) / 24, note="∫y dY √(bb-yy)")
integral_step("G1", G1, y * sp.diff((a + Yg) * R, y),
              -(y * (y * a - p * b ** 2 + 2 * p * y ** 2 + 3 * q * y ** 3 - 2 * q * y * b ** 2) / sp.sqrt(b ** 2
              - y ** 2)),
              -b ** 2 * (12 * sp.pi * a + 16 * p * b + 3 * sp.pi * q * b ** 2) / 48, note="∫y d.(a+Y)√(bb-yy)")
integral_step("S1", S1, (a + Yg) * R,
              -((y + b) * (y - b) * (a + p * y + q * y ** 2) / sp.sqrt(b ** 2 - y ** 2)),
              b ** 2 * (12 * sp.pi * a + 16 * p * b + 3 * sp.pi * q * b ** 2) / 48, note="∫(a+Y) dy √(bb-yy)")
# the centroid's abscissa, F_AEB / A_AEB of the closed values (the step AC-value checks it)
ACv = (12 * sp.pi * a + 16 * p * b + 3 * sp.pi * q * b ** 2) / (12 * sp.pi)
integral_step("moment-EF", KEF, 2 * ((xR - ACv) ** 3 - (xL - ACv) ** 3) / 3,
              -a * (y + b) * (y - b) * (256 * p ** 2 * b ** 4 - 48 * sp.pi ** 2 * y ** 2 * a ** 2
              + 9 * sp.pi ** 2 * q ** 2 * b ** 6 + 48 * sp.pi ** 2 * a ** 2 * b ** 2
              - 384 * sp.pi * y * p ** 2 * b ** 3 - 72 * sp.pi ** 2 * q ** 2 * y ** 2 * b ** 4
              + 96 * sp.pi * p * q * b ** 5 + 144 * sp.pi ** 2 * p ** 2 * y ** 2 * b ** 2
              + 144 * sp.pi ** 2 * q ** 2 * y ** 4 * b ** 2 - 384 * sp.pi * p * q * y ** 2 * b ** 3
              - 72 * p * q * y * sp.pi ** 2 * b ** 4
              + 288 * p * q * sp.pi ** 2 * y ** 3 * b ** 2) / (36 * sp.pi ** 2 * b ** 3 * sp.sqrt(b ** 2 - y ** 2)),
              a * b * (-1280 * p ** 2 * b ** 2 + 180 * sp.pi ** 2 * a ** 2 + 45 * sp.pi ** 2 * q ** 2 * b ** 4
              + 180 * sp.pi ** 2 * p ** 2 * b ** 2 + 288 * sp.pi * p * q * b ** 3) / (720 * sp.pi),
              note="∫∫ (x - AC)² over the whole figure (twice AEB), about EF through the centroid")
d.step("AC-value", (AC, ACv), "algebra", uses=("centroid", "first-moment", "area-AEB"))
XY = named("int-xy-dx", r"\left(\int_{0}^{b} xy\,dx_{Ace} - \int_{0}^{b} xy\,dx_{Bce}\right)", y * (xL * sp.diff(xL, y) - xR * sp.diff(xR, y)),
              2 * y * a * (y * a - p * b ** 2 + 2 * p * y ** 2 + 3 * q * y ** 3
              - 2 * q * y * b ** 2) / (b * sp.sqrt(b ** 2 - y ** 2)),
              a * b * (12 * sp.pi * a + 16 * p * b + 3 * sp.pi * q * b ** 2) / 24,
           note="∫xy dx along Ace from A to e and back along Bce from e to B")
E0 = named("int-E0", r"y\,dy \sqrt{bb-yy}", y * R,
              -(y * (y + b) * (y - b) / sp.sqrt(b ** 2 - y ** 2)),
              b ** 3 / 3, note="the second integral of §226 as transcribed", called="int_y_R_dy")
d.step("DAC-by-parts", (XY, FAEB), "integration",
       uses=("first-moment",), note="∫xy dx along Ace and back along Bce is the strip integral")
d.step("parallel-axes", (KEF, Kwhole - 2 * D * AC ** 2), "algebra",
       uses=("moment-EF", "Aa-whole", "centroid", "semi-ellipse"))
d.quote("DAC-definition", "§226", r"$DAC = \int y dx$",
        reading=(D * AC, CA - CB),
        erratum=Erratum(
            "transcription", "low", r"D \cdot AC = \int xy\,dx",
            r"$D \cdot AC$ is the moment of AEB about aAa, $\int xy\,dx$ (the strip $y\,dx$ at the distance $x$); "
            r"$\int y\,dx$ over AEB is the area $D$ itself (§222), which would make $AC = 1$. The next member, "
            r"$(2a/b)\int yy\,dy\,(a+Y)/\surd - \ldots$, is the moment. An x lost in the transcription ('$yx\,dx$'), "
            "or omitted by the printer: low.",
            corrected_reading=(D * AC, XY),
                        objection="The x may have been lost in the print: a compositor dropping one letter of "
                                  r"'$xy\,dx$' (or '$yx\,dx$'), which the scan then read faithfully.",
                        answer=r"The next member is the moment, so Euler meant $\int xy\,dx$; but the loss of a whole "
                               "letter is not a glyph the scan confuses, and nothing in the text tells the print's "
                               "omission from the scan's. Lowered to low."),
        note=claim("D·AC is the integral ∫y dx (as printed) extended over AEB."))
d.quote("DAC", "§226",
        r"$DAC = \frac{2a}{b} \int \frac{y^2 dy(a+Y)}{\sqrt{bb-yy}} - \frac{2a}{b} \int y dy V(bb-yy) = "
        r"-\frac{2a}{b} \int yd.(a+Y) V(bb-yy) = \frac{2a}{b} \int (a+Y) dy V(bb-yy),$",
        reading=(D * AC, 2 * a / b * W1 - 2 * a / b * E0, -2 * a / b * G1,
                 2 * a / b * S1),
        erratum=Erratum(
            "transcription", "medium", r"DAC = \frac{2a}{b} \int \frac{y^2 dy(a+Y)}{\sqrt{bb-yy}} - \frac{2a}{b} \int y\,dY \sqrt{bb-yy} = \ldots",
            r"$x\,dx = d(x^2/2)$ on both branches gives $(2a/b)\int yy\,dy\,(a+Y)/\sqrt{bb-yy} - (2a/b)\int "
            r"y\,dY\sqrt{bb-yy}$, and only so is it $-(2a/b)\int y\,d.(a+Y)\sqrt{bb-yy}$, the next member "
            r"($d.(a+Y)\surd = dY\surd - (a+Y)\,y\,dy/\surd$). $dY$ read as $dy$, as in §225; the other members hold.",
            corrected_reading=(D * AC, 2 * a / b * W1 - 2 * a / b * Z1, -2 * a / b * G1, 2 * a / b * S1),
                        objection="As in §225: $dy$ for $dY$ in two paragraphs may be the same slip of Euler's or of "
                                  "the print, not the scan's.",
                        answer=r"The next member $-(2a/b)\int y\,d.(a+Y)\sqrt{bb-yy}$ expands to $dY\surd - "
                               r"(a+Y)\,y\,dy/\surd$ and equals the line only with $dY$, and $AC = a - c/4$ in §227 "
                               "follows; the slip is not carried on. The Y/y confusion of the scan is the likelier; "
                               "medium."),
        note=claim("D·AC = (2a/b)∫y²dy(a+Y)/√ - (2a/b)∫y dY√ = -(2a/b)∫y d.(a+Y)√ = (2a/b)∫(a+Y)dy√ "
                   "(√ = √(bb-yy), from 0 to b)."))
d.quote("AC", "§226", r"$AC = \frac{2a}{bD} \int (a+Y) dy V(bb-yy).$", reading=(AC, 2 * a / (b * D) * S1),
        note=claim("hence AC = (2a/bD)∫(a+Y)dy√(bb-yy)."))
d.quote("moment-EF", "§226",
        r"$= \frac{aaD}{2} + \frac{2a}{b} \int (a+Y)^2 dy V(bb-yy) - \frac{aa}{bbD} (\int (a+Y) dy V(bb-yy)).$",
        reading=(KEF, a * a * D / 2 + 2 * a / b * S2 - a * a / (b * b * D) * S1),
        erratum=Erratum(
            "misprint", "medium",
            r"= \frac{aaD}{2} + \frac{4a}{b} \int (a+Y)^2 dy \sqrt{bb-yy} - \frac{8aa}{bbD} \left(\int (a+Y) dy \sqrt{bb-yy}\right)^2",
            r"The moment about aAa less $2D \cdot AC^2$ (area $2D$, §217) with $AC = (2a/bD)\int (a+Y)\,dy\surd$ is "
            r"$a^2D/2 + (4a/b)\int (a+Y)^2\,dy\surd - (8a^2/b^2D)(\int (a+Y)\,dy\surd)^2$. The print repeats the "
            "$2a/b$ of §225 and has $aa/bbD$ without the square of the integral (the last term then is not even a "
            "moment); the square and the 8 may be the transcription's losses, the $2a/b$ is the print's. §227's value "
            "$a^2D/2 + c^2D/8$ follows only from the corrected formula; medium.",
            corrected_reading=(KEF, a * a * D / 2 + 4 * a / b * S2 - 8 * a * a / (b * b * D) * S1 ** 2),
                        objection="The correction needs three changes ($4a/b$, the 8, the square); booked as one "
                                  "misprint it claims more than one slip of the compositor.",
                        answer="The kind rests on the $2a/b$, which repeats §225's and so stood in the print; the 8 "
                               "and the square are needed whoever lost them, since without the square the last term is "
                               "not a moment and §227's $a^2D/2 + c^2D/8$ follows only from the corrected formula. "
                               "Which of the three the scan lost cannot be told; medium."),
        note=claim("about the latitudinal axis EF through C the whole figure has the moment "
                   "a²D/2 + (2a/b)∫(a+Y)²dy√ - (aa/bbD)(∫(a+Y)dy√)."))
d.quote("reduce-V2", "§226", r"$\int \frac{yydy}{\sqrt{bb-yy}} = \frac{bD}{2a}$", reading=(V2, b * D / (2 * a)),
        note=claim("for even Y the integrals reduce to ∫yy dy/√(bb-yy) = bD/2a (from 0 to b) ..."))
d.quote("reduce-U2", "§226", r"seu hanc $\int yy dy V(bb-yy) = \frac{b^3 D}{8a},$",
        reading=(U2, b ** 3 * D / (8 * a)), note=claim("... or ∫yy dy√(bb-yy) = b³D/8a ..."))
d.quote("reduce-U0", "§226", r"$\int dy V(bb-yy) = \frac{bD}{2a}.$", reading=(U0, b * D / (2 * a)),
        note=claim("... or ∫dy√(bb-yy) = bD/2a."))

# ================================================================ §227: Y = -cyy/bb
xLc, xRc = a + Yc - a * R / b, a + Yc + a * R / b
AEBc, FAEBc, ACc, KEFc = sp.symbols("A_{AEBc} F_{AEBc} AC_c K_{EFc}")
S2c = integral_symbol("int_a_cY2_R_dy", r"\left(a - \tfrac{cyy}{bb}\right)^2 dy \sqrt{bb-yy}")
S1c = integral_symbol("int_a_cY_R_dy", r"\left(a - \tfrac{cyy}{bb}\right) dy \sqrt{bb-yy}")
integral_step("S2c", S2c, (a + Yc) ** 2 * R,
              -((c * y ** 2 - a * b ** 2) ** 2 * (y + b) * (y - b) / (b ** 4 * sp.sqrt(b ** 2 - y ** 2))),
              sp.pi * b ** 2 * (c ** 2 + 8 * a ** 2 - 4 * a * c) / 32, note="∫(a+Y)²dy√(bb-yy) with Y = -cyy/bb")
integral_step("S1c", S1c, (a + Yc) * R,
              (y + b) * (y - b) * (c * y ** 2 - a * b ** 2) / (b ** 2 * sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * b ** 2 * (-c + 4 * a) / 16)
integral_step("area-c", AEBc, xRc - xLc,
              -2 * a * (y + b) * (y - b) / (b * sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * a * b / 2)
integral_step("first-moment-c", FAEBc, (xRc ** 2 - xLc ** 2) / 2,
              2 * a * (y + b) * (y - b) * (c * y ** 2 - a * b ** 2) / (b ** 3 * sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * a * b * (-c + 4 * a) / 8)
d.step("centroid-c", Eq(ACc, FAEBc / AEBc), "definition", result=ACc)
# the same for Y = -cyy/bb: (4a - c)/4 (the step AC-c-value checks it)
ACcv = sp.Mul(sp.Rational(1, 4), -c + 4 * a, evaluate=False)
kefc = integral_step("moment-EF-c", KEFc, 2 * ((xRc - ACcv) ** 3 - (xLc - ACcv) ** 3) / 3,
              -a * (y + b) * (y - b) * (3 * b ** 4 * c ** 2 + 16 * a ** 2 * b ** 4 + 48 * y ** 4 * c ** 2
              - 24 * y ** 2 * b ** 2 * c ** 2
              - 16 * y ** 2 * a ** 2 * b ** 2) / (12 * b ** 5 * sp.sqrt(b ** 2 - y ** 2)),
              sp.pi * a * b * (c ** 2 + 4 * a ** 2) / 16,
              note="∫∫ (x - AC)² over the whole figure for Y = -cyy/bb")
d.step("AC-c-value", (ACc, ACcv), "algebra", uses=("centroid-c", "first-moment-c", "area-c"))
d.step("integrands", (sp.Matrix([f for f, _ in REWRITTEN]), sp.Matrix([w for _, w in REWRITTEN])), "algebra",
       note="every strip's integrand above, as stated for integration (a polynomial plus P(y)/√(b² - y²)), is the "
            "integrand it was written from")
BRANCHES_C = sp.Matrix([xLc, xRc])
d.quote("Y-c", "§227", r"Ponamus esse $Y = \frac{-cyy}{bb},$",
        reading=(sp.Subs(a - (a + Yc), y, b), c),
        note=claim("Y = −cyy/bb moves the greatest breadth ce, at y = b and x = a + Y(b), by Oc = c from the middle O."))
d.quote("curve-c", "§227", r"seu $x = a - \frac{cyy}{bb} + \frac{c}{b} V(bb-yy),$",
        reading=(xRc, a - c * y ** 2 / b ** 2 + c / b * R),
        erratum=Erratum(
            "misprint", "medium", r"x = a - \frac{cyy}{bb} \pm \frac{a}{b}\sqrt{bb-yy}",
            r"$Y = -cyy/bb$ put into $x = a + Y \pm a\sqrt{1 - yy/bb}$ of §221 gives $a - cyy/bb \pm "
            r"(a/b)\sqrt{bb-yy}$; with $(c/b)\surd$ the curve would not end at B ($x = a + c$ at $y = 0$, not $2a$). "
            r"The same $c/b$, with the same $+$ for the $\pm$, stands in §228's 'aequatio assumta' ('curve-c-again'): "
            "a fault repeated alike at two places a paragraph apart is the print's, not a confusion of the scan (the "
            "consistency criterion of the errata's kinds). Medium: the scan confuses a and c beside it ('$Oc = a$').",
            corrected_reading=as_printed(lambda: (BRANCHES_C, sp.Matrix([a - c * y ** 2 / b ** 2 - a / b * R,
                                                      a - c * y ** 2 / b ** 2 + a / b * R]))),
                        objection="The scan confuses a and c in the very next clause ('$Oc = a$' for $Oc = c$), so "
                                  "$c/b$ may be the same confusion of the scan, and §228's line, damaged at its head "
                                  "('$a =$' for '$x =$'), may repeat it by the same confusion.",
                        answer="A confusion of glyphs does not set the same wrong letter at the same place of two "
                               r"lines a paragraph apart and shorten the $\pm$ to $+$ at both; §228 calls the line the "
                               "'aequatio assumta', the equation of §227 set again. Euler's working does not use it "
                               r"($x = a + Y \pm a\sqrt{1 - yy/bb}$ of §221 with $Y = -cyy/bb$ gives his $\int "
                               r"(a+Y)^2\,dy\surd$ and $AC = a - c/4$), so the slip is the print's: misprint (was the "
                               "scan's, low). The a/c confusion beside it keeps the cause at medium."),
        note=claim("with Y = -cyy/bb the curve is x = a - cyy/bb + (c/b)√(bb-yy); read as the branch Bce."))
d.quote("Oc", "§227", r"ex qua fit $Oc = a$ vti assumsumus",
        reading=(sp.Subs(a - xLc, y, b), a),
        erratum=Erratum(
            "transcription", "medium", r"Oc = c",
            "At $y = b$ both branches give $x = a - c$, so $Ac = a - c$ and $Oc = AO - Ac = c$, 'as we assumed' (§220, "
            "§221, and §232: '$Ac = a - c$ et $Oc = c$'). a for c, the confusion of the line before.",
            corrected_reading=(sp.Subs(a - xLc, y, b), c),
                        objection="'$Oc = a$' may be the print's (a compositor's a for c), or Oc may name another "
                                  "segment of the lost figure.",
                        answer="§221 closes with the same words, 'quo fiat interuallum $Oc = c$ uti assumimus', and "
                               "§232 has '$Oc = c$'; at $y = b$ the curve gives $Ac = a - c$, so $Oc = c$. One letter, "
                               "printed right at the two other places, is the scan's by the criteria; medium, since a "
                               "single a for c may as well be the compositor's and the print cannot be seen."),
        note=claim("the breadth ef stands at Oc = c from the middle O, as assumed."))
d.quote("S2c-expanded", "§227",
        "$\\int (a+Y)^2 dy V(bb-yy) = a^2 \\int dy V(bb-yy) - \\frac{2ac}{bb} \\int yy dy$\n "
        "$V(bb-yy) + \\frac{cc}{b^4} \\int y^4 dy V(bb-yy)$",
        reading=(S2c, a * a * U0 - 2 * a * c / b ** 2 * U2 + c * c / b ** 4 * U4),
        note=claim("∫(a+Y)²dy√ = a²∫dy√ - (2ac/bb)∫yy dy√ + (cc/b⁴)∫y⁴dy√ for Y = -cyy/bb."))
SHIFT = (r"From $y = 0$ to $b$: $\int dy\sqrt{bb-yy} = \pi b^2/4 = bD/2a$, $\int yy\,dy\surd = \pi b^4/16 = b^3D/8a$, "
         r"$\int y^4\,dy\surd = \pi b^6/32 = b^5D/16a$ ($D = \pi ab/2$; the first two as printed in §226). The line "
         "that follows, $abD/2 - bcD/4 + bccD/16a$, is made of exactly these values, so Euler had them. The print "
         "gives $b^3D/8a$, $b^5D/16a$, $b^9D/16a$: each value moved one integral on, consistently through the three "
         "equations of the line, and the last filled with a power that belongs to none. A scan of glyphs misreads "
         "them; it does not move values from one equation to the next: the consistency criterion of the errata's "
         "kinds makes it the print's (the compositor setting the values against the wrong integrals). But this "
         "transcription is a model's reading, which continues patterns (the pairs of factors of §234's table are "
         "booked as the transcription's) and may have moved the values itself; the printed page cannot be seen: "
         "low.")
SHIFT_OBJECTION = ("A scan can lose a line (a fault of the transcription by the criteria): with the first value "
                   "dropped, the others would each move one place on.")
SHIFT_ANSWER = ("A lost value leaves an integral without its value; here all three equations stand, each with a value "
                "of the right form for its neighbour, and the last with $b^9D/16a$, which no line of the page holds. "
                "Not a lost line, then: a shift, the compositor's or the transcription's (a model's reading that "
                "continues patterns); the page cannot be seen, hence low.")
d.quote("U0-value", "§227", r"Verum est $\int dy V(bb-yy) = \frac{b^3 D}{8a}$",
        reading=(U0, b ** 3 * D / (8 * a)),
        erratum=Erratum("misprint", "low", r"\int dy \sqrt{bb-yy} = \frac{bD}{2a}", SHIFT,
                        corrected_reading=(U0, b * D / (2 * a)),
                        objection=SHIFT_OBJECTION, answer=SHIFT_ANSWER),
        note=claim("∫dy√(bb-yy) = b³D/8a (as printed)."))
d.quote("U2-value-c", "§227", r"$\int yy dy V(bb-yy) = \frac{b^5 D}{16a}$", reading=(U2, b ** 5 * D / (16 * a)),
        erratum=Erratum("misprint", "low", r"\int yy dy \sqrt{bb-yy} = \frac{b^3 D}{8a}", SHIFT,
                        corrected_reading=(U2, b ** 3 * D / (8 * a)),
                        objection=SHIFT_OBJECTION,
                        answer="$abD/2 - bcD/4 + bccD/16a$ uses $b^3D/8a$ for this integral, as §226 prints it; the "
                               "value printed here is the next integral's, the shift of the line. " + SHIFT_ANSWER),
        note=claim("∫yy dy√(bb-yy) = b⁵D/16a (as printed)."))
d.quote("U4-value", "§227", r"$\int y^4 dy V(bb-yy) = \frac{b^9 D}{16a}$", reading=(U4, b ** 9 * D / (16 * a)),
        erratum=Erratum("misprint", "low", r"\int y^4 dy \sqrt{bb-yy} = \frac{b^5 D}{16a}", SHIFT,
                        corrected_reading=(U4, b ** 5 * D / (16 * a)),
                        objection=SHIFT_OBJECTION + " And $b^9$ may be a 5 the scan read as 9.",
                        answer=r"The term $bccD/16a$ of the next line is $(cc/b^4) \cdot b^5D/16a$, so Euler had "
                               "$b^5$; a 9 for a 5 would leave the value right in place, not shifted with its "
                               "neighbours. "
                               + SHIFT_ANSWER),
        note=claim("∫y⁴dy√(bb-yy) = b⁹D/16a (as printed)."))
d.quote("S2c-value", "§227",
        r"$\int (a+Y)^2 dy V(bb-yy) = \frac{abD}{2} - \frac{bcD}{4} + \frac{bccD}{16a} = \frac{bD}{16a} (8aa - 4ac + cc)$",
        reading=(S2c, a * b * D / 2 - b * c * D / 4 + b * c * c * D / (16 * a),
                 b * D / (16 * a) * (8 * a * a - 4 * a * c + c * c)),
        note=claim(r"hence $\int (a+Y)^2 dy \sqrt{bb-yy} = abD/2 - bcD/4 + bc^2D/16a = bD(8a^2 - 4ac + c^2)/16a$."))
d.quote("S1c-value", "§227", r"$\int (a+Y) dy V(bb-yy) = \frac{bD}{2} - \frac{bcD}{8a} = \frac{bD}{8a} (4a - c)$",
        reading=(S1c, b * D / 2 - b * c * D / (8 * a), b * D / (8 * a) * (4 * a - c)),
        note=claim(r"likewise $\int (a+Y) dy \sqrt{bb-yy} = bD/2 - bcD/8a = bD(4a - c)/8a$."))
d.quote("AC-c", "§227", r"$AC = a - \frac{c}{4}$", reading=(ACc, a - c / 4),
        note=claim("the centroid lies at AC = a - c/4."))
d.quote("moment-EF-c", "§227",
        r"$EF = \frac{aaD}{2} + \frac{ccD}{8} = \frac{AB^2 D}{8} + \frac{cc^2 D}{128}$",
        reading=(KEFc, a * a * D / 2 + c * c * D / 8, (2 * a) ** 2 * D / 8 + c * c ** 2 * D / 128),
        erratum=Erratum(
            "transcription", "low", r"= \frac{AB^2 D}{8} + \frac{ccD}{8}",
            r"$a^2D/2 + c^2D/8$ (the member before, which holds) with $AB = 2a$ is $AB^2D/8 + c^2D/8$; $c \cdot "
            "c^2D/128$ is neither. The 128 belongs to §228's $AB^2D/128$ ($c = a/2$); what the print had after '$+$' "
            "cannot be told from the transcription, low.",
            corrected_reading=as_printed(lambda: (KEFc, a * a * D / 2 + c * c * D / 8, (2 * a) ** 2 * D / 8 + c * c * D / 8)),
                        objection="The print may have had '$+ ccD/128$' or another form Euler meant for a special "
                                  "case, anticipating §228.",
                        answer="The member before, $a^2D/2 + c^2D/8$, holds and with $AB = 2a$ is $AB^2D/8 + c^2D/8$; "
                               "any other last term contradicts it for general $c$, and §228 sets $c = a/2$ only "
                               "afterwards. What the print had cannot be told, so low."),
        note=claim("the whole figure AEBF has the moment a²D/2 + c²D/8 = AB²D/8 + ... about EF."))

# ================================================================ §228: growth, the limit c <= a/2, c = a/2
d.step("left-branch-split", (xLc, (a / 2 - c) * y ** 2 / b ** 2 + a / 2 * (1 - R / b) ** 2), "algebra",
       note="x_L = (a/2 - c) y²/b² + (a/2)(1 - √(bb-yy)/b)²: both terms >= 0 for c <= a/2, so the curve "
            "stays on the side x >= 0 of aa")
d.step("left-branch-slope", (sp.Limit(xLc * b ** 2 / y ** 2, y, 0), a / 2 - c), "limit",
       note="near A, x_L = (a/2 - c) y²/b² + O(y⁴): negative for c > a/2, the curve crosses aa")
d.quote("moment-grows", "§228",
        "momentum sectionis aquae respectu axis latitudinalis EF maius fieri, quo magis latitudo maxima ef a "
        "punto axis AB medio C distet, ceteris paribus",
        reading=Holds(sp.Derivative(KEFc, c) > 0),
        note=claim("the moment about EF grows as ef moves away from the middle of AB (the text says 'C', the "
                   "middle is O, booked at 'middle-named-C'): at fixed a, b, D its derivative in c = Oc is "
                   "cD/4 = pi a b c/8 > 0 (read as the relation: the derivative is positive)."))
d.quote("middle-named-C", "§228", r"a punto axis AB medio C distet",
        reading=(ACc, sp.Subs((xLc + xRc) / 2, y, 0)),
        erratum=Erratum(
            "transcription", "medium", r"\text{a puncto axis AB medio } O \text{ distet}",
            ("The midpoint of AB is O (§220: 'existente O puncto axis longitudinalis medio'; the same paragraph ends "
             "'a medio punto longitudinis O'), at $AO = a$; C is the centroid of the figure, at $AC = a - c/4$ "
             "(§227), which is not the midpoint for $c > 0$: read as printed, C would be the midpoint of $AB$, $(x_A "
             "+ x_B)/2$ at $y = 0$. The moment $AB^2 D/8 + ccD/8$ grows with $Oc = c$, the distance of ef from O. O "
             "and C are alike in the scan; medium."),
            corrected_reading=(sp.Subs((xLc + xRc) / 2, y, 0), a),
                        objection="Read with C the sentence is still true: ef stands at $3c/4$ from the centroid C "
                                  "($AC = a - c/4$, $Ac = a - c$), and the moment $a^2D/2 + c^2D/8$ grows with that "
                                  "distance too; 'medio' may loosely mean the centre of the figure.",
                        answer="The growth holds either way, but 'punctum axis AB medium' is Euler's own name for O "
                               "(§220 'O puncto axis longitudinalis medio', §232 'punctum axis longitudinalis medium "
                               "O'), and this paragraph ends 'a medio punto longitudinis O'; C is not the midpoint for "
                               "$c > 0$. O and C are alike in the scan; the print's slip is the one alternative left, "
                               "medium."),
        note=claim("the middle of the axis AB, from which the distance of ef is counted, is O (AO = a)."))
d.quote("curve-c-again", "§228", r"$a = a - \frac{cyy}{bb} + \frac{c}{b}$ $V(bb-yy)$",
        reading=Eq(a, a - c * y ** 2 / b ** 2 + c / b * R),
        erratum=Erratum(
            "misprint", "medium", r"x = a - \frac{cyy}{bb} \pm \frac{a}{b}\sqrt{bb-yy}",
            r"The assumed equation is the curve of §227, $x = a - cyy/bb \pm (a/b)\sqrt{bb-yy}$; the print repeats the "
            "$c/b$ and the $+$ of §227, the fault booked there ('curve-c'), which runs alike through both places: the "
            "print's. The a for x at the head of the line is a second, smaller fault booked with it, the scan's (the "
            "curve's abscissa is $x$ throughout).",
            corrected_reading=as_printed(lambda: (BRANCHES_C, sp.Matrix([a - c * y ** 2 / b ** 2 - a / b * R,
                                                      a - c * y ** 2 / b ** 2 + a / b * R]))),
                        same_as="euler-220-228/curve-c",
                        objection="The line differs from the right one in three letters ('$a =$' for '$x =$', c for a, "
                                  r"$+$ for $\pm$), which no single slip explains; the scan, which confuses a and c in "
                                  "these lines, may have made all of them.",
                        answer="The $c/b$ and the $+$ are §227's, set alike at both places, which the scan does not "
                               "do: the print's, as at 'curve-c' (medium there, for the scan's a/c confusion beside "
                               "it). The '$a =$' is the scan's and booked with it, as the stray prime of §241 is "
                               r"booked with the swap of $\mu$ and $\nu$; misprint, medium (was the scan's, low)."),
        note=claim("the assumed equation (of §227)."))
d.quote("c-limit", "§228",
        r"non permittit, vt capiatur $c > \frac{1}{2}a$, alias enim curua ultra rectam aa excurreret",
        reading=(sp.Matrix([sp.Limit(xLc * b ** 2 / y ** 2, y, 0), xLc - (a / 2 - c) * y ** 2 / b ** 2]),
                 sp.Matrix([a / 2 - c, a / 2 * (1 - R / b) ** 2])),
        note=claim("for c > a/2 the curve would run beyond the line aa (x < 0). Read as the two facts that "
                   "decide it: near A the branch Ace is x = (a/2 - c)y²/b² + O(y⁴), negative for c > a/2; and "
                   "x - (a/2 - c)y²/b² = (a/2)(1 - √(bb-yy)/b)² >= 0, so for c <= a/2 no point has x < 0."))
d.quote("c-half", "§228", r"$c = \frac{1}{2}a$ seu $Oc = \frac{1}{2}AO = \frac{1}{4}AB$",
        reading=as_printed(lambda: (sp.Rational(1, 2) * a, sp.Rational(1, 4) * (2 * a))),
        note=claim("c = a/2 is Oc = AO/2 = AB/4 (Oc is c and AO is a: the middle member renames the first, "
                   "so the reading keeps c = a/2 = AB/4 with AB = 2a)."))
KEFh, KEF0 = sp.symbols("K_{EF}(c=a/2) K_{EF}(c=0)")
d.step("moment-EF-half-value", (KEFh, sp.Subs(KEFc, c, a / 2), kefc.subs(c, a / 2)), "substitution",
       uses=("moment-EF-c",), result=KEFh, note="Oc = AB/4")
d.step("moment-EF-ellipse", (KEF0, sp.Subs(KEFc, c, 0), kefc.subs(c, 0)), "substitution",
       uses=("moment-EF-c",), result=KEF0, note="c = 0: the ellipse of §219 (AB²D/8 there)")
d.quote("moment-EF-half", "§228", r"$= \frac{AB^2 D}{8} + \frac{AB^2 D}{128}$",
        reading=(KEFh, (2 * a) ** 2 * D / 8 + (2 * a) ** 2 * D / 128),
        note=claim("at c = a/2 the moment about EF is AB²D/8 + AB²D/128."))
d.quote("sixteenth", "§228", "momentum respectu axis latitudinalis sui parte decima sexta augetur",
        reading=((KEFh - KEF0) / KEF0, sp.Rational(1, 16)),
        note=claim("moving ef to Oc = AB/4 increases the moment about EF by a sixteenth of the ellipse's "
                   "(c = 0)."))


d.quote("even-Y", "§221", r"ut curva haec ad utramque partem axis AB duas habeat partes AEB et AFB similes et "
        r"aequales, necesse est ut Y sit functio par ipsius y",
        reading=(sp.Matrix([e - sp.Subs(e, y, -y) for e in x21]), sp.Matrix([2 * p * y, 2 * p * y])),
        note=claim("the parts on either side of AB are mirror images (x the same at y and -y) only if Y is even: "
                   "for Y = py + qy² the two branches move by x(y) - x(-y) = 2py, zero for every y only when the "
                   "odd part p vanishes."))
