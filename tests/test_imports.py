"""The package's imports go one way and sit at the top of modules.

Rooms, lowest first (a module may import from its own room and the rooms below it, never above): ``contact`` ←
the FE core (``fem.core``: knows no plate) ← the plates (``fem.axisymmetric``, ``fem.solid``: neither imports the
other) ← the plates' face and couplings (``fem``) ← the wear law (``wear.law``, ``wear.laws``, ``wear.pressure``,
``wear.slip``, ``wear.pressure_profiles``, ``wear.integrate``, ``wear.substeps``, ``wear.accumulate``,
``wear.solid_wear``, ``wear.triangle_finder``, ``wear.surface``) ← the case
(``wear.case``) ← erosion (``wear.erosion``) ← a component's wall (``wear.wall``: impact records, the wall, per-face
sums; never the chains nor the command line) ← the chains (``wear.chain``) ← the command line (``wear.app``).
``meshes`` is data: it imports nothing of the project (``fem.axisymmetric.regenerate_mesh`` regenerates its mesh).
No import cycle between the project's modules (imports for type checking included), and at most 10 function-level
imports of them, each with a comment saying why.
"""

from __future__ import annotations

import ast
import importlib
import re
import subprocess
import sys
from pathlib import Path

import pytest

import wear
from wear.app.cli import JOB_COMMANDS
from wear.app.sweep.stages import STAGES
from wear.app.validation.checks import AREAS
from wear.app.validation.groups import BY_AREA, GROUPS
from wear.case import JOBS
from wear.laws.registry import LAWS

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("contact", "fem", "wear", "meshes")
ROOMS = (
    ("contact",),
    ("fem.core",),
    ("fem.axisymmetric", "fem.solid"),
    ("fem",),
    (
        "wear.law",
        "wear.laws",
        "wear.pressure",
        "wear.slip",
        "wear.pressure_profiles",
        "wear.integrate",
        "wear.substeps",
        "wear.accumulate",
        "wear.solid_wear",
        "wear.triangle_finder",
        "wear.surface",
    ),
    ("wear.case",),
    ("wear.erosion",),
    ("wear.wall",),
    ("wear.chain",),
    ("wear.app",),
)


