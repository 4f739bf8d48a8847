"""Checks of the built HTML, run at the end of every docs build; each finding is a warning (an error with ``-W``).

- **Offline maths**: no page loads MathJax (or any script) from a network address, and the MathJax the pages load
  (``sphinx-mathjax-offline``'s copy, under ``_static/``) is in the build. A page opened without a network then
  renders every equation.
- **Whole API summaries**: autosummary takes the first sentence of a docstring as its one-line summary and ends a
  sentence at any period followed by a space, so ``errata Eq. 6`` in a first sentence cut the summary to
  ``errata Eq.``. A summary of the API tables that ends in such an abbreviation is reported (write "equation 6" in
  a docstring's first sentence).
- **No runaway italics**: in the Markdown pages, an emphasis opened inside a word (``8G*a`` reads ``*`` as an
  opening delimiter, which italicises everything up to the next ``*``), or one longer than a title, is reported
  (write ``8G\\*a``); and in the built pages, whatever their source (Markdown, reST, docstrings), an italic span
  (``<em>``) longer than a title.
- **No build machine in the pages**: no page shows the absolute path of the source tree, the temporary folder
  (``/tmp/``) or the home folder, or a Python warning (``...Warning: ...``), and no example's output a traceback:
  what the examples print, and what they write to stderr, is part of the gallery pages.
- **A figure in every example**: each gallery page (when the gallery is run) shows at least one figure.
- **Maths as maths**: on the user-guide pages whose equations are MyST maths (:data:`MATH_PAGES`), an equation-like
  run of plain text outside a math role is reported: ``^`` between word characters (``p^α``, ``m^(1−β)``,
  ``(k/n)^{3/2}``), ``√``,
  ``_{``, a subscript between letters (``p_max``, ``e_n``) or a Unicode subscript (``p₀``). Code, maths, links,
  URLs and file names are not searched. Write ``$p_{\\max}$``; a name of the code goes in backticks.
- **No code line scrolls sideways**: in the Markdown pages (``docs/*.md``), a line of a code block (a fence of
  any language, ``python``, ``bash``, ``toml``, ``text``, none, or ``{code-block}``; fences inside a note or other
  admonition too) longer than :data:`LONGEST_CODE_LINE` characters is reported. Break a command with a final ``\\``, a
  Python line inside parentheses, a TOML array over lines. A program's printed output is exempt, as it prints it
  (a wrapped copy would not be what it prints): in a ``console`` block the lines that are not commands (a command
  starts with ``$ ``, and runs on after a line ending in ``\\``), and an ``output`` block (a program's output or a
  file's lines, verbatim). The gallery's examples (``examples/*.py``, split into cells as sphinx-gallery splits
  them) too: a line of a code cell, or of a literal block (``::``, ``.. code-block::``) in the docstring or a text
  cell, longer than :data:`LONGEST_CODE_LINE`. What an example prints is exempt (it is not in the source).
- **Reference apart from record**: a page of the user guide, the reference or the results (every page but the
  development record's, ``*-record.md``, and the changelog: :data:`RECORD_PAGES`) is reported if it holds an ISO
  date (``2026-11-27``: a dated measurement) or a commit hash (7 to 40 hexadecimal characters with a digit and a
  letter, ``0c54ec7``), outside URLs. What was tried and when, and dated timings, go to a record page; the page
  keeps the current numbers and links to the record.
"""

from __future__ import annotations

import html
import re
import tempfile
from pathlib import Path

from markdown_it import MarkdownIt
from mdit_py_plugins.dollarmath import dollarmath_plugin
from sphinx.util import logging
from sphinx_gallery.py_source_parser import split_code_and_text_blocks

logger = logging.getLogger(__name__)

