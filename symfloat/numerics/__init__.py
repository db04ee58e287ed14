"""Numerical studies of the library: conditioning of the solver near bifurcations."""
