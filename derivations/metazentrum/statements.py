"""What the metacentre lesson says and how each formula is derived (see the package's docstring)."""
import sympy as sp

from symfloat import Derivation, Eq, Erratum, Holds
from symfloat.model.vocabulary import DependsOn, Is, StableIff

a, b, c, d = sp.symbols("a b c d", positive=True)
phi = sp.Symbol("phi", positive=True)
rho_w, rho_s = sp.symbols("rho_w rho_s", positive=True)
x, y, z = sp.symbols("x y z", real=True)
V_b, M_b, M_s, z_B, z_G, z_M, I_w, A_q, A_t, x_t, shift, BM, e, y_G = sp.symbols(
    "V_b M_b M_s z_B z_G z_M I_w A_q A_t x_t Delta BM e y_G", real=True)
g, F_b, F_g, m_g, V_w, M_w = sp.symbols("g F_b F_g m_g V_w M_w", positive=True)

DERIVATION = dv = Derivation(
    id="metazentrum",
    source="metazentrum",
    title="Metacentre and stability function of a rectangular hull",
    locator="Vereinfachtes Modell: gerades Parallelepiped",
    summary="z_B = -d/2, z_G = c - d, z_M = -d/2 + b^2/(3d); stable iff e = b^2/(6c^2) - d/(2c) (1 - d/(2c)) > 0.",
    domain={a: (3, 6), b: (sp.Rational(1, 2), 3), c: (sp.Rational(1, 2), 3), d: (sp.Rational(1, 10), 5),
            phi: (sp.Rational(1, 20), 1), rho_w: (sp.Rational(1, 2), 2), g: (1, 10), m_g: (1, 100),
            V_w: (1, 100), M_w: (1, 100)},
    constraints=(d < 2 * c, b < a),
    assumptions=("homogeneous box 2a × 2b × 2c, centre of mass at its centre, floating upright with draught "
                 "0 < d < 2c", "heel about the long axis (b < a), angle phi, 0 < phi < pi/2; the wedges stay within "
                 "the side faces (b tg phi < d and < 2c - d) for the exact wedge formulas",
                 "z up from the water surface"),
)
dv.step("displaced-volume", (V_b, sp.Integral(1, (x, -a, a), (y, -b, b), (z, -d, 0)), 4 * a * b * d), "integration",
        result=V_b)
dv.step("displaced-mass", Eq(M_b, rho_w * V_b), "definition", result=M_b)
dv.step("archimedes", Eq(rho_s, rho_w * V_b / sp.integrate(1, (x, -a, a), (y, -b, b), (z, -d, 2 * c - d))),
        "definition", result=rho_s, note="the body floats: its mass 8abc rho_s equals the displaced mass M_b")
dv.step("body-mass", (M_s, rho_s * sp.Integral(1, (x, -a, a), (y, -b, b), (z, -d, 2 * c - d)), rho_w * 4 * a * b * d),
        "integration", result=M_s, uses=("archimedes",))
dv.step("density-ratio", (rho_s / rho_w, d / (2 * c)), "algebra", uses=("archimedes", "displaced-volume"))
dv.step("buoyancy-centre", (z_B, sp.Integral(z, (z, -d, 0)) / d, -d / 2), "integration", result=z_B)
dv.step("gravity-centre", (z_G, sp.Integral(z, (z, -d, 2 * c - d)) / (2 * c), c - d), "integration", result=z_G)
dv.step("section", (A_q, sp.Integral(1, (y, -b, b), (z, -d, 0)), 2 * b * d), "integration", result=A_q,
        note="the immersed cross-section (the 'mass' of the lesson, per unit length)")
t = sp.tan(phi)
dv.step("triangles", (A_t, 2 * sp.Integral(y * t, (y, 0, b)), b ** 2 * t), "integration", result=A_t,
        note="heeled by phi about the centre of the waterline: one wedge triangle of legs b and b tg phi enters "
             "the water, the same leaves it")
dv.step("triangle-arm", (x_t, sp.Integral(y * y * t, (y, 0, b)) / sp.Integral(y * t, (y, 0, b)), 2 * b / 3),
        "integration", result=x_t, note="distance of each triangle's centroid from the axis")
dv.step("shift", (shift, x_t * A_t / A_q, b ** 2 * t / (3 * d)), "algebra", result=shift,
        uses=("section", "triangles", "triangle-arm"),
        note="moment theorem: the triangle entering at +2b/3 and the one leaving at -2b/3 move the centroid of "
             "the section across the ship by (2b/3) A_t / A_q (exact, in the body frame)")
