"""A command's output folder: checked before any work, built aside, moved in at the end, and never touching what
impactwear did not write.

An output folder is new, empty, or one impactwear wrote: such a folder holds the manifest :data:`MANIFEST` (the
command and the entries it wrote). A non-empty folder without a manifest holds the user's files: the command refuses
it before any work (:func:`check_output_folder`: one line, exit status 2). In a folder of its own, a new run replaces
exactly the entries the manifest lists and leaves every other file alone (notes a user put beside the results
survive); the output folder of another command is refused (its results are never deleted), and so is a file of the
user's under a name the command writes (each command states its names, or patterns such as ``angle_*``, before the
work starts).

The new output is built in a hidden temporary folder beside the target, ``.NAME.partial-PID-XXXX``, then moved in by
:func:`output_folder`:

- a new folder: renamed into place in one step;
- an existing folder: the user's entries in it are hard-linked into the temporary folder (the same files, nothing
  copied), the manifest written there, and the two folders swapped in one step (:func:`~.exchange.exchange`); the
  temporary folder, which then holds the earlier output, is removed. At every instant the folder holds the earlier
  output as it was or the complete new one; a temporary folder a kill leaves behind is never the only copy of
  anything, and the next run into the folder removes it. A complete earlier output that cannot be swapped (its parent
  folder cannot be written, it is a mount point, the file system cannot swap folders) is refused before any work; a
  folder that cannot be swapped and holds none (empty, or what a killed filling left) is filled entry by entry (the
  summaries last, the manifest "incomplete" until the last entry is in).

Folders and files get the permissions the user's umask gives (as ``mkdir`` and ``open`` would), so colleagues on a
shared machine read the results as they read the user's other files.
"""

from __future__ import annotations

import fnmatch
import json
import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from wear.app.outputs.exchange import can_exchange, exchange
from wear.app.outputs.writer import WRITE_ERRORS, is_temporary, permissions, remove_stale_temps, write_json

__all__ = [
    "MANIFEST",
    "check_named_file",
    "check_output_folder",
    "check_writable_folder",
    "claim_output_folder",
    "output_folder",
    "read_manifest",
]

#: The manifest of an impactwear output folder: ``{"command": ..., "entries": [...], "complete": bool}``.
MANIFEST = ".impactwear.json"

#: Commands whose folder grows over several invocations (finished cases are kept): no other command replaces it.
RESUMABLE = ("sweep",)


