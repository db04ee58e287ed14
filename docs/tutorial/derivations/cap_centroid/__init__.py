"""The centre of gravity of a spherical segment (tutorial source ``cap``): volume, moment, centroid.

The section at abscissa x is the circle pi (r^2 - x^2); the segment of height h lies between
x = r - h and x = r.  Volume and moment are defined by their integrals and integrated; the centroid
is their quotient.  The print's denominator 4 (3r + h) is a misprint for 4 (3r - h): its own
hemisphere value 3r/8 needs the minus sign.
"""
from .statements import DERIVATION

__all__ = ["DERIVATION"]
