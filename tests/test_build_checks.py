"""The docs build's checks of the gallery pages (docs/_ext/build_checks.py) find what they are for: a path of the
build machine, a Python warning or traceback in a page, a gallery example without a figure."""

import logging
import sys
import tempfile
from pathlib import Path
from types import SimpleNamespace

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "docs" / "_ext"))
build_checks = pytest.importorskip("build_checks")  # needs the docs extra (Sphinx, markdown-it)

FIGURE = '<img src="../_images/sphx_glr_x_001.png" alt="x" class = "sphx-glr-single-img"/>'


def _site(tmp_path: Path, pages: dict[str, str], plot_gallery: str = "True"):
    src, out = tmp_path / "src" / "docs", tmp_path / "html"
    src.mkdir(parents=True)
    for name, text in pages.items():
        (out / name).parent.mkdir(parents=True, exist_ok=True)
        (out / name).write_text(f"<html><body>{text}</body></html>", encoding="utf-8")
    conf = SimpleNamespace(sphinx_gallery_conf={"gallery_dirs": "auto_examples", "plot_gallery": plot_gallery})
    return SimpleNamespace(srcdir=str(src), outdir=str(out), config=conf), sorted(out.rglob("*.html"))


def _warnings(caplog) -> list[str]:
    return [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]


def test_clean_pages_pass(tmp_path, caplog):
    doctest = "<pre>&gt;&gt;&gt; Case().with_(impact={'angle': 120.0})\nTraceback (most recent call last):</pre>"
    pages = {"index.html": "impact at 30 deg", "api.html": doctest, "auto_examples/a.html": FIGURE}
    app, pages = _site(tmp_path, pages)
    build_checks._check_machine_text(app, pages)
    build_checks._check_gallery_figures(app)
    assert _warnings(caplog) == []


@pytest.mark.parametrize(
    "text",
    [
        "outputs in {src}/examples/out",
        f"wrote {Path(tempfile.gettempdir()).resolve()}/impactwear-gallery-1/x.csv",
        "/tmp/abc/summary.json",
        "plate.py:32: UserWarning: elastic ball: represented by a rigid sphere",
        '<div class="sphx-glr-script-out highlight-none"><div class="highlight"><pre>Traceback (most recent call last):'
        "</pre></div></div>",
    ],
)
def test_machine_path_or_warning_is_reported(tmp_path, caplog, text):
    app, _ = _site(tmp_path, {})
    app, pages = _site(tmp_path / "b", {"auto_examples/a.html": FIGURE + text.format(src=Path(app.srcdir).parent)})
    build_checks._check_machine_text(app, pages)
    assert len(_warnings(caplog)) == 1 and "auto_examples/a.html" in _warnings(caplog)[0]


def test_gallery_page_without_figure_is_reported(tmp_path, caplog):
    pages = {"auto_examples/index.html": "", "auto_examples/a.html": FIGURE, "auto_examples/b.html": "no image"}
    app, _ = _site(tmp_path, pages)
    build_checks._check_gallery_figures(app)
    assert _warnings(caplog) == ["auto_examples/b.html: the example shows no figure"]
    caplog.clear()
    app, _ = _site(tmp_path / "c", pages, plot_gallery="False")  # the gallery shown without running the examples
    build_checks._check_gallery_figures(app)
    assert _warnings(caplog) == []


@pytest.mark.parametrize(
    "text",
    [
        "Eq. 15, dw/dt = K p^α v^β at each point",
        "K in m^(1−β) s^(β−1) Pa^(−α)",
        "F_y = F·(Y/σ_vm,max)³",
        "z = −δ + R − √(R² − r²)",
        "the yield force F_{y} of Eq. 18",
        "overlaps δ (k/n)^{3/2} up to the maximum",
        "peak pressure p_max at the centre",
        "restitution e_n 0.91",
        "p₀ = 3F/(2πa²)",
        "| Finnie | E ∝ V^2 f(θ) |\n|---|---|\n| a | b |",
        "```{note}\nthe overlap δ_c\n```",
    ],
)
def test_plain_text_maths_is_reported(text):
    assert len(build_checks._plain_math(text)) >= 1


