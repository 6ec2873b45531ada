"""The functions ``dataclasses`` generates for nczones' classes, compiled once like any module (written
by ``python -m nczones.precompiled --write``; do not edit: see :mod:`nczones.precompiled`): the functions the start-ups of ``python -m nczones.precompiled``'s scenarios make, 
``functions_later`` the others)."""
# ruff: noqa
# mypy: ignore-errors
# fmt: off

def f0():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.axes,self.columns,self.offset_bound,self.motions,self.lines,self.rapids,self.blocks,self.start,self.first_row,self.row0,self.arcs,self.arc_rows,self.arc_axes,self.arc_boxes,self.arc_more,self.dwells,self.dwell_rows,self.modes,self.inc_bound,self.assumed,self.tolerance,self.arc_planes,)==(other.axes,other.columns,other.offset_bound,other.motions,other.lines,other.rapids,other.blocks,other.start,other.first_row,other.row0,other.arcs,other.arc_rows,other.arc_axes,other.arc_boxes,other.arc_more,other.dwells,other.dwell_rows,other.modes,other.inc_bound,other.assumed,other.tolerance,other.arc_planes,)
  return NotImplemented
 return __eq__

def f1():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.axes,self.degrees,self.cos,self.sin,self.before,self.after,)==(other.axes,other.degrees,other.cos,other.sin,other.before,other.after,)
  return NotImplemented
 return __eq__

def f2():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.axes,self.scale,self.kind,self.start,self.end,self.line,self.block,self.tool_length,self.centre,self.plane,self.clockwise,self.turns,self.feed,self.file,self.objects,self.dwell,self.derived,self.frame,self.radius,self.tool_register,self.tools_known,)==(other.axes,other.scale,other.kind,other.start,other.end,other.line,other.block,other.tool_length,other.centre,other.plane,other.clockwise,other.turns,other.feed,other.file,other.objects,other.dwell,other.derived,other.frame,other.radius,other.tool_register,other.tools_known,)
  return NotImplemented
 return __eq__

def f3():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.blend,self.tolerance,self.naive,self.dialect,self.code,)==(other.blend,other.tolerance,other.naive,other.dialect,other.code,)
  return NotImplemented
 return __eq__

def f4():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.block,self.span,self.zone,self.point,self.path_point,self.parameter,self.parameter_exact,self.first_exit,self.first_exit_parameter,self.first_exit_exact,self.depth,self.depth_exact,self.engine,self.segment_kind,self.derived,self.kind,self.params,self.zones,self.note,self.on_path,self.break_line,self.break_parameter,self.break_point,self.leg,self.switches,self.exit_located,)==(other.block,other.span,other.zone,other.point,other.path_point,other.parameter,other.parameter_exact,other.first_exit,other.first_exit_parameter,other.first_exit_exact,other.depth,other.depth_exact,other.engine,other.segment_kind,other.derived,other.kind,other.params,other.zones,other.note,other.on_path,other.break_line,other.break_parameter,other.break_point,other.leg,other.switches,other.exit_located,)
  return NotImplemented
 return __eq__

def f5():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.code,self.message,self.span,self.severity,self.file,)==(other.code,other.message,other.span,other.severity,other.file,)
  return NotImplemented
 return __eq__

def f6():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.code,self.reason,self.span,)==(other.code,other.reason,other.span,)
  return NotImplemented
 return __eq__

def f7():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.decimal_point_input,self.increment_system,self.g73_retract,self.g83_clearance,self.boring_shift,self.scaling_unit,self.rotation_incremental,self.atan_signed,self.tool_length_motion,self.harmless_m,self.references,self.variables,self.macros,self.gcode_system,self.g71_depth,self.g71_retract,self.roughing_final_pass,self.g73_relief_x,self.g73_relief_z,self.g73_divisions,self.g74_retract,self.thread_chamfer,self.thread_chamfer_angle,self.g76_finish_passes,self.g76_tool_angle,self.g76_min_depth,self.g76_finish_allowance,self.tool_offset_motion,self.tool_offset_cancel,self.path,)==(other.decimal_point_input,other.increment_system,other.g73_retract,other.g83_clearance,other.boring_shift,other.scaling_unit,other.rotation_incremental,other.atan_signed,other.tool_length_motion,other.harmless_m,other.references,other.variables,other.macros,other.gcode_system,other.g71_depth,other.g71_retract,other.roughing_final_pass,other.g73_relief_x,other.g73_relief_z,other.g73_divisions,other.g74_retract,other.thread_chamfer,other.thread_chamfer_angle,other.g76_finish_passes,other.g76_tool_angle,other.g76_min_depth,other.g76_finish_allowance,other.tool_offset_motion,other.tool_offset_cancel,other.path,)
  return NotImplemented
 return __eq__

def f8():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.degree,self.knots,self.control,self.weights,self.source,)==(other.degree,other.knots,other.control,other.weights,other.source,)
  return NotImplemented
 return __eq__

def f9():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.delete,self.number,self.oword,self.words,self.assigns,self.comments,self.percent,self.unsupported,)==(other.delete,other.number,other.oword,other.words,other.assigns,other.comments,other.percent,other.unsupported,)
  return NotImplemented
 return __eq__

def f10():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.delete,self.number,self.program,self.words,self.assigns,self.comments,self.stmt,self.stmt_at,self.percent,self.unmodelled,)==(other.delete,other.number,other.program,other.words,other.assigns,other.comments,other.stmt,other.stmt_at,other.percent,other.unmodelled,)
  return NotImplemented
 return __eq__

def f11():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.file,self.line,self.column,self.end_column,self.text,)==(other.file,other.line,other.column,other.end_column,other.text,)
  return NotImplemented
 return __eq__

def f12():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.ia,self.ib,self.s,self.e,self.ccw,self.full,self.centre,self.r_signed,self.r2_lo,self.r2_hi,self.start,self.end,)==(other.ia,other.ib,other.s,other.e,other.ccw,other.full,other.centre,other.r_signed,other.r2_lo,other.r2_hi,other.start,other.end,)
  return NotImplemented
 return __eq__

def f13():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.key,self.group,self.lanes,)==(other.key,other.group,other.lanes,)
  return NotImplemented
 return __eq__

def f14():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.key,self.meaning,self.read,)==(other.key,other.meaning,other.read,)
  return NotImplemented
 return __eq__

def f15():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.kind,self.label,self.head,self.remaining,self.count,self.ifs,)==(other.kind,other.label,other.head,other.remaining,other.count,other.ifs,)
  return NotImplemented
 return __eq__

def f16():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.kind,self.label,self.ret,self.saved,self.body,self.repeats,self.loops,self.ifs,self.caller,)==(other.kind,other.label,other.ret,other.saved,other.body,other.repeats,other.loops,other.ifs,other.caller,)
  return NotImplemented
 return __eq__

def f17():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.kind,self.source,self.program,self.ret,self.body,self.repeats,self.saved,self.args,self.loops,self.custom,)==(other.kind,other.source,other.program,other.ret,other.body,other.repeats,other.saved,other.args,other.loops,other.custom,)
  return NotImplemented
 return __eq__

def f18():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.kind,self.start,self.end,self.axes,self.block,self.span,self.tool_length,self.feed_mm_min,self.plane,self.clockwise,self.centre,self.radius,self.turns,self.dwell_s,self.derived,self.tool_register,self.deps_start,self.deps_end,self.deps_tool,self.extra,)==(other.kind,other.start,other.end,other.axes,other.block,other.span,other.tool_length,other.feed_mm_min,other.plane,other.clockwise,other.centre,other.radius,other.turns,other.dwell_s,other.derived,other.tool_register,other.deps_start,other.deps_end,other.deps_tool,other.extra,)
  return NotImplemented
 return __eq__

def f19():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.label,self.keyword,self.args,self.column,self.end_column,)==(other.label,other.keyword,other.args,other.column,other.end_column,)
  return NotImplemented
 return __eq__

def f20():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.lane,self.g,self.m,)==(other.lane,other.g,other.m,)
  return NotImplemented
 return __eq__

def f21():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.linear_axis,self.rotary_axis,self.cylinder_radius,)==(other.linear_axis,other.rotary_axis,other.cylinder_radius,)
  return NotImplemented
 return __eq__

def f22():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.lo,self.hi,)==(other.lo,other.hi,)
  return NotImplemented
 return __eq__

def f23():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.lo,self.hi,self.lo_closed,self.hi_closed,)==(other.lo,other.hi,other.lo_closed,other.hi_closed,)
  return NotImplemented
 return __eq__

def f24():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.m,self.head,self.count,)==(other.m,other.head,other.count,)
  return NotImplemented
 return __eq__

def f25():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.margin,self.params,self.engine,self.max_violations,self.arc_tolerance,self.recovery,self.max_iterations,self.dialect,self.library,self.block_delete,self.budget_s,self.tool_table,self.tool_table_units,self.tool_table_x_offset,)==(other.margin,other.params,other.engine,other.max_violations,other.arc_tolerance,other.recovery,other.max_iterations,other.dialect,other.library,other.block_delete,other.budget_s,other.tool_table,other.tool_table_units,other.tool_table_x_offset,)
  return NotImplemented
 return __eq__

def f26():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.message,self.span,self.block,self.code,)==(other.message,other.span,other.block,other.code,)
  return NotImplemented
 return __eq__

def f27():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.missing,self.on_fallback,)==(other.missing,other.on_fallback,)
  return NotImplemented
 return __eq__

def f28():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.name,self.limits,self.forbid,self.point,)==(other.name,other.limits,other.forbid,other.point,)
  return NotImplemented
 return __eq__

def f29():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.name,self.lo,self.hi,self.written,self.absolute,self.lo_open,self.hi_open,self.centre,)==(other.name,other.lo,other.hi,other.written,other.absolute,other.lo_open,other.hi_open,other.centre,)
  return NotImplemented
 return __eq__

def f30():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.name,self.max_passes,self.spent,)==(other.name,other.max_passes,other.spent,)
  return NotImplemented
 return __eq__

def f31():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.name,self.plane,self.vertices,self.limits,self.forbid,self.point,)==(other.name,other.plane,other.vertices,other.limits,other.forbid,other.point,)
  return NotImplemented
 return __eq__

def f32():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.name,self.pulse,self.rapid_mm_min,self.max_feed_mm_min,self.rotary,self.accel_mm_s2,)==(other.name,other.pulse,other.rapid_mm_min,other.max_feed_mm_min,other.rotary,other.accel_mm_s2,)
  return NotImplemented
 return __eq__

def f33():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.name,self.reference_axis,self.limited_axis,self.start,self.regions,self.forbid,self.point,)==(other.name,other.reference_axis,other.limited_axis,other.start,other.regions,other.forbid,other.point,)
  return NotImplemented
 return __eq__

def f34():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.name,self.units,self.axes,self.rapid_mode,self.monitor_period_ms,self.reference,self.start,self.offsets,self.tool_lengths,self.allowed,self.modal,self.tool_axis,self.source,self.warnings,self.sections,self.cutter_compensation,self.tool_diameters,self.sha256,self.dialect,self.fanuc,self.block_delete,self.arc_tolerance,self.path_mode,self.path_tolerance,self.machine_type,self.diameter_axes,self.tool_offsets,self.tool_length_wear,self.tool_radius_wear,self.control_units,self.tool_change_quill_up,self.tool_change_at_g30,self.tool_change_position,self.subroutine_path,)==(other.name,other.units,other.axes,other.rapid_mode,other.monitor_period_ms,other.reference,other.start,other.offsets,other.tool_lengths,other.allowed,other.modal,other.tool_axis,other.source,other.warnings,other.sections,other.cutter_compensation,other.tool_diameters,other.sha256,other.dialect,other.fanuc,other.block_delete,other.arc_tolerance,other.path_mode,other.path_tolerance,other.machine_type,other.diameter_axes,other.tool_offsets,other.tool_length_wear,other.tool_radius_wear,other.control_units,other.tool_change_quill_up,other.tool_change_at_g30,other.tool_change_position,other.subroutine_path,)
  return NotImplemented
 return __eq__

def f35():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.number,)==(other.number,)
  return NotImplemented
 return __eq__

def f36():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.number,self.geometry,self.wear,self.nose_radius,self.wear_radius,self.tip,)==(other.number,other.geometry,other.wear,other.nose_radius,other.wear_radius,other.tip,)
  return NotImplemented
 return __eq__

def f37():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.offsets,)==(other.offsets,)
  return NotImplemented
 return __eq__

def f38():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.p0,self.p1,self.tau0,self.tau1,)==(other.p0,other.p1,other.tau0,other.tau1,)
  return NotImplemented
 return __eq__

def f39():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.start,self.end,self.turns,self.x_off,self.c_entry,self.linear_axis,self.rotary_axis,self.grid,self.arc,self.centre,self.radius,)==(other.start,other.end,other.turns,other.x_off,other.c_entry,other.linear_axis,other.rotary_axis,other.grid,other.arc,other.centre,other.radius,)
  return NotImplemented
 return __eq__

def f40():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.status,self.values,self.approximate,self.stopped,)==(other.status,other.values,other.approximate,other.stopped,)
  return NotImplemented
 return __eq__

def f41():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.summary,self.configure,)==(other.summary,other.configure,)
  return NotImplemented
 return __eq__

def f42():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.text,self.name,self.digest,self.path,self.notes,)==(other.text,other.name,other.digest,other.path,other.notes,)
  return NotImplemented
 return __eq__

def f43():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.upto,self.min,self.max,)==(other.upto,other.min,other.max,)
  return NotImplemented
 return __eq__

def f44():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.value,self.deps,)==(other.value,other.deps,)
  return NotImplemented
 return __eq__

def f45():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.verdict,self.violations,self.reasons,self.engines,self.solver,self.solver_version,self.timings,self.notes,self.stats,self.margin,self.params,self.engine,self.truncated,self.file,self.program_digest,self.machine_name,self.machine_file,self.machine_sha256,self.settings,self.interrupted,self.budget_s,)==(other.verdict,other.violations,other.reasons,other.engines,other.solver,other.solver_version,other.timings,other.notes,other.stats,other.margin,other.params,other.engine,other.truncated,other.file,other.program_digest,other.machine_name,other.machine_file,other.machine_sha256,other.settings,other.interrupted,other.budget_s,)
  return NotImplemented
 return __eq__

def f46():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.violation,self.reason,self.engine,)==(other.violation,other.reason,other.engine,)
  return NotImplemented
 return __eq__

def f47():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.work,self.offset,self.rotation,self.diameter,self.inch,self.opaque,self.work_offset,)==(other.work,other.offset,other.rotation,other.diameter,other.inch,other.opaque,other.work_offset,)
  return NotImplemented
 return __eq__

def f48():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.zones,self.tool_axis,)==(other.zones,other.tool_axis,)
  return NotImplemented
 return __eq__

def f49():
 def __hash__(self):
  return hash((self.axes,self.columns,self.offset_bound,self.motions,self.lines,self.rapids,self.blocks,self.start,self.first_row,self.row0,self.arcs,self.arc_rows,self.arc_axes,self.arc_boxes,self.arc_more,self.dwells,self.dwell_rows,self.modes,self.inc_bound,self.assumed,self.tolerance,self.arc_planes,))
 return __hash__

def f50():
 def __hash__(self):
  return hash((self.axes,self.degrees,self.cos,self.sin,self.before,self.after,))
 return __hash__

def f51():
 def __hash__(self):
  return hash((self.axes,self.scale,self.kind,self.start,self.end,self.line,self.block,self.tool_length,self.centre,self.plane,self.clockwise,self.turns,self.feed,self.file,self.objects,self.dwell,self.derived,self.frame,self.radius,self.tool_register,self.tools_known,))
 return __hash__

def f52():
 def __hash__(self):
  return hash((self.blend,self.tolerance,self.naive,self.dialect,self.code,))
 return __hash__

def f53():
 def __hash__(self):
  return hash((self.block,self.span,self.zone,self.point,self.path_point,self.parameter,self.parameter_exact,self.first_exit,self.first_exit_parameter,self.first_exit_exact,self.depth,self.depth_exact,self.engine,self.segment_kind,self.derived,self.kind,self.params,self.zones,self.note,self.on_path,self.break_line,self.break_parameter,self.break_point,self.leg,self.switches,self.exit_located,))
 return __hash__

def f54():
 def __hash__(self):
  return hash((self.code,self.message,self.span,self.severity,self.file,))
 return __hash__

def f55():
 def __hash__(self):
  return hash((self.code,self.reason,self.span,))
 return __hash__

def f56():
 def __hash__(self):
  return hash((self.decimal_point_input,self.increment_system,self.g73_retract,self.g83_clearance,self.boring_shift,self.scaling_unit,self.rotation_incremental,self.atan_signed,self.tool_length_motion,self.harmless_m,self.references,self.variables,self.macros,self.gcode_system,self.g71_depth,self.g71_retract,self.roughing_final_pass,self.g73_relief_x,self.g73_relief_z,self.g73_divisions,self.g74_retract,self.thread_chamfer,self.thread_chamfer_angle,self.g76_finish_passes,self.g76_tool_angle,self.g76_min_depth,self.g76_finish_allowance,self.tool_offset_motion,self.tool_offset_cancel,self.path,))
 return __hash__

def f57():
 def __hash__(self):
  return hash((self.degree,self.knots,self.control,self.weights,self.source,))
 return __hash__

def f58():
 def __hash__(self):
  return hash((self.delete,self.number,self.oword,self.words,self.assigns,self.comments,self.percent,self.unsupported,))
 return __hash__

def f59():
 def __hash__(self):
  return hash((self.delete,self.number,self.program,self.words,self.assigns,self.comments,self.stmt,self.stmt_at,self.percent,self.unmodelled,))
 return __hash__

def f60():
 def __hash__(self):
  return hash((self.file,self.line,self.column,self.end_column,self.text,))
 return __hash__

def f61():
 def __hash__(self):
  return hash((self.ia,self.ib,self.s,self.e,self.ccw,self.full,self.centre,self.r_signed,self.r2_lo,self.r2_hi,self.start,self.end,))
 return __hash__

def f62():
 def __hash__(self):
  return hash((self.key,self.group,self.lanes,))
 return __hash__

def f63():
 def __hash__(self):
  return hash((self.key,self.meaning,self.read,))
 return __hash__

def f64():
 def __hash__(self):
  return hash((self.kind,self.start,self.end,self.axes,self.block,self.span,self.tool_length,self.feed_mm_min,self.plane,self.clockwise,self.centre,self.radius,self.turns,self.dwell_s,self.derived,self.tool_register,self.deps_start,self.deps_end,self.deps_tool,self.extra,))
 return __hash__

def f65():
 def __hash__(self):
  return hash((self.label,self.keyword,self.args,self.column,self.end_column,))
 return __hash__

def f66():
 def __hash__(self):
  return hash((self.lane,self.g,self.m,))
 return __hash__

def f67():
 def __hash__(self):
  return hash((self.linear_axis,self.rotary_axis,self.cylinder_radius,))
 return __hash__

def f68():
 def __hash__(self):
  return hash((self.lo,self.hi,))
 return __hash__

def f69():
 def __hash__(self):
  return hash((self.lo,self.hi,self.lo_closed,self.hi_closed,))
 return __hash__

def f70():
 def __hash__(self):
  return hash((self.margin,self.params,self.engine,self.max_violations,self.arc_tolerance,self.recovery,self.max_iterations,self.dialect,self.library,self.block_delete,self.budget_s,self.tool_table,self.tool_table_units,self.tool_table_x_offset,))
 return __hash__

def f71():
 def __hash__(self):
  return hash((self.message,self.span,self.block,self.code,))
 return __hash__

def f72():
 def __hash__(self):
  return hash((self.missing,self.on_fallback,))
 return __hash__

def f73():
 def __hash__(self):
  return hash((self.name,self.limits,self.forbid,self.point,))
 return __hash__

def f74():
 def __hash__(self):
  return hash((self.name,self.lo,self.hi,self.written,self.absolute,self.lo_open,self.hi_open,self.centre,))
 return __hash__

def f75():
 def __hash__(self):
  return hash((self.name,self.max_passes,self.spent,))
 return __hash__

def f76():
 def __hash__(self):
  return hash((self.name,self.plane,self.vertices,self.limits,self.forbid,self.point,))
 return __hash__

def f77():
 def __hash__(self):
  return hash((self.name,self.pulse,self.rapid_mm_min,self.max_feed_mm_min,self.rotary,self.accel_mm_s2,))
 return __hash__

def f78():
 def __hash__(self):
  return hash((self.name,self.reference_axis,self.limited_axis,self.start,self.regions,self.forbid,self.point,))
 return __hash__

def f79():
 def __hash__(self):
  return hash((self.name,self.units,self.axes,self.rapid_mode,self.monitor_period_ms,self.reference,self.start,self.offsets,self.tool_lengths,self.allowed,self.modal,self.tool_axis,self.source,self.warnings,self.sections,self.cutter_compensation,self.tool_diameters,self.sha256,self.dialect,self.fanuc,self.block_delete,self.arc_tolerance,self.path_mode,self.path_tolerance,self.machine_type,self.diameter_axes,self.tool_offsets,self.tool_length_wear,self.tool_radius_wear,self.control_units,self.tool_change_quill_up,self.tool_change_at_g30,self.tool_change_position,self.subroutine_path,))
 return __hash__

def f80():
 def __hash__(self):
  return hash((self.number,))
 return __hash__

def f81():
 def __hash__(self):
  return hash((self.number,self.geometry,self.wear,self.nose_radius,self.wear_radius,self.tip,))
 return __hash__

def f82():
 def __hash__(self):
  return hash((self.offsets,))
 return __hash__

def f83():
 def __hash__(self):
  return hash((self.p0,self.p1,self.tau0,self.tau1,))
 return __hash__

def f84():
 def __hash__(self):
  return hash((self.start,self.end,self.turns,self.x_off,self.c_entry,self.linear_axis,self.rotary_axis,self.grid,self.arc,self.centre,self.radius,))
 return __hash__

def f85():
 def __hash__(self):
  return hash((self.status,self.values,self.approximate,self.stopped,))
 return __hash__

def f86():
 def __hash__(self):
  return hash((self.summary,self.configure,))
 return __hash__

def f87():
 def __hash__(self):
  return hash((self.text,self.name,self.digest,self.path,self.notes,))
 return __hash__

def f88():
 def __hash__(self):
  return hash((self.upto,self.min,self.max,))
 return __hash__

def f89():
 def __hash__(self):
  return hash((self.value,self.deps,))
 return __hash__

def f90():
 def __hash__(self):
  return hash((self.verdict,self.violations,self.reasons,self.engines,self.solver,self.solver_version,self.timings,self.notes,self.stats,self.margin,self.params,self.engine,self.truncated,self.file,self.program_digest,self.machine_name,self.machine_file,self.machine_sha256,self.settings,self.interrupted,self.budget_s,))
 return __hash__

def f91():
 def __hash__(self):
  return hash((self.work,self.offset,self.rotation,self.diameter,self.inch,self.opaque,self.work_offset,))
 return __hash__

def f92():
 def __hash__(self):
  return hash((self.zones,self.tool_axis,))
 return __hash__

def f93():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(axes={self.axes!r}, columns={self.columns!r}, offset_bound={self.offset_bound!r}, motions={self.motions!r}, lines={self.lines!r}, rapids={self.rapids!r}, blocks={self.blocks!r}, start={self.start!r}, first_row={self.first_row!r}, row0={self.row0!r}, arcs={self.arcs!r}, arc_rows={self.arc_rows!r}, arc_axes={self.arc_axes!r}, arc_boxes={self.arc_boxes!r}, arc_more={self.arc_more!r}, dwells={self.dwells!r}, dwell_rows={self.dwell_rows!r}, modes={self.modes!r}, inc_bound={self.inc_bound!r}, assumed={self.assumed!r}, tolerance={self.tolerance!r}, arc_planes={self.arc_planes!r})"
 return __repr__

def f94():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(axes={self.axes!r}, degrees={self.degrees!r}, cos={self.cos!r}, sin={self.sin!r}, before={self.before!r}, after={self.after!r})"
 return __repr__

def f95():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(axes={self.axes!r}, scale={self.scale!r}, kind={self.kind!r}, start={self.start!r}, end={self.end!r}, line={self.line!r}, block={self.block!r}, tool_length={self.tool_length!r}, centre={self.centre!r}, plane={self.plane!r}, clockwise={self.clockwise!r}, turns={self.turns!r}, feed={self.feed!r}, file={self.file!r}, objects={self.objects!r}, dwell={self.dwell!r}, derived={self.derived!r}, frame={self.frame!r}, radius={self.radius!r}, tool_register={self.tool_register!r}, tools_known={self.tools_known!r})"
 return __repr__

def f96():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(blend={self.blend!r}, tolerance={self.tolerance!r}, naive={self.naive!r}, dialect={self.dialect!r}, code={self.code!r})"
 return __repr__

def f97():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(block={self.block!r}, span={self.span!r}, zone={self.zone!r}, point={self.point!r}, path_point={self.path_point!r}, parameter={self.parameter!r}, parameter_exact={self.parameter_exact!r}, first_exit={self.first_exit!r}, first_exit_parameter={self.first_exit_parameter!r}, first_exit_exact={self.first_exit_exact!r}, depth={self.depth!r}, depth_exact={self.depth_exact!r}, engine={self.engine!r}, segment_kind={self.segment_kind!r}, derived={self.derived!r}, kind={self.kind!r}, params={self.params!r}, zones={self.zones!r}, note={self.note!r}, on_path={self.on_path!r}, break_line={self.break_line!r}, break_parameter={self.break_parameter!r}, break_point={self.break_point!r}, leg={self.leg!r}, switches={self.switches!r}, exit_located={self.exit_located!r}, frame={self.frame!r})"
 return __repr__

def f98():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(code={self.code!r}, message={self.message!r}, span={self.span!r}, severity={self.severity!r}, file={self.file!r})"
 return __repr__

def f99():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(code={self.code!r}, reason={self.reason!r}, span={self.span!r})"
 return __repr__

def f100():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(decimal_point_input={self.decimal_point_input!r}, increment_system={self.increment_system!r}, g73_retract={self.g73_retract!r}, g83_clearance={self.g83_clearance!r}, boring_shift={self.boring_shift!r}, scaling_unit={self.scaling_unit!r}, rotation_incremental={self.rotation_incremental!r}, atan_signed={self.atan_signed!r}, tool_length_motion={self.tool_length_motion!r}, harmless_m={self.harmless_m!r}, references={self.references!r}, variables={self.variables!r}, macros={self.macros!r}, gcode_system={self.gcode_system!r}, g71_depth={self.g71_depth!r}, g71_retract={self.g71_retract!r}, roughing_final_pass={self.roughing_final_pass!r}, g73_relief_x={self.g73_relief_x!r}, g73_relief_z={self.g73_relief_z!r}, g73_divisions={self.g73_divisions!r}, g74_retract={self.g74_retract!r}, thread_chamfer={self.thread_chamfer!r}, thread_chamfer_angle={self.thread_chamfer_angle!r}, g76_finish_passes={self.g76_finish_passes!r}, g76_tool_angle={self.g76_tool_angle!r}, g76_min_depth={self.g76_min_depth!r}, g76_finish_allowance={self.g76_finish_allowance!r}, tool_offset_motion={self.tool_offset_motion!r}, tool_offset_cancel={self.tool_offset_cancel!r}, path={self.path!r})"
 return __repr__

def f101():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(degree={self.degree!r}, knots={self.knots!r}, control={self.control!r}, weights={self.weights!r}, source={self.source!r})"
 return __repr__

