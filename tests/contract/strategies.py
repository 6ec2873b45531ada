"""The generated machines and programs the contract is checked on."""

from hypothesis import strategies as st

from nczones.testing import machines, programs


@st.composite
def contract_cases(draw, *, axes=(("X", "Y"), ("X", "Y", "Z")), allow_kinds=("stepped", "box", "polygon"),
                   pulses=("0.01", "0.01", "0.001"), max_blocks=6, arcs=True, inside_biases=(0.3, 0.6, 0.9),
                   boundary_bias=0.7, mix=None):
    """(machine, program text): every zone kind, 2 or 3 axes, boundary-biased programs."""
    machine = draw(
        machines(
            axes=draw(st.sampled_from(axes)),
            allow_kinds=allow_kinds,
            size=100,
            pulse=draw(st.sampled_from(pulses)),
        )
    )
    text = draw(
        programs(
            machine,
            max_blocks=max_blocks,
            arcs=arcs,
            subprograms=True,
            inside_bias=draw(st.sampled_from(inside_biases)),
            boundary_bias=boundary_bias,
            mix=mix,
        )
    )
    return machine, text


@st.composite
def roughing_profiles(draw):
    """A monotone turning contour for a roughing cycle: its (z, x) points (x a radius that grows as z falls
    from 0), the stock's radius above it, and the cycle's depth of cut and retract (decimal text)."""
    n = draw(st.integers(1, 3))
    x, z = draw(st.integers(2, 6)), 0
    points = [(z, x)]
    for _ in range(n):
        z -= draw(st.integers(2, 8))
        x += draw(st.integers(0, 3))
        points.append((z, x))
    top = x + draw(st.integers(1, 4))
    depth = draw(st.sampled_from(["1", "1.5", "2"]))
    retract = draw(st.sampled_from(["0.3", "0.5", "1"]))
    return points, top, depth, retract