def _modules() -> dict[str, Path]:
    out = {}
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            parts = list(path.relative_to(ROOT).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = path
    return out


MODULES = _modules()


def _prefix(module: str) -> str:
    """The longest prefix in ROOMS that ``module`` falls under (``fem.solid.mesh`` is in ``fem.solid``, not ``fem``)."""
    matches = [p for prefixes in ROOMS for p in prefixes if module == p or module.startswith(p + ".")]
    if not matches:
        raise AssertionError(f"{module} is in no room: add it to ROOMS")
    return max(matches, key=len)


def _room(module: str) -> int:
    """The room of a module; the package ``wear`` itself re-exports the chains (its room is theirs)."""
    if module == "wear":
        return _room("wear.chain")
    prefix = _prefix(module)
    return next(rank for rank, prefixes in enumerate(ROOMS) if prefix in prefixes)


def _target(name: str) -> str | None:
    """The project module an imported dotted name refers to (the longest known prefix), or None."""
    parts = name.split(".")
    for n in range(len(parts), 0, -1):
        candidate = ".".join(parts[:n])
        if candidate in MODULES:
            return candidate
    return None


def _imports(module: str) -> list[tuple[str, int, bool]]:
    """(imported project module, line, outside any function) of ``module``: imports at module level, including those
    under ``if TYPE_CHECKING:``, which an import cycle counts too."""
    path = MODULES[module]
    tree = ast.parse(path.read_text(encoding="utf-8"))
    functions = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)
    inner = {id(n) for f in ast.walk(tree) if isinstance(f, functions) for n in ast.walk(f)}
    found = []
    for node in ast.walk(tree):
        names: list[str] = []
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names = [f"{node.module}.{a.name}" for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            raise AssertionError(f"{path}:{node.lineno}: relative import; write the module's full name")
        for name in names:
            target = _target(name)
            if target is not None and target != module:
                found.append((target, node.lineno, id(node) not in inner))
    return found


def test_every_module_is_in_a_room():
    for module in MODULES:
        if module.split(".")[0] != "meshes":
            _room(module)


@pytest.mark.parametrize("module", sorted(m for m in MODULES if not m.startswith("meshes")))
def test_imports_go_one_way(module):
    room = _room(module)
    for target, line, _ in _imports(module):
        assert not target.startswith("meshes"), f"{MODULES[module]}:{line} imports the data package meshes"
        if module.endswith("__init__") or MODULES[module].name == "__init__.py":
            continue  # a package's __init__ re-exports what is below it
        assert _room(target) <= room, (
            f"{MODULES[module]}:{line}: {module} (room {ROOMS[room]}) imports {target} (room "
            f"{ROOMS[_room(target)]}), against the direction contact <- fem <- wear law <- case <- erosion <- "
            "chains <- app"
        )


PLATES = ("fem.axisymmetric", "fem.solid")


@pytest.mark.parametrize("module", sorted(m for m in MODULES if m.startswith("fem.") and _prefix(m) in PLATES))
def test_neither_plate_imports_the_other(module):
    own = _prefix(module)
    for target, line, _ in _imports(module):
        other = _prefix(target) if target.startswith("fem.") else None
        assert other not in PLATES or other == own, f"{MODULES[module]}:{line}: the plate {own} imports {other}"


@pytest.mark.parametrize("module", sorted(m for m in MODULES if m == "fem.core" or m.startswith("fem.core.")))
def test_the_core_imports_no_plate(module):
    for target, line, _ in _imports(module):
        plate = _prefix(target) if target.startswith("fem.") else None
        assert plate not in PLATES, f"{MODULES[module]}:{line}: the FE core imports the plate {plate}"


#: The FE solvers: the core and each plate's folder (the command line asks the chains and fem's face, never these).
SOLVERS = ("fem.core", *PLATES)


@pytest.mark.parametrize("module", sorted(m for m in MODULES if m.startswith("wear.app")))
def test_the_command_line_imports_no_solver_module(module):
    for target, line, _ in _imports(module):
        assert not target.startswith(tuple(f"{s}." for s in SOLVERS)) and target not in SOLVERS, (
            f"{MODULES[module]}:{line}: the command line imports the solver module {target}"
        )


def test_meshes_is_data():
    modules = [m for m in MODULES if m.startswith("meshes")]
    assert modules, "the data package meshes is not found"
    for module in modules:
        targets = {t for t, _, _ in _imports(module)}
        assert not targets, f"{module} imports {sorted(targets)}: meshes is data, it imports nothing of the project"


def test_no_import_cycle():
    graph = {m: sorted({t for t, _, top in _imports(m) if top}) for m in MODULES}
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> None:
        state[node] = 1
        stack.append(node)
        for nxt in graph[node]:
            if state.get(nxt) == 1:
                raise AssertionError("import cycle: " + " -> ".join(stack[stack.index(nxt) :] + [nxt]))
            elif nxt not in state:
                visit(nxt)
        stack.pop()
        state[node] = 2

    for module in graph:
        if module not in state:
            visit(module)


def test_function_level_imports_are_few_and_say_why():
    inner = []
    for module, path in MODULES.items():
        lines = path.read_text(encoding="utf-8").splitlines()
        for _target_module, line, top in _imports(module):
            if not top:
                here, before = lines[line - 1], lines[line - 2] if line > 1 else ""
                assert "#" in here or before.strip().startswith("#"), f"{path}:{line}: say why the import is here"
                inner.append(f"{path.relative_to(ROOT)}:{line}")
    assert len(inner) <= 10, inner


@pytest.mark.parametrize(
    "module", ["contact", "wear.law", "wear.laws", "wear.laws.registry", "wear.solid_wear", "wear.case"]
)
def test_light_modules_do_not_load_the_fe_plate(module):
    """The impact engine and the wear law work without the FE plate: importing them (in a fresh interpreter)
    loads neither ``fem`` nor scikit-fem, so that ``wear/__init__.py`` re-exporting the chains costs nothing."""
    code = f"import sys, {module}; print(sorted(m for m in ('fem', 'skfem') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert out.stdout.strip() == "[]", f"import {module} loads {out.stdout.strip()}"


@pytest.mark.parametrize("module", ["wear.law", "contact.checks"])
def test_the_wear_law_and_the_checks_load_no_numba(module):
    """The wear law and the input checks are plain numpy: importing them (in a fresh interpreter) loads neither the
    impact's numba engine nor scipy nor scikit-fem (``contact/__init__.py`` exports the impact and the closed forms
    on first access), so that a script or a worker that evaluates a wear law starts in a fraction of a second."""
    code = f"import sys, {module}; print(sorted(m for m in ('numba', 'scipy', 'skfem') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert out.stdout.strip() == "[]", f"import {module} loads {out.stdout.strip()}"


@pytest.mark.parametrize("module", sorted(m for m in MODULES if not m.startswith(("wear.app", "meshes"))))
def test_no_matplotlib_below_the_command_line(module):
    """Plotting is the command line's (``wear.app``): no module below it imports matplotlib, not even inside a
    function (the run-time check below sees only what importing the chains loads)."""
    for node in ast.walk(TREES[module]):
        names = [a.name for a in node.names] if isinstance(node, ast.Import) else []
        names += [node.module or ""] if isinstance(node, ast.ImportFrom) else []
        assert not any(n.split(".")[0] == "matplotlib" for n in names), f"{MODULES[module]}:{node.lineno}: {names}"


def test_the_chains_load_no_matplotlib():
    """Figures are the command line's (``wear.app``): importing the chains (in a fresh interpreter) loads no
    matplotlib module, so that a script that runs them pays nothing for plotting (the 3-D plate's fields are located
    in its surface triangles by :func:`wear.triangle_finder.find_triangles`, not matplotlib's trifinder)."""
    code = "import sys, wear.chain; print(sorted(m for m in sys.modules if m.startswith('matplotlib')))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert out.stdout.strip() == "[]", f"import wear.chain loads {out.stdout.strip()}"


def test_each_wear_law_is_one_module_of_the_registry():
    """The registry (:data:`wear.laws.registry.LAWS`) lists the law modules' declarations by plain imports: each law
    is ``wear.laws.<name>.LAW``, and no ``"module:attribute"`` string names one."""
    for name, law in LAWS.items():
        assert importlib.import_module(f"wear.laws.{name}").LAW is law
    text = (ROOT / "wear" / "laws" / "registry.py").read_text(encoding="utf-8")
    assert not re.search(r"[\"']wear\.[\w.]+:\w+", text)


WEAR_LAW_ROOM = next(room for room in ROOMS if "wear.law" in room)


@pytest.mark.parametrize("module", sorted(m for m in MODULES if m.startswith(WEAR_LAW_ROOM)))
def test_the_wear_law_never_imports_the_fe(module):
    """The wear law reads a plate's surface field (contact.fields.SurfaceField: plain arrays), never the plate: no
    module of its room imports ``fem`` (not even for a type)."""
    for target, line, _ in _imports(module):
        assert target.split(".")[0] != "fem", f"{MODULES[module]}:{line}: the wear law imports {target}"


def test_the_jobs_commands_and_stages_are_listed_above_the_case():
    """The jobs (wear.case.JOBS) are data: name, tables, default case, plate models. Their commands
    (wear.app.cli.JOB_COMMANDS) and sweep stages (wear.app.sweep.stages.STAGES) are listed in the command line's
    room, which imports what they run by name; importing the case loads none of that room. Every job has its
    command, in the jobs' order, and every stage belongs to a job and runs a function."""
    code = "import sys, wear.case; print(sorted({m.split('.')[1] for m in sys.modules if m.startswith('wear.')}))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    # the case reads the wear laws' registry (their names and keys), not their per-impact wear (wear.laws.impact)
    assert out.stdout.strip() == "['case', 'law', 'laws', 'pressure', 'pressure_profiles', 'slip']"
    assert tuple(JOB_COMMANDS) == tuple(JOBS)
    for name, command in JOB_COMMANDS.items():
        assert callable(command.configure) and callable(command.main) and command.HELP, name
    order = list(JOBS)
    assert [order.index(stage.job) for stage in STAGES.values()] == sorted(order.index(s.job) for s in STAGES.values())
    for name, stage in STAGES.items():
        assert callable(stage.function) and stage.name == name, name
        assert all(isinstance(v, str) for v in stage.result_units().values()), name


#: A string naming a project object for an import on use: ``"module:attribute"``.
_REFERENCE = re.compile(r"[A-Za-z_][\w.]*:[A-Za-z_]\w*")
#: The one module that imports by name on use: the package ``wear``'s lazy re-exports (PEP 562), so that importing
#: ``wear.case`` (which runs ``wear/__init__.py``) does not load the chains.
_LAZY = "wear"


def _dynamic_imports(tree: ast.Module) -> list[str]:
    """The calls in ``tree`` that import a module named by a string (``importlib.import_module``, ``__import__``,
    ``pkgutil.resolve_name``)."""
    names = ("import_module", "__import__", "resolve_name")
    return [
        ast.unparse(node)
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and (getattr(node.func, "attr", None) or getattr(node.func, "id", None)) in names
    ]


@pytest.mark.parametrize("module", sorted(m for m in MODULES if not m.startswith("meshes")))
def test_the_wiring_is_plain_imports(module):
    """What calls what is a plain import, which the import graph above and jump-to-definition follow: no
    ``"module:attribute"`` string names a project object (nor an f-string builds one), no ``resolve`` helper imports
    one on use, and no module but the package ``wear`` (its lazy re-exports) imports a module named by a string."""
    tree = TREES[module]
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and _REFERENCE.fullmatch(node.value):
            assert _target(node.value.partition(":")[0]) is None, f"{MODULES[module]}:{node.lineno}: {node.value!r}"
        if isinstance(node, ast.JoinedStr):
            text = "".join(p.value if isinstance(p, ast.Constant) else "{}" for p in node.values)
            assert not re.fullmatch(r"\{\}:[A-Za-z_]\w*", text), f"{MODULES[module]}:{node.lineno}: {ast.unparse(node)}"
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            assert node.name != "resolve", f"{MODULES[module]}:{node.lineno}: a resolve() helper"
    calls = _dynamic_imports(tree)
    assert module == _LAZY or not calls, f"{MODULES[module]}: imports by name on use: {calls}"


VALIDATION = ROOT / "wear" / "app" / "validation"


def _group_functions() -> set[str]:
    """The check groups the validation's modules define: their public functions ``name(quick) -> list[Check]``."""
    names = set()
    for path in sorted(VALIDATION.glob("*.py")):
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.FunctionDef) and not _private(node.name) and node.returns is not None:
                if ast.unparse(node.returns) == "list[Check]":
                    names.add(node.name)
    return names