def read_manifest(folder: str | os.PathLike) -> dict | None:
    """The manifest of ``folder`` (None if it has none or it cannot be read)."""
    try:
        data = json.loads((Path(folder) / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or not isinstance(data.get("entries"), list):
        return None
    return data


def _ours(manifest: dict | None, entries: tuple[str, ...] | None) -> set[str]:
    """The entries of ``manifest`` that impactwear wrote: those the command writes (``entries``, names or patterns;
    None: every entry listed). A manifest is a file anyone can edit: an entry the command never writes (a user's
    file, a path outside the folder) is not replaced, whatever the manifest says."""
    listed = manifest["entries"] if manifest else []
    plain = {e for e in listed if isinstance(e, str) and e == Path(e).name and e not in ("", ".", "..", MANIFEST)}
    return plain if entries is None else {e for e in plain if _written_by(e, entries)}


def _foreign(folder: Path, manifest: dict | None, entries: tuple[str, ...] | None = None) -> list[str]:
    """Entries of ``folder`` that impactwear did not write (sorted); ``entries``: what the command writes (see
    :func:`_ours`)."""
    ours = _ours(manifest, entries)
    return sorted(
        p.name for p in folder.iterdir() if p.name != MANIFEST and p.name not in ours and not is_temporary(p.name)
    )


def check_writable_folder(path: str | os.PathLike, option: str = "--out") -> Path:
    """``path`` as a folder that exists or can be made, and can be written; ValueError (one line naming ``option``
    and the value) when it is a file, lies under a file or cannot be written."""
    target = Path(path)
    shown = f"{option}={str(path)!r}"
    if target.exists() and not target.is_dir():
        raise ValueError(f"{shown} is a file, not a folder: give a folder")
    base = target
    while not base.exists():
        if base.parent == base:
            break
        base = base.parent
    if not base.is_dir():
        raise ValueError(f"{shown} cannot be made: {str(base)!r} is a file, not a folder")
    try:  # a real attempt: permission bits do not tell about read-only mounts and special file systems
        probe = tempfile.mkdtemp(prefix=".impactwear.probe-", dir=base)
        os.rmdir(probe)
    except OSError as exc:
        raise ValueError(
            f"{shown} cannot be written ({exc.strerror or exc} in {str(base)!r}): give a folder you can write"
        ) from None
    return target


def _listed(names: list[str]) -> str:
    return ", ".join(names[:3]) + (f" and {len(names) - 3} more" if len(names) > 3 else "")


def _written_by(name: str, entries: tuple[str, ...]) -> bool:
    """Whether ``name`` is one of ``entries`` (names, or patterns such as ``angle_*``)."""
    return any(fnmatch.fnmatchcase(name, e) for e in entries)


def check_output_folder(
    path: str | os.PathLike, command: str, entries: tuple[str, ...] = (), option: str = "--out"
) -> Path:
    """``path`` as a usable output folder of ``command``, which writes ``entries`` (names or patterns) in it, checked
    before any work; ValueError (one line naming ``option`` and the value) when it is a file, lies under a file, cannot
    be written (:func:`check_writable_folder`), is a non-empty folder impactwear did not write, the output folder of
    another command (whose results replacing it would delete), holds a file of the user's under the name of one of
    ``entries``, or holds a complete earlier output that cannot be replaced in one step
    (:func:`~.exchange.can_exchange`)."""
    target = check_writable_folder(path, option)
    shown = f"{option}={str(path)!r}"
    if not target.is_dir():
        return target
    manifest = read_manifest(target)
    foreign = _foreign(target, manifest, entries or None)
    if foreign and manifest is None:
        raise ValueError(
            f"{shown} holds files impactwear did not write ({_listed(foreign)}): give a new or empty folder, "
            "or an earlier output folder of this command (its files are replaced, nothing else is touched)"
        )
    if manifest is None:
        return target
    owner = manifest.get("command")
    if owner != command:  # its results are another command's: replacing them would delete them
        raise ValueError(
            f"{shown} is the output folder of `impactwear {owner}`: give `impactwear "
            f"{command}` a new or empty folder (or its own earlier output folder)"
        )
    clash = [name for name in foreign if _written_by(name, entries)]
    if clash:  # a file the user put there under the name of an output: keep the user's
        raise ValueError(
            f"{shown} holds {_listed(clash)}, which impactwear did not write and `impactwear {command}` "
            "would write: move it, or give a new folder"
        )
    if manifest["entries"] and manifest.get("complete") and command not in RESUMABLE:
        why = can_exchange(target.resolve())
        if why is not None:
            raise ValueError(
                f"{shown} holds an earlier output that cannot be replaced in one step ({why}): give a new folder"
            )
    return target


def is_own_file(path: str | os.PathLike, header: str) -> bool:
    """Whether the file ``path`` begins with ``header`` (the first line and stamp of a file impactwear writes)."""
    stamp = header.encode("utf-8")
    with open(path, "rb") as f:
        return f.read(len(stamp)) == stamp


def check_named_file(path: str | os.PathLike, command: str, header: str, shown: str) -> None:
    """Before any work: a file ``path`` that ``command`` would replace must be absent or its own (it begins with
    ``header``); ValueError (one line, ``shown``: the option and value the user gave) otherwise."""
    path = Path(path)
    if path.is_dir():
        raise ValueError(f"{shown} holds a folder {path.name!r}, where `impactwear {command}` writes a file: move it")
    if path.exists() and not is_own_file(path, header):
        raise ValueError(
            f"{shown} holds {path.name!r}, which impactwear did not write and `impactwear {command}` would replace: "
            "move it, or give another folder"
        )


def _manifest(command: str, entries: list[str], complete: bool) -> dict:
    return {
        "command": command,
        "entries": sorted(set(entries)),
        "complete": complete,
        "about": "written by impactwear: the entries it replaces when this folder is an output folder again; "
        "every other file here is left alone",
    }


def _summaries_last(names: set[str]) -> list[str]:
    """Data first, the JSON summaries (what marks an output complete) last."""
    return sorted(names, key=lambda n: (n.endswith(".json"), n))


@contextmanager
def output_folder(path: str | os.PathLike, command: str, entries: tuple[str, ...]) -> Iterator[Path]:
    """Yield an empty temporary folder to write ``command``'s outputs in (``entries``: the names, or patterns such
    as ``angle_*``, it may write); when the block ends without error they are moved into ``path`` (see the module
    doc), otherwise the temporary folder is removed and ``path`` is as it was. ``path`` is checked first
    (:func:`check_output_folder`). A write the file system refuses (a full disk, a quota, a read-only or
    forbidden folder) is a ValueError naming ``path`` and the cause (one line; nothing written, an earlier output
    as it was)."""
    target = check_output_folder(path, command, entries).resolve()
    existing = target.is_dir()
    aside = not existing or can_exchange(target) is None
    if existing:
        remove_stale_temps(target)
    else:
        target.parent.mkdir(parents=True, exist_ok=True)
    remove_stale_temps(target.parent, name=target.name)
    tmp = Path(
        tempfile.mkdtemp(
            prefix=f".{target.name if aside else 'impactwear'}.partial-{os.getpid()}-",
            dir=target.parent if aside else target,
        )
    )
    try:
        yield tmp
        new = {p.name for p in tmp.iterdir()}
        unlisted = sorted(n for n in new if not _written_by(n, entries))
        if unlisted:  # the check before the work could not have protected a user's file of that name
            raise RuntimeError(f"impactwear {command} wrote {unlisted[0]!r}, which is not among its entries")
        _set_permissions(tmp)
        if not target.exists():
            write_json(tmp / MANIFEST, _manifest(command, list(new), True))
            os.replace(tmp, target)
        elif aside:
            _exchange_folder(tmp, check_output_folder(target, command, entries), command, new, entries)
        else:
            _move_entries(tmp, check_output_folder(target, command, entries), command, new, entries)
    except OSError as exc:
        if exc.errno not in WRITE_ERRORS or not _inside(exc.filename, target):
            raise
        kept = "the earlier output is as it was" if existing else "nothing was written"
        raise ValueError(f"--out={str(path)!r} cannot be written ({exc.strerror or exc}): {kept}") from None
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _inside(filename: str | bytes | None, target: Path) -> bool:
    """Whether an error's ``filename`` is one of the output's (in ``target`` or its temporary folder beside it;
    None: a write to a file already open, which is the output's)."""
    if filename is None:
        return True
    path = Path(os.fsdecode(filename)).resolve()
    if path.is_relative_to(target):
        return True
    if not path.is_relative_to(target.parent):
        return False
    return next(iter(path.relative_to(target.parent).parts), "").startswith(f".{target.name}.partial-")


def _link_tree(source: Path, copy: Path) -> None:
    """``copy`` as ``source`` (a file, a symbolic link or a folder, recursively): files hard-linked (the same file,
    nothing duplicated), copied where the file system has no hard links."""
    if source.is_symlink():
        os.symlink(os.readlink(source), copy)
    elif source.is_dir():
        copy.mkdir()
        for entry in source.iterdir():
            _link_tree(entry, copy / entry.name)
        shutil.copystat(source, copy)
    else:
        try:
            os.link(source, copy)
        except OSError:
            if not source.is_file():  # a pipe or a device is not read through: copying it could block
                raise
            shutil.copy2(source, copy)


def _exchange_folder(tmp: Path, target: Path, command: str, new: set[str], entries: tuple[str, ...]) -> None:
    """Replace the output in ``target`` by the entries ``new`` of ``tmp`` (a folder beside it) in one step: the
    user's entries of ``target`` are linked into ``tmp``, the two folders swapped, and the earlier output (now in
    ``tmp``) removed. At every instant ``target`` holds the earlier output as it was or the complete new one; a
    ``tmp`` a kill leaves behind is never the only copy of anything, and the next run removes it."""
    for name in _foreign(target, read_manifest(target), entries):
        _link_tree(target / name, tmp / name)
    write_json(tmp / MANIFEST, _manifest(command, list(new), True))
    shutil.copystat(target, tmp)  # the folder keeps its permissions
    exchange(tmp, target)
    # what the user put in the folder while it was being linked: moved over (the new output's names win)
    for name in _foreign(tmp, read_manifest(tmp), entries):
        if not (target / name).exists() and not (target / name).is_symlink():
            os.replace(tmp / name, target / name)


def _move_entries(tmp: Path, target: Path, command: str, new: set[str], entries: tuple[str, ...]) -> None:
    """Move the entries ``new`` of ``tmp`` into ``target``, a folder that cannot be swapped (e.g. a mount point) and
    holds no complete earlier output: what an interrupted filling left is removed, the data moved in first, the
    summaries last, the manifest "incomplete" until every entry is in."""
    left = _ours(read_manifest(target), entries)
    write_json(target / MANIFEST, _manifest(command, list(left | new), False))
    for name in left:
        if (target / name).is_dir() and not (target / name).is_symlink():
            shutil.rmtree(target / name)
        else:
            (target / name).unlink(missing_ok=True)
    for name in _summaries_last(new):
        os.replace(tmp / name, target / name)
    write_json(target / MANIFEST, _manifest(command, list(new), True))


def claim_output_folder(path: str | os.PathLike, command: str, entries: tuple[str, ...]) -> Path:
    """``path`` checked (:func:`check_output_folder`), created, and marked as the output folder of ``command``, which
    writes ``entries`` in it in place, file by file (a resumable command: its finished parts are kept)."""
    target = check_output_folder(path, command, entries)
    target.mkdir(parents=True, exist_ok=True)
    remove_stale_temps(target)
    manifest = read_manifest(target)
    listed = set(manifest["entries"]) if manifest else set()
    write_json(target / MANIFEST, _manifest(command, [*listed, *entries], True))
    return target


def _set_permissions(folder: Path) -> None:
    """The umask's permissions on ``folder`` and everything in it (temporary files and folders are made private)."""
    file_mode, dir_mode = permissions()
    os.chmod(folder, dir_mode)
    for root, dirs, files in os.walk(folder):
        for d in dirs:
            os.chmod(os.path.join(root, d), dir_mode)
        for f in files:
            os.chmod(os.path.join(root, f), file_mode)
