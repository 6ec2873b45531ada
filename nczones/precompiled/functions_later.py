"""The functions ``dataclasses`` generates for nczones' classes, compiled once like any module (written
by ``python -m nczones.precompiled --write``; do not edit: see :mod:`nczones.precompiled`): the functions no start-up of ``python -m nczones.precompiled``'s scenarios makes, 
loaded at the first one a run makes)."""
# ruff: noqa
# mypy: ignore-errors
# fmt: off

def f0():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.axes,)==(other.axes,)
  return NotImplemented
 return __eq__

def f1():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.centre,self.factors,)==(other.centre,other.factors,)
  return NotImplemented
 return __eq__

def f2():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.centre,self.u,self.rho,self.ratio,self.sweep,self.clockwise,self.rho_max,)==(other.centre,other.u,other.rho,other.ratio,other.sweep,other.clockwise,other.rho_max,)
  return NotImplemented
 return __eq__

def f3():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.ia,self.ib,self.ca,self.cb,self.angle,)==(other.ia,other.ib,other.ca,other.cb,other.angle,)
  return NotImplemented
 return __eq__

def f4():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.ia,self.ib,self.radius,self.angle,)==(other.ia,other.ib,other.radius,other.angle,)
  return NotImplemented
 return __eq__

def f5():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.kind,self.end,self.label,self.centre,self.clockwise,self.dwell_s,self.feed,self.synced,)==(other.kind,other.end,other.label,other.centre,other.clockwise,other.dwell_s,other.feed,other.synced,)
  return NotImplemented
 return __eq__

def f6():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.kind,self.start,self.end,self.centre,self.clockwise,self.line,self.feed,)==(other.kind,other.start,other.end,other.centre,other.clockwise,other.line,other.feed,)
  return NotImplemented
 return __eq__

def f7():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.p0,self.p1,self.turns,self.x_off,self.c_entry,self.arc,)==(other.p0,other.p1,other.turns,other.x_off,other.c_entry,other.arc,)
  return NotImplemented
 return __eq__

def f8():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.rotation,self.scaling,self.step,self.off,)==(other.rotation,other.scaling,other.step,other.off,)
  return NotImplemented
 return __eq__

def f9():
 def __eq__(self,other):
  if other.__class__ is self.__class__:
   return (self.swap,self.sc,self.sh,)==(other.swap,other.sc,other.sh,)
  return NotImplemented
 return __eq__

def f10():
 def __hash__(self):
  return hash((self.axes,))
 return __hash__

def f11():
 def __hash__(self):
  return hash((self.centre,self.factors,))
 return __hash__

def f12():
 def __hash__(self):
  return hash((self.centre,self.u,self.rho,self.ratio,self.sweep,self.clockwise,self.rho_max,))
 return __hash__

def f13():
 def __hash__(self):
  return hash((self.ia,self.ib,self.ca,self.cb,self.angle,))
 return __hash__

def f14():
 def __hash__(self):
  return hash((self.ia,self.ib,self.radius,self.angle,))
 return __hash__

def f15():
 def __hash__(self):
  return hash((self.kind,self.end,self.label,self.centre,self.clockwise,self.dwell_s,self.feed,self.synced,))
 return __hash__

def f16():
 def __hash__(self):
  return hash((self.kind,self.start,self.end,self.centre,self.clockwise,self.line,self.feed,))
 return __hash__

def f17():
 def __hash__(self):
  return hash((self.p0,self.p1,self.turns,self.x_off,self.c_entry,self.arc,))
 return __hash__

def f18():
 def __hash__(self):
  return hash((self.rotation,self.scaling,self.step,self.off,))
 return __hash__

def f19():
 def __hash__(self):
  return hash((self.swap,self.sc,self.sh,))
 return __hash__

def f20():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(axes={self.axes!r})"
 return __repr__

def f21():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(centre={self.centre!r}, factors={self.factors!r})"
 return __repr__

def f22():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(centre={self.centre!r}, u={self.u!r}, rho={self.rho!r}, ratio={self.ratio!r}, sweep={self.sweep!r}, clockwise={self.clockwise!r}, rho_max={self.rho_max!r})"
 return __repr__

def f23():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(ia={self.ia!r}, ib={self.ib!r}, ca={self.ca!r}, cb={self.cb!r}, angle={self.angle!r})"
 return __repr__

