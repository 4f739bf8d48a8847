"""Links to a public name (``wear.run``) go to the object's entry in the module reference (``wear.chain.single.run``).

The public-API page (``docs/api.md``) names each object by the path a user imports it from; the module reference
documents it once, in the module that defines it. A cross-reference to a public path that the Python domain does not
know is resolved here: the object is imported and looked up under the module that defines it (a class or function:
its ``__module__`` and ``__qualname__``; a constant: a module of the same project that holds it, packages last). With
the module reference left out (``IMPACTWEAR_DOCS_API=0``) the name stays plain text.
"""

from __future__ import annotations

import pkgutil
import sys

PACKAGES = ("contact", "fem", "wear")


def defining_paths(path: str) -> list[str]:
    """Where the object at ``path`` may be documented: its defining module first."""
    obj = pkgutil.resolve_name(path)
    name = path.rsplit(".", 1)[1]
    paths = []
    if getattr(obj, "__module__", None) and getattr(obj, "__qualname__", None):
        paths.append(f"{obj.__module__}.{obj.__qualname__}")
    holders = [m for m in sorted(sys.modules) if m.split(".")[0] in PACKAGES and vars(sys.modules[m]).get(name) is obj]
    # modules before packages: a package re-exports what a module defines
    holders.sort(key=lambda m: hasattr(sys.modules[m], "__path__"))
    return paths + [f"{m}.{name}" for m in holders]


def _resolve(app, env, node, contnode):
    target = node.get("reftarget", "")
    if node.get("refdomain") != "py" or target.split(".")[0] not in PACKAGES:
        return None
    try:
        candidates = defining_paths(target)
    except (ImportError, AttributeError, ValueError):
        return None
    domain = env.get_domain("py")
    for candidate in candidates:
        if candidate != target and candidate in domain.objects:
            return domain.resolve_xref(env, node["refdoc"], app.builder, node["reftype"], candidate, node, contnode)
    return None


def setup(app) -> dict:
    app.connect("missing-reference", _resolve)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
