"""A command's output folder: checked before any work, built aside, moved in at the end, and never touching what
impactwear did not write.

An output folder is new, empty, or one impactwear wrote: such a folder holds the manifest :data:`MANIFEST` (the
command and the entries it wrote). A non-empty folder without a manifest holds the user's files: the command refuses
it before any work (:func:`check_output_folder`: one line, exit status 2). In a folder of its own, a new run replaces
exactly the entries the manifest lists and leaves every other file alone (notes a user put beside the results
survive); the output folder of another command is refused (its results are never deleted).

The new output is built in a hidden temporary folder (``.NAME.partial-PID-XXXX``, inside the target when it exists,
beside it otherwise), then moved in by :func:`output_folder`:

- a new folder: renamed into place in one step;
- an existing folder: the manifest is rewritten "incomplete" listing the old and the new entries, the old entries are
  removed (the JSON summaries first), the new ones renamed in (the JSON summaries last), and the manifest rewritten
  complete. An interruption leaves the old output, or a folder whose manifest says incomplete and which has no
  summary — never a complete-looking mix — and a rerun accepts and replaces it.

Folders and files get the permissions the user's umask gives (as ``mkdir`` and ``open`` would), so colleagues on a
shared machine read the results as they read the user's other files.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from wear.app.outputs.writer import is_temporary, permissions, remove_stale_temps, write_json

__all__ = [
    "MANIFEST",
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


def _foreign(folder: Path, manifest: dict | None) -> list[str]:
    """Entries of ``folder`` that impactwear did not write (sorted)."""
    ours = set(manifest["entries"]) if manifest else set()
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


def check_output_folder(path: str | os.PathLike, command: str, option: str = "--out") -> Path:
    """``path`` as a usable output folder of ``command``, checked before any work; ValueError (one line naming
    ``option`` and the value) when it is a file, lies under a file, cannot be written (:func:`check_writable_folder`),
    or is a non-empty folder impactwear did not write, or the output folder of another command (whose results
    replacing it would delete)."""
    target = check_writable_folder(path, option)
    shown = f"{option}={str(path)!r}"
    if target.is_dir():
        manifest = read_manifest(target)
        foreign = _foreign(target, manifest)
        if foreign and manifest is None:
            listed = ", ".join(foreign[:3]) + (f" and {len(foreign) - 3} more" if len(foreign) > 3 else "")
            raise ValueError(
                f"{shown} holds files impactwear did not write ({listed}): give a new or empty folder, "
                "or an earlier output folder of this command (its files are replaced, nothing else is "
                "touched)"
            )
        if manifest is not None:
            owner = manifest.get("command")
            if owner != command:  # its results are another command's: replacing them would delete them
                raise ValueError(
                    f"{shown} is the output folder of `impactwear {owner}`: give `impactwear "
                    f"{command}` a new or empty folder (or its own earlier output folder)"
                )
    return target


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
def output_folder(path: str | os.PathLike, command: str) -> Iterator[Path]:
    """Yield an empty temporary folder to write ``command``'s outputs in; when the block ends without error they
    are moved into ``path`` (see the module doc), otherwise the temporary folder is removed and ``path`` is as it
    was. ``path`` is checked first (:func:`check_output_folder`)."""
    target = check_output_folder(path, command).resolve()
    existing = target.is_dir()
    if existing:
        remove_stale_temps(target)
    else:
        target.parent.mkdir(parents=True, exist_ok=True)
        remove_stale_temps(target.parent, name=target.name)
    tmp = Path(
        tempfile.mkdtemp(
            prefix=f".{'impactwear' if existing else target.name}.partial-{os.getpid()}-",
            dir=target if existing else target.parent,
        )
    )
    try:
        yield tmp
        new = {p.name for p in tmp.iterdir()}
        _set_permissions(tmp)
        if not target.exists():
            write_json(tmp / MANIFEST, _manifest(command, list(new), True))
            os.replace(tmp, target)
            return
        _replace_entries(tmp, check_output_folder(target, command), command, new)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _replace_entries(tmp: Path, target: Path, command: str, new: set[str]) -> None:
    """Move the entries ``new`` of ``tmp`` into the existing folder ``target`` in place of its manifest's."""
    manifest = read_manifest(target)
    old = set(manifest["entries"]) if manifest else set()
    clash = sorted(new.intersection(_foreign(target, manifest)))
    if clash:  # a file the user put there under the name of a new output: keep the user's
        raise ValueError(
            f"out={str(target)!r} holds {clash[0]!r}, which impactwear did not write and would replace: "
            "move it, or give a new folder"
        )
    write_json(target / MANIFEST, _manifest(command, list(old | new), False))
    trash = Path(tempfile.mkdtemp(prefix=f".impactwear.partial-{os.getpid()}-", dir=target))
    try:
        for name in sorted(old, key=lambda n: (not n.endswith(".json"), n)):  # summaries leave first
            if (target / name).exists() or (target / name).is_symlink():
                os.replace(target / name, trash / name)
        for name in _summaries_last(new):
            os.replace(tmp / name, target / name)
        write_json(target / MANIFEST, _manifest(command, list(new), True))
    finally:
        shutil.rmtree(trash, ignore_errors=True)


def claim_output_folder(path: str | os.PathLike, command: str, entries: tuple[str, ...]) -> Path:
    """``path`` checked (:func:`check_output_folder`), created, and marked as the output folder of ``command``, which
    writes ``entries`` in it in place, file by file (a resumable command: its finished parts are kept)."""
    target = check_output_folder(path, command)
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
