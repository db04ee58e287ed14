"""How each proof strategy shows a claim, in words: the identity check's
(:data:`symfloat.engine.identity.STRATEGIES`) and the relation check's. An erratum's evidence and
``symfloat check`` name the strategy that proved a reading by these words, never by its name in the code."""

__all__ = ["PROOF_WORDS"]

PROOF_WORDS = {"cancel": "the difference cancels over a common denominator",
               "squares": "both sides are non-negative and their squares agree",
               "expand": "the difference expands to 0",
               "radsimp": "the difference cancels once its roots are cleared from the denominators",
               "pythagoras": ("with tangents as sines over cosines and multiple angles expanded, the difference is 0 "
                              "once $\\sin^2 x + \\cos^2 x = 1$ is used"),
               "branches": "in each case of its piecewise definition the difference cancels over a common denominator",
               "simplify": "SymPy's general simplification takes the difference to 0",
               "assumptions": "the statement follows from the derivation's assumptions",
               "sign of factors": "the sign of each factor is fixed on the domain",
               "sign cells": "it holds in every cell between the real roots of its numerators and denominators, and at the roots"}