def test_maths_code_links_and_file_names_are_not_reported():
    text = (
        "Eq. 15, $\\mathrm{d}w/\\mathrm{d}t = K\\,p^{\\alpha} v^{\\beta}$, `wear.load_steps`, `p_max`,\n"
        "[the fig_wear_laws example](auto_examples/plot_wear_laws.md), fig_wear_laws.png, docs/fem.md,\n"
        "<https://example.org/a_b>, 6.60e-15 m³ in 1e-13…1e-10, 221 mm/year.\n\n"
        "```python\nw = K * p_max ** alpha\n```\n\n$$\nz = -\\delta + R - \\sqrt{R^2 - r^2}\n$$ (eq-z)\n"
    )
    assert build_checks._plain_math(text) == []


def test_converted_pages_have_no_plain_text_maths():
    docs = Path(__file__).resolve().parents[1] / "docs"
    found = {n: build_checks._plain_math((docs / n).read_text(encoding="utf-8")) for n in build_checks.MATH_PAGES}
    assert not any(found.values()), found


LONG = "x" * 89


@pytest.mark.parametrize(
    "text",
    [
        f"```python\nr = simulate_impact(radius=2.5e-3)  # {LONG}\n```",
        f"```bash\nimpactwear wall records/ case/ --set {LONG}\n```",
        f"```toml\nfree = [{LONG}]\n```",
        f"```text\nwear/app/   {LONG}\n```",
        f"```\nwear/app/   {LONG}\n```",
        f"```console\n$ impactwear {LONG}\nprinted\n```",
        f"```console\n$ impactwear wall a b \\\n    --set {LONG}\nprinted\n```",
        f"````{{note}}\n:class: dropdown\n```python\n{LONG}\n```\n````",
        f"```{{code-block}} python\n{LONG}\n```",
    ],
)
def test_long_code_line_is_reported(text):
    found = build_checks._long_code_lines("A page.\n\n" + text)
    assert len(found) == 1 and "code line of" in found[0], found


def test_printed_output_and_prose_are_not_reported(tmp_path, caplog):
    text = (
        f"A prose line {LONG}, not code.\n\n"
        f"```console\n$ impactwear wall a b \\\n    --out bend\nwall: {LONG}\n  eroded {LONG}\n```\n\n"
        f"```output\n(    x    y {LONG})\n```\n\n```python\nx = 1  # {'y' * 78}\n```\n\n"
        f"```{{figure}} figures/{LONG}.png\n```\n"
    )
    assert build_checks._long_code_lines(text) == []
    app, _ = _site(tmp_path, {})
    (Path(app.srcdir) / "page.md").write_text(text + f"\n```bash\n{LONG}\n```\n", encoding="utf-8")
    build_checks._check_code_lines(app)
    assert _warnings(caplog) == [
        "page.md, line 22: code line of 89 characters: " + repr(LONG[:40]) + "… (longer than 88: it scrolls)"
    ]


def test_pages_have_no_long_code_lines():
    docs = Path(__file__).resolve().parents[1] / "docs"
    found = {p.name: build_checks._long_code_lines(p.read_text(encoding="utf-8")) for p in docs.glob("*.md")}
    assert not any(found.values()), {name: lines for name, lines in found.items() if lines}


@pytest.mark.parametrize(
    "text",
    [
        "**2026-11-27, side by side in one run**: 121.3 s",
        "the code before the speed-ups (main at 0c54ec7) 285.3 s",
        "| a wall's erosion (2026-11-28, load 0.04) | 30 s |",
        "```bash\ngit checkout 3f2a9c1d8e\n```",
        "fixed in a1b2c3d.",
    ],
)
def test_dated_measurement_or_commit_hash_is_reported(text):
    assert len(build_checks._record_text("A page.\n\n" + text)) == 1, build_checks._record_text(text)


