"""A non-GUI LinuxCNC front end that opens programs the way AXIS does (tests/cli/test_linuxcnc_filter.py).

LinuxCNC's launcher starts it as the INI's [DISPLAY] DISPLAY (``frontend.py -ini FILE.ini``), with the
system Python that has LinuxCNC's ``linuxcnc`` module.  For each program in $NCZONES_FRONTEND_PROGRAMS
(separated by newlines) it runs the INI's [FILTER] program with AXIS's own ``get_filter`` and
``filter_program``, taken out of the installed /usr/bin/axis (only the Tk progress bar and text widget are
stood in), then does what AXIS's ``open_file_guts`` does with the outcome: a non-zero exit loads nothing;
otherwise the filtered file is opened in LinuxCNC's task (``program_open``) and the loaded file read back
from LinuxCNC's status.  One line per program goes to $NCZONES_FRONTEND_LOG; leaving shuts LinuxCNC down.
"""

import ast
import os
import re
import select
import sys
import time
import types

import linuxcnc

ini = sys.argv[sys.argv.index("-ini") + 1]
text = open("/usr/bin/axis", encoding="utf-8").read()
wanted = [node for node in ast.parse(text).body
          if (isinstance(node, ast.FunctionDef) and node.name in ("filter_program", "get_filter"))
          or (isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "progress_re" for t in node.targets))]


class Progress:
    def __init__(self, *args):
        self.values = []

    def set_text(self, text):
        pass

    def update(self, value, *args):
        PROGRESS.append(value)

    def done(self):
        pass


PROGRESS = []
namespace = {"os": os, "re": re, "select": select, "sys": sys, "Progress": Progress, "_": lambda s: s,
             "t": types.SimpleNamespace(update=lambda: None), "inifile": linuxcnc.ini(ini)}
exec(compile("\n".join(ast.get_source_segment(text, n) for n in wanted), "/usr/bin/axis", "exec"), namespace)

command, status = linuxcnc.command(), linuxcnc.stat()
command.state(linuxcnc.STATE_ESTOP_RESET)
command.state(linuxcnc.STATE_ON)
command.wait_complete()
command.mode(linuxcnc.MODE_AUTO)
command.wait_complete()
with open(os.environ["NCZONES_FRONTEND_LOG"], "w", encoding="utf-8") as log:
    for program in os.environ["NCZONES_FRONTEND_PROGRAMS"].splitlines():
        del PROGRESS[:]
        program_filter = namespace["get_filter"](program)
        filtered = os.path.join(os.path.dirname(ini), "filtered-" + os.path.basename(program))
        code, stderr = namespace["filter_program"](program_filter, program, filtered)
        if code:
            print(f"REFUSED {program} exit {code} progress {PROGRESS[-1:]} message {stderr!r}", file=log)
            continue
        command.program_open(filtered)
        command.wait_complete()
        deadline = time.time() + 10
        while time.time() < deadline:
            status.poll()
            if status.file == filtered:
                break
            time.sleep(0.05)
        print(f"LOADED {program} file {status.file} progress {PROGRESS[-1:]}", file=log)
