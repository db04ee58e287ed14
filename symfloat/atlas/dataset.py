"""The atlas on disk: one Parquet part per shape cell, then one combined file.

``DIR/parts/b<b/a>-c<c/a>.parquet`` holds a cell's rows (:mod:`symfloat.atlas.cell`); it is
written atomically (a temporary file renamed over it), so a killed run leaves whole parts only,
and a part that records the requested sweep and the same code (:func:`code_stamp`) is not
computed again.
``DIR/atlas.parquet`` is every cell's rows in grid order (c/a, then b/a, then the interval),
written when every cell is there.  The data hold no time and no date: the same grid gives the
same bytes (for one pyarrow version).
"""
from __future__ import annotations

import functools
import io
import json
from fractions import Fraction
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq

from ..files import write_atomic
from ..report.stamp import digest

__all__ = ["SCHEMA", "FORMAT", "code_stamp", "solver_stamp", "part_path", "part_done", "write_part", "read_part", "write_combined",
           "read_atlas", "table_of"]

FORMAT = 1
_KEY = b"symfloat.atlas"

_CHANGE = pa.struct([("position", pa.string()), ("change", pa.string()), ("note", pa.string()),
                     ("sources", pa.list_(pa.string()))])
_STABLE = pa.struct([("position", pa.string()), ("up", pa.list_(pa.float64(), 3)), ("tilt_deg", pa.float64()),
                     ("family", pa.string()), ("g_above_b", pa.float64()), ("min_eigenvalue", pa.float64()),
                     ("error_rad", pa.float64()), ("copies", pa.int32()), ("waterplane", pa.string()),
                     ("evidence", pa.string())])
_PREDICTION = pa.struct([("derivation", pa.string()), ("locators", pa.list_(pa.string())),
                         ("verdicts", pa.list_(pa.string())), ("predicted_up", pa.list_(pa.float64(), 3)),
                         ("predicted_stability", pa.string()), ("agrees", pa.bool_()),
                         ("disagreement", pa.string())])
SCHEMA = pa.schema([
    ("b_a", pa.float64()), ("c_a", pa.float64()), ("b_a_exact", pa.string()), ("c_a_exact", pa.string()),
    ("body", pa.string()), ("failure", pa.string()), ("interval", pa.int32()),
    ("s_from", pa.float64()), ("s_from_error", pa.float64()), ("s_to", pa.float64()), ("s_to_error", pa.float64()),
    ("from_changes", pa.list_(_CHANGE)), ("sample_density", pa.float64()), ("stable", pa.list_(_STABLE)),
    ("stable_classes", pa.int32()), ("stable_positions", pa.int32()), ("index_sum", pa.int32()),
    ("sweep_points", pa.int32()), ("sweep_agrees", pa.bool_()), ("duality_holds", pa.bool_()),
    ("thresholds_without_dual", pa.list_(pa.string())),
    ("sources_not_found", pa.list_(pa.string())), ("predictions", pa.list_(_PREDICTION)),
])


def _slug(x: Fraction) -> str:
    return str(x).replace("/", "_")


def part_path(out: Path, ba: Fraction, ca: Fraction) -> Path:
    return Path(out) / "parts" / f"b{_slug(ba)}-c{_slug(ca)}.parquet"


@functools.cache
def solver_stamp() -> str:
    """Digest of the code below the atlas that its rows depend on: the code of a phase record (the solver, the
    geometry, the model, the comparison with the sources, the manifests and the registry:
    :func:`symfloat.report.phase_data.code_files`) and every derivation's modules (predictions, thresholds),
    read where the registry finds them (the checkout's top-level ``derivations/``, not under the package)."""
    from ..registry import files, ids
    from ..report.phase_data import code_files
    root = Path(__file__).resolve().parents[1]
    return digest(*(f"{f.relative_to(root)}\n{f.read_text(encoding='utf-8')}" for f in code_files()),
                  *(f"{did}/{f.name}\n{f.read_text(encoding='utf-8')}" for did in ids() for f in sorted(files(did))
                    if f.suffix == ".py"))


@functools.cache
def code_stamp() -> str:
    """Digest of the code a cell's rows depend on: the atlas's cell, grid and data modules and
    :func:`solver_stamp`."""
    here = Path(__file__).parent
    return digest(*(here / f for f in ("cell.py", "grid.py", "dataset.py")), solver_stamp())


def _meta(ba, ca, densities) -> dict:
    return {"format": FORMAT, "code": code_stamp(), "b_a": str(ba), "c_a": str(ca),
            "densities": [str(Fraction(s)) for s in densities]}


def table_of(rows: list[dict], metadata: dict | None = None) -> pa.Table:
    table = pa.Table.from_pylist([{name: r.get(name) for name in SCHEMA.names} for r in rows], schema=SCHEMA)
    return table.replace_schema_metadata({_KEY: json.dumps(metadata or {}, sort_keys=True).encode()})


def _bytes(table: pa.Table) -> bytes:
    buffer = io.BytesIO()
    pq.write_table(table, buffer, compression="zstd")
    return buffer.getvalue()


def write_part(out: Path, ba, ca, densities, rows) -> Path:
    path = part_path(out, ba, ca)
    write_atomic(path, _bytes(table_of(rows, _meta(ba, ca, densities))))
    return path


def _metadata(path: Path) -> dict | None:
    try:
        meta = pq.read_schema(path).metadata or {}
        return json.loads(meta.get(_KEY, b"null"))
    except (OSError, ValueError, pa.ArrowException):
        return None


def part_done(out: Path, ba, ca, densities) -> bool:
    """Whether the cell's part exists, is readable and records the same sweep, format and code."""
    path = part_path(out, ba, ca)
    return path.is_file() and _metadata(path) == _meta(ba, ca, densities)


def read_part(out: Path, ba, ca) -> pa.Table:
    return pq.read_table(part_path(out, ba, ca), schema=SCHEMA)


def write_combined(out: Path, cells, densities) -> Path:
    """``DIR/atlas.parquet``: the parts of *cells* (in the order given) in one file."""
    table = pa.concat_tables([read_part(out, ba, ca) for ba, ca in cells])
    meta = {"format": FORMAT, "code": code_stamp(), "b_a": sorted({str(ba) for ba, _ in cells}, key=Fraction),
            "c_a": sorted({str(ca) for _, ca in cells}, key=Fraction),
            "densities": [str(Fraction(s)) for s in densities]}
    path = Path(out) / "atlas.parquet"
    write_atomic(path, _bytes(table_of(table.to_pylist(), meta)))
    return path


def read_atlas(path: Path) -> tuple[list[dict], dict]:
    """The rows of a combined atlas and its metadata (grid of b/a, c/a and densities)."""
    table = pq.read_table(path)
    return table.to_pylist(), json.loads((table.schema.metadata or {}).get(_KEY, b"{}"))