#: A script or stylesheet loaded from a network address (src/href of script and link tags).
_REMOTE_ASSET = re.compile(r"<(?:script|link)\b[^>]*\b(?:src|href)=[\"'](?:https?:)?//[^\"']+", re.IGNORECASE)
#: A MathJax or CDN address anywhere in a page, e.g. in an inline loader script.
_REMOTE_MATH = re.compile(r"(?:https?:)?//[^\s\"'<>]*(?:mathjax|katex|cdn\.jsdelivr|cdnjs|unpkg)", re.IGNORECASE)
#: The summary cell of an autosummary table row (the second cell).
_SUMMARY_CELL = re.compile(r"<tr class=\"row-(?:odd|even)\"><td>.*?</td>\s*<td><p>(.*?)</p></td>", re.DOTALL)
#: Abbreviations autosummary takes for a sentence end (its own list: et al., e.g., i.e., vs.).
_ABBREVIATION = re.compile(r"\b(?:Eqs?|Figs?|Refs?|Secs?|Tabs?|Nos?|Vol|Proc|cf|approx|resp|incl|ca)\.$")


def _pages(outdir: Path) -> list[Path]:
    return sorted(outdir.rglob("*.html"))


def _check_offline_math(app, pages: list[Path]) -> None:
    outdir = Path(app.outdir)
    local = outdir / "_static" / app.config.mathjax_path
    if app.config.mathjax_path.startswith(("http:", "https:", "//")) or not local.is_file():
        logger.warning(f"MathJax is not served from the build: mathjax_path = {app.config.mathjax_path!r}")
    for page in pages:
        text = page.read_text(encoding="utf-8")
        found = _REMOTE_ASSET.findall(text) + _REMOTE_MATH.findall(text)
        if found:
            logger.warning(f"{page.relative_to(outdir)} loads from the network: {found[0]}")


def _check_api_summaries(app, pages: list[Path]) -> None:
    outdir = Path(app.outdir)
    for page in pages:
        for cell in _SUMMARY_CELL.findall(page.read_text(encoding="utf-8")):
            summary = html.unescape(re.sub(r"<[^>]+>", "", cell)).strip()
            if _ABBREVIATION.search(summary):
                logger.warning(f"{page.relative_to(outdir)}: API summary cut at an abbreviation: {summary!r}")


#: The longest emphasis (characters) a page means: a title in italics; longer ones ran on past a stray delimiter.
_LONGEST_EMPHASIS = 80
#: An italic span of a built page (``<em>`` without attributes: signatures' parameters are ``<em class=...>``).
_EM_SPAN = re.compile(r"<em>(.*?)</em>", re.DOTALL)


def _emphasis_problems(text: str) -> list[str]:
    """The emphases of a Markdown ``text`` that a stray ``*`` or ``_`` opened: inside a word, or running on."""
    parser = MarkdownIt("commonmark").enable("table").use(dollarmath_plugin)  # $...$ as MyST reads it
    problems = []
    for block in parser.parse(text):
        children = block.children or []
        for k, token in enumerate(children):
            if token.type not in ("em_open", "strong_open"):
                continue
            before = children[k - 1] if k else None
            close = token.type.replace("_open", "_close")
            end = next((j for j in range(k + 1, len(children)) if children[j].type == close), len(children))
            inside = "".join(c.content for c in children[k + 1 : end])
            line = (block.map[0] + 1) if block.map else 0
            if before is not None and before.type == "text" and before.content[-1:].isalnum():
                problems.append(f"line {line}: emphasis opened inside a word: {before.content[-10:]}{token.markup}")
            elif len(inside) > _LONGEST_EMPHASIS:
                problems.append(f"line {line}: emphasis of {len(inside)} characters: {inside[:40]!r}…")
    return problems


def _warn_on_pages(app, names, find, why: str = "") -> None:
    """A warning for each problem ``find`` (a function of a page's Markdown text) reports on the pages ``names``
    (relative to the source folder; None: every page), each naming its page and ending in ``why``."""
    srcdir = Path(app.srcdir)
    if names is None:
        names = sorted(str(page.relative_to(srcdir)) for page in srcdir.glob("*.md"))
    for name in names:
        for problem in find((srcdir / name).read_text(encoding="utf-8")):
            logger.warning(f"{name}, {problem}{why}")


def _check_emphasis(app) -> None:
    _warn_on_pages(app, None, _emphasis_problems)


def _long_italics(text: str) -> list[str]:
    """The italic spans of an HTML ``text`` longer than :data:`_LONGEST_EMPHASIS` characters (tags left out)."""
    spans = (html.unescape(re.sub(r"<[^>]+>", "", span)) for span in _EM_SPAN.findall(text))
    return [" ".join(span.split()) for span in spans if len(" ".join(span.split())) > _LONGEST_EMPHASIS]


