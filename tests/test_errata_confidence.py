"""docs/errata-kinds.md's rule for confidence *high*, held on the committed errata: the correction is proved,
or, where no strategy decides it, confirmed at the sample points with an independent witness agreeing."""
import json
from pathlib import Path

ERRATA = Path(__file__).resolve().parents[1] / "docs" / "errata.json"


def unsupported_high(errata):
    """The high-confidence errata whose correction is neither proved nor backed by an agreeing witness."""
    return [e["id"] for e in errata if e["confidence"] == "high" and "the correction is proved" not in e["evidence"]
            and not ("the correction is confirmed by sampling" in e["evidence"]
                     and "agrees with the correction" in e["evidence"])]


def test_high_confidence_errata_are_established():
    errata = json.loads(ERRATA.read_text(encoding="utf-8"))
    assert unsupported_high(errata) == []
    # not vacuous: a sampled correction without its witness is caught (Scheeffer (82), 13 such entries in all)
    sampled = next(e for e in errata if e["id"] == "scheeffer-82-1")
    sampled["evidence"] = sampled["evidence"].replace("agrees with the correction", "was run")
    assert unsupported_high(errata) == ["scheeffer-82-1"]
