"""Pulse distribution of arcs in cylindrical interpolation (G07.1).

As in JP patent 001: the controller interpolates the circle in the developed
plane (linear axis, developed rotary coordinate ``s`` in mm), then converts
the developed component into the rotary displacement ``C = C0 + s / k``
(``k = pi R / 180`` mm per degree) and rounds it to rotary pulses.

Method (all exact integers and rationals):

1. A fine developed grid: ``u_z / 4`` on the linear axis and
   ``u_s = u_c k_lo / 4`` mm on ``s`` (``k_lo`` a rational just below ``k``),
   so one fine step is at most a quarter pulse on either machine axis.
2. The exact circle (start ``(Z0, 0)``, end ``(Z1, D)``, centre) is replaced
   by rationals within ``1e-18`` mm (enclosures of :mod:`nczones.geometry.cylinder`),
   and :func:`nczones.controller.pulses.arc_walk` walks it on the fine grid
   from the grid point nearest the exact start: every walk point is within
   one fine step of that circle.
3. Each walk point is converted: Z pulse = nearest pulse of ``Z``, C pulse =
   nearest pulse of ``C0 + s / k~``; repeated positions are dropped and the
   motion ends exactly on the rounded end point.

Invariant: every commanded position is within ``1/4 + 1/2`` pulse (plus
``1e-12`` of a pulse) of the exact developed path on each axis, so the
rotary pulse count equals developed length / radius within one pulse; and
consecutive positions differ by at most one pulse per axis (pulse
distribution).  Tests check both against the enclosed exact path.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from fractions import Fraction
from itertools import chain

import numpy as np

from ..errors import InvalidArgument
from ..geometry.cylinder import cylinder_of, developed_arc_of
from ..motion import Segment
from .pulses import arc_walk, line_steps, round_pulse

__all__ = ["developed_arc_positions", "FINE"]

#: Fine grid steps per machine pulse in the developed plane.
FINE = 4
_APPROX = 10**18


def _rat(x: Fraction) -> Fraction:
    return Fraction(round(x * _APPROX), _APPROX)


def developed_arc_positions(seg: Segment, pulses: tuple[Fraction, ...], p0: tuple[int, ...]) -> np.ndarray:
    """The commanded pulse positions after each step of a developed arc (``(steps, axes)`` int64).

    ``pulses`` are the machine's pulse lengths, ``p0`` where the controller
    stands (pulses).  The last row is the rounded end point of ``seg``.

    >>> from nczones.motion import Developed, Segment, SegmentKind
    >>> F = Fraction
    >>> ex = (Developed("Z", "C", F(10)),)
    >>> seg = Segment(SegmentKind.DEVELOPED_ARC, (F(0), F(0)), (F(2), F(0)), ("Z", "C"),
    ...               clockwise=True, radius=F(1), extra=ex)
    >>> pos = developed_arc_positions(seg, (F(1, 1000), F(1, 1000)), (0, 0))
    >>> pos[-1].tolist(), int(pos[:, 1].max()) > 5700     # 1 mm on r = 10 mm is 5.73 deg
    ([2000, 0], True)
    """
    info = cylinder_of(seg)
    if info is None:
        raise InvalidArgument("not a motion made in cylindrical interpolation (G07.1)")
    lin, rot, _ = info
    iz, ic = seg.axes.index(lin), seg.axes.index(rot)
    arc = developed_arc_of(seg)
    uz, uc = pulses[iz], pulses[ic]
    k_lo = Fraction(math.floor(arc.k.lo * _APPROX), _APPROX)  # the conversion factor (k - 1e-18 < k_lo <= k)
    fz, fs = uz / FINE, uc * k_lo / FINE
    d_t = _rat(arc.d.mid())
    centre = (_rat(arc.centre[0].mid()), _rat(arc.centre[1].mid()))
    start = (arc.z0, Fraction(0))
    end = (arc.z1, d_t)
    sp = (round_pulse(arc.z0, fz), 0)
    ep = (round_pulse(arc.z1, fz), round_pulse(d_t, fs))
    walk = arc_walk(sp, ep, start, end, centre, seg.clockwise, 0, (fz, fs))
    p1 = tuple(round_pulse(v, u) for v, u in zip(seg.end, pulses))
    # conversion, in integers: Z = zf * u_z / FINE, C = C0 + sf * u_s / k_lo = C0 + sf * u_c / FINE
    c0 = arc.c0 / uc
    num, den = c0.numerator, c0.denominator
    pts = [sp] + list(walk.points)
    zq = [(2 * zf + FINE) // (2 * FINE) for zf, _ in pts]
    cq = [(2 * (FINE * num + sf * den) + FINE * den) // (2 * FINE * den) for _, sf in pts]
    base = list(p0)

    def cells(z: int, c: int) -> tuple[int, ...]:
        row = list(base)
        row[iz], row[ic] = z, c
        return tuple(row)

    return join_steps((cells(z, c) for z, c in zip(zq, cq)), tuple(p0), p1)


def join_steps(rows: Iterable[tuple[int, ...]], p0: tuple[int, ...], p1: tuple[int, ...]) -> np.ndarray:
    """The single pulse steps from ``p0`` through ``rows`` (pulse positions at most two pulses apart, repeats
    allowed) to ``p1``, as an ``(n, axes)`` int64 array without ``p0``."""
    out: list[tuple[int, ...]] = []
    last = p0
    for row in chain(rows, (p1,)):
        if row == last:
            continue
        jump = max(abs(x - y) for x, y in zip(last, row))
        if jump > 2:  # pragma: no cover - the walks' invariant says at most 1
            raise InvalidArgument(f"a jump of more than two pulses between {last} and {row}")
        if jump <= 1:
            out.append(row)
        else:
            out.extend(line_steps(last, row))
        last = row
    if not out:
        return np.zeros((0, len(p0)), dtype=np.int64)
    return np.array(out, dtype=np.int64)


def developed_arc_walk(seg: Segment, pulse: tuple[Fraction, ...], p0: tuple[int, ...]) -> tuple[np.ndarray, float]:
    """The pulse positions of a developed arc and the length its feed applies to (``Controller.plan``).

    The length is in developed mm: F is the feed on the developed surface.
    """
    pos = developed_arc_positions(seg, pulse, p0)
    return pos, float(developed_arc_of(seg).length().mid())