dv.step("radius", (BM, sp.Subs(sp.Derivative(shift, phi), phi, 0), b ** 2 / (3 * d)), "series", result=BM,
        uses=("shift",), note="for small phi the shift is the arc BM * phi about the metacentre")
dv.step("waterplane-inertia", (I_w, sp.Integral(y ** 2, (x, -a, a), (y, -b, b)), 4 * a * b ** 3 / 3), "integration",
        result=I_w)
dv.step("radius-inertia", (BM, I_w / V_b), "algebra", uses=("radius", "waterplane-inertia", "displaced-volume"),
        note="the same radius as the waterplane's moment of inertia over the displaced volume (Duhamel, Bouguer)")
dv.step("metacentre", (z_M, z_B + BM, -d / 2 + b ** 2 / (3 * d)), "algebra", result=z_M,
        uses=("buoyancy-centre", "radius"))
dv.step("stability-function", Eq(e, d / (2 * c ** 2) * (z_M - z_G)), "definition", result=e,
        note="the lesson's e is z_M - z_G made dimensionless: times d/(2c^2) > 0, so it has the sign of z_M - z_G")
e_print = sp.Rational(1, 6) * b ** 2 / c ** 2 - d / (2 * c) * (1 - d / (2 * c))
dv.step("stability-function-value", (e, e_print), "algebra", uses=("stability-function", "metacentre", "gravity-centre"))
dv.step("criterion", (sp.sign(z_M - z_G), sp.sign(I_w / V_b - (z_G - z_B)), sp.sign(e)), "algebra",
        uses=("metacentre", "radius-inertia", "stability-function"),
        note="z_M >= z_G is Duhamel's criterion T1/V1 - e1 > 0 (Scheeffer (18)) for this body")

dv.step("body-centroid-across", (y_G, sp.Integral(y, (y, -b, b), (z, -d, 2 * c - d))
                                  / sp.Integral(1, (y, -b, b), (z, -d, 2 * c - d)), 0), "integration", result=y_G,
        note="the tilted body's own centroid across the ship, in the body frame: the centre of its whole section "
             "2b × 2c, on the centre line whatever the heel")
# the quantities the lesson names in words (symfloat/model/vocabulary.json), by the formulas that define them here:
# a centroid by its shift across the ship on a heel phi, the stability by the lesson's function e
dv.defines("centre of gravity", y_G)
dv.defines("centre of buoyancy", shift)
dv.defines("stability", e)

L1 = "Vereinfachtes Modell: gerades Parallelepiped"
L2 = "Berechnung der Lage des Massenschwerpunktes des verdrängten Wassers"
L3 = "Berechnung der Position des Metazentrums"
L4 = "Analyse der Stabilitätsbedingung für das Parallelepiped"
L_SHIP = "Modell eines Schiffsrumpfes"
L6 = "formula list"                     # the page's second part, "Modell": its formulas, one block each
dv.quote("z_G", L1, "$ z_G = c - d $", reading=(z_G, c - d))
dv.quote("section", L2, "$2b d$", reading=(A_q, 2 * b * d))
def first_order(q):
    """The term linear in phi of a quantity that vanishes upright: q'(0) phi (the lesson writes phi for tg phi)."""
    return sp.Subs(sp.Derivative(q, phi), phi, 0) * phi


dv.quote("triangles", L2, r"$b^2\phi$", reading=(first_order(A_t), b ** 2 * phi),
         note="read to first order in phi, as the lesson does throughout (tg phi = phi)")
dv.quote("triangle-arm", L2, r"$\displaystyle\frac{2b}{3}$", reading=(x_t, 2 * b / 3))
dv.quote("shift", L2,
         r"$\displaystyle\frac{\displaystyle\frac{2b}{3} b^2\phi}{2bd}=\displaystyle\frac{b^2\phi}{3d}$",
         reading=(first_order(shift), sp.Mul(2 * b / 3, b ** 2 * phi, sp.Pow(2 * b * d, -1, evaluate=False),
                                             evaluate=False), b ** 2 * phi / (3 * d)),
         note="read to first order in phi, as the lesson does (tg phi = phi)")
dv.quote("radius", L3, r"$\displaystyle\frac{b^2}{3d}$", reading=(BM, b ** 2 / (3 * d)))
dv.quote("z_M", L3, r"$ z_M = -\displaystyle\frac{ d }{2} + \displaystyle\frac{ b ^2}{ 3 d }$",
         reading=(z_M, -d / 2 + b ** 2 / (3 * d)))