def f102():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(delete={self.delete!r}, number={self.number!r}, oword={self.oword!r}, words={self.words!r}, assigns={self.assigns!r}, comments={self.comments!r}, percent={self.percent!r}, unsupported={self.unsupported!r})"
 return __repr__

def f103():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(delete={self.delete!r}, number={self.number!r}, program={self.program!r}, words={self.words!r}, assigns={self.assigns!r}, comments={self.comments!r}, stmt={self.stmt!r}, stmt_at={self.stmt_at!r}, percent={self.percent!r}, unmodelled={self.unmodelled!r})"
 return __repr__

def f104():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(file={self.file!r}, line={self.line!r}, column={self.column!r}, end_column={self.end_column!r}, text={self.text!r})"
 return __repr__

def f105():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(ia={self.ia!r}, ib={self.ib!r}, s={self.s!r}, e={self.e!r}, ccw={self.ccw!r}, full={self.full!r}, centre={self.centre!r}, r_signed={self.r_signed!r}, r2_lo={self.r2_lo!r}, r2_hi={self.r2_hi!r}, start={self.start!r}, end={self.end!r})"
 return __repr__

def f106():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(key={self.key!r}, group={self.group!r}, lanes={self.lanes!r})"
 return __repr__

def f107():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(key={self.key!r}, meaning={self.meaning!r}, read={self.read!r})"
 return __repr__

def f108():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(kind={self.kind!r}, label={self.label!r}, head={self.head!r}, remaining={self.remaining!r}, count={self.count!r}, ifs={self.ifs!r})"
 return __repr__

def f109():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(kind={self.kind!r}, label={self.label!r}, ret={self.ret!r}, saved={self.saved!r}, body={self.body!r}, repeats={self.repeats!r}, loops={self.loops!r}, ifs={self.ifs!r}, caller={self.caller!r})"
 return __repr__

def f110():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(kind={self.kind!r}, source={self.source!r}, program={self.program!r}, ret={self.ret!r}, body={self.body!r}, repeats={self.repeats!r}, saved={self.saved!r}, args={self.args!r}, loops={self.loops!r}, custom={self.custom!r})"
 return __repr__

def f111():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(kind={self.kind!r}, start={self.start!r}, end={self.end!r}, axes={self.axes!r}, block={self.block!r}, span={self.span!r}, tool_length={self.tool_length!r}, feed_mm_min={self.feed_mm_min!r}, plane={self.plane!r}, clockwise={self.clockwise!r}, centre={self.centre!r}, radius={self.radius!r}, turns={self.turns!r}, dwell_s={self.dwell_s!r}, derived={self.derived!r}, tool_register={self.tool_register!r}, deps_start={self.deps_start!r}, deps_end={self.deps_end!r}, deps_tool={self.deps_tool!r}, extra={self.extra!r}, frame={self.frame!r})"
 return __repr__

def f112():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(label={self.label!r}, keyword={self.keyword!r}, args={self.args!r}, column={self.column!r}, end_column={self.end_column!r})"
 return __repr__

def f113():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(lane={self.lane!r}, g={self.g!r}, m={self.m!r})"
 return __repr__

def f114():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(letter={self.letter!r}, value={self.value!r}, span={self.span!r}, text={self.text!r})"
 return __repr__

def f115():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(linear_axis={self.linear_axis!r}, rotary_axis={self.rotary_axis!r}, cylinder_radius={self.cylinder_radius!r})"
 return __repr__

def f116():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(lo={self.lo!r}, hi={self.hi!r})"
 return __repr__

def f117():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(lo={self.lo!r}, hi={self.hi!r}, lo_closed={self.lo_closed!r}, hi_closed={self.hi_closed!r})"
 return __repr__

def f118():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(m={self.m!r}, head={self.head!r}, count={self.count!r})"
 return __repr__

def f119():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(margin={self.margin!r}, params={self.params!r}, engine={self.engine!r}, max_violations={self.max_violations!r}, arc_tolerance={self.arc_tolerance!r}, recovery={self.recovery!r}, max_iterations={self.max_iterations!r}, dialect={self.dialect!r}, library={self.library!r}, block_delete={self.block_delete!r}, budget_s={self.budget_s!r}, limits={self.limits!r}, tool_table={self.tool_table!r}, tool_table_units={self.tool_table_units!r}, tool_table_x_offset={self.tool_table_x_offset!r})"
 return __repr__

def f120():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(message={self.message!r}, span={self.span!r}, block={self.block!r}, code={self.code!r})"
 return __repr__

def f121():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(missing={self.missing!r}, on_fallback={self.on_fallback!r})"
 return __repr__

def f122():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(name={self.name!r}, limits={self.limits!r}, forbid={self.forbid!r}, point={self.point!r})"
 return __repr__

def f123():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(name={self.name!r}, lo={self.lo!r}, hi={self.hi!r}, written={self.written!r}, absolute={self.absolute!r}, lo_open={self.lo_open!r}, hi_open={self.hi_open!r}, centre={self.centre!r})"
 return __repr__

def f124():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(name={self.name!r}, max_passes={self.max_passes!r}, spent={self.spent!r})"
 return __repr__

def f125():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(name={self.name!r}, plane={self.plane!r}, vertices={self.vertices!r}, limits={self.limits!r}, forbid={self.forbid!r}, point={self.point!r})"
 return __repr__

def f126():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(name={self.name!r}, pulse={self.pulse!r}, rapid_mm_min={self.rapid_mm_min!r}, max_feed_mm_min={self.max_feed_mm_min!r}, rotary={self.rotary!r}, accel_mm_s2={self.accel_mm_s2!r})"
 return __repr__

def f127():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(name={self.name!r}, reference_axis={self.reference_axis!r}, limited_axis={self.limited_axis!r}, start={self.start!r}, regions={self.regions!r}, forbid={self.forbid!r}, point={self.point!r})"
 return __repr__

def f128():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(name={self.name!r}, units={self.units!r}, axes={self.axes!r}, rapid_mode={self.rapid_mode!r}, monitor_period_ms={self.monitor_period_ms!r}, reference={self.reference!r}, start={self.start!r}, offsets={self.offsets!r}, tool_lengths={self.tool_lengths!r}, allowed={self.allowed!r}, modal={self.modal!r}, tool_axis={self.tool_axis!r}, source={self.source!r}, warnings={self.warnings!r}, sections={self.sections!r}, cutter_compensation={self.cutter_compensation!r}, tool_diameters={self.tool_diameters!r}, sha256={self.sha256!r}, dialect={self.dialect!r}, fanuc={self.fanuc!r}, block_delete={self.block_delete!r}, arc_tolerance={self.arc_tolerance!r}, path_mode={self.path_mode!r}, path_tolerance={self.path_tolerance!r}, machine_type={self.machine_type!r}, diameter_axes={self.diameter_axes!r}, tool_offsets={self.tool_offsets!r}, tool_length_wear={self.tool_length_wear!r}, tool_radius_wear={self.tool_radius_wear!r}, control_units={self.control_units!r}, tool_change_quill_up={self.tool_change_quill_up!r}, tool_change_at_g30={self.tool_change_at_g30!r}, tool_change_position={self.tool_change_position!r}, subroutine_path={self.subroutine_path!r})"
 return __repr__

def f129():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(number={self.number!r})"
 return __repr__

def f130():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(number={self.number!r}, geometry={self.geometry!r}, wear={self.wear!r}, nose_radius={self.nose_radius!r}, wear_radius={self.wear_radius!r}, tip={self.tip!r})"
 return __repr__

def f131():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(offsets={self.offsets!r})"
 return __repr__

def f132():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(p0={self.p0!r}, p1={self.p1!r}, tau0={self.tau0!r}, tau1={self.tau1!r})"
 return __repr__

def f133():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(start={self.start!r}, end={self.end!r}, turns={self.turns!r}, x_off={self.x_off!r}, c_entry={self.c_entry!r}, linear_axis={self.linear_axis!r}, rotary_axis={self.rotary_axis!r}, grid={self.grid!r}, arc={self.arc!r}, centre={self.centre!r}, radius={self.radius!r})"
 return __repr__

def f134():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(status={self.status!r}, values={self.values!r}, approximate={self.approximate!r}, stopped={self.stopped!r})"
 return __repr__

def f135():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(summary={self.summary!r}, configure={self.configure!r})"
 return __repr__

def f136():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(text={self.text!r}, name={self.name!r}, digest={self.digest!r}, path={self.path!r}, notes={self.notes!r})"
 return __repr__

def f137():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(upto={self.upto!r}, min={self.min!r}, max={self.max!r})"
 return __repr__

def f138():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(value={self.value!r}, deps={self.deps!r})"
 return __repr__

def f139():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(verdict={self.verdict!r}, violations={self.violations!r}, reasons={self.reasons!r}, engines={self.engines!r}, solver={self.solver!r}, solver_version={self.solver_version!r}, timings={self.timings!r}, notes={self.notes!r}, stats={self.stats!r}, margin={self.margin!r}, params={self.params!r}, engine={self.engine!r}, truncated={self.truncated!r}, file={self.file!r}, extra={self.extra!r}, program_digest={self.program_digest!r}, machine_name={self.machine_name!r}, machine_file={self.machine_file!r}, machine_sha256={self.machine_sha256!r}, settings={self.settings!r}, interrupted={self.interrupted!r}, budget_s={self.budget_s!r}, profile={self.profile!r})"
 return __repr__

def f140():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(violation={self.violation!r}, reason={self.reason!r}, engine={self.engine!r})"
 return __repr__

def f141():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(words={self.words!r}, span={self.span!r}, index={self.index!r}, number={self.number!r}, messages={self.messages!r})"
 return __repr__

def f142():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(words={self.words!r}, span={self.span!r}, index={self.index!r}, number={self.number!r}, messages={self.messages!r}, shape={self.shape!r})"
 return __repr__

def f143():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(work={self.work!r}, offset={self.offset!r}, rotation={self.rotation!r}, diameter={self.diameter!r}, inch={self.inch!r}, opaque={self.opaque!r}, work_offset={self.work_offset!r})"
 return __repr__

def f144():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(zones={self.zones!r}, tool_axis={self.tool_axis!r})"
 return __repr__

def f145():
 def make(delete,number,words,assigns):
  o = _new(_draft)
  o.delete = delete
  o.number = number
  o.words = words
  o.assigns = assigns
  o.oword = _c_oword
  o.comments = _c_comments
  o.percent = _c_percent
  o.unsupported = _c_unsupported
  o.__class__ = _cls
  return o
 return make

def f146():
 def make(file,line,column,end_column,text):
  o = _new(_draft)
  o.file = file
  o.line = line
  o.column = column
  o.end_column = end_column
  o.text = text
  o.__class__ = _cls
  return o
 return make

def f147():
 def make(kind,start,end,axes,block,span,tool_length,feed_mm_min,plane,clockwise,centre,radius,turns,dwell_s,derived,tool_register,deps_start,deps_end,extra,frame):
  o = _new(_draft)
  o.kind = kind
  o.start = start
  o.end = end
  o.axes = axes
  o.block = block
  o.span = span
  o.tool_length = tool_length
  o.feed_mm_min = feed_mm_min
  o.plane = plane
  o.clockwise = clockwise
  o.centre = centre
  o.radius = radius
  o.turns = turns
  o.dwell_s = dwell_s
  o.derived = derived
  o.tool_register = tool_register
  o.deps_start = deps_start
  o.deps_end = deps_end
  o.extra = extra
  o.frame = frame
  o.deps_tool = _c_deps_tool
  o.__class__ = _cls
  return o
 return make

def f148():
 def make(letter,value,span,text):
  o = _new(_draft)
  o.letter = letter
  o.value = value
  o.span = span
  o.text = text
  o.__class__ = _cls
  return o
 return make

def f149(_type_axes, _type_columns, _type_offset_bound, _type_motions, _type_lines, _type_rapids, _type_blocks, _type_start, _type_first_row, _type_row0, _type_arcs, _type_arc_rows, _type_arc_axes, _type_arc_boxes, _type_arc_more, _type_dwells, _type_dwell_rows, _type_modes, _type_inc_bound, _type_assumed, _type_tolerance, _type_arc_planes, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_row0, _dflt_arcs, _dflt_arc_rows, _dflt_arc_axes, _dflt_arc_boxes, _dflt_arc_more, _dflt_dwells, _dflt_dwell_rows, _dflt_modes, _dflt_inc_bound, _dflt_assumed, _dflt_tolerance, _dflt_arc_planes, _return_type):
 def __init__(self,axes:_type_axes,columns:_type_columns,offset_bound:_type_offset_bound,motions:_type_motions,lines:_type_lines,rapids:_type_rapids,blocks:_type_blocks,start:_type_start,first_row:_type_first_row,row0:_type_row0=_dflt_row0,arcs:_type_arcs=_dflt_arcs,arc_rows:_type_arc_rows=_dflt_arc_rows,arc_axes:_type_arc_axes=_dflt_arc_axes,arc_boxes:_type_arc_boxes=_dflt_arc_boxes,arc_more:_type_arc_more=_dflt_arc_more,dwells:_type_dwells=_dflt_dwells,dwell_rows:_type_dwell_rows=_dflt_dwell_rows,modes:_type_modes=_dflt_modes,inc_bound:_type_inc_bound=_dflt_inc_bound,assumed:_type_assumed=_dflt_assumed,tolerance:_type_tolerance=_dflt_tolerance,arc_planes:_type_arc_planes=_dflt_arc_planes)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'axes',axes)
  __dataclass_builtins_object__.__setattr__(self,'columns',columns)
  __dataclass_builtins_object__.__setattr__(self,'offset_bound',offset_bound)
  __dataclass_builtins_object__.__setattr__(self,'motions',motions)
  __dataclass_builtins_object__.__setattr__(self,'lines',lines)
  __dataclass_builtins_object__.__setattr__(self,'rapids',rapids)
  __dataclass_builtins_object__.__setattr__(self,'blocks',blocks)
  __dataclass_builtins_object__.__setattr__(self,'start',start)
  __dataclass_builtins_object__.__setattr__(self,'first_row',first_row)
  __dataclass_builtins_object__.__setattr__(self,'row0',row0)
  __dataclass_builtins_object__.__setattr__(self,'arcs',arcs)
  __dataclass_builtins_object__.__setattr__(self,'arc_rows',arc_rows)
  __dataclass_builtins_object__.__setattr__(self,'arc_axes',arc_axes)
  __dataclass_builtins_object__.__setattr__(self,'arc_boxes',arc_boxes)
  __dataclass_builtins_object__.__setattr__(self,'arc_more',arc_more)
  __dataclass_builtins_object__.__setattr__(self,'dwells',dwells)
  __dataclass_builtins_object__.__setattr__(self,'dwell_rows',dwell_rows)
  __dataclass_builtins_object__.__setattr__(self,'modes',modes)
  __dataclass_builtins_object__.__setattr__(self,'inc_bound',inc_bound)
  __dataclass_builtins_object__.__setattr__(self,'assumed',assumed)
  __dataclass_builtins_object__.__setattr__(self,'tolerance',tolerance)
  __dataclass_builtins_object__.__setattr__(self,'arc_planes',arc_planes)
 return __init__

def f150(_type_axes, _type_degrees, _type_cos, _type_sin, _type_before, _type_after, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,axes:_type_axes,degrees:_type_degrees,cos:_type_cos,sin:_type_sin,before:_type_before,after:_type_after)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'axes',axes)
  __dataclass_builtins_object__.__setattr__(self,'degrees',degrees)
  __dataclass_builtins_object__.__setattr__(self,'cos',cos)
  __dataclass_builtins_object__.__setattr__(self,'sin',sin)
  __dataclass_builtins_object__.__setattr__(self,'before',before)
  __dataclass_builtins_object__.__setattr__(self,'after',after)
 return __init__

def f151(_type_axes, _type_scale, _type_kind, _type_start, _type_end, _type_line, _type_block, _type_tool_length, _type_centre, _type_plane, _type_clockwise, _type_turns, _type_feed, _type_file, _type_objects, _type_dwell, _type_derived, _type_frame, _type_radius, _type_tool_register, _type_tools_known, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_kind, _dflt_start, _dflt_end, _dflt_line, _dflt_block, _dflt_tool_length, _dflt_centre, _dflt_plane, _dflt_clockwise, _dflt_turns, _dflt_feed, _dflt_file, _dflt_objects, _dflt_dwell, _dflt_derived, _dflt_frame, _dflt_radius, _dflt_tool_register, _dflt_tools_known, _return_type):
 def __init__(self,axes:_type_axes,scale:_type_scale,kind:_type_kind=_dflt_kind,start:_type_start=_dflt_start,end:_type_end=_dflt_end,line:_type_line=_dflt_line,block:_type_block=_dflt_block,tool_length:_type_tool_length=_dflt_tool_length,centre:_type_centre=_dflt_centre,plane:_type_plane=_dflt_plane,clockwise:_type_clockwise=_dflt_clockwise,turns:_type_turns=_dflt_turns,feed:_type_feed=_dflt_feed,file:_type_file=_dflt_file,objects:_type_objects=_dflt_objects,dwell:_type_dwell=_dflt_dwell,derived:_type_derived=_dflt_derived,frame:_type_frame=_dflt_frame,radius:_type_radius=_dflt_radius,tool_register:_type_tool_register=_dflt_tool_register,tools_known:_type_tools_known=_dflt_tools_known)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'axes',axes)
  __dataclass_builtins_object__.__setattr__(self,'scale',scale)
  __dataclass_builtins_object__.__setattr__(self,'kind',kind)
  __dataclass_builtins_object__.__setattr__(self,'start',start)
  __dataclass_builtins_object__.__setattr__(self,'end',end)
  __dataclass_builtins_object__.__setattr__(self,'line',line)
  __dataclass_builtins_object__.__setattr__(self,'block',block)
  __dataclass_builtins_object__.__setattr__(self,'tool_length',tool_length)
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
  __dataclass_builtins_object__.__setattr__(self,'plane',plane)
  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)
  __dataclass_builtins_object__.__setattr__(self,'turns',turns)
  __dataclass_builtins_object__.__setattr__(self,'feed',feed)
  __dataclass_builtins_object__.__setattr__(self,'file',file)
  __dataclass_builtins_object__.__setattr__(self,'objects',objects)
  __dataclass_builtins_object__.__setattr__(self,'dwell',dwell)
  __dataclass_builtins_object__.__setattr__(self,'derived',derived)
  __dataclass_builtins_object__.__setattr__(self,'frame',frame)
  __dataclass_builtins_object__.__setattr__(self,'radius',radius)
  __dataclass_builtins_object__.__setattr__(self,'tool_register',tool_register)
  __dataclass_builtins_object__.__setattr__(self,'tools_known',tools_known)
 return __init__

def f152(_type_blend, _type_tolerance, _type_naive, _type_dialect, _type_code, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_tolerance, _dflt_naive, _dflt_dialect, _dflt_code, _return_type):
 def __init__(self,blend:_type_blend,tolerance:_type_tolerance=_dflt_tolerance,naive:_type_naive=_dflt_naive,dialect:_type_dialect=_dflt_dialect,code:_type_code=_dflt_code)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'blend',blend)
  __dataclass_builtins_object__.__setattr__(self,'tolerance',tolerance)
  __dataclass_builtins_object__.__setattr__(self,'naive',naive)
  __dataclass_builtins_object__.__setattr__(self,'dialect',dialect)
  __dataclass_builtins_object__.__setattr__(self,'code',code)
 return __init__

def f153(_type_block, _type_span, _type_zone, _type_point, _type_path_point, _type_parameter, _type_parameter_exact, _type_first_exit, _type_first_exit_parameter, _type_first_exit_exact, _type_depth, _type_depth_exact, _type_engine, _type_segment_kind, _type_derived, _type_kind, _type_params, _type_zones, _type_note, _type_on_path, _type_break_line, _type_break_parameter, _type_break_point, _type_leg, _type_switches, _type_exit_located, _type_frame, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_derived, _dflt_kind, _dflt_params, _dflt_zones, _dflt_note, _dflt_on_path, _dflt_break_line, _dflt_break_parameter, _dflt_break_point, _dflt_leg, _dflt_switches, _dflt_exit_located, _dflt_frame, _return_type):
 def __init__(self,block:_type_block,span:_type_span,zone:_type_zone,point:_type_point,path_point:_type_path_point,parameter:_type_parameter,parameter_exact:_type_parameter_exact,first_exit:_type_first_exit,first_exit_parameter:_type_first_exit_parameter,first_exit_exact:_type_first_exit_exact,depth:_type_depth,depth_exact:_type_depth_exact,engine:_type_engine,segment_kind:_type_segment_kind,derived:_type_derived=_dflt_derived,kind:_type_kind=_dflt_kind,params:_type_params=_dflt_params,zones:_type_zones=_dflt_zones,note:_type_note=_dflt_note,on_path:_type_on_path=_dflt_on_path,break_line:_type_break_line=_dflt_break_line,break_parameter:_type_break_parameter=_dflt_break_parameter,break_point:_type_break_point=_dflt_break_point,leg:_type_leg=_dflt_leg,switches:_type_switches=_dflt_switches,exit_located:_type_exit_located=_dflt_exit_located,frame:_type_frame=_dflt_frame)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'block',block)
  __dataclass_builtins_object__.__setattr__(self,'span',span)
  __dataclass_builtins_object__.__setattr__(self,'zone',zone)
  __dataclass_builtins_object__.__setattr__(self,'point',point)
  __dataclass_builtins_object__.__setattr__(self,'path_point',path_point)
  __dataclass_builtins_object__.__setattr__(self,'parameter',parameter)
  __dataclass_builtins_object__.__setattr__(self,'parameter_exact',parameter_exact)
  __dataclass_builtins_object__.__setattr__(self,'first_exit',first_exit)
  __dataclass_builtins_object__.__setattr__(self,'first_exit_parameter',first_exit_parameter)
  __dataclass_builtins_object__.__setattr__(self,'first_exit_exact',first_exit_exact)
  __dataclass_builtins_object__.__setattr__(self,'depth',depth)
  __dataclass_builtins_object__.__setattr__(self,'depth_exact',depth_exact)
  __dataclass_builtins_object__.__setattr__(self,'engine',engine)
  __dataclass_builtins_object__.__setattr__(self,'segment_kind',segment_kind)
  __dataclass_builtins_object__.__setattr__(self,'derived',derived)
  __dataclass_builtins_object__.__setattr__(self,'kind',kind)
  __dataclass_builtins_object__.__setattr__(self,'params',params)
  __dataclass_builtins_object__.__setattr__(self,'zones',zones)
  __dataclass_builtins_object__.__setattr__(self,'note',note)
  __dataclass_builtins_object__.__setattr__(self,'on_path',on_path)
  __dataclass_builtins_object__.__setattr__(self,'break_line',break_line)
  __dataclass_builtins_object__.__setattr__(self,'break_parameter',break_parameter)
  __dataclass_builtins_object__.__setattr__(self,'break_point',break_point)
  __dataclass_builtins_object__.__setattr__(self,'leg',leg)
  __dataclass_builtins_object__.__setattr__(self,'switches',switches)
  __dataclass_builtins_object__.__setattr__(self,'exit_located',exit_located)
  __dataclass_builtins_object__.__setattr__(self,'frame',frame)
 return __init__

def f154(_type_code, _type_message, _type_span, _type_severity, _type_file, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_span, _dflt_severity, _dflt_file, _return_type):
 def __init__(self,code:_type_code,message:_type_message,span:_type_span=_dflt_span,severity:_type_severity=_dflt_severity,file:_type_file=_dflt_file)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'code',code)
  __dataclass_builtins_object__.__setattr__(self,'message',message)
  __dataclass_builtins_object__.__setattr__(self,'span',span)
  __dataclass_builtins_object__.__setattr__(self,'severity',severity)
  __dataclass_builtins_object__.__setattr__(self,'file',file)
 return __init__

def f155(_type_code, _type_reason, _type_span, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,code:_type_code,reason:_type_reason,span:_type_span)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'code',code)
  __dataclass_builtins_object__.__setattr__(self,'reason',reason)
  __dataclass_builtins_object__.__setattr__(self,'span',span)
 return __init__

def f156(_type_decimal_point_input, _type_increment_system, _type_g73_retract, _type_g83_clearance, _type_boring_shift, _type_scaling_unit, _type_rotation_incremental, _type_atan_signed, _type_tool_length_motion, _type_harmless_m, _type_references, _type_variables, _type_macros, _type_gcode_system, _type_g71_depth, _type_g71_retract, _type_roughing_final_pass, _type_g73_relief_x, _type_g73_relief_z, _type_g73_divisions, _type_g74_retract, _type_thread_chamfer, _type_thread_chamfer_angle, _type_g76_finish_passes, _type_g76_tool_angle, _type_g76_min_depth, _type_g76_finish_allowance, _type_tool_offset_motion, _type_tool_offset_cancel, _type_path, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_decimal_point_input, _dflt_increment_system, _dflt_g73_retract, _dflt_g83_clearance, _dflt_boring_shift, _dflt_scaling_unit, _dflt_rotation_incremental, _dflt_atan_signed, _dflt_tool_length_motion, _dflt_harmless_m, _dflt_references, _dflt_variables, _dflt_macros, _dflt_gcode_system, _dflt_g71_depth, _dflt_g71_retract, _dflt_roughing_final_pass, _dflt_g73_relief_x, _dflt_g73_relief_z, _dflt_g73_divisions, _dflt_g74_retract, _dflt_thread_chamfer, _dflt_thread_chamfer_angle, _dflt_g76_finish_passes, _dflt_g76_tool_angle, _dflt_g76_min_depth, _dflt_g76_finish_allowance, _dflt_tool_offset_motion, _dflt_tool_offset_cancel, _dflt_path, _return_type):
 def __init__(self,decimal_point_input:_type_decimal_point_input=_dflt_decimal_point_input,increment_system:_type_increment_system=_dflt_increment_system,g73_retract:_type_g73_retract=_dflt_g73_retract,g83_clearance:_type_g83_clearance=_dflt_g83_clearance,boring_shift:_type_boring_shift=_dflt_boring_shift,scaling_unit:_type_scaling_unit=_dflt_scaling_unit,rotation_incremental:_type_rotation_incremental=_dflt_rotation_incremental,atan_signed:_type_atan_signed=_dflt_atan_signed,tool_length_motion:_type_tool_length_motion=_dflt_tool_length_motion,harmless_m:_type_harmless_m=_dflt_harmless_m,references:_type_references=_HAS_DEFAULT_FACTORY,variables:_type_variables=_HAS_DEFAULT_FACTORY,macros:_type_macros=_HAS_DEFAULT_FACTORY,gcode_system:_type_gcode_system=_dflt_gcode_system,g71_depth:_type_g71_depth=_dflt_g71_depth,g71_retract:_type_g71_retract=_dflt_g71_retract,roughing_final_pass:_type_roughing_final_pass=_dflt_roughing_final_pass,g73_relief_x:_type_g73_relief_x=_dflt_g73_relief_x,g73_relief_z:_type_g73_relief_z=_dflt_g73_relief_z,g73_divisions:_type_g73_divisions=_dflt_g73_divisions,g74_retract:_type_g74_retract=_dflt_g74_retract,thread_chamfer:_type_thread_chamfer=_dflt_thread_chamfer,thread_chamfer_angle:_type_thread_chamfer_angle=_dflt_thread_chamfer_angle,g76_finish_passes:_type_g76_finish_passes=_dflt_g76_finish_passes,g76_tool_angle:_type_g76_tool_angle=_dflt_g76_tool_angle,g76_min_depth:_type_g76_min_depth=_dflt_g76_min_depth,g76_finish_allowance:_type_g76_finish_allowance=_dflt_g76_finish_allowance,tool_offset_motion:_type_tool_offset_motion=_dflt_tool_offset_motion,tool_offset_cancel:_type_tool_offset_cancel=_dflt_tool_offset_cancel,path:_type_path=_dflt_path)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'decimal_point_input',decimal_point_input)
  __dataclass_builtins_object__.__setattr__(self,'increment_system',increment_system)
  __dataclass_builtins_object__.__setattr__(self,'g73_retract',g73_retract)
  __dataclass_builtins_object__.__setattr__(self,'g83_clearance',g83_clearance)
  __dataclass_builtins_object__.__setattr__(self,'boring_shift',boring_shift)
  __dataclass_builtins_object__.__setattr__(self,'scaling_unit',scaling_unit)
  __dataclass_builtins_object__.__setattr__(self,'rotation_incremental',rotation_incremental)
  __dataclass_builtins_object__.__setattr__(self,'atan_signed',atan_signed)
  __dataclass_builtins_object__.__setattr__(self,'tool_length_motion',tool_length_motion)
  __dataclass_builtins_object__.__setattr__(self,'harmless_m',harmless_m)
  __dataclass_builtins_object__.__setattr__(self,'references',_dflt_references() if references is _HAS_DEFAULT_FACTORY else references)
  __dataclass_builtins_object__.__setattr__(self,'variables',_dflt_variables() if variables is _HAS_DEFAULT_FACTORY else variables)
  __dataclass_builtins_object__.__setattr__(self,'macros',_dflt_macros() if macros is _HAS_DEFAULT_FACTORY else macros)
  __dataclass_builtins_object__.__setattr__(self,'gcode_system',gcode_system)
  __dataclass_builtins_object__.__setattr__(self,'g71_depth',g71_depth)
  __dataclass_builtins_object__.__setattr__(self,'g71_retract',g71_retract)
  __dataclass_builtins_object__.__setattr__(self,'roughing_final_pass',roughing_final_pass)
  __dataclass_builtins_object__.__setattr__(self,'g73_relief_x',g73_relief_x)
  __dataclass_builtins_object__.__setattr__(self,'g73_relief_z',g73_relief_z)
  __dataclass_builtins_object__.__setattr__(self,'g73_divisions',g73_divisions)
  __dataclass_builtins_object__.__setattr__(self,'g74_retract',g74_retract)
  __dataclass_builtins_object__.__setattr__(self,'thread_chamfer',thread_chamfer)
  __dataclass_builtins_object__.__setattr__(self,'thread_chamfer_angle',thread_chamfer_angle)
  __dataclass_builtins_object__.__setattr__(self,'g76_finish_passes',g76_finish_passes)
  __dataclass_builtins_object__.__setattr__(self,'g76_tool_angle',g76_tool_angle)
  __dataclass_builtins_object__.__setattr__(self,'g76_min_depth',g76_min_depth)
  __dataclass_builtins_object__.__setattr__(self,'g76_finish_allowance',g76_finish_allowance)
  __dataclass_builtins_object__.__setattr__(self,'tool_offset_motion',tool_offset_motion)
  __dataclass_builtins_object__.__setattr__(self,'tool_offset_cancel',tool_offset_cancel)
  __dataclass_builtins_object__.__setattr__(self,'path',path)
 return __init__