def test_the_validation_groups_are_listed():
    """The check groups are listed by area (wear.app.validation.groups imports each group's function by name), not
    registered by importing their modules: the listing alone, imported first in a fresh interpreter, holds every
    area's groups, and it holds every group the validation's modules define, none of them decorated."""
    code = (
        "import sys; from wear.app.validation.groups import BY_AREA, GROUPS; "
        "print({a: len(f) for a, f in BY_AREA.items()}, len(GROUPS), 'wear.app.validation.runner' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert out.stdout.strip() == "{'contact': 10, 'fem': 5, 'wear': 13} 28 False"
    assert tuple(BY_AREA) == AREAS
    assert {name: group.function.__name__ for name, group in GROUPS.items()} == {n: n for n in _group_functions()}
    for path in sorted(VALIDATION.glob("*.py")):
        decorated = [
            node.name
            for node in ast.parse(path.read_text(encoding="utf-8")).body
            if isinstance(node, ast.FunctionDef) and node.decorator_list
        ]
        assert not decorated, f"{path.relative_to(ROOT)}: decorated functions {decorated}: list a group instead"


def test_the_package_wear_exports_its_names():
    for name in wear.__all__:  # each is loaded on first access (PEP 562) and kept
        getattr(wear, name)
        assert name in vars(wear), name
    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        wear.nothing  # noqa: B018


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _owned(tree: ast.Module) -> set[str]:
    """The private names a module defines: at module level, in class bodies (methods, class attributes,
    dataclass fields) and as ``self._x = ...`` in its methods."""
    names: set[str] = set()
    bodies = [tree.body, *(node.body for node in ast.walk(tree) if isinstance(node, ast.ClassDef))]
    for body in bodies:
        for node in body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                names.add(node.name)
            elif isinstance(node, (ast.Assign, ast.AnnAssign)):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                names.update(n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name))
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store) and _is_self(node.value):
            names.add(node.attr)
    return {n for n in names if _private(n)}