dv.quote("criterion", L4, r"$ z_M \geq z_G $", reading=(sp.sign(z_M - z_G), sp.sign(I_w / V_b - (z_G - z_B))),
         note="read as: the position is stable (Duhamel, I/V > z_G - z_B) exactly when z_M > z_G")
dv.quote("e", L4, r"$ e = \displaystyle\frac{1}{6}\displaystyle\frac{ b ^2}{ c ^2} - \displaystyle\frac{ d }{2 c }"
         r"\left(1-\displaystyle\frac{ d }{2 c }\right)$", reading=(e, e_print))
dv.quote("M_b", "formula list", r"$ M_b =4 a b d \rho_w $", reading=(M_b, 4 * a * b * d * rho_w))
dv.quote("M_s", "formula list", r"$ M_s =8 a b c \rho_s $", reading=(M_s, 8 * a * b * c * rho_s))
dv.quote("M_b=M_s", "formula list", r"$ M_b = M_s $", reading=(M_b, M_s),
         note="the page calls M_b = M_s Archimedes' principle ('Das Archimedes-Prinzip besagt, dass die Masse des "
              "verdrängten Wassers gleich der Masse des Objekts ist', and again for 'eines schwimmenden Objekts'): "
              "not booked, since the page applies it to the floating hull only, where it is what the principle "
              "gives (F_b = rho_w V_b g = M_s g, F_b=F_g), a loose naming rather than a false formula")
dv.quote("density", "formula list", r"$ \displaystyle\frac{ \rho_s }{ \rho_w }= \displaystyle\frac{ d }{ 2 c }$",
         reading=(rho_s / rho_w, d / (2 * c)))
dv.quote("V_b", "formula list", "$ V_b = 4 a b d $", reading=(V_b, 4 * a * b * d))
dv.quote("z_B", "formula list", r"$ z_B =-\displaystyle\frac{ d }{2}$", reading=(z_B, -d / 2))
dv.quote("e-sign", L6, "was größer als eins im Falle einer stabilen Situation und negativ im Falle von Instabilität ist.",
         reading=(sp.sign(z_M - z_G), sp.sign(e - 1)),
         erratum=Erratum("claim", "high", "$e > 0$ in the stable case, $e < 0$ in the unstable case",
                         ("$e = d/(2c^2) (z_M - z_G)$ has the sign of $z_M - z_G$, so the boundary of stability is "
                          r"$e = 0$, not $e = 1$: e.g. $b = c$, $d = c$ (half immersed) gives $e = \tfrac16 - "
                          r"\tfrac14 < 0$ (unstable), and $b = 3c/2$, $d = c$ gives $e = \tfrac38 - \tfrac14 = "
                          r"\tfrac18$, between $0$ and $1$ and stable ($z_M - z_G = c/4 > 0$). $e > 1$ needs $b > "
                          r"\sqrt6\, c$ at least ($e \le b^2/(6c^2)$), so 'größer als eins' would declare most stable "
                          "hulls unstable. Probably a slip for 'größer als null' (the German web page is a "
                          "translation), so a claim fault of the lesson, not of the transcription."),
                         corrected_reading=(sp.sign(z_M - z_G), sp.sign(e)),
                         objection=("The lesson might measure stability by a ratio ($z_M/z_G$, or a moment ratio), "
                                    "for which 'greater than one' is the right boundary."),
                         answer=("The page defines $e$ by the display just before, $b^2/(6c^2) - d/(2c)(1 - "
                                 "d/(2c))$: a difference whose sign is that of $z_M - z_G$, not a ratio; and the "
                                 r"sentence itself pairs 'negativ' with instability, which leaves $0 < e \le 1$ in "
                                 "neither case unless the threshold is 0.")))
dv.quote("vasa", L4, "Eine Lösung wäre gewesen, es tiefer zu versenken oder einen höheren $d/c$-Wert zu erreichen, "
         "um die Zone der Instabilität zu vermeiden.",
         reading=(sp.sign(sp.Limit(e, d, 2 * c, "-")), 1),
         note="read as the lesson's model gives it: sunk towards full immersion (d -> 2c, d/c -> 2), e tends to "
              "b^2/(6c^2) > 0, so every hull leaves the zone of instability when sunk deep enough. Not read as "
              "'e grows with d': below half immersion (d < c) e falls with d (de/dd = (d - c)/(2c^2)), and the "
              "sentence does not claim otherwise")