def f24():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(ia={self.ia!r}, ib={self.ib!r}, radius={self.radius!r}, angle={self.angle!r})"
 return __repr__

def f25():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(kind={self.kind!r}, end={self.end!r}, label={self.label!r}, centre={self.centre!r}, clockwise={self.clockwise!r}, dwell_s={self.dwell_s!r}, feed={self.feed!r}, synced={self.synced!r})"
 return __repr__

def f26():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(kind={self.kind!r}, start={self.start!r}, end={self.end!r}, centre={self.centre!r}, clockwise={self.clockwise!r}, line={self.line!r}, feed={self.feed!r})"
 return __repr__

def f27():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(p0={self.p0!r}, p1={self.p1!r}, turns={self.turns!r}, x_off={self.x_off!r}, c_entry={self.c_entry!r}, arc={self.arc!r})"
 return __repr__

def f28():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(rotation={self.rotation!r}, scaling={self.scaling!r}, step={self.step!r}, off={self.off!r})"
 return __repr__

def f29():
 def __repr__(self):
  return self.__class__.__qualname__ + f"(swap={self.swap!r}, sc={self.sc!r}, sh={self.sh!r})"
 return __repr__

def f30(_type_axes, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,axes:_type_axes)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'axes',axes)
 return __init__

def f31(_type_centre, _type_factors, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,centre:_type_centre,factors:_type_factors)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
  __dataclass_builtins_object__.__setattr__(self,'factors',factors)
 return __init__

def f32(_type_centre, _type_u, _type_rho, _type_ratio, _type_sweep, _type_clockwise, _type_rho_max, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,centre:_type_centre,u:_type_u,rho:_type_rho,ratio:_type_ratio,sweep:_type_sweep,clockwise:_type_clockwise,rho_max:_type_rho_max)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
  __dataclass_builtins_object__.__setattr__(self,'u',u)
  __dataclass_builtins_object__.__setattr__(self,'rho',rho)
  __dataclass_builtins_object__.__setattr__(self,'ratio',ratio)
  __dataclass_builtins_object__.__setattr__(self,'sweep',sweep)
  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)
  __dataclass_builtins_object__.__setattr__(self,'rho_max',rho_max)
 return __init__

def f33(_type_ia, _type_ib, _type_ca, _type_cb, _type_angle, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,ia:_type_ia,ib:_type_ib,ca:_type_ca,cb:_type_cb,angle:_type_angle)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'ia',ia)
  __dataclass_builtins_object__.__setattr__(self,'ib',ib)
  __dataclass_builtins_object__.__setattr__(self,'ca',ca)
  __dataclass_builtins_object__.__setattr__(self,'cb',cb)
  __dataclass_builtins_object__.__setattr__(self,'angle',angle)
 return __init__

def f34(_type_ia, _type_ib, _type_radius, _type_angle, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_radius, _dflt_angle, _return_type):
 def __init__(self,ia:_type_ia,ib:_type_ib,radius:_type_radius=_dflt_radius,angle:_type_angle=_dflt_angle)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'ia',ia)
  __dataclass_builtins_object__.__setattr__(self,'ib',ib)
  __dataclass_builtins_object__.__setattr__(self,'radius',radius)
  __dataclass_builtins_object__.__setattr__(self,'angle',angle)
 return __init__

def f35(_type_kind, _type_end, _type_label, _type_centre, _type_clockwise, _type_dwell_s, _type_feed, _type_synced, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_centre, _dflt_clockwise, _dflt_dwell_s, _dflt_feed, _dflt_synced, _return_type):
 def __init__(self,kind:_type_kind,end:_type_end,label:_type_label,centre:_type_centre=_dflt_centre,clockwise:_type_clockwise=_dflt_clockwise,dwell_s:_type_dwell_s=_dflt_dwell_s,feed:_type_feed=_dflt_feed,synced:_type_synced=_dflt_synced)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'kind',kind)
  __dataclass_builtins_object__.__setattr__(self,'end',end)
  __dataclass_builtins_object__.__setattr__(self,'label',label)
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)
  __dataclass_builtins_object__.__setattr__(self,'dwell_s',dwell_s)
  __dataclass_builtins_object__.__setattr__(self,'feed',feed)
  __dataclass_builtins_object__.__setattr__(self,'synced',synced)
 return __init__

