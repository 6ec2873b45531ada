"""SHA-256 without loading OpenSSL: the hash of the program and the machine file every report carries.

``hashlib.sha256`` is OpenSSL's, and ``import hashlib`` loads ``libcrypto`` (about 3 ms of every start-up on
the machine of specs/performance.md); CPython's own ``_sha256`` (``_sha2`` since Python 3.12) computes the
same digest.  The standard library's :mod:`random` takes its SHA-512 the same way.  Where neither built-in
module exists, :mod:`hashlib`.

>>> sha256(b"abc").hexdigest()[:16]
'ba7816bf8f01cfea'
"""

from __future__ import annotations

__all__ = ["sha256"]

try:
    from _sha2 import sha256  # type: ignore[import-not-found,unused-ignore]  # Python >= 3.12
except ImportError:
    try:
        from _sha256 import sha256  # type: ignore[import-not-found,no-redef,unused-ignore]  # Python 3.11
    except ImportError:
        from hashlib import sha256  # type: ignore[assignment,unused-ignore]
