"""What a `safe` verdict assumes, in one list (``specs/contract.md``, "What `safe` assumes").

A proof is about a model of the machine and the run; these are the model's terms.  Each report
states the run's own settings (margin, ranges, block-delete positions, notes); this list is what
holds for every run.  ``specs/contract.md`` carries the same list (a test keeps them equal) and
the HTML report prints it.

>>> len(SAFE_ASSUMPTIONS) > 10 and all(a.endswith(".") for a in SAFE_ASSUMPTIONS)
True
"""

from __future__ import annotations

__all__ = ["SAFE_ASSUMPTIONS"]

#: One sentence per assumption, in the order of specs/contract.md.
SAFE_ASSUMPTIONS: tuple[str, ...] = (
    "The machine is its machine file: axes, rapid rates and rapid mode, zones, work offsets, tool lengths "
    "and diameters, the start and reference positions, as written, or anywhere in the --param ranges "
    "(independent intervals; every combination of values is covered).",
    "Homing puts the machine coordinates where the machine file says (or within the home.* ranges).",
    "The program runs from its first line (no run-from-line, no restart in the middle) with the machine "
    "file's modal state, no G92 offset and no tool length active, the tool table of the machine file, and "
    "numbered parameters #1-#5000 at 0 (a freshly started controller); state parameters (#5221 work "
    "offsets, #5161 G28 position, ...) read what the machine file and the program set.",
    "The G-code means what LinuxCNC's interpreter makes of it (specs/gcode-support.md; expressions in "
    "its doubles), or with dialect = \"fanuc\" what specs/fanuc.md says a Fanuc control makes of it; a "
    "code nczones cannot model makes the verdict unknown, never safe.",
    "Fanuc dialect: macro values are IEEE doubles, as the manuals state, and a position computed from "
    "them, an offset they write (#5201-#5340, #7001-, the tool offset tables; stored in whole increments, as "
    "G10 stores it) and a point moved by scaling (G51) are rounded to the least input increment, halves away "
    "from zero; a macro double is read as its 15-digit decimal, as scaled to increments in doubles or as the "
    "exact decimal it stands for, and where these round to different increments the verdict is unknown "
    "(GC399); a control that reads or rounds otherwise can stand one increment away from the proved path. FIX, "
    "FUP, ROUND, MOD, AND/OR/XOR, BIN/BCD, a variable number (computed or a literal), the relational operators, "
    "POW's integer exponent and ASIN/ACOS's bound -1..1 take the result the double as it is, its 15-digit "
    "decimal and its exact decimal all give, and where they differ the verdict is unknown (GC398); a control "
    "that reads otherwise can count a loop or take a branch differently. SIN, COS, TAN, ATAN, ASIN, ACOS, LN, "
    "EXP and POW of the control's double give the double CPython's math library gives or one of its two "
    "neighbours (the true value where nczones knows it is a double), and where these give different results or "
    "round to different increments the verdict is unknown (GC396, GC397); a control whose library is further "
    "off can stand one increment away or take a branch differently where a result lies that near a half "
    "increment or a comparison's edge. A point "
    "moved by rotation (G68) or polar input (G16) is the exact point rounded to the nearest increment: "
    "the control computes it to within a millionth of an increment (a point nearer than that to halfway "
    "between two increments makes the verdict unknown).",
    "The machine moves along the programmed path: straight lines, exact circles (spirals for arcs whose "
    "end is off the circle within the tolerance; a Grbl control, arc_tolerance = \"grbl\", moves such an "
    "arc on its start radius and then straight to the end point, at most 0.005 mm from that spiral; an I/J "
    "arc whose end lies on the ray from the centre through its start, where LinuxCNC moves a whole spiral "
    "turn, stays within the larger of its two radii from the centre in its plane), "
    "exact NURBS, rapids straight or dogleg as the machine file says, except where its path mode rounds "
    "corners and, on a Fanuc control, inside an arc or a polar move (acc/dec after interpolation: anywhere "
    "in its convex hull, in every path mode); no following error or overshoot.",
    "Corner blending (specs/path-modes.md): the corner after a motion in G64 (LinuxCNC, the default) or "
    "cutting mode (Fanuc G64/G62/G63, the default) may be rounded, in G61, G61.1 and after a Fanuc G09 "
    "block not. LinuxCNC G64 uses at most half of a straight motion (BLEND_DIST_FRACTION; next to an arc the "
    "planner's fit does not check it, and at most half is measured on 300,000 random corners), the last two "
    "thirds of an arc before the corner and the first third of one after it (phi_max); G64 P p "
    "(its Q defaults to P) stays within p + q of the programmed path, assuming a blend the planner takes "
    "as nearly straight (a direction change under 0.002 rad) stays within p too and the feed override is "
    "constant during a blend; a Fanuc control in cutting mode stays in the convex hull of the motions "
    "since its last exact stop, or within [machine] path_tolerance. A dogleg rapid stops exactly at both "
    "ends. A corner whose enclosure may leave the allowed set is unknown (VF208).",
    "LinuxCNC dialect, tool change: M6 moves the machine only as the machine file says, each move a rapid in "
    "machine coordinates: tool_change_quill_up (Z to machine 0), then tool_change_at_g30 (every axis to the G30 "
    "position), then [machine.tool_change_position] (a straight move there, LinuxCNC's TOOL_CHANGE_POSITION); "
    "without them M6 does not move the machine. The tool changer's own mechanism (carousel, arm) stays clear of "
    "the zones, and M6 is not remapped (REMAP=M6 runs a program nczones does not see).",
    "Block delete: every block-skip switch the program uses (Fanuc /1 .. /9, / is /1; LinuxCNC's one "
    "switch) is verified in both positions, in every combination with the others, unless the machine "
    "file (block_delete) or --block-delete fixes it, which the report then says (more than 16 "
    "combinations whose runs can differ: unknown, VF206); an optional stop (M1) does not move the "
    "machine in either position.",
    "The operator does not move the machine during the program: no jogging or handwheel moves during a "
    "stop (M0, M1, M60) or feed hold, no manual data input, no mirror-image, axis-lock or Z-neglect "
    "switches; feed and rapid overrides change speed only (a dogleg rapid keeps its shape).",
    "Zones are exact: touching a forbid zone's boundary is allowed, a forbid zone without interior "
    "(min = max on an axis) forbids nothing, tool-tip zones see machine Z minus the active tool length.",
    "Lathe tool nose: the tool's cutting edge is the nose circle of its tool offset's radius; tool-tip "
    "zones are proved against the square of half-width R (tip 0/9) or 2R (tips 1-8) around the imaginary "
    "tool tip on X and Z (the largest over the machine file's tool offsets), which contains that circle; a "
    "tip zone that cannot be enlarged so makes the verdict unknown.",
    "Tool solids (a machine file with [[tools]] or [spindle]): every part is the cylinder the machine "
    "file gives, enclosing the real cutter, shank, holder or spindle nose; the tool in the spindle is the"
    " [[tools]] entry numbered like the active tool length register (G43 H<n>: tool n; a motion after the "
    "program's own M6 or M61 put another tool in the spindle is unknown) and its tip is at "
    "machine Z minus the active tool length; fixtures are where the machine file puts them (forbid box "
    "zones, stepped tables of X/Y/Z as a box per region, forbid XY polygons as prisms included), a "
    "fixture with a `frame` at that work offset as the program sets it; on tool-break recovery legs the "
    "replacement tool has the broken tool's [[tools]] parts, at the replacement's tool length. The tool is "
    "rigid and moves with the controlled point without turning, so where the control rounds a corner every "
    "part moves by the same vector as the controlled point, within the corner enclosures above (a mill's "
    "solids are proved over them; a lathe's within a tolerance only, its corners without one are unknown).",
    "Lathe tool solids (a lathe's [[tools]] parts): the tool lies on centre height (its tip and its "
    "parts' section in the plane through the spindle axis, Y = 0); every part is the rectangle the "
    "machine file gives, enclosing the real insert, bar or holder in that plane (a round bar along Z by "
    "its diameter), grown by half its thickness across it; the tool at the turret is the [[tools]] entry "
    "of the T word's tool number (Fanuc) or of the tool length register (LinuxCNC) and its tip is the "
    "controlled point minus the tool offsets; the other stations of the turret carry nothing that reaches "
    "a fixture; the fixtures are solids of revolution about the spindle axis (a forbid box zone "
    "revolved); on tool-break recovery legs the replacement tool has the broken tool's [[tools]] parts and "
    "tip offset.",
    "Fanuc dialect: a tool change moves no axis: M06 on a machining centre and the T code that indexes a "
    "lathe's turret (with tool_offset_motion = \"shift\") only change the tool and its offsets, unless "
    "[macros] calls a program for them, whose moves are proved; the machine builder's tool change motion and "
    "the turret's swing are not checked (M06 on a lathe is unknown).",
    "A margin d is clearance on every axis: the box of half-width d around every path point fits the "
    "allowed set.",
    "Cutter radius compensation is modelled only with cutter_compensation = \"linuxcnc\" (otherwise "
    "unknown); tool-break recovery only with --recovery and without --param ranges (with ranges it is "
    "proved at one point of them and the verdict is at best unknown); its legs are the controller's own "
    "positioning moves, each to an exact stop (no corner between two legs is rounded, whatever the program's "
    "path mode).",
    "Loops run at most --max-iterations times per entry (more is unknown); probing, M66 inputs and reads "
    "of spindle, coolant, override or HAL state are unknown.",
    "Numbers are exact: decimals as written, no float enters a proof; irrational quantities are enclosed "
    "and a witness is re-checked exactly before it is reported.",
)
