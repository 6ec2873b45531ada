"""nczones.digest: the report's SHA-256 without loading OpenSSL for small inputs (issue 36, start-up).

The oracle is hashlib's SHA-256 (OpenSSL), the digest every report carried before; the sizes cross
OWN_BELOW, where the built-in hash gives way to OpenSSL's.
"""

from __future__ import annotations

import hashlib

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.digest import OWN_BELOW, sha256


@settings(max_examples=60, deadline=None)
@given(st.binary(max_size=300), st.sampled_from([0, 1, OWN_BELOW - 301, OWN_BELOW - 1, OWN_BELOW + 7]))
def test_the_digest_is_hashlibs(tail, pad):
    data = b"\x00" * pad + tail
    assert sha256(data).hexdigest() == hashlib.sha256(data).hexdigest()


def test_a_streamed_digest_is_hashlibs():
    d = sha256()  # no data: a streamed file's digest, fed by update
    for block in (b"G1 X1\n", b"", b"G0 Z5\n" * 1000):
        d.update(block)
    assert d.hexdigest() == hashlib.sha256(b"G1 X1\n" + b"G0 Z5\n" * 1000).hexdigest()