# ---- the words around the formulas (second pass) -----------------------------------------------------
L5 = "Metazentrum unterhalb des Schwerpunkts"
stable_margin = I_w / V_b - (z_G - z_B)                 # Duhamel's criterion for this hull (the step criterion)
dv.quote("buoyancy-point", L4, "Daher ist mit die Höhe des Schwerpunkts ($z_G$)8670 als dem Angriffspunkt der "
         "gegebenen Auftriebskraft", reading=(z_B, c - d),
         erratum=Erratum("misprint", "high", r"z_G \text{ als dem Angriffspunkt der Schwerkraft}",
                         ("The buoyancy acts at the centre of buoyancy $z_B = -d/2$, the centroid of the displaced "
                          "water (the formula list says so); $z_G = c - d$, the centre of the hull, is where gravity "
                          "acts. As printed the sentence puts the buoyancy at $z_G = c - d$ (e.g. $c = 1$, $d = "
                          r"\tfrac12$: $z_G = \tfrac12$, $z_B = -\tfrac14$). The sentence appears twice on the page, "
                          "with the same words: a slip of the lesson, not of the transcription."),
                         corrected_reading=(z_G, c - d), places=(L6,),
                         objection="'Schwerpunkt' alone may mean the centroid of the displaced water, which is where "
                                   "the buoyancy acts.",
                         answer=("The sentence names it by the symbol $z_G$ and gives it the value $c - d$, the "
                                 "page's symbols for the hull's centre of gravity; the displaced water's centroid is "
                                 "$z_B = -d/2$ on the same page.")),
         note="read as: the point where the buoyancy acts is at height c - d")
dv.quote("below-G", L5, "Wenn der Metazentrum über oder unter dem Schwerpunkt liegt",
         reading=Holds(sp.Implies(sp.Ne(z_M, z_G), stable_margin < 0)),
         erratum=Erratum("misprint", "medium", r"\text{Wenn das Metazentrum unter dem Schwerpunkt liegt}",
                         ("The paragraph, headed 'Metazentrum unterhalb des Schwerpunkts', concludes that the system "
                          r"becomes unstable; by the lesson's own criterion $z_M \ge z_G$ that holds for $M$ below "
                          "$G$ only. 'über oder unter' makes every hull with $M$ above $G$ unstable too, against the "
                          r"paragraph 'Stabile Situation' just before it (e.g. $b = \tfrac32$, $c = 1$, $d = "
                          r"\tfrac12$: $z_M - z_G = \tfrac34 > 0$, stable). Read: wherever $M$ is not at $G$ the hull "
                          "is unstable."),
                         corrected_reading=Holds(sp.Implies(z_M < z_G, stable_margin < 0)),
                         objection="'über oder unter' may open a case distinction ('whether above or below ...') of "
                                   "which the paragraph treats the 'below' case only.",
                         answer="As printed the clause leads straight to one conclusion, that the system becomes "
                                "unstable, with no second branch for 'über'; the heading 'Metazentrum unterhalb des"
                                " Schwerpunkts' supports reading a slip, but the case-distinction reading is "
                                "grammatical, hence medium."),
         note="read as: wherever M is not at G (above or below) the hull is unstable")
dv.quote("wide-hull", L4, "Mit anderen Worten: Stabilität wird mit großen Werten von $b/c$ (Breite größer als "
         "Tiefgang) erreicht.",
         reading=Holds(sp.Implies(2 * b > d, stable_margin > 0)),
         erratum=Erratum("claim", "high", r"\text{Stabilität bei jedem Tiefgang, wenn } b/c > \sqrt{3/2} "
                         r"\text{ (Breite groß gegen die Höhe)}",
                         (r"$e = b^2/(6c^2) - s(1 - s)$ with $s = d/(2c)$, and $s(1 - s) \le 1/4$: every draught is "
                          r"stable when $b/c > \sqrt{3/2}$, so what matters is the breadth against the height $2c$, "
                          "not against the draught. As printed ('breadth greater than draught' makes the hull "
                          r"stable) it fails: $b = 0.9\, c$, $d = 0.8\, c$ has $2b > d$ but $e = 0.135 - 0.24 < 0$ "
                          r"($z_M - z_G = -0.2625\, c$), unstable. A claim of the lesson."),
                         corrected_reading=Holds(sp.Implies(b > sp.sqrt(sp.Rational(3, 2)) * c, stable_margin > 0)),
                         objection="'Große Werte von b/c' is right (e grows with b/c); the parenthesis is a loose "
                                   "gloss, and 'Tiefgang' may stand loosely for the hull's height.",
                         answer="The sentence states the gloss as what stability needs; read with the draught it "
                                "fails (b = 0.9c, d = 0.8c), and read with the height (breadth 2b greater than "
                                "height 2c) it fails too: b = c, d = c gives e = 1/6 - 1/4 < 0."),
         note="read as: a hull whose breadth 2b exceeds its draught d is stable")
