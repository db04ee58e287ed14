"""Volume, moment and centroid of the segment by quadrature of its section area: a route that never uses the
formulas."""
import sympy as sp

from symfloat.engine.witness import Case, SectionIntegral

from .statements import AREA, d, h, r, x

CASES = (Case({r: 1, h: sp.Rational(1, 2)}), Case({r: 2, h: sp.Rational(3, 2)}))
d.witness(SectionIntegral("volume-quadrature", "volume by quadrature of the section area", ("volume",), CASES,
                          area=AREA, z=x, bounds=(r - h, r), quantity="volume"))
d.witness(SectionIntegral("moment-quadrature", "moment about the centre by quadrature", ("moment",), CASES,
                          area=AREA, z=x, bounds=(r - h, r), quantity="moment", origin=0))
d.witness(SectionIntegral("centroid-quadrature", "centroid: moment over volume by quadrature", ("centroid",), CASES,
                          area=AREA, z=x, bounds=(r - h, r), quantity="centroid", origin=0))
