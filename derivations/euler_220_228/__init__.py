"""Euler, Scientia navalis (1749), Cap. III "De stabilitate situs aequilibrii", §§220–228.

English summary, paragraph by paragraph:

* §220: for the quadrilaterals (§218) unequal parts fore and aft of the latitudinal axis gave a larger
  moment than the rhombus; is it the same for curved figures?  Take a figure AEBF with the same
  longitudinal axis AB, the same greatest breadth ef and the same area as the ellipse of §219, but with
  ef cutting AB unequally at c; O is the midpoint of AB, C the centroid, EF the latitudinal axis.  Put
  AO = BO = a, ce = cf = b, Oc = c.
* §221: infinitely many such curves: with AP = x, PM = y, x = a + Y ± a√(1 − y²/b²), Y a function of
  y vanishing at y = 0.  At y = 0, x = 0 or 2a, so AB = 2a; the greatest breadth b lies at the abscissa
  a + Y(b), not at O; the halves AEB, AFB are equal when Y is even.  Take Y = −cy²/b², so that Oc = c.
* §222: whatever (single-valued) Y is, the area equals that of the ellipse with axes 2a, 2b: the portion
  Ace has the area ∫y dY + (a/b)∫y²dy/√(b² − y²) (from y = 0 to b), Bce the same with the opposite sign
  of the second term and the limits reversed, so AEB = (2a/b)∫y²dy/√(b² − y²) = D, the half ellipse.
* §223: the moment about AB does not depend on Y either: (1/3)∫y³dx over Ace and Bce gives
  (2a/3b)∫y⁴dy/√(b² − y²) for AEB, and for the whole figure Db²/2 = ef²D/8, as for the ellipse.
* §224: the moment about the line aAa through A normal to AB: for Ace, ∫y x² dx with
  x = a + Y − (a/b)√(b² − y²), expanded into six integrals; for Bce the same with the signs of the odd
  powers of √(b² − y²) changed and the limits reversed.
* §225: adding, AEB about aAa = −(4a/b)∫y dY (a+Y)√(b² − y²) + (2a/b)∫y²dy(a+Y)²/√(b² − y²)
  + (2a³/b³)∫y²dy√(b² − y²) = (2a³/b³)∫y²dy√ + (2a/b)∫(a+Y)²dy√ (by parts, the boundary term vanishes
  at y = 0 and y = b); with ∫y²dy√(b² − y²) = b³D/8a this is a²D/4 + (2a/b)∫(a+Y)²dy√, and the
  whole figure has twice as much (printed a²D/2 + (2a/b)∫..., see the errata).
* §226: the centroid: D·AC = ∫xy dx over AEB = (2a/b)∫(a+Y)dy√(b² − y²); the moment about EF through
  C is the moment about aAa less 2D·AC², a²D/2 + (4a/b)∫(a+Y)²dy√ − (8a²/b²D)(∫(a+Y)dy√)² (printed
  with 2a/b, aa/bbD and no square).  For even Y the integrals reduce to ∫y²dy/√(b² − y²) = bD/2a,
  ∫y²dy√(b² − y²) = b³D/8a, ∫dy√(b² − y²) = bD/2a.
* §227: Y = −cy²/b²: $\\int (a+Y)^2 dy \\surd = bD(8a^2 - 4ac + c^2)/16a$, $\\int (a+Y) dy \\surd = bD(4a - c)/8a$, AC = a − c/4,
  and the moment about EF is a²D/2 + c²D/8 = AB²D/8 + c²D/8.
* §228: so, as for the quadrilaterals, the moment about EF grows as ef moves away from the middle O
  (the text says C).  The
  curve does not allow c > a/2 (it would cross the line aa); at c = a/2 (Oc = AB/4) the moment is
  AB²D/8 + AB²D/128, a sixteenth more than the ellipse's.

What the print or its transcription gets wrong (each argued in its erratum, the kind saying which): a fraction bar lost three times in
§223; the vinculum over the factor x² and a 'dy' in §224; 'dy' for 'dY' in §225 and §226; 'D³' for D
in §225; the factor 2a/b (for 4a/b) of the whole figure in §225, repeated in §226 together with a lost
factor 8 and a lost square; ∫y dx for ∫xy dx in §226; c/b for a/b and Oc = a for Oc = c in §227, with
the three auxiliary integrals of §227 shifted against their values and c·c² D/128 for c²D/8; the
curve of §227 again in §228, with a for x.

Checking: the integrals with √(b² − y²) are stated once each, closed by the substitution y = b sin θ, and
the readings are built on them; every integral is stated with its closed value and its integrand written as
a polynomial plus P(y)/√(b² − y²) (the engine integrates it and compares; the step "integrands" checks each
written integrand against the strip's); Y is checked in the general form Y = p|y| + qy² (even, vanishing at 0)
and in Euler's case Y = −cy²/b².

Witnesses: every figure is declared by its chords and its areas and moments measured by the figure
witnesses (the chord by the three-point Gauss rule, exact for its integrand of degree at most two in x;
across the chords tanh-sinh at 50 digits and Gauss–Legendre after a smoothing substitution in float64).
The one-dimensional integrals of §§225–227 are witnessed by quadrature of their integrands in the same
two ways.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
