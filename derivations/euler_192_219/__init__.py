"""Euler, Scientia navalis (1749), Cap. III "De stabilitate situs aequilibrii", §§192–219.

English summary, paragraph by paragraph group:

* §§192–200: a floating ship must not only be in equilibrium but stable; the stability
  against a small inclination about a horizontal axis is the restoring moment divided by
  the (infinitely small) angle.  It must be judged about every horizontal axis; the
  longitudinal axis (stern to bow) and the latitudinal axis (across) are the principal
  ones.  Only the waterplane depends on the axis; weight, volume and the distance between
  the centre of gravity and the centre of buoyancy do not.
* §201: with weight M, displaced volume V and distance b between the centre of gravity and
  the centre of buoyancy, the stability about the axis AB through the centroid C of the
  waterplane is M(∫(PM³ + PN³)Pp/(3V) ± b), + when G lies below B.
* §§202–203: ∫(PM³ + PN³)Pp/3 is the second moment ("momentum") of the waterplane about AB:
  the strip Pp of half-widths PM, PN contributes Pp·∫w²dw = Pp(PM³ + PN³)/3.  With I, K the
  moments about the longitudinal and the latitudinal axis the stabilities are M(I/V + b),
  M(K/V + b).
* §§204–209: the moment about an axis PQ through C making with AB an angle of sine m,
  cosine n, is m²∫x² + n²∫y² − 2mn∫xy; the moments about two perpendicular axes add up to
  I + K (the polar moment about C).  For a waterplane symmetric about AB, ∫xy = 0, so the
  moment about PQ is n²I + m²K = I + m²(K − I): the least moment is about AB, the greatest
  about EF (when K > I), and at 45° it is (I + K)/2.
* §210: when I = K every axis through C has the same moment (the square).
* §211: the moments are computed quadrant by quadrant: (1/3)∫y³dx about AB, ∫yx²dx about EF.
* §212: square of half-side a: moment 4a⁴/3 = AB⁴/12 = AB²D/6 about every axis (area 2D).
* §213: rectangle 2a × 2b: I = EF²D/6, K = AB²D/6.
* §214: rhombus with diagonals 2a, 2b: I = EF²D/12, K = AB²D/12, half the rectangle's.
* §§215–216: the quadrilateral of two isosceles triangles eAf, eBf on a common base ef
  (Ac = a, ce = b, Bc = c): the centroid C lies (c − a)/3 from c; I = ef²D/12; the moment
  about ef is D(a² − ac + c²)/3.
* §217: parallel-axis rule: the moment about EF through C is L − 2D·Cc², L the moment
  about the parallel ef.
* §218: hence the quadrilateral's moment about EF is D(a² + ac + c²)/9
  = D·AB²/12 + D·Cc²/4, larger than for the rhombus of the same length and breadth.
* §219: the ellipse with semi-axes a, b: K = AB²D/8, I = EF²D/8.

The claims in words of §§192–200 are read on a worked body: a long box of half-beam e and draught T,
heeled by phi while wall-sided, whose righting arm GZ = sin phi (e²/(3T) − b + e² tan²phi/(6T)) comes
from the centroid of the heeled section.  M·GZ/phi → M(I/V − b) (the stability is the slope of the
moment); the moment departs from S·phi at third order (only small angles); S = 0 leaves no first-order
arm (the box still rights at third order: indifference is a statement of the linear theory); S < 0
drives the box to a heeled stable equilibrium at tan²phi = 2g/(I/V); the box 1 × 1 × 2 with G 1/3 above
B is stable about EF and unstable about AB; ships resist pitching more than rolling (K > I).

Witnesses: every figure is declared by its vertices (the ellipse by its half-breadth) and its moments
measured by the figure witnesses (exact polygon integrals, the ellipse by quadrature of its chords, in
float64 and at 50 digits); the boxes by exact clipping, the arm's coefficients extrapolated to phi → 0
and the heeled equilibrium found as a root of the clipped arm.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
