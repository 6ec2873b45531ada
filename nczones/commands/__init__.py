"""The subcommands of ``nczones`` (DESIGN §8), one module each.

Each module registers its subcommand with :data:`nczones.cli.REGISTRARS`;
:data:`nczones.cli.COMMANDS` names the module and the summary of each.
The commands sit above every stage: ``home --prove`` and ``verify`` run the
prover, ``simulate`` and ``home`` the reference controller, and a command may
hold the two side by side (``home --prove`` replays each counterexample of
the proofs in the pulse simulation) while the prover and the controller never
import each other.
"""
