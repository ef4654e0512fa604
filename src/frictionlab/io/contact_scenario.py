"""Contact scenario files: the parser is :mod:`frictionlab.schema.contact` (names kept)."""

from __future__ import annotations

from typing import Any

from frictionlab.schema.contact import SEGMENT, ContactScenario, parse_contact
from frictionlab.schema.contact import load_contact as load_contact_scenario

__all__ = ["ContactScenario", "load_contact_scenario", "parse_contact_scenario"]

_SEGMENTS = SEGMENT.variants


def parse_contact_scenario(data: dict[str, Any], source: str = "") -> ContactScenario:
    """:func:`frictionlab.schema.contact.parse_contact` (the older name)."""
    return parse_contact(data, source=source)