dv.quote("displaced-volume-claim", L6, "was bedeutet, dass das verdrängte Wasser ein gleiches oder größeres Volumen "
         "als der Gegenstand einnimmt.",
         reading=Holds(V_b >= 8 * a * b * c),
         erratum=Erratum("claim", "high", r"V_b \leq V_s: \text{das verdrängte Wasser nimmt ein kleineres oder "
                         r"gleiches Volumen ein}",
                         (r"A floating body weighs less than water of its volume, $\rho_s \le \rho_w$; with $M_b = "
                          r"M_s$, $\rho_w V_b = \rho_s V_s$, so $V_b / V_s = \rho_s / \rho_w \le 1$: the displaced "
                          "water takes at most the body's volume (for the box $V_b / V_s = d/(2c) < 1$, the draught "
                          "below the height). 'gleiches oder größeres' reverses the inequality; it would describe a "
                          "body that sinks."),
                         corrected_reading=Holds(V_b <= 8 * a * b * c),
                         objection="The sentence may speak loosely of the displaced water's weight, which equals the "
                                   "body's.",
                         answer=("It says 'Volumen' and compares the volumes; a floating body's displaced volume is "
                                 "a part of its own, $V_b = (d/2c) V_s < V_s$ for the box, so 'gleiches oder "
                                 "größeres' is false as written.")),
         note="the box: V_s = 8abc; read as V_b >= V_s, 'ein gleiches oder größeres Volumen'")

dv.quote("half-length", L_SHIP, "der Mittlere Länge des Parallelepipeds ($a$)8673, der Halbe Breite des Parallelepipeds "
         "($b$)8674 und die Halbe Höhe des Parallelepipeds ($c$)8672 reduziert, was zu Abmessungen von "
         "$2a \\times 2b \\times 2c$ führt",
         reading=(sp.Matrix([a, b, c]), sp.Matrix([sp.Integral(1, (x, -a, a)), sp.Integral(1, (y, -b, b)) / 2,
                                                     sp.Integral(1, (z, -d, 2 * c - d)) / 2])),
         erratum=Erratum("misprint", "medium", r"\text{der Halbe Länge des Parallelepipeds } (a)",
                         (r"The box is $2a \times 2b \times 2c$, so $a$ is half its length, as $b$ and $c$ are the "
                          "halves of the breadth and the height ('Halbe Breite', 'Halbe Höhe'), and the lesson's own "
                          r"formulas use it so: $M_s = 8abc \rho_s, V_b = 4abd$. 'Mittlere Länge' (mean length) names "
                          "the whole length $2a$ of a box of constant length. The same name is the page's label of "
                          "$a$ in every list and sentence after it (the variable's glossary entry): one fault at "
                          "eight places."),
                         corrected_reading=(sp.Matrix([a, b, c]),
                                            sp.Matrix([sp.Integral(1, (x, -a, a)) / 2, sp.Integral(1, (y, -b, b)) / 2,
                                                       sp.Integral(1, (z, -d, 2 * c - d)) / 2])),
                         fault="der Mittlere Länge des Parallelepipeds",
                         places=(L1, L3, L6, L6, L6, L6, L6),
                         objection="'Mittlere Länge' might mean the length measured from the middle, the half length,"
                                   " as the page's own 'Halbe' means for b and c.",
                         answer="'mittlere Länge' means the mean length in German usage, and the page writes "
                                "'Halbe' for the two other halves in the same phrase; a coined sense cannot be "
                                "excluded, hence medium."),
         note="read as: a, b, c are the box's length, half breadth and half height, its extents measured along x, y "
              "and z")