def f157(_type_degree, _type_knots, _type_control, _type_weights, _type_source, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_source, _return_type):
 def __init__(self,degree:_type_degree,knots:_type_knots,control:_type_control,weights:_type_weights,source:_type_source=_dflt_source)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'degree',degree)
  __dataclass_builtins_object__.__setattr__(self,'knots',knots)
  __dataclass_builtins_object__.__setattr__(self,'control',control)
  __dataclass_builtins_object__.__setattr__(self,'weights',weights)
  __dataclass_builtins_object__.__setattr__(self,'source',source)
 return __init__

def f158(_type_delete, _type_number, _type_oword, _type_words, _type_assigns, _type_comments, _type_percent, _type_unsupported, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_delete, _dflt_number, _dflt_oword, _dflt_words, _dflt_assigns, _dflt_comments, _dflt_percent, _dflt_unsupported, _return_type):
 def __init__(self,delete:_type_delete=_dflt_delete,number:_type_number=_dflt_number,oword:_type_oword=_dflt_oword,words:_type_words=_dflt_words,assigns:_type_assigns=_dflt_assigns,comments:_type_comments=_dflt_comments,percent:_type_percent=_dflt_percent,unsupported:_type_unsupported=_dflt_unsupported)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'delete',delete)
  __dataclass_builtins_object__.__setattr__(self,'number',number)
  __dataclass_builtins_object__.__setattr__(self,'oword',oword)
  __dataclass_builtins_object__.__setattr__(self,'words',words)
  __dataclass_builtins_object__.__setattr__(self,'assigns',assigns)
  __dataclass_builtins_object__.__setattr__(self,'comments',comments)
  __dataclass_builtins_object__.__setattr__(self,'percent',percent)
  __dataclass_builtins_object__.__setattr__(self,'unsupported',unsupported)
 return __init__

def f159(_type_delete, _type_number, _type_program, _type_words, _type_assigns, _type_comments, _type_stmt, _type_stmt_at, _type_percent, _type_unmodelled, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_delete, _dflt_number, _dflt_program, _dflt_words, _dflt_assigns, _dflt_comments, _dflt_stmt, _dflt_stmt_at, _dflt_percent, _dflt_unmodelled, _return_type):
 def __init__(self,delete:_type_delete=_dflt_delete,number:_type_number=_dflt_number,program:_type_program=_dflt_program,words:_type_words=_dflt_words,assigns:_type_assigns=_dflt_assigns,comments:_type_comments=_dflt_comments,stmt:_type_stmt=_dflt_stmt,stmt_at:_type_stmt_at=_dflt_stmt_at,percent:_type_percent=_dflt_percent,unmodelled:_type_unmodelled=_dflt_unmodelled)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'delete',delete)
  __dataclass_builtins_object__.__setattr__(self,'number',number)
  __dataclass_builtins_object__.__setattr__(self,'program',program)
  __dataclass_builtins_object__.__setattr__(self,'words',words)
  __dataclass_builtins_object__.__setattr__(self,'assigns',assigns)
  __dataclass_builtins_object__.__setattr__(self,'comments',comments)
  __dataclass_builtins_object__.__setattr__(self,'stmt',stmt)
  __dataclass_builtins_object__.__setattr__(self,'stmt_at',stmt_at)
  __dataclass_builtins_object__.__setattr__(self,'percent',percent)
  __dataclass_builtins_object__.__setattr__(self,'unmodelled',unmodelled)
 return __init__

def f160(_type_file, _type_line, _type_column, _type_end_column, _type_text, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_column, _dflt_end_column, _dflt_text, _return_type):
 def __init__(self,file:_type_file,line:_type_line,column:_type_column=_dflt_column,end_column:_type_end_column=_dflt_end_column,text:_type_text=_dflt_text)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'file',file)
  __dataclass_builtins_object__.__setattr__(self,'line',line)
  __dataclass_builtins_object__.__setattr__(self,'column',column)
  __dataclass_builtins_object__.__setattr__(self,'end_column',end_column)
  __dataclass_builtins_object__.__setattr__(self,'text',text)
 return __init__

def f161(_type_ia, _type_ib, _type_s, _type_e, _type_ccw, _type_full, _type_centre, _type_r_signed, _type_r2_lo, _type_r2_hi, _type_start, _type_end, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,ia:_type_ia,ib:_type_ib,s:_type_s,e:_type_e,ccw:_type_ccw,full:_type_full,centre:_type_centre,r_signed:_type_r_signed,r2_lo:_type_r2_lo,r2_hi:_type_r2_hi,start:_type_start,end:_type_end)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'ia',ia)
  __dataclass_builtins_object__.__setattr__(self,'ib',ib)
  __dataclass_builtins_object__.__setattr__(self,'s',s)
  __dataclass_builtins_object__.__setattr__(self,'e',e)
  __dataclass_builtins_object__.__setattr__(self,'ccw',ccw)
  __dataclass_builtins_object__.__setattr__(self,'full',full)
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
  __dataclass_builtins_object__.__setattr__(self,'r_signed',r_signed)
  __dataclass_builtins_object__.__setattr__(self,'r2_lo',r2_lo)
  __dataclass_builtins_object__.__setattr__(self,'r2_hi',r2_hi)
  __dataclass_builtins_object__.__setattr__(self,'start',start)
  __dataclass_builtins_object__.__setattr__(self,'end',end)
 return __init__

def f162(_type_key, _type_group, _type_lanes, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,key:_type_key,group:_type_group,lanes:_type_lanes)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'key',key)
  __dataclass_builtins_object__.__setattr__(self,'group',group)
  __dataclass_builtins_object__.__setattr__(self,'lanes',lanes)
 return __init__

def f163(_type_key, _type_meaning, _type_read, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,key:_type_key,meaning:_type_meaning,read:_type_read)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'key',key)
  __dataclass_builtins_object__.__setattr__(self,'meaning',meaning)
  __dataclass_builtins_object__.__setattr__(self,'read',read)
 return __init__

def f164(_type_kind, _type_label, _type_head, _type_remaining, _type_count, _type_ifs, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_remaining, _dflt_count, _dflt_ifs, _return_type):
 def __init__(self,kind:_type_kind,label:_type_label,head:_type_head,remaining:_type_remaining=_dflt_remaining,count:_type_count=_dflt_count,ifs:_type_ifs=_dflt_ifs)->_return_type:
  self.kind=kind
  self.label=label
  self.head=head
  self.remaining=remaining
  self.count=count
  self.ifs=ifs
 return __init__

def f165(_type_kind, _type_label, _type_ret, _type_saved, _type_body, _type_repeats, _type_loops, _type_ifs, _type_caller, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_label, _dflt_ret, _dflt_saved, _dflt_body, _dflt_repeats, _dflt_loops, _dflt_ifs, _dflt_caller, _return_type):
 def __init__(self,kind:_type_kind,label:_type_label=_dflt_label,ret:_type_ret=_dflt_ret,saved:_type_saved=_dflt_saved,body:_type_body=_dflt_body,repeats:_type_repeats=_dflt_repeats,loops:_type_loops=_HAS_DEFAULT_FACTORY,ifs:_type_ifs=_HAS_DEFAULT_FACTORY,caller:_type_caller=_dflt_caller)->_return_type:
  self.kind=kind
  self.label=label
  self.ret=ret
  self.saved=saved
  self.body=body
  self.repeats=repeats
  self.loops=_dflt_loops() if loops is _HAS_DEFAULT_FACTORY else loops
  self.ifs=_dflt_ifs() if ifs is _HAS_DEFAULT_FACTORY else ifs
  self.caller=caller
 return __init__

def f166(_type_kind, _type_source, _type_program, _type_ret, _type_body, _type_repeats, _type_saved, _type_args, _type_loops, _type_custom, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_program, _dflt_ret, _dflt_body, _dflt_repeats, _dflt_saved, _dflt_args, _dflt_loops, _dflt_custom, _return_type):
 def __init__(self,kind:_type_kind,source:_type_source,program:_type_program=_dflt_program,ret:_type_ret=_dflt_ret,body:_type_body=_dflt_body,repeats:_type_repeats=_dflt_repeats,saved:_type_saved=_dflt_saved,args:_type_args=_dflt_args,loops:_type_loops=_HAS_DEFAULT_FACTORY,custom:_type_custom=_dflt_custom)->_return_type:
  self.kind=kind
  self.source=source
  self.program=program
  self.ret=ret
  self.body=body
  self.repeats=repeats
  self.saved=saved
  self.args=args
  self.loops=_dflt_loops() if loops is _HAS_DEFAULT_FACTORY else loops
  self.custom=custom
 return __init__

def f167(_type_kind, _type_start, _type_end, _type_axes, _type_block, _type_span, _type_tool_length, _type_feed_mm_min, _type_plane, _type_clockwise, _type_centre, _type_radius, _type_turns, _type_dwell_s, _type_derived, _type_tool_register, _type_deps_start, _type_deps_end, _type_deps_tool, _type_extra, _type_frame, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_block, _dflt_span, _dflt_tool_length, _dflt_feed_mm_min, _dflt_plane, _dflt_clockwise, _dflt_centre, _dflt_radius, _dflt_turns, _dflt_dwell_s, _dflt_derived, _dflt_tool_register, _dflt_deps_start, _dflt_deps_end, _dflt_deps_tool, _dflt_extra, _dflt_frame, _return_type):
 def __init__(self,kind:_type_kind,start:_type_start,end:_type_end,axes:_type_axes,block:_type_block=_dflt_block,span:_type_span=_dflt_span,tool_length:_type_tool_length=_dflt_tool_length,feed_mm_min:_type_feed_mm_min=_dflt_feed_mm_min,plane:_type_plane=_dflt_plane,clockwise:_type_clockwise=_dflt_clockwise,centre:_type_centre=_dflt_centre,radius:_type_radius=_dflt_radius,turns:_type_turns=_dflt_turns,dwell_s:_type_dwell_s=_dflt_dwell_s,derived:_type_derived=_dflt_derived,tool_register:_type_tool_register=_dflt_tool_register,deps_start:_type_deps_start=_dflt_deps_start,deps_end:_type_deps_end=_dflt_deps_end,deps_tool:_type_deps_tool=_dflt_deps_tool,extra:_type_extra=_dflt_extra,frame:_type_frame=_dflt_frame)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'kind',kind)
  __dataclass_builtins_object__.__setattr__(self,'start',start)
  __dataclass_builtins_object__.__setattr__(self,'end',end)
  __dataclass_builtins_object__.__setattr__(self,'axes',axes)
  __dataclass_builtins_object__.__setattr__(self,'block',block)
  __dataclass_builtins_object__.__setattr__(self,'span',span)
  __dataclass_builtins_object__.__setattr__(self,'tool_length',tool_length)
  __dataclass_builtins_object__.__setattr__(self,'feed_mm_min',feed_mm_min)
  __dataclass_builtins_object__.__setattr__(self,'plane',plane)
  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
  __dataclass_builtins_object__.__setattr__(self,'radius',radius)
  __dataclass_builtins_object__.__setattr__(self,'turns',turns)
  __dataclass_builtins_object__.__setattr__(self,'dwell_s',dwell_s)
  __dataclass_builtins_object__.__setattr__(self,'derived',derived)
  __dataclass_builtins_object__.__setattr__(self,'tool_register',tool_register)
  __dataclass_builtins_object__.__setattr__(self,'deps_start',deps_start)
  __dataclass_builtins_object__.__setattr__(self,'deps_end',deps_end)
  __dataclass_builtins_object__.__setattr__(self,'deps_tool',deps_tool)
  __dataclass_builtins_object__.__setattr__(self,'extra',extra)
  __dataclass_builtins_object__.__setattr__(self,'frame',frame)
 return __init__

def f168(_type_label, _type_keyword, _type_args, _type_column, _type_end_column, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,label:_type_label,keyword:_type_keyword,args:_type_args,column:_type_column,end_column:_type_end_column)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'label',label)
  __dataclass_builtins_object__.__setattr__(self,'keyword',keyword)
  __dataclass_builtins_object__.__setattr__(self,'args',args)
  __dataclass_builtins_object__.__setattr__(self,'column',column)
  __dataclass_builtins_object__.__setattr__(self,'end_column',end_column)
 return __init__

def f169(_type_lane, _type_g, _type_m, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,lane:_type_lane,g:_type_g,m:_type_m)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'lane',lane)
  __dataclass_builtins_object__.__setattr__(self,'g',g)
  __dataclass_builtins_object__.__setattr__(self,'m',m)
 return __init__

def f170(_type_letter, _type_value, _type_span, _type_text, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_text, _return_type):
 def __init__(self,letter:_type_letter,value:_type_value,span:_type_span,text:_type_text=_dflt_text)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'letter',letter)
  __dataclass_builtins_object__.__setattr__(self,'value',value)
  __dataclass_builtins_object__.__setattr__(self,'span',span)
  __dataclass_builtins_object__.__setattr__(self,'text',text)
 return __init__

def f171(_type_linear_axis, _type_rotary_axis, _type_cylinder_radius, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,linear_axis:_type_linear_axis,rotary_axis:_type_rotary_axis,cylinder_radius:_type_cylinder_radius)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'linear_axis',linear_axis)
  __dataclass_builtins_object__.__setattr__(self,'rotary_axis',rotary_axis)
  __dataclass_builtins_object__.__setattr__(self,'cylinder_radius',cylinder_radius)
 return __init__

def f172(_type_lo, _type_hi, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,lo:_type_lo,hi:_type_hi)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'lo',lo)
  __dataclass_builtins_object__.__setattr__(self,'hi',hi)
 return __init__

def f173(_type_lo, _type_hi, _type_lo_closed, _type_hi_closed, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,lo:_type_lo,hi:_type_hi,lo_closed:_type_lo_closed,hi_closed:_type_hi_closed)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'lo',lo)
  __dataclass_builtins_object__.__setattr__(self,'hi',hi)
  __dataclass_builtins_object__.__setattr__(self,'lo_closed',lo_closed)
  __dataclass_builtins_object__.__setattr__(self,'hi_closed',hi_closed)
 return __init__

def f174(_type_m, _type_head, _type_count, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_count, _return_type):
 def __init__(self,m:_type_m,head:_type_head,count:_type_count=_dflt_count)->_return_type:
  self.m=m
  self.head=head
  self.count=count
 return __init__

def f175(_type_margin, _type_params, _type_engine, _type_max_violations, _type_arc_tolerance, _type_recovery, _type_max_iterations, _type_dialect, _type_library, _type_block_delete, _type_budget_s, _type_limits, _type_tool_table, _type_tool_table_units, _type_tool_table_x_offset, _type_written, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_margin, _dflt_params, _dflt_engine, _dflt_max_violations, _dflt_arc_tolerance, _dflt_recovery, _dflt_max_iterations, _dflt_dialect, _dflt_library, _dflt_block_delete, _dflt_budget_s, _dflt_limits, _dflt_tool_table, _dflt_tool_table_units, _dflt_tool_table_x_offset, _dflt_written, _return_type):
 def __init__(self,margin:_type_margin=_dflt_margin,params:_type_params=_dflt_params,engine:_type_engine=_dflt_engine,max_violations:_type_max_violations=_dflt_max_violations,arc_tolerance:_type_arc_tolerance=_dflt_arc_tolerance,recovery:_type_recovery=_dflt_recovery,max_iterations:_type_max_iterations=_dflt_max_iterations,dialect:_type_dialect=_dflt_dialect,library:_type_library=_dflt_library,block_delete:_type_block_delete=_dflt_block_delete,budget_s:_type_budget_s=_dflt_budget_s,limits:_type_limits=_dflt_limits,tool_table:_type_tool_table=_dflt_tool_table,tool_table_units:_type_tool_table_units=_dflt_tool_table_units,tool_table_x_offset:_type_tool_table_x_offset=_dflt_tool_table_x_offset,written:_type_written=_dflt_written)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'margin',margin)
  __dataclass_builtins_object__.__setattr__(self,'params',params)
  __dataclass_builtins_object__.__setattr__(self,'engine',engine)
  __dataclass_builtins_object__.__setattr__(self,'max_violations',max_violations)
  __dataclass_builtins_object__.__setattr__(self,'arc_tolerance',arc_tolerance)
  __dataclass_builtins_object__.__setattr__(self,'recovery',recovery)
  __dataclass_builtins_object__.__setattr__(self,'max_iterations',max_iterations)
  __dataclass_builtins_object__.__setattr__(self,'dialect',dialect)
  __dataclass_builtins_object__.__setattr__(self,'library',library)
  __dataclass_builtins_object__.__setattr__(self,'block_delete',block_delete)
  __dataclass_builtins_object__.__setattr__(self,'budget_s',budget_s)
  __dataclass_builtins_object__.__setattr__(self,'limits',limits)
  __dataclass_builtins_object__.__setattr__(self,'tool_table',tool_table)
  __dataclass_builtins_object__.__setattr__(self,'tool_table_units',tool_table_units)
  __dataclass_builtins_object__.__setattr__(self,'tool_table_x_offset',tool_table_x_offset)
  __dataclass_builtins_object__.__setattr__(self,'written',written)
 return __init__

def f176(_type_message, _type_span, _type_block, _type_code, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_span, _dflt_block, _dflt_code, _return_type):
 def __init__(self,message:_type_message,span:_type_span=_dflt_span,block:_type_block=_dflt_block,code:_type_code=_dflt_code)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'message',message)
  __dataclass_builtins_object__.__setattr__(self,'span',span)
  __dataclass_builtins_object__.__setattr__(self,'block',block)
  __dataclass_builtins_object__.__setattr__(self,'code',code)
 return __init__

def f177(_type_missing, _type_on_fallback, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,missing:_type_missing,on_fallback:_type_on_fallback)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'missing',missing)
  __dataclass_builtins_object__.__setattr__(self,'on_fallback',on_fallback)
 return __init__

def f178(_type_name, _type_limits, _type_forbid, _type_point, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_forbid, _dflt_point, _return_type):
 def __init__(self,name:_type_name,limits:_type_limits,forbid:_type_forbid=_dflt_forbid,point:_type_point=_dflt_point)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'name',name)
  __dataclass_builtins_object__.__setattr__(self,'limits',limits)
  __dataclass_builtins_object__.__setattr__(self,'forbid',forbid)
  __dataclass_builtins_object__.__setattr__(self,'point',point)
 return __init__

def f179(_type_name, _type_lo, _type_hi, _type_written, _type_absolute, _type_lo_open, _type_hi_open, _type_centre, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_absolute, _dflt_lo_open, _dflt_hi_open, _dflt_centre, _return_type):
 def __init__(self,name:_type_name,lo:_type_lo,hi:_type_hi,written:_type_written,absolute:_type_absolute=_dflt_absolute,lo_open:_type_lo_open=_dflt_lo_open,hi_open:_type_hi_open=_dflt_hi_open,centre:_type_centre=_dflt_centre)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'name',name)
  __dataclass_builtins_object__.__setattr__(self,'lo',lo)
  __dataclass_builtins_object__.__setattr__(self,'hi',hi)
  __dataclass_builtins_object__.__setattr__(self,'written',written)
  __dataclass_builtins_object__.__setattr__(self,'absolute',absolute)
  __dataclass_builtins_object__.__setattr__(self,'lo_open',lo_open)
  __dataclass_builtins_object__.__setattr__(self,'hi_open',hi_open)
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
 return __init__

def f180(_type_name, _type_max_passes, _type_spent, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_spent, _return_type):
 def __init__(self,name:_type_name,max_passes:_type_max_passes,spent:_type_spent=_dflt_spent)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'name',name)
  __dataclass_builtins_object__.__setattr__(self,'max_passes',max_passes)
  __dataclass_builtins_object__.__setattr__(self,'spent',spent)
 return __init__

def f181(_type_name, _type_plane, _type_vertices, _type_limits, _type_forbid, _type_point, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_limits, _dflt_forbid, _dflt_point, _return_type):
 def __init__(self,name:_type_name,plane:_type_plane,vertices:_type_vertices,limits:_type_limits=_dflt_limits,forbid:_type_forbid=_dflt_forbid,point:_type_point=_dflt_point)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'name',name)
  __dataclass_builtins_object__.__setattr__(self,'plane',plane)
  __dataclass_builtins_object__.__setattr__(self,'vertices',vertices)
  __dataclass_builtins_object__.__setattr__(self,'limits',limits)
  __dataclass_builtins_object__.__setattr__(self,'forbid',forbid)
  __dataclass_builtins_object__.__setattr__(self,'point',point)
 return __init__

def f182(_type_name, _type_pulse, _type_rapid_mm_min, _type_max_feed_mm_min, _type_rotary, _type_accel_mm_s2, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_rotary, _dflt_accel_mm_s2, _return_type):
 def __init__(self,name:_type_name,pulse:_type_pulse,rapid_mm_min:_type_rapid_mm_min,max_feed_mm_min:_type_max_feed_mm_min,rotary:_type_rotary=_dflt_rotary,accel_mm_s2:_type_accel_mm_s2=_dflt_accel_mm_s2)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'name',name)
  __dataclass_builtins_object__.__setattr__(self,'pulse',pulse)
  __dataclass_builtins_object__.__setattr__(self,'rapid_mm_min',rapid_mm_min)
  __dataclass_builtins_object__.__setattr__(self,'max_feed_mm_min',max_feed_mm_min)
  __dataclass_builtins_object__.__setattr__(self,'rotary',rotary)
  __dataclass_builtins_object__.__setattr__(self,'accel_mm_s2',accel_mm_s2)
 return __init__

def f183(_type_name, _type_reference_axis, _type_limited_axis, _type_start, _type_regions, _type_forbid, _type_point, _type__steps, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_forbid, _dflt_point, _dflt__steps, _return_type):
 def __init__(self,name:_type_name,reference_axis:_type_reference_axis,limited_axis:_type_limited_axis,start:_type_start,regions:_type_regions,forbid:_type_forbid=_dflt_forbid,point:_type_point=_dflt_point)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'name',name)
  __dataclass_builtins_object__.__setattr__(self,'reference_axis',reference_axis)
  __dataclass_builtins_object__.__setattr__(self,'limited_axis',limited_axis)
  __dataclass_builtins_object__.__setattr__(self,'start',start)
  __dataclass_builtins_object__.__setattr__(self,'regions',regions)
  __dataclass_builtins_object__.__setattr__(self,'forbid',forbid)
  __dataclass_builtins_object__.__setattr__(self,'point',point)
  __dataclass_builtins_object__.__setattr__(self,'_steps',_dflt__steps)
 return __init__

