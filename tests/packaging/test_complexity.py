"""No function grows past the size and complexity limits; the exemption list only shrinks (issue 34).

The exempted functions may shrink (rewrite their values with ``python -m tests.tools.complexity --write``)
but not grow.
"""

from __future__ import annotations

import ast

from tests.tools.complexity import MAX_LINES, _body_lines, measure, read_exemptions


def test_no_new_function_over_the_limits_and_the_list_shrinks():
    measured, listed = measure(), read_exemptions()
    new = sorted(k for k in measured if k not in listed)
    assert not new, ("over the limits and not exempted (split the function; the list only shrinks): "
                     + ", ".join(f"{k} = {measured[k]}" for k in new))
    grown = sorted(k for k in measured if k in listed and int(measured[k]) > int(listed[k]))
    assert not grown, ("an exempted function grew (split it instead): "
                       + ", ".join(f"{k} {listed[k]} -> {measured[k]}" for k in grown))
    within = sorted(k for k in listed if k not in measured)
    assert not within, ("now within the limits or gone: remove from tests/packaging/complexity_exemptions.txt "
                        "(python -m tests.tools.complexity --write): " + ", ".join(within))


def test_body_lines_leave_out_the_docstring():
    tree = ast.parse('def f():\n    """Doc\n    string."""\n    a = 1\n\n    return a\n')
    assert _body_lines(tree.body[0]) == 3
    long = ast.parse("def g():\n" + "    x = 1\n" * (MAX_LINES + 1))
    assert _body_lines(long.body[0]) == MAX_LINES + 1
