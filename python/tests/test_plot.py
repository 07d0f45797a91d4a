"""Pictures through ic_plot_write, and the notebook view (_repr_html_):
the library's HTML page in an iframe where it writes .html, else its SVG."""

import base64
import html
import re

import pytest

import intercurve as ic
from conftest import example

# the first bytes of each format
MAGIC = {".png": b"\x89PNG\r\n\x1a\n", ".pdf": b"%PDF-", ".svg": b"<?xml"}


@pytest.fixture(scope="module")
def cusp():
    return ic.Problem.load(example("cusp.json"))


@pytest.mark.parametrize("ext", sorted(MAGIC))
def test_plot_formats(cusp, tmp_path, ext):
    path = tmp_path / ("figure" + ext)
    cusp.plot(path, size=(400, 300), mesh=8)
    data = path.read_bytes()
    assert data.startswith(MAGIC[ext])
    if ext == ".svg":
        assert re.search(rb'<svg[^>]* width="400(pt)?"', data)


def test_plot_of_a_result_and_surfaces_only(cusp, tmp_path):
    r = cusp.trace()
    r.plot(tmp_path / "a.png", size=(400, 300), mesh=8)
    cusp.plot(tmp_path / "b.png", surfaces_only=True, size=(400, 300), mesh=8)
    a, b = (tmp_path / "a.png").read_bytes(), (tmp_path / "b.png").read_bytes()
    assert a.startswith(MAGIC[".png"]) and b.startswith(MAGIC[".png"]) and a != b


def test_plot_of_an_unpickled_result(tmp_path):
    import gc
    import pickle
    p = ic.Problem.load(example("cusp.json"))
    r = p.trace()
    back = pickle.loads(pickle.dumps(r))
    assert back == r and back._handles is None  # the document only
    back.problem.plot(tmp_path / "a.svg", result=back, size=(400, 300), mesh=8)
    gc.collect()  # the result traced again owns its handles: still valid
    back.plot(tmp_path / "b.svg", size=(400, 300), mesh=8)
    # the same picture, but for cairo's ids, numbered per process
    a, b = ((tmp_path / f).read_bytes() for f in ("a.svg", "b.svg"))
    assert re.sub(rb"[a-z]+[0-9]+", b"id", a) == re.sub(rb"[a-z]+[0-9]+", b"id", b)
    del back
    gc.collect()


def test_plot_errors(cusp, tmp_path):
    with pytest.raises(ic.InputError, match="format"):
        cusp.plot(tmp_path / "figure.xyz")
    with pytest.raises(ic.InputError, match="width"):
        cusp.plot(tmp_path / "figure.png", size=(10, 10))
    with pytest.raises(ic.InputError, match="another problem"):
        ic.Problem.load(example("cusp.json")).plot(tmp_path / "f.png", result=cusp.trace())
    with pytest.raises(ic.ComputationError):
        cusp.plot(tmp_path / "no-such-dir" / "figure.png", size=(400, 300), mesh=8)


def check_view(text):
    """The HTML page in an iframe (a script in it) or the SVG picture."""
    page = re.fullmatch(r'<iframe srcdoc="([^"]*)"[^>]*></iframe>', text)
    if page:
        doc = html.unescape(page.group(1))
        assert "<script" in doc and "</html>" in doc.lower()
        return "html"
    img = re.fullmatch(r'<img src="data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)"[^>]*>', text)
    assert img, text[:200]
    svg = base64.b64decode(img.group(1))
    assert svg.startswith(MAGIC[".svg"]) and b"<svg" in svg
    return "svg"


def test_notebook_views():
    p = ic.Problem.load(example("viviani-implicit.json"))
    r = p.trace()
    kinds = {check_view(p._repr_html_()), check_view(r._repr_html_())}
    assert len(kinds) == 1  # the same library writes both
    assert p._repr_html_() != r._repr_html_()  # the trace's view has the curves