def f184(_type_name, _type_units, _type_axes, _type_rapid_mode, _type_monitor_period_ms, _type_reference, _type_start, _type_offsets, _type_tool_lengths, _type_allowed, _type_modal, _type_tool_axis, _type_source, _type_warnings, _type_sections, _type_cutter_compensation, _type_tool_diameters, _type_sha256, _type_dialect, _type_fanuc, _type_block_delete, _type_arc_tolerance, _type_path_mode, _type_path_tolerance, _type_machine_type, _type_diameter_axes, _type_tool_offsets, _type_tool_length_wear, _type_tool_radius_wear, _type_control_units, _type_tool_change_quill_up, _type_tool_change_at_g30, _type_tool_change_position, _type_subroutine_path, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_modal, _dflt_tool_axis, _dflt_source, _dflt_warnings, _dflt_sections, _dflt_cutter_compensation, _dflt_tool_diameters, _dflt_sha256, _dflt_dialect, _dflt_fanuc, _dflt_block_delete, _dflt_arc_tolerance, _dflt_path_mode, _dflt_path_tolerance, _dflt_machine_type, _dflt_diameter_axes, _dflt_tool_offsets, _dflt_tool_length_wear, _dflt_tool_radius_wear, _dflt_control_units, _dflt_tool_change_quill_up, _dflt_tool_change_at_g30, _dflt_tool_change_position, _dflt_subroutine_path, _return_type):
 def __init__(self,name:_type_name,units:_type_units,axes:_type_axes,rapid_mode:_type_rapid_mode,monitor_period_ms:_type_monitor_period_ms,reference:_type_reference,start:_type_start,offsets:_type_offsets,tool_lengths:_type_tool_lengths,allowed:_type_allowed,modal:_type_modal=_dflt_modal,tool_axis:_type_tool_axis=_dflt_tool_axis,source:_type_source=_dflt_source,warnings:_type_warnings=_dflt_warnings,sections:_type_sections=_HAS_DEFAULT_FACTORY,cutter_compensation:_type_cutter_compensation=_dflt_cutter_compensation,tool_diameters:_type_tool_diameters=_HAS_DEFAULT_FACTORY,sha256:_type_sha256=_dflt_sha256,dialect:_type_dialect=_dflt_dialect,fanuc:_type_fanuc=_HAS_DEFAULT_FACTORY,block_delete:_type_block_delete=_dflt_block_delete,arc_tolerance:_type_arc_tolerance=_dflt_arc_tolerance,path_mode:_type_path_mode=_dflt_path_mode,path_tolerance:_type_path_tolerance=_dflt_path_tolerance,machine_type:_type_machine_type=_dflt_machine_type,diameter_axes:_type_diameter_axes=_dflt_diameter_axes,tool_offsets:_type_tool_offsets=_HAS_DEFAULT_FACTORY,tool_length_wear:_type_tool_length_wear=_HAS_DEFAULT_FACTORY,tool_radius_wear:_type_tool_radius_wear=_HAS_DEFAULT_FACTORY,control_units:_type_control_units=_dflt_control_units,tool_change_quill_up:_type_tool_change_quill_up=_dflt_tool_change_quill_up,tool_change_at_g30:_type_tool_change_at_g30=_dflt_tool_change_at_g30,tool_change_position:_type_tool_change_position=_HAS_DEFAULT_FACTORY,subroutine_path:_type_subroutine_path=_dflt_subroutine_path)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'name',name)
  __dataclass_builtins_object__.__setattr__(self,'units',units)
  __dataclass_builtins_object__.__setattr__(self,'axes',axes)
  __dataclass_builtins_object__.__setattr__(self,'rapid_mode',rapid_mode)
  __dataclass_builtins_object__.__setattr__(self,'monitor_period_ms',monitor_period_ms)
  __dataclass_builtins_object__.__setattr__(self,'reference',reference)
  __dataclass_builtins_object__.__setattr__(self,'start',start)
  __dataclass_builtins_object__.__setattr__(self,'offsets',offsets)
  __dataclass_builtins_object__.__setattr__(self,'tool_lengths',tool_lengths)
  __dataclass_builtins_object__.__setattr__(self,'allowed',allowed)
  __dataclass_builtins_object__.__setattr__(self,'modal',modal)
  __dataclass_builtins_object__.__setattr__(self,'tool_axis',tool_axis)
  __dataclass_builtins_object__.__setattr__(self,'source',source)
  __dataclass_builtins_object__.__setattr__(self,'warnings',warnings)
  __dataclass_builtins_object__.__setattr__(self,'sections',_dflt_sections() if sections is _HAS_DEFAULT_FACTORY else sections)
  __dataclass_builtins_object__.__setattr__(self,'cutter_compensation',cutter_compensation)
  __dataclass_builtins_object__.__setattr__(self,'tool_diameters',_dflt_tool_diameters() if tool_diameters is _HAS_DEFAULT_FACTORY else tool_diameters)
  __dataclass_builtins_object__.__setattr__(self,'sha256',sha256)
  __dataclass_builtins_object__.__setattr__(self,'dialect',dialect)
  __dataclass_builtins_object__.__setattr__(self,'fanuc',_dflt_fanuc() if fanuc is _HAS_DEFAULT_FACTORY else fanuc)
  __dataclass_builtins_object__.__setattr__(self,'block_delete',block_delete)
  __dataclass_builtins_object__.__setattr__(self,'arc_tolerance',arc_tolerance)
  __dataclass_builtins_object__.__setattr__(self,'path_mode',path_mode)
  __dataclass_builtins_object__.__setattr__(self,'path_tolerance',path_tolerance)
  __dataclass_builtins_object__.__setattr__(self,'machine_type',machine_type)
  __dataclass_builtins_object__.__setattr__(self,'diameter_axes',diameter_axes)
  __dataclass_builtins_object__.__setattr__(self,'tool_offsets',_dflt_tool_offsets() if tool_offsets is _HAS_DEFAULT_FACTORY else tool_offsets)
  __dataclass_builtins_object__.__setattr__(self,'tool_length_wear',_dflt_tool_length_wear() if tool_length_wear is _HAS_DEFAULT_FACTORY else tool_length_wear)
  __dataclass_builtins_object__.__setattr__(self,'tool_radius_wear',_dflt_tool_radius_wear() if tool_radius_wear is _HAS_DEFAULT_FACTORY else tool_radius_wear)
  __dataclass_builtins_object__.__setattr__(self,'control_units',control_units)
  __dataclass_builtins_object__.__setattr__(self,'tool_change_quill_up',tool_change_quill_up)
  __dataclass_builtins_object__.__setattr__(self,'tool_change_at_g30',tool_change_at_g30)
  __dataclass_builtins_object__.__setattr__(self,'tool_change_position',_dflt_tool_change_position() if tool_change_position is _HAS_DEFAULT_FACTORY else tool_change_position)
  __dataclass_builtins_object__.__setattr__(self,'subroutine_path',subroutine_path)
 return __init__

def f185(_type_number, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,number:_type_number)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'number',number)
 return __init__

def f186(_type_number, _type_geometry, _type_wear, _type_nose_radius, _type_wear_radius, _type_tip, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_geometry, _dflt_wear, _dflt_nose_radius, _dflt_wear_radius, _dflt_tip, _return_type):
 def __init__(self,number:_type_number,geometry:_type_geometry=_dflt_geometry,wear:_type_wear=_dflt_wear,nose_radius:_type_nose_radius=_dflt_nose_radius,wear_radius:_type_wear_radius=_dflt_wear_radius,tip:_type_tip=_dflt_tip)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'number',number)
  __dataclass_builtins_object__.__setattr__(self,'geometry',geometry)
  __dataclass_builtins_object__.__setattr__(self,'wear',wear)
  __dataclass_builtins_object__.__setattr__(self,'nose_radius',nose_radius)
  __dataclass_builtins_object__.__setattr__(self,'wear_radius',wear_radius)
  __dataclass_builtins_object__.__setattr__(self,'tip',tip)
 return __init__

def f187(_type_offsets, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,offsets:_type_offsets)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'offsets',offsets)
 return __init__

def f188(_type_p0, _type_p1, _type_tau0, _type_tau1, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_tau0, _dflt_tau1, _return_type):
 def __init__(self,p0:_type_p0,p1:_type_p1,tau0:_type_tau0=_dflt_tau0,tau1:_type_tau1=_dflt_tau1)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'p0',p0)
  __dataclass_builtins_object__.__setattr__(self,'p1',p1)
  __dataclass_builtins_object__.__setattr__(self,'tau0',tau0)
  __dataclass_builtins_object__.__setattr__(self,'tau1',tau1)
 return __init__

def f189(_type_start, _type_end, _type_turns, _type_x_off, _type_c_entry, _type_linear_axis, _type_rotary_axis, _type_grid, _type_arc, _type_centre, _type_radius, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_centre, _dflt_radius, _return_type):
 def __init__(self,start:_type_start,end:_type_end,turns:_type_turns,x_off:_type_x_off,c_entry:_type_c_entry,linear_axis:_type_linear_axis,rotary_axis:_type_rotary_axis,grid:_type_grid,arc:_type_arc,centre:_type_centre=_dflt_centre,radius:_type_radius=_dflt_radius)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'start',start)
  __dataclass_builtins_object__.__setattr__(self,'end',end)
  __dataclass_builtins_object__.__setattr__(self,'turns',turns)
  __dataclass_builtins_object__.__setattr__(self,'x_off',x_off)
  __dataclass_builtins_object__.__setattr__(self,'c_entry',c_entry)
  __dataclass_builtins_object__.__setattr__(self,'linear_axis',linear_axis)
  __dataclass_builtins_object__.__setattr__(self,'rotary_axis',rotary_axis)
  __dataclass_builtins_object__.__setattr__(self,'grid',grid)
  __dataclass_builtins_object__.__setattr__(self,'arc',arc)
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
  __dataclass_builtins_object__.__setattr__(self,'radius',radius)
 return __init__

def f190(_type_status, _type_values, _type_approximate, _type_stopped, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_approximate, _dflt_stopped, _return_type):
 def __init__(self,status:_type_status,values:_type_values,approximate:_type_approximate=_dflt_approximate,stopped:_type_stopped=_dflt_stopped)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'status',status)
  __dataclass_builtins_object__.__setattr__(self,'values',values)
  __dataclass_builtins_object__.__setattr__(self,'approximate',approximate)
  __dataclass_builtins_object__.__setattr__(self,'stopped',stopped)
 return __init__

def f191(_type_summary, _type_configure, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,summary:_type_summary,configure:_type_configure)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'summary',summary)
  __dataclass_builtins_object__.__setattr__(self,'configure',configure)
 return __init__

def f192(_type_text, _type_name, _type_digest, _type_path, _type_notes, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_path, _dflt_notes, _return_type):
 def __init__(self,text:_type_text,name:_type_name,digest:_type_digest,path:_type_path=_dflt_path,notes:_type_notes=_dflt_notes)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'text',text)
  __dataclass_builtins_object__.__setattr__(self,'name',name)
  __dataclass_builtins_object__.__setattr__(self,'digest',digest)
  __dataclass_builtins_object__.__setattr__(self,'path',path)
  __dataclass_builtins_object__.__setattr__(self,'notes',notes)
 return __init__

def f193(_type_upto, _type_min, _type_max, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_min, _dflt_max, _return_type):
 def __init__(self,upto:_type_upto,min:_type_min=_dflt_min,max:_type_max=_dflt_max)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'upto',upto)
  __dataclass_builtins_object__.__setattr__(self,'min',min)
  __dataclass_builtins_object__.__setattr__(self,'max',max)
 return __init__

def f194(_type_value, _type_deps, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_deps, _return_type):
 def __init__(self,value:_type_value,deps:_type_deps=_HAS_DEFAULT_FACTORY)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'value',value)
  __dataclass_builtins_object__.__setattr__(self,'deps',_dflt_deps() if deps is _HAS_DEFAULT_FACTORY else deps)
 return __init__

def f195(_type_verdict, _type_violations, _type_reasons, _type_engines, _type_solver, _type_solver_version, _type_timings, _type_notes, _type_stats, _type_margin, _type_params, _type_engine, _type_truncated, _type_file, _type_extra, _type_program_digest, _type_machine_name, _type_machine_file, _type_machine_sha256, _type_settings, _type_interrupted, _type_budget_s, _type_profile, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_violations, _dflt_reasons, _dflt_engines, _dflt_solver, _dflt_solver_version, _dflt_timings, _dflt_notes, _dflt_stats, _dflt_margin, _dflt_params, _dflt_engine, _dflt_truncated, _dflt_file, _dflt_extra, _dflt_program_digest, _dflt_machine_name, _dflt_machine_file, _dflt_machine_sha256, _dflt_settings, _dflt_interrupted, _dflt_budget_s, _dflt_profile, _return_type):
 def __init__(self,verdict:_type_verdict,violations:_type_violations=_dflt_violations,reasons:_type_reasons=_dflt_reasons,engines:_type_engines=_dflt_engines,solver:_type_solver=_dflt_solver,solver_version:_type_solver_version=_dflt_solver_version,timings:_type_timings=_dflt_timings,notes:_type_notes=_dflt_notes,stats:_type_stats=_dflt_stats,margin:_type_margin=_dflt_margin,params:_type_params=_dflt_params,engine:_type_engine=_dflt_engine,truncated:_type_truncated=_dflt_truncated,file:_type_file=_dflt_file,extra:_type_extra=_HAS_DEFAULT_FACTORY,program_digest:_type_program_digest=_dflt_program_digest,machine_name:_type_machine_name=_dflt_machine_name,machine_file:_type_machine_file=_dflt_machine_file,machine_sha256:_type_machine_sha256=_dflt_machine_sha256,settings:_type_settings=_dflt_settings,interrupted:_type_interrupted=_dflt_interrupted,budget_s:_type_budget_s=_dflt_budget_s,profile:_type_profile=_HAS_DEFAULT_FACTORY)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'verdict',verdict)
  __dataclass_builtins_object__.__setattr__(self,'violations',violations)
  __dataclass_builtins_object__.__setattr__(self,'reasons',reasons)
  __dataclass_builtins_object__.__setattr__(self,'engines',engines)
  __dataclass_builtins_object__.__setattr__(self,'solver',solver)
  __dataclass_builtins_object__.__setattr__(self,'solver_version',solver_version)
  __dataclass_builtins_object__.__setattr__(self,'timings',timings)
  __dataclass_builtins_object__.__setattr__(self,'notes',notes)
  __dataclass_builtins_object__.__setattr__(self,'stats',stats)
  __dataclass_builtins_object__.__setattr__(self,'margin',margin)
  __dataclass_builtins_object__.__setattr__(self,'params',params)
  __dataclass_builtins_object__.__setattr__(self,'engine',engine)
  __dataclass_builtins_object__.__setattr__(self,'truncated',truncated)
  __dataclass_builtins_object__.__setattr__(self,'file',file)
  __dataclass_builtins_object__.__setattr__(self,'extra',_dflt_extra() if extra is _HAS_DEFAULT_FACTORY else extra)
  __dataclass_builtins_object__.__setattr__(self,'program_digest',program_digest)
  __dataclass_builtins_object__.__setattr__(self,'machine_name',machine_name)
  __dataclass_builtins_object__.__setattr__(self,'machine_file',machine_file)
  __dataclass_builtins_object__.__setattr__(self,'machine_sha256',machine_sha256)
  __dataclass_builtins_object__.__setattr__(self,'settings',settings)
  __dataclass_builtins_object__.__setattr__(self,'interrupted',interrupted)
  __dataclass_builtins_object__.__setattr__(self,'budget_s',budget_s)
  __dataclass_builtins_object__.__setattr__(self,'profile',_dflt_profile() if profile is _HAS_DEFAULT_FACTORY else profile)
 return __init__

def f196(_type_violation, _type_reason, _type_engine, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_violation, _dflt_reason, _dflt_engine, _return_type):
 def __init__(self,violation:_type_violation=_dflt_violation,reason:_type_reason=_dflt_reason,engine:_type_engine=_dflt_engine)->_return_type:
  self.violation=violation
  self.reason=reason
  self.engine=engine
 return __init__

def f197(_type_words, _type_span, _type_index, _type_number, _type_messages, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_number, _dflt_messages, _return_type):
 def __init__(self,words:_type_words,span:_type_span,index:_type_index,number:_type_number=_dflt_number,messages:_type_messages=_dflt_messages)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'words',words)
  __dataclass_builtins_object__.__setattr__(self,'span',span)
  __dataclass_builtins_object__.__setattr__(self,'index',index)
  __dataclass_builtins_object__.__setattr__(self,'number',number)
  __dataclass_builtins_object__.__setattr__(self,'messages',messages)
 return __init__

def f198(_type_words, _type_span, _type_index, _type_number, _type_messages, _type_shape, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_number, _dflt_messages, _dflt_shape, _return_type):
 def __init__(self,words:_type_words,span:_type_span,index:_type_index,number:_type_number=_dflt_number,messages:_type_messages=_dflt_messages,shape:_type_shape=_dflt_shape)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'words',words)
  __dataclass_builtins_object__.__setattr__(self,'span',span)
  __dataclass_builtins_object__.__setattr__(self,'index',index)
  __dataclass_builtins_object__.__setattr__(self,'number',number)
  __dataclass_builtins_object__.__setattr__(self,'messages',messages)
  __dataclass_builtins_object__.__setattr__(self,'shape',shape)
 return __init__

def f199(_type_work, _type_offset, _type_rotation, _type_diameter, _type_inch, _type_opaque, _type_work_offset, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_rotation, _dflt_diameter, _dflt_inch, _dflt_opaque, _dflt_work_offset, _return_type):
 def __init__(self,work:_type_work,offset:_type_offset,rotation:_type_rotation=_dflt_rotation,diameter:_type_diameter=_dflt_diameter,inch:_type_inch=_dflt_inch,opaque:_type_opaque=_dflt_opaque,work_offset:_type_work_offset=_dflt_work_offset)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'work',work)
  __dataclass_builtins_object__.__setattr__(self,'offset',offset)
  __dataclass_builtins_object__.__setattr__(self,'rotation',rotation)
  __dataclass_builtins_object__.__setattr__(self,'diameter',diameter)
  __dataclass_builtins_object__.__setattr__(self,'inch',inch)
  __dataclass_builtins_object__.__setattr__(self,'opaque',opaque)
  __dataclass_builtins_object__.__setattr__(self,'work_offset',work_offset)
 return __init__

def f200(_type_zones, _type_tool_axis, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_tool_axis, _return_type):
 def __init__(self,zones:_type_zones,tool_axis:_type_tool_axis=_dflt_tool_axis)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'zones',zones)
  __dataclass_builtins_object__.__setattr__(self,'tool_axis',tool_axis)
 return __init__

