"""The comparison of the solver's answers with the sources: which printed formulas predict each
equilibrium of a scene (:mod:`.coverage`), and where the printed formulas put the thresholds of a phase
diagram (:mod:`.thresholds`).  Above both the solver (found without any formula of a source) and the
derivations (read through :mod:`symfloat.registry`)."""
