"""Zones: stepped limit-value tables, boxes, polygons, and the allowed set."""

from .model import (
    AllowedSet,
    BoxZone,
    Point,
    PolygonZone,
    Region,
    SteppedZone,
    StepTable,
    Zone,
    ZonePoint,
    tip_shifted,
    translated,
)

__all__ = [
    "AllowedSet",
    "BoxZone",
    "Point",
    "PolygonZone",
    "Region",
    "SteppedZone",
    "StepTable",
    "Zone",
    "ZonePoint",
    "tip_shifted",
    "translated",
]