def _check_italics(app, pages: list[Path]) -> None:
    outdir = Path(app.outdir)
    for page in pages:
        for span in _long_italics(page.read_text(encoding="utf-8")):
            logger.warning(f"{page.relative_to(outdir)}: italics of {len(span)} characters: {span[:40]!r}…")


#: The user-guide pages whose equations are written as MyST maths (``$...$``, ``$$...$$``): on these, plain-text
#: maths is reported. Pages not listed here still write some equations as text.
MATH_PAGES = ("wear.md", "wear-laws.md", "wall.md", "run.md", "repeat.md", "fem.md")
#: Plain-text maths: ``^`` after a word character or ``)``, a root sign, ``_{``, a subscript between letters, a Unicode
#: subscript.
_PLAIN_MATH = re.compile(r"[\w)]\^[\w(\-−{]|√|_\{|[^\W\d_]_[^\W_]|[\u2080-\u209c]")
#: A word that is a URL, a path or a file name (``fig_wear_laws.png``, ``docs/fem.md``): not maths.
_NOT_MATH_WORD = re.compile(r"^\W*(?:\S*://\S*|www\.\S*|[\w.-]*/[\w./-]*\.\w+|[\w-]+\.[A-Za-z][\w]{0,4})\W*$")
#: Admonition-like directives whose body is Markdown (searched like the page); other fences are code.
_PROSE_DIRECTIVES = re.compile(
    r"^\{(?:note|warning|tip|important|hint|attention|caution|seealso|admonition|dropdown)\}"
)


def _plain_math(text: str, first_line: int = 0) -> list[str]:
    """The equation-like runs of plain text in a Markdown ``text``, outside code, maths, links and file names."""
    parser = MarkdownIt("commonmark").enable("table").use(dollarmath_plugin)  # $...$ as MyST reads it
    found = []
    for block in parser.parse(text):
        line = first_line + (block.map[0] + 1 if block.map else 0)
        if block.type == "fence" and _PROSE_DIRECTIVES.match(block.info.strip()):
            body = "\n".join(ln for ln in block.content.splitlines() if not re.match(r"^:\w[\w-]*:", ln))
            found += _plain_math(body, line)
            continue
        depth = 0  # inside a link
        for token in block.children or []:
            depth += token.type == "link_open"
            depth -= token.type == "link_close"
            if token.type != "text" or depth:
                continue
            for word in token.content.split():
                if not _NOT_MATH_WORD.match(word) and _PLAIN_MATH.search(word):
                    found.append(f"line {line}: {word!r}")
    return found


def _check_plain_math(app) -> None:
    _warn_on_pages(app, MATH_PAGES, _plain_math, ": plain-text maths outside a math role (write $...$)")


#: The longest code line (characters) of a page's code block: the line length of the project's code (ruff), and
#: about what the theme's code blocks show without a scroll bar.
LONGEST_CODE_LINE = 88
#: Fences that are not code: directives whose body is not shown as a code block.
_CODE_DIRECTIVES = re.compile(r"^\{(?:code|code-block|sourcecode|code-cell)\}")


def _long_code_lines(text: str, first_line: int = 0) -> list[str]:
    """The lines over :data:`LONGEST_CODE_LINE` characters of a Markdown ``text``'s code blocks, except printed
    output (a ``console`` block's lines that are not commands, an ``output`` block)."""
    parser = MarkdownIt("commonmark").enable("table").use(dollarmath_plugin)
    found = []
    for block in parser.parse(text):
        if block.type not in ("fence", "code_block"):
            continue
        info = block.info.strip()
        start = first_line + (block.map[0] + 1 if block.map else 0)
        if _PROSE_DIRECTIVES.match(info):
            body = "\n".join("" if re.match(r"^:\w[\w-]*:", ln) else ln for ln in block.content.splitlines())
            found += _long_code_lines(body, start)
            continue
        if info.startswith("{") and not _CODE_DIRECTIVES.match(info):
            continue  # toctree, include, figure, eval-rst...: not a code block of the page
        language = info.split("}")[-1].split()[0] if info.split("}")[-1].split() else ""
        if language == "output":
            continue
        command = False  # a console block's command, which runs on after a line ending in a backslash
        for k, line in enumerate(block.content.splitlines()):
            if language == "console":
                command = line.startswith("$") or command
                if not command:
                    continue
                command = line.rstrip().endswith("\\")
            if len(line) > LONGEST_CODE_LINE:
                where = start + k + (block.type == "fence")
                found.append(f"line {where}: code line of {len(line)} characters: {line[:40]!r}…")
    return found