def test_numbers_urls_and_words_are_not_reported():
    text = (
        "OpenFOAM v1912 (1912.200626), 1.000000e-03 and 0.000000e+00, 6.60e-15 m³, 1e-13…1e-10, 2026 and 11-27,\n"
        "a decade, deadbeef, fig06_spin.png, <https://example.org/commit/0c54ec7a/2026-11-27>, 10⁴ impacts.\n"
    )
    assert build_checks._record_text(text) == []


def test_record_pages_and_changelog_are_exempt(tmp_path, caplog):
    app, _ = _site(tmp_path, {})
    for name in ("fem.md", "fem-record.md", "changelog.md", "wall-records.md"):
        (Path(app.srcdir) / name).write_text("Measured 2026-11-27 at 0c54ec7.\n", encoding="utf-8")
    build_checks._check_record_text(app)
    found = _warnings(caplog)
    assert len(found) == 4 and sorted({w.split(",")[0] for w in found}) == ["fem.md", "wall-records.md"], found


def test_pages_have_no_dated_measurements_or_commit_hashes():
    docs = Path(__file__).resolve().parents[1] / "docs"
    pages = [p for p in docs.glob("*.md") if not build_checks.RECORD_PAGES.search(p.name)]
    found = {p.name: build_checks._record_text(p.read_text(encoding="utf-8")) for p in pages}
    assert not any(found.values()), {name: lines for name, lines in found.items() if lines}


def test_long_example_code_line_is_reported(tmp_path, caplog):
    """A gallery example's code cell line, or a literal block's line in its text, over 88 characters is reported;
    prose and maths of the text cells are not (the page wraps them), nor a short code line."""
    example = (
        f'"""\nTitle\n=====\n\nA prose line {LONG}.\n\n.. math::\n\n    x = {LONG}\n"""\n\n'
        f"x = 1  # {'y' * 78}\n"
        f'print("{LONG}")\n\n'
        f"# %%\n# A prose line {LONG}, then a command::\n#\n#     impactwear {LONG}\n#\n\n"
        f"# %%\n# A code directive:\n#\n# .. code-block:: bash\n#    :caption: run\n#\n#    impactwear {LONG}\n\n"
        "y = 2\n"
    )
    app, _ = _site(tmp_path, {})
    examples = Path(app.srcdir).parent / "examples"
    examples.mkdir()
    (examples / "a.py").write_text(example, encoding="utf-8")
    app.config.sphinx_gallery_conf["examples_dirs"] = "../examples"
    build_checks._check_code_lines(app)
    found = _warnings(caplog)
    assert [w.split(":")[0] for w in found] == [
        "examples/a.py, line 13",
        "examples/a.py, line 18",
        "examples/a.py, line 27",
    ]
    assert all(w.endswith("(longer than 88: it scrolls)") for w in found), found


def test_examples_have_no_long_code_lines():
    examples = Path(__file__).resolve().parents[1] / "examples"
    found = {p.name: build_checks._long_example_lines(p) for p in examples.glob("*.py")}
    assert not any(found.values()), {name: lines for name, lines in found.items() if lines}


def test_gallery_figure_with_overlapping_texts_is_reported():
    """The gallery's scraper checks the figures an example leaves open: one whose tick labels crowd and whose
    texts sit on one another is reported, naming the example and the figure; a plain one is not."""
    gallery_support = pytest.importorskip("gallery_support")
    plt = pytest.importorskip("matplotlib.pyplot")
    plt.close("all")
    try:
        fig, ax = plt.subplots(figsize=(4.0, 3.0))
        ax.set_xticks([0.0, 0.01], ["0.000", "0.010"])
        ax.text(0.5, 0.5, "one label", transform=ax.transAxes)
        ax.text(0.52, 0.51, "another label", transform=ax.transAxes)
        found = gallery_support.figure_text_problems("x.py")
        assert len(found) == 2 and all(f.startswith(f"x.py, figure {fig.number}: ") for f in found), found
        plt.close(fig)
        fig, ax = plt.subplots(figsize=(4.0, 3.0), layout="constrained")
        ax.set(title="title", xlabel="x (m)", ylabel="y (m)")
        assert gallery_support.figure_text_problems("x.py") == []
    finally:
        plt.close("all")
