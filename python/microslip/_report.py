"""Report: a read-only view of one of the application's JSON reports (a cycle, a K_T table, a fit,
an FE comparison), so a script reads ``r.coulomb.D_Nmm`` or ``r["coulomb"]["D_Nmm"]`` and
``r.to_dict()`` gives the dict ``json.loads`` makes of the CLI's ``--format json`` output.
"""

from __future__ import annotations

# No `typing` import: it would be half of `import microslip`'s time (the stubs carry the types).

import copy
from collections.abc import Mapping


def _view(value):
    if isinstance(value, dict):
        return Report(value)
    if isinstance(value, list):
        return tuple(_view(v) for v in value)
    return value


class Report(Mapping):
    """A JSON report, read-only: keys as items and, where they are identifiers, as attributes."""

    __slots__ = ("_data",)

    def __init__(self, data: dict) -> None:
        object.__setattr__(self, "_data", data)

    def __getitem__(self, key: str):
        return _view(self._data[key])

    def __iter__(self):
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def __getattr__(self, key: str):
        try:
            return _view(self._data[key])
        except KeyError:
            raise AttributeError(f"report has no key {key!r} (keys: {', '.join(self._data)})") from None

    def __setattr__(self, key: str, value) -> None:
        raise AttributeError("a Report is read-only; use to_dict() for a mutable copy")

    def __dir__(self) -> list:
        return sorted(set(super().__dir__()) | {k for k in self._data if k.isidentifier()})

    def to_dict(self) -> dict:
        """A deep copy of the report as plain dicts and lists (the CLI's JSON, parsed)."""
        return copy.deepcopy(self._data)

    def __repr__(self) -> str:
        return f"Report({self._data!r})"
