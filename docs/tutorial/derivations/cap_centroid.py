"""The centre of gravity of a spherical segment (tutorial source ``cap``): volume, moment, centroid.

The section at abscissa x is the circle pi (r^2 - x^2); the segment of height h lies between
x = r - h and x = r.  Volume and moment are defined by their integrals and integrated; the centroid
is their quotient.  The print's denominator 4 (3r + h) is a misprint for 4 (3r - h): its own
hemisphere value 3r/8 needs the minus sign.
"""
import sympy as sp

from symfloat import Derivation, Eq, Erratum
from symfloat.engine.witness import Case, SectionIntegral

r, h, x, V, M, X = sp.symbols("r h x V M x_s", positive=True)

DERIVATION = d = Derivation(
    id="cap-centroid", source="cap", title="Centre of gravity of a spherical segment", locator="segment",
    domain={r: (1, 3), h: (0, 1)},            # h sampled below r (h = r t, 0 < t < 1: the constraint below)
    constraints=(h < r,), assumptions=("0 < h < r",))

AREA = sp.pi * (r ** 2 - x ** 2)              # the section at abscissa x
d.step("volume", Eq(V, sp.Integral(AREA, (x, r - h, r))), "definition", result=V)
d.step("volume-value", (sp.Integral(AREA, (x, r - h, r)), sp.pi * h ** 2 * (3 * r - h) / 3), "integration",
       uses=("volume",), result=V)            # the closed form has the last word
d.step("moment", Eq(M, sp.Integral(x * AREA, (x, r - h, r))), "definition", result=M)
d.step("moment-value", (sp.Integral(x * AREA, (x, r - h, r)), sp.pi * h ** 2 * (2 * r - h) ** 2 / 4),
       "integration", uses=("moment",), result=M)
d.step("centroid", Eq(X, M / V), "definition", uses=("volume-value", "moment-value"), result=X)

d.quote("volume", "volume", r"$$V = \frac{\pi h^2}{3} (3r - h).$$", reading=(V, sp.pi * h ** 2 / 3 * (3 * r - h)))
d.quote("moment", "moment", r"$$M = \frac{\pi h^2}{4} (2r - h)^2,$$", reading=(M, sp.pi * h ** 2 / 4 * (2 * r - h) ** 2))
d.quote("centroid", "centroid", r"$$x_s = \frac{3 (2r - h)^2}{4 (3r + h)}.$$",
        reading=(X, 3 * (2 * r - h) ** 2 / (4 * (3 * r + h))),
        erratum=Erratum("misprint", "high", "x_s = 3 (2r - h)^2 / (4 (3r - h))",
                        "M/V = (pi h^2 (2r - h)^2/4) / (pi h^2 (3r - h)/3); the text's own hemisphere value "
                        "3r/8 (h = r) needs 3r - h: with 3r + h it would be 3r/16",
                        corrected_reading=(X, 3 * (2 * r - h) ** 2 / (4 * (3 * r - h)))))
d.quote("hemisphere", "hemisphere", r"For the hemisphere, $h = r$, this gives $x_s = \frac{3}{8} r$.",
        reading=(sp.Subs(X, h, r), sp.Rational(3, 8) * r))

CASES = (Case({r: 1, h: sp.Rational(1, 2)}), Case({r: 2, h: sp.Rational(3, 2)}))
d.witness(SectionIntegral("volume-quadrature", "volume by quadrature of the section area", ("volume",), CASES,
                          area=AREA, z=x, bounds=(r - h, r), quantity="volume"))
d.witness(SectionIntegral("moment-quadrature", "moment about the centre by quadrature", ("moment",), CASES,
                          area=AREA, z=x, bounds=(r - h, r), quantity="moment", origin=0))
d.witness(SectionIntegral("centroid-quadrature", "centroid: moment over volume by quadrature", ("centroid",), CASES,
                          area=AREA, z=x, bounds=(r - h, r), quantity="centroid", origin=0))
