"""Vectorized fast path (placeholder)."""
def run_with_fastpath(interp):
    from . import _blocks
    yield from interp.interpreter.run(_blocks(interp.text, interp.file, interp.block_delete, interp.interpreter))
