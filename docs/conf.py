"""Sphinx configuration of the impactwear documentation.

Build (warnings are errors)::

    pip install ".[docs]" && sphinx-build -W --keep-going -b html docs docs/_build/html

Generated at build time, into ``docs/_generated/`` (not committed):

- ``commands.md``: the ``--help`` of every ``impactwear`` command, from the argparse parser;
- ``keys.md``: every case key, from the case schema;
- ``api/``: the module reference stubs (autosummary, recursive over ``contact``, ``fem``, ``wear``);
- ``examples/``: a copy of ``examples/`` plus the gallery header, which sphinx-gallery executes in quick mode
  (``IMPACTWEAR_QUICK=1``) into ``docs/auto_examples/``.

Switches (environment): ``IMPACTWEAR_DOCS_API=0`` leaves the module reference out; ``IMPACTWEAR_DOCS_GALLERY=0``
shows the gallery without running the examples.
"""

from __future__ import annotations

import atexit
import os
import re
import shutil
import sys
import tempfile
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
GENERATED = DOCS / "_generated"
sys.path.insert(0, str(ROOT))  # document (and run the gallery against) this source tree
sys.path.insert(0, str(DOCS / "_ext"))

# Off-screen, quick, quiet: the gallery runs the examples at reduced size and nothing opens a window.
os.environ.setdefault("IMPACTWEAR_QUICK", "1")
os.environ.setdefault("MPLBACKEND", "Agg")
os.environ.setdefault("PYVISTA_OFF_SCREEN", "true")


def _switch(name: str, default: bool = True) -> bool:
    value = os.environ.get(name)
    if value is None or value.strip() == "":
        return default
    return value.strip().lower() not in ("0", "false", "no", "off")


API = _switch("IMPACTWEAR_DOCS_API")
GALLERY_RUN = _switch("IMPACTWEAR_DOCS_GALLERY")

project = "impactwear"
author = "the impactwear developers"
copyright = "the impactwear developers"
try:
    from importlib.metadata import version as _version

    release = _version("impactwear")
except Exception:  # not installed: documenting a bare source tree
    release = "unknown"
version = release

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.intersphinx",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax from the pip package, copied into the build: equations render offline
    "sphinx.ext.napoleon",
    "sphinx_gallery.gen_gallery",
    "build_checks",  # docs/_ext: no page loads maths from the network; no API summary cut at "Eq."
    "public_api",  # docs/_ext: a public name (wear.run) links to its entry in the module reference
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = [
    "_build",
    "_ext",
    "_generated/examples",
    "_generated/*.md",  # included from commands.md and keys.md, not pages of their own
    "auto_examples/*.ipynb",
    "auto_examples/*.py",
    "auto_examples/*.zip",
    "auto_examples/*.json",
    "auto_examples/*.md5",
    "sg_execution_times.rst",
    "auto_examples/sg_execution_times.rst",  # of an earlier build (write_computation_times is off)
]
if not API:
    exclude_patterns += ["_generated/api"]  # stubs of an earlier build
templates_path = ["_templates"]
smartquotes = False  # keep "quotes" and -- as typed: TOML defaults, option names and code-like text

# MyST: $...$ and $$...$$ maths, ``:::`` fences, and anchors on headings so that links such as
# reproduce.md#fig-4-peak-normal-force-vs-impact-angle resolve (the generated reports are linked this way).
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
myst_heading_anchors = 3

# API reference: docstrings are reST (``code``, :func: roles, ``.. math::``); some classes and functions use
# numpy-style "Parameters" / "Attributes" sections, which napoleon turns into field lists. Every object is documented
# in the module that defines it (the packages' re-exports are not documented twice).
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_ivar = True  # "Attributes" as a field list: no second description of a dataclass field
autosummary_generate = API
autosummary_imported_members = False
autosummary_ignore_module_all = True
autodoc_default_options = {"member-order": "bysource"}
autodoc_typehints = "signature"
autodoc_preserve_defaults = True
add_module_names = False
nitpicky = False  # unresolved cross-references (e.g. np.ndarray in a type hint) are not errors
intersphinx_mapping = {
    "python": ("https://docs.python.org/3", None),
    "numpy": ("https://numpy.org/doc/stable/", None),
    "scipy": ("https://docs.scipy.org/doc/scipy/", None),
    "matplotlib": ("https://matplotlib.org/stable/", None),
}
# The build machine may have no network: an unreachable inventory is then a warning, which -W would turn into an
# error. Set IMPACTWEAR_DOCS_INTERSPHINX=1 to fetch the inventories (links into the Python/numpy/scipy docs).
if not _switch("IMPACTWEAR_DOCS_INTERSPHINX", default=False):
    intersphinx_mapping = {}

