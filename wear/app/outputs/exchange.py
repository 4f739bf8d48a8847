"""Two folders swapped in one step, as the file system does it: the replace of an output folder that keeps, at every
instant, either the earlier folder or the new one at its path (:mod:`wear.app.outputs.folder`).

POSIX renames a folder only onto a missing or empty one; the swap of two names is the kernel's ``renameat2`` with
``RENAME_EXCHANGE`` on Linux (3.15 and later, on local file systems such as ext4, xfs, btrfs, tmpfs) and
``renamex_np`` with ``RENAME_SWAP`` on macOS (APFS). Elsewhere, and on file systems that do not do it (e.g. NFS),
:func:`exchange` raises OSError and :func:`can_exchange` says no.
"""

from __future__ import annotations

import ctypes
import errno
import os
import shutil
import sys
import tempfile
from pathlib import Path

__all__ = ["can_exchange", "exchange"]

_AT_FDCWD = -100
_RENAME_EXCHANGE = 2  # linux/fs.h
_RENAME_SWAP = 2  # macOS stdio.h


def _libc() -> ctypes.CDLL | None:
    try:
        return ctypes.CDLL(None, use_errno=True)
    except OSError:
        return None


_LIBC = _libc()


def exchange(a: str | os.PathLike, b: str | os.PathLike) -> None:
    """Swap the folders ``a`` and ``b`` (both exist, on one file system) in one step; OSError if the system or the
    file system cannot."""
    fa, fb = os.fsencode(a), os.fsencode(b)
    if sys.platform.startswith("linux") and _LIBC is not None and hasattr(_LIBC, "renameat2"):
        status = _LIBC.renameat2(_AT_FDCWD, fa, _AT_FDCWD, fb, _RENAME_EXCHANGE)
    elif sys.platform == "darwin" and _LIBC is not None and hasattr(_LIBC, "renamex_np"):
        status = _LIBC.renamex_np(fa, fb, _RENAME_SWAP)
    else:
        raise OSError(errno.ENOSYS, "this system cannot swap two folders in one step", os.fspath(a))
    if status != 0:
        code = ctypes.get_errno()
        raise OSError(code, os.strerror(code), os.fspath(a), None, os.fspath(b))


def can_exchange(folder: Path) -> str | None:
    """None if ``folder`` (an existing folder) can be swapped with a new folder beside it; otherwise why not (its
    parent cannot be written, it is a mount point, or the system or file system cannot swap folders)."""
    parent = folder.parent
    if folder.stat().st_dev != parent.stat().st_dev:
        return "it is a mount point"
    probes: list[str] = []
    try:
        for _ in range(2):
            # named as the output's temporary folders: the next run removes those a kill left
            probes.append(tempfile.mkdtemp(prefix=f".{folder.name}.partial-{os.getpid()}-", dir=parent))
        exchange(*probes)
    except OSError as exc:
        if not probes:
            return f"its parent folder {str(parent)!r} cannot be written ({exc.strerror or exc})"
        return f"{exc.strerror or exc} in {str(parent)!r}"
    finally:
        for probe in probes:
            shutil.rmtree(probe, ignore_errors=True)
    return None
