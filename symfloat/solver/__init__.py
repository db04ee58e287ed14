"""Every equilibrium of a floating homogeneous body, found without any formula of a source.

>>> from symfloat.solver import make_scene, solve
>>> sol = solve(make_scene("box", "1/2", dims="1,2,3"))
>>> [(e.up, e.stability) for e in sol.equilibria][0]
((1.0, 0.0, 0.0), 'stable')
"""
from .bodies import SceneError, make_scene
from .solve import Equilibrium, Solution, solve

__all__ = ["SceneError", "make_scene", "solve", "Equilibrium", "Solution"]