#: The start of a literal block in reST: a code directive, or a paragraph ending in ``::`` (not a directive's).
_REST_CODE_START = re.compile(r"^\s*\.\.\s+(?:code-block|code|sourcecode)::|^(?!\s*\.\.\s).*::\s*$")


def _rest_code_lines(text: str) -> list[tuple[int, str]]:
    """The lines (index in ``text``, line as shown: the block's indent removed) of a reST ``text``'s literal blocks
    and code directives (a directive's options left out)."""
    lines = text.splitlines()
    found = []
    k = 0
    while k < len(lines):
        if not _REST_CODE_START.match(lines[k]):
            k += 1
            continue
        indent = len(lines[k]) - len(lines[k].lstrip())
        body = []
        k += 1
        while k < len(lines) and (not lines[k].strip() or len(lines[k]) - len(lines[k].lstrip()) > indent):
            if lines[k].strip() and not (not body and re.match(r"^\s*:\w[\w-]*:", lines[k])):
                body.append(k)
            k += 1
        shown = min((len(lines[j]) - len(lines[j].lstrip()) for j in body), default=0)
        found += [(j, lines[j][shown:]) for j in body]
    return found


def _long_example_lines(path: Path) -> list[str]:
    """The lines over :data:`LONGEST_CODE_LINE` characters of a gallery example's code, as its page shows it: the
    code cells, and the literal blocks of its docstring and text cells (line numbers of the ``.py`` file)."""
    found = []
    for block in split_code_and_text_blocks(path)[1]:
        if block.type == "code":
            lines = list(enumerate(block.content.splitlines()))
        else:  # a text cell: its lines follow its "# %%" line (sphinx-gallery drops the leading blank ones)
            lines = _rest_code_lines(block.content)
        for k, line in lines:
            if len(line) > LONGEST_CODE_LINE:
                found.append(f"line {block.lineno + k}: code line of {len(line)} characters: {line[:40]!r}…")
    return found


def _gallery_examples(app) -> list[Path]:
    """The example scripts of the gallery (``sphinx_gallery_conf``'s ``examples_dirs``, relative to the source)."""
    conf = getattr(app.config, "sphinx_gallery_conf", None) or {}
    dirs = conf.get("examples_dirs", [])
    return sorted(p for d in ([dirs] if isinstance(dirs, str) else dirs) for p in (Path(app.srcdir) / d).glob("*.py"))


def _check_code_lines(app) -> None:
    why = f" (longer than {LONGEST_CODE_LINE}: it scrolls)"
    _warn_on_pages(app, None, _long_code_lines, why)
    root = Path(app.srcdir).resolve().parent
    for path in _gallery_examples(app):
        name = path.resolve().relative_to(root) if path.resolve().is_relative_to(root) else path.name
        for problem in _long_example_lines(path):
            logger.warning(f"{name}, {problem}{why}")


#: The pages exempt from the record check: the development record (``*-record.md``) and the changelog, which
#: hold the dated history on purpose.
RECORD_PAGES = re.compile(r"(?:-record|^changelog)\.md$")
#: An ISO date (``2026-11-27``), a whole word.
_ISO_DATE = re.compile(r"(?<![\w-])\d{4}-(?:0[1-9]|1[0-2])-(?:0[1-9]|[12]\d|3[01])(?![\w-])")
#: A commit hash: 7 to 40 hexadecimal characters with at least one digit and one letter, a whole word (not part of
#: a number such as ``1.000000e-03``).
_COMMIT_HASH = re.compile(r"(?<![\w.+-])(?=[0-9a-fA-F]*\d)(?=[0-9a-fA-F]*[a-fA-F])[0-9a-fA-F]{7,40}(?![\w+-]|\.\w)")
#: A URL (its path may hold a date or a hash legitimately).
_URL = re.compile(r"(?:https?|ftp)://\S+|www\.\S+")