dv.says("moving-centroid", "Definition der Position des Metazentrums",
        "Das Metazentrum wird berechnet, indem der Schwerpunkt des gekippten Körpers unter der Bedingung bestimmt "
        "wird, dass die Fläche unter der Wasserlinie (blaue Linie) konstant bleibt:",
        "Schwerpunkt des gekippten Körpers", Is(x_t * A_t / A_q),
        erratum=Erratum("claim", "low",
                        r"\text{indem der Schwerpunkt des verdrängten Wassers (des eingetauchten Querschnitts) "
                        r"\ldots bestimmt wird}",
                        ("The centroid whose shift on heel gives the metacentre is that of the displaced water: the "
                         "next section is 'Berechnung der Lage des Massenschwerpunktes des verdrängten Wassers' and "
                         r"moves the two wedge triangles of the immersed section, $b^2 \operatorname{tg} "
                         r"\varphi/(3d)$. The tilted body's own centroid is fixed in the body ($z_G = c - d$ "
                         "throughout the lesson): across the ship it stays on the centre line, shift $0$, whatever "
                         "the heel."),
                        corrected_reading=dv.reads("Schwerpunkt des verdrängten Wassers", Is(x_t * A_t / A_q)),
                        objection="'Der Schwerpunkt des gekippten Körpers' may mean the centroid of the body's "
                                  "immersed part, as the same sentence's condition 'die Fläche unter der Wasserlinie"
                                  " ... konstant' concerns the immersed section.",
                        answer=("The page keeps 'Körper' for the hull ($z_G$) and the displaced water for $z_B$, "
                                "and the next section is titled 'Massenschwerpunkt des verdrängten Wassers'; but "
                                "the sentence's own condition supports the loose reading, so the objection is not "
                                "fully answered: lowered to low.")),
        note="Read as: the centroid named is the one whose shift across the ship the lesson computes by the moment "
             "theorem, (2b/3) A_t/A_q.")

dv.step("buoyancy-force", Eq(F_b, M_b * g), "definition", result=F_b, note="the weight of the displaced water")
dv.step("gravity-force", Eq(F_g, M_s * g), "definition", result=F_g, note="the weight of the hull")
dv.quote("wedges-equal", L2, "Wenn das Boot krängt, bewegt sich auf der einen Seite ein größerer Wasserabschnitt und auf "
         "der gegenüberliegenden Seite derselbe kleinere Wasserabschnitt.",
         reading=(sp.Integral(y * t, (y, 0, b)), sp.Integral(-y * t, (y, -b, 0))),
         note="the wedge entering the water (0 < y < b) and the one leaving it (-b < y < 0) have the same area "
              "b^2 tg(phi)/2: the displaced volume stays the same")
dv.quote("triangles-only", L2, "Alle Massen, die auf beiden Seiten der Achse versetzt sind, tragen nicht zum Zähler bei "
         "und nur die beiden angegebenen Dreiecke ergeben eine Fläche", reading=(first_order(A_t), b ** 2 * phi),
         note="the two wedge triangles together, to first order in phi (the display b^2 phi follows)")
dv.quote("arc", L3, "Da dieser Abstand der Bogen des Kreises ist, der um das Metazentrum gezogen werden kann",
         reading=(BM, sp.Subs(sp.Derivative(shift, phi), phi, 0)),
         note="the shift of B is the arc BM * phi for small phi: the radius is the shift's rate at phi = 0")
dv.quote("surface-origin", L3, "$d/2$", reading=(-z_B, d / 2),
         note="the origin on the water surface lies d/2 above the centre of buoyancy")
GE_FAULT = "muss die Höhe des Metazentrums ($z_M$)8671 immer größer oder gleich die Höhe des Schwerpunkts"
GE_EVIDENCE = (r"The lesson's stability is its function $e = \frac{d}{2c^2}(z_M - z_G)$ (the display after the "
               r"sentence), positive for a stable and negative for an unstable hull; where $z_M = z_G$ it vanishes: "
               r"the heeled box has no righting moment to the lesson's order (the shift $b^2\varphi/(3d)$ with "
               r"$\operatorname{tg}\varphi = \varphi$), the neutral case. 'größer oder gleich' counts that case as "
               r"stable (e.g. $b = c = 1$, $d = 1 - \sqrt{3}/3$: $z_M = z_G$ and $e = 0$), and the page's own split "
               r"of the diagram 'stabil und in seinem Komplement instabil' leaves it in neither part. The display "
               r"$z_M \ge z_G$ that follows states the same condition.")