def f201(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('axes','columns','offset_bound','motions','lines','rapids','blocks','start','first_row','row0','arcs','arc_rows','arc_axes','arc_boxes','arc_more','dwells','dwell_rows','modes','inc_bound','assumed','tolerance','arc_planes',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f202(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('axes','degrees','cos','sin','before','after',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f203(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('axes','scale','kind','start','end','line','block','tool_length','centre','plane','clockwise','turns','feed','file','objects','dwell','derived','frame','radius','tool_register','tools_known',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f204(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('blend','tolerance','naive','dialect','code',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f205(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('block','span','zone','point','path_point','parameter','parameter_exact','first_exit','first_exit_parameter','first_exit_exact','depth','depth_exact','engine','segment_kind','derived','kind','params','zones','note','on_path','break_line','break_parameter','break_point','leg','switches','exit_located','frame',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f206(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('code','message','span','severity','file',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f207(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('code','reason','span',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f208(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('decimal_point_input','increment_system','g73_retract','g83_clearance','boring_shift','scaling_unit','rotation_incremental','atan_signed','tool_length_motion','harmless_m','references','variables','macros','gcode_system','g71_depth','g71_retract','roughing_final_pass','g73_relief_x','g73_relief_z','g73_divisions','g74_retract','thread_chamfer','thread_chamfer_angle','g76_finish_passes','g76_tool_angle','g76_min_depth','g76_finish_allowance','tool_offset_motion','tool_offset_cancel','path',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f209(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('degree','knots','control','weights','source',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f210(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('delete','number','oword','words','assigns','comments','percent','unsupported',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f211(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('delete','number','program','words','assigns','comments','stmt','stmt_at','percent','unmodelled',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f212(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('file','line','column','end_column','text',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f213(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('ia','ib','s','e','ccw','full','centre','r_signed','r2_lo','r2_hi','start','end',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f214(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('key','group','lanes',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f215(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('key','meaning','read',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f216(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('kind','start','end','axes','block','span','tool_length','feed_mm_min','plane','clockwise','centre','radius','turns','dwell_s','derived','tool_register','deps_start','deps_end','deps_tool','extra','frame',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f217(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('label','keyword','args','column','end_column',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f218(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('lane','g','m',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f219(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('letter','value','span','text',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f220(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('linear_axis','rotary_axis','cylinder_radius',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f221(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('lo','hi','lo_closed','hi_closed',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f222(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('lo','hi',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f223(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('margin','params','engine','max_violations','arc_tolerance','recovery','max_iterations','dialect','library','block_delete','budget_s','limits','tool_table','tool_table_units','tool_table_x_offset','written',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f224(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('message','span','block','code',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f225(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('missing','on_fallback',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f226(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('name','limits','forbid','point',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f227(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('name','lo','hi','written','absolute','lo_open','hi_open','centre',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f228(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('name','max_passes','spent',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f229(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('name','plane','vertices','limits','forbid','point',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f230(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('name','pulse','rapid_mm_min','max_feed_mm_min','rotary','accel_mm_s2',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f231(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('name','reference_axis','limited_axis','start','regions','forbid','point','_steps',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f232(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('name','units','axes','rapid_mode','monitor_period_ms','reference','start','offsets','tool_lengths','allowed','modal','tool_axis','source','warnings','sections','cutter_compensation','tool_diameters','sha256','dialect','fanuc','block_delete','arc_tolerance','path_mode','path_tolerance','machine_type','diameter_axes','tool_offsets','tool_length_wear','tool_radius_wear','control_units','tool_change_quill_up','tool_change_at_g30','tool_change_position','subroutine_path',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f233(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('number','geometry','wear','nose_radius','wear_radius','tip',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f234(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('number',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f235(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('offsets',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f236(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('p0','p1','tau0','tau1',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f237(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('start','end','turns','x_off','c_entry','linear_axis','rotary_axis','grid','arc','centre','radius',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f238(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('status','values','approximate','stopped',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f239(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('summary','configure',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f240(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('text','name','digest','path','notes',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f241(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('upto','min','max',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f242(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('value','deps',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f243(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('verdict','violations','reasons','engines','solver','solver_version','timings','notes','stats','margin','params','engine','truncated','file','extra','program_digest','machine_name','machine_file','machine_sha256','settings','interrupted','budget_s','profile',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f244(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('words','span','index','number','messages','shape',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f245(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('words','span','index','number','messages',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f246(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('work','offset','rotation','diameter','inch','opaque','work_offset',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f247(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('zones','tool_axis',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f248(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('axes','columns','offset_bound','motions','lines','rapids','blocks','start','first_row','row0','arcs','arc_rows','arc_axes','arc_boxes','arc_more','dwells','dwell_rows','modes','inc_bound','assumed','tolerance','arc_planes',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f249(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('axes','degrees','cos','sin','before','after',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f250(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('axes','scale','kind','start','end','line','block','tool_length','centre','plane','clockwise','turns','feed','file','objects','dwell','derived','frame','radius','tool_register','tools_known',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f251(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('blend','tolerance','naive','dialect','code',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f252(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('block','span','zone','point','path_point','parameter','parameter_exact','first_exit','first_exit_parameter','first_exit_exact','depth','depth_exact','engine','segment_kind','derived','kind','params','zones','note','on_path','break_line','break_parameter','break_point','leg','switches','exit_located','frame',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f253(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('code','message','span','severity','file',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f254(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('code','reason','span',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f255(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('decimal_point_input','increment_system','g73_retract','g83_clearance','boring_shift','scaling_unit','rotation_incremental','atan_signed','tool_length_motion','harmless_m','references','variables','macros','gcode_system','g71_depth','g71_retract','roughing_final_pass','g73_relief_x','g73_relief_z','g73_divisions','g74_retract','thread_chamfer','thread_chamfer_angle','g76_finish_passes','g76_tool_angle','g76_min_depth','g76_finish_allowance','tool_offset_motion','tool_offset_cancel','path',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f256(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('degree','knots','control','weights','source',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f257(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('delete','number','oword','words','assigns','comments','percent','unsupported',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f258(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('delete','number','program','words','assigns','comments','stmt','stmt_at','percent','unmodelled',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f259(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('file','line','column','end_column','text',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f260(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('ia','ib','s','e','ccw','full','centre','r_signed','r2_lo','r2_hi','start','end',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f261(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('key','group','lanes',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f262(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('key','meaning','read',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f263(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('kind','start','end','axes','block','span','tool_length','feed_mm_min','plane','clockwise','centre','radius','turns','dwell_s','derived','tool_register','deps_start','deps_end','deps_tool','extra','frame',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f264(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('label','keyword','args','column','end_column',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f265(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('lane','g','m',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f266(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('letter','value','span','text',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f267(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('linear_axis','rotary_axis','cylinder_radius',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f268(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('lo','hi','lo_closed','hi_closed',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f269(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('lo','hi',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f270(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('margin','params','engine','max_violations','arc_tolerance','recovery','max_iterations','dialect','library','block_delete','budget_s','limits','tool_table','tool_table_units','tool_table_x_offset','written',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f271(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('message','span','block','code',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f272(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('missing','on_fallback',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f273(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('name','limits','forbid','point',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f274(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('name','lo','hi','written','absolute','lo_open','hi_open','centre',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f275(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('name','max_passes','spent',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f276(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('name','plane','vertices','limits','forbid','point',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f277(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('name','pulse','rapid_mm_min','max_feed_mm_min','rotary','accel_mm_s2',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f278(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('name','reference_axis','limited_axis','start','regions','forbid','point','_steps',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f279(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('name','units','axes','rapid_mode','monitor_period_ms','reference','start','offsets','tool_lengths','allowed','modal','tool_axis','source','warnings','sections','cutter_compensation','tool_diameters','sha256','dialect','fanuc','block_delete','arc_tolerance','path_mode','path_tolerance','machine_type','diameter_axes','tool_offsets','tool_length_wear','tool_radius_wear','control_units','tool_change_quill_up','tool_change_at_g30','tool_change_position','subroutine_path',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f280(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('number','geometry','wear','nose_radius','wear_radius','tip',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f281(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('number',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f282(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('offsets',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f283(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('p0','p1','tau0','tau1',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f284(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('start','end','turns','x_off','c_entry','linear_axis','rotary_axis','grid','arc','centre','radius',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f285(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('status','values','approximate','stopped',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f286(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('summary','configure',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f287(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('text','name','digest','path','notes',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f288(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('upto','min','max',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f289(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('value','deps',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f290(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('verdict','violations','reasons','engines','solver','solver_version','timings','notes','stats','margin','params','engine','truncated','file','extra','program_digest','machine_name','machine_file','machine_sha256','settings','interrupted','budget_s','profile',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f291(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('words','span','index','number','messages','shape',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f292(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('words','span','index','number','messages',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f293(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('work','offset','rotation','diameter','inch','opaque','work_offset',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f294(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('zones','tool_axis',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

FUNCTIONS = {
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.axes,self.columns,self.offset_bound,self.motions,self.lines,self.rapids,self.blocks,self.start,self.first_row,self.row0,self.arcs,self.arc_rows,self.arc_axes,self.arc_boxes,self.arc_more,self.dwells,self.dwell_rows,self.modes,self.inc_bound,self.assumed,self.tolerance,self.arc_planes,)==(other.axes,other.columns,other.offset_bound,other.motions,other.lines,other.rapids,other.blocks,other.start,other.first_row,other.row0,other.arcs,other.arc_rows,other.arc_axes,other.arc_boxes,other.arc_more,other.dwells,other.dwell_rows,other.modes,other.inc_bound,other.assumed,other.tolerance,other.arc_planes,)\n  return NotImplemented\n return __eq__': f0,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.axes,self.degrees,self.cos,self.sin,self.before,self.after,)==(other.axes,other.degrees,other.cos,other.sin,other.before,other.after,)\n  return NotImplemented\n return __eq__': f1,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.axes,self.scale,self.kind,self.start,self.end,self.line,self.block,self.tool_length,self.centre,self.plane,self.clockwise,self.turns,self.feed,self.file,self.objects,self.dwell,self.derived,self.frame,self.radius,self.tool_register,self.tools_known,)==(other.axes,other.scale,other.kind,other.start,other.end,other.line,other.block,other.tool_length,other.centre,other.plane,other.clockwise,other.turns,other.feed,other.file,other.objects,other.dwell,other.derived,other.frame,other.radius,other.tool_register,other.tools_known,)\n  return NotImplemented\n return __eq__': f2,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.blend,self.tolerance,self.naive,self.dialect,self.code,)==(other.blend,other.tolerance,other.naive,other.dialect,other.code,)\n  return NotImplemented\n return __eq__': f3,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.block,self.span,self.zone,self.point,self.path_point,self.parameter,self.parameter_exact,self.first_exit,self.first_exit_parameter,self.first_exit_exact,self.depth,self.depth_exact,self.engine,self.segment_kind,self.derived,self.kind,self.params,self.zones,self.note,self.on_path,self.break_line,self.break_parameter,self.break_point,self.leg,self.switches,self.exit_located,)==(other.block,other.span,other.zone,other.point,other.path_point,other.parameter,other.parameter_exact,other.first_exit,other.first_exit_parameter,other.first_exit_exact,other.depth,other.depth_exact,other.engine,other.segment_kind,other.derived,other.kind,other.params,other.zones,other.note,other.on_path,other.break_line,other.break_parameter,other.break_point,other.leg,other.switches,other.exit_located,)\n  return NotImplemented\n return __eq__': f4,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.code,self.message,self.span,self.severity,self.file,)==(other.code,other.message,other.span,other.severity,other.file,)\n  return NotImplemented\n return __eq__': f5,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.code,self.reason,self.span,)==(other.code,other.reason,other.span,)\n  return NotImplemented\n return __eq__': f6,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.decimal_point_input,self.increment_system,self.g73_retract,self.g83_clearance,self.boring_shift,self.scaling_unit,self.rotation_incremental,self.atan_signed,self.tool_length_motion,self.harmless_m,self.references,self.variables,self.macros,self.gcode_system,self.g71_depth,self.g71_retract,self.roughing_final_pass,self.g73_relief_x,self.g73_relief_z,self.g73_divisions,self.g74_retract,self.thread_chamfer,self.thread_chamfer_angle,self.g76_finish_passes,self.g76_tool_angle,self.g76_min_depth,self.g76_finish_allowance,self.tool_offset_motion,self.tool_offset_cancel,self.path,)==(other.decimal_point_input,other.increment_system,other.g73_retract,other.g83_clearance,other.boring_shift,other.scaling_unit,other.rotation_incremental,other.atan_signed,other.tool_length_motion,other.harmless_m,other.references,other.variables,other.macros,other.gcode_system,other.g71_depth,other.g71_retract,other.roughing_final_pass,other.g73_relief_x,other.g73_relief_z,other.g73_divisions,other.g74_retract,other.thread_chamfer,other.thread_chamfer_angle,other.g76_finish_passes,other.g76_tool_angle,other.g76_min_depth,other.g76_finish_allowance,other.tool_offset_motion,other.tool_offset_cancel,other.path,)\n  return NotImplemented\n return __eq__': f7,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.degree,self.knots,self.control,self.weights,self.source,)==(other.degree,other.knots,other.control,other.weights,other.source,)\n  return NotImplemented\n return __eq__': f8,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.delete,self.number,self.oword,self.words,self.assigns,self.comments,self.percent,self.unsupported,)==(other.delete,other.number,other.oword,other.words,other.assigns,other.comments,other.percent,other.unsupported,)\n  return NotImplemented\n return __eq__': f9,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.delete,self.number,self.program,self.words,self.assigns,self.comments,self.stmt,self.stmt_at,self.percent,self.unmodelled,)==(other.delete,other.number,other.program,other.words,other.assigns,other.comments,other.stmt,other.stmt_at,other.percent,other.unmodelled,)\n  return NotImplemented\n return __eq__': f10,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.file,self.line,self.column,self.end_column,self.text,)==(other.file,other.line,other.column,other.end_column,other.text,)\n  return NotImplemented\n return __eq__': f11,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.ia,self.ib,self.s,self.e,self.ccw,self.full,self.centre,self.r_signed,self.r2_lo,self.r2_hi,self.start,self.end,)==(other.ia,other.ib,other.s,other.e,other.ccw,other.full,other.centre,other.r_signed,other.r2_lo,other.r2_hi,other.start,other.end,)\n  return NotImplemented\n return __eq__': f12,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.key,self.group,self.lanes,)==(other.key,other.group,other.lanes,)\n  return NotImplemented\n return __eq__': f13,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.key,self.meaning,self.read,)==(other.key,other.meaning,other.read,)\n  return NotImplemented\n return __eq__': f14,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.kind,self.label,self.head,self.remaining,self.count,self.ifs,)==(other.kind,other.label,other.head,other.remaining,other.count,other.ifs,)\n  return NotImplemented\n return __eq__': f15,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.kind,self.label,self.ret,self.saved,self.body,self.repeats,self.loops,self.ifs,self.caller,)==(other.kind,other.label,other.ret,other.saved,other.body,other.repeats,other.loops,other.ifs,other.caller,)\n  return NotImplemented\n return __eq__': f16,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.kind,self.source,self.program,self.ret,self.body,self.repeats,self.saved,self.args,self.loops,self.custom,)==(other.kind,other.source,other.program,other.ret,other.body,other.repeats,other.saved,other.args,other.loops,other.custom,)\n  return NotImplemented\n return __eq__': f17,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.kind,self.start,self.end,self.axes,self.block,self.span,self.tool_length,self.feed_mm_min,self.plane,self.clockwise,self.centre,self.radius,self.turns,self.dwell_s,self.derived,self.tool_register,self.deps_start,self.deps_end,self.deps_tool,self.extra,)==(other.kind,other.start,other.end,other.axes,other.block,other.span,other.tool_length,other.feed_mm_min,other.plane,other.clockwise,other.centre,other.radius,other.turns,other.dwell_s,other.derived,other.tool_register,other.deps_start,other.deps_end,other.deps_tool,other.extra,)\n  return NotImplemented\n return __eq__': f18,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.label,self.keyword,self.args,self.column,self.end_column,)==(other.label,other.keyword,other.args,other.column,other.end_column,)\n  return NotImplemented\n return __eq__': f19,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.lane,self.g,self.m,)==(other.lane,other.g,other.m,)\n  return NotImplemented\n return __eq__': f20,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.linear_axis,self.rotary_axis,self.cylinder_radius,)==(other.linear_axis,other.rotary_axis,other.cylinder_radius,)\n  return NotImplemented\n return __eq__': f21,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.lo,self.hi,)==(other.lo,other.hi,)\n  return NotImplemented\n return __eq__': f22,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.lo,self.hi,self.lo_closed,self.hi_closed,)==(other.lo,other.hi,other.lo_closed,other.hi_closed,)\n  return NotImplemented\n return __eq__': f23,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.m,self.head,self.count,)==(other.m,other.head,other.count,)\n  return NotImplemented\n return __eq__': f24,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.margin,self.params,self.engine,self.max_violations,self.arc_tolerance,self.recovery,self.max_iterations,self.dialect,self.library,self.block_delete,self.budget_s,self.tool_table,self.tool_table_units,self.tool_table_x_offset,)==(other.margin,other.params,other.engine,other.max_violations,other.arc_tolerance,other.recovery,other.max_iterations,other.dialect,other.library,other.block_delete,other.budget_s,other.tool_table,other.tool_table_units,other.tool_table_x_offset,)\n  return NotImplemented\n return __eq__': f25,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.message,self.span,self.block,self.code,)==(other.message,other.span,other.block,other.code,)\n  return NotImplemented\n return __eq__': f26,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.missing,self.on_fallback,)==(other.missing,other.on_fallback,)\n  return NotImplemented\n return __eq__': f27,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.name,self.limits,self.forbid,self.point,)==(other.name,other.limits,other.forbid,other.point,)\n  return NotImplemented\n return __eq__': f28,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.name,self.lo,self.hi,self.written,self.absolute,self.lo_open,self.hi_open,self.centre,)==(other.name,other.lo,other.hi,other.written,other.absolute,other.lo_open,other.hi_open,other.centre,)\n  return NotImplemented\n return __eq__': f29,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.name,self.max_passes,self.spent,)==(other.name,other.max_passes,other.spent,)\n  return NotImplemented\n return __eq__': f30,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.name,self.plane,self.vertices,self.limits,self.forbid,self.point,)==(other.name,other.plane,other.vertices,other.limits,other.forbid,other.point,)\n  return NotImplemented\n return __eq__': f31,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.name,self.pulse,self.rapid_mm_min,self.max_feed_mm_min,self.rotary,self.accel_mm_s2,)==(other.name,other.pulse,other.rapid_mm_min,other.max_feed_mm_min,other.rotary,other.accel_mm_s2,)\n  return NotImplemented\n return __eq__': f32,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.name,self.reference_axis,self.limited_axis,self.start,self.regions,self.forbid,self.point,)==(other.name,other.reference_axis,other.limited_axis,other.start,other.regions,other.forbid,other.point,)\n  return NotImplemented\n return __eq__': f33,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.name,self.units,self.axes,self.rapid_mode,self.monitor_period_ms,self.reference,self.start,self.offsets,self.tool_lengths,self.allowed,self.modal,self.tool_axis,self.source,self.warnings,self.sections,self.cutter_compensation,self.tool_diameters,self.sha256,self.dialect,self.fanuc,self.block_delete,self.arc_tolerance,self.path_mode,self.path_tolerance,self.machine_type,self.diameter_axes,self.tool_offsets,self.tool_length_wear,self.tool_radius_wear,self.control_units,self.tool_change_quill_up,self.tool_change_at_g30,self.tool_change_position,self.subroutine_path,)==(other.name,other.units,other.axes,other.rapid_mode,other.monitor_period_ms,other.reference,other.start,other.offsets,other.tool_lengths,other.allowed,other.modal,other.tool_axis,other.source,other.warnings,other.sections,other.cutter_compensation,other.tool_diameters,other.sha256,other.dialect,other.fanuc,other.block_delete,other.arc_tolerance,other.path_mode,other.path_tolerance,other.machine_type,other.diameter_axes,other.tool_offsets,other.tool_length_wear,other.tool_radius_wear,other.control_units,other.tool_change_quill_up,other.tool_change_at_g30,other.tool_change_position,other.subroutine_path,)\n  return NotImplemented\n return __eq__': f34,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.number,)==(other.number,)\n  return NotImplemented\n return __eq__': f35,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.number,self.geometry,self.wear,self.nose_radius,self.wear_radius,self.tip,)==(other.number,other.geometry,other.wear,other.nose_radius,other.wear_radius,other.tip,)\n  return NotImplemented\n return __eq__': f36,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.offsets,)==(other.offsets,)\n  return NotImplemented\n return __eq__': f37,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.p0,self.p1,self.tau0,self.tau1,)==(other.p0,other.p1,other.tau0,other.tau1,)\n  return NotImplemented\n return __eq__': f38,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.start,self.end,self.turns,self.x_off,self.c_entry,self.linear_axis,self.rotary_axis,self.grid,self.arc,self.centre,self.radius,)==(other.start,other.end,other.turns,other.x_off,other.c_entry,other.linear_axis,other.rotary_axis,other.grid,other.arc,other.centre,other.radius,)\n  return NotImplemented\n return __eq__': f39,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.status,self.values,self.approximate,self.stopped,)==(other.status,other.values,other.approximate,other.stopped,)\n  return NotImplemented\n return __eq__': f40,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.summary,self.configure,)==(other.summary,other.configure,)\n  return NotImplemented\n return __eq__': f41,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.text,self.name,self.digest,self.path,self.notes,)==(other.text,other.name,other.digest,other.path,other.notes,)\n  return NotImplemented\n return __eq__': f42,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.upto,self.min,self.max,)==(other.upto,other.min,other.max,)\n  return NotImplemented\n return __eq__': f43,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.value,self.deps,)==(other.value,other.deps,)\n  return NotImplemented\n return __eq__': f44,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.verdict,self.violations,self.reasons,self.engines,self.solver,self.solver_version,self.timings,self.notes,self.stats,self.margin,self.params,self.engine,self.truncated,self.file,self.program_digest,self.machine_name,self.machine_file,self.machine_sha256,self.settings,self.interrupted,self.budget_s,)==(other.verdict,other.violations,other.reasons,other.engines,other.solver,other.solver_version,other.timings,other.notes,other.stats,other.margin,other.params,other.engine,other.truncated,other.file,other.program_digest,other.machine_name,other.machine_file,other.machine_sha256,other.settings,other.interrupted,other.budget_s,)\n  return NotImplemented\n return __eq__': f45,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.violation,self.reason,self.engine,)==(other.violation,other.reason,other.engine,)\n  return NotImplemented\n return __eq__': f46,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.work,self.offset,self.rotation,self.diameter,self.inch,self.opaque,self.work_offset,)==(other.work,other.offset,other.rotation,other.diameter,other.inch,other.opaque,other.work_offset,)\n  return NotImplemented\n return __eq__': f47,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.zones,self.tool_axis,)==(other.zones,other.tool_axis,)\n  return NotImplemented\n return __eq__': f48,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.axes,self.columns,self.offset_bound,self.motions,self.lines,self.rapids,self.blocks,self.start,self.first_row,self.row0,self.arcs,self.arc_rows,self.arc_axes,self.arc_boxes,self.arc_more,self.dwells,self.dwell_rows,self.modes,self.inc_bound,self.assumed,self.tolerance,self.arc_planes,))\n return __hash__': f49,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.axes,self.degrees,self.cos,self.sin,self.before,self.after,))\n return __hash__': f50,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.axes,self.scale,self.kind,self.start,self.end,self.line,self.block,self.tool_length,self.centre,self.plane,self.clockwise,self.turns,self.feed,self.file,self.objects,self.dwell,self.derived,self.frame,self.radius,self.tool_register,self.tools_known,))\n return __hash__': f51,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.blend,self.tolerance,self.naive,self.dialect,self.code,))\n return __hash__': f52,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.block,self.span,self.zone,self.point,self.path_point,self.parameter,self.parameter_exact,self.first_exit,self.first_exit_parameter,self.first_exit_exact,self.depth,self.depth_exact,self.engine,self.segment_kind,self.derived,self.kind,self.params,self.zones,self.note,self.on_path,self.break_line,self.break_parameter,self.break_point,self.leg,self.switches,self.exit_located,))\n return __hash__': f53,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.code,self.message,self.span,self.severity,self.file,))\n return __hash__': f54,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.code,self.reason,self.span,))\n return __hash__': f55,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.decimal_point_input,self.increment_system,self.g73_retract,self.g83_clearance,self.boring_shift,self.scaling_unit,self.rotation_incremental,self.atan_signed,self.tool_length_motion,self.harmless_m,self.references,self.variables,self.macros,self.gcode_system,self.g71_depth,self.g71_retract,self.roughing_final_pass,self.g73_relief_x,self.g73_relief_z,self.g73_divisions,self.g74_retract,self.thread_chamfer,self.thread_chamfer_angle,self.g76_finish_passes,self.g76_tool_angle,self.g76_min_depth,self.g76_finish_allowance,self.tool_offset_motion,self.tool_offset_cancel,self.path,))\n return __hash__': f56,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.degree,self.knots,self.control,self.weights,self.source,))\n return __hash__': f57,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.delete,self.number,self.oword,self.words,self.assigns,self.comments,self.percent,self.unsupported,))\n return __hash__': f58,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.delete,self.number,self.program,self.words,self.assigns,self.comments,self.stmt,self.stmt_at,self.percent,self.unmodelled,))\n return __hash__': f59,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.file,self.line,self.column,self.end_column,self.text,))\n return __hash__': f60,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.ia,self.ib,self.s,self.e,self.ccw,self.full,self.centre,self.r_signed,self.r2_lo,self.r2_hi,self.start,self.end,))\n return __hash__': f61,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.key,self.group,self.lanes,))\n return __hash__': f62,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.key,self.meaning,self.read,))\n return __hash__': f63,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.kind,self.start,self.end,self.axes,self.block,self.span,self.tool_length,self.feed_mm_min,self.plane,self.clockwise,self.centre,self.radius,self.turns,self.dwell_s,self.derived,self.tool_register,self.deps_start,self.deps_end,self.deps_tool,self.extra,))\n return __hash__': f64,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.label,self.keyword,self.args,self.column,self.end_column,))\n return __hash__': f65,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.lane,self.g,self.m,))\n return __hash__': f66,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.linear_axis,self.rotary_axis,self.cylinder_radius,))\n return __hash__': f67,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.lo,self.hi,))\n return __hash__': f68,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.lo,self.hi,self.lo_closed,self.hi_closed,))\n return __hash__': f69,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.margin,self.params,self.engine,self.max_violations,self.arc_tolerance,self.recovery,self.max_iterations,self.dialect,self.library,self.block_delete,self.budget_s,self.tool_table,self.tool_table_units,self.tool_table_x_offset,))\n return __hash__': f70,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.message,self.span,self.block,self.code,))\n return __hash__': f71,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.missing,self.on_fallback,))\n return __hash__': f72,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.name,self.limits,self.forbid,self.point,))\n return __hash__': f73,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.name,self.lo,self.hi,self.written,self.absolute,self.lo_open,self.hi_open,self.centre,))\n return __hash__': f74,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.name,self.max_passes,self.spent,))\n return __hash__': f75,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.name,self.plane,self.vertices,self.limits,self.forbid,self.point,))\n return __hash__': f76,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.name,self.pulse,self.rapid_mm_min,self.max_feed_mm_min,self.rotary,self.accel_mm_s2,))\n return __hash__': f77,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.name,self.reference_axis,self.limited_axis,self.start,self.regions,self.forbid,self.point,))\n return __hash__': f78,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.name,self.units,self.axes,self.rapid_mode,self.monitor_period_ms,self.reference,self.start,self.offsets,self.tool_lengths,self.allowed,self.modal,self.tool_axis,self.source,self.warnings,self.sections,self.cutter_compensation,self.tool_diameters,self.sha256,self.dialect,self.fanuc,self.block_delete,self.arc_tolerance,self.path_mode,self.path_tolerance,self.machine_type,self.diameter_axes,self.tool_offsets,self.tool_length_wear,self.tool_radius_wear,self.control_units,self.tool_change_quill_up,self.tool_change_at_g30,self.tool_change_position,self.subroutine_path,))\n return __hash__': f79,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.number,))\n return __hash__': f80,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.number,self.geometry,self.wear,self.nose_radius,self.wear_radius,self.tip,))\n return __hash__': f81,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.offsets,))\n return __hash__': f82,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.p0,self.p1,self.tau0,self.tau1,))\n return __hash__': f83,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.start,self.end,self.turns,self.x_off,self.c_entry,self.linear_axis,self.rotary_axis,self.grid,self.arc,self.centre,self.radius,))\n return __hash__': f84,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.status,self.values,self.approximate,self.stopped,))\n return __hash__': f85,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.summary,self.configure,))\n return __hash__': f86,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.text,self.name,self.digest,self.path,self.notes,))\n return __hash__': f87,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.upto,self.min,self.max,))\n return __hash__': f88,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.value,self.deps,))\n return __hash__': f89,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.verdict,self.violations,self.reasons,self.engines,self.solver,self.solver_version,self.timings,self.notes,self.stats,self.margin,self.params,self.engine,self.truncated,self.file,self.program_digest,self.machine_name,self.machine_file,self.machine_sha256,self.settings,self.interrupted,self.budget_s,))\n return __hash__': f90,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.work,self.offset,self.rotation,self.diameter,self.inch,self.opaque,self.work_offset,))\n return __hash__': f91,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.zones,self.tool_axis,))\n return __hash__': f92,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(axes={self.axes!r}, columns={self.columns!r}, offset_bound={self.offset_bound!r}, motions={self.motions!r}, lines={self.lines!r}, rapids={self.rapids!r}, blocks={self.blocks!r}, start={self.start!r}, first_row={self.first_row!r}, row0={self.row0!r}, arcs={self.arcs!r}, arc_rows={self.arc_rows!r}, arc_axes={self.arc_axes!r}, arc_boxes={self.arc_boxes!r}, arc_more={self.arc_more!r}, dwells={self.dwells!r}, dwell_rows={self.dwell_rows!r}, modes={self.modes!r}, inc_bound={self.inc_bound!r}, assumed={self.assumed!r}, tolerance={self.tolerance!r}, arc_planes={self.arc_planes!r})"\n return __repr__': f93,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(axes={self.axes!r}, degrees={self.degrees!r}, cos={self.cos!r}, sin={self.sin!r}, before={self.before!r}, after={self.after!r})"\n return __repr__': f94,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(axes={self.axes!r}, scale={self.scale!r}, kind={self.kind!r}, start={self.start!r}, end={self.end!r}, line={self.line!r}, block={self.block!r}, tool_length={self.tool_length!r}, centre={self.centre!r}, plane={self.plane!r}, clockwise={self.clockwise!r}, turns={self.turns!r}, feed={self.feed!r}, file={self.file!r}, objects={self.objects!r}, dwell={self.dwell!r}, derived={self.derived!r}, frame={self.frame!r}, radius={self.radius!r}, tool_register={self.tool_register!r}, tools_known={self.tools_known!r})"\n return __repr__': f95,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(blend={self.blend!r}, tolerance={self.tolerance!r}, naive={self.naive!r}, dialect={self.dialect!r}, code={self.code!r})"\n return __repr__': f96,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(block={self.block!r}, span={self.span!r}, zone={self.zone!r}, point={self.point!r}, path_point={self.path_point!r}, parameter={self.parameter!r}, parameter_exact={self.parameter_exact!r}, first_exit={self.first_exit!r}, first_exit_parameter={self.first_exit_parameter!r}, first_exit_exact={self.first_exit_exact!r}, depth={self.depth!r}, depth_exact={self.depth_exact!r}, engine={self.engine!r}, segment_kind={self.segment_kind!r}, derived={self.derived!r}, kind={self.kind!r}, params={self.params!r}, zones={self.zones!r}, note={self.note!r}, on_path={self.on_path!r}, break_line={self.break_line!r}, break_parameter={self.break_parameter!r}, break_point={self.break_point!r}, leg={self.leg!r}, switches={self.switches!r}, exit_located={self.exit_located!r}, frame={self.frame!r})"\n return __repr__': f97,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(code={self.code!r}, message={self.message!r}, span={self.span!r}, severity={self.severity!r}, file={self.file!r})"\n return __repr__': f98,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(code={self.code!r}, reason={self.reason!r}, span={self.span!r})"\n return __repr__': f99,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(decimal_point_input={self.decimal_point_input!r}, increment_system={self.increment_system!r}, g73_retract={self.g73_retract!r}, g83_clearance={self.g83_clearance!r}, boring_shift={self.boring_shift!r}, scaling_unit={self.scaling_unit!r}, rotation_incremental={self.rotation_incremental!r}, atan_signed={self.atan_signed!r}, tool_length_motion={self.tool_length_motion!r}, harmless_m={self.harmless_m!r}, references={self.references!r}, variables={self.variables!r}, macros={self.macros!r}, gcode_system={self.gcode_system!r}, g71_depth={self.g71_depth!r}, g71_retract={self.g71_retract!r}, roughing_final_pass={self.roughing_final_pass!r}, g73_relief_x={self.g73_relief_x!r}, g73_relief_z={self.g73_relief_z!r}, g73_divisions={self.g73_divisions!r}, g74_retract={self.g74_retract!r}, thread_chamfer={self.thread_chamfer!r}, thread_chamfer_angle={self.thread_chamfer_angle!r}, g76_finish_passes={self.g76_finish_passes!r}, g76_tool_angle={self.g76_tool_angle!r}, g76_min_depth={self.g76_min_depth!r}, g76_finish_allowance={self.g76_finish_allowance!r}, tool_offset_motion={self.tool_offset_motion!r}, tool_offset_cancel={self.tool_offset_cancel!r}, path={self.path!r})"\n return __repr__': f100,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(degree={self.degree!r}, knots={self.knots!r}, control={self.control!r}, weights={self.weights!r}, source={self.source!r})"\n return __repr__': f101,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(delete={self.delete!r}, number={self.number!r}, oword={self.oword!r}, words={self.words!r}, assigns={self.assigns!r}, comments={self.comments!r}, percent={self.percent!r}, unsupported={self.unsupported!r})"\n return __repr__': f102,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(delete={self.delete!r}, number={self.number!r}, program={self.program!r}, words={self.words!r}, assigns={self.assigns!r}, comments={self.comments!r}, stmt={self.stmt!r}, stmt_at={self.stmt_at!r}, percent={self.percent!r}, unmodelled={self.unmodelled!r})"\n return __repr__': f103,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(file={self.file!r}, line={self.line!r}, column={self.column!r}, end_column={self.end_column!r}, text={self.text!r})"\n return __repr__': f104,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(ia={self.ia!r}, ib={self.ib!r}, s={self.s!r}, e={self.e!r}, ccw={self.ccw!r}, full={self.full!r}, centre={self.centre!r}, r_signed={self.r_signed!r}, r2_lo={self.r2_lo!r}, r2_hi={self.r2_hi!r}, start={self.start!r}, end={self.end!r})"\n return __repr__': f105,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(key={self.key!r}, group={self.group!r}, lanes={self.lanes!r})"\n return __repr__': f106,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(key={self.key!r}, meaning={self.meaning!r}, read={self.read!r})"\n return __repr__': f107,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(kind={self.kind!r}, label={self.label!r}, head={self.head!r}, remaining={self.remaining!r}, count={self.count!r}, ifs={self.ifs!r})"\n return __repr__': f108,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(kind={self.kind!r}, label={self.label!r}, ret={self.ret!r}, saved={self.saved!r}, body={self.body!r}, repeats={self.repeats!r}, loops={self.loops!r}, ifs={self.ifs!r}, caller={self.caller!r})"\n return __repr__': f109,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(kind={self.kind!r}, source={self.source!r}, program={self.program!r}, ret={self.ret!r}, body={self.body!r}, repeats={self.repeats!r}, saved={self.saved!r}, args={self.args!r}, loops={self.loops!r}, custom={self.custom!r})"\n return __repr__': f110,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(kind={self.kind!r}, start={self.start!r}, end={self.end!r}, axes={self.axes!r}, block={self.block!r}, span={self.span!r}, tool_length={self.tool_length!r}, feed_mm_min={self.feed_mm_min!r}, plane={self.plane!r}, clockwise={self.clockwise!r}, centre={self.centre!r}, radius={self.radius!r}, turns={self.turns!r}, dwell_s={self.dwell_s!r}, derived={self.derived!r}, tool_register={self.tool_register!r}, deps_start={self.deps_start!r}, deps_end={self.deps_end!r}, deps_tool={self.deps_tool!r}, extra={self.extra!r}, frame={self.frame!r})"\n return __repr__': f111,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(label={self.label!r}, keyword={self.keyword!r}, args={self.args!r}, column={self.column!r}, end_column={self.end_column!r})"\n return __repr__': f112,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(lane={self.lane!r}, g={self.g!r}, m={self.m!r})"\n return __repr__': f113,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(letter={self.letter!r}, value={self.value!r}, span={self.span!r}, text={self.text!r})"\n return __repr__': f114,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(linear_axis={self.linear_axis!r}, rotary_axis={self.rotary_axis!r}, cylinder_radius={self.cylinder_radius!r})"\n return __repr__': f115,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(lo={self.lo!r}, hi={self.hi!r})"\n return __repr__': f116,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(lo={self.lo!r}, hi={self.hi!r}, lo_closed={self.lo_closed!r}, hi_closed={self.hi_closed!r})"\n return __repr__': f117,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(m={self.m!r}, head={self.head!r}, count={self.count!r})"\n return __repr__': f118,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(margin={self.margin!r}, params={self.params!r}, engine={self.engine!r}, max_violations={self.max_violations!r}, arc_tolerance={self.arc_tolerance!r}, recovery={self.recovery!r}, max_iterations={self.max_iterations!r}, dialect={self.dialect!r}, library={self.library!r}, block_delete={self.block_delete!r}, budget_s={self.budget_s!r}, limits={self.limits!r}, tool_table={self.tool_table!r}, tool_table_units={self.tool_table_units!r}, tool_table_x_offset={self.tool_table_x_offset!r})"\n return __repr__': f119,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(message={self.message!r}, span={self.span!r}, block={self.block!r}, code={self.code!r})"\n return __repr__': f120,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(missing={self.missing!r}, on_fallback={self.on_fallback!r})"\n return __repr__': f121,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(name={self.name!r}, limits={self.limits!r}, forbid={self.forbid!r}, point={self.point!r})"\n return __repr__': f122,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(name={self.name!r}, lo={self.lo!r}, hi={self.hi!r}, written={self.written!r}, absolute={self.absolute!r}, lo_open={self.lo_open!r}, hi_open={self.hi_open!r}, centre={self.centre!r})"\n return __repr__': f123,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(name={self.name!r}, max_passes={self.max_passes!r}, spent={self.spent!r})"\n return __repr__': f124,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(name={self.name!r}, plane={self.plane!r}, vertices={self.vertices!r}, limits={self.limits!r}, forbid={self.forbid!r}, point={self.point!r})"\n return __repr__': f125,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(name={self.name!r}, pulse={self.pulse!r}, rapid_mm_min={self.rapid_mm_min!r}, max_feed_mm_min={self.max_feed_mm_min!r}, rotary={self.rotary!r}, accel_mm_s2={self.accel_mm_s2!r})"\n return __repr__': f126,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(name={self.name!r}, reference_axis={self.reference_axis!r}, limited_axis={self.limited_axis!r}, start={self.start!r}, regions={self.regions!r}, forbid={self.forbid!r}, point={self.point!r})"\n return __repr__': f127,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(name={self.name!r}, units={self.units!r}, axes={self.axes!r}, rapid_mode={self.rapid_mode!r}, monitor_period_ms={self.monitor_period_ms!r}, reference={self.reference!r}, start={self.start!r}, offsets={self.offsets!r}, tool_lengths={self.tool_lengths!r}, allowed={self.allowed!r}, modal={self.modal!r}, tool_axis={self.tool_axis!r}, source={self.source!r}, warnings={self.warnings!r}, sections={self.sections!r}, cutter_compensation={self.cutter_compensation!r}, tool_diameters={self.tool_diameters!r}, sha256={self.sha256!r}, dialect={self.dialect!r}, fanuc={self.fanuc!r}, block_delete={self.block_delete!r}, arc_tolerance={self.arc_tolerance!r}, path_mode={self.path_mode!r}, path_tolerance={self.path_tolerance!r}, machine_type={self.machine_type!r}, diameter_axes={self.diameter_axes!r}, tool_offsets={self.tool_offsets!r}, tool_length_wear={self.tool_length_wear!r}, tool_radius_wear={self.tool_radius_wear!r}, control_units={self.control_units!r}, tool_change_quill_up={self.tool_change_quill_up!r}, tool_change_at_g30={self.tool_change_at_g30!r}, tool_change_position={self.tool_change_position!r}, subroutine_path={self.subroutine_path!r})"\n return __repr__': f128,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(number={self.number!r})"\n return __repr__': f129,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(number={self.number!r}, geometry={self.geometry!r}, wear={self.wear!r}, nose_radius={self.nose_radius!r}, wear_radius={self.wear_radius!r}, tip={self.tip!r})"\n return __repr__': f130,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(offsets={self.offsets!r})"\n return __repr__': f131,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(p0={self.p0!r}, p1={self.p1!r}, tau0={self.tau0!r}, tau1={self.tau1!r})"\n return __repr__': f132,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(start={self.start!r}, end={self.end!r}, turns={self.turns!r}, x_off={self.x_off!r}, c_entry={self.c_entry!r}, linear_axis={self.linear_axis!r}, rotary_axis={self.rotary_axis!r}, grid={self.grid!r}, arc={self.arc!r}, centre={self.centre!r}, radius={self.radius!r})"\n return __repr__': f133,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(status={self.status!r}, values={self.values!r}, approximate={self.approximate!r}, stopped={self.stopped!r})"\n return __repr__': f134,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(summary={self.summary!r}, configure={self.configure!r})"\n return __repr__': f135,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(text={self.text!r}, name={self.name!r}, digest={self.digest!r}, path={self.path!r}, notes={self.notes!r})"\n return __repr__': f136,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(upto={self.upto!r}, min={self.min!r}, max={self.max!r})"\n return __repr__': f137,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(value={self.value!r}, deps={self.deps!r})"\n return __repr__': f138,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(verdict={self.verdict!r}, violations={self.violations!r}, reasons={self.reasons!r}, engines={self.engines!r}, solver={self.solver!r}, solver_version={self.solver_version!r}, timings={self.timings!r}, notes={self.notes!r}, stats={self.stats!r}, margin={self.margin!r}, params={self.params!r}, engine={self.engine!r}, truncated={self.truncated!r}, file={self.file!r}, extra={self.extra!r}, program_digest={self.program_digest!r}, machine_name={self.machine_name!r}, machine_file={self.machine_file!r}, machine_sha256={self.machine_sha256!r}, settings={self.settings!r}, interrupted={self.interrupted!r}, budget_s={self.budget_s!r}, profile={self.profile!r})"\n return __repr__': f139,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(violation={self.violation!r}, reason={self.reason!r}, engine={self.engine!r})"\n return __repr__': f140,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(words={self.words!r}, span={self.span!r}, index={self.index!r}, number={self.number!r}, messages={self.messages!r})"\n return __repr__': f141,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(words={self.words!r}, span={self.span!r}, index={self.index!r}, number={self.number!r}, messages={self.messages!r}, shape={self.shape!r})"\n return __repr__': f142,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(work={self.work!r}, offset={self.offset!r}, rotation={self.rotation!r}, diameter={self.diameter!r}, inch={self.inch!r}, opaque={self.opaque!r}, work_offset={self.work_offset!r})"\n return __repr__': f143,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(zones={self.zones!r}, tool_axis={self.tool_axis!r})"\n return __repr__': f144,
    'def __create_fn__():\n def make(delete,number,words,assigns):\n  o = _new(_draft)\n  o.delete = delete\n  o.number = number\n  o.words = words\n  o.assigns = assigns\n  o.oword = _c_oword\n  o.comments = _c_comments\n  o.percent = _c_percent\n  o.unsupported = _c_unsupported\n  o.__class__ = _cls\n  return o\n return make': f145,
    'def __create_fn__():\n def make(file,line,column,end_column,text):\n  o = _new(_draft)\n  o.file = file\n  o.line = line\n  o.column = column\n  o.end_column = end_column\n  o.text = text\n  o.__class__ = _cls\n  return o\n return make': f146,
    'def __create_fn__():\n def make(kind,start,end,axes,block,span,tool_length,feed_mm_min,plane,clockwise,centre,radius,turns,dwell_s,derived,tool_register,deps_start,deps_end,extra,frame):\n  o = _new(_draft)\n  o.kind = kind\n  o.start = start\n  o.end = end\n  o.axes = axes\n  o.block = block\n  o.span = span\n  o.tool_length = tool_length\n  o.feed_mm_min = feed_mm_min\n  o.plane = plane\n  o.clockwise = clockwise\n  o.centre = centre\n  o.radius = radius\n  o.turns = turns\n  o.dwell_s = dwell_s\n  o.derived = derived\n  o.tool_register = tool_register\n  o.deps_start = deps_start\n  o.deps_end = deps_end\n  o.extra = extra\n  o.frame = frame\n  o.deps_tool = _c_deps_tool\n  o.__class__ = _cls\n  return o\n return make': f147,
    'def __create_fn__():\n def make(letter,value,span,text):\n  o = _new(_draft)\n  o.letter = letter\n  o.value = value\n  o.span = span\n  o.text = text\n  o.__class__ = _cls\n  return o\n return make': f148,
    "def __create_fn__(_type_axes, _type_columns, _type_offset_bound, _type_motions, _type_lines, _type_rapids, _type_blocks, _type_start, _type_first_row, _type_row0, _type_arcs, _type_arc_rows, _type_arc_axes, _type_arc_boxes, _type_arc_more, _type_dwells, _type_dwell_rows, _type_modes, _type_inc_bound, _type_assumed, _type_tolerance, _type_arc_planes, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_row0, _dflt_arcs, _dflt_arc_rows, _dflt_arc_axes, _dflt_arc_boxes, _dflt_arc_more, _dflt_dwells, _dflt_dwell_rows, _dflt_modes, _dflt_inc_bound, _dflt_assumed, _dflt_tolerance, _dflt_arc_planes, _return_type):\n def __init__(self,axes:_type_axes,columns:_type_columns,offset_bound:_type_offset_bound,motions:_type_motions,lines:_type_lines,rapids:_type_rapids,blocks:_type_blocks,start:_type_start,first_row:_type_first_row,row0:_type_row0=_dflt_row0,arcs:_type_arcs=_dflt_arcs,arc_rows:_type_arc_rows=_dflt_arc_rows,arc_axes:_type_arc_axes=_dflt_arc_axes,arc_boxes:_type_arc_boxes=_dflt_arc_boxes,arc_more:_type_arc_more=_dflt_arc_more,dwells:_type_dwells=_dflt_dwells,dwell_rows:_type_dwell_rows=_dflt_dwell_rows,modes:_type_modes=_dflt_modes,inc_bound:_type_inc_bound=_dflt_inc_bound,assumed:_type_assumed=_dflt_assumed,tolerance:_type_tolerance=_dflt_tolerance,arc_planes:_type_arc_planes=_dflt_arc_planes)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'axes',axes)\n  __dataclass_builtins_object__.__setattr__(self,'columns',columns)\n  __dataclass_builtins_object__.__setattr__(self,'offset_bound',offset_bound)\n  __dataclass_builtins_object__.__setattr__(self,'motions',motions)\n  __dataclass_builtins_object__.__setattr__(self,'lines',lines)\n  __dataclass_builtins_object__.__setattr__(self,'rapids',rapids)\n  __dataclass_builtins_object__.__setattr__(self,'blocks',blocks)\n  __dataclass_builtins_object__.__setattr__(self,'start',start)\n  __dataclass_builtins_object__.__setattr__(self,'first_row',first_row)\n  __dataclass_builtins_object__.__setattr__(self,'row0',row0)\n  __dataclass_builtins_object__.__setattr__(self,'arcs',arcs)\n  __dataclass_builtins_object__.__setattr__(self,'arc_rows',arc_rows)\n  __dataclass_builtins_object__.__setattr__(self,'arc_axes',arc_axes)\n  __dataclass_builtins_object__.__setattr__(self,'arc_boxes',arc_boxes)\n  __dataclass_builtins_object__.__setattr__(self,'arc_more',arc_more)\n  __dataclass_builtins_object__.__setattr__(self,'dwells',dwells)\n  __dataclass_builtins_object__.__setattr__(self,'dwell_rows',dwell_rows)\n  __dataclass_builtins_object__.__setattr__(self,'modes',modes)\n  __dataclass_builtins_object__.__setattr__(self,'inc_bound',inc_bound)\n  __dataclass_builtins_object__.__setattr__(self,'assumed',assumed)\n  __dataclass_builtins_object__.__setattr__(self,'tolerance',tolerance)\n  __dataclass_builtins_object__.__setattr__(self,'arc_planes',arc_planes)\n return __init__": f149,
    "def __create_fn__(_type_axes, _type_degrees, _type_cos, _type_sin, _type_before, _type_after, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,axes:_type_axes,degrees:_type_degrees,cos:_type_cos,sin:_type_sin,before:_type_before,after:_type_after)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'axes',axes)\n  __dataclass_builtins_object__.__setattr__(self,'degrees',degrees)\n  __dataclass_builtins_object__.__setattr__(self,'cos',cos)\n  __dataclass_builtins_object__.__setattr__(self,'sin',sin)\n  __dataclass_builtins_object__.__setattr__(self,'before',before)\n  __dataclass_builtins_object__.__setattr__(self,'after',after)\n return __init__": f150,
    "def __create_fn__(_type_axes, _type_scale, _type_kind, _type_start, _type_end, _type_line, _type_block, _type_tool_length, _type_centre, _type_plane, _type_clockwise, _type_turns, _type_feed, _type_file, _type_objects, _type_dwell, _type_derived, _type_frame, _type_radius, _type_tool_register, _type_tools_known, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_kind, _dflt_start, _dflt_end, _dflt_line, _dflt_block, _dflt_tool_length, _dflt_centre, _dflt_plane, _dflt_clockwise, _dflt_turns, _dflt_feed, _dflt_file, _dflt_objects, _dflt_dwell, _dflt_derived, _dflt_frame, _dflt_radius, _dflt_tool_register, _dflt_tools_known, _return_type):\n def __init__(self,axes:_type_axes,scale:_type_scale,kind:_type_kind=_dflt_kind,start:_type_start=_dflt_start,end:_type_end=_dflt_end,line:_type_line=_dflt_line,block:_type_block=_dflt_block,tool_length:_type_tool_length=_dflt_tool_length,centre:_type_centre=_dflt_centre,plane:_type_plane=_dflt_plane,clockwise:_type_clockwise=_dflt_clockwise,turns:_type_turns=_dflt_turns,feed:_type_feed=_dflt_feed,file:_type_file=_dflt_file,objects:_type_objects=_dflt_objects,dwell:_type_dwell=_dflt_dwell,derived:_type_derived=_dflt_derived,frame:_type_frame=_dflt_frame,radius:_type_radius=_dflt_radius,tool_register:_type_tool_register=_dflt_tool_register,tools_known:_type_tools_known=_dflt_tools_known)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'axes',axes)\n  __dataclass_builtins_object__.__setattr__(self,'scale',scale)\n  __dataclass_builtins_object__.__setattr__(self,'kind',kind)\n  __dataclass_builtins_object__.__setattr__(self,'start',start)\n  __dataclass_builtins_object__.__setattr__(self,'end',end)\n  __dataclass_builtins_object__.__setattr__(self,'line',line)\n  __dataclass_builtins_object__.__setattr__(self,'block',block)\n  __dataclass_builtins_object__.__setattr__(self,'tool_length',tool_length)\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n  __dataclass_builtins_object__.__setattr__(self,'plane',plane)\n  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)\n  __dataclass_builtins_object__.__setattr__(self,'turns',turns)\n  __dataclass_builtins_object__.__setattr__(self,'feed',feed)\n  __dataclass_builtins_object__.__setattr__(self,'file',file)\n  __dataclass_builtins_object__.__setattr__(self,'objects',objects)\n  __dataclass_builtins_object__.__setattr__(self,'dwell',dwell)\n  __dataclass_builtins_object__.__setattr__(self,'derived',derived)\n  __dataclass_builtins_object__.__setattr__(self,'frame',frame)\n  __dataclass_builtins_object__.__setattr__(self,'radius',radius)\n  __dataclass_builtins_object__.__setattr__(self,'tool_register',tool_register)\n  __dataclass_builtins_object__.__setattr__(self,'tools_known',tools_known)\n return __init__": f151,
    "def __create_fn__(_type_blend, _type_tolerance, _type_naive, _type_dialect, _type_code, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_tolerance, _dflt_naive, _dflt_dialect, _dflt_code, _return_type):\n def __init__(self,blend:_type_blend,tolerance:_type_tolerance=_dflt_tolerance,naive:_type_naive=_dflt_naive,dialect:_type_dialect=_dflt_dialect,code:_type_code=_dflt_code)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'blend',blend)\n  __dataclass_builtins_object__.__setattr__(self,'tolerance',tolerance)\n  __dataclass_builtins_object__.__setattr__(self,'naive',naive)\n  __dataclass_builtins_object__.__setattr__(self,'dialect',dialect)\n  __dataclass_builtins_object__.__setattr__(self,'code',code)\n return __init__": f152,
    "def __create_fn__(_type_block, _type_span, _type_zone, _type_point, _type_path_point, _type_parameter, _type_parameter_exact, _type_first_exit, _type_first_exit_parameter, _type_first_exit_exact, _type_depth, _type_depth_exact, _type_engine, _type_segment_kind, _type_derived, _type_kind, _type_params, _type_zones, _type_note, _type_on_path, _type_break_line, _type_break_parameter, _type_break_point, _type_leg, _type_switches, _type_exit_located, _type_frame, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_derived, _dflt_kind, _dflt_params, _dflt_zones, _dflt_note, _dflt_on_path, _dflt_break_line, _dflt_break_parameter, _dflt_break_point, _dflt_leg, _dflt_switches, _dflt_exit_located, _dflt_frame, _return_type):\n def __init__(self,block:_type_block,span:_type_span,zone:_type_zone,point:_type_point,path_point:_type_path_point,parameter:_type_parameter,parameter_exact:_type_parameter_exact,first_exit:_type_first_exit,first_exit_parameter:_type_first_exit_parameter,first_exit_exact:_type_first_exit_exact,depth:_type_depth,depth_exact:_type_depth_exact,engine:_type_engine,segment_kind:_type_segment_kind,derived:_type_derived=_dflt_derived,kind:_type_kind=_dflt_kind,params:_type_params=_dflt_params,zones:_type_zones=_dflt_zones,note:_type_note=_dflt_note,on_path:_type_on_path=_dflt_on_path,break_line:_type_break_line=_dflt_break_line,break_parameter:_type_break_parameter=_dflt_break_parameter,break_point:_type_break_point=_dflt_break_point,leg:_type_leg=_dflt_leg,switches:_type_switches=_dflt_switches,exit_located:_type_exit_located=_dflt_exit_located,frame:_type_frame=_dflt_frame)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'block',block)\n  __dataclass_builtins_object__.__setattr__(self,'span',span)\n  __dataclass_builtins_object__.__setattr__(self,'zone',zone)\n  __dataclass_builtins_object__.__setattr__(self,'point',point)\n  __dataclass_builtins_object__.__setattr__(self,'path_point',path_point)\n  __dataclass_builtins_object__.__setattr__(self,'parameter',parameter)\n  __dataclass_builtins_object__.__setattr__(self,'parameter_exact',parameter_exact)\n  __dataclass_builtins_object__.__setattr__(self,'first_exit',first_exit)\n  __dataclass_builtins_object__.__setattr__(self,'first_exit_parameter',first_exit_parameter)\n  __dataclass_builtins_object__.__setattr__(self,'first_exit_exact',first_exit_exact)\n  __dataclass_builtins_object__.__setattr__(self,'depth',depth)\n  __dataclass_builtins_object__.__setattr__(self,'depth_exact',depth_exact)\n  __dataclass_builtins_object__.__setattr__(self,'engine',engine)\n  __dataclass_builtins_object__.__setattr__(self,'segment_kind',segment_kind)\n  __dataclass_builtins_object__.__setattr__(self,'derived',derived)\n  __dataclass_builtins_object__.__setattr__(self,'kind',kind)\n  __dataclass_builtins_object__.__setattr__(self,'params',params)\n  __dataclass_builtins_object__.__setattr__(self,'zones',zones)\n  __dataclass_builtins_object__.__setattr__(self,'note',note)\n  __dataclass_builtins_object__.__setattr__(self,'on_path',on_path)\n  __dataclass_builtins_object__.__setattr__(self,'break_line',break_line)\n  __dataclass_builtins_object__.__setattr__(self,'break_parameter',break_parameter)\n  __dataclass_builtins_object__.__setattr__(self,'break_point',break_point)\n  __dataclass_builtins_object__.__setattr__(self,'leg',leg)\n  __dataclass_builtins_object__.__setattr__(self,'switches',switches)\n  __dataclass_builtins_object__.__setattr__(self,'exit_located',exit_located)\n  __dataclass_builtins_object__.__setattr__(self,'frame',frame)\n return __init__": f153,
    "def __create_fn__(_type_code, _type_message, _type_span, _type_severity, _type_file, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_span, _dflt_severity, _dflt_file, _return_type):\n def __init__(self,code:_type_code,message:_type_message,span:_type_span=_dflt_span,severity:_type_severity=_dflt_severity,file:_type_file=_dflt_file)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'code',code)\n  __dataclass_builtins_object__.__setattr__(self,'message',message)\n  __dataclass_builtins_object__.__setattr__(self,'span',span)\n  __dataclass_builtins_object__.__setattr__(self,'severity',severity)\n  __dataclass_builtins_object__.__setattr__(self,'file',file)\n return __init__": f154,
    "def __create_fn__(_type_code, _type_reason, _type_span, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,code:_type_code,reason:_type_reason,span:_type_span)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'code',code)\n  __dataclass_builtins_object__.__setattr__(self,'reason',reason)\n  __dataclass_builtins_object__.__setattr__(self,'span',span)\n return __init__": f155,
    "def __create_fn__(_type_decimal_point_input, _type_increment_system, _type_g73_retract, _type_g83_clearance, _type_boring_shift, _type_scaling_unit, _type_rotation_incremental, _type_atan_signed, _type_tool_length_motion, _type_harmless_m, _type_references, _type_variables, _type_macros, _type_gcode_system, _type_g71_depth, _type_g71_retract, _type_roughing_final_pass, _type_g73_relief_x, _type_g73_relief_z, _type_g73_divisions, _type_g74_retract, _type_thread_chamfer, _type_thread_chamfer_angle, _type_g76_finish_passes, _type_g76_tool_angle, _type_g76_min_depth, _type_g76_finish_allowance, _type_tool_offset_motion, _type_tool_offset_cancel, _type_path, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_decimal_point_input, _dflt_increment_system, _dflt_g73_retract, _dflt_g83_clearance, _dflt_boring_shift, _dflt_scaling_unit, _dflt_rotation_incremental, _dflt_atan_signed, _dflt_tool_length_motion, _dflt_harmless_m, _dflt_references, _dflt_variables, _dflt_macros, _dflt_gcode_system, _dflt_g71_depth, _dflt_g71_retract, _dflt_roughing_final_pass, _dflt_g73_relief_x, _dflt_g73_relief_z, _dflt_g73_divisions, _dflt_g74_retract, _dflt_thread_chamfer, _dflt_thread_chamfer_angle, _dflt_g76_finish_passes, _dflt_g76_tool_angle, _dflt_g76_min_depth, _dflt_g76_finish_allowance, _dflt_tool_offset_motion, _dflt_tool_offset_cancel, _dflt_path, _return_type):\n def __init__(self,decimal_point_input:_type_decimal_point_input=_dflt_decimal_point_input,increment_system:_type_increment_system=_dflt_increment_system,g73_retract:_type_g73_retract=_dflt_g73_retract,g83_clearance:_type_g83_clearance=_dflt_g83_clearance,boring_shift:_type_boring_shift=_dflt_boring_shift,scaling_unit:_type_scaling_unit=_dflt_scaling_unit,rotation_incremental:_type_rotation_incremental=_dflt_rotation_incremental,atan_signed:_type_atan_signed=_dflt_atan_signed,tool_length_motion:_type_tool_length_motion=_dflt_tool_length_motion,harmless_m:_type_harmless_m=_dflt_harmless_m,references:_type_references=_HAS_DEFAULT_FACTORY,variables:_type_variables=_HAS_DEFAULT_FACTORY,macros:_type_macros=_HAS_DEFAULT_FACTORY,gcode_system:_type_gcode_system=_dflt_gcode_system,g71_depth:_type_g71_depth=_dflt_g71_depth,g71_retract:_type_g71_retract=_dflt_g71_retract,roughing_final_pass:_type_roughing_final_pass=_dflt_roughing_final_pass,g73_relief_x:_type_g73_relief_x=_dflt_g73_relief_x,g73_relief_z:_type_g73_relief_z=_dflt_g73_relief_z,g73_divisions:_type_g73_divisions=_dflt_g73_divisions,g74_retract:_type_g74_retract=_dflt_g74_retract,thread_chamfer:_type_thread_chamfer=_dflt_thread_chamfer,thread_chamfer_angle:_type_thread_chamfer_angle=_dflt_thread_chamfer_angle,g76_finish_passes:_type_g76_finish_passes=_dflt_g76_finish_passes,g76_tool_angle:_type_g76_tool_angle=_dflt_g76_tool_angle,g76_min_depth:_type_g76_min_depth=_dflt_g76_min_depth,g76_finish_allowance:_type_g76_finish_allowance=_dflt_g76_finish_allowance,tool_offset_motion:_type_tool_offset_motion=_dflt_tool_offset_motion,tool_offset_cancel:_type_tool_offset_cancel=_dflt_tool_offset_cancel,path:_type_path=_dflt_path)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'decimal_point_input',decimal_point_input)\n  __dataclass_builtins_object__.__setattr__(self,'increment_system',increment_system)\n  __dataclass_builtins_object__.__setattr__(self,'g73_retract',g73_retract)\n  __dataclass_builtins_object__.__setattr__(self,'g83_clearance',g83_clearance)\n  __dataclass_builtins_object__.__setattr__(self,'boring_shift',boring_shift)\n  __dataclass_builtins_object__.__setattr__(self,'scaling_unit',scaling_unit)\n  __dataclass_builtins_object__.__setattr__(self,'rotation_incremental',rotation_incremental)\n  __dataclass_builtins_object__.__setattr__(self,'atan_signed',atan_signed)\n  __dataclass_builtins_object__.__setattr__(self,'tool_length_motion',tool_length_motion)\n  __dataclass_builtins_object__.__setattr__(self,'harmless_m',harmless_m)\n  __dataclass_builtins_object__.__setattr__(self,'references',_dflt_references() if references is _HAS_DEFAULT_FACTORY else references)\n  __dataclass_builtins_object__.__setattr__(self,'variables',_dflt_variables() if variables is _HAS_DEFAULT_FACTORY else variables)\n  __dataclass_builtins_object__.__setattr__(self,'macros',_dflt_macros() if macros is _HAS_DEFAULT_FACTORY else macros)\n  __dataclass_builtins_object__.__setattr__(self,'gcode_system',gcode_system)\n  __dataclass_builtins_object__.__setattr__(self,'g71_depth',g71_depth)\n  __dataclass_builtins_object__.__setattr__(self,'g71_retract',g71_retract)\n  __dataclass_builtins_object__.__setattr__(self,'roughing_final_pass',roughing_final_pass)\n  __dataclass_builtins_object__.__setattr__(self,'g73_relief_x',g73_relief_x)\n  __dataclass_builtins_object__.__setattr__(self,'g73_relief_z',g73_relief_z)\n  __dataclass_builtins_object__.__setattr__(self,'g73_divisions',g73_divisions)\n  __dataclass_builtins_object__.__setattr__(self,'g74_retract',g74_retract)\n  __dataclass_builtins_object__.__setattr__(self,'thread_chamfer',thread_chamfer)\n  __dataclass_builtins_object__.__setattr__(self,'thread_chamfer_angle',thread_chamfer_angle)\n  __dataclass_builtins_object__.__setattr__(self,'g76_finish_passes',g76_finish_passes)\n  __dataclass_builtins_object__.__setattr__(self,'g76_tool_angle',g76_tool_angle)\n  __dataclass_builtins_object__.__setattr__(self,'g76_min_depth',g76_min_depth)\n  __dataclass_builtins_object__.__setattr__(self,'g76_finish_allowance',g76_finish_allowance)\n  __dataclass_builtins_object__.__setattr__(self,'tool_offset_motion',tool_offset_motion)\n  __dataclass_builtins_object__.__setattr__(self,'tool_offset_cancel',tool_offset_cancel)\n  __dataclass_builtins_object__.__setattr__(self,'path',path)\n return __init__": f156,
    "def __create_fn__(_type_degree, _type_knots, _type_control, _type_weights, _type_source, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_source, _return_type):\n def __init__(self,degree:_type_degree,knots:_type_knots,control:_type_control,weights:_type_weights,source:_type_source=_dflt_source)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'degree',degree)\n  __dataclass_builtins_object__.__setattr__(self,'knots',knots)\n  __dataclass_builtins_object__.__setattr__(self,'control',control)\n  __dataclass_builtins_object__.__setattr__(self,'weights',weights)\n  __dataclass_builtins_object__.__setattr__(self,'source',source)\n return __init__": f157,
    "def __create_fn__(_type_delete, _type_number, _type_oword, _type_words, _type_assigns, _type_comments, _type_percent, _type_unsupported, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_delete, _dflt_number, _dflt_oword, _dflt_words, _dflt_assigns, _dflt_comments, _dflt_percent, _dflt_unsupported, _return_type):\n def __init__(self,delete:_type_delete=_dflt_delete,number:_type_number=_dflt_number,oword:_type_oword=_dflt_oword,words:_type_words=_dflt_words,assigns:_type_assigns=_dflt_assigns,comments:_type_comments=_dflt_comments,percent:_type_percent=_dflt_percent,unsupported:_type_unsupported=_dflt_unsupported)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'delete',delete)\n  __dataclass_builtins_object__.__setattr__(self,'number',number)\n  __dataclass_builtins_object__.__setattr__(self,'oword',oword)\n  __dataclass_builtins_object__.__setattr__(self,'words',words)\n  __dataclass_builtins_object__.__setattr__(self,'assigns',assigns)\n  __dataclass_builtins_object__.__setattr__(self,'comments',comments)\n  __dataclass_builtins_object__.__setattr__(self,'percent',percent)\n  __dataclass_builtins_object__.__setattr__(self,'unsupported',unsupported)\n return __init__": f158,
    "def __create_fn__(_type_delete, _type_number, _type_program, _type_words, _type_assigns, _type_comments, _type_stmt, _type_stmt_at, _type_percent, _type_unmodelled, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_delete, _dflt_number, _dflt_program, _dflt_words, _dflt_assigns, _dflt_comments, _dflt_stmt, _dflt_stmt_at, _dflt_percent, _dflt_unmodelled, _return_type):\n def __init__(self,delete:_type_delete=_dflt_delete,number:_type_number=_dflt_number,program:_type_program=_dflt_program,words:_type_words=_dflt_words,assigns:_type_assigns=_dflt_assigns,comments:_type_comments=_dflt_comments,stmt:_type_stmt=_dflt_stmt,stmt_at:_type_stmt_at=_dflt_stmt_at,percent:_type_percent=_dflt_percent,unmodelled:_type_unmodelled=_dflt_unmodelled)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'delete',delete)\n  __dataclass_builtins_object__.__setattr__(self,'number',number)\n  __dataclass_builtins_object__.__setattr__(self,'program',program)\n  __dataclass_builtins_object__.__setattr__(self,'words',words)\n  __dataclass_builtins_object__.__setattr__(self,'assigns',assigns)\n  __dataclass_builtins_object__.__setattr__(self,'comments',comments)\n  __dataclass_builtins_object__.__setattr__(self,'stmt',stmt)\n  __dataclass_builtins_object__.__setattr__(self,'stmt_at',stmt_at)\n  __dataclass_builtins_object__.__setattr__(self,'percent',percent)\n  __dataclass_builtins_object__.__setattr__(self,'unmodelled',unmodelled)\n return __init__": f159,
    "def __create_fn__(_type_file, _type_line, _type_column, _type_end_column, _type_text, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_column, _dflt_end_column, _dflt_text, _return_type):\n def __init__(self,file:_type_file,line:_type_line,column:_type_column=_dflt_column,end_column:_type_end_column=_dflt_end_column,text:_type_text=_dflt_text)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'file',file)\n  __dataclass_builtins_object__.__setattr__(self,'line',line)\n  __dataclass_builtins_object__.__setattr__(self,'column',column)\n  __dataclass_builtins_object__.__setattr__(self,'end_column',end_column)\n  __dataclass_builtins_object__.__setattr__(self,'text',text)\n return __init__": f160,
    "def __create_fn__(_type_ia, _type_ib, _type_s, _type_e, _type_ccw, _type_full, _type_centre, _type_r_signed, _type_r2_lo, _type_r2_hi, _type_start, _type_end, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,ia:_type_ia,ib:_type_ib,s:_type_s,e:_type_e,ccw:_type_ccw,full:_type_full,centre:_type_centre,r_signed:_type_r_signed,r2_lo:_type_r2_lo,r2_hi:_type_r2_hi,start:_type_start,end:_type_end)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'ia',ia)\n  __dataclass_builtins_object__.__setattr__(self,'ib',ib)\n  __dataclass_builtins_object__.__setattr__(self,'s',s)\n  __dataclass_builtins_object__.__setattr__(self,'e',e)\n  __dataclass_builtins_object__.__setattr__(self,'ccw',ccw)\n  __dataclass_builtins_object__.__setattr__(self,'full',full)\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n  __dataclass_builtins_object__.__setattr__(self,'r_signed',r_signed)\n  __dataclass_builtins_object__.__setattr__(self,'r2_lo',r2_lo)\n  __dataclass_builtins_object__.__setattr__(self,'r2_hi',r2_hi)\n  __dataclass_builtins_object__.__setattr__(self,'start',start)\n  __dataclass_builtins_object__.__setattr__(self,'end',end)\n return __init__": f161,
    "def __create_fn__(_type_key, _type_group, _type_lanes, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,key:_type_key,group:_type_group,lanes:_type_lanes)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'key',key)\n  __dataclass_builtins_object__.__setattr__(self,'group',group)\n  __dataclass_builtins_object__.__setattr__(self,'lanes',lanes)\n return __init__": f162,
    "def __create_fn__(_type_key, _type_meaning, _type_read, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,key:_type_key,meaning:_type_meaning,read:_type_read)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'key',key)\n  __dataclass_builtins_object__.__setattr__(self,'meaning',meaning)\n  __dataclass_builtins_object__.__setattr__(self,'read',read)\n return __init__": f163,
    'def __create_fn__(_type_kind, _type_label, _type_head, _type_remaining, _type_count, _type_ifs, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_remaining, _dflt_count, _dflt_ifs, _return_type):\n def __init__(self,kind:_type_kind,label:_type_label,head:_type_head,remaining:_type_remaining=_dflt_remaining,count:_type_count=_dflt_count,ifs:_type_ifs=_dflt_ifs)->_return_type:\n  self.kind=kind\n  self.label=label\n  self.head=head\n  self.remaining=remaining\n  self.count=count\n  self.ifs=ifs\n return __init__': f164,
    'def __create_fn__(_type_kind, _type_label, _type_ret, _type_saved, _type_body, _type_repeats, _type_loops, _type_ifs, _type_caller, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_label, _dflt_ret, _dflt_saved, _dflt_body, _dflt_repeats, _dflt_loops, _dflt_ifs, _dflt_caller, _return_type):\n def __init__(self,kind:_type_kind,label:_type_label=_dflt_label,ret:_type_ret=_dflt_ret,saved:_type_saved=_dflt_saved,body:_type_body=_dflt_body,repeats:_type_repeats=_dflt_repeats,loops:_type_loops=_HAS_DEFAULT_FACTORY,ifs:_type_ifs=_HAS_DEFAULT_FACTORY,caller:_type_caller=_dflt_caller)->_return_type:\n  self.kind=kind\n  self.label=label\n  self.ret=ret\n  self.saved=saved\n  self.body=body\n  self.repeats=repeats\n  self.loops=_dflt_loops() if loops is _HAS_DEFAULT_FACTORY else loops\n  self.ifs=_dflt_ifs() if ifs is _HAS_DEFAULT_FACTORY else ifs\n  self.caller=caller\n return __init__': f165,
    'def __create_fn__(_type_kind, _type_source, _type_program, _type_ret, _type_body, _type_repeats, _type_saved, _type_args, _type_loops, _type_custom, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_program, _dflt_ret, _dflt_body, _dflt_repeats, _dflt_saved, _dflt_args, _dflt_loops, _dflt_custom, _return_type):\n def __init__(self,kind:_type_kind,source:_type_source,program:_type_program=_dflt_program,ret:_type_ret=_dflt_ret,body:_type_body=_dflt_body,repeats:_type_repeats=_dflt_repeats,saved:_type_saved=_dflt_saved,args:_type_args=_dflt_args,loops:_type_loops=_HAS_DEFAULT_FACTORY,custom:_type_custom=_dflt_custom)->_return_type:\n  self.kind=kind\n  self.source=source\n  self.program=program\n  self.ret=ret\n  self.body=body\n  self.repeats=repeats\n  self.saved=saved\n  self.args=args\n  self.loops=_dflt_loops() if loops is _HAS_DEFAULT_FACTORY else loops\n  self.custom=custom\n return __init__': f166,
    "def __create_fn__(_type_kind, _type_start, _type_end, _type_axes, _type_block, _type_span, _type_tool_length, _type_feed_mm_min, _type_plane, _type_clockwise, _type_centre, _type_radius, _type_turns, _type_dwell_s, _type_derived, _type_tool_register, _type_deps_start, _type_deps_end, _type_deps_tool, _type_extra, _type_frame, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_block, _dflt_span, _dflt_tool_length, _dflt_feed_mm_min, _dflt_plane, _dflt_clockwise, _dflt_centre, _dflt_radius, _dflt_turns, _dflt_dwell_s, _dflt_derived, _dflt_tool_register, _dflt_deps_start, _dflt_deps_end, _dflt_deps_tool, _dflt_extra, _dflt_frame, _return_type):\n def __init__(self,kind:_type_kind,start:_type_start,end:_type_end,axes:_type_axes,block:_type_block=_dflt_block,span:_type_span=_dflt_span,tool_length:_type_tool_length=_dflt_tool_length,feed_mm_min:_type_feed_mm_min=_dflt_feed_mm_min,plane:_type_plane=_dflt_plane,clockwise:_type_clockwise=_dflt_clockwise,centre:_type_centre=_dflt_centre,radius:_type_radius=_dflt_radius,turns:_type_turns=_dflt_turns,dwell_s:_type_dwell_s=_dflt_dwell_s,derived:_type_derived=_dflt_derived,tool_register:_type_tool_register=_dflt_tool_register,deps_start:_type_deps_start=_dflt_deps_start,deps_end:_type_deps_end=_dflt_deps_end,deps_tool:_type_deps_tool=_dflt_deps_tool,extra:_type_extra=_dflt_extra,frame:_type_frame=_dflt_frame)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'kind',kind)\n  __dataclass_builtins_object__.__setattr__(self,'start',start)\n  __dataclass_builtins_object__.__setattr__(self,'end',end)\n  __dataclass_builtins_object__.__setattr__(self,'axes',axes)\n  __dataclass_builtins_object__.__setattr__(self,'block',block)\n  __dataclass_builtins_object__.__setattr__(self,'span',span)\n  __dataclass_builtins_object__.__setattr__(self,'tool_length',tool_length)\n  __dataclass_builtins_object__.__setattr__(self,'feed_mm_min',feed_mm_min)\n  __dataclass_builtins_object__.__setattr__(self,'plane',plane)\n  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n  __dataclass_builtins_object__.__setattr__(self,'radius',radius)\n  __dataclass_builtins_object__.__setattr__(self,'turns',turns)\n  __dataclass_builtins_object__.__setattr__(self,'dwell_s',dwell_s)\n  __dataclass_builtins_object__.__setattr__(self,'derived',derived)\n  __dataclass_builtins_object__.__setattr__(self,'tool_register',tool_register)\n  __dataclass_builtins_object__.__setattr__(self,'deps_start',deps_start)\n  __dataclass_builtins_object__.__setattr__(self,'deps_end',deps_end)\n  __dataclass_builtins_object__.__setattr__(self,'deps_tool',deps_tool)\n  __dataclass_builtins_object__.__setattr__(self,'extra',extra)\n  __dataclass_builtins_object__.__setattr__(self,'frame',frame)\n return __init__": f167,
    "def __create_fn__(_type_label, _type_keyword, _type_args, _type_column, _type_end_column, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,label:_type_label,keyword:_type_keyword,args:_type_args,column:_type_column,end_column:_type_end_column)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'label',label)\n  __dataclass_builtins_object__.__setattr__(self,'keyword',keyword)\n  __dataclass_builtins_object__.__setattr__(self,'args',args)\n  __dataclass_builtins_object__.__setattr__(self,'column',column)\n  __dataclass_builtins_object__.__setattr__(self,'end_column',end_column)\n return __init__": f168,
    "def __create_fn__(_type_lane, _type_g, _type_m, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,lane:_type_lane,g:_type_g,m:_type_m)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'lane',lane)\n  __dataclass_builtins_object__.__setattr__(self,'g',g)\n  __dataclass_builtins_object__.__setattr__(self,'m',m)\n return __init__": f169,
    "def __create_fn__(_type_letter, _type_value, _type_span, _type_text, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_text, _return_type):\n def __init__(self,letter:_type_letter,value:_type_value,span:_type_span,text:_type_text=_dflt_text)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'letter',letter)\n  __dataclass_builtins_object__.__setattr__(self,'value',value)\n  __dataclass_builtins_object__.__setattr__(self,'span',span)\n  __dataclass_builtins_object__.__setattr__(self,'text',text)\n return __init__": f170,
    "def __create_fn__(_type_linear_axis, _type_rotary_axis, _type_cylinder_radius, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,linear_axis:_type_linear_axis,rotary_axis:_type_rotary_axis,cylinder_radius:_type_cylinder_radius)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'linear_axis',linear_axis)\n  __dataclass_builtins_object__.__setattr__(self,'rotary_axis',rotary_axis)\n  __dataclass_builtins_object__.__setattr__(self,'cylinder_radius',cylinder_radius)\n return __init__": f171,
    "def __create_fn__(_type_lo, _type_hi, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,lo:_type_lo,hi:_type_hi)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'lo',lo)\n  __dataclass_builtins_object__.__setattr__(self,'hi',hi)\n return __init__": f172,
    "def __create_fn__(_type_lo, _type_hi, _type_lo_closed, _type_hi_closed, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,lo:_type_lo,hi:_type_hi,lo_closed:_type_lo_closed,hi_closed:_type_hi_closed)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'lo',lo)\n  __dataclass_builtins_object__.__setattr__(self,'hi',hi)\n  __dataclass_builtins_object__.__setattr__(self,'lo_closed',lo_closed)\n  __dataclass_builtins_object__.__setattr__(self,'hi_closed',hi_closed)\n return __init__": f173,
    'def __create_fn__(_type_m, _type_head, _type_count, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_count, _return_type):\n def __init__(self,m:_type_m,head:_type_head,count:_type_count=_dflt_count)->_return_type:\n  self.m=m\n  self.head=head\n  self.count=count\n return __init__': f174,
    "def __create_fn__(_type_margin, _type_params, _type_engine, _type_max_violations, _type_arc_tolerance, _type_recovery, _type_max_iterations, _type_dialect, _type_library, _type_block_delete, _type_budget_s, _type_limits, _type_tool_table, _type_tool_table_units, _type_tool_table_x_offset, _type_written, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_margin, _dflt_params, _dflt_engine, _dflt_max_violations, _dflt_arc_tolerance, _dflt_recovery, _dflt_max_iterations, _dflt_dialect, _dflt_library, _dflt_block_delete, _dflt_budget_s, _dflt_limits, _dflt_tool_table, _dflt_tool_table_units, _dflt_tool_table_x_offset, _dflt_written, _return_type):\n def __init__(self,margin:_type_margin=_dflt_margin,params:_type_params=_dflt_params,engine:_type_engine=_dflt_engine,max_violations:_type_max_violations=_dflt_max_violations,arc_tolerance:_type_arc_tolerance=_dflt_arc_tolerance,recovery:_type_recovery=_dflt_recovery,max_iterations:_type_max_iterations=_dflt_max_iterations,dialect:_type_dialect=_dflt_dialect,library:_type_library=_dflt_library,block_delete:_type_block_delete=_dflt_block_delete,budget_s:_type_budget_s=_dflt_budget_s,limits:_type_limits=_dflt_limits,tool_table:_type_tool_table=_dflt_tool_table,tool_table_units:_type_tool_table_units=_dflt_tool_table_units,tool_table_x_offset:_type_tool_table_x_offset=_dflt_tool_table_x_offset,written:_type_written=_dflt_written)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'margin',margin)\n  __dataclass_builtins_object__.__setattr__(self,'params',params)\n  __dataclass_builtins_object__.__setattr__(self,'engine',engine)\n  __dataclass_builtins_object__.__setattr__(self,'max_violations',max_violations)\n  __dataclass_builtins_object__.__setattr__(self,'arc_tolerance',arc_tolerance)\n  __dataclass_builtins_object__.__setattr__(self,'recovery',recovery)\n  __dataclass_builtins_object__.__setattr__(self,'max_iterations',max_iterations)\n  __dataclass_builtins_object__.__setattr__(self,'dialect',dialect)\n  __dataclass_builtins_object__.__setattr__(self,'library',library)\n  __dataclass_builtins_object__.__setattr__(self,'block_delete',block_delete)\n  __dataclass_builtins_object__.__setattr__(self,'budget_s',budget_s)\n  __dataclass_builtins_object__.__setattr__(self,'limits',limits)\n  __dataclass_builtins_object__.__setattr__(self,'tool_table',tool_table)\n  __dataclass_builtins_object__.__setattr__(self,'tool_table_units',tool_table_units)\n  __dataclass_builtins_object__.__setattr__(self,'tool_table_x_offset',tool_table_x_offset)\n  __dataclass_builtins_object__.__setattr__(self,'written',written)\n return __init__": f175,
    "def __create_fn__(_type_message, _type_span, _type_block, _type_code, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_span, _dflt_block, _dflt_code, _return_type):\n def __init__(self,message:_type_message,span:_type_span=_dflt_span,block:_type_block=_dflt_block,code:_type_code=_dflt_code)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'message',message)\n  __dataclass_builtins_object__.__setattr__(self,'span',span)\n  __dataclass_builtins_object__.__setattr__(self,'block',block)\n  __dataclass_builtins_object__.__setattr__(self,'code',code)\n return __init__": f176,
    "def __create_fn__(_type_missing, _type_on_fallback, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,missing:_type_missing,on_fallback:_type_on_fallback)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'missing',missing)\n  __dataclass_builtins_object__.__setattr__(self,'on_fallback',on_fallback)\n return __init__": f177,
    "def __create_fn__(_type_name, _type_limits, _type_forbid, _type_point, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_forbid, _dflt_point, _return_type):\n def __init__(self,name:_type_name,limits:_type_limits,forbid:_type_forbid=_dflt_forbid,point:_type_point=_dflt_point)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'name',name)\n  __dataclass_builtins_object__.__setattr__(self,'limits',limits)\n  __dataclass_builtins_object__.__setattr__(self,'forbid',forbid)\n  __dataclass_builtins_object__.__setattr__(self,'point',point)\n return __init__": f178,
    "def __create_fn__(_type_name, _type_lo, _type_hi, _type_written, _type_absolute, _type_lo_open, _type_hi_open, _type_centre, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_absolute, _dflt_lo_open, _dflt_hi_open, _dflt_centre, _return_type):\n def __init__(self,name:_type_name,lo:_type_lo,hi:_type_hi,written:_type_written,absolute:_type_absolute=_dflt_absolute,lo_open:_type_lo_open=_dflt_lo_open,hi_open:_type_hi_open=_dflt_hi_open,centre:_type_centre=_dflt_centre)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'name',name)\n  __dataclass_builtins_object__.__setattr__(self,'lo',lo)\n  __dataclass_builtins_object__.__setattr__(self,'hi',hi)\n  __dataclass_builtins_object__.__setattr__(self,'written',written)\n  __dataclass_builtins_object__.__setattr__(self,'absolute',absolute)\n  __dataclass_builtins_object__.__setattr__(self,'lo_open',lo_open)\n  __dataclass_builtins_object__.__setattr__(self,'hi_open',hi_open)\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n return __init__": f179,
    "def __create_fn__(_type_name, _type_max_passes, _type_spent, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_spent, _return_type):\n def __init__(self,name:_type_name,max_passes:_type_max_passes,spent:_type_spent=_dflt_spent)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'name',name)\n  __dataclass_builtins_object__.__setattr__(self,'max_passes',max_passes)\n  __dataclass_builtins_object__.__setattr__(self,'spent',spent)\n return __init__": f180,
    "def __create_fn__(_type_name, _type_plane, _type_vertices, _type_limits, _type_forbid, _type_point, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_limits, _dflt_forbid, _dflt_point, _return_type):\n def __init__(self,name:_type_name,plane:_type_plane,vertices:_type_vertices,limits:_type_limits=_dflt_limits,forbid:_type_forbid=_dflt_forbid,point:_type_point=_dflt_point)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'name',name)\n  __dataclass_builtins_object__.__setattr__(self,'plane',plane)\n  __dataclass_builtins_object__.__setattr__(self,'vertices',vertices)\n  __dataclass_builtins_object__.__setattr__(self,'limits',limits)\n  __dataclass_builtins_object__.__setattr__(self,'forbid',forbid)\n  __dataclass_builtins_object__.__setattr__(self,'point',point)\n return __init__": f181,
    "def __create_fn__(_type_name, _type_pulse, _type_rapid_mm_min, _type_max_feed_mm_min, _type_rotary, _type_accel_mm_s2, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_rotary, _dflt_accel_mm_s2, _return_type):\n def __init__(self,name:_type_name,pulse:_type_pulse,rapid_mm_min:_type_rapid_mm_min,max_feed_mm_min:_type_max_feed_mm_min,rotary:_type_rotary=_dflt_rotary,accel_mm_s2:_type_accel_mm_s2=_dflt_accel_mm_s2)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'name',name)\n  __dataclass_builtins_object__.__setattr__(self,'pulse',pulse)\n  __dataclass_builtins_object__.__setattr__(self,'rapid_mm_min',rapid_mm_min)\n  __dataclass_builtins_object__.__setattr__(self,'max_feed_mm_min',max_feed_mm_min)\n  __dataclass_builtins_object__.__setattr__(self,'rotary',rotary)\n  __dataclass_builtins_object__.__setattr__(self,'accel_mm_s2',accel_mm_s2)\n return __init__": f182,
    "def __create_fn__(_type_name, _type_reference_axis, _type_limited_axis, _type_start, _type_regions, _type_forbid, _type_point, _type__steps, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_forbid, _dflt_point, _dflt__steps, _return_type):\n def __init__(self,name:_type_name,reference_axis:_type_reference_axis,limited_axis:_type_limited_axis,start:_type_start,regions:_type_regions,forbid:_type_forbid=_dflt_forbid,point:_type_point=_dflt_point)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'name',name)\n  __dataclass_builtins_object__.__setattr__(self,'reference_axis',reference_axis)\n  __dataclass_builtins_object__.__setattr__(self,'limited_axis',limited_axis)\n  __dataclass_builtins_object__.__setattr__(self,'start',start)\n  __dataclass_builtins_object__.__setattr__(self,'regions',regions)\n  __dataclass_builtins_object__.__setattr__(self,'forbid',forbid)\n  __dataclass_builtins_object__.__setattr__(self,'point',point)\n  __dataclass_builtins_object__.__setattr__(self,'_steps',_dflt__steps)\n return __init__": f183,
    "def __create_fn__(_type_name, _type_units, _type_axes, _type_rapid_mode, _type_monitor_period_ms, _type_reference, _type_start, _type_offsets, _type_tool_lengths, _type_allowed, _type_modal, _type_tool_axis, _type_source, _type_warnings, _type_sections, _type_cutter_compensation, _type_tool_diameters, _type_sha256, _type_dialect, _type_fanuc, _type_block_delete, _type_arc_tolerance, _type_path_mode, _type_path_tolerance, _type_machine_type, _type_diameter_axes, _type_tool_offsets, _type_tool_length_wear, _type_tool_radius_wear, _type_control_units, _type_tool_change_quill_up, _type_tool_change_at_g30, _type_tool_change_position, _type_subroutine_path, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_modal, _dflt_tool_axis, _dflt_source, _dflt_warnings, _dflt_sections, _dflt_cutter_compensation, _dflt_tool_diameters, _dflt_sha256, _dflt_dialect, _dflt_fanuc, _dflt_block_delete, _dflt_arc_tolerance, _dflt_path_mode, _dflt_path_tolerance, _dflt_machine_type, _dflt_diameter_axes, _dflt_tool_offsets, _dflt_tool_length_wear, _dflt_tool_radius_wear, _dflt_control_units, _dflt_tool_change_quill_up, _dflt_tool_change_at_g30, _dflt_tool_change_position, _dflt_subroutine_path, _return_type):\n def __init__(self,name:_type_name,units:_type_units,axes:_type_axes,rapid_mode:_type_rapid_mode,monitor_period_ms:_type_monitor_period_ms,reference:_type_reference,start:_type_start,offsets:_type_offsets,tool_lengths:_type_tool_lengths,allowed:_type_allowed,modal:_type_modal=_dflt_modal,tool_axis:_type_tool_axis=_dflt_tool_axis,source:_type_source=_dflt_source,warnings:_type_warnings=_dflt_warnings,sections:_type_sections=_HAS_DEFAULT_FACTORY,cutter_compensation:_type_cutter_compensation=_dflt_cutter_compensation,tool_diameters:_type_tool_diameters=_HAS_DEFAULT_FACTORY,sha256:_type_sha256=_dflt_sha256,dialect:_type_dialect=_dflt_dialect,fanuc:_type_fanuc=_HAS_DEFAULT_FACTORY,block_delete:_type_block_delete=_dflt_block_delete,arc_tolerance:_type_arc_tolerance=_dflt_arc_tolerance,path_mode:_type_path_mode=_dflt_path_mode,path_tolerance:_type_path_tolerance=_dflt_path_tolerance,machine_type:_type_machine_type=_dflt_machine_type,diameter_axes:_type_diameter_axes=_dflt_diameter_axes,tool_offsets:_type_tool_offsets=_HAS_DEFAULT_FACTORY,tool_length_wear:_type_tool_length_wear=_HAS_DEFAULT_FACTORY,tool_radius_wear:_type_tool_radius_wear=_HAS_DEFAULT_FACTORY,control_units:_type_control_units=_dflt_control_units,tool_change_quill_up:_type_tool_change_quill_up=_dflt_tool_change_quill_up,tool_change_at_g30:_type_tool_change_at_g30=_dflt_tool_change_at_g30,tool_change_position:_type_tool_change_position=_HAS_DEFAULT_FACTORY,subroutine_path:_type_subroutine_path=_dflt_subroutine_path)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'name',name)\n  __dataclass_builtins_object__.__setattr__(self,'units',units)\n  __dataclass_builtins_object__.__setattr__(self,'axes',axes)\n  __dataclass_builtins_object__.__setattr__(self,'rapid_mode',rapid_mode)\n  __dataclass_builtins_object__.__setattr__(self,'monitor_period_ms',monitor_period_ms)\n  __dataclass_builtins_object__.__setattr__(self,'reference',reference)\n  __dataclass_builtins_object__.__setattr__(self,'start',start)\n  __dataclass_builtins_object__.__setattr__(self,'offsets',offsets)\n  __dataclass_builtins_object__.__setattr__(self,'tool_lengths',tool_lengths)\n  __dataclass_builtins_object__.__setattr__(self,'allowed',allowed)\n  __dataclass_builtins_object__.__setattr__(self,'modal',modal)\n  __dataclass_builtins_object__.__setattr__(self,'tool_axis',tool_axis)\n  __dataclass_builtins_object__.__setattr__(self,'source',source)\n  __dataclass_builtins_object__.__setattr__(self,'warnings',warnings)\n  __dataclass_builtins_object__.__setattr__(self,'sections',_dflt_sections() if sections is _HAS_DEFAULT_FACTORY else sections)\n  __dataclass_builtins_object__.__setattr__(self,'cutter_compensation',cutter_compensation)\n  __dataclass_builtins_object__.__setattr__(self,'tool_diameters',_dflt_tool_diameters() if tool_diameters is _HAS_DEFAULT_FACTORY else tool_diameters)\n  __dataclass_builtins_object__.__setattr__(self,'sha256',sha256)\n  __dataclass_builtins_object__.__setattr__(self,'dialect',dialect)\n  __dataclass_builtins_object__.__setattr__(self,'fanuc',_dflt_fanuc() if fanuc is _HAS_DEFAULT_FACTORY else fanuc)\n  __dataclass_builtins_object__.__setattr__(self,'block_delete',block_delete)\n  __dataclass_builtins_object__.__setattr__(self,'arc_tolerance',arc_tolerance)\n  __dataclass_builtins_object__.__setattr__(self,'path_mode',path_mode)\n  __dataclass_builtins_object__.__setattr__(self,'path_tolerance',path_tolerance)\n  __dataclass_builtins_object__.__setattr__(self,'machine_type',machine_type)\n  __dataclass_builtins_object__.__setattr__(self,'diameter_axes',diameter_axes)\n  __dataclass_builtins_object__.__setattr__(self,'tool_offsets',_dflt_tool_offsets() if tool_offsets is _HAS_DEFAULT_FACTORY else tool_offsets)\n  __dataclass_builtins_object__.__setattr__(self,'tool_length_wear',_dflt_tool_length_wear() if tool_length_wear is _HAS_DEFAULT_FACTORY else tool_length_wear)\n  __dataclass_builtins_object__.__setattr__(self,'tool_radius_wear',_dflt_tool_radius_wear() if tool_radius_wear is _HAS_DEFAULT_FACTORY else tool_radius_wear)\n  __dataclass_builtins_object__.__setattr__(self,'control_units',control_units)\n  __dataclass_builtins_object__.__setattr__(self,'tool_change_quill_up',tool_change_quill_up)\n  __dataclass_builtins_object__.__setattr__(self,'tool_change_at_g30',tool_change_at_g30)\n  __dataclass_builtins_object__.__setattr__(self,'tool_change_position',_dflt_tool_change_position() if tool_change_position is _HAS_DEFAULT_FACTORY else tool_change_position)\n  __dataclass_builtins_object__.__setattr__(self,'subroutine_path',subroutine_path)\n return __init__": f184,
    "def __create_fn__(_type_number, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,number:_type_number)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'number',number)\n return __init__": f185,
    "def __create_fn__(_type_number, _type_geometry, _type_wear, _type_nose_radius, _type_wear_radius, _type_tip, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_geometry, _dflt_wear, _dflt_nose_radius, _dflt_wear_radius, _dflt_tip, _return_type):\n def __init__(self,number:_type_number,geometry:_type_geometry=_dflt_geometry,wear:_type_wear=_dflt_wear,nose_radius:_type_nose_radius=_dflt_nose_radius,wear_radius:_type_wear_radius=_dflt_wear_radius,tip:_type_tip=_dflt_tip)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'number',number)\n  __dataclass_builtins_object__.__setattr__(self,'geometry',geometry)\n  __dataclass_builtins_object__.__setattr__(self,'wear',wear)\n  __dataclass_builtins_object__.__setattr__(self,'nose_radius',nose_radius)\n  __dataclass_builtins_object__.__setattr__(self,'wear_radius',wear_radius)\n  __dataclass_builtins_object__.__setattr__(self,'tip',tip)\n return __init__": f186,
    "def __create_fn__(_type_offsets, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,offsets:_type_offsets)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'offsets',offsets)\n return __init__": f187,
    "def __create_fn__(_type_p0, _type_p1, _type_tau0, _type_tau1, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_tau0, _dflt_tau1, _return_type):\n def __init__(self,p0:_type_p0,p1:_type_p1,tau0:_type_tau0=_dflt_tau0,tau1:_type_tau1=_dflt_tau1)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'p0',p0)\n  __dataclass_builtins_object__.__setattr__(self,'p1',p1)\n  __dataclass_builtins_object__.__setattr__(self,'tau0',tau0)\n  __dataclass_builtins_object__.__setattr__(self,'tau1',tau1)\n return __init__": f188,
    "def __create_fn__(_type_start, _type_end, _type_turns, _type_x_off, _type_c_entry, _type_linear_axis, _type_rotary_axis, _type_grid, _type_arc, _type_centre, _type_radius, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_centre, _dflt_radius, _return_type):\n def __init__(self,start:_type_start,end:_type_end,turns:_type_turns,x_off:_type_x_off,c_entry:_type_c_entry,linear_axis:_type_linear_axis,rotary_axis:_type_rotary_axis,grid:_type_grid,arc:_type_arc,centre:_type_centre=_dflt_centre,radius:_type_radius=_dflt_radius)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'start',start)\n  __dataclass_builtins_object__.__setattr__(self,'end',end)\n  __dataclass_builtins_object__.__setattr__(self,'turns',turns)\n  __dataclass_builtins_object__.__setattr__(self,'x_off',x_off)\n  __dataclass_builtins_object__.__setattr__(self,'c_entry',c_entry)\n  __dataclass_builtins_object__.__setattr__(self,'linear_axis',linear_axis)\n  __dataclass_builtins_object__.__setattr__(self,'rotary_axis',rotary_axis)\n  __dataclass_builtins_object__.__setattr__(self,'grid',grid)\n  __dataclass_builtins_object__.__setattr__(self,'arc',arc)\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n  __dataclass_builtins_object__.__setattr__(self,'radius',radius)\n return __init__": f189,
    "def __create_fn__(_type_status, _type_values, _type_approximate, _type_stopped, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_approximate, _dflt_stopped, _return_type):\n def __init__(self,status:_type_status,values:_type_values,approximate:_type_approximate=_dflt_approximate,stopped:_type_stopped=_dflt_stopped)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'status',status)\n  __dataclass_builtins_object__.__setattr__(self,'values',values)\n  __dataclass_builtins_object__.__setattr__(self,'approximate',approximate)\n  __dataclass_builtins_object__.__setattr__(self,'stopped',stopped)\n return __init__": f190,
    "def __create_fn__(_type_summary, _type_configure, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,summary:_type_summary,configure:_type_configure)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'summary',summary)\n  __dataclass_builtins_object__.__setattr__(self,'configure',configure)\n return __init__": f191,
    "def __create_fn__(_type_text, _type_name, _type_digest, _type_path, _type_notes, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_path, _dflt_notes, _return_type):\n def __init__(self,text:_type_text,name:_type_name,digest:_type_digest,path:_type_path=_dflt_path,notes:_type_notes=_dflt_notes)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'text',text)\n  __dataclass_builtins_object__.__setattr__(self,'name',name)\n  __dataclass_builtins_object__.__setattr__(self,'digest',digest)\n  __dataclass_builtins_object__.__setattr__(self,'path',path)\n  __dataclass_builtins_object__.__setattr__(self,'notes',notes)\n return __init__": f192,
    "def __create_fn__(_type_upto, _type_min, _type_max, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_min, _dflt_max, _return_type):\n def __init__(self,upto:_type_upto,min:_type_min=_dflt_min,max:_type_max=_dflt_max)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'upto',upto)\n  __dataclass_builtins_object__.__setattr__(self,'min',min)\n  __dataclass_builtins_object__.__setattr__(self,'max',max)\n return __init__": f193,
    "def __create_fn__(_type_value, _type_deps, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_deps, _return_type):\n def __init__(self,value:_type_value,deps:_type_deps=_HAS_DEFAULT_FACTORY)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'value',value)\n  __dataclass_builtins_object__.__setattr__(self,'deps',_dflt_deps() if deps is _HAS_DEFAULT_FACTORY else deps)\n return __init__": f194,
    "def __create_fn__(_type_verdict, _type_violations, _type_reasons, _type_engines, _type_solver, _type_solver_version, _type_timings, _type_notes, _type_stats, _type_margin, _type_params, _type_engine, _type_truncated, _type_file, _type_extra, _type_program_digest, _type_machine_name, _type_machine_file, _type_machine_sha256, _type_settings, _type_interrupted, _type_budget_s, _type_profile, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_violations, _dflt_reasons, _dflt_engines, _dflt_solver, _dflt_solver_version, _dflt_timings, _dflt_notes, _dflt_stats, _dflt_margin, _dflt_params, _dflt_engine, _dflt_truncated, _dflt_file, _dflt_extra, _dflt_program_digest, _dflt_machine_name, _dflt_machine_file, _dflt_machine_sha256, _dflt_settings, _dflt_interrupted, _dflt_budget_s, _dflt_profile, _return_type):\n def __init__(self,verdict:_type_verdict,violations:_type_violations=_dflt_violations,reasons:_type_reasons=_dflt_reasons,engines:_type_engines=_dflt_engines,solver:_type_solver=_dflt_solver,solver_version:_type_solver_version=_dflt_solver_version,timings:_type_timings=_dflt_timings,notes:_type_notes=_dflt_notes,stats:_type_stats=_dflt_stats,margin:_type_margin=_dflt_margin,params:_type_params=_dflt_params,engine:_type_engine=_dflt_engine,truncated:_type_truncated=_dflt_truncated,file:_type_file=_dflt_file,extra:_type_extra=_HAS_DEFAULT_FACTORY,program_digest:_type_program_digest=_dflt_program_digest,machine_name:_type_machine_name=_dflt_machine_name,machine_file:_type_machine_file=_dflt_machine_file,machine_sha256:_type_machine_sha256=_dflt_machine_sha256,settings:_type_settings=_dflt_settings,interrupted:_type_interrupted=_dflt_interrupted,budget_s:_type_budget_s=_dflt_budget_s,profile:_type_profile=_HAS_DEFAULT_FACTORY)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'verdict',verdict)\n  __dataclass_builtins_object__.__setattr__(self,'violations',violations)\n  __dataclass_builtins_object__.__setattr__(self,'reasons',reasons)\n  __dataclass_builtins_object__.__setattr__(self,'engines',engines)\n  __dataclass_builtins_object__.__setattr__(self,'solver',solver)\n  __dataclass_builtins_object__.__setattr__(self,'solver_version',solver_version)\n  __dataclass_builtins_object__.__setattr__(self,'timings',timings)\n  __dataclass_builtins_object__.__setattr__(self,'notes',notes)\n  __dataclass_builtins_object__.__setattr__(self,'stats',stats)\n  __dataclass_builtins_object__.__setattr__(self,'margin',margin)\n  __dataclass_builtins_object__.__setattr__(self,'params',params)\n  __dataclass_builtins_object__.__setattr__(self,'engine',engine)\n  __dataclass_builtins_object__.__setattr__(self,'truncated',truncated)\n  __dataclass_builtins_object__.__setattr__(self,'file',file)\n  __dataclass_builtins_object__.__setattr__(self,'extra',_dflt_extra() if extra is _HAS_DEFAULT_FACTORY else extra)\n  __dataclass_builtins_object__.__setattr__(self,'program_digest',program_digest)\n  __dataclass_builtins_object__.__setattr__(self,'machine_name',machine_name)\n  __dataclass_builtins_object__.__setattr__(self,'machine_file',machine_file)\n  __dataclass_builtins_object__.__setattr__(self,'machine_sha256',machine_sha256)\n  __dataclass_builtins_object__.__setattr__(self,'settings',settings)\n  __dataclass_builtins_object__.__setattr__(self,'interrupted',interrupted)\n  __dataclass_builtins_object__.__setattr__(self,'budget_s',budget_s)\n  __dataclass_builtins_object__.__setattr__(self,'profile',_dflt_profile() if profile is _HAS_DEFAULT_FACTORY else profile)\n return __init__": f195,
    'def __create_fn__(_type_violation, _type_reason, _type_engine, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_violation, _dflt_reason, _dflt_engine, _return_type):\n def __init__(self,violation:_type_violation=_dflt_violation,reason:_type_reason=_dflt_reason,engine:_type_engine=_dflt_engine)->_return_type:\n  self.violation=violation\n  self.reason=reason\n  self.engine=engine\n return __init__': f196,
    "def __create_fn__(_type_words, _type_span, _type_index, _type_number, _type_messages, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_number, _dflt_messages, _return_type):\n def __init__(self,words:_type_words,span:_type_span,index:_type_index,number:_type_number=_dflt_number,messages:_type_messages=_dflt_messages)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'words',words)\n  __dataclass_builtins_object__.__setattr__(self,'span',span)\n  __dataclass_builtins_object__.__setattr__(self,'index',index)\n  __dataclass_builtins_object__.__setattr__(self,'number',number)\n  __dataclass_builtins_object__.__setattr__(self,'messages',messages)\n return __init__": f197,
    "def __create_fn__(_type_words, _type_span, _type_index, _type_number, _type_messages, _type_shape, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_number, _dflt_messages, _dflt_shape, _return_type):\n def __init__(self,words:_type_words,span:_type_span,index:_type_index,number:_type_number=_dflt_number,messages:_type_messages=_dflt_messages,shape:_type_shape=_dflt_shape)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'words',words)\n  __dataclass_builtins_object__.__setattr__(self,'span',span)\n  __dataclass_builtins_object__.__setattr__(self,'index',index)\n  __dataclass_builtins_object__.__setattr__(self,'number',number)\n  __dataclass_builtins_object__.__setattr__(self,'messages',messages)\n  __dataclass_builtins_object__.__setattr__(self,'shape',shape)\n return __init__": f198,
    "def __create_fn__(_type_work, _type_offset, _type_rotation, _type_diameter, _type_inch, _type_opaque, _type_work_offset, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_rotation, _dflt_diameter, _dflt_inch, _dflt_opaque, _dflt_work_offset, _return_type):\n def __init__(self,work:_type_work,offset:_type_offset,rotation:_type_rotation=_dflt_rotation,diameter:_type_diameter=_dflt_diameter,inch:_type_inch=_dflt_inch,opaque:_type_opaque=_dflt_opaque,work_offset:_type_work_offset=_dflt_work_offset)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'work',work)\n  __dataclass_builtins_object__.__setattr__(self,'offset',offset)\n  __dataclass_builtins_object__.__setattr__(self,'rotation',rotation)\n  __dataclass_builtins_object__.__setattr__(self,'diameter',diameter)\n  __dataclass_builtins_object__.__setattr__(self,'inch',inch)\n  __dataclass_builtins_object__.__setattr__(self,'opaque',opaque)\n  __dataclass_builtins_object__.__setattr__(self,'work_offset',work_offset)\n return __init__": f199,
    "def __create_fn__(_type_zones, _type_tool_axis, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_tool_axis, _return_type):\n def __init__(self,zones:_type_zones,tool_axis:_type_tool_axis=_dflt_tool_axis)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'zones',zones)\n  __dataclass_builtins_object__.__setattr__(self,'tool_axis',tool_axis)\n return __init__": f200,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'axes\',\'columns\',\'offset_bound\',\'motions\',\'lines\',\'rapids\',\'blocks\',\'start\',\'first_row\',\'row0\',\'arcs\',\'arc_rows\',\'arc_axes\',\'arc_boxes\',\'arc_more\',\'dwells\',\'dwell_rows\',\'modes\',\'inc_bound\',\'assumed\',\'tolerance\',\'arc_planes\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f201,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'axes\',\'degrees\',\'cos\',\'sin\',\'before\',\'after\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f202,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'axes\',\'scale\',\'kind\',\'start\',\'end\',\'line\',\'block\',\'tool_length\',\'centre\',\'plane\',\'clockwise\',\'turns\',\'feed\',\'file\',\'objects\',\'dwell\',\'derived\',\'frame\',\'radius\',\'tool_register\',\'tools_known\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f203,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'blend\',\'tolerance\',\'naive\',\'dialect\',\'code\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f204,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'block\',\'span\',\'zone\',\'point\',\'path_point\',\'parameter\',\'parameter_exact\',\'first_exit\',\'first_exit_parameter\',\'first_exit_exact\',\'depth\',\'depth_exact\',\'engine\',\'segment_kind\',\'derived\',\'kind\',\'params\',\'zones\',\'note\',\'on_path\',\'break_line\',\'break_parameter\',\'break_point\',\'leg\',\'switches\',\'exit_located\',\'frame\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f205,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'code\',\'message\',\'span\',\'severity\',\'file\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f206,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'code\',\'reason\',\'span\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f207,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'decimal_point_input\',\'increment_system\',\'g73_retract\',\'g83_clearance\',\'boring_shift\',\'scaling_unit\',\'rotation_incremental\',\'atan_signed\',\'tool_length_motion\',\'harmless_m\',\'references\',\'variables\',\'macros\',\'gcode_system\',\'g71_depth\',\'g71_retract\',\'roughing_final_pass\',\'g73_relief_x\',\'g73_relief_z\',\'g73_divisions\',\'g74_retract\',\'thread_chamfer\',\'thread_chamfer_angle\',\'g76_finish_passes\',\'g76_tool_angle\',\'g76_min_depth\',\'g76_finish_allowance\',\'tool_offset_motion\',\'tool_offset_cancel\',\'path\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f208,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'degree\',\'knots\',\'control\',\'weights\',\'source\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f209,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'delete\',\'number\',\'oword\',\'words\',\'assigns\',\'comments\',\'percent\',\'unsupported\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f210,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'delete\',\'number\',\'program\',\'words\',\'assigns\',\'comments\',\'stmt\',\'stmt_at\',\'percent\',\'unmodelled\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f211,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'file\',\'line\',\'column\',\'end_column\',\'text\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f212,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'ia\',\'ib\',\'s\',\'e\',\'ccw\',\'full\',\'centre\',\'r_signed\',\'r2_lo\',\'r2_hi\',\'start\',\'end\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f213,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'key\',\'group\',\'lanes\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f214,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'key\',\'meaning\',\'read\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f215,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'kind\',\'start\',\'end\',\'axes\',\'block\',\'span\',\'tool_length\',\'feed_mm_min\',\'plane\',\'clockwise\',\'centre\',\'radius\',\'turns\',\'dwell_s\',\'derived\',\'tool_register\',\'deps_start\',\'deps_end\',\'deps_tool\',\'extra\',\'frame\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f216,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'label\',\'keyword\',\'args\',\'column\',\'end_column\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f217,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'lane\',\'g\',\'m\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f218,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'letter\',\'value\',\'span\',\'text\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f219,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'linear_axis\',\'rotary_axis\',\'cylinder_radius\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f220,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'lo\',\'hi\',\'lo_closed\',\'hi_closed\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f221,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'lo\',\'hi\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f222,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'margin\',\'params\',\'engine\',\'max_violations\',\'arc_tolerance\',\'recovery\',\'max_iterations\',\'dialect\',\'library\',\'block_delete\',\'budget_s\',\'limits\',\'tool_table\',\'tool_table_units\',\'tool_table_x_offset\',\'written\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f223,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'message\',\'span\',\'block\',\'code\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f224,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'missing\',\'on_fallback\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f225,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'name\',\'limits\',\'forbid\',\'point\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f226,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'name\',\'lo\',\'hi\',\'written\',\'absolute\',\'lo_open\',\'hi_open\',\'centre\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f227,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'name\',\'max_passes\',\'spent\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f228,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'name\',\'plane\',\'vertices\',\'limits\',\'forbid\',\'point\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f229,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'name\',\'pulse\',\'rapid_mm_min\',\'max_feed_mm_min\',\'rotary\',\'accel_mm_s2\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f230,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'name\',\'reference_axis\',\'limited_axis\',\'start\',\'regions\',\'forbid\',\'point\',\'_steps\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f231,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'name\',\'units\',\'axes\',\'rapid_mode\',\'monitor_period_ms\',\'reference\',\'start\',\'offsets\',\'tool_lengths\',\'allowed\',\'modal\',\'tool_axis\',\'source\',\'warnings\',\'sections\',\'cutter_compensation\',\'tool_diameters\',\'sha256\',\'dialect\',\'fanuc\',\'block_delete\',\'arc_tolerance\',\'path_mode\',\'path_tolerance\',\'machine_type\',\'diameter_axes\',\'tool_offsets\',\'tool_length_wear\',\'tool_radius_wear\',\'control_units\',\'tool_change_quill_up\',\'tool_change_at_g30\',\'tool_change_position\',\'subroutine_path\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f232,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'number\',\'geometry\',\'wear\',\'nose_radius\',\'wear_radius\',\'tip\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f233,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'number\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f234,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'offsets\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f235,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'p0\',\'p1\',\'tau0\',\'tau1\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f236,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'start\',\'end\',\'turns\',\'x_off\',\'c_entry\',\'linear_axis\',\'rotary_axis\',\'grid\',\'arc\',\'centre\',\'radius\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f237,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'status\',\'values\',\'approximate\',\'stopped\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f238,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'summary\',\'configure\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f239,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'text\',\'name\',\'digest\',\'path\',\'notes\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f240,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'upto\',\'min\',\'max\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f241,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'value\',\'deps\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f242,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'verdict\',\'violations\',\'reasons\',\'engines\',\'solver\',\'solver_version\',\'timings\',\'notes\',\'stats\',\'margin\',\'params\',\'engine\',\'truncated\',\'file\',\'extra\',\'program_digest\',\'machine_name\',\'machine_file\',\'machine_sha256\',\'settings\',\'interrupted\',\'budget_s\',\'profile\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f243,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'words\',\'span\',\'index\',\'number\',\'messages\',\'shape\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f244,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'words\',\'span\',\'index\',\'number\',\'messages\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f245,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'work\',\'offset\',\'rotation\',\'diameter\',\'inch\',\'opaque\',\'work_offset\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f246,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'zones\',\'tool_axis\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f247,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'axes\',\'columns\',\'offset_bound\',\'motions\',\'lines\',\'rapids\',\'blocks\',\'start\',\'first_row\',\'row0\',\'arcs\',\'arc_rows\',\'arc_axes\',\'arc_boxes\',\'arc_more\',\'dwells\',\'dwell_rows\',\'modes\',\'inc_bound\',\'assumed\',\'tolerance\',\'arc_planes\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f248,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'axes\',\'degrees\',\'cos\',\'sin\',\'before\',\'after\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f249,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'axes\',\'scale\',\'kind\',\'start\',\'end\',\'line\',\'block\',\'tool_length\',\'centre\',\'plane\',\'clockwise\',\'turns\',\'feed\',\'file\',\'objects\',\'dwell\',\'derived\',\'frame\',\'radius\',\'tool_register\',\'tools_known\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f250,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'blend\',\'tolerance\',\'naive\',\'dialect\',\'code\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f251,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'block\',\'span\',\'zone\',\'point\',\'path_point\',\'parameter\',\'parameter_exact\',\'first_exit\',\'first_exit_parameter\',\'first_exit_exact\',\'depth\',\'depth_exact\',\'engine\',\'segment_kind\',\'derived\',\'kind\',\'params\',\'zones\',\'note\',\'on_path\',\'break_line\',\'break_parameter\',\'break_point\',\'leg\',\'switches\',\'exit_located\',\'frame\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f252,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'code\',\'message\',\'span\',\'severity\',\'file\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f253,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'code\',\'reason\',\'span\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f254,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'decimal_point_input\',\'increment_system\',\'g73_retract\',\'g83_clearance\',\'boring_shift\',\'scaling_unit\',\'rotation_incremental\',\'atan_signed\',\'tool_length_motion\',\'harmless_m\',\'references\',\'variables\',\'macros\',\'gcode_system\',\'g71_depth\',\'g71_retract\',\'roughing_final_pass\',\'g73_relief_x\',\'g73_relief_z\',\'g73_divisions\',\'g74_retract\',\'thread_chamfer\',\'thread_chamfer_angle\',\'g76_finish_passes\',\'g76_tool_angle\',\'g76_min_depth\',\'g76_finish_allowance\',\'tool_offset_motion\',\'tool_offset_cancel\',\'path\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f255,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'degree\',\'knots\',\'control\',\'weights\',\'source\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f256,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'delete\',\'number\',\'oword\',\'words\',\'assigns\',\'comments\',\'percent\',\'unsupported\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f257,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'delete\',\'number\',\'program\',\'words\',\'assigns\',\'comments\',\'stmt\',\'stmt_at\',\'percent\',\'unmodelled\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f258,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'file\',\'line\',\'column\',\'end_column\',\'text\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f259,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'ia\',\'ib\',\'s\',\'e\',\'ccw\',\'full\',\'centre\',\'r_signed\',\'r2_lo\',\'r2_hi\',\'start\',\'end\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f260,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'key\',\'group\',\'lanes\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f261,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'key\',\'meaning\',\'read\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f262,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'kind\',\'start\',\'end\',\'axes\',\'block\',\'span\',\'tool_length\',\'feed_mm_min\',\'plane\',\'clockwise\',\'centre\',\'radius\',\'turns\',\'dwell_s\',\'derived\',\'tool_register\',\'deps_start\',\'deps_end\',\'deps_tool\',\'extra\',\'frame\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f263,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'label\',\'keyword\',\'args\',\'column\',\'end_column\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f264,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'lane\',\'g\',\'m\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f265,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'letter\',\'value\',\'span\',\'text\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f266,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'linear_axis\',\'rotary_axis\',\'cylinder_radius\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f267,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'lo\',\'hi\',\'lo_closed\',\'hi_closed\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f268,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'lo\',\'hi\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f269,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'margin\',\'params\',\'engine\',\'max_violations\',\'arc_tolerance\',\'recovery\',\'max_iterations\',\'dialect\',\'library\',\'block_delete\',\'budget_s\',\'limits\',\'tool_table\',\'tool_table_units\',\'tool_table_x_offset\',\'written\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f270,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'message\',\'span\',\'block\',\'code\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f271,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'missing\',\'on_fallback\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f272,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'name\',\'limits\',\'forbid\',\'point\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f273,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'name\',\'lo\',\'hi\',\'written\',\'absolute\',\'lo_open\',\'hi_open\',\'centre\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f274,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'name\',\'max_passes\',\'spent\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f275,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'name\',\'plane\',\'vertices\',\'limits\',\'forbid\',\'point\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f276,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'name\',\'pulse\',\'rapid_mm_min\',\'max_feed_mm_min\',\'rotary\',\'accel_mm_s2\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f277,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'name\',\'reference_axis\',\'limited_axis\',\'start\',\'regions\',\'forbid\',\'point\',\'_steps\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f278,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'name\',\'units\',\'axes\',\'rapid_mode\',\'monitor_period_ms\',\'reference\',\'start\',\'offsets\',\'tool_lengths\',\'allowed\',\'modal\',\'tool_axis\',\'source\',\'warnings\',\'sections\',\'cutter_compensation\',\'tool_diameters\',\'sha256\',\'dialect\',\'fanuc\',\'block_delete\',\'arc_tolerance\',\'path_mode\',\'path_tolerance\',\'machine_type\',\'diameter_axes\',\'tool_offsets\',\'tool_length_wear\',\'tool_radius_wear\',\'control_units\',\'tool_change_quill_up\',\'tool_change_at_g30\',\'tool_change_position\',\'subroutine_path\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f279,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'number\',\'geometry\',\'wear\',\'nose_radius\',\'wear_radius\',\'tip\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f280,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'number\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f281,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'offsets\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f282,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'p0\',\'p1\',\'tau0\',\'tau1\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f283,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'start\',\'end\',\'turns\',\'x_off\',\'c_entry\',\'linear_axis\',\'rotary_axis\',\'grid\',\'arc\',\'centre\',\'radius\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f284,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'status\',\'values\',\'approximate\',\'stopped\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f285,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'summary\',\'configure\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f286,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'text\',\'name\',\'digest\',\'path\',\'notes\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f287,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'upto\',\'min\',\'max\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f288,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'value\',\'deps\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f289,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'verdict\',\'violations\',\'reasons\',\'engines\',\'solver\',\'solver_version\',\'timings\',\'notes\',\'stats\',\'margin\',\'params\',\'engine\',\'truncated\',\'file\',\'extra\',\'program_digest\',\'machine_name\',\'machine_file\',\'machine_sha256\',\'settings\',\'interrupted\',\'budget_s\',\'profile\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f290,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'words\',\'span\',\'index\',\'number\',\'messages\',\'shape\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f291,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'words\',\'span\',\'index\',\'number\',\'messages\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f292,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'work\',\'offset\',\'rotation\',\'diameter\',\'inch\',\'opaque\',\'work_offset\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f293,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'zones\',\'tool_axis\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f294,
}
