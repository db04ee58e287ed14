"""`symfloat phase`: thresholds located to 10 digits and matched with the sources' closed forms."""
import math

import pytest

from symfloat.report.phase import phase_record, phase_table
from symfloat.solver.phase import phase_diagram


@pytest.fixture(scope="module")
def box_phase():
    # a box 1 x 2 x 3 on a coarse sweep: every threshold is still found (the source thresholds outside the
    # sweep are looked for at their own density)
    return phase_diagram("box", "1,2,3", steps=8)


def test_box_thresholds_match_the_upright_closed_form(box_phase):
    # Scheeffer IV (18) / metazentrum: with edge k vertical over the base w x l (w the shorter), the upright
    # position is stable iff 6 s (1 - s) < (w/h)^2: s = 1/2 - sqrt(1/4 - (w/h)^2/6)
    expected = {"face z up": 0.5 - math.sqrt(0.25 - (1 / 3) ** 2 / 6),
                "face y up": 0.5 - math.sqrt(0.25 - (1 / 2) ** 2 / 6)}
    for label, value in expected.items():
        found = [t for t in box_phase.thresholds if t.label == label and t.density < 0.5]
        assert len(found) == 1 and abs(found[0].density - value) < 1e-10
        assert found[0].source, "the source's threshold is named"
        upper = [t for t in box_phase.thresholds if t.label == label and t.density > 0.5]
        assert abs(upper[0].density - (1 - value)) < 1e-10           # the duality s <-> 1 - s
    assert box_phase.duality_ok and box_phase.unmatched_sources == []


def test_phase_outputs(box_phase, tmp_path):
    record = phase_record(box_phase)
    assert {"body", "dims", "sweep", "thresholds", "duality_holds"} <= set(record)
    from test_json_schemas import errors
    assert errors("phase", record) == []                  # symfloat/schemas/phase.schema.json
    assert "duality s <-> 1 - s: holds" in phase_table(box_phase)