def f36(_type_kind, _type_start, _type_end, _type_centre, _type_clockwise, _type_line, _type_feed, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_centre, _dflt_clockwise, _dflt_line, _dflt_feed, _return_type):
 def __init__(self,kind:_type_kind,start:_type_start,end:_type_end,centre:_type_centre=_dflt_centre,clockwise:_type_clockwise=_dflt_clockwise,line:_type_line=_dflt_line,feed:_type_feed=_dflt_feed)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'kind',kind)
  __dataclass_builtins_object__.__setattr__(self,'start',start)
  __dataclass_builtins_object__.__setattr__(self,'end',end)
  __dataclass_builtins_object__.__setattr__(self,'centre',centre)
  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)
  __dataclass_builtins_object__.__setattr__(self,'line',line)
  __dataclass_builtins_object__.__setattr__(self,'feed',feed)
 return __init__

def f37(_type_p0, _type_p1, _type_turns, _type_x_off, _type_c_entry, _type_arc, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_arc, _return_type):
 def __init__(self,p0:_type_p0,p1:_type_p1,turns:_type_turns,x_off:_type_x_off,c_entry:_type_c_entry,arc:_type_arc=_dflt_arc)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'p0',p0)
  __dataclass_builtins_object__.__setattr__(self,'p1',p1)
  __dataclass_builtins_object__.__setattr__(self,'turns',turns)
  __dataclass_builtins_object__.__setattr__(self,'x_off',x_off)
  __dataclass_builtins_object__.__setattr__(self,'c_entry',c_entry)
  __dataclass_builtins_object__.__setattr__(self,'arc',arc)
 return __init__

def f38(_type_rotation, _type_scaling, _type_step, _type_off, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,rotation:_type_rotation,scaling:_type_scaling,step:_type_step,off:_type_off)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'rotation',rotation)
  __dataclass_builtins_object__.__setattr__(self,'scaling',scaling)
  __dataclass_builtins_object__.__setattr__(self,'step',step)
  __dataclass_builtins_object__.__setattr__(self,'off',off)
 return __init__

def f39(_type_swap, _type_sc, _type_sh, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):
 def __init__(self,swap:_type_swap,sc:_type_sc,sh:_type_sh)->_return_type:
  __dataclass_builtins_object__.__setattr__(self,'swap',swap)
  __dataclass_builtins_object__.__setattr__(self,'sc',sc)
  __dataclass_builtins_object__.__setattr__(self,'sh',sh)
 return __init__

