"""What the tutorial's paragraph says of the spherical segment, and how each formula is derived."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum

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
                        r"$M/V = (\pi h^2 (2r - h)^2/4) / (\pi h^2 (3r - h)/3)$; the text's own hemisphere value "
                        "$3r/8$ ($h = r$) needs $3r - h$: with $3r + h$ it would be $3r/16$.",
                        corrected_reading=(X, 3 * (2 * r - h) ** 2 / (4 * (3 * r - h)))))
d.quote("hemisphere", "hemisphere", r"For the hemisphere, $h = r$, this gives $x_s = \frac{3}{8} r$.",
        reading=(sp.Subs(X, h, r), sp.Rational(3, 8) * r))
