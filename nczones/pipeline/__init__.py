"""The pipeline of a verification and of a simulation: text → interpretation → lane → proof (DESIGN §1).

The prover (:mod:`nczones.prover`) proves motion (:func:`nczones.prover.core.prove`) and never reads
program text; the interpreters (:mod:`nczones.gcode`) turn text into motion.  This module sits above both
and owns what joins them:

* :func:`~nczones.pipeline.verification.verify_source`: one program (a :class:`~nczones.gcode.source.ProgramSource`) on a machine with
  :class:`~nczones.prover.options.VerifyOptions`: the lane (the double pass of a parametric LinuxCNC
  program, else the interpreter, the vectorized fast path for programs of
  :data:`~nczones.pipeline.verification.FAST_PATH_MIN_LINES` lines or more), the cases of parameter ranges, the runs of the block-skip
  switch combinations, the tool-break recovery runs, and the report's source text, notes and settings.
  :func:`nczones.prover.verify` and :func:`~nczones.prover.verify_text` are its public wrappers.
* :func:`~nczones.pipeline.simulation.simulate_source`: the same interpretation run through the reference controller.

The modules: :mod:`.verification` (verify; what :func:`nczones.prover.verify` calls, so it never
imports the controller) and :mod:`.simulation` (simulate).  This file imports neither: the prover's entry
points load only the verification.
"""