def _is_self(node: ast.expr) -> bool:
    return isinstance(node, ast.Name) and node.id in ("self", "cls")


TREES = {module: ast.parse(path.read_text(encoding="utf-8")) for module, path in MODULES.items()}
OWNED = {module: _owned(tree) for module, tree in TREES.items()}


@pytest.mark.parametrize("module", sorted(MODULES))
def test_no_private_name_crosses_modules(module):
    """A name with a leading underscore stays in the module that defines it: never imported from another project
    module, never read or written (``x._y``, ``getattr(x, "_y")``, a keyword ``_y=``) on another module's object
    when the module itself does not define ``_y``, and never written onto an object other than ``self``/``cls``
    (``self._y`` and a module's own private names are its business)."""
    others = set().union(*(names for m, names in OWNED.items() if m != module)) - OWNED[module]
    path, bad = MODULES[module], []
    for node in ast.walk(TREES[module]):
        if isinstance(node, ast.ImportFrom) and node.module and _target(node.module):
            bad += [f"from {node.module} import {a.name}" for a in node.names if _private(a.name)]
        elif isinstance(node, ast.Attribute) and _private(node.attr) and not _is_self(node.value):
            if node.attr in others or isinstance(node.ctx, ast.Store):
                bad.append(ast.unparse(node))
        elif isinstance(node, ast.Call):
            function = node.func.id if isinstance(node.func, ast.Name) else None
            if function in ("getattr", "setattr", "hasattr", "delattr") and len(node.args) >= 2:
                obj, name = node.args[:2]
                if isinstance(name, ast.Constant) and isinstance(name.value, str) and _private(name.value):
                    if not _is_self(obj) and (name.value in others or function in ("setattr", "delattr")):
                        bad.append(ast.unparse(node))
            bad += [f"{ast.unparse(node.func)}({k.arg}=...)" for k in node.keywords if k.arg in others]
    assert not bad, f"{path.relative_to(ROOT)}: private names of other modules: {bad}"
