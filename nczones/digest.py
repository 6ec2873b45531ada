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

__all__ = ["sha256", "OWN_BELOW", "LaterDigest"]

#: Inputs of fewer bytes are hashed by CPython's built-in SHA-256 (no OpenSSL to load); larger ones by hashlib's.
OWN_BELOW = 1 << 20



def _built_in() -> Any:
    """CPython's own ``sha256`` (None where there is none), imported at the first digest: a text report asks
    for none, and the module is a C extension to load (issue 36).  Python 3.11 names it ``_sha256``, 3.12
    ``_sha2``: the one this version has is asked (a failed import searches every folder of ``sys.path``)."""
    import sys

    try:
        if sys.version_info >= (3, 12):
            from _sha2 import sha256 as own  # type: ignore[import-not-found,unused-ignore]
        else:
            from _sha256 import sha256 as own  # type: ignore[import-not-found,no-redef,unused-ignore]
    except ImportError:
        return None
    return own


#: :func:`_built_in`'s answer, once asked
_OWN: list[Any] = []


def sha256(data: bytes | None = None) -> Any:
    """A SHA-256 hash object (``update``, ``digest``, ``hexdigest``) started with ``data``: the built-in one for
    fewer than :data:`OWN_BELOW` bytes, OpenSSL's (:mod:`hashlib`) for more or without ``data`` (a digest
    fed by ``update`` is a streamed file's, large)."""
    if data is not None and len(data) < OWN_BELOW:
        if not _OWN:
            _OWN.append(_built_in())
        if _OWN[0] is not None:
            return _OWN[0](data)
    import hashlib

    return hashlib.sha256(b"" if data is None else data)


class LaterDigest:
    """The SHA-256 (hex) of some bytes, computed when first asked for (:attr:`hex`), then kept.

    A program's digest is read only by the reports that name what they verified (JSON, SARIF, replay, the
    fleet's store); a text report never asks, and hashing a 200 KB program costs some 9 million instructions
    of a verify (issue 36).  Either the bytes (hashed later) or the digest already known (a streamed file's,
    computed as it was read) is given.  Two equal digests compare equal whether computed yet or not, and equal
    to the ``str`` of the digest; a pickled one is its digest (the bytes are not sent along).

    >>> d = LaterDigest(b"abc")
    >>> d.known, d.hex[:16], d.known, d == LaterDigest(known=d.hex), d == d.hex
    (False, 'ba7816bf8f01cfea', True, True, True)
    """

    __slots__ = ("_data", "_hex")

    def __init__(self, data: bytes | None = None, known: str = "") -> None:
        self._data = None if known else data
        self._hex = known

    @property
    def known(self) -> bool:
        """Whether the digest has been computed (or was given)."""
        return bool(self._hex)

    @property
    def hex(self) -> str:
        """The 64 hex digits of the SHA-256 (computed now at the first call)."""
        if not self._hex:
            self._hex = sha256(self._data or b"").hexdigest()
            self._data = None
        return self._hex

    def __str__(self) -> str:
        return self.hex

    def __repr__(self) -> str:
        return f"LaterDigest(known={self.hex!r})"

    def __eq__(self, other: object) -> bool:
        if isinstance(other, LaterDigest):
            return other is self or self.hex == other.hex
        if isinstance(other, str):
            return self.hex == other
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self.hex)

    def __reduce__(self) -> tuple[Any, tuple[str]]:
        return str, (self.hex,)

