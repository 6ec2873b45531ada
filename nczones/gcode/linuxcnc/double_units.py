"""G20 (inches) in the double pass (:mod:`nczones.gcode.linuxcnc.doubles`): the code of a straight move's ends
in inches, and why the pass's bound still holds.

The full path (``Interpreter.program_target``, ``_lean_move``) takes a G20 word's exact value ``w`` (its shadow,
or its double: within half an ulp of the double ``d``) times exactly 25.4 (``INCH``, ``_qinch``) and adds the
exact offset ``O`` (work offset plus tool length, both millimetres whatever the units) in G90, or the machine
position in G91: millimetres, exactly.  LinuxCNC keeps positions in program units (``convert_length_units``
divides its offsets by 25.4 at G20) and its canon multiplies by 25.4 in a double (``FROM_PROG_LEN``) before it
adds its offsets in millimetres; the pass computes the same shape, ``s = fl(d * c)`` with ``c = fl(25.4)``,
then ``x = fl(s + fl(O))`` (G90) or ``x = fl(p + s)`` (G91, ``p`` the row before).

Why the bound holds
-------------------
Write ``u = 2**-53`` and ``eta = 2**-1075`` (half the least subnormal: a rounding's error is at most
``u |result| + eta``).  ``|c - 25.4| = 1.42e-15 < 0.51 u 25.4`` and ``|w - d| <= u |d| + eta``, so with the
exact ``W = 25.4 w``: ``|d c - W| <= |d| |c - 25.4| + 25.4 |w - d| <= 1.51 u 25.4 |d| + 26 eta``, and with
the rounding of ``s``: ``|s - W| <= 2.52 u |s| + 28 eta`` (``25.4 |d| <= |s| (1 + 2u)`` plus ``eta``).

*G90*: ``|x - (W + O)| <= u |x| + |s - W| + u |O| + 30 eta``, and ``|s| <= (1 + u)(|x| + |O|) + eta``
(``s = x - fl(O) + `` the sum's rounding), so ``|x - (W + O)| <= 3.6 u (|x| + |O|) + 32 eta``.  The enclosure
(:meth:`~nczones.gcode.linuxcnc.doubles.DoublePath.enclosure`) widens a window's rows by ``8 u (top + offb) +
2**-60`` (``top`` the largest row, ``offb`` the offsets' bound): above it, as above the G21 row's
``2 u (|x| + |O|)``.  A G91 chain's start (:func:`chain_start`) is ``4 u (|p| + offb)`` rounded up, plus
``2**-1000`` in a program that may write G20 (above ``32 eta``): above it too.  The arcs' boxes
(:mod:`.double_arcs`) assume rows within ``(4 m + 2**-8) 2**-52``, ``m`` above every row and the offsets'
bound: they hold the G20 rows as they do the G21 ones (a row on a G91 chain, in either units, grows that bound by the
chain's error: :func:`~.double_arcs.chain_offb`).  An I/J arc *in* G20 has scaled words, ``2.52 u |s|``
from the exact ones where the arcs' sums take ``u |s|``: it is computed with a larger offsets' bound
(:func:`~.double_arcs.inch_offb`, which says why that covers them) and LinuxCNC's I/J rule in inches
(:func:`~.double_arcs.inch_rule`); an R arc in G20 with ``R**2`` within ``R'**2 2**-50`` where a word's is within
``R'**2 2**-51`` (:data:`~.double_arcs.R_INCH_REL`, which says why).

*G91*: with ``|p - M| <= e`` (``M`` the full path's machine position), ``|x - (M + W)| <= e + |s - W| + u |x|
+ eta <= e + 2.52 u |s| + u |x| + 29 eta``; :func:`inch_ends` adds ``(3 |s| + |x|) 2**-52 + 2**-1000`` rounded
up (``6 u |s| + 2 u |x|``: above it, the slack far above the roundings of that float expression, and
``2**-1000`` above ``29 eta`` when the sum is below ``2**-900``), so ``ERR`` bounds the chain as in G21
(:meth:`~nczones.gcode.linuxcnc.doubles._Pass._straight_ends`); the units may change inside a chain: each
step adds its own units' term.

The tool length: LinuxCNC 2.9 does not convert an applied tool length at a units change (the full path's
``_tool_length`` and ``tool_length_units_stale``: unknown for a G43/G49 after G20/G21 while a length is
applied); the pass declines a G43 or G49 made in other units than the length applied (:meth:`~nczones.gcode.
linuxcnc.doubles._Pass.tool`), whatever that length.  ``tests/gcode/test_double_pass_units.py`` holds the
pass to the full path on G20 programs (and faces at ``25.4 x`` and ``5e-16`` mm either side of it, where the
controller's double lies 1.08 ulp short of the exact end).
"""

from __future__ import annotations

#: ``fl(25.4)``: a G20 word's double times it is the word's millimetres (one rounding, as LinuxCNC's canon).
INCH = 25.4
#: The absolute term a G20 program's chain bound adds (above ``32 * 2**-1075``, far below any bound that matters).
TA = 2.0**-1000


def chain_start(i: int, offb2: float, inch_text: bool) -> str:
    """The source of the bound of a G90 row (``pos[i]``) where a G91 chain starts: ``(2 |p| + 2 offb) 2**-52``
    rounded up (``offb2`` is ``2 offb`` rounded up), plus ``2**-1000`` when the program may write G20 (its G90
    rows' bound then has the ``32 eta`` term of the module's docstring)."""
    tail = " + TA" if inch_text else ""
    return f"if e is None: e = NA((2.0 * abs(pos[{i}]) + {offb2!r}) * EPS2{tail}, INF)"


def inch_ends(axes: list[tuple[int, int]], offb2: list[float], named: tuple[int, ...]) -> list[str]:
    """The code of a straight move's ends in G20: ``s = v * 25.4``, then G91 ``x = pos + s`` with the chain's
    bound (the module's docstring), or G90 ``x = s + off`` (ending the axes' chains)."""
    inc = []
    for k, i in axes:
        inc += [f"s = v[{k}] * {INCH!r}", f"x{i} = pos[{i}] + s", f"e = ERR[{i}]", chain_start(i, offb2[i], True),
                f"e = ERR[{i}] = NA(e + NA((3.0 * abs(s) + abs(x{i})) * EPS2 + TA, INF), INF)",
                f"if e > XERR[{i}]: XERR[{i}] = e", f"pos[{i}] = x{i}"]
    g90 = [f"pos[{i}] = x{i} = v[{k}] * {INCH!r} + off[{i}]" for k, i in axes]
    return ["if st.inc:", *(f"    {b}" for b in inc), "    st.chained = True",
            "else:", *(f"    {b}" for b in g90), f"    if st.chained: st.unchain({named!r})"]