def f40(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('axes',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f41(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('centre','factors',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f42(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('centre','u','rho','ratio','sweep','clockwise','rho_max',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f43(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('ia','ib','ca','cb','angle',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f44(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('ia','ib','radius','angle',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f45(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('kind','end','label','centre','clockwise','dwell_s','feed','synced',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f46(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('kind','start','end','centre','clockwise','line','feed',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f47(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('p0','p1','turns','x_off','c_entry','arc',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f48(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('rotation','scaling','step','off',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f49(cls, FrozenInstanceError):
 def __delattr__(self,name):
  if type(self) is cls or name in ('swap','sc','sh',):
   raise FrozenInstanceError(f"cannot delete field {name!r}")
  super(cls, self).__delattr__(name)
 return __delattr__

def f50(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('axes',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f51(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('centre','factors',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f52(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('centre','u','rho','ratio','sweep','clockwise','rho_max',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f53(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('ia','ib','ca','cb','angle',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f54(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('ia','ib','radius','angle',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f55(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('kind','end','label','centre','clockwise','dwell_s','feed','synced',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f56(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('kind','start','end','centre','clockwise','line','feed',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f57(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('p0','p1','turns','x_off','c_entry','arc',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f58(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('rotation','scaling','step','off',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

def f59(cls, FrozenInstanceError):
 def __setattr__(self,name,value):
  if type(self) is cls or name in ('swap','sc','sh',):
   raise FrozenInstanceError(f"cannot assign to field {name!r}")
  super(cls, self).__setattr__(name, value)
 return __setattr__

FUNCTIONS = {
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.axes,)==(other.axes,)\n  return NotImplemented\n return __eq__': f0,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.centre,self.factors,)==(other.centre,other.factors,)\n  return NotImplemented\n return __eq__': f1,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.centre,self.u,self.rho,self.ratio,self.sweep,self.clockwise,self.rho_max,)==(other.centre,other.u,other.rho,other.ratio,other.sweep,other.clockwise,other.rho_max,)\n  return NotImplemented\n return __eq__': f2,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.ia,self.ib,self.ca,self.cb,self.angle,)==(other.ia,other.ib,other.ca,other.cb,other.angle,)\n  return NotImplemented\n return __eq__': f3,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.ia,self.ib,self.radius,self.angle,)==(other.ia,other.ib,other.radius,other.angle,)\n  return NotImplemented\n return __eq__': f4,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.kind,self.end,self.label,self.centre,self.clockwise,self.dwell_s,self.feed,self.synced,)==(other.kind,other.end,other.label,other.centre,other.clockwise,other.dwell_s,other.feed,other.synced,)\n  return NotImplemented\n return __eq__': f5,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.kind,self.start,self.end,self.centre,self.clockwise,self.line,self.feed,)==(other.kind,other.start,other.end,other.centre,other.clockwise,other.line,other.feed,)\n  return NotImplemented\n return __eq__': f6,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.p0,self.p1,self.turns,self.x_off,self.c_entry,self.arc,)==(other.p0,other.p1,other.turns,other.x_off,other.c_entry,other.arc,)\n  return NotImplemented\n return __eq__': f7,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.rotation,self.scaling,self.step,self.off,)==(other.rotation,other.scaling,other.step,other.off,)\n  return NotImplemented\n return __eq__': f8,
    'def __create_fn__():\n def __eq__(self,other):\n  if other.__class__ is self.__class__:\n   return (self.swap,self.sc,self.sh,)==(other.swap,other.sc,other.sh,)\n  return NotImplemented\n return __eq__': f9,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.axes,))\n return __hash__': f10,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.centre,self.factors,))\n return __hash__': f11,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.centre,self.u,self.rho,self.ratio,self.sweep,self.clockwise,self.rho_max,))\n return __hash__': f12,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.ia,self.ib,self.ca,self.cb,self.angle,))\n return __hash__': f13,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.ia,self.ib,self.radius,self.angle,))\n return __hash__': f14,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.kind,self.end,self.label,self.centre,self.clockwise,self.dwell_s,self.feed,self.synced,))\n return __hash__': f15,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.kind,self.start,self.end,self.centre,self.clockwise,self.line,self.feed,))\n return __hash__': f16,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.p0,self.p1,self.turns,self.x_off,self.c_entry,self.arc,))\n return __hash__': f17,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.rotation,self.scaling,self.step,self.off,))\n return __hash__': f18,
    'def __create_fn__():\n def __hash__(self):\n  return hash((self.swap,self.sc,self.sh,))\n return __hash__': f19,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(axes={self.axes!r})"\n return __repr__': f20,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(centre={self.centre!r}, factors={self.factors!r})"\n return __repr__': f21,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(centre={self.centre!r}, u={self.u!r}, rho={self.rho!r}, ratio={self.ratio!r}, sweep={self.sweep!r}, clockwise={self.clockwise!r}, rho_max={self.rho_max!r})"\n return __repr__': f22,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(ia={self.ia!r}, ib={self.ib!r}, ca={self.ca!r}, cb={self.cb!r}, angle={self.angle!r})"\n return __repr__': f23,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(ia={self.ia!r}, ib={self.ib!r}, radius={self.radius!r}, angle={self.angle!r})"\n return __repr__': f24,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(kind={self.kind!r}, end={self.end!r}, label={self.label!r}, centre={self.centre!r}, clockwise={self.clockwise!r}, dwell_s={self.dwell_s!r}, feed={self.feed!r}, synced={self.synced!r})"\n return __repr__': f25,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(kind={self.kind!r}, start={self.start!r}, end={self.end!r}, centre={self.centre!r}, clockwise={self.clockwise!r}, line={self.line!r}, feed={self.feed!r})"\n return __repr__': f26,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(p0={self.p0!r}, p1={self.p1!r}, turns={self.turns!r}, x_off={self.x_off!r}, c_entry={self.c_entry!r}, arc={self.arc!r})"\n return __repr__': f27,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(rotation={self.rotation!r}, scaling={self.scaling!r}, step={self.step!r}, off={self.off!r})"\n return __repr__': f28,
    'def __create_fn__():\n def __repr__(self):\n  return self.__class__.__qualname__ + f"(swap={self.swap!r}, sc={self.sc!r}, sh={self.sh!r})"\n return __repr__': f29,
    "def __create_fn__(_type_axes, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,axes:_type_axes)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'axes',axes)\n return __init__": f30,
    "def __create_fn__(_type_centre, _type_factors, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,centre:_type_centre,factors:_type_factors)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n  __dataclass_builtins_object__.__setattr__(self,'factors',factors)\n return __init__": f31,
    "def __create_fn__(_type_centre, _type_u, _type_rho, _type_ratio, _type_sweep, _type_clockwise, _type_rho_max, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,centre:_type_centre,u:_type_u,rho:_type_rho,ratio:_type_ratio,sweep:_type_sweep,clockwise:_type_clockwise,rho_max:_type_rho_max)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n  __dataclass_builtins_object__.__setattr__(self,'u',u)\n  __dataclass_builtins_object__.__setattr__(self,'rho',rho)\n  __dataclass_builtins_object__.__setattr__(self,'ratio',ratio)\n  __dataclass_builtins_object__.__setattr__(self,'sweep',sweep)\n  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)\n  __dataclass_builtins_object__.__setattr__(self,'rho_max',rho_max)\n return __init__": f32,
    "def __create_fn__(_type_ia, _type_ib, _type_ca, _type_cb, _type_angle, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,ia:_type_ia,ib:_type_ib,ca:_type_ca,cb:_type_cb,angle:_type_angle)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'ia',ia)\n  __dataclass_builtins_object__.__setattr__(self,'ib',ib)\n  __dataclass_builtins_object__.__setattr__(self,'ca',ca)\n  __dataclass_builtins_object__.__setattr__(self,'cb',cb)\n  __dataclass_builtins_object__.__setattr__(self,'angle',angle)\n return __init__": f33,
    "def __create_fn__(_type_ia, _type_ib, _type_radius, _type_angle, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_radius, _dflt_angle, _return_type):\n def __init__(self,ia:_type_ia,ib:_type_ib,radius:_type_radius=_dflt_radius,angle:_type_angle=_dflt_angle)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'ia',ia)\n  __dataclass_builtins_object__.__setattr__(self,'ib',ib)\n  __dataclass_builtins_object__.__setattr__(self,'radius',radius)\n  __dataclass_builtins_object__.__setattr__(self,'angle',angle)\n return __init__": f34,
    "def __create_fn__(_type_kind, _type_end, _type_label, _type_centre, _type_clockwise, _type_dwell_s, _type_feed, _type_synced, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_centre, _dflt_clockwise, _dflt_dwell_s, _dflt_feed, _dflt_synced, _return_type):\n def __init__(self,kind:_type_kind,end:_type_end,label:_type_label,centre:_type_centre=_dflt_centre,clockwise:_type_clockwise=_dflt_clockwise,dwell_s:_type_dwell_s=_dflt_dwell_s,feed:_type_feed=_dflt_feed,synced:_type_synced=_dflt_synced)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'kind',kind)\n  __dataclass_builtins_object__.__setattr__(self,'end',end)\n  __dataclass_builtins_object__.__setattr__(self,'label',label)\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)\n  __dataclass_builtins_object__.__setattr__(self,'dwell_s',dwell_s)\n  __dataclass_builtins_object__.__setattr__(self,'feed',feed)\n  __dataclass_builtins_object__.__setattr__(self,'synced',synced)\n return __init__": f35,
    "def __create_fn__(_type_kind, _type_start, _type_end, _type_centre, _type_clockwise, _type_line, _type_feed, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_centre, _dflt_clockwise, _dflt_line, _dflt_feed, _return_type):\n def __init__(self,kind:_type_kind,start:_type_start,end:_type_end,centre:_type_centre=_dflt_centre,clockwise:_type_clockwise=_dflt_clockwise,line:_type_line=_dflt_line,feed:_type_feed=_dflt_feed)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'kind',kind)\n  __dataclass_builtins_object__.__setattr__(self,'start',start)\n  __dataclass_builtins_object__.__setattr__(self,'end',end)\n  __dataclass_builtins_object__.__setattr__(self,'centre',centre)\n  __dataclass_builtins_object__.__setattr__(self,'clockwise',clockwise)\n  __dataclass_builtins_object__.__setattr__(self,'line',line)\n  __dataclass_builtins_object__.__setattr__(self,'feed',feed)\n return __init__": f36,
    "def __create_fn__(_type_p0, _type_p1, _type_turns, _type_x_off, _type_c_entry, _type_arc, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _dflt_arc, _return_type):\n def __init__(self,p0:_type_p0,p1:_type_p1,turns:_type_turns,x_off:_type_x_off,c_entry:_type_c_entry,arc:_type_arc=_dflt_arc)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'p0',p0)\n  __dataclass_builtins_object__.__setattr__(self,'p1',p1)\n  __dataclass_builtins_object__.__setattr__(self,'turns',turns)\n  __dataclass_builtins_object__.__setattr__(self,'x_off',x_off)\n  __dataclass_builtins_object__.__setattr__(self,'c_entry',c_entry)\n  __dataclass_builtins_object__.__setattr__(self,'arc',arc)\n return __init__": f37,
    "def __create_fn__(_type_rotation, _type_scaling, _type_step, _type_off, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,rotation:_type_rotation,scaling:_type_scaling,step:_type_step,off:_type_off)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'rotation',rotation)\n  __dataclass_builtins_object__.__setattr__(self,'scaling',scaling)\n  __dataclass_builtins_object__.__setattr__(self,'step',step)\n  __dataclass_builtins_object__.__setattr__(self,'off',off)\n return __init__": f38,
    "def __create_fn__(_type_swap, _type_sc, _type_sh, MISSING, _HAS_DEFAULT_FACTORY, __dataclass_builtins_object__, _return_type):\n def __init__(self,swap:_type_swap,sc:_type_sc,sh:_type_sh)->_return_type:\n  __dataclass_builtins_object__.__setattr__(self,'swap',swap)\n  __dataclass_builtins_object__.__setattr__(self,'sc',sc)\n  __dataclass_builtins_object__.__setattr__(self,'sh',sh)\n return __init__": f39,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'axes\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f40,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'centre\',\'factors\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f41,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'centre\',\'u\',\'rho\',\'ratio\',\'sweep\',\'clockwise\',\'rho_max\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f42,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'ia\',\'ib\',\'ca\',\'cb\',\'angle\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f43,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'ia\',\'ib\',\'radius\',\'angle\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f44,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'kind\',\'end\',\'label\',\'centre\',\'clockwise\',\'dwell_s\',\'feed\',\'synced\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f45,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'kind\',\'start\',\'end\',\'centre\',\'clockwise\',\'line\',\'feed\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f46,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'p0\',\'p1\',\'turns\',\'x_off\',\'c_entry\',\'arc\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f47,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'rotation\',\'scaling\',\'step\',\'off\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f48,
    'def __create_fn__(cls, FrozenInstanceError):\n def __delattr__(self,name):\n  if type(self) is cls or name in (\'swap\',\'sc\',\'sh\',):\n   raise FrozenInstanceError(f"cannot delete field {name!r}")\n  super(cls, self).__delattr__(name)\n return __delattr__': f49,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'axes\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f50,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'centre\',\'factors\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f51,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'centre\',\'u\',\'rho\',\'ratio\',\'sweep\',\'clockwise\',\'rho_max\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f52,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'ia\',\'ib\',\'ca\',\'cb\',\'angle\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f53,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'ia\',\'ib\',\'radius\',\'angle\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f54,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'kind\',\'end\',\'label\',\'centre\',\'clockwise\',\'dwell_s\',\'feed\',\'synced\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f55,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'kind\',\'start\',\'end\',\'centre\',\'clockwise\',\'line\',\'feed\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f56,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'p0\',\'p1\',\'turns\',\'x_off\',\'c_entry\',\'arc\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f57,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'rotation\',\'scaling\',\'step\',\'off\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f58,
    'def __create_fn__(cls, FrozenInstanceError):\n def __setattr__(self,name,value):\n  if type(self) is cls or name in (\'swap\',\'sc\',\'sh\',):\n   raise FrozenInstanceError(f"cannot assign to field {name!r}")\n  super(cls, self).__setattr__(name, value)\n return __setattr__': f59,
}
