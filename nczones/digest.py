"""SHA-256 without loading OpenSSL for small inputs: the hash of the program and the machine file every report
carries.

``hashlib.sha256`` is OpenSSL's, and ``import hashlib`` loads ``libcrypto``: about 3 ms of every start-up on
the machine of specs/performance.md.  CPython's own ``_sha256`` (``_sha2`` since Python 3.12; the standard
library's :mod:`random` takes its SHA-512 the same way) computes the same digest with nothing to load, but
at about 3 ms per MiB where OpenSSL takes 0.6: below :data:`OWN_BELOW` bytes the built-in one is cheaper,
above it (and for a digest fed by ``update``, as for a streamed file) OpenSSL's.

>>> sha256(b"abc").hexdigest()[:16]
'ba7816bf8f01cfea'
>>> sha256(b"x" * OWN_BELOW).hexdigest()[:8]  # OpenSSL's
'8f990ba0'
"""

from __future__ import annotations

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["sha256", "OWN_BELOW"]

#: Inputs of fewer bytes are hashed by CPython's built-in SHA-256 (no OpenSSL to load); larger ones by hashlib's.
OWN_BELOW = 1 << 20

try:
    from _sha2 import sha256 as _own  # type: ignore[import-not-found,unused-ignore]  # Python >= 3.12
except ImportError:
    try:
        from _sha256 import sha256 as _own  # type: ignore[import-not-found,no-redef,unused-ignore]  # Python 3.11
    except ImportError:
        _own = None


def sha256(data: bytes | None = None) -> Any:
    """A SHA-256 hash object (``update``, ``digest``, ``hexdigest``) started with ``data``: the built-in one for
    fewer than :data:`OWN_BELOW` bytes, OpenSSL's (:mod:`hashlib`) for more or without ``data`` (a digest
    fed by ``update`` is a streamed file's, large)."""
    if data is not None and len(data) < OWN_BELOW and _own is not None:
        return _own(data)
    import hashlib

    return hashlib.sha256(b"" if data is None else data)