GE_OBJECTION = (r"At $z_M = z_G$ the wall-sided box still rights at a finite heel, $GZ = \frac{BM}{2}"
                r"\operatorname{tg}^2\varphi \sin\varphi > 0$ (third order), so 'stable for $z_M \ge z_G$' is right for "
                r"the body; and 'muss' states a necessary condition, which $z_M \ge z_G$ is.")
GE_ANSWER = (r"The lesson's stability is first order (the metacentre is defined by the small-heel shift, $e$ by "
             r"$z_M - z_G$), where equality is neutral; and the page uses the condition as the criterion both ways "
             r"(the diagram's stable region and its complement). The higher-order reading is the page's due, so low.")
dv.says("criterion-words", L4, "Um sicherzustellen, dass der Quader stabil ist, muss die Höhe des Metazentrums "
        "($z_M$)8671 immer größer oder gleich die Höhe des Schwerpunkts ($z_G$)8670 sein, das heißt",
        "stabil", StableIff(z_M >= z_G),
        erratum=Erratum("claim", "low", r"\text{immer größer als die Höhe des Schwerpunkts}\ (z_M > z_G)",
                        GE_EVIDENCE, corrected_reading=dv.reads("stabil", StableIff(z_M > z_G)),
                        fault=GE_FAULT, places=("Stabilitätsbedingung", "Stabilitätsbedingung für das Parallelepiped"),
                        objection=GE_OBJECTION, answer=GE_ANSWER),
        note="Read as the page uses it, the criterion both ways: stable exactly when z_M >= z_G, the equality "
             "case included.")
dv.says("criterion-words-2", "formula list", "Damit das Objekt stabil ist, muss die Höhe des Metazentrums ($z_M$)8671 "
        "immer größer oder gleich die Höhe des Schwerpunkts ($z_G$)8670 sein.",
        "stabil", StableIff(z_M >= z_G),
        erratum=Erratum("claim", "low", r"\text{immer größer als die Höhe des Schwerpunkts}\ (z_M > z_G)",
                        GE_EVIDENCE, corrected_reading=dv.reads("stabil", StableIff(z_M > z_G)),
                        same_as="metazentrum/criterion-words",
                        objection=GE_OBJECTION, answer=GE_ANSWER),
        note="The same criterion in the page's list of formulas.")
BREADTH, HEIGHT, DRAUGHT = (sp.Integral(1, (y, -b, b)), sp.Integral(1, (z, -d, 2 * c - d)),
                            sp.Integral(1, (z, -d, 0)))
dv.quote("diagram-axes", L4, "Das bedeutet, dass es im Diagramm $b/c$ (Breite/Tiefe) versus $d/2c$ (Tiefe/Höhe)",
         reading=(sp.Matrix([b / c, d / (2 * c)]), sp.Matrix([BREADTH / DRAUGHT, DRAUGHT / HEIGHT])),
         erratum=Erratum("claim", "high", r"b/c\ (\text{Breite/Höhe}) \text{ versus } d/2c\ (\text{Tiefe/Höhe})",
                         "In one sentence 'Tiefe' names the draught d (d/2c, Tiefe/Höhe: the draught over the "
                         "height 2c) and the denominator of b/c, which is the half height c: b/c = 2b/2c is the "
                         "breadth over the height, not over the draught (b = 3/2, c = 1, d = 1/2: b/c = 3/2, "
                         "breadth/draught = 6). The same confusion of the height with the draught as the next "
                         "sentence's '(Breite größer als Tiefgang)', booked there (wide-hull).",
                         corrected_reading=(sp.Matrix([b / c, d / (2 * c)]),
                                            sp.Matrix([BREADTH / HEIGHT, DRAUGHT / HEIGHT])),
                         same_as="metazentrum/wide-hull",
                         objection="In naval architecture 'depth' is the hull's height, so b/c as breadth over "
                                   "'Tiefe' (depth) is the usual B/D ratio and the first label is right.",
                         answer="The same sentence labels d/2c 'Tiefe/Höhe', with 2c the height, so 'Tiefe' there "
                                "is the draught; one word names two quantities in one sentence, which is the fault "
                                "booked, whichever label one mends."),
         note="read with one meaning of 'Tiefe' in the sentence, the draught d of the second axis: the axes as the "
              "ratios of the box's breadth 2b, draught d and height 2c that the words name")
dv.quote("diagram-regions", L4, "in dem das System stabil und in seinem Komplement instabil ist",
         reading=(sp.Matrix([sp.Subs(sp.sign(e), (b, d), (2 * c, c)), sp.Subs(sp.sign(e), (b, d), (c / 2, c))]),
                  sp.Matrix([1, -1])),
         note="both regions exist: b = 2c, d = c (half immersed) is stable, b = c/2, d = c unstable")
