"""The static web site (``symfloat site``): the committed records shown to a reader.

:mod:`.records` reads the records and the notebooks, :mod:`.typeset` typesets TeX with KaTeX (and is
the Sphinx extension that does so), :mod:`.text` renders a transcription, :mod:`.edition` marks it
by verdict, :mod:`.errata_pages` and :mod:`.notebooks` make the other pages, :mod:`.build` stages
them and runs Sphinx.  Nothing here checks or computes a result.
"""