html_theme = "furo"
html_title = f"impactwear {release}"
html_static_path = ["_static"]
# printed output wrapped on screen rather than scrolling sideways (docs/_static/impactwear.css says why)
html_css_files = ["impactwear.css"]

# ---------------------------------------------------------------------------------------------------------------
# Generated pages: commands and case keys. An import failure stops the build: these pages must not go stale.


def _write_if_changed(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.is_file() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def _commands_markdown() -> str:
    import argparse

    from wear.app.cli import build_parser  # no fallback: a missing parser must fail the build

    columns = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = "88"  # argparse wraps help to the terminal width: the same page on every machine
    try:
        parser = build_parser()
        subparsers = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
        if not subparsers or not subparsers[0].choices:
            raise RuntimeError("docs/conf.py: wear.app.cli.build_parser() has no sub-commands")
        texts = {"impactwear": parser.format_help()}
        texts.update({f"impactwear {name}": sub.format_help() for name, sub in subparsers[0].choices.items()})
    finally:
        if columns is None:
            del os.environ["COLUMNS"]
        else:
            os.environ["COLUMNS"] = columns
    parts = []
    for title, text in texts.items():
        parts += [f"## `{title}`", "", "```text", text.rstrip(), "```", ""]
    return "\n".join(parts)


def _keys_markdown() -> str:
    from wear.case import key_reference  # no fallback: the key table comes from the schema or the build fails

    return key_reference().rstrip() + "\n"


def _bibtex_names(authors: list[dict]) -> str:
    names = []
    for a in authors:
        if "family-names" in a:
            names.append(f"{a['family-names']}, {a.get('given-names', '')}".rstrip(", "))
        else:
            names.append("{" + a["name"] + "}")  # an entity: braces keep BibTeX from splitting it into names
    return " and ".join(names)


def _bibtex(kind: str, key: str, work: dict) -> str:
    fields = {"title": "{" + work["title"] + "}", "author": _bibtex_names(work["authors"])}
    for cff_key, bib_key in (("journal", "journal"), ("volume", "volume"), ("issue", "number"), ("year", "year")):
        if cff_key in work:
            fields[bib_key] = str(work[cff_key])
    if "start" in work:
        fields["pages"] = f"{work['start']}--{work['end']}" if "end" in work else str(work["start"])
    if "doi" in work:
        fields["doi"] = work["doi"]
    if "license" in work:
        fields["note"] = f"License {work['license']}"
    # lines of at most 88 characters, as every code block of the site: authors broken between names, the rest
    # between words
    entries = []
    for k, v in fields.items():
        lines = []
        sep = " and " if k == "author" else " "
        line = f"  {k} = {{"
        for j, part in enumerate(v.split(sep)):
            piece = (sep if j else "") + part
            if j and len(line) + len(piece) > 86:
                lines.append(line + sep.rstrip())
                line, piece = "    ", part
            line += piece
        entries.append("\n".join([*lines, line + "}"]))
    body = ",\n".join(entries)
    return f"@{kind}{{{key},\n{body}\n}}"


def _citation_markdown() -> str:
    """The message of ``CITATION.cff`` and BibTeX entries of the software and of its references, written from it."""
    import yaml  # a dependency of myst-parser

    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    parts = [" ".join(cff["message"].split()), "", "The software:", "", "```bibtex"]
    parts += [_bibtex("software", "impactwear", cff), "```", ""]
    if cff.get("references"):
        parts += ["The paper whose model it implements (the file's references):", ""]
    for ref in cff.get("references", []):
        kind = {"article": "article", "book": "book"}.get(ref.get("type"), "misc")
        first = ref["authors"][0]
        key = (first.get("family-names") or first.get("name", "ref")).split()[0].lower() + str(ref.get("year", ""))
        parts += ["```bibtex", _bibtex(kind, key, ref), "```", ""]
    return "\n".join(parts)


_write_if_changed(GENERATED / "commands.md", _commands_markdown())
_write_if_changed(GENERATED / "keys.md", _keys_markdown())
_write_if_changed(GENERATED / "citation.md", _citation_markdown())

# ---------------------------------------------------------------------------------------------------------------
# Gallery: the examples, executed in quick mode. sphinx-gallery needs a header file in the examples folder; the
# examples folder holds only scripts and their data, so a copy of it with docs/_ext/GALLERY_HEADER.rst is run.

GALLERY_SRC = GENERATED / "examples"


def _copy_examples() -> None:
    GALLERY_SRC.mkdir(parents=True, exist_ok=True)
    wanted = {p.name: p for p in (ROOT / "examples").iterdir() if p.suffix in (".py", ".toml")}
    wanted["GALLERY_HEADER.rst"] = DOCS / "_ext" / "GALLERY_HEADER.rst"
    for old in GALLERY_SRC.iterdir():
        if old.name not in wanted and old.is_file():
            old.unlink()
    for name, src in wanted.items():
        dst = GALLERY_SRC / name
        if not dst.is_file() or dst.read_bytes() != src.read_bytes():
            shutil.copyfile(src, dst)


_copy_examples()
# The examples write their files under IMPACTWEAR_EXAMPLE_OUT: a temporary folder, out of the docs tree (they print
# no path, so no page shows one of the build machine).
_EXAMPLE_OUT = tempfile.mkdtemp(prefix="impactwear-gallery-")
atexit.register(shutil.rmtree, _EXAMPLE_OUT, ignore_errors=True)
os.environ.setdefault("IMPACTWEAR_EXAMPLE_OUT", _EXAMPLE_OUT)

sphinx_gallery_conf = {
    "examples_dirs": os.path.relpath(GALLERY_SRC, DOCS),
    "gallery_dirs": "auto_examples",
    "filename_pattern": r".*\.py$",  # run every example
    "ignore_pattern": r"__init__\.py",
    "plot_gallery": "True" if GALLERY_RUN else "False",
    # the figures an example's cell leaves open, under that cell, each checked for overlapping texts first
    "image_scrapers": ("gallery_support.checked_matplotlib_scraper",),
    "reset_modules": ("matplotlib", "gallery_support.guard_exit"),  # sys.exit in an example must not end the build
    "reset_modules_order": "both",
    "within_subsection_order": "gallery_support.example_order",  # the tutorial first
    "download_all_examples": False,
    "remove_config_comments": True,
    "abort_on_example_error": False,  # every failing example is reported, then the build fails
    "only_warn_on_example_error": False,
    "show_memory": False,
    "capture_repr": (),
    "write_computation_times": False,  # its page loads a stylesheet from a CDN: the docs must work offline
}


# ---------------------------------------------------------------------------------------------------------------
# IMPACTWEAR_DOCS_API=0: the module reference page stays (links to it hold) but its autosummary block is replaced by a
# note, so no docstring is read.

_API_BLOCK = re.compile(r"^% api-reference: start.*?^% api-reference: end[^\n]*$", re.DOTALL | re.MULTILINE)
_API_OFF_NOTE = """```{note}
The module reference was left out of this build (`IMPACTWEAR_DOCS_API=0`). Build without the variable to
include it.
```"""


def _api_switch(app, docname: str, source: list[str]) -> None:
    if docname == "api-reference" and not API:
        text, n = _API_BLOCK.subn(_API_OFF_NOTE, source[0])
        if n != 1:
            raise RuntimeError("docs/api-reference.md: the '% api-reference: start/end' markers are missing")
        source[0] = text


def setup(app) -> None:
    app.connect("source-read", _api_switch)
