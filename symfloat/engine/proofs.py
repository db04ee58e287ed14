"""Proof certificates: how each claim was proved, replayed without a clock.

A symbolic proof is found once, by a *search* that tries the strategies of
:data:`~symfloat.engine.identity.STRATEGIES` under a time limit, and written
down as a :class:`Certificate`: the digest of the claim as checked, the
strategy that reduced its difference to zero (or ``None`` when the search
found none) and what the search tried.  Every later check *replays* the
certificate: it runs exactly that strategy, with no time limit, so the
verdict and its evidence are the same on any machine, however slow or busy.

A search happens only when a claim has no certificate or its digest changed
(the claim changed), or on request (``symfloat verify --search-proofs``).
A certificate that no longer proves its unchanged claim is a failure, never
a silent downgrade.

Certificates live in one JSON file per derivation, ``proofs/<id>.json``
beside the derivation modules, committed with them.
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from pathlib import Path

import sympy as sp

from .environment import slowdown

__all__ = ["Certificate", "ProofBook", "claim_digest", "proofs_file", "slowdown"]


@dataclass(frozen=True)
class Certificate:
    """How one claim was proved: ``strategy`` reduced the difference of the
    claim with digest ``digest`` to zero (``None``: the recorded search found
    no proof, and the claim rests on sampling).  ``tried`` is the search's own
    account, kept verbatim so that replays report it identically."""

    digest: str
    strategy: str | None
    tried: tuple[str, ...] = ()
    residual: str = ""

    def to_json(self) -> dict:
        data = {"digest": self.digest, "strategy": self.strategy, "tried": list(self.tried)}
        if self.residual:
            data["residual"] = self.residual
        return data

    @classmethod
    def from_json(cls, data: dict) -> "Certificate":
        return cls(str(data["digest"]), data["strategy"], tuple(data.get("tried", ())), data.get("residual", ""))


def claim_digest(pairs) -> str:
    """A digest of the claim as checked: the printed form of each pair of members.

    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> claim_digest([(x + 1, 1 + x)]) == claim_digest([(1 + x, x + 1)])
    True
    >>> claim_digest([(x, 2 * x)]) == claim_digest([(x, 3 * x)])
    False
    """
    h = hashlib.sha256()
    for a, b in pairs:
        h.update(sp.sstr(a).encode())
        h.update(b"\x00=\x00")
        h.update(sp.sstr(b).encode())
        h.update(b"\x00;\x00")
    return h.hexdigest()[:24]


def proofs_file(derivation_id: str) -> Path:
    """Where a derivation's certificates are kept: ``proofs.json`` in its package; a derivation built
    outside the registry, as tests do, keeps them in the working directory's ``proofs/``."""
    from ..registry import SelectorError, manifest

    try:
        folder = manifest(derivation_id).folder
    except SelectorError:
        return Path("proofs") / f"{derivation_id}.json"
    return folder / "proofs.json"


class ProofBook:
    """The certificates of one derivation, keyed by claim (``<derivation>/<step>#<link>``).

    ``search`` set: every claim is searched anew (certificates are ignored but
    the new outcome replaces them when written)."""

    def __init__(self, derivation_id: str, entries: dict | None = None, search: bool = False):
        self.derivation_id = derivation_id
        self.entries: dict[str, Certificate] = dict(entries or {})
        self.search = search

    @classmethod
    def load(cls, derivation_id: str, search: bool = False, folder: Path | None = None) -> "ProofBook":
        path = cls.path(derivation_id, folder)
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            data = {}
        except (OSError, ValueError) as exc:
            raise ValueError(f"{path}: unreadable proof certificates ({exc})") from None
        return cls(derivation_id, {k: Certificate.from_json(v) for k, v in data.items()}, search)

    def get(self, key: str, digest: str) -> Certificate | None:
        """The certificate of *key* if it is for this very claim (and no search was asked)."""
        cert = None if self.search else self.entries.get(key)
        return cert if cert is not None and cert.digest == digest else None

    @staticmethod
    def text(certificates: dict) -> str:
        """The file content for *certificates* (``key -> Certificate JSON``), in a stable order."""
        return json.dumps(dict(sorted(certificates.items())), indent=1, ensure_ascii=False) + "\n"

    @staticmethod
    def path(derivation_id: str, folder: Path | None = None) -> Path:
        return folder / f"{derivation_id}.json" if folder else proofs_file(derivation_id)
