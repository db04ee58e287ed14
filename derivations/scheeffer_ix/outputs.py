"""Scheeffer IX's outputs: the case tables against the solver on a grid (:mod:`.grid`), as reports and a picture
(:mod:`.figure`)."""
from pathlib import Path

from symfloat.model.derivation import Figure, Report

from .figure import grid_caption, grid_figure
from .grid import grid_data, grid_markdown, grid_stamp, report_rows
from .statements import d


def _grid_report(progress=None) -> str:
    """docs/scheeffer-ix-grid.md: the tables against the solver on a grid of (s, a/b) and across every
    boundary of the tables (:mod:`.grid`)."""
    return grid_markdown(report_rows(progress), grid_stamp())


def _grid_data(progress=None) -> str:
    """docs/scheeffer-ix-grid.json: every cell's counts, the data of the grid's picture."""
    return grid_data(report_rows(progress), grid_stamp())


d.provides("report", Report("scheeffer-ix-grid.md", grid_stamp, _grid_report))
d.provides("report", Report("scheeffer-ix-grid.json", grid_stamp, _grid_data))
d.provides("figure", Figure("scheeffer-ix-grid.png", ("scheeffer-ix-grid.json",), grid_figure,
                            code=(Path(__file__).with_name("figure.py"),),
                            title="Scheeffer IX: the case tables against the solver", caption=grid_caption))