dv.quote("metacentre-from-radius", "formula list", "Die Berechnung von die Höhe des Metazentrums ($z_M$)8671 aus dem "
         "Abstand zwischen dem Metazentrum und dem Schwerpunkt des verdrängten Wassers",
         reading=(z_M, z_B + BM))
dv.quote("F_b", "formula list", r"$ F_b = \rho_w V_b g $", reading=(F_b, rho_w * V_b * g))
dv.quote("F_g", "formula list", r"$ F_g = m_g g $", reading=(F_g, m_g * g),
         erratum=Erratum("misprint", "low", "F_g = M_s g",
                         ("The sentence before introduces the weight with the mass of the floating object $M_s$; "
                          "$m_g$ is defined nowhere on the page (a symbol of the site's general gravity lesson). "
                          "With $M_s$ the chain $F_b = M_b g = M_s g = F_g$ below closes."),
                         corrected_reading=(F_g, M_s * g),
                         objection=("$m_g$ may be the site's general symbol for the gravitating mass, here the "
                                    "hull's $M_s$: a correct formula."),
                         answer=("On this page the floating object's mass is $M_s$ and $m_g$ is defined nowhere; the "
                                 "formula holds only by identifying the two, which the page does not do (hence low).")))
dv.quote("F_b=F_g", "formula list", r"$F_b = \rho_w V_w g = M_w g = M_s g = F_g$",
         reading=(F_b, rho_w * V_w * g, M_w * g, M_s * g, F_g),
         erratum=Erratum("misprint", "low", r"F_b = \rho_w V_b g = M_b g = M_s g = F_g",
                         ("The page names the displaced volume $V_b$ and the displaced mass $M_b$ (formula list); "
                          "$V_w$ and $M_w$ are defined nowhere. With $V_b$ and $M_b$ the chain is Archimedes' "
                          r"principle, $\rho_w V_b g = M_b g$, and $M_b = M_s$. A naming slip of the lesson."),
                         corrected_reading=(F_b, rho_w * V_b * g, M_b * g, M_s * g, F_g),
                         objection=("$V_w$ and $M_w$ may be the site's general names for the displaced water's "
                                    "volume and mass."),
                         answer=("The page names them $V_b$ and $M_b$ in its formula list and never defines $V_w, "
                                 "M_w$; the chain holds by identifying them (hence low).")))
dv.says("shift-depends-on", L3,
        r"Wenn ein Schiff bei der Krängungswinkel ($\phi$)10285 krängt, verschiebt sich der Schwerpunkt des "
        r"verdrängten Wassers um der Halbe Breite des Parallelepipeds ($b$)8674 und der Mittlere Länge des "
        r"Parallelepipeds ($a$)8673 um eine Distanz von:",
        "Schwerpunkt des verdrängten Wassers", DependsOn(b, a),
        erratum=Erratum("claim", "medium",
                        r"\text{verschiebt sich der Schwerpunkt \ldots um eine von der Halben Breite } (b) "
                        r"\text{ und dem Tiefgang } (d) \text{ abhängige Distanz von:}",
                        (r"The distance the sentence introduces is the next display, $b^2 \varphi/(3d)$ (the "
                         r"lesson's shift $\frac{2b}{3} \frac{A_t}{A_q} = \frac{b^2 \operatorname{tg}\varphi}{3d}$): "
                         r"the length $a$ cancels (the wedges' moment and the displaced volume both carry the factor "
                         r"$2a$), and the draught $d$, on which it does depend, is not named. The sentence lists $b$ "
                         r"and $a$ as the dimensions the distance is computed from."),
                        corrected_reading=dv.reads("Schwerpunkt des verdrängten Wassers", DependsOn(b, d)),
                        objection=(r"'um der Halbe Breite ($b$) und der Mittlere Länge ($a$)' may only name the hull "
                                   r"the computation is for, a box of half breadth $b$ and length $a$, not claim "
                                   r"that the distance depends on both."),
                        answer=(r"The construction 'verschiebt sich … um $b$ und $a$ um eine Distanz von' ties the "
                                r"two to the shift, and the page gives no other place where $a$ would enter; but a "
                                r"loose naming of the hull cannot be excluded, hence medium, not high.")),
        note="Read as: the displaced water's shift across the ship changes with the half breadth b and with a.")
