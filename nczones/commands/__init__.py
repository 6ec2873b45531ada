"""The subcommands of ``nczones`` (DESIGN §8), one module each, and :data:`COMMANDS`, the one table of them.

:mod:`nczones.cli` reads the table: it makes each command's parser (named, with its summary) and, for the
command about to run, calls the function the table names to add that command's arguments and its handler
(``parser.set_defaults(handler=...)``); the handler returns the exit status.  A command's module is imported
only then, so ``nczones --help`` and one command stay clear of what the other commands import (the prover,
the controller, numpy, Z3, matplotlib).  Nothing registers by being imported.

The commands share :mod:`nczones.commands.conventions` (exit statuses, the common arguments, how a command
fails) and never import :mod:`nczones.cli`.  They sit above every stage: ``home --prove`` and ``verify`` run
the prover, ``simulate`` and ``home`` the reference controller, and a command may hold the two side by side
(``home --prove`` replays each counterexample of the proofs in the pulse simulation) while the prover and
the controller never import each other.

To add a command: its module here with a ``configure(parser)`` function, and its row in :data:`COMMANDS`
(docs/design.md, "How to add a command").
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Mapping
from types import MappingProxyType

from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)

# typing is not imported by `nczones --help` (issue 36); a type checker takes this name as true
TYPE_CHECKING = False
if TYPE_CHECKING:
    import argparse

__all__ = ["Command", "COMMANDS", "configurer"]


@dataclass(frozen=True, slots=True)
class Command:
    """A subcommand: its one line in ``nczones --help`` and where its arguments are added, ``"module:function"``
    (the function takes the command's parser, adds its arguments and sets its ``handler``)."""

    summary: str
    configure: str

    @property
    def module(self) -> str:
        """The module that holds the command."""
        return self.configure.partition(":")[0]


#: The subcommands in the order ``nczones --help`` lists them.
COMMANDS: Mapping[str, Command] = MappingProxyType({
    "check-machine": Command("validate a machine file and summarise it", "nczones.commands.check_machine:configure"),
    "verify": Command("prove that programs stay inside the allowed set (or show where not)",
                      "nczones.commands.verify:configure"),
    "simulate": Command("run a program through the reference controller (pulses, limit monitor)",
                        "nczones.commands.simulate:configure"),
    "home": Command("simulate homing (near-zero dog, grid point, grid shift) or prove it exact",
                    "nczones.commands.home:configure"),
    "plot": Command("draw a program's toolpath over the machine's allowed set (PNG/SVG/PDF)",
                    "nczones.commands.plot:configure"),
    "import-machine": Command("write a machine file from a LinuxCNC, Grbl or Fanuc configuration",
                              "nczones.commands.machine_files:configure_import"),
    "export-zones": Command("write the soft limits (LinuxCNC) or stored stroke checks (Fanuc) that hold a machine "
                            "file's zones", "nczones.commands.machine_files:configure_export"),
    "replay": Command("re-check the counterexamples of a JSON report exactly against the files it names",
                      "nczones.commands.replay:configure"),
    "fleet": Command("verify a library of programs against its machines, incrementally (serial or on Dask)",
                     "nczones.commands.fleet:configure"),
    "linuxcnc-filter": Command("LinuxCNC's [FILTER] program: pass a program through only when it is proved safe",
                               "nczones.commands.linuxcnc_filter:configure"),
})


def configurer(name: str) -> Callable[[argparse.ArgumentParser], None]:
    """The function that adds command ``name``'s arguments and handler to its parser (its module imported now).

    >>> configurer("check-machine").__module__
    'nczones.commands.check_machine'
    """
    module, _, function = COMMANDS[name].configure.partition(":")
    __import__(module)  # importlib.import_module's work for an absolute name, without importlib (and warnings)
    configure: Callable[[argparse.ArgumentParser], None] = getattr(sys.modules[module], function)
    return configure