def _record_text(text: str) -> list[str]:
    """The ISO dates and commit hashes of a Markdown ``text`` outside URLs: what belongs on a record page."""
    found = []
    for number, line in enumerate(text.splitlines(), start=1):
        line = _URL.sub(" ", line)
        found += [f"line {number}: date {m.group()!r}" for m in _ISO_DATE.finditer(line)]
        found += [f"line {number}: commit hash {m.group()!r}" for m in _COMMIT_HASH.finditer(line)]
    return found


def _check_record_text(app) -> None:
    names = sorted(p.name for p in Path(app.srcdir).glob("*.md") if not RECORD_PAGES.search(p.name))
    why = ": a dated measurement or a commit hash belongs on a development-record page (*-record.md)"
    _warn_on_pages(app, names, _record_text, why)


#: A Python warning as ``warnings`` prints it (``file.py:12: UserWarning: text``).
_PYTHON_WARNING = re.compile(r"\b[A-Z]\w*Warning: ")
#: A traceback (a doctest of an error shows one on purpose: only what an example printed is searched).
_TRACEBACK = re.compile(r"Traceback \(most recent call last\)")
#: What an example printed: sphinx-gallery's output blocks.
_SCRIPT_OUTPUT = re.compile(r"<div class=\"sphx-glr-script-out.*?</pre>", re.DOTALL)


def _machine_paths(app) -> list[str]:
    """Paths of the build machine that no page may show: the source tree, the temporary folder, the home folder."""
    paths = {str(Path(app.srcdir).resolve().parent), "/tmp/", str(Path(tempfile.gettempdir()).resolve()) + "/"}
    home = Path.home().resolve()
    if home != home.parent:  # a home folder "/" is in every path
        paths.add(str(home) + "/")
    return sorted(paths)


def _check_machine_text(app, pages: list[Path]) -> None:
    outdir = Path(app.outdir)
    paths = _machine_paths(app)
    for page in pages:
        text = html.unescape(page.read_text(encoding="utf-8"))
        found = [p for p in paths if p in text]
        if found:
            logger.warning(f"{page.relative_to(outdir)} shows a path of the build machine: {found[0]!r}")
        printed = "\n".join(_SCRIPT_OUTPUT.findall(text))
        warning = _PYTHON_WARNING.search(text) or _TRACEBACK.search(printed)
        if warning:
            where = warning.string
            line = where[where.rfind("\n", 0, warning.start()) + 1 : where.find("\n", warning.end())]
            logger.warning(f"{page.relative_to(outdir)} shows a Python warning or traceback: {line.strip()[:200]!r}")


#: An image the gallery's matplotlib scraper put on an example's page.
_GALLERY_FIGURE = re.compile(r"<img\b[^>]*\bclass\s*=\s*\"[^\"]*sphx-glr-(?:single|multi)-img")


def _check_gallery_figures(app) -> None:
    conf = getattr(app.config, "sphinx_gallery_conf", None) or {}
    if str(conf.get("plot_gallery", "True")) == "False":  # the gallery shown without running the examples
        return
    outdir = Path(app.outdir)
    dirs = conf.get("gallery_dirs", [])
    for gallery in [dirs] if isinstance(dirs, str) else dirs:
        for page in sorted((outdir / gallery).glob("*.html")):
            if page.name in ("index.html", "sg_execution_times.html"):
                continue
            if not _GALLERY_FIGURE.search(page.read_text(encoding="utf-8")):
                logger.warning(f"{page.relative_to(outdir)}: the example shows no figure")


def check_build(app, exception: Exception | None) -> None:
    """Run the checks on a finished HTML build."""
    if exception is not None or app.builder.format != "html":
        return
    pages = _pages(Path(app.outdir))
    _check_offline_math(app, pages)
    _check_api_summaries(app, pages)
    _check_emphasis(app)
    _check_italics(app, pages)
    _check_machine_text(app, pages)
    _check_gallery_figures(app)
    _check_plain_math(app)
    _check_code_lines(app)
    _check_record_text(app)


def setup(app) -> dict:
    # after sphinx-mathjax-offline has copied MathJax into the build (its handler has the default priority, 500)
    app.connect("build-finished", check_build, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
