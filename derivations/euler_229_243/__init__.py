r"""Euler, Scientia navalis (1749), Cap. III "De stabilitate situs aequilibrii", §§229–243.

English summary, paragraph by paragraph:

* §229: a wider family of waterplanes AEBF, symmetric about the long axis AB, each half made of two
  portions meeting at the greatest breadth ce = b.  With AO = BO = a, AP = x, PM = y the portion Ace is
  x = a + Y − a(1 − yⁿ/bⁿ)^κ, the portion Bce is x = a + Y + a(1 − yⁿ/bⁿ)^κ (Y a function of y vanishing
  at y = 0).  The chord is Mm = 2a(1 − yⁿ/bⁿ)^κ, so the half area D = 2a∫dy(1 − yⁿ/bⁿ)^κ (y from 0 to b)
  does not depend on Y.
* §230: the moment of AEB about AB is 2a∫y²dy(1 − yⁿ/bⁿ)^κ, also free of Y.  With PO = −Y + aR,
  pO = Y + aR (R = (1 − yⁿ/bⁿ)^κ) the moment about the normal to AB through O is
  (2nκa³/bⁿ)∫yⁿdy(1 − yⁿ/bⁿ)^{3κ−1} + 2a∫Y²R dy (by parts from (2a³/3)∫R³dy), twice that for the whole figure.
* §231: the centroid C: D·CO = −2a∫Y R dy; the moment about the latitudinal axis EF through C is
  (4nκa³/bⁿ)∫yⁿ(1 − yⁿ/bⁿ)^{3κ−1}dy + 4a∫Y²R dy − 8a²(∫Y R dy)²/D.  For Y = αyⁿ + βy^{n−1} + … (as
  transcribed) and κ integer or half-integer the integrals are said to reduce to the area integral
  ∫R dy = D/(2a) (true for the powers y^{jn}; not checked for the others).
* §232: Y = −cyⁿ/bⁿ puts the greatest breadth at Oc = c from the middle: ∫YR = −cD/(2a(n(κ+1)+1)),
  ∫Y²R = (n+1)c²D/(2a(n(κ+1)+1)(n(κ+2)+1)); the moment about EF is
  (4nκa³/bⁿ)∫yⁿ(1 − yⁿ/bⁿ)^{3κ−1}dy + 2n²(κ+1)c²D/((n(κ+1)+1)²(n(κ+2)+1)), the larger the larger c.
* §233: ∫yⁿ(…)^{3κ−1}dy/bⁿ = ∫(…)^{3κ−1}dy/(1 + 3nκ); with ∫(…)^{3κ−1}dy = N∫(…)^κ dy = ND/(2a) the
  moment about EF is 2nκa²ND/(1 + 3nκ) + 2n²(κ+1)c²D/((n(κ+1)+1)²(n(κ+2)+1)); a table of N for
  κ = 1/2, 1, …, 3.
* §234: for c = 0 a table of the moment about EF for the same κ.
* §235: n = 1 gives oblique angles at A and B, n < 1 makes the curve touch AB (unfit); as n → ∞ the
  figure tends to the rectangle with moment 2a²D/3 = AB²D/6, for every κ > 0; κ < 0 gives open curves.
* §236: κ > 1 gives cusps at e and f; κ = 1 the quadrilateral of §215; κ < 1 tangents parallel to AB.
  κ = 1: n = 1 gives 2a²D/6 = AB²D/12 (rhombus), n = 2 gives 16a²D/35 = 4AB²D/35; κ = 1/2: n = 1 gives
  2a²D/5 = AB²D/10, n = 2 gives a²D/2 = AB²D/8 (the ellipse).
* §237: for any waterplane the moments are EF²D/μ about AB and AB²D/μ about EF with 6 ≤ μ ≤ 12:
  rectangle 6, rhombus 12, ellipse 8, the parabola with its axis across the ship 35/4 (about AB) and
  10 (about EF); unequal fore and aft halves increase the moment about EF.
* §§238–239: the stability of a ship of weight M, displacement V, centre of gravity G above the centre
  of buoyancy O is M(EF²D/(μV) − OG) about AB and M(AB²D/(νV) − OG) about EF; + OG when G lies below O.
* §§240–242: G lies above O in real ships; it suffices to make the stability about AB large enough: with
  AB = 4EF the quantity for EF is about 16 times that for AB.
* §243: V lies between the pyramid (2/3)D·CD and the prism 2D·CD over the waterplane with the depth
  CD; V ≈ D·CD (the solid of lines from the waterplane's rim normal to the keel), so the stability
  about AB is M(EF²/(μ·CD) − OG).

The transcription prints x (and once n) for the exponent κ, α for a, drops lost factors of the tables
and garbles their denominators; each such print is declared with its correction.  The integrals
∫₀ᵇ yᵖ(1 − yⁿ/bⁿ)^q dy are written as atoms whose closed form b^{p+1}Γ((p+1)/n)Γ(q+1)/(nΓ((p+1)/n+q+1))
is established once (step ``beta-integral``, checked against SymPy's integral); the recurrences Euler
uses are checked on them.

Rebuilt tables of §§233–234 (exact, from the Beta integrals; N = ∫(1 − uⁿ)^{3κ−1}du / ∫(1 − uⁿ)^κ du and
K₀ = moment about EF for c = 0):

| κ | N printed | N rebuilt | N at n = 1 | N at n = 2 | K₀ printed | K₀ rebuilt | K₀/(a²D) at n = 1 | at n = 2 |
|---|---|---|---|---|---|---|---|---|
| 1/2 | $N = \frac{1}{2}$ | $1$ | 1 ≈ 1.000000000 | 1 ≈ 1.000000000 | $2a^2 D \cdot \frac{n}{2+3n}$ | $2a^2 D \cdot \frac{n}{(2+3n)}$ | 2/5 ≈ 0.4000000000 | 1/2 ≈ 0.5000000000 |
| 1 | $N = \frac{4n}{2+4n}$ | $\frac{4n}{(2+4n)}$ | 2/3 ≈ 0.6666666667 | 4/5 ≈ 0.8000000000 | $2a^2 D \cdot \frac{2n}{(2+4n)(2+6n)} \cdot \frac{4n}{(2+6n)(2+8n)}$ | $2a^2 D \cdot \frac{2n \cdot 4n}{(2+4n)(2+6n)}$ | 1/3 ≈ 0.3333333333 | 16/35 ≈ 0.4571428571 |
| 3/2 | $N = \frac{5n}{(2+1)n}(2+7n)$ | $\frac{5n \cdot 7n}{(2+5n)(2+7n)}$ | 5/9 ≈ 0.5555555556 | 35/48 ≈ 0.7291666667 | $2a^2 D \cdot \frac{3n}{(2+5n)(2+7n)} \cdot \frac{5n}{(2+7n)(2+9n)} \cdot \frac{7n}{(2+9n)(2+11n)}$ | $2a^2 D \cdot \frac{3n \cdot 5n \cdot 7n}{(2+5n)(2+7n)(2+9n)}$ | 10/33 ≈ 0.3030303030 | 7/16 ≈ 0.4375000000 |
| 2 | $N = \frac{6n}{(2+6n)(2+8n)(2+10n)}$ | $\frac{6n \cdot 8n \cdot 10n}{(2+6n)(2+8n)(2+10n)}$ | 1/2 ≈ 0.5000000000 | 160/231 ≈ 0.6926406926 | $2a^2 D \cdot \frac{4n}{(2+6n)(2+8n)} \cdot \frac{6n}{(2+8n)(2+10n)} \cdot \frac{8n}{(2+10n)(2+12n)} \cdot \frac{10n}{(2+12n)(2+14n)}$ | $2a^2 D \cdot \frac{4n \cdot 6n \cdot 8n \cdot 10n}{(2+6n)(2+8n)(2+10n)(2+12n)}$ | 2/7 ≈ 0.2857142857 | 1280/3003 ≈ 0.4262404262 |
| 5/2 | $N = \frac{7n}{(2+7n)(2+9n)(2+11n)(2+13n)}$ | $\frac{7n \cdot 9n \cdot 11n \cdot 13n}{(2+7n)(2+9n)(2+11n)(2+13n)}$ | 7/15 ≈ 0.4666666667 | 429/640 ≈ 0.6703125000 | $2a^2 D \cdot \frac{5n}{(2+7n)(2+9n)} \cdot \frac{7n}{(2+9n)(2+11n)} \cdot \frac{9n}{(2+11n)(2+13n)} \cdot \frac{11n}{(2+13n)(2+15n)} \cdot \frac{13n}{(2+15n)(2+17n)}$ | $2a^2 D \cdot \frac{5n \cdot 7n \cdot 9n \cdot 11n \cdot 13n}{(2+7n)(2+9n)(2+11n)(2+13n)(2+15n)}$ | 14/51 ≈ 0.2745098039 | 429/1024 ≈ 0.4189453125 |
| 3 | $N = \frac{8n}{(2+8n)(2+10n)(2+12n)(2+14n)(2+16n)}$ | $\frac{8n \cdot 10n \cdot 12n \cdot 14n \cdot 16n}{(2+8n)(2+10n)(2+12n)(2+14n)(2+16n)}$ | 4/9 ≈ 0.4444444444 | 14336/21879 ≈ 0.6552401846 | $2a^2 D \cdot \frac{6n}{(2+8n)(2+10n)} \cdot \frac{8n}{(2+10n)(2+12n)} \cdot \frac{10n}{(2+12n)(2+14n)} \cdot \frac{12n}{(2+14n)(2+16n)} \cdot \frac{14n}{(2+16n)(2+18n)} \cdot \frac{16n}{(2+18n)(2+20n)}$ | $2a^2 D \cdot \frac{6n \cdot 8n \cdot 10n \cdot 12n \cdot 14n \cdot 16n}{(2+8n)(2+10n)(2+12n)(2+14n)(2+16n)(2+18n)}$ | 4/15 ≈ 0.2666666667 | 57344/138567 ≈ 0.4138359061 |

Witnesses: every figure is declared by its chords (the rectangle and the rhombus of §237 by their vertices)
and its moments measured by the figure witnesses (the chord by three-point Gauss–Legendre, exact for its
quadratic integrand; across the chords tanh-sinh at 50 digits, and Gauss–Legendre in float64 after a
substitution of order 4, which smooths the endpoint singularity of (1 − yⁿ/bⁿ)^κ for κ a multiple of 1/4;
the polygons by exact polygon integrals), the tables over
the grid n ∈ {1, 2, 3} × κ ∈ {1/2, 1, 3/2, 2, 5/2, 3}; N by the same rules on its two one-dimensional
integrals; the volumes of §243 by exact convex hulls; the stabilities of §239–243 by heeling a V-shaped
prism and pitching an upright prism over the quadrilateral of §215 (whose μ = 12 and ν = 81/7 differ) —
exact clipping, M·GZ/φ extrapolated to φ → 0.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
