"""Derivation modules, one per source section; each defines ``DERIVATION``.

They use :mod:`symfloat` and nothing else, and only describe steps: importing
them is cheap, the engine does the checking.
"""
